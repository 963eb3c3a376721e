!> The material interface. A material maps a strain measure to its work-conjugate stress and
!> the consistent tangent, carrying history per integration point.
!>
!> Voigt convention used everywhere in frix (strain, stress, tangent):
!>   index 1..6 = xx, yy, zz, xy, xz, yz; strains carry engineering shears
!>   (gamma_xy = 2 eps_xy), stresses carry tensor shears.
!> Under small strain the strain is the linearised strain eps and the stress the Cauchy
!> stress; under total Lagrangian kinematics the strain is the Green-Lagrange strain E and
!> the stress the second Piola-Kirchhoff stress S. In both cases tangent = d stress / d strain.
!> The element tells the law which (`finite`): hyperelastic laws are the same function either
!> way, but an inelastic law is not (von Mises plasticity returns in the logarithmic strain
!> 1/2 ln C under finite strain, in eps under small strain; docs/materials.md). The law needs C
!> only, C = I + 2 E, not the deformation gradient: every law is frame-indifferent and
!> isotropic, so E carries all it uses.
module frix_material
   use frix_kinds, only: dp
   use frix_error, only: error_t
   implicit none
   private

   public :: material_t, material_slot_t

   type, abstract :: material_t
      character(len=:), allocatable :: name   !! deck keyword of the law, e.g. MAT_Struct_StVenantKirchhoff
      real(dp) :: density = 0.0_dp            !! mass per unit reference volume (body force rho g)
   contains
      !> Number of history variables per integration point (0 for elasticity).
      procedure(n_state_interface), deferred :: n_state
      !> Stress and consistent tangent for a strain, given the history at the start of the
      !> increment (`state_old`); writes the updated history to `state_new`.
      procedure(response_interface), deferred :: response
      !> Small-strain elastic modulus tensor (for initial stiffness and error estimates).
      procedure(elastic_tangent_interface), deferred :: elastic_tangent
      procedure :: history_names
      procedure :: symmetric_tangent
      !> `response` from an initial (in-situ) stress: the stress at zero strain is sigma0.
      procedure :: initial_stress_response
   end type material_t

   integer, parameter, public :: history_name_length = 16

   !> Holder so that materials of different classes can live in one array.
   type :: material_slot_t
      class(material_t), allocatable :: law
   end type material_slot_t

   abstract interface
      pure function n_state_interface(self) result(n)
         import :: material_t
         class(material_t), intent(in) :: self
         integer :: n
      end function n_state_interface

      subroutine response_interface(self, strain, finite, state_old, state_new, stress, tangent, error)
         import :: material_t, dp, error_t
         class(material_t), intent(in) :: self
         real(dp), intent(in) :: strain(6)        !! eps (small strain) or E (Green-Lagrange), Voigt
         logical, intent(in) :: finite            !! .true.: total Lagrangian (strain is E, stress S)
         real(dp), intent(in) :: state_old(:)     !! history at the start of the increment
         real(dp), intent(inout) :: state_new(:)  !! history at the end (written)
         real(dp), intent(out) :: stress(6)       !! sigma (small strain) or S (2nd Piola-Kirchhoff)
         real(dp), intent(out) :: tangent(6, 6)   !! d stress / d strain, consistent
         type(error_t), allocatable, intent(out) :: error  !! e.g. det(C) <= 0
      end subroutine response_interface

      pure subroutine elastic_tangent_interface(self, tangent)
         import :: material_t, dp
         class(material_t), intent(in) :: self
         real(dp), intent(out) :: tangent(6, 6)
      end subroutine elastic_tangent_interface
   end interface

contains

   !> Names of the history variables that the result files show per integration point:
   !> names(k) labels entry k of the state vector (e.g. 'EQPS'); entries beyond size(names)
   !> are internal (restart data only). A law with history variables to show overrides this;
   !> the default shows none.
   pure subroutine history_names(self, names)
      class(material_t), intent(in) :: self
      character(len=history_name_length), allocatable, intent(out) :: names(:)
      allocate (names(0))
   end subroutine history_names

   !> Whether the law's consistent tangent d stress / d strain is symmetric (hyperelastic and
   !> associated laws); a law with an unsymmetric tangent (non-associated flow) overrides this,
   !> and the elements then assemble the full element tangent and the solver an unsymmetric
   !> system. Default: symmetric.
   pure logical function symmetric_tangent(self)
      class(material_t), intent(in) :: self
      symmetric_tangent = .true.
   end function symmetric_tangent

   !> The response of a point that starts from the initial stress sigma0 (Cauchy under small
   !> strain, S under total Lagrangian kinematics; e.g. a soil's geostatic stress): the stress
   !> at zero strain is sigma0. Default, for the elastic and hyperelastic laws: the response
   !> plus sigma0 (a prestress; the tangent is unchanged). A plastic law overrides it so that
   !> its yield condition sees the stress sigma0 + D eps_e (frix_plastic_law).
   subroutine initial_stress_response(self, strain, finite, initial_stress, state_old, state_new, stress, tangent, error)
      class(material_t), intent(in) :: self
      real(dp), intent(in) :: strain(6)           !! eps or E, Voigt, engineering shears
      logical, intent(in) :: finite
      real(dp), intent(in) :: initial_stress(6)   !! sigma0, Voigt, tensor shears
      real(dp), intent(in) :: state_old(:)
      real(dp), intent(inout) :: state_new(:)
      real(dp), intent(out) :: stress(6), tangent(6, 6)
      type(error_t), allocatable, intent(out) :: error
      call self%response(strain, finite, state_old, state_new, stress, tangent, error)
      if (.not. allocated(error)) stress = stress + initial_stress
   end subroutine initial_stress_response
end module frix_material
