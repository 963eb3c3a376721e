!> Writes POS3D neutral files from synthetic data for tests/pos3d/check_synthetic.py, and checks
!> the writer's error returns. Usage: pos3d_writer_check OUTPUT_DIRECTORY
!>
!> Mesh: a 3 x 2 x 2 block of HEX8 on [0,3] x [0,2] x [0,1], nodes numbered x fastest, then y,
!> then z, every node moved by a small node-dependent offset (so that each element is a
!> general trilinear hexahedron; the same formula is in check_synthetic.py).
!> Synthetic fields at load factor f (the same formulas are in check_synthetic.py):
!>   u(x)            = f 1e-3 (x + 2 y, y z - x, 3 z + x y)
!>   stress_c(x)     = f (100 c + (c + 1) x - 2 c y + 3 z),  c = 1..6 (frix Voigt order),
!>                     evaluated at each Gauss point's physical position (point g at s_g/sqrt(3),
!>                     s_g the VTK corner signs of node g): linear in x, hence trilinear in the
!>                     natural coordinates, so the nodal extrapolation is exact;
!>   CONTACT_PRESSURE = f (x + y),  CONTACT_SHEAR = f z^2 (nodal).
!> Files: synthetic.pos (steps f = 0.5, 1.0; materials (1000, 0.3) for elements with centroid
!> x < 1.5, (2000, 0.25) otherwise; closed), crashed.pos (one step f = 0.5, never closed, dummy
!> material). Prints "N passed, N failed" for its own error checks; exit status 1 if any failed.
program pos3d_writer_check
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_mesh, only: mesh_t
   use frix_pos3d_writer, only: pos3d_writer_t
   implicit none

   integer, parameter :: nx = 3, ny = 2, nz = 2
   !> VTK corner signs, written out here independently of frix_field_recovery.
   integer, parameter :: corner_signs(3, 8) = reshape([-1, -1, -1, 1, -1, -1, 1, 1, -1, -1, 1, -1, &
                                                       -1, -1, 1, 1, -1, 1, 1, 1, 1, -1, 1, 1], [3, 8])
   type(mesh_t) :: mesh
   type(pos3d_writer_t) :: writer, crashed, bad
   type(error_t), allocatable :: error
   character(len=:), allocatable :: directory
   character(len=512) :: argument
   real(dp), allocatable :: materials(:, :), bad_displacement(:, :)
   integer, allocatable :: element_material(:)
   integer :: n_passed, n_failed, e, length
   character(len=16), parameter :: names(2) = [character(len=16) :: 'CONTACT_PRESSURE', 'CONTACT_SHEAR']

   n_passed = 0
   n_failed = 0
   if (command_argument_count() /= 1) then
      write (0, '(a)') 'usage: pos3d_writer_check OUTPUT_DIRECTORY'
      error stop 2
   end if
   call get_command_argument(1, argument, length)
   directory = trim(argument)

   call build_mesh(mesh)
   allocate (element_material(mesh%n_elements))
   do e = 1, mesh%n_elements
      element_material(e) = merge(1, 2, sum(mesh%coords(1, mesh%connectivity(:, e)))/8.0_dp < 1.5_dp)
   end do
   materials = reshape([1000.0_dp, 0.3_dp, 2000.0_dp, 0.25_dp], [2, 2])

   call writer%open(directory//'/synthetic.pos', "synthetic 3x2x2 block, frix's pos3d check", mesh, error, &
                    materials=materials, element_material=element_material)
   call expect_success('open synthetic.pos')
   call write_step(writer, 0.5_dp, 'step 1 of synthetic.pos')
   call write_step(writer, 1.0_dp, 'step 2 of synthetic.pos')
   call expect(writer%n_steps() == 2, 'n_steps counts 2 steps')
   call writer%close(error)
   call expect_success('close synthetic.pos')
   call write_step_expect_error(writer, 'add_step after close')

   call crashed%open(directory//'/crashed.pos', 'a run that stops after its first step', mesh, error)
   call expect_success('open crashed.pos')
   call write_step(crashed, 0.5_dp, 'step 1 of crashed.pos')
   ! no close: the file must already be complete

   call bad%open(directory//'/no_such_folder/x.pos', 'x', mesh, error)
   call expect(allocated(error), 'open in a missing folder returns an error')
   if (allocated(error)) deallocate (error)

   call bad%open(directory//'/bad.pos', 'x', mesh, error, materials=materials)
   call expect(allocated(error), 'materials without element_material returns an error')
   if (allocated(error)) deallocate (error)
   element_material(1) = 3
   call bad%open(directory//'/bad.pos', 'x', mesh, error, materials=materials, element_material=element_material)
   call expect(allocated(error), 'material index out of range returns an error')
   if (allocated(error)) deallocate (error)

   call bad%open(directory//'/bad.pos', 'x', mesh, error)
   call expect_success('open bad.pos')
   allocate (bad_displacement(3, mesh%n_nodes - 1))
   bad_displacement = 0.0_dp
   call bad%add_step(1.0_dp, bad_displacement, stress_field(mesh, 1.0_dp), [character(len=1) ::], &
                     reshape([real(dp) ::], [0, mesh%n_nodes]), error)
   call expect(allocated(error), 'displacement of the wrong shape returns an error')
   if (allocated(error)) deallocate (error)
   call bad%add_step(1.0_dp, displacement_field(mesh, 1.0_dp), stress_field(mesh, 1.0_dp), ['BAD''NAME'], &
                     reshape([(0.0_dp, e=1, mesh%n_nodes)], [1, mesh%n_nodes]), error)
   call expect(allocated(error), 'a quote in a scalar name returns an error')
   if (allocated(error)) deallocate (error)
   call bad%add_step(1.0_dp, displacement_field(mesh, 1.0_dp), stress_field(mesh, 1.0_dp), names, &
                     reshape([(0.0_dp, e=1, mesh%n_nodes)], [1, mesh%n_nodes]), error)
   call expect(allocated(error), 'nodal_scalars of the wrong shape returns an error')
   if (allocated(error)) deallocate (error)
   call expect(bad%n_steps() == 0, 'failed steps are not counted')
   call bad%close(error)
   call expect_success('close bad.pos')

   ! main-program variables outlive the program's end: freed here for LeakSanitizer
   deallocate (directory, element_material, materials, bad_displacement)
   write (*, '(i0,a,i0,a)') n_passed, ' passed, ', n_failed, ' failed'
   if (n_failed > 0) error stop 1

contains

   subroutine build_mesh(mesh)
      type(mesh_t), intent(out) :: mesh
      integer :: i, j, k, n
      mesh%n_nodes = (nx + 1)*(ny + 1)*(nz + 1)
      mesh%n_elements = nx*ny*nz
      allocate (mesh%coords(3, mesh%n_nodes), mesh%node_ids(mesh%n_nodes))
      allocate (mesh%connectivity(8, mesh%n_elements), mesh%element_ids(mesh%n_elements))
      allocate (mesh%element_block(mesh%n_elements))
      do k = 0, nz
         do j = 0, ny
            do i = 0, nx
               n = node_number(i, j, k)
               ! offsets up to 0.08: elements stay convex and right-handed
               mesh%coords(:, n) = [real(i, dp) + 0.08_dp*sin(1.3_dp*n), real(j, dp) + 0.06_dp*cos(0.7_dp*n), &
                                    0.5_dp*real(k, dp) + 0.04_dp*sin(2.1_dp*n)]
               mesh%node_ids(n) = 100 + n
            end do
         end do
      end do
      n = 0
      do k = 0, nz - 1
         do j = 0, ny - 1
            do i = 0, nx - 1
               n = n + 1
               mesh%connectivity(:, n) = [node_number(i, j, k), node_number(i + 1, j, k), node_number(i + 1, j + 1, k), &
                                          node_number(i, j + 1, k), node_number(i, j, k + 1), node_number(i + 1, j, k + 1), &
                                          node_number(i + 1, j + 1, k + 1), node_number(i, j + 1, k + 1)]
               mesh%element_ids(n) = 500 + n
               mesh%element_block(n) = 1
            end do
         end do
      end do
   end subroutine build_mesh

   pure integer function node_number(i, j, k)
      integer, intent(in) :: i, j, k
      node_number = 1 + i + (nx + 1)*(j + (ny + 1)*k)
   end function node_number

   function displacement_field(mesh, factor) result(u)
      type(mesh_t), intent(in) :: mesh
      real(dp), intent(in) :: factor
      real(dp) :: u(3, mesh%n_nodes)
      integer :: n
      do n = 1, mesh%n_nodes
         associate (x => mesh%coords(1, n), y => mesh%coords(2, n), z => mesh%coords(3, n))
            u(:, n) = factor*1.0e-3_dp*[x + 2.0_dp*y, y*z - x, 3.0_dp*z + x*y]
         end associate
      end do
   end function displacement_field

   function stress_field(mesh, factor) result(stress)
      type(mesh_t), intent(in) :: mesh
      real(dp), intent(in) :: factor
      real(dp) :: stress(6, 8, mesh%n_elements)
      real(dp) :: point(3), shape_values(8), position(3)
      integer :: e, g, a, c
      do e = 1, mesh%n_elements
         do g = 1, 8
            point = real(corner_signs(:, g), dp)/sqrt(3.0_dp)
            do a = 1, 8
               shape_values(a) = product(1.0_dp + real(corner_signs(:, a), dp)*point)/8.0_dp
            end do
            position = matmul(mesh%coords(:, mesh%connectivity(:, e)), shape_values)
            do c = 1, 6
               stress(c, g, e) = factor*(100.0_dp*c + (c + 1)*position(1) - 2.0_dp*c*position(2) + 3.0_dp*position(3))
            end do
         end do
      end do
   end function stress_field

   subroutine write_step(target_writer, factor, label)
      type(pos3d_writer_t), intent(inout) :: target_writer
      real(dp), intent(in) :: factor
      character(len=*), intent(in) :: label
      real(dp) :: scalars(2, mesh%n_nodes)
      scalars(1, :) = factor*(mesh%coords(1, :) + mesh%coords(2, :))
      scalars(2, :) = factor*mesh%coords(3, :)**2
      call target_writer%add_step(factor, displacement_field(mesh, factor), stress_field(mesh, factor), names, scalars, error)
      call expect_success(label)
   end subroutine write_step

   subroutine write_step_expect_error(target_writer, label)
      type(pos3d_writer_t), intent(inout) :: target_writer
      character(len=*), intent(in) :: label
      real(dp) :: scalars(2, mesh%n_nodes)
      scalars = 0.0_dp
      call target_writer%add_step(1.0_dp, displacement_field(mesh, 1.0_dp), stress_field(mesh, 1.0_dp), names, scalars, error)
      call expect(allocated(error), label//' returns an error')
      if (allocated(error)) deallocate (error)
   end subroutine write_step_expect_error

   subroutine expect_success(label)
      character(len=*), intent(in) :: label
      if (allocated(error)) then
         write (*, '(a)') 'FAILED: '//label//': '//error%message
         n_failed = n_failed + 1
         deallocate (error)
      else
         n_passed = n_passed + 1
      end if
   end subroutine expect_success

   subroutine expect(condition, label)
      logical, intent(in) :: condition
      character(len=*), intent(in) :: label
      if (condition) then
         n_passed = n_passed + 1
      else
         write (*, '(a)') 'FAILED: '//label
         n_failed = n_failed + 1
      end if
   end subroutine expect
end program pos3d_writer_check
