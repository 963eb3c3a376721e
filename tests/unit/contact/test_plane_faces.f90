!> The master faces of a plane pass (frix_contact_pass's set_plane_master_faces,
!> pass_positions, pass_node). References, by hand: the top edges of a plane block of 2 x 1
!> unit QUAD4 become the faces of corners at the edges' nodes moved to z = -h/2 and +h/2
!> (h = 1, the mean edge length), outward normal +y, free edges everywhere but the z edge at
!> the shared node x = 1; each corner moves with its node. The kernel on such a face, its force
!> and tangent summed over the two corners of each node (u_corner = u_node), is the contact of
!> a slave node in z = 0 against the edge: its normal and force lie in the x-y plane, and the
!> summed tangent equals central differences of the summed force under the nodes'
!> displacements (chain rule), frictionless and with Coulomb friction (stick and slip).
module test_plane_faces
   use frix_kinds, only: dp
   use frix_error, only: error_t, fatal_error
   use frix_testing, only: unittest_t, new_unittest, check, check_close
   use frix_strings, only: to_string
   use frix_mesh, only: mesh_t
   use frix_block_generator, only: generate_block
   use frix_face_projection, only: face_normal
   use frix_contact_parameters, only: contact_parameters_t
   use frix_contact_kernel, only: contact_point_result_t, node_face_contact, contact_stick, contact_slip
   use frix_contact_pass, only: contact_pass_t, set_plane_master_faces, pass_positions, pass_node
   use test_contact_fixtures, only: make_parameters
   implicit none
   private

   public :: collect_plane_faces

contains

   subroutine collect_plane_faces(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('plane block top: corner faces, normal +y, free edges', test_faces), &
               new_unittest('edge contact: in-plane force, corner-summed tangent = differences', test_tangent)]
   end subroutine collect_plane_faces

   !> The plane block [0, 2] x [0, 1] of 2 x 1 QUAD4 and the pass of its top edges.
   subroutine top_pass(mesh, pass, error)
      type(mesh_t), intent(out) :: mesh
      type(contact_pass_t), intent(out) :: pass
      type(error_t), allocatable, intent(out) :: error
      call generate_block('b', [0.0_dp, 0.0_dp, 0.0_dp], [2.0_dp, 1.0_dp, 0.0_dp], [2, 1, 0], 1, 1, mesh, error)
      if (allocated(error)) return
      call set_plane_master_faces(mesh, mesh%surfaces(mesh%find_surface('b_ymax')), pass)
   end subroutine top_pass

   subroutine test_faces(error)
      type(error_t), allocatable, intent(out) :: error
      type(mesh_t) :: mesh
      type(contact_pass_t) :: pass
      real(dp) :: x(3, 4), zero(3*6)
      integer :: f, k
      call top_pass(mesh, pass, error)
      if (allocated(error)) return
      call check(error, size(pass%faces, 2) == 2 .and. pass%plane, 'two faces of a plane pass')
      if (allocated(error)) return
      call check_close(error, pass%corner_height, 1.0_dp, 1.0e-15_dp, message='h = the mean edge length')
      if (allocated(error)) return
      zero = 0.0_dp
      do f = 1, 2
         x = pass_positions(pass, mesh%coords, zero, pass%faces(:, f))
         do k = 1, 4
            call check(error, all(abs(x(1:2, k) - mesh%coords(1:2, pass_node(pass, pass%faces(k, f)))) == 0.0_dp), &
                       'face '//to_string(f)//' corner '//to_string(k)//': at its node in x and y')
            if (allocated(error)) return
         end do
         call check(error, all(x(3, :) == [-0.5_dp, -0.5_dp, 0.5_dp, 0.5_dp]), 'corners at z = -h/2, -h/2, h/2, h/2')
         if (allocated(error)) return
         call check(error, maxval(abs(face_normal(x, [0.0_dp, 0.0_dp]) - [0.0_dp, 1.0_dp, 0.0_dp])) < 1.0e-15_dp, &
                    'face '//to_string(f)//': outward normal +y')
         if (allocated(error)) return
         ! edges 1 and 3 (z = -h/2, +h/2) belong to one face; of the z edges 2 and 4 only the
         ! one at the shared node x = 1 has a neighbour
         call check(error, pass%free_edge(1, f) .and. pass%free_edge(3, f), 'the z = -+h/2 edges are free')
         if (allocated(error)) return
         do k = 2, 4, 2
            call check(error, pass%free_edge(k, f) .eqv. abs(x(1, k) - 1.0_dp) > 0.5_dp, &
                       'face '//to_string(f)//' z edge '//to_string(k)//': free unless at x = 1')
            if (allocated(error)) return
         end do
      end do
      ! a displacement of node 5 (top, x = 1) moves the corners of both faces at x = 1
      zero(13:15) = [0.1_dp, -0.2_dp, 0.0_dp]
      x = pass_positions(pass, mesh%coords, zero, pass%faces(:, 1))
      do k = 1, 4
         if (pass_node(pass, pass%faces(k, 1)) == 5) then
            call check(error, abs(x(1, k) - 1.1_dp) < 1.0e-15_dp .and. abs(x(2, k) - 0.8_dp) < 1.0e-15_dp, &
                       'a corner of node 5 moves with it')
            if (allocated(error)) return
         end if
      end do
   end subroutine test_faces

   !> The kernel of a slave node in z = 0 just below face 1's middle line, its force and
   !> tangent folded onto the slave and the face's two nodes (9 unknowns), against central
   !> differences of the folded force.
   subroutine test_tangent(error)
      type(error_t), allocatable, intent(out) :: error
      type(mesh_t) :: mesh
      type(contact_pass_t) :: pass
      type(contact_point_result_t) :: result
      real(dp) :: q(9), force(9), tangent(9, 9), f_plus(9), f_minus(9), k_other(9, 9), h, worst
      real(dp) :: u(3*6)
      integer :: nodes(2), c, j, status
      integer, parameter :: expected(3) = [contact_slip, contact_stick, contact_slip]
      real(dp), parameter :: mu(3) = [0.0_dp, 0.3_dp, 0.3_dp]
      call top_pass(mesh, pass, error)
      if (allocated(error)) return
      nodes = pass_node(pass, pass%faces(1:2, 1))
      do c = 1, 3
         ! slave under face 1 (the top edge of element 1, from x = 1 to x = 0: xi_1 = 1 - 2 x)
         ! about 0.01 deep; its anchor xi_1 = 0.3 at x = 0.35 (stick: the slave there, the
         ! anchor moved 1e-3 by the nodes, a traction eps_T 1e-3 = 1 within mu p = 30; slip:
         ! the slave 0.05 away, 50 beyond 30)
         q(1:3) = [0.35_dp + merge(0.05_dp, 0.0_dp, c == 3), 0.99_dp, 0.0_dp]
         q(4:6) = mesh%coords(:, nodes(1)) + [0.002_dp, -0.001_dp, 0.0_dp]
         q(7:9) = mesh%coords(:, nodes(2)) + [-0.001_dp, 0.003_dp, 0.0_dp]
         call evaluate(q, mu(c), result, force, tangent)
         status = result%status
         call check(error, status == expected(c), 'case '//to_string(c)//': status '//to_string(status))
         if (allocated(error)) return
         call check(error, abs(result%normal(3)) < 1.0e-15_dp .and. maxval(abs(force(3::3))) < 1.0e-12_dp, &
                    'case '//to_string(c)//': normal and forces in the x-y plane')
         if (allocated(error)) return
         h = 1.0e-7_dp
         worst = 0.0_dp
         do j = 1, 9
            if (mod(j, 3) == 0) cycle   ! z: held by the plane model
            q(j) = q(j) + h
            call evaluate(q, mu(c), result, f_plus, k_other)
            q(j) = q(j) - 2.0_dp*h
            call evaluate(q, mu(c), result, f_minus, k_other)
            q(j) = q(j) + h
            worst = max(worst, maxval(abs((f_plus - f_minus)/(2.0_dp*h) - tangent(:, j))))
         end do
         if (.not. (worst <= 1.0e-7_dp*maxval(abs(tangent)))) then
            call fatal_error(error, 'case '//to_string(c)//': folded tangent vs differences '//to_string(worst)// &
                             ', max |K| '//to_string(maxval(abs(tangent))))
            return
         end if
      end do
   contains
      !> The kernel at slave position q(1:3) and node positions q(4:6), q(7:9) (the face's
      !> corners from them through pass_positions), folded: (slave, node 1, node 2).
      subroutine evaluate(q, coefficient, result, folded_force, folded_tangent)
         real(dp), intent(in) :: q(9), coefficient
         type(contact_point_result_t), intent(out) :: result
         real(dp), intent(out) :: folded_force(9), folded_tangent(9, 9)
         type(contact_parameters_t) :: parameters
         real(dp) :: force(15), tangent(15, 15), x_face(3, 4), fold(15, 9)
         integer :: k, a, b
         u = 0.0_dp
         u(3*nodes(1) - 2:3*nodes(1)) = q(4:6) - mesh%coords(:, nodes(1))
         u(3*nodes(2) - 2:3*nodes(2)) = q(7:9) - mesh%coords(:, nodes(2))
         x_face = pass_positions(pass, mesh%coords, u, pass%faces(:, 1))
         parameters = make_parameters(coefficient)
         call node_face_contact(parameters, q(1:3), x_face, 0.5_dp, [0.3_dp, 0.0_dp], .true., .true., &
                                result, force, tangent)
         ! fold(3 (a - 1) + i, 3 (b - 1) + i) = 1: kernel node a (slave, 4 corners) is unknown b
         fold = 0.0_dp
         do a = 1, 5
            b = 1
            if (a > 1) b = 1 + findloc(nodes, pass_node(pass, pass%faces(a - 1, 1)), dim=1)
            do k = 1, 3
               fold(3*(a - 1) + k, 3*(b - 1) + k) = 1.0_dp
            end do
         end do
         folded_force = matmul(transpose(fold), force)
         folded_tangent = matmul(transpose(fold), matmul(tangent, fold))
      end subroutine evaluate
   end subroutine test_tangent
end module test_plane_faces
