!> St. Venant-Kirchhoff hyperelasticity: S = lambda tr(E) I + 2 mu E, with E the
!> Green-Lagrange strain and S the second Piola-Kirchhoff stress (Holzapfel, Nonlinear Solid
!> Mechanics, eq. 6.151). In the Voigt convention of frix_material (engineering shear strains,
!> tensor shear stresses) this is exactly Hooke's matrix applied to E, so the type extends
!> linear_elastic_t and reuses its response; only the deck keyword differs. Under small strain
!> kinematics it is Hooke's law.
!>
!> Known limitation: in strong compression (uniaxial, nu = 0: stretch below 1/sqrt(3)) the law
!> softens and reaches a limit point; use MAT_Struct_NeoHooke for large compression.
module frix_saint_venant_kirchhoff
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_property_list, only: property_list_t
   use frix_material, only: material_t
   use frix_linear_elastic, only: linear_elastic_t, elastic_constants
   implicit none
   private

   public :: saint_venant_kirchhoff_t, new_saint_venant_kirchhoff, saint_venant_kirchhoff_from_properties

   !> St. Venant-Kirchhoff material: Hooke's law between E and S.
   type, extends(linear_elastic_t) :: saint_venant_kirchhoff_t
   end type saint_venant_kirchhoff_t

contains

   !> St. Venant-Kirchhoff material named by the deck keyword MAT_Struct_StVenantKirchhoff.
   pure function new_saint_venant_kirchhoff(young, poisson, density) result(material)
      real(dp), intent(in) :: young    !! Young's modulus E (stress unit), > 0
      real(dp), intent(in) :: poisson  !! Poisson's ratio nu, in (-1, 0.5)
      real(dp), intent(in) :: density  !! mass per unit reference volume, >= 0
      type(saint_venant_kirchhoff_t) :: material
      material%name = 'MAT_Struct_StVenantKirchhoff'
      material%young = young
      material%poisson = poisson
      material%density = density
   end function new_saint_venant_kirchhoff

   !> The material of deck properties YOUNG, NUE, DENS (frix_linear_elastic's elastic_constants).
   subroutine saint_venant_kirchhoff_from_properties(properties, material, error)
      type(property_list_t), intent(in) :: properties
      class(material_t), allocatable, intent(out) :: material
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: young, poisson, density
      call elastic_constants(properties, young, poisson, density, error)
      if (.not. allocated(error)) allocate (material, source=new_saint_venant_kirchhoff(young, poisson, density))
   end subroutine saint_venant_kirchhoff_from_properties
end module frix_saint_venant_kirchhoff
