!> The deck constructors of the plane elements (frix_plane_solid), as the element registry
!> calls them: shape keyword, options from a property list and the kinematics of the element
!> line. Kept apart from frix_plane_solid so that the formulation file holds the mechanics only.
!>   PLANE4   QUAD4, plane strain; options THICKNESS t (length unit, > 0, default 1) and
!>            EAS 0 (default) or 4 (Simo & Rifai's enhanced strains, frix_plane_solid)
!>   PLANE3   TRI3, plane strain; option THICKNESS (EAS 0 only)
!>   AXISYM4  QUAD4, axisymmetric (x = radius, y = axis); option EAS 0 (default) or 4
!>   AXISYM3  TRI3, axisymmetric (EAS 0 only)
module frix_plane_solid_options
   use frix_kinds, only: dp
   use frix_error, only: error_t, fatal_error
   use frix_strings, only: to_string
   use frix_eas_modes, only: plane_eas_counts
   use frix_property_list, only: property_list_t, property_spec_t, spec_names
   use frix_element, only: element_t
   use frix_reference_cell, only: reference_cell_t
   use frix_quad4_cell, only: new_quad4_cell
   use frix_tri3_cell, only: new_tri3_cell
   use frix_plane_solid, only: new_plane_solid
   implicit none
   private

   public :: plane_strain_options, axisymmetric_options, plane4_from_options, plane3_from_options, axisym4_from_options, &
             axisym3_from_options

contains

   !> The options of the plane strain shapes: THICKNESS, a length > 0, and EAS.
   function plane_strain_options() result(specs)
      type(property_spec_t), allocatable :: specs(:)
      type(property_spec_t) :: eas(1)
      eas = axisymmetric_options()
      allocate (specs(2))
      specs(1)%name = 'THICKNESS'
      specs(1)%what = 'a thickness (length)'
      specs(1)%bounded = .true.
      specs(1)%strict = .true.
      specs(1)%minimum = 0.0_dp
      specs(1)%bound_message = 'the thickness must be > 0'
      specs(1)%has_default = .true.
      specs(1)%default = 1.0_dp
      specs(2) = eas(1)
   end function plane_strain_options

   !> The options of the axisymmetric shapes: EAS, a whole number (default 0).
   function axisymmetric_options() result(specs)
      type(property_spec_t), allocatable :: specs(:)
      allocate (specs(1))
      specs(1)%name = 'EAS'
      specs(1)%what = 'an EAS parameter count'
      specs(1)%whole = .true.
   end function axisymmetric_options

   !> PLANE4: QUAD4, plane strain.
   subroutine plane4_from_options(options, kinematics, element, error)
      type(property_list_t), intent(in) :: options
      integer, intent(in) :: kinematics   !! kinematics_linear or kinematics_total_lagrangian
      class(element_t), allocatable, intent(out) :: element
      type(error_t), allocatable, intent(out) :: error
      call plane_strain_from_options('PLANE4', new_quad4_cell(), options, kinematics, element, error)
   end subroutine plane4_from_options

   !> PLANE3: TRI3, plane strain.
   subroutine plane3_from_options(options, kinematics, element, error)
      type(property_list_t), intent(in) :: options
      integer, intent(in) :: kinematics
      class(element_t), allocatable, intent(out) :: element
      type(error_t), allocatable, intent(out) :: error
      call plane_strain_from_options('PLANE3', new_tri3_cell(), options, kinematics, element, error)
   end subroutine plane3_from_options

   !> AXISYM4: QUAD4, axisymmetric.
   subroutine axisym4_from_options(options, kinematics, element, error)
      type(property_list_t), intent(in) :: options
      integer, intent(in) :: kinematics
      class(element_t), allocatable, intent(out) :: element
      type(error_t), allocatable, intent(out) :: error
      call axisymmetric_from_options('AXISYM4', new_quad4_cell(), options, kinematics, element, error)
   end subroutine axisym4_from_options

   !> AXISYM3: TRI3, axisymmetric.
   subroutine axisym3_from_options(options, kinematics, element, error)
      type(property_list_t), intent(in) :: options
      integer, intent(in) :: kinematics
      class(element_t), allocatable, intent(out) :: element
      type(error_t), allocatable, intent(out) :: error
      call axisymmetric_from_options('AXISYM3', new_tri3_cell(), options, kinematics, element, error)
   end subroutine axisym3_from_options

   !> The plane strain element `name` on `cell` with the THICKNESS (default 1) and EAS count
   !> (default 0) of `options`.
   subroutine plane_strain_from_options(name, cell, options, kinematics, element, error)
      character(len=*), intent(in) :: name
      class(reference_cell_t), intent(in) :: cell
      type(property_list_t), intent(in) :: options
      integer, intent(in) :: kinematics
      class(element_t), allocatable, intent(out) :: element
      type(error_t), allocatable, intent(out) :: error
      type(property_spec_t), allocatable :: specs(:)
      real(dp) :: thickness
      integer :: n_eas
      logical :: found
      specs = plane_strain_options()
      call options%check_names(spec_names(specs), error)
      if (allocated(error)) return
      call options%take_real('THICKNESS', thickness, found, error, default=specs(1)%default)
      if (allocated(error)) return
      if (.not. specs(1)%admits(thickness)) then
         call fatal_error(error, 'element shape '//name//': '//trim(specs(1)%bound_message))
         return
      end if
      call eas_count(name, cell, options, n_eas, error)
      if (allocated(error)) return
      allocate (element, source=new_plane_solid(name, cell, kinematics, axisymmetric=.false., thickness=thickness, &
                                                n_eas=n_eas))
   end subroutine plane_strain_from_options

   !> The axisymmetric element `name` on `cell` with the EAS count of `options` (default 0).
   subroutine axisymmetric_from_options(name, cell, options, kinematics, element, error)
      character(len=*), intent(in) :: name
      class(reference_cell_t), intent(in) :: cell
      type(property_list_t), intent(in) :: options
      integer, intent(in) :: kinematics
      class(element_t), allocatable, intent(out) :: element
      type(error_t), allocatable, intent(out) :: error
      integer :: n_eas
      call options%check_names(spec_names(axisymmetric_options()), error)
      if (allocated(error)) return
      call eas_count(name, cell, options, n_eas, error)
      if (allocated(error)) return
      allocate (element, source=new_plane_solid(name, cell, kinematics, axisymmetric=.true., n_eas=n_eas))
   end subroutine axisymmetric_from_options

   !> The EAS option of `options` (0 when not given): 0 or 4 on a QUAD4 cell, 0 otherwise
   !> (frix_eas_modes%plane_eas_counts); another count is an error listing the valid ones.
   subroutine eas_count(name, cell, options, n_eas, error)
      character(len=*), intent(in) :: name
      class(reference_cell_t), intent(in) :: cell
      type(property_list_t), intent(in) :: options
      integer, intent(out) :: n_eas
      type(error_t), allocatable, intent(out) :: error
      logical :: found
      character(len=:), allocatable :: valid
      integer :: i
      call options%take_integer('EAS', n_eas, found, error, default=0)
      if (allocated(error)) return
      valid = '0'
      if (cell%n_nodes == 4) then
         do i = 2, size(plane_eas_counts)
            valid = valid//', '//to_string(plane_eas_counts(i))
         end do
         if (any(plane_eas_counts == n_eas)) return
      else if (n_eas == 0) then
         return
      end if
      call fatal_error(error, 'element shape '//name//': unsupported number of EAS parameters '// &
                       to_string(n_eas)//' (valid: '//valid//')')
   end subroutine eas_count

end module frix_plane_solid_options
