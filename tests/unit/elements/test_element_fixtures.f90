!> Shared fixtures of the element tests: a distorted HEX8, sample displacement fields, a
!> symmetric eigenvalue routine (cyclic Jacobi, Golub & Van Loan, Matrix Computations, 4th ed.,
!> alg. 8.5.3) and a dense solver, written here because the test executable links only
!> frix_elements (no LAPACK).
module test_element_fixtures
   use frix_kinds, only: dp
   implicit none
   private

   public :: distorted_coords, sample_displacement, parent_corner, symmetric_eigenvalues, solve_dense
   public :: element_size

   real(dp), parameter :: element_size = 2.0_dp   !! edge length of the undistorted cube

   !> VTK node order on [-1, 1]^3.
   real(dp), parameter :: parent_corner(3, 8) = reshape([ &
                                                        -1, -1, -1, 1, -1, -1, 1, 1, -1, -1, 1, -1, &
                                                        -1, -1, 1, 1, -1, 1, 1, 1, 1, -1, 1, 1], [3, 8])

   !> Node perturbations (fixed, arbitrary, up to 0.15 = 7.5 % of the edge).
   real(dp), parameter :: perturbation(3, 8) = reshape([ &
                                                       0.10_dp, -0.05_dp, 0.08_dp, &
                                                       -0.12_dp, 0.07_dp, -0.03_dp, &
                                                       0.15_dp, 0.10_dp, 0.05_dp, &
                                                       -0.06_dp, -0.11_dp, 0.09_dp, &
                                                       0.04_dp, 0.13_dp, -0.10_dp, &
                                                       0.11_dp, -0.08_dp, 0.12_dp, &
                                                       -0.09_dp, 0.06_dp, -0.14_dp, &
                                                       0.07_dp, -0.10_dp, 0.03_dp], [3, 8])

   !> A displacement pattern with entries in [-1, 1] (fixed, arbitrary, no symmetry).
   real(dp), parameter :: pattern(3, 8) = reshape([ &
                                                  0.30_dp, -0.70_dp, 0.20_dp, &
                                                  -0.50_dp, 0.90_dp, 0.40_dp, &
                                                  0.80_dp, 0.10_dp, -0.60_dp, &
                                                  -0.20_dp, -0.40_dp, 1.00_dp, &
                                                  0.60_dp, 0.50_dp, -0.30_dp, &
                                                  -0.90_dp, 0.20_dp, 0.70_dp, &
                                                  0.40_dp, -1.00_dp, -0.10_dp, &
                                                  -0.70_dp, 0.60_dp, 0.50_dp], [3, 8])

contains

   !> The cube [0, 2]^3 with every node moved by `perturbation`: a general (non-parallelepiped)
   !> trilinear hexahedron, edge about 2.
   pure function distorted_coords() result(coords)
      real(dp) :: coords(3, 8)
      coords = 1.0_dp + parent_corner + perturbation
   end function distorted_coords

   !> `amplitude` times a fixed irregular pattern.
   pure function sample_displacement(amplitude) result(u)
      real(dp), intent(in) :: amplitude
      real(dp) :: u(3, 8)
      u = amplitude*pattern
   end function sample_displacement

   !> Eigenvalues of a symmetric matrix by the cyclic Jacobi method, ascending.
   pure function symmetric_eigenvalues(matrix) result(values)
      real(dp), intent(in) :: matrix(:, :)
      real(dp) :: values(size(matrix, 1))
      real(dp) :: a(size(matrix, 1), size(matrix, 1)), off, theta, t, c, s, apq
      real(dp) :: row_p(size(matrix, 1)), row_q(size(matrix, 1))
      integer :: n, p, q, sweep, i, j
      n = size(matrix, 1)
      a = matrix
      do sweep = 1, 100
         off = 0.0_dp
         do q = 2, n
            off = off + sum(a(1:q - 1, q)**2)
         end do
         if (off <= (1.0e-17_dp*norm2(a))**2) exit
         do p = 1, n - 1
            do q = p + 1, n
               apq = a(p, q)
               if (apq == 0.0_dp) cycle
               theta = (a(q, q) - a(p, p))/(2.0_dp*apq)
               t = sign(1.0_dp, theta)/(abs(theta) + sqrt(theta**2 + 1.0_dp))
               c = 1.0_dp/sqrt(t**2 + 1.0_dp)
               s = t*c
               ! A <- J^T A J with the rotation in the (p, q) plane
               row_p = a(p, :)
               row_q = a(q, :)
               a(p, :) = c*row_p - s*row_q
               a(q, :) = s*row_p + c*row_q
               row_p = a(:, p)
               row_q = a(:, q)
               a(:, p) = c*row_p - s*row_q
               a(:, q) = s*row_p + c*row_q
               a(p, q) = 0.0_dp
               a(q, p) = 0.0_dp
            end do
         end do
      end do
      do i = 1, n
         values(i) = a(i, i)
      end do
      ! insertion sort
      do i = 2, n
         t = values(i)
         j = i - 1
         do while (j >= 1)
            if (values(j) <= t) exit
            values(j + 1) = values(j)
            j = j - 1
         end do
         values(j + 1) = t
      end do
   end function symmetric_eigenvalues

   !> Solve A x = b by Gaussian elimination with partial pivoting (small dense systems).
   pure function solve_dense(matrix, rhs) result(x)
      real(dp), intent(in) :: matrix(:, :), rhs(:)
      real(dp) :: x(size(rhs))
      real(dp) :: a(size(rhs), size(rhs)), b(size(rhs)), swap(size(rhs)), factor, swap_b
      integer :: n, k, pivot, i
      n = size(rhs)
      a = matrix
      b = rhs
      do k = 1, n
         pivot = k - 1 + maxloc(abs(a(k:n, k)), dim=1)
         if (pivot /= k) then
            swap = a(k, :)
            a(k, :) = a(pivot, :)
            a(pivot, :) = swap
            swap_b = b(k)
            b(k) = b(pivot)
            b(pivot) = swap_b
         end if
         do i = k + 1, n
            factor = a(i, k)/a(k, k)
            a(i, k:n) = a(i, k:n) - factor*a(k, k:n)
            b(i) = b(i) - factor*b(k)
         end do
      end do
      do k = n, 1, -1
         x(k) = (b(k) - dot_product(a(k, k + 1:n), x(k + 1:n)))/a(k, k)
      end do
   end function solve_dense
end module test_element_fixtures
