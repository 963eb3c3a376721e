!> Parameters of one contact pair (slave surface against master surface or rigid plane): its
!> normal contact law (frix_normal_contact_law), tangential penalty, friction law, search band
!> and normal field.
module frix_contact_parameters
   use frix_kinds, only: dp
   use frix_error, only: error_t, append_error
   use frix_strings, only: to_string
   use frix_friction_law, only: friction_law_t
   use frix_normal_contact_law, only: normal_contact_law_t
   implicit none
   private

   public :: contact_parameters_t, new_contact_parameters, default_edge_tolerance, default_feature_angle
   public :: default_penalty_factor

   !> Default feature angle of NORMALS Auto (degrees): adjacent master faces whose reference
   !> normals differ by at most this share averaged nodal normals, sharper edges keep facet
   !> normals. 30 degrees smooths a circle meshed with more than 12 faces per full turn
   !> (360/12 = 30) and keeps right-angled (90 degrees) and 45-degree edges sharp
   !> (docs/contact.md, "Normals").
   real(dp), parameter :: default_feature_angle = 30.0_dp

   !> Default factor c of an automatic penalty, eps_N = c min over the pair's deformable
   !> surfaces of the mean M/h of the elements under them (docs/contact.md, "Choosing the
   !> penalties": 10 to 100 times E_soft/h keeps the penetration at 1-10 % of the first
   !> element's deformation; 10, the low end, for the best-conditioned system).
   real(dp), parameter :: default_penalty_factor = 10.0_dp

   !> Default of `edge_tolerance` (parent coordinates: 1e-6 of half a face).
   real(dp), parameter :: default_edge_tolerance = 1.0e-6_dp

   !> The normal contact law, the tangential penalty and the friction law. eps_T, like the
   !> penalty law's eps_N, is a stiffness per unit area (stress per length, e.g. kPa/m), so that
   !> the nodal force eps_T |g_T| A_s does not depend on the mesh size.
   type :: contact_parameters_t
      class(normal_contact_law_t), allocatable :: normal   !! p_N(g, lambda): PENALTY
      real(dp) :: tangential_penalty = 0.0_dp  !! eps_T > 0: stick traction per unit elastic slip
      !> .true.: a pair with friction created without EPST; eps_T is then set to the pair's eps_N
      !> by the deck reader (0 until then) and this stays .true. to say where the value came from
      logical :: automatic_tangential_penalty = .false.
      !> TMETHOD Augmented: the stick traction is augmented too, with a tangential multiplier
      !> per slave node (frix_contact_augmentation), until every sticking node's elastic slip
      !> |t - lambda_T| / eps_T is below `stick_tolerance` (length; < 0: the default, the
      !> penetration tolerance's rule); needs an augmented normal law
      logical :: tangential_augmented = .false.
      real(dp) :: stick_tolerance = -1.0_dp
      !> PREDICT (augmented normal law only): an increment that is not its step's first starts
      !> from multipliers extrapolated from the last converged increment's rates
      !> (frix_contact_augmentation's predict_multipliers); No: from the committed ones
      logical :: predict = .true.
      !> Search band (length): the contact search keeps slave/master candidates whose gap is
      !> below this, so that a node about to close is tracked; it does NOT activate contact,
      !> which the normal law decides (penalty: g < 0). CARAT's "gap tolerance" (1e-4 in
      !> benchmarks S2/S3) is read this way.
      real(dp) :: gap_tolerance = 0.0_dp
      !> A closest point with |xi_k| <= 1 + edge_tolerance counts as inside the face.
      real(dp) :: edge_tolerance = default_edge_tolerance
      !> NORMALS Smoothed or Auto: the master surface's normal field is interpolated from
      !> averaged nodal normals (frix_contact_kernel); .false.: facet normals (NORMALS Facet)
      logical :: smoothed_normals = .false.
      !> with smoothed_normals: a face's nodal normals average the adjacent faces whose
      !> reference normal is within this angle of its own (degrees; 180, every adjacent face:
      !> NORMALS Smoothed, continuous across all faces; NORMALS Auto: default_feature_angle or
      !> FEATURE_ANGLE, facet-like across sharper edges; frix_contact_patches)
      real(dp) :: feature_angle = 180.0_dp
      class(friction_law_t), allocatable :: friction   !! Coulomb or frictionless
   end type contact_parameters_t

contains

   !> Validated parameters: gap_tolerance >= 0 always; eps_T > 0 unless the friction law is
   !> frictionless (eps_T is then irrelevant and stored as given) or `automatic_tangential`
   !> (a pair with friction without EPST: eps_T is set later, to eps_N). The normal law is
   !> validated by its registry (frix_normal_contact_law_registry).
   subroutine new_contact_parameters(normal, tangential_penalty, gap_tolerance, friction, parameters, error, &
                                     automatic_tangential)
      class(normal_contact_law_t), intent(in) :: normal
      real(dp), intent(in) :: tangential_penalty   !! eps_T (force/area/length)
      real(dp), intent(in) :: gap_tolerance        !! search band (length)
      class(friction_law_t), intent(in) :: friction
      type(contact_parameters_t), intent(out) :: parameters
      type(error_t), allocatable, intent(out) :: error
      logical, intent(in), optional :: automatic_tangential   !! EPST not given (default .false.)
      logical :: automatic
      automatic = .false.
      if (present(automatic_tangential)) automatic = automatic_tangential .and. .not. friction%frictionless()
      if (.not. friction%frictionless() .and. .not. automatic .and. &
          .not. (tangential_penalty > 0.0_dp .and. tangential_penalty < huge(1.0_dp))) &
         call append_error(error, 'contact: tangential penalty EPST must be > 0 with friction, got '// &
                           to_string(tangential_penalty))
      if (.not. (gap_tolerance >= 0.0_dp .and. gap_tolerance < huge(1.0_dp))) &
         call append_error(error, 'contact: gap tolerance must be >= 0, got '//to_string(gap_tolerance))
      if (allocated(error)) return
      allocate (parameters%normal, source=normal)
      parameters%tangential_penalty = tangential_penalty
      parameters%automatic_tangential_penalty = automatic
      parameters%gap_tolerance = gap_tolerance
      allocate (parameters%friction, source=friction)
   end subroutine new_contact_parameters
end module frix_contact_parameters
