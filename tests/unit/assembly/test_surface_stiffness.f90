!> The stiffness M/h of the elements under a surface (frix_surface_stiffness), from which an
!> automatic contact penalty is derived, on a block of known E, nu and element sizes:
!> M = E (1 - nu)/((1 + nu)(1 - 2 nu)) (the constrained modulus lambda + 2 mu of Hooke's law)
!> and h = the element's thickness normal to the face; for the edges of PLANE4 (THICKNESS 0.1:
!> it cancels) h = the element's size normal to the edge, for AXISYM4 the same times the ratio
!> of the element's centroid radius to the edge's radius (V = 2 pi R_c A, A_edge = 2 pi r L).
module test_surface_stiffness
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_testing, only: unittest_t, new_unittest, check, check_close
   use frix_property_list, only: property_list_t
   use frix_block_generator, only: generate_block
   use frix_material_registry, only: create_material
   use frix_element, only: kinematics_linear
   use frix_element_registry, only: create_element
   use frix_model, only: model_t
   use frix_surface_stiffness, only: representative_modulus, face_stiffness, surface_stiffness
   implicit none
   private

   public :: collect_surface_stiffness

   real(dp), parameter :: young = 1000.0_dp, poisson = 0.3_dp
   !> the block's size and divisions: elements 0.5 (x) by 0.5 (y) by 0.25 (z)
   real(dp), parameter :: lengths(3) = [2.0_dp, 1.0_dp, 0.5_dp]
   integer, parameter :: divisions(3) = [4, 2, 2]

contains

   subroutine collect_surface_stiffness(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('M of Hooke: E (1 - nu)/((1 + nu)(1 - 2 nu))', test_modulus), &
               new_unittest('M/h of a block''s faces: h = element thickness normal to the face', test_block), &
               new_unittest('M/h of a sheared block: h = its height, unchanged', test_sheared), &
               new_unittest('M/h of plane elements'' edges: PLANE4 and AXISYM4', test_plane)]
   end subroutine collect_surface_stiffness

   !> E (1 - nu)/((1 + nu)(1 - 2 nu)) for E = 1000, nu = 0.3.
   pure real(dp) function constrained_modulus()
      constrained_modulus = young*(1.0_dp - poisson)/((1.0_dp + poisson)*(1.0_dp - 2.0_dp*poisson))
   end function constrained_modulus

   !> The block `lengths` / `divisions` of HEX8 (no EAS) elements of Hooke's law (E, nu).
   subroutine block_model(model, error)
      type(model_t), intent(out) :: model
      type(error_t), allocatable, intent(out) :: error
      type(property_list_t) :: no_options
      call generate_block('blk', [0.0_dp, 0.0_dp, 0.0_dp], lengths, divisions, 1, 1, model%mesh, error)
      if (allocated(error)) return
      allocate (model%materials(1), model%blocks(1))
      call create_material('MAT_Struct_LinearElastic', [character(len=5) :: 'YOUNG', 'NUE'], [young, poisson], &
                           model%materials(1)%law, error)
      if (allocated(error)) return
      call create_element('HEX8', no_options, kinematics_linear, model%blocks(1)%element%formulation, error)
      if (allocated(error)) return
      model%blocks(1)%material = 1
      if (allocated(model%mesh%element_block)) deallocate (model%mesh%element_block)
      allocate (model%mesh%element_block(model%mesh%n_elements), source=1)
   end subroutine block_model

   subroutine test_modulus(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      call block_model(model, error)
      if (allocated(error)) return
      ! 1000 x 0.7/(1.3 x 0.4) = 1346.153846...
      call check_close(error, representative_modulus(model%materials(1)%law), constrained_modulus(), 1.0e-14_dp, &
                       message='M of Hooke''s law')
   end subroutine test_modulus

   !> zmin/zmax faces: h = 0.25; xmin/xmax: h = 0.5; ymin: h = 0.5 (each element's thickness
   !> normal to the face); every face of a surface alike, so the mean is each face's value.
   subroutine test_block(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      call block_model(model, error)
      if (allocated(error)) return
      call check_surface(model, 'blk_zmin', 0.25_dp, error)
      if (allocated(error)) return
      call check_surface(model, 'blk_zmax', 0.25_dp, error)
      if (allocated(error)) return
      call check_surface(model, 'blk_xmin', 0.5_dp, error)
      if (allocated(error)) return
      call check_surface(model, 'blk_ymin', 0.5_dp, error)
   end subroutine test_block

   !> The block sheared (x += 0.6 z): volumes and the z faces' areas are unchanged, so the z
   !> faces keep h = 0.25.
   subroutine test_sheared(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      call block_model(model, error)
      if (allocated(error)) return
      model%mesh%coords(1, :) = model%mesh%coords(1, :) + 0.6_dp*model%mesh%coords(3, :)
      call check_surface(model, 'blk_zmin', 0.25_dp, error)
      if (allocated(error)) return
      call check_surface(model, 'blk_zmax', 0.25_dp, error)
   end subroutine test_sheared

   !> A plane block [1, 3] x [0, 1] of 4 x 4 elements 0.5 x 0.25: PLANE4 (THICKNESS 0.1) edges
   !> of y = const have h = 0.25, of x = const h = 0.5; AXISYM4 (x = r): the edges of
   !> y = const h = 0.25 R_c / r = 0.25 (their element's centroid is at the edge's mid-radius),
   !> the edges r = 1 and r = 3 h = 0.5 (R_c / r) with R_c = 1.25 and 2.75.
   subroutine test_plane(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(property_list_t) :: options
      integer :: surface, k
      call generate_block('blk', [1.0_dp, 0.0_dp, 0.0_dp], [2.0_dp, 1.0_dp, 0.0_dp], [4, 4, 0], 1, 1, model%mesh, error)
      if (allocated(error)) return
      allocate (model%materials(1), model%blocks(1))
      call create_material('MAT_Struct_LinearElastic', [character(len=5) :: 'YOUNG', 'NUE'], [young, poisson], &
                           model%materials(1)%law, error)
      if (allocated(error)) return
      call options%add('THICKNESS', 0.1_dp)
      call create_element('PLANE4', options, kinematics_linear, model%blocks(1)%element%formulation, error)
      if (allocated(error)) return
      model%blocks(1)%material = 1
      if (allocated(model%mesh%element_block)) deallocate (model%mesh%element_block)
      allocate (model%mesh%element_block(model%mesh%n_elements), source=1)
      call check_surface(model, 'blk_ymin', 0.25_dp, error)
      if (allocated(error)) return
      call check_surface(model, 'blk_xmax', 0.5_dp, error)
      if (allocated(error)) return
      deallocate (model%blocks(1)%element%formulation)
      call create_element('AXISYM4', property_list_t(), kinematics_linear, model%blocks(1)%element%formulation, error)
      if (allocated(error)) return
      call check_surface(model, 'blk_ymax', 0.25_dp, error)
      if (allocated(error)) return
      surface = model%mesh%find_surface('blk_xmin')
      associate (faces => model%mesh%surfaces(surface))
         do k = 1, size(faces%elements)
            call check_close(error, face_stiffness(model, faces%elements(k), faces%faces(k)), &
                             constrained_modulus()/(0.5_dp*1.25_dp), 1.0e-12_dp, message='AXISYM4 M/h at r = 1')
            if (allocated(error)) return
         end do
      end associate
      surface = model%mesh%find_surface('blk_xmax')
      associate (faces => model%mesh%surfaces(surface))
         do k = 1, size(faces%elements)
            call check_close(error, face_stiffness(model, faces%elements(k), faces%faces(k)), &
                             constrained_modulus()/(0.5_dp*2.75_dp/3.0_dp), 1.0e-12_dp, message='AXISYM4 M/h at r = 3')
            if (allocated(error)) return
         end do
      end associate
   end subroutine test_plane

   !> Every face of surface `name` and the surface's mean give M/h.
   subroutine check_surface(model, name, h, error)
      type(model_t), intent(in) :: model
      character(len=*), intent(in) :: name
      real(dp), intent(in) :: h   !! the elements' thickness normal to the surface
      type(error_t), allocatable, intent(out) :: error
      integer :: surface, k
      surface = model%mesh%find_surface(name)
      call check(error, surface > 0, 'no surface '//name)
      if (allocated(error)) return
      call check(error, size(model%mesh%surfaces(surface)%elements) > 0, 'surface '//name//' has no face')
      if (allocated(error)) return
      associate (faces => model%mesh%surfaces(surface))
         do k = 1, size(faces%elements)
            call check_close(error, face_stiffness(model, faces%elements(k), faces%faces(k)), &
                             constrained_modulus()/h, 1.0e-12_dp, message='M/h of a face of '//name)
            if (allocated(error)) return
         end do
      end associate
      call check_close(error, surface_stiffness(model, surface), constrained_modulus()/h, 1.0e-12_dp, &
                       message='mean M/h of '//name)
   end subroutine check_surface
end module test_surface_stiffness
