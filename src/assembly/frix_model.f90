!> The analysis model as read from a deck: mesh, materials, element blocks, boundary
!> conditions, loads, load curves, steps, solver controls and result requests.
!>
!> Pseudo time: step s runs from t = s-1 to t = s. Every load and prescribed displacement is
!> `value * f(t)` where f is its load curve; without a curve f is the default ramp
!> f(t) = min(t, 1) (applied in the first step, held afterwards). The load factor printed by
!> the driver is t.
module frix_model
   use frix_kinds, only: dp
   use frix_mesh, only: mesh_t
   use frix_material, only: material_slot_t
   use frix_element, only: element_slot_t, kinematics_linear
   use frix_contact_parameters, only: contact_parameters_t, default_penalty_factor
   implicit none
   private

   public :: model_t, element_block_t, dirichlet_t, nodal_force_t, pressure_load_t
   public :: body_force_t, load_curve_t, step_t, solver_controls_t, results_request_t
   public :: history_request_t, curve_factor, contact_pair_t, kinematic_coupling_t, initial_stress_t

   !> Elements sharing one formulation and one material.
   type :: element_block_t
      type(element_slot_t) :: element     !! formulation (shape, EAS variant, kinematics)
      integer :: material = 0             !! index into model%materials
   end type element_block_t

   !> Prescribed displacement u_i = value * f(t) on `nodes` (value 0: fixed).
   type :: dirichlet_t
      integer, allocatable :: nodes(:)    !! internal node numbers
      integer :: component = 0            !! 1 = x, 2 = y, 3 = z
      real(dp) :: value = 0.0_dp
      integer :: curve = 0                !! index into model%curves, 0 = default ramp
      integer :: line = 0                 !! deck line (for messages)
   end type dirichlet_t

   !> Nodal force F_i = value * f(t) applied to each node of `nodes`.
   type :: nodal_force_t
      integer, allocatable :: nodes(:)
      integer :: component = 0
      real(dp) :: value = 0.0_dp
      integer :: curve = 0
   end type nodal_force_t

   !> Pressure p * f(t) on a surface, positive pushing into the body (traction -p n with n the
   !> outward normal). Dead: reference normal and area. Follower: current normal and area.
   type :: pressure_load_t
      integer :: surface = 0              !! index into model%mesh%surfaces
      real(dp) :: value = 0.0_dp
      integer :: curve = 0
      logical :: follower = .false.
   end type pressure_load_t

   !> Body force rho g f(t) per unit reference volume on `elements` (rho from the material).
   type :: body_force_t
      integer, allocatable :: elements(:)
      real(dp) :: gravity(3) = 0.0_dp     !! acceleration vector, e.g. (0, 0, -9.81)
      integer :: curve = 0
   end type body_force_t

   !> An initial (in-situ) stress on `elements` (INITIAL STRESS, docs/deck-format.md), evaluated
   !> at each integration point's reference position by frix_initial_stress. Geostatic, with
   !> the vertical axis `axis` and tension positive: sigma_v = -(q + gamma (z0 - z)) and
   !> sigma_h = K0 sigma_v in the two other normal directions, no shear; else `stress`.
   type :: initial_stress_t
      integer, allocatable :: elements(:)
      logical :: geostatic = .false.
      real(dp) :: datum = 0.0_dp          !! z0: the level of sigma_v = -q [length]
      real(dp) :: unit_weight = 0.0_dp    !! gamma = rho g [force / length^3], >= 0
      real(dp) :: k0 = 0.0_dp             !! K0 = sigma_h / sigma_v, >= 0
      real(dp) :: surcharge = 0.0_dp      !! q: the vertical stress at the datum, compression positive
      integer :: axis = 3                 !! the vertical direction, 1 = x, 2 = y, 3 = z (up)
      real(dp) :: stress(6) = 0.0_dp      !! explicit sigma0: xx yy zz xy xz yz, tensor shears
      integer :: line = 0                 !! deck line
   end type initial_stress_t

   !> Piecewise-linear curve f(t) through (times(k), factors(k)), constant beyond the ends.
   type :: load_curve_t
      integer :: id = 0
      real(dp), allocatable :: times(:)
      real(dp), allocatable :: factors(:)
   end type load_curve_t

   !> A load step from t = s-1 to t = s. With `CONTROL Path` the pseudo time (the load factor) is
   !> an unknown of each increment and one displacement component drives the step instead
   !> (docs/solver.md, "Path following").
   type :: step_t
      integer :: n_increments = 1
      integer :: max_iterations = 0       !! 0: use the solver controls' value
      character(len=:), allocatable :: control  !! 'LOAD', 'DISPLACEMENT' (as declared) or 'PATH'
      integer :: path_node = 0            !! CONTROL Path: internal number of the driving node
      integer :: path_component = 0       !! its driven component, 1 = x, 2 = y, 3 = z
      real(dp) :: path_target = 0.0_dp    !! the displacement [length] at which the step ends
      !> RESET_DISPLACEMENT: the displacements reported from this step on are measured from the
      !> state at its start, u_reported = u_total - u_reference (frix_analysis_state)
      logical :: reset_displacement = .false.
   end type step_t

   type :: solver_controls_t
      integer :: max_iterations = 25
      real(dp) :: tol_residual = 1.0e-8_dp     !! ||r|| <= tol * max(||f_ext||, ||reactions||)
      real(dp) :: tol_displacement = 1.0e-8_dp !! ||du|| <= tol * ||u||
      integer :: max_cutbacks = 6              !! halvings of an increment before giving up
      !> deck keyword of the linear solver (frix_linear_solver_registry), upper case
      character(len=16) :: linear_solver = 'AUTO'
      integer :: default_kinematics = kinematics_linear
      !> MU_CONTINUATION f_1 > f_2 > ... > f_m > 1: after a failed increment on a model with
      !> frictional contact, solve it again with the friction coefficients scaled by f_1, ..., f_m
      !> and finally 1, each stage starting from the previous one's solution (frix_driver).
      !> Empty: no continuation.
      real(dp), allocatable :: friction_continuation(:)
      !> EXTRAPOLATION Linear: an increment's iterations start from the committed displacements
      !> plus the last increment's rate times the new increment size, when the last increment
      !> belongs to the same step (frix_analysis_state, extrapolate_displacements)
      logical :: extrapolate = .false.
   end type solver_controls_t

   !> One column of the CSV history: displacement ('U') or reaction ('R') of a node's DOF.
   !> A column of the CSV history (RESULTS HISTORY, docs/deck-format.md): one node's DOF, a
   !> total over a node set, or the resultant of a contact pair's forces.
   type :: history_request_t
      integer :: node = 0                 !! internal node number (one node)
      integer :: component = 0            !! 1..3; 0: a contact pair's NORMAL force
      character(len=1) :: kind = 'U'      !! U displacement, R reaction, C contact
      !> '' one node; 'SUM' (reactions) or 'MEAN' (displacements) over `nodes`
      character(len=4) :: reduction = ''
      integer, allocatable :: nodes(:)    !! SUM, MEAN: the set's internal node numbers
      character(len=:), allocatable :: set_name   !! SUM, MEAN: the set's name
      integer :: pair = 0                 !! C: index into model%contact_pairs
   end type history_request_t

   type :: results_request_t
      logical :: vtk = .true.
      logical :: listing = .true.
      logical :: pos3d = .false.          !! Tecgraf neutral file <base>.pos
      logical :: hdf5 = .false.           !! <base>.h5: results and restart data
      integer :: every = 1                !! write every n-th converged increment (and the last)
      type(history_request_t), allocatable :: history(:)
   end type results_request_t

   !> A contact pair: the nodes of the slave surface against the faces of the master surface
   !> (node-to-segment) or against a rigid plane, or a tie of the slave nodes to the master
   !> surface. See docs/contact.md.
   type :: contact_pair_t
      integer :: id = 0
      integer :: slave_surface = 0          !! index into model%mesh%surfaces
      integer :: master_surface = 0         !! index into model%mesh%surfaces; 0: rigid plane
      real(dp) :: plane_point(3) = 0.0_dp   !! rigid plane: a point of it
      real(dp) :: plane_normal(3) = 0.0_dp  !! rigid plane: unit normal out of the rigid body
      type(contact_parameters_t) :: parameters  !! normal contact law (METHOD, EPSN), EPST, gap tolerance, friction law
      integer :: passes = 1                 !! 2: also the master's nodes against the slave's faces
      !> TIE: the slave nodes are bonded to the master surface by elimination
      !> (frix_tie_constraints); `parameters` is then not set
      logical :: tied = .false.
      !> TIE: slave nodes farther than this from the master surface (reference configuration,
      !> length) are not tied; < 0: the default, a tenth of the mean master face size
      real(dp) :: tie_tolerance = -1.0_dp
      !> DISCRETIZATION Mortar: segment-to-segment contact with dual mortar weighted gaps
      !> (frix_mortar_contact, one pass, deformable master); .false.: node-to-segment
      logical :: mortar = .false.
      !> PENALTY_FACTOR c of an automatic penalty: eps_N = c (M/h of the softer surface)
      real(dp) :: penalty_factor = default_penalty_factor
      !> How the penalties of a pair with an automatic one were chosen, e.g. `EPSN 2.69e+04
      !> (automatic: 10 x 2692.31 = M/h of surface found_zmax), EPST 2.69e+04 (automatic)`,
      !> printed at the start of the run and written to the listing's header; unallocated when
      !> the deck gives every penalty the pair needs
      character(len=:), allocatable :: penalty_note
      integer :: line = 0                   !! deck line
   end type contact_pair_t

   !> A kinematic (rigid) coupling: the coupled nodes follow the small rigid motion of a
   !> reference node, u_i = u_R + theta x (X_i - X_R), with theta the displacements of the
   !> rotation node (frix_kinematic_coupling, docs/couplings.md).
   type :: kinematic_coupling_t
      integer :: id = 0
      integer :: reference_node = 0        !! internal node number R (its displacements: u_R)
      integer :: rotation_node = 0         !! internal node number Q (its displacements: theta)
      integer, allocatable :: nodes(:)     !! the coupled nodes (internal numbers, sorted)
      integer :: line = 0                  !! deck line
   end type kinematic_coupling_t

   type :: model_t
      character(len=:), allocatable :: deck_path       !! as given on the command line
      character(len=:), allocatable :: title           !! the deck's header comment lines
      type(mesh_t) :: mesh
      type(material_slot_t), allocatable :: materials(:)
      integer, allocatable :: material_ids(:)          !! user ids of `materials`
      type(element_block_t), allocatable :: blocks(:)
      type(dirichlet_t), allocatable :: dirichlet(:)
      type(nodal_force_t), allocatable :: nodal_forces(:)
      type(pressure_load_t), allocatable :: pressures(:)
      type(body_force_t), allocatable :: body_forces(:)
      type(load_curve_t), allocatable :: curves(:)
      type(step_t), allocatable :: steps(:)
      type(contact_pair_t), allocatable :: contact_pairs(:)
      type(kinematic_coupling_t), allocatable :: couplings(:)
      type(initial_stress_t), allocatable :: initial_stresses(:)
      !> The initial stress of each element's points, (6, max points, n_elements), and which
      !> definition of `initial_stresses` gave it (n_elements, 0: none); both unallocated in a
      !> model without initial stresses (frix_initial_stress)
      real(dp), allocatable :: point_initial_stress(:, :, :)
      integer, allocatable :: initial_stress_source(:)
      type(solver_controls_t) :: controls
      type(results_request_t) :: results
   end type model_t

contains

   !> f(t) of curve `curve` (0: default ramp min(t, 1)).
   pure function curve_factor(model, curve, time) result(factor)
      type(model_t), intent(in) :: model
      integer, intent(in) :: curve
      real(dp), intent(in) :: time
      real(dp) :: factor
      integer :: k, n
      real(dp) :: weight
      if (curve == 0) then
         factor = min(max(time, 0.0_dp), 1.0_dp)
         return
      end if
      associate (times => model%curves(curve)%times, factors => model%curves(curve)%factors)
         n = size(times)
         if (time <= times(1)) then
            factor = factors(1)
         else if (time >= times(n)) then
            factor = factors(n)
         else
            do k = 2, n
               if (time <= times(k)) exit
            end do
            weight = (time - times(k - 1))/(times(k) - times(k - 1))
            factor = (1.0_dp - weight)*factors(k - 1) + weight*factors(k)
         end if
      end associate
   end function curve_factor
end module frix_model
