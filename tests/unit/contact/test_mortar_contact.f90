!> Mortar integrals and mortar contact (frix_mortar_segments, frix_mortar_contact).
!> References:
!> - one slave face [0, 1]^2 (z = 0, outward -z) over half of a master face [0.5, 1.5] x [0, 1]
!>   (z = -0.1, outward +z), by hand: the dual basis of the unit square is the tensor product
!>   of the 1D duals psi_1 = 2 - 3 x, psi_2 = 3 x - 1 (int psi_i N_k dx = delta_ik / 2 on
!>   [0, 1]), y is fully covered, so each integral is (1/2) delta_(y) times an x integral over
!>   [0.5, 1]: int psi_1 (1.5 - x) = -1/16, int psi_1 (x - 0.5) = -1/16, int psi_2 (1.5 - x) =
!>   7/16, int psi_2 (x - 0.5) = 3/16 (master), int psi_1 (1 - x) = 0, int psi_1 x = -1/8,
!>   int psi_2 (1 - x) = 1/8, int psi_2 x = 1/2 (slave);
!> - a 3 x 3 slave grid on [0, 1]^2 covered by a 4 x 4 master grid on [-0.2, 1.2]^2 tilted as
!>   z = -0.1 + 0.05 x: D_j equals the tributary area (1/9, 1/18, 1/36), sum_l M_jl = D_j, and
!>   the mean gap g_j / D_j equals (0.1 - 0.05 x_j) / (1 + 0.05^2): a slave point (x, y, 0) is
!>   paired with its closest point on the master plane, which lies along the master's normal
!>   (tilt tan t = 0.05), so (x_s - x_m) . e_z = (0.1 - 0.05 x) cos^2 t, linear in x, which the
!>   dual basis reproduces (int phi_j f dA = D_j f(x_j) where covered);
!> - the tangent of one slave node against central differences of its internal force with the
!>   mortar rows (D, M, n) held fixed, as the tangent is defined (docs/contact.md, "Mortar
!>   contact"): relative step 1e-7, tolerance 1e-8 as in test_contact_fixtures.
module test_mortar_contact
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_testing, only: unittest_t, new_unittest, check, check_close
   use frix_strings, only: to_string
   use frix_mortar_segments, only: segment_integrals
   use frix_mortar_contact, only: mortar_rows_t, mortar_rows, mortar_node_contact
   use frix_penalty_normal_law, only: new_penalty_normal_law
   use frix_contact_kernel, only: contact_point_result_t, contact_slip
   use test_contact_fixtures, only: grid_faces
   implicit none
   private

   public :: collect_mortar_contact

contains

   subroutine collect_mortar_contact(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('half-covered unit face: D and M by hand', test_half_face), &
               new_unittest('covered grid: D = tributary area, sum M = D, linear gap', test_covered_grid), &
               new_unittest('tangent = central differences with D, M, n fixed', test_tangent)]
   end subroutine collect_mortar_contact

   subroutine test_half_face(error)
      type(error_t), allocatable, intent(out) :: error
      ! slave nodes (x, y): (0, 0), (0, 1), (1, 1), (1, 0); master (0.5, 0), (1.5, 0), (1.5, 1), (0.5, 1)
      real(dp), parameter :: x_slave(3, 4) = reshape([0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 1.0_dp, 0.0_dp, &
                                                      1.0_dp, 1.0_dp, 0.0_dp, 1.0_dp, 0.0_dp, 0.0_dp], [3, 4])
      real(dp), parameter :: x_master(3, 4) = reshape([0.5_dp, 0.0_dp, -0.1_dp, 1.5_dp, 0.0_dp, -0.1_dp, &
                                                       1.5_dp, 1.0_dp, -0.1_dp, 0.5_dp, 1.0_dp, -0.1_dp], [3, 4])
      ! x integrals over [0.5, 1] (header): master(i, k), slave(i, k), i the slave node's x index
      real(dp), parameter :: x_master_integral(2, 2) = reshape([-1.0_dp/16, 7.0_dp/16, -1.0_dp/16, 3.0_dp/16], [2, 2])
      real(dp), parameter :: x_slave_integral(2, 2) = reshape([0.0_dp, 1.0_dp/8, -1.0_dp/8, 0.5_dp], [2, 2])
      real(dp) :: master_part(4, 4), slave_part(4, 4), expected_m(4, 4), expected_d(4, 4)
      logical :: overlap
      integer :: j, a
      do j = 1, 4
         do a = 1, 4
            expected_m(j, a) = 0.0_dp
            expected_d(j, a) = 0.0_dp
            if (x_slave(2, j) == x_master(2, a)) &
               expected_m(j, a) = 0.5_dp*x_master_integral(x_index(x_slave(1, j)), x_index(x_master(1, a) - 0.5_dp))
            if (x_slave(2, j) == x_slave(2, a)) &
               expected_d(j, a) = 0.5_dp*x_slave_integral(x_index(x_slave(1, j)), x_index(x_slave(1, a)))
         end do
      end do
      call segment_integrals(x_slave, x_master, 0.5_dp, master_part, slave_part, overlap)
      call check(error, overlap, 'no overlap found')
      if (allocated(error)) return
      call check(error, maxval(abs(master_part - expected_m)) <= 1.0e-14_dp, &
                 'M off by '//to_string(maxval(abs(master_part - expected_m))))
      if (allocated(error)) return
      call check(error, maxval(abs(slave_part - expected_d)) <= 1.0e-14_dp, &
                 'D off by '//to_string(maxval(abs(slave_part - expected_d))))
      if (allocated(error)) return
      ! the master face moved out of reach (centre 0.6 from the slave plane, distance 0.5): nothing
      call segment_integrals(x_slave, x_master - spread([0.0_dp, 0.0_dp, 0.5_dp], 2, 4), 0.5_dp, master_part, &
                             slave_part, overlap)
      call check(error, .not. overlap .and. all(master_part == 0.0_dp), 'a face beyond the distance overlaps')
   contains
      pure integer function x_index(x)
         real(dp), intent(in) :: x
         x_index = merge(1, 2, x < 0.5_dp)
      end function x_index
   end subroutine test_half_face

   !> The slave grid (nodes 1-16 at (i/3, j/3, 0), faces turned to face -z) above the master grid
   !> (nodes 17-41 at (-0.2 + 0.35 i, -0.2 + 0.35 j, -0.1 + 0.05 x)) and the mortar rows.
   subroutine grid_rows(coords, rows)
      real(dp), intent(out) :: coords(3, 41)
      type(mortar_rows_t), intent(out) :: rows
      integer :: slave_faces(4, 9), master_faces(4, 16), i, j
      real(dp) :: x
      do j = 0, 3
         do i = 0, 3
            coords(:, 1 + i + 4*j) = [real(i, dp)/3.0_dp, real(j, dp)/3.0_dp, 0.0_dp]
         end do
      end do
      do j = 0, 4
         do i = 0, 4
            x = -0.2_dp + 0.35_dp*i
            coords(:, 17 + i + 5*j) = [x, -0.2_dp + 0.35_dp*j, -0.1_dp + 0.05_dp*x]
         end do
      end do
      slave_faces = grid_faces(3)
      slave_faces = slave_faces([1, 4, 3, 2], :)   ! clockwise from above: outward -z
      master_faces = grid_faces(4) + 16
      call mortar_rows(coords, [(i, i=1, 16)], slave_faces, master_faces, 0.5_dp, rows)
   end subroutine grid_rows

   subroutine test_covered_grid(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: coords(3, 41), area, gap
      type(mortar_rows_t) :: rows
      integer :: j, i_x, i_y, edges
      call grid_rows(coords, rows)
      do j = 1, 16
         i_x = mod(j - 1, 4)
         i_y = (j - 1)/4
         edges = count([i_x == 0 .or. i_x == 3, i_y == 0 .or. i_y == 3])
         area = (1.0_dp/9.0_dp)/2.0_dp**edges
         call check_close(error, rows%dual_area(j), area, 1.0e-13_dp, message='D of node '//to_string(j))
         if (allocated(error)) return
         associate (c => rows%weight(rows%start(j) + 1:rows%start(j + 1)), nodes => rows%nodes(rows%start(j) + 1:rows%start(j + 1)))
            call check(error, abs(sum(c)) <= 1.0e-14_dp, 'node '//to_string(j)//': sum D - sum M = '// &
                       to_string(sum(c)))
            if (allocated(error)) return
            call check(error, maxval(abs(rows%normal(:, j) - [0.0_dp, 0.0_dp, 1.0_dp])) <= 1.0e-15_dp, &
                       'normal of node '//to_string(j))
            if (allocated(error)) return
            gap = dot_product(rows%normal(:, j), matmul(coords(:, nodes), c))/rows%dual_area(j)
         end associate
         call check_close(error, gap, (0.1_dp - 0.05_dp*coords(1, j))/(1.0_dp + 0.05_dp**2), 1.0e-13_dp, &
                          message='mean gap of node '//to_string(j))
         if (allocated(error)) return
      end do
   end subroutine test_covered_grid

   !> Node 6 (interior) of the covered grid pressed 0.02 into the master (slave grid lowered by
   !> 0.12 - 0.05 x: penetration 0.02 + ...), eps_N = 1e4; every row node's coordinates perturbed.
   subroutine test_tangent(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: coords(3, 41), h, largest
      type(mortar_rows_t) :: rows
      type(contact_point_result_t) :: result
      real(dp), allocatable :: x(:, :), fint(:), tangent(:, :), plus(:), minus(:), differences(:, :), dummy(:, :)
      integer :: n, k, c
      integer, parameter :: j = 6
      call grid_rows(coords, rows)
      coords(3, :16) = coords(3, :16) - 0.12_dp + 0.05_dp*coords(1, :16)
      associate (nodes => rows%nodes(rows%start(j) + 1:rows%start(j + 1)))
         n = size(nodes)
         x = coords(:, nodes)
      end associate
      allocate (fint(3*n), plus(3*n), minus(3*n), tangent(3*n, 3*n), differences(3*n, 3*n), dummy(3*n, 3*n))
      call mortar_node_contact(new_penalty_normal_law(1.0e4_dp), rows, j, x, 1.0_dp/9.0_dp, result, fint, tangent)
      call check(error, result%status == contact_slip .and. result%pressure > 0.0_dp, &
                 'node not in contact: gap '//to_string(result%gap))
      if (allocated(error)) return
      h = 1.0e-7_dp
      do k = 1, n
         do c = 1, 3
            x(c, k) = x(c, k) + h
            call mortar_node_contact(new_penalty_normal_law(1.0e4_dp), rows, j, x, 1.0_dp/9.0_dp, result, plus, dummy)
            x(c, k) = x(c, k) - 2.0_dp*h
            call mortar_node_contact(new_penalty_normal_law(1.0e4_dp), rows, j, x, 1.0_dp/9.0_dp, result, minus, dummy)
            x(c, k) = x(c, k) + h
            differences(:, 3*k - 3 + c) = (plus - minus)/(2.0_dp*h)
         end do
      end do
      largest = maxval(abs(tangent))
      call check(error, maxval(abs(differences - tangent)) <= 1.0e-8_dp*largest, &
                 'tangent off by '//to_string(maxval(abs(differences - tangent))/largest)//' of its largest entry')
      if (allocated(error)) return
      call check(error, maxval(abs(tangent - transpose(tangent))) <= 1.0e-14_dp*largest, 'tangent not symmetric')
   end subroutine test_tangent
end module test_mortar_contact
