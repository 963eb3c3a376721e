!> Unit tests of the TET10 element (frix_cell_solid on the TET10 cell): the tangent against
!> central differences of fint under linear and total Lagrangian kinematics (elastic,
!> hyperelastic and von Mises plastic) on a tetrahedron with curved edges, six rigid-body modes
!> and no spurious one (the 4-point rule integrates B^T C B exactly on straight edges), zero
!> force under a finite rotation, a quadratic displacement field exact (the linear strain at
!> every point), and the volume weights of the quadratic shape functions (-V/20 at a corner,
!> V/5 at a mid-edge node: int L_i L_j dV = V/20, int L_i^2 dV = V/10).
module test_tet10
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_strings, only: to_string
   use frix_testing, only: unittest_t, new_unittest, check
   use frix_material, only: material_t
   use frix_element, only: kinematics_linear, kinematics_total_lagrangian
   use frix_cell_solid, only: cell_solid_t, new_cell_solid
   use frix_tet10_cell, only: new_tet10_cell
   use frix_linear_elastic, only: new_linear_elastic, hooke_tangent
   use frix_saint_venant_kirchhoff, only: new_saint_venant_kirchhoff
   use frix_neo_hookean, only: new_neo_hookean
   use frix_material_registry, only: create_material
   use test_element_fixtures, only: symmetric_eigenvalues
   use test_tet4, only: check_tangent, rodrigues
   implicit none
   private

   public :: collect_tet10

   real(dp), parameter :: young = 1000.0_dp, poisson = 0.3_dp
   !> The corners of a general tetrahedron, edges about 1 (positive volume), as test_tet4's.
   real(dp), parameter :: corners(3, 4) = reshape([0.0_dp, 0.0_dp, 0.0_dp, 1.1_dp, 0.1_dp, -0.05_dp, &
                                                   0.2_dp, 0.9_dp, 0.1_dp, -0.1_dp, 0.15_dp, 1.2_dp], [3, 4])
   !> The corners of each mid-edge node 5..10 (VTK / C3D10 order).
   integer, parameter :: edge_corners(2, 5:10) = reshape([1, 2, 2, 3, 3, 1, 1, 4, 2, 4, 3, 4], [2, 6])

contains

   subroutine collect_tet10(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('counts and name', test_counts), &
               new_unittest('tangent, linear kinematics', test_tangent_linear), &
               new_unittest('tangent, total Lagrangian', test_tangent_total), &
               new_unittest('tangent, von Mises plasticity', test_tangent_plastic), &
               new_unittest('rigid-body modes', test_rigid_body_modes), &
               new_unittest('finite rotation gives no force', test_rigid_rotation), &
               new_unittest('quadratic displacement exact', test_quadratic_field), &
               new_unittest('volume weights -V/20 and V/5', test_volume_weights)]
   end subroutine collect_tet10

   function tet10(kinematics) result(element)
      integer, intent(in) :: kinematics
      type(cell_solid_t) :: element
      element = new_cell_solid(new_tet10_cell(), kinematics)
   end function tet10

   !> The 10 nodes: the corners, the mid-edge nodes at the middle of the straight edges, each
   !> then moved by `bend` times a fixed irregular offset (0: straight edges).
   pure function tet10_coords(bend) result(coords)
      real(dp), intent(in) :: bend
      real(dp) :: coords(3, 10)
      integer :: m
      coords(:, 1:4) = corners
      do m = 5, 10
         coords(:, m) = 0.5_dp*(corners(:, edge_corners(1, m)) + corners(:, edge_corners(2, m))) + &
                        bend*[sin(1.7_dp*m), cos(2.3_dp*m), sin(0.9_dp*m + 1.0_dp)]
      end do
   end function tet10_coords

   !> An irregular displacement pattern of size about 0.5.
   pure function pattern() result(u)
      real(dp) :: u(3, 10)
      integer :: a, i
      do a = 1, 10
         do i = 1, 3
            u(i, a) = 0.5_dp*sin(1.3_dp*i + 2.1_dp*a)
         end do
      end do
   end function pattern

   subroutine test_counts(error)
      type(error_t), allocatable, intent(out) :: error
      type(cell_solid_t) :: element
      element = tet10(kinematics_linear)
      call check(error, element%name == 'TET10' .and. element%n_nodes() == 10 .and. element%n_points() == 4 &
                 .and. element%n_enhanced() == 0, 'TET10: 10 nodes, 4 points, no EAS')
   end subroutine test_counts

   !> On a tetrahedron with curved edges (mid-edge nodes moved by 0.05).
   subroutine test_tangent_linear(error)
      type(error_t), allocatable, intent(out) :: error
      call check_tangent(tet10(kinematics_linear), new_linear_elastic(young, poisson, 0.0_dp), tet10_coords(0.05_dp), &
                         0.01_dp*pattern(), error)
   end subroutine test_tangent_linear

   !> St. Venant-Kirchhoff and neo-Hookean at displacements of 10 % of the size.
   subroutine test_tangent_total(error)
      type(error_t), allocatable, intent(out) :: error
      call check_tangent(tet10(kinematics_total_lagrangian), new_saint_venant_kirchhoff(young, poisson, 0.0_dp), &
                         tet10_coords(0.05_dp), 0.1_dp*pattern(), error)
      if (allocated(error)) return
      call check_tangent(tet10(kinematics_total_lagrangian), new_neo_hookean(young, poisson, 0.0_dp), &
                         tet10_coords(0.05_dp), 0.1_dp*pattern(), error)
   end subroutine test_tangent_total

   !> Von Mises with saturation and kinematic hardening (sigma_y = 2): some point yields at
   !> both amplitudes (checked), and K is still d fint / du.
   subroutine test_tangent_plastic(error)
      type(error_t), allocatable, intent(out) :: error
      class(material_t), allocatable :: material
      type(error_t), allocatable :: law_error
      call create_material('MAT_3DMisesPlastic', [character(len=6) :: 'YOUNG', 'NUE', 'SIGY', 'SIGINF', 'DELTA', &
                           'KINH'], [young, poisson, 2.0_dp, 3.0_dp, 50.0_dp, 20.0_dp], material, law_error)
      call check(error, .not. allocated(law_error), 'plastic law')
      if (allocated(error)) return
      call check_tangent(tet10(kinematics_linear), material, tet10_coords(0.05_dp), 0.01_dp*pattern(), error, &
                         plastic=.true.)
      if (allocated(error)) return
      call check_tangent(tet10(kinematics_total_lagrangian), material, tet10_coords(0.05_dp), 0.1_dp*pattern(), &
                         error, plastic=.true.)
   end subroutine test_tangent_plastic

   !> Undeformed, Hooke, straight edges: exactly 6 eigenvalues of K below 1e-10 max
   !> (translations, rotations), the 7th a deformation mode (above 1e-4 max).
   subroutine test_rigid_body_modes(error)
      type(error_t), allocatable, intent(out) :: error
      type(cell_solid_t) :: element
      real(dp) :: tangent(30, 30), fint(30), values(30), state_old(0, 4), state_new(0, 4), alpha(0)
      integer :: n_zero
      element = tet10(kinematics_linear)
      call element%evaluate(new_linear_elastic(young, poisson, 0.0_dp), tet10_coords(0.0_dp), &
                            spread([0.0_dp, 0.0_dp, 0.0_dp], 2, 10), alpha, state_old, state_new, fint, &
                            tangent=tangent, error=error)
      if (allocated(error)) return
      values = symmetric_eigenvalues(tangent)
      n_zero = count(abs(values) <= 1.0e-10_dp*values(30))
      call check(error, n_zero == 6, 'TET10: '//to_string(n_zero)//' zero eigenvalues')
      if (allocated(error)) return
      call check(error, values(7) > 1.0e-4_dp*values(30), 'TET10: 7th eigenvalue '//to_string(values(7)))
   end subroutine test_rigid_body_modes

   !> u = (R - I) X + c with a finite rotation R (40 degrees about an oblique axis), curved
   !> edges, total Lagrangian: fint and the Cauchy stress vanish to round-off of E |X|.
   subroutine test_rigid_rotation(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: coords(3, 10), u(3, 10), fint(30), stress(6, 4), state_old(0, 4), state_new(0, 4), alpha(0)
      real(dp) :: rotation(3, 3)
      type(cell_solid_t) :: element
      integer :: a
      coords = tet10_coords(0.05_dp)
      rotation = rodrigues([1.0_dp, 2.0_dp, -1.0_dp]/sqrt(6.0_dp), 40.0_dp*acos(-1.0_dp)/180.0_dp)
      do a = 1, 10
         u(:, a) = matmul(rotation, coords(:, a)) - coords(:, a) + [0.5_dp, 0.0_dp, -0.3_dp]
      end do
      element = tet10(kinematics_total_lagrangian)
      call element%evaluate(new_saint_venant_kirchhoff(young, poisson, 0.0_dp), coords, u, alpha, state_old, &
                            state_new, fint, stress=stress, error=error)
      if (allocated(error)) return
      call check(error, maxval(abs(fint)) <= 1.0e-12_dp*young .and. maxval(abs(stress)) <= 1.0e-12_dp*young, &
                 'TET10 total Lagrangian: fint '//to_string(maxval(abs(fint)))//', stress '// &
                 to_string(maxval(abs(stress))))
   end subroutine test_rigid_rotation

   !> Straight edges, small strain, u_i = A_ij X_j + Q_i (X_1^2 - X_2 X_3) (a quadratic field, in
   !> the span of the shape functions): at every integration point x_g the strain is that of the
   !> field there, eps = sym(A) + sym(Q grad(X_1^2 - X_2 X_3)), and the stress C eps. The points
   !> are the natural ones mapped by the straight-edged (affine) element.
   subroutine test_quadratic_field(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp), parameter :: gradient(3, 3) = 1.0e-3_dp*reshape([1.0_dp, 0.2_dp, -0.7_dp, 0.4_dp, -0.5_dp, 0.1_dp, &
                                                                 -0.3_dp, 0.6_dp, 0.8_dp], [3, 3])
      real(dp), parameter :: q(3) = 1.0e-3_dp*[0.5_dp, -0.8_dp, 0.3_dp]
      real(dp) :: coords(3, 10), u(3, 10), fint(30), stress(6, 4), strain(6, 4), state_old(0, 4), state_new(0, 4)
      real(dp) :: alpha(0), x(3), grad(3, 3), expected(6), worst
      type(cell_solid_t) :: element
      integer :: a, g
      coords = tet10_coords(0.0_dp)
      do a = 1, 10
         x = coords(:, a)
         u(:, a) = matmul(gradient, x) + q*(x(1)**2 - x(2)*x(3))
      end do
      element = tet10(kinematics_linear)
      call element%evaluate(new_linear_elastic(young, poisson, 0.0_dp), coords, u, alpha, state_old, state_new, &
                            fint, stress=stress, strain=strain, error=error)
      if (allocated(error)) return
      worst = 0.0_dp
      do g = 1, 4
         ! x_g = X_1 + sum_d xi_d (X_{d+1} - X_1) for the affine element
         x = corners(:, 1) + matmul(corners(:, 2:4) - spread(corners(:, 1), 2, 3), element%cell%points(:, g))
         grad = gradient + spread(q, 2, 3)*spread([2.0_dp*x(1), -x(3), -x(2)], 1, 3)
         expected = [grad(1, 1), grad(2, 2), grad(3, 3), grad(1, 2) + grad(2, 1), grad(1, 3) + grad(3, 1), &
                     grad(2, 3) + grad(3, 2)]
         worst = max(worst, maxval(abs(strain(:, g) - expected))/maxval(abs(expected)), &
                     maxval(abs(stress(:, g) - matmul(hooke_tangent(young, poisson), expected)))/ &
                     maxval(abs(matmul(hooke_tangent(young, poisson), expected))))
      end do
      call check(error, worst <= 1.0e-12_dp, 'TET10: the quadratic field''s strain or stress off by '// &
                 to_string(worst)//' (relative)')
   end subroutine test_quadratic_field

   !> Straight edges: int N_a dV = -V/20 at a corner (N = L (2 L - 1)), V/5 at a mid-edge node
   !> (N = 4 L_i L_j), V = det[x2 - x1, x3 - x1, x4 - x1]/6; they sum to V.
   subroutine test_volume_weights(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: weights(10), edges(3, 3), volume, expected(10)
      type(cell_solid_t) :: element
      element = tet10(kinematics_linear)
      call element%volume_weights(tet10_coords(0.0_dp), weights)
      edges = corners(:, 2:4) - spread(corners(:, 1), 2, 3)
      volume = (edges(1, 1)*(edges(2, 2)*edges(3, 3) - edges(3, 2)*edges(2, 3)) - &
                edges(1, 2)*(edges(2, 1)*edges(3, 3) - edges(3, 1)*edges(2, 3)) + &
                edges(1, 3)*(edges(2, 1)*edges(3, 2) - edges(3, 1)*edges(2, 2)))/6.0_dp
      expected(1:4) = -volume/20
      expected(5:10) = volume/5
      call check(error, maxval(abs(weights - expected)) <= 1.0e-15_dp, 'TET10 weights '//to_string(weights(1))// &
                 ', '//to_string(weights(5))//', expected -V/20 = '//to_string(-volume/20)//', V/5 = '// &
                 to_string(volume/5))
   end subroutine test_volume_weights

end module test_tet10
