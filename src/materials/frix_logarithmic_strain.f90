!> The Lagrangian logarithmic (Hencky) strain E_log = 1/2 ln C, C = I + 2 E, and its first and
!> second derivatives with respect to the Green-Lagrange strain E, for laws formulated in the
!> logarithmic strain space (Miehe, Apel & Lambrecht, "Anisotropic additive plasticity in the
!> logarithmic strain space", CMAME 191 (2002) 5383-5425): a small-strain law evaluated at E_log
!> returns the stress T conjugate to E_log and its moduli dT/dE_log; then
!>   S = P^T T,   dS/dE = P^T (dT/dE_log) P + T : d^2 E_log / dE dE,   P = dE_log / dE.
!>
!> Derivatives of the spectral function F(C) = Q f(Lambda) Q^T, f(lambda) = 1/2 ln lambda, by
!> the Daleckii-Krein formulas (Bhatia, Matrix Analysis, Springer 1997, V.3): in the eigenbasis
!> of C (hats),
!>   DF(C)[H]_ij      = f[l_i, l_j] H^_ij
!>   D2F(C)[H, K]_ij  = sum_k f[l_i, l_k, l_j] (H^_ik K^_kj + K^_ik H^_kj)
!> with the divided differences f[.,.] and f[.,.,.] of f; coinciding eigenvalues need no special
!> case, the divided differences have confluent limits that are computed stably (below).
!>
!> Voigt convention of frix_material: strains xx yy zz xy xz yz with engineering shears,
!> stresses with tensor shears; P maps engineering E increments to engineering E_log increments,
!> so that T . dE_log = (P^T T) . dE.
module frix_logarithmic_strain
   use frix_kinds, only: dp
   use frix_symmetric_tensor, only: tensor_of_stress, strain_of_tensor, right_cauchy_green, rotated_unit_strain
   implicit none
   private

   public :: log_strain_t, logarithmic_strain, log_strain_stress, log_strain_tangent
   public :: symmetric_eigen3

   !> E_log of one strain state with what its derivatives need.
   type :: log_strain_t
      real(dp) :: strain(6) = 0.0_dp          !! E_log, Voigt, engineering shears
      real(dp) :: projection(6, 6) = 0.0_dp   !! P = dE_log / dE (engineering both sides)
      real(dp) :: eigenvalues(3) = 1.0_dp     !! of C (squared principal stretches)
      real(dp) :: eigenvectors(3, 3) = 0.0_dp !! columns: principal directions of C
      real(dp) :: unit_hat(3, 3, 6) = 0.0_dp  !! Q^T H_a Q, H_a the tensor of unit component a
   end type log_strain_t

contains

   !> E_log = 1/2 ln C and P = dE_log/dE for the Green-Lagrange strain `green` (Voigt,
   !> engineering shears). `valid` is .false. when C is not positive definite (det F <= 0 or a
   !> non-physical E), and the result is then not set.
   pure subroutine logarithmic_strain(green, log_strain, valid)
      real(dp), intent(in) :: green(6)
      type(log_strain_t), intent(out) :: log_strain
      logical, intent(out) :: valid
      real(dp) :: c(3, 3), first(3, 3), logarithm(3, 3)
      integer :: a, i
      c = right_cauchy_green(green)
      call symmetric_eigen3(c, log_strain%eigenvalues, log_strain%eigenvectors)
      valid = all(log_strain%eigenvalues > 0.0_dp)
      if (.not. valid) return
      associate (l => log_strain%eigenvalues, q => log_strain%eigenvectors)
         logarithm = 0.0_dp
         do i = 1, 3
            logarithm(i, i) = 0.5_dp*log(l(i))
         end do
         log_strain%strain = strain_of_tensor(matmul(q, matmul(logarithm, transpose(q))))
         first = first_differences(l)
         do a = 1, 6
            log_strain%unit_hat(:, :, a) = rotated_unit_strain(q, a)
            ! dC = 2 H_a for a unit engineering component a of E
            log_strain%projection(:, a) = strain_of_tensor(matmul(q, matmul(2.0_dp*first*log_strain%unit_hat(:, :, a), &
                                                                              transpose(q))))
         end do
      end associate
   end subroutine logarithmic_strain

   !> S = P^T T: the second Piola-Kirchhoff stress of the stress T conjugate to E_log.
   pure function log_strain_stress(log_strain, stress) result(pk2)
      type(log_strain_t), intent(in) :: log_strain
      real(dp), intent(in) :: stress(6)   !! T, Voigt, tensor shears
      real(dp) :: pk2(6)
      pk2 = matmul(transpose(log_strain%projection), stress)
   end function log_strain_stress

   !> dS/dE = P^T M P + G with M = dT/dE_log and G_ab = T : d^2 E_log / dE_a dE_b
   !>       = 4 T : D2F(C)[H_a, H_b] (dC = 2 dE), H_a the tensor of unit engineering component a.
   pure function log_strain_tangent(log_strain, stress, moduli) result(tangent)
      type(log_strain_t), intent(in) :: log_strain
      real(dp), intent(in) :: stress(6)       !! T, Voigt, tensor shears
      real(dp), intent(in) :: moduli(6, 6)    !! dT/dE_log
      real(dp) :: tangent(6, 6)
      real(dp) :: second(3, 3, 3), t_hat(3, 3), weighted(3, 3, 3), contracted(3, 3, 6)
      integer :: a, b, i, j, k
      ! With T^, f[.,.,.] and H^ symmetric, T : D2F[H_a, H_b] = 2 sum_ikj T^_ij f[l_i,l_k,l_j]
      ! H^a_ik H^b_kj, so G_ab = 8 sum_ik H^a_ik V^b_ik with V^b_ik = sum_j W_ikj H^b_kj and
      ! W_ikj = T^_ij f[l_i, l_k, l_j].
      associate (p => log_strain%projection, q => log_strain%eigenvectors, h_hat => log_strain%unit_hat)
         tangent = matmul(transpose(p), matmul(moduli, p))
         second = second_differences(log_strain%eigenvalues)
         t_hat = matmul(transpose(q), matmul(tensor_of_stress(stress), q))
         do j = 1, 3
            do k = 1, 3
               do i = 1, 3
                  weighted(i, k, j) = t_hat(i, j)*second(i, k, j)
               end do
            end do
         end do
         do b = 1, 6
            do k = 1, 3
               do i = 1, 3
                  contracted(i, k, b) = sum(weighted(i, k, :)*h_hat(k, :, b))
               end do
            end do
         end do
         do b = 1, 6
            do a = b, 6
               tangent(a, b) = tangent(a, b) + 8.0_dp*sum(h_hat(:, :, a)*contracted(:, :, b))
               if (a /= b) tangent(b, a) = tangent(b, a) + 8.0_dp*sum(h_hat(:, :, a)*contracted(:, :, b))
            end do
         end do
      end associate
   end function log_strain_tangent

   !> f[l_i, l_j] of f = 1/2 ln: with m = (a + b)/2 and x = (a - b)/(a + b),
   !> (ln a - ln b) / (2 (a - b)) = atanh(x) / (2 m x), whose limit x -> 0 is 1/(2m) = f'(m);
   !> the series atanh(x)/x = 1 + x^2/3 + x^4/5 + ... below |x| = 1e-4 (error < 1e-24).
   pure function first_differences(l) result(first)
      real(dp), intent(in) :: l(3)
      real(dp) :: first(3, 3)
      integer :: i, j
      do j = 1, 3
         do i = 1, 3
            first(i, j) = first_difference(l(i), l(j))
         end do
      end do
   end function first_differences

   pure real(dp) function first_difference(a, b)
      real(dp), intent(in) :: a, b
      real(dp) :: m, x
      m = 0.5_dp*(a + b)
      x = (a - b)/(a + b)
      if (abs(x) < 1.0e-4_dp) then
         first_difference = (1.0_dp + x*x/3.0_dp + x**4/5.0_dp)/(2.0_dp*m)
      else
         first_difference = atanh(x)/(2.0_dp*m*x)
      end if
   end function first_difference

   !> f[l_i, l_k, l_j] for all i, k, j (symmetric in its arguments).
   pure function second_differences(l) result(second)
      real(dp), intent(in) :: l(3)
      real(dp) :: second(3, 3, 3)
      integer :: i, j, k
      do j = 1, 3
         do k = 1, 3
            do i = 1, 3
               second(i, k, j) = second_difference(l(i), l(k), l(j))
            end do
         end do
      end do
   end function second_differences

   !> f[x0, x1, x2] of f = 1/2 ln. Sorted so that the largest gap x_max - x_min is the divisor:
   !> (f[x_max, x_mid] - f[x_mid, x_min]) / (x_max - x_min), whose round-off is ~ 1e-16 m /
   !> (x_max - x_min) relative; below a spread of 1e-3 m the Taylor expansion about the mean m,
   !> f[x0,x1,x2] = f''(m)/2 + f''''(m)/24 h2(d) + f'''''(m)/120 h3(d) + O(d^4/m^6), with
   !> d = x - m (sum d = 0), h_n the complete homogeneous symmetric polynomials of d, and
   !> f'' = -1/(2m^2), f'''' = -3/m^4, f''''' = 12/m^5 (truncation ~ 1e-12 relative).
   pure real(dp) function second_difference(x0, x1, x2)
      real(dp), intent(in) :: x0, x1, x2
      real(dp) :: high, middle, low, m, d(3), h2, h3
      high = max(x0, x1, x2)
      low = min(x0, x1, x2)
      middle = x0 + x1 + x2 - high - low
      m = (x0 + x1 + x2)/3.0_dp
      if (high - low > 1.0e-3_dp*m) then
         second_difference = (first_difference(high, middle) - first_difference(middle, low))/(high - low)
      else
         d = [x0, x1, x2] - m
         h2 = d(1)**2 + d(2)**2 + d(3)**2 + d(1)*d(2) + d(1)*d(3) + d(2)*d(3)
         h3 = sum(d**3) + d(1)**2*(d(2) + d(3)) + d(2)**2*(d(1) + d(3)) + d(3)**2*(d(1) + d(2)) &
              + d(1)*d(2)*d(3)
         second_difference = -1.0_dp/(4.0_dp*m*m) - h2/(8.0_dp*m**4) + h3/(10.0_dp*m**5)
      end if
   end function second_difference

   !> Eigenvalues and orthonormal eigenvectors (columns) of a symmetric 3 x 3 matrix by classical
   !> Jacobi rotations (Golub & Van Loan, Matrix Computations, 4th ed., 8.5.2): each rotation
   !> zeroes the largest off-diagonal entry, until the off-diagonal part is below 1e-15 of the
   !> matrix (quadratic convergence). Rotating the largest entry first makes a nearly diagonal
   !> or nearly 2 x 2 matrix (a strain with round-off shears) cost one full rotation and a few
   !> by round-off angles, for which t = 1/(2 theta) and c = 1 are exact.
   pure subroutine symmetric_eigen3(matrix, eigenvalues, eigenvectors)
      real(dp), intent(in) :: matrix(3, 3)
      real(dp), intent(out) :: eigenvalues(3)
      real(dp), intent(out) :: eigenvectors(3, 3)
      real(dp) :: a(3, 3), scale, theta, t, c, s, column_p(3), column_q(3), off(3)
      integer :: rotation, p, q, pair
      integer, parameter :: pair_p(3) = [1, 1, 2], pair_q(3) = [2, 3, 3]
      a = 0.5_dp*(matrix + transpose(matrix))
      eigenvectors = 0.0_dp
      do p = 1, 3
         eigenvectors(p, p) = 1.0_dp
      end do
      scale = sqrt(sum(a*a))
      do rotation = 1, 150
         off = [a(1, 2), a(1, 3), a(2, 3)]
         if (sqrt(2.0_dp*sum(off**2)) <= 1.0e-15_dp*scale) exit
         pair = maxloc(abs(off), dim=1)
         p = pair_p(pair)
         q = pair_q(pair)
         ! t = tan(phi), the smaller root of t^2 + 2 theta t - 1 = 0; A <- R^T A R with the
         ! rotation R = I + (c - 1)(e_p e_p + e_q e_q) + s (e_p e_q - e_q e_p)
         if (abs(a(p, q)) < 1.0e-8_dp*abs(a(q, q) - a(p, p))) then
            ! |theta| > 5e7: t = 1/(2 theta) (relative error theta^-2 / 4) and c = 1 to round-off
            t = a(p, q)/(a(q, q) - a(p, p))
            c = 1.0_dp
         else
            theta = (a(q, q) - a(p, p))/(2.0_dp*a(p, q))
            t = sign(1.0_dp, theta)/(abs(theta) + sqrt(theta*theta + 1.0_dp))
            c = 1.0_dp/sqrt(t*t + 1.0_dp)
         end if
         s = t*c
         column_p = a(:, p)
         column_q = a(:, q)
         a(:, p) = c*column_p - s*column_q
         a(:, q) = s*column_p + c*column_q
         column_p = a(p, :)
         column_q = a(q, :)
         a(p, :) = c*column_p - s*column_q
         a(q, :) = s*column_p + c*column_q
         a(p, q) = 0.0_dp
         a(q, p) = 0.0_dp
         column_p = eigenvectors(:, p)
         column_q = eigenvectors(:, q)
         eigenvectors(:, p) = c*column_p - s*column_q
         eigenvectors(:, q) = s*column_p + c*column_q
      end do
      do p = 1, 3
         eigenvalues(p) = a(p, p)
      end do
   end subroutine symmetric_eigen3
end module frix_logarithmic_strain
