!> Isotropic linear elasticity (Hooke's law) in the Voigt convention of frix_material:
!> stress = D strain with D = lambda 1 (x) 1 + 2 mu I, where, because strains carry engineering
!> shears (gamma_xy = 2 eps_xy), the shear diagonal of D is mu (tau_xy = mu gamma_xy).
!>
!> Lame parameters from Young's modulus E and Poisson's ratio nu (any textbook, e.g.
!> Timoshenko & Goodier): lambda = E nu / ((1 + nu)(1 - 2 nu)), mu = E / (2 (1 + nu)).
!> Units: stresses and moduli in the user's consistent stress unit; strains dimensionless.
module frix_linear_elastic
   use frix_kinds, only: dp
   use frix_error, only: error_t, append_error
   use frix_strings, only: to_string
   use frix_property_list, only: property_list_t
   use frix_material, only: material_t
   implicit none
   private

   public :: linear_elastic_t, new_linear_elastic, lame_parameters, hooke_tangent
   public :: linear_elastic_from_properties, elastic_constants, hooke_strain

   !> Hooke's law; no history. Valid for 0 < young and -1 < poisson < 0.5 (the registry
   !> checks this before constructing).
   type, extends(material_t) :: linear_elastic_t
      real(dp) :: young = 0.0_dp    !! Young's modulus E (stress unit)
      real(dp) :: poisson = 0.0_dp  !! Poisson's ratio nu (dimensionless)
   contains
      procedure :: n_state => linear_elastic_n_state
      procedure :: response => linear_elastic_response
      procedure :: elastic_tangent => linear_elastic_elastic_tangent
   end type linear_elastic_t

contains

   !> Hooke material named by the deck keyword MAT_Struct_LinearElastic.
   pure function new_linear_elastic(young, poisson, density) result(material)
      real(dp), intent(in) :: young    !! Young's modulus E (stress unit), > 0
      real(dp), intent(in) :: poisson  !! Poisson's ratio nu, in (-1, 0.5)
      real(dp), intent(in) :: density  !! mass per unit reference volume, >= 0
      type(linear_elastic_t) :: material
      material%name = 'MAT_Struct_LinearElastic'
      material%young = young
      material%poisson = poisson
      material%density = density
   end function new_linear_elastic

   !> The Hooke material of deck properties YOUNG, NUE, DENS (elastic_constants).
   subroutine linear_elastic_from_properties(properties, material, error)
      type(property_list_t), intent(in) :: properties
      class(material_t), allocatable, intent(out) :: material
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: young, poisson, density
      call elastic_constants(properties, young, poisson, density, error)
      if (.not. allocated(error)) allocate (material, source=new_linear_elastic(young, poisson, density))
   end subroutine linear_elastic_from_properties

   !> The properties of every elastic law: YOUNG (required, > 0), NUE (required,
   !> -1 < NUE < 0.5), DENS (optional, >= 0, default 0; mass per unit reference volume).
   !> A law with further properties names them in `other_names`; any other name is reported.
   !> `other_listed` is how messages name YOUNG, NUE, DENS and the other names together.
   subroutine elastic_constants(properties, young, poisson, density, error, other_names, other_listed)
      type(property_list_t), intent(in) :: properties
      real(dp), intent(out) :: young, poisson, density
      type(error_t), allocatable, intent(inout) :: error
      character(len=*), intent(in), optional :: other_names(:)  !! upper case
      character(len=*), intent(in), optional :: other_listed
      logical :: has_young, has_poisson, has_density
      character(len=:), allocatable :: law
      character(len=32), allocatable :: valid(:)
      integer :: n_other
      law = trim(properties%owner)
      n_other = 0
      if (present(other_names)) n_other = size(other_names)
      ! filled element by element: gfortran 12 takes the first item's length for a typed array
      ! constructor whose length is not a constant
      allocate (valid(3 + n_other))
      valid(1:3) = [character(len=32) :: 'YOUNG', 'NUE', 'DENS']
      if (present(other_names)) valid(4:) = other_names
      call properties%check_names(valid, error, other_listed)
      call properties%take_real('YOUNG', young, has_young, error)
      call properties%take_real('NUE', poisson, has_poisson, error)
      call properties%take_real('DENS', density, has_density, error, default=0.0_dp)
      if (has_young .and. .not. (young > 0.0_dp)) &
         call append_error(error, law//': YOUNG must be > 0, got '//to_string(young))
      if (has_poisson .and. .not. (poisson > -1.0_dp .and. poisson < 0.5_dp)) &
         call append_error(error, law//': NUE must lie in (-1, 0.5), got '//to_string(poisson))
      if (has_density .and. .not. (density >= 0.0_dp)) &
         call append_error(error, law//': DENS must be >= 0, got '//to_string(density))
   end subroutine elastic_constants

   !> Lame parameters lambda and mu (shear modulus) from E and nu.
   pure subroutine lame_parameters(young, poisson, lambda, mu)
      real(dp), intent(in) :: young    !! Young's modulus E
      real(dp), intent(in) :: poisson  !! Poisson's ratio nu
      real(dp), intent(out) :: lambda  !! lambda = E nu / ((1 + nu)(1 - 2 nu))
      real(dp), intent(out) :: mu      !! mu = G = E / (2 (1 + nu))
      lambda = young*poisson/((1.0_dp + poisson)*(1.0_dp - 2.0_dp*poisson))
      mu = young/(2.0_dp*(1.0_dp + poisson))
   end subroutine lame_parameters

   !> Isotropic modulus matrix D (6 x 6, Voigt xx yy zz xy xz yz, engineering shear strains):
   !> D_ij = lambda + 2 mu delta_ij for i, j <= 3; D_ii = mu for the shear rows; zero elsewhere.
   pure function hooke_tangent(young, poisson) result(tangent)
      real(dp), intent(in) :: young    !! Young's modulus E
      real(dp), intent(in) :: poisson  !! Poisson's ratio nu
      real(dp) :: tangent(6, 6)
      real(dp) :: lambda, mu
      integer :: i
      call lame_parameters(young, poisson, lambda, mu)
      tangent = 0.0_dp
      tangent(1:3, 1:3) = lambda
      do i = 1, 3
         tangent(i, i) = lambda + 2.0_dp*mu
         tangent(i + 3, i + 3) = mu
      end do
   end function hooke_tangent

   !> D^-1 sigma: eps = ((1 + nu) sigma - nu tr(sigma) 1) / E, gamma = tau / G (engineering).
   pure function hooke_strain(young, poisson, stress) result(strain)
      real(dp), intent(in) :: young, poisson
      real(dp), intent(in) :: stress(6)   !! Voigt, tensor shears
      real(dp) :: strain(6)
      strain(1:3) = ((1.0_dp + poisson)*stress(1:3) - poisson*sum(stress(1:3)))/young
      strain(4:6) = 2.0_dp*(1.0_dp + poisson)*stress(4:6)/young
   end function hooke_strain

   pure function linear_elastic_n_state(self) result(n)
      class(linear_elastic_t), intent(in) :: self
      integer :: n
      n = 0
   end function linear_elastic_n_state

   !> stress = D strain; tangent = D. Never fails; the history arrays are empty and untouched.
   subroutine linear_elastic_response(self, strain, finite, state_old, state_new, stress, tangent, error)
      class(linear_elastic_t), intent(in) :: self
      real(dp), intent(in) :: strain(6)        !! eps or E, Voigt, engineering shears
      logical, intent(in) :: finite            !! unused: the same law under both kinematics
      real(dp), intent(in) :: state_old(:)     !! unused (no history)
      real(dp), intent(inout) :: state_new(:)  !! unused (no history)
      real(dp), intent(out) :: stress(6)       !! sigma or S, Voigt, tensor shears
      real(dp), intent(out) :: tangent(6, 6)   !! D
      type(error_t), allocatable, intent(out) :: error
      tangent = hooke_tangent(self%young, self%poisson)
      stress = matmul(tangent, strain)
   end subroutine linear_elastic_response

   pure subroutine linear_elastic_elastic_tangent(self, tangent)
      class(linear_elastic_t), intent(in) :: self
      real(dp), intent(out) :: tangent(6, 6)  !! D
      tangent = hooke_tangent(self%young, self%poisson)
   end subroutine linear_elastic_elastic_tangent
end module frix_linear_elastic
