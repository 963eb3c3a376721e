!> A test material with an unsymmetric tangent: sigma = C eps with C = Hooke's tangent plus a
!> skew-symmetric part, as a non-associated flow rule would give: the fixture with which
!> test_hex8's test_unsymmetric_tangent checks that the elements assemble the full tangent
!> (every block, and K_au of the EAS condensation computed, not taken as K_ua^T) when a
!> material says its tangent is not symmetric.
module test_unsymmetric_material
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_material, only: material_t
   use frix_linear_elastic, only: hooke_tangent
   implicit none
   private

   public :: unsymmetric_elastic_t, new_unsymmetric_elastic

   type, extends(material_t) :: unsymmetric_elastic_t
      real(dp) :: moduli(6, 6) = 0.0_dp
   contains
      procedure :: n_state
      procedure :: response
      procedure :: elastic_tangent
      procedure :: symmetric_tangent
   end type unsymmetric_elastic_t

contains

   !> Hooke (young, poisson) plus skew * young in C(1,2), C(2,4), C(3,6) and minus it in the
   !> transposed entries.
   function new_unsymmetric_elastic(young, poisson, skew) result(material)
      real(dp), intent(in) :: young, poisson, skew
      type(unsymmetric_elastic_t) :: material
      material%name = 'unsymmetric test law'
      material%moduli = hooke_tangent(young, poisson)
      material%moduli(1, 2) = material%moduli(1, 2) + skew*young
      material%moduli(2, 1) = material%moduli(2, 1) - skew*young
      material%moduli(2, 4) = material%moduli(2, 4) + skew*young
      material%moduli(4, 2) = material%moduli(4, 2) - skew*young
      material%moduli(3, 6) = material%moduli(3, 6) + skew*young
      material%moduli(6, 3) = material%moduli(6, 3) - skew*young
   end function new_unsymmetric_elastic

   pure integer function n_state(self)
      class(unsymmetric_elastic_t), intent(in) :: self
      n_state = 0
   end function n_state

   subroutine response(self, strain, finite, state_old, state_new, stress, tangent, error)
      class(unsymmetric_elastic_t), intent(in) :: self
      real(dp), intent(in) :: strain(6)
      logical, intent(in) :: finite            !! unused: the same law under both kinematics
      real(dp), intent(in) :: state_old(:)
      real(dp), intent(inout) :: state_new(:)
      real(dp), intent(out) :: stress(6)
      real(dp), intent(out) :: tangent(6, 6)
      type(error_t), allocatable, intent(out) :: error
      stress = matmul(self%moduli, strain)
      tangent = self%moduli
   end subroutine response

   pure subroutine elastic_tangent(self, tangent)
      class(unsymmetric_elastic_t), intent(in) :: self
      real(dp), intent(out) :: tangent(6, 6)
      tangent = self%moduli
   end subroutine elastic_tangent

   pure logical function symmetric_tangent(self)
      class(unsymmetric_elastic_t), intent(in) :: self
      symmetric_tangent = .false.
   end function symmetric_tangent
end module test_unsymmetric_material
