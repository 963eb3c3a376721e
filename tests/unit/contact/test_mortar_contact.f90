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
!> - the tangent of one slave node (frictionless, stick, slip) against central differences of
!>   its internal force: frictionless with the mortar rows held fixed, exact (relative step
!>   1e-7, tolerance 1e-8 as in test_contact_fixtures); all three against the full force, the
!>   rows recomputed, up to the terms the tangent leaves out (docs/contact.md, "Mortar
!>   contact"; test_tangent);
!> - degenerate faces (all four nodes at one point; two nodes coinciding, a triangle): no NaN
!>   anywhere, the collapsed face contributes nothing (zero normal and D_j at its nodes), the
!>   triangle over a larger master face is covered and D_j = sum_l M_jl there (sum_a N_a^m = 1);
!> - the slave grid shrunk in its plane by 0.6 about its centre (area 0.36 of the reference,
!>   below least_mortar_coverage = 0.5 of the reference tributary area) and pressed 1e-6 into
!>   the master (so tilted as the master, z = -0.1 - 1e-6 + 0.05 x): every node covered,
!>   a_j = 0.36 sqrt(1 + 0.05^2) times the flat grid's tributary area (1/9, 1/18, 1/36; the
!>   faces are parallelograms, exact), the interior node 6 in contact;
!> - first touch: the slave grid 0.1 above the flat master (open) at the last commit, now slid
!>   by s = (0.03, -0.02) and pressed 1e-6 into it (mu 0.3): the interior node, started from
!>   its current row as a node open at the last commit, has no tangential traction (exactly 0:
!>   no slip increment), where taking the committed row would give it the slip traction
!>   mu p_j (|s| = 0.036 is far beyond the stick limit mu p_j / eps_T);
!> - the weighted slip increment sum_k (c^n_jk - c_jk) x_k of a slave grid slid by s over a
!>   flat master: D_j s (the integrals are exact there); of both grids moved rigidly: 0.
module test_mortar_contact
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_testing, only: unittest_t, new_unittest, check, check_close
   use frix_strings, only: to_string
   use frix_mortar_segments, only: segment_integrals
   use frix_mortar_contact, only: mortar_rows_t, mortar_rows, mortar_node_t, mortar_node, mortar_node_contact, &
                                  mortar_covered
   use frix_contact_parameters, only: contact_parameters_t
   use frix_contact_kernel, only: contact_point_result_t, contact_slip, contact_stick
   use frix_friction_law, only: branch_free
   use test_contact_fixtures, only: grid_faces, make_parameters
   implicit none
   private

   public :: collect_mortar_contact

contains

   subroutine collect_mortar_contact(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('half-covered unit face: D and M by hand', test_half_face), &
               new_unittest('covered grid: D = tributary area, sum M = D, linear gap', test_covered_grid), &
               new_unittest('tangent against central differences (frictionless, stick, slip)', test_tangent), &
               new_unittest('objective slip: a slide gives D_j s, a rigid motion none', test_objective_slip), &
               new_unittest('degenerate faces: zero area and coincident nodes give no NaN', test_degenerate_faces), &
               new_unittest('coverage in the current configuration: a shrunk slave grid stays covered', &
                            test_shrunk_coverage), &
               new_unittest('first touch: motion before contact is no slip', test_first_touch)]
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

   !> Node 6 (interior) of the covered grid pressed 1e-6 into the master (slave grid lowered by
   !> 0.1 + 1e-6 - 0.05 x), eps_N = 1e4, eps_T = 1e3 (make_parameters); its committed row taken
   !> with the slave grid 1e-6 further back in x and y (a slip of (1e-6, 1e-6) since) and
   !> t^n = (3e-3, -2e-3, 0): mu = 0 (frictionless), mu = 10 (stick), mu = 0.1 (slip: |t_trial| =
   !> |(3e-3, -2e-3) - 1e3 (1e-6, 1e-6)| = 3.6e-3 against mu p = 0.1 x 1e4 x 1e-6 = 1e-3).
   !> Frictionless, with the rows held fixed, the tangent is the exact derivative (1e-8) and
   !> symmetric. Against the derivative of the full force (the rows recomputed at every
   !> perturbed position, central differences, step 1e-8), what the tangent leaves out is of
   !> relative order |g| / h, slip / h, |t^n| / (eps_T h) (1e-5 here, h = 1/3: frix_mortar_contact):
   !> bound 1e-5 of the largest entry (that estimate); measured 1.5e-6 in all three cases. (The slip's derivative
   !> taken with the rows fixed, P (c^n - c) dx instead of P c^n dx, is off by 0.10 in stick.)
   subroutine test_tangent(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp), parameter :: coefficients(3) = [0.0_dp, 10.0_dp, 0.1_dp]
      integer, parameter :: expected_status(3) = [contact_slip, contact_stick, contact_slip]
      real(dp), parameter :: traction(3) = [3.0e-3_dp, -2.0e-3_dp, 0.0_dp]
      real(dp) :: coords(3, 41), back(3, 41), largest, global(123, 123), full(123, 123)
      type(mortar_rows_t) :: rows, committed
      type(mortar_node_t) :: node
      type(contact_point_result_t) :: result
      real(dp), allocatable :: fint(:), tangent(:, :)
      integer :: m
      integer, parameter :: j = 6
      call grid_rows(coords, rows)
      coords(3, :16) = coords(3, :16) - 0.1_dp - 1.0e-6_dp + 0.05_dp*coords(1, :16)
      back = coords
      back(1:2, :16) = back(1:2, :16) - 1.0e-6_dp
      call committed_rows(back, committed)
      call committed_rows(coords, rows)
      do m = 1, 3
         call mortar_node(rows, j, 1.0_dp/9.0_dp, node, committed, traction, .true.)
         node%x = coords(:, node%nodes)
         allocate (fint(3*size(node%nodes)), tangent(3*size(node%nodes), 3*size(node%nodes)))
         call mortar_node_contact(make_parameters(coefficients(m)), node, 1.0_dp, branch_free, result, fint, tangent)
         call check(error, result%status == expected_status(m) .and. result%pressure > 0.0_dp, 'mu '// &
                    to_string(coefficients(m))//': status '//to_string(result%status)//', gap '//to_string(result%gap))
         if (allocated(error)) return
         largest = maxval(abs(tangent))
         if (m == 1) then
            call check(error, maxval(abs(central_differences(make_parameters(0.0_dp), node) - tangent)) <= &
                       1.0e-8_dp*largest, 'frictionless tangent is not the derivative with the rows fixed')
            if (allocated(error)) return
            call check(error, maxval(abs(tangent - transpose(tangent))) <= 1.0e-14_dp*largest, &
                       'frictionless tangent not symmetric')
            if (allocated(error)) return
         end if
         global = scattered(node%nodes, tangent)
         full = full_differences(make_parameters(coefficients(m)), coords, committed, traction)
         call check(error, maxval(abs(full - global)) <= 1.0e-5_dp*largest, 'mu '//to_string(coefficients(m))// &
                    ': tangent off the full derivative by '//to_string(maxval(abs(full - global))/largest)// &
                    ' of its largest entry')
         if (allocated(error)) return
         deallocate (fint, tangent)
      end do
   end subroutine test_tangent

   !> Slave faces: the unit square (nodes 1-4, z = 0, outward -z) and one collapsed onto the
   !> point (2, 2, 0) (nodes 5-8); master: one face over [-1, 3]^2 at z = -0.1 (nodes 9-12,
   !> outward +z). Then the triangle of the unit square with nodes 1 and 2 coinciding.
   subroutine test_degenerate_faces(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: coords(3, 12), master_part(4, 4), slave_part(4, 4)
      type(mortar_rows_t) :: rows
      logical :: overlap
      integer :: i
      coords(:, 1:4) = reshape([0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 1.0_dp, 0.0_dp, &
                                1.0_dp, 1.0_dp, 0.0_dp, 1.0_dp, 0.0_dp, 0.0_dp], [3, 4])
      coords(:, 5:8) = spread([2.0_dp, 2.0_dp, 0.0_dp], 2, 4)
      coords(:, 9:12) = reshape([-1.0_dp, -1.0_dp, -0.1_dp, 3.0_dp, -1.0_dp, -0.1_dp, &
                                 3.0_dp, 3.0_dp, -0.1_dp, -1.0_dp, 3.0_dp, -0.1_dp], [3, 4])
      call mortar_rows(coords, [(i, i=1, 8)], reshape([1, 2, 3, 4, 5, 6, 7, 8], [4, 2]), &
                       reshape([9, 10, 11, 12], [4, 1]), 0.5_dp, rows)
      call check(error, all(ieee_is_finite(rows%normal)) .and. all(ieee_is_finite(rows%dual_area)) .and. &
                 all(ieee_is_finite(rows%weight)), 'a collapsed face gives a NaN')
      if (allocated(error)) return
      call check(error, all(rows%normal(:, 5:8) == 0.0_dp) .and. all(rows%dual_area(5:8) == 0.0_dp) .and. &
                 all(abs(rows%dual_area(1:4) - 0.25_dp) <= 1.0e-14_dp), &
                 'collapsed face: D_j '//to_string(rows%dual_area(5))//', unit square: '//to_string(rows%dual_area(1)))
      if (allocated(error)) return
      coords(:, 2) = coords(:, 1)
      call segment_integrals(coords(:, 1:4), coords(:, 9:12), 0.5_dp, master_part, slave_part, overlap)
      call check(error, overlap .and. all(ieee_is_finite(master_part)) .and. all(ieee_is_finite(slave_part)), &
                 'coincident nodes: no overlap or a NaN')
      if (allocated(error)) return
      call check(error, maxval(abs(sum(master_part, dim=2) - sum(slave_part, dim=2))) <= 1.0e-12_dp, &
                 'coincident nodes: sum_l M_jl /= D_j')
      if (allocated(error)) return
      call segment_integrals(coords(:, 5:8), coords(:, 9:12), 0.5_dp, master_part, slave_part, overlap)
      call check(error, .not. overlap .and. all(master_part == 0.0_dp), 'a collapsed face overlaps')
   end subroutine test_degenerate_faces

   subroutine test_shrunk_coverage(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp), parameter :: factor = 0.6_dp
      real(dp), parameter :: tilt = sqrt(1.0_dp + 0.05_dp**2)   ! area of the tilted plane per flat area
      real(dp) :: coords(3, 41), fint(3*41), tangent(3*41, 3*41)
      type(mortar_rows_t) :: rows
      type(mortar_node_t) :: node
      type(contact_point_result_t) :: result
      integer :: j
      call grid_rows(coords, rows)
      coords(1:2, :16) = 0.5_dp + factor*(coords(1:2, :16) - 0.5_dp)
      coords(3, :16) = -0.1_dp - 1.0e-6_dp + 0.05_dp*coords(1, :16)
      call committed_rows(coords, rows)
      call check(error, all([(mortar_covered(rows, j), j=1, 16)]), 'a node of the shrunk grid is not covered')
      if (allocated(error)) return
      call check_close(error, rows%tributary_area(6), factor**2*tilt/9.0_dp, 1.0e-13_dp, message='a_6')
      if (allocated(error)) return
      call check_close(error, rows%tributary_area(1), factor**2*tilt/36.0_dp, 1.0e-13_dp, message='a_1')
      if (allocated(error)) return
      call mortar_node(rows, 6, 1.0_dp/9.0_dp, node)
      node%x = coords(:, node%nodes)
      call mortar_node_contact(make_parameters(0.0_dp), node, 1.0_dp, branch_free, result, &
                               fint(:3*size(node%nodes)), tangent(:3*size(node%nodes), :3*size(node%nodes)))
      call check(error, result%status == contact_slip .and. result%pressure > 0.0_dp, &
                 'node 6 of the shrunk grid: status '//to_string(result%status)//', gap '//to_string(result%gap))
   end subroutine test_shrunk_coverage

   !> A node's matrix on its nodes placed into the (123, 123) matrix of the 41 grid nodes.
   pure function scattered(nodes, local) result(global)
      integer, intent(in) :: nodes(:)
      real(dp), intent(in) :: local(:, :)
      real(dp) :: global(123, 123)
      integer :: a, b
      global = 0.0_dp
      do b = 1, size(nodes)
         do a = 1, size(nodes)
            global(3*nodes(a) - 2:3*nodes(a), 3*nodes(b) - 2:3*nodes(b)) = local(3*a - 2:3*a, 3*b - 2:3*b)
         end do
      end do
   end function scattered

   !> d fint / d x of node 6 over the 41 grid nodes by central differences (step 1e-8), its rows
   !> recomputed at every perturbed position (committed row and traction fixed).
   function full_differences(parameters, coords, committed, traction) result(differences)
      type(contact_parameters_t), intent(in) :: parameters
      real(dp), intent(in) :: coords(3, 41), traction(3)
      type(mortar_rows_t), intent(in) :: committed
      real(dp) :: differences(123, 123)
      real(dp) :: moved(3, 41), plus(123), minus(123)
      real(dp), parameter :: h = 1.0e-8_dp   ! below the penetration: the node stays in contact
      integer :: k, c
      moved = coords
      do k = 1, 41
         do c = 1, 3
            moved(c, k) = coords(c, k) + h
            plus = node_force(parameters, moved, committed, traction)
            moved(c, k) = coords(c, k) - h
            minus = node_force(parameters, moved, committed, traction)
            moved(c, k) = coords(c, k)
            differences(:, 3*k - 3 + c) = (plus - minus)/(2.0_dp*h)
         end do
      end do
   end function full_differences

   !> fint of node 6 (over the 41 grid nodes) with its rows computed at `coords`.
   function node_force(parameters, coords, committed, traction) result(force)
      type(contact_parameters_t), intent(in) :: parameters
      real(dp), intent(in) :: coords(3, 41), traction(3)
      type(mortar_rows_t), intent(in) :: committed
      real(dp) :: force(123)
      type(mortar_rows_t) :: rows
      type(mortar_node_t) :: node
      type(contact_point_result_t) :: result
      real(dp), allocatable :: fint(:), tangent(:, :)
      integer :: a
      call committed_rows(coords, rows)
      call mortar_node(rows, 6, 1.0_dp/9.0_dp, node, committed, traction, .true.)
      node%x = coords(:, node%nodes)
      allocate (fint(3*size(node%nodes)), tangent(3*size(node%nodes), 3*size(node%nodes)))
      call mortar_node_contact(parameters, node, 1.0_dp, branch_free, result, fint, tangent)
      force = 0.0_dp
      do a = 1, size(node%nodes)
         force(3*node%nodes(a) - 2:3*node%nodes(a)) = fint(3*a - 2:3*a)
      end do
   end function node_force

   !> The mortar rows of the grid_rows pair at the coordinates `coords`.
   subroutine committed_rows(coords, rows)
      real(dp), intent(in) :: coords(3, 41)
      type(mortar_rows_t), intent(out) :: rows
      integer :: slave_faces(4, 9), i
      slave_faces = grid_faces(3)
      slave_faces = slave_faces([1, 4, 3, 2], :)
      call mortar_rows(coords, [(i, i=1, 16)], slave_faces, grid_faces(4) + 16, 0.5_dp, rows)
   end subroutine committed_rows

   !> d fint / d x of `node` by central differences (relative step 1e-7), its rows fixed.
   function central_differences(parameters, node) result(differences)
      type(contact_parameters_t), intent(in) :: parameters
      type(mortar_node_t), intent(in) :: node
      real(dp), allocatable :: differences(:, :)
      type(mortar_node_t) :: moved
      type(contact_point_result_t) :: result
      real(dp), allocatable :: plus(:), minus(:), dummy(:, :)
      real(dp), parameter :: h = 1.0e-7_dp
      integer :: k, c, n
      n = 3*size(node%nodes)
      allocate (differences(n, n), plus(n), minus(n), dummy(n, n))
      moved = node
      do k = 1, size(node%nodes)
         do c = 1, 3
            moved%x(c, k) = node%x(c, k) + h
            call mortar_node_contact(parameters, moved, 1.0_dp, branch_free, result, plus, dummy)
            moved%x(c, k) = node%x(c, k) - h
            call mortar_node_contact(parameters, moved, 1.0_dp, branch_free, result, minus, dummy)
            moved%x(c, k) = node%x(c, k)
            differences(:, 3*k - 3 + c) = (plus - minus)/(2.0_dp*h)
         end do
      end do
   end function central_differences

   !> Objective slip: the slave grid slid by s = (0.03, -0.02) over the flat master (z = -0.1)
   !> gives sum_k (c^n_jk - c_jk) x_k = D_j s at every slave node (to 1e-13 of D_j |s|); both
   !> grids moved together by a rigid rotation (0.7 rad about (1, 2, 3)) and translation give 0.
   subroutine test_objective_slip(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp), parameter :: s(3) = [0.03_dp, -0.02_dp, 0.0_dp]
      real(dp) :: coords(3, 41), moved(3, 41), rotation(3, 3), axis(3), slip(3)
      type(mortar_rows_t) :: before, after
      type(mortar_node_t) :: node
      integer :: j
      call grid_rows(coords, before)
      coords(3, 17:) = -0.1_dp
      call committed_rows(coords, before)
      moved = coords
      moved(:, :16) = moved(:, :16) + spread(s, 2, 16)
      call committed_rows(moved, after)
      do j = 1, 16
         call mortar_node(after, j, before%dual_area(j), node, before, [0.0_dp, 0.0_dp, 0.0_dp], .true.)
         slip = matmul(moved(:, node%nodes), node%committed_weight - node%weight)
         call check(error, norm2(slip - after%dual_area(j)*s) <= 1.0e-13_dp*after%dual_area(j)*norm2(s), &
                    'slid: node '//to_string(j)//' slip off by '//to_string(norm2(slip/after%dual_area(j) - s)))
         if (allocated(error)) return
      end do
      axis = [1.0_dp, 2.0_dp, 3.0_dp]/norm2([1.0_dp, 2.0_dp, 3.0_dp])
      rotation = rotation_matrix(axis, 0.7_dp)
      moved = matmul(rotation, coords) + spread([0.4_dp, -1.0_dp, 2.0_dp], 2, 41)
      call committed_rows(moved, after)
      do j = 1, 16
         call mortar_node(after, j, before%dual_area(j), node, before, [0.0_dp, 0.0_dp, 0.0_dp], .true.)
         slip = matmul(moved(:, node%nodes), node%committed_weight - node%weight)
         call check(error, norm2(slip) <= 1.0e-13_dp*after%dual_area(j), &
                    'rigid motion: node '//to_string(j)//' slip '//to_string(norm2(slip)/after%dual_area(j)))
         if (allocated(error)) return
      end do
   end subroutine test_objective_slip

   subroutine test_first_touch(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp), parameter :: s(3) = [0.03_dp, -0.02_dp, 0.0_dp]
      real(dp) :: coords(3, 41), moved(3, 41), fint(3*41), tangent(3*41, 3*41), pressure
      type(mortar_rows_t) :: before, after
      type(mortar_node_t) :: node
      type(contact_point_result_t) :: result
      logical :: closed
      integer :: n, case
      call grid_rows(coords, before)
      coords(3, 17:) = -0.1_dp
      call committed_rows(coords, before)
      moved = coords
      moved(:, :16) = moved(:, :16) + spread(s, 2, 16)
      moved(3, :16) = -0.1_dp - 1.0e-6_dp
      call committed_rows(moved, after)
      do case = 1, 2
         closed = case == 2   ! 1: open at the last commit (the node's state); 2: taken as closed
         call mortar_node(after, 6, 1.0_dp/9.0_dp, node, before, [0.0_dp, 0.0_dp, 0.0_dp], closed)
         node%x = moved(:, node%nodes)
         n = 3*size(node%nodes)
         call mortar_node_contact(make_parameters(0.3_dp), node, 1.0_dp, branch_free, result, fint(:n), &
                                  tangent(:n, :n))
         pressure = result%pressure
         if (.not. closed) then
            call check(error, pressure > 0.0_dp .and. all(result%traction == 0.0_dp), &
                       'open at the last commit: traction '//to_string(norm2(result%traction))//', pressure '// &
                       to_string(pressure))
         else
            call check_close(error, norm2(result%traction), 0.3_dp*pressure, 1.0e-12_dp, &
                             message='closed at the last commit: |t| against mu p')
         end if
         if (allocated(error)) return
      end do
   end subroutine test_first_touch

   !> Rodrigues: rotation by `angle` (rad) about the unit `axis`.
   pure function rotation_matrix(axis, angle) result(r)
      real(dp), intent(in) :: axis(3), angle
      real(dp) :: r(3, 3), k(3, 3)
      integer :: i
      k = reshape([0.0_dp, axis(3), -axis(2), -axis(3), 0.0_dp, axis(1), axis(2), -axis(1), 0.0_dp], [3, 3])
      r = sin(angle)*k + (1.0_dp - cos(angle))*matmul(k, k)
      do i = 1, 3
         r(i, i) = r(i, i) + 1.0_dp
      end do
   end function rotation_matrix
end module test_mortar_contact
