!> Enhanced assumed strain (EAS) interpolations of the 8-node hexahedron: the mode tables M(xi)
!> in parent coordinates and the strain transformation T0^{-T} built from the Jacobian at the
!> element centre. The full derivation and the sources of each table are in docs/elements.md.
!>
!> Conventions: parent coordinates (xi, eta, zeta) in [-1, 1]^3; strain components in the
!> frix Voigt order 11 22 33 12 13 23 with engineering shears (gamma_12 = 2 E_12), both for the
!> natural (parent) components E_xi_ij = g_i . E . g_j (g_i = dX/dxi_i) and for the Cartesian
!> components. Every mode is an odd polynomial in at least one parent coordinate, so it
!> integrates to zero over [-1, 1]^3 exactly and under 2x2x2 Gauss quadrature: with the
!> detJ0 / detJ(xi) factor the enhanced strain has zero mean over the element, which is the
!> condition of Simo & Rifai (1990) for passing the patch test.
!>
!> Tables (column = one parameter alpha_k; rows = natural strain component):
!>   EAS3  (normal modes of Simo & Rifai):   E11 ~ xi, E22 ~ eta, E33 ~ zeta
!>   EAS9  (Simo & Rifai 1990, IJNME 29):    EAS3 + E12 ~ xi, eta; E13 ~ xi, zeta; E23 ~ eta, zeta
!>   EAS21 (Andelfinger & Ramm 1993, IJNME 36, as tabulated in BACI/4C so_hex8 "easfull"
!>          and Ikarus E21): EAS9 + E11 ~ xi eta, xi zeta; E22 ~ xi eta, eta zeta;
!>          E33 ~ xi zeta, eta zeta; E12 ~ xi zeta, eta zeta; E13 ~ xi eta, eta zeta;
!>          E23 ~ xi eta, xi zeta
!>   EAS30 (frix's table, the complete enhancement under 2x2x2 quadrature; see docs):
!>          EAS21 + E11, E22, E33 ~ xi eta zeta; E12 ~ xi eta, xi eta zeta;
!>          E13 ~ xi zeta, xi eta zeta; E23 ~ eta zeta, xi eta zeta
!> The 4-node quadrilateral (frix_plane_solid), parent coordinates (xi, eta) in [-1, 1]^2, the
!> in-plane rows 11 22 12 of the same Voigt layout (rows 33 13 23 not enhanced):
!>   EAS4  (Simo & Rifai 1990, IJNME 29, the Q1/E4 element): E11 ~ xi, E22 ~ eta, E12 ~ xi, eta
module frix_eas_modes
   use frix_kinds, only: dp
   implicit none
   private

   public :: eas_mode_counts, max_eas_modes, is_valid_eas_count, eas_modes, strain_push_matrix
   public :: plane_eas_counts, plane_eas_modes

   !> The supported numbers of enhanced parameters (0 = plain displacement element).
   integer, parameter :: eas_mode_counts(5) = [0, 3, 9, 21, 30]
   integer, parameter :: max_eas_modes = 30   !! largest entry of eas_mode_counts
   !> The supported numbers of enhanced parameters of the 4-node quadrilateral.
   integer, parameter :: plane_eas_counts(2) = [0, 4]

contains

   !> True if `n_eas` is one of `eas_mode_counts`.
   pure logical function is_valid_eas_count(n_eas) result(valid)
      integer, intent(in) :: n_eas
      valid = any(eas_mode_counts == n_eas)
   end function is_valid_eas_count

   !> Enhanced natural strain interpolation M(xi) (6 x n_eas) at the parent point `xi`.
   !> The caller checks `is_valid_eas_count(n_eas)`; an unsupported count leaves M zero.
   pure subroutine eas_modes(n_eas, xi, modes)
      integer, intent(in) :: n_eas          !! 0, 3, 9, 21 or 30
      real(dp), intent(in) :: xi(3)         !! parent coordinates (xi, eta, zeta)
      real(dp), intent(out) :: modes(:, :)  !! (6, n_eas), Voigt rows 11 22 33 12 13 23
      real(dp) :: r, s, t
      r = xi(1)
      s = xi(2)
      t = xi(3)
      modes = 0.0_dp
      if (n_eas < 3) return
      ! EAS3: normal strains, linear in their own direction
      modes(1, 1) = r
      modes(2, 2) = s
      modes(3, 3) = t
      if (n_eas < 9) return
      ! EAS9: Simo & Rifai's shear modes
      modes(4, 4) = r
      modes(4, 5) = s
      modes(5, 6) = r
      modes(5, 7) = t
      modes(6, 8) = s
      modes(6, 9) = t
      if (n_eas < 21) return
      ! EAS21: bilinear modes of Andelfinger & Ramm
      modes(1, 10) = r*s
      modes(1, 11) = r*t
      modes(2, 12) = r*s
      modes(2, 13) = s*t
      modes(3, 14) = r*t
      modes(3, 15) = s*t
      modes(4, 16) = r*t
      modes(4, 17) = s*t
      modes(5, 18) = r*s
      modes(5, 19) = s*t
      modes(6, 20) = r*s
      modes(6, 21) = r*t
      if (n_eas < 30) return
      ! EAS30: the remaining modes that complete the enhanced space under 2x2x2 quadrature
      modes(1, 22) = r*s*t
      modes(2, 23) = r*s*t
      modes(3, 24) = r*s*t
      modes(4, 25) = r*s
      modes(4, 26) = r*s*t
      modes(5, 27) = r*t
      modes(5, 28) = r*s*t
      modes(6, 29) = s*t
      modes(6, 30) = r*s*t
   end subroutine eas_modes

   !> Enhanced natural strain interpolation M(xi) (6 x n_eas) of the quadrilateral at the
   !> parent point `xi` (module header; n_eas 0 or 4, the caller checks it).
   pure subroutine plane_eas_modes(n_eas, xi, modes)
      integer, intent(in) :: n_eas          !! 0 or 4
      real(dp), intent(in) :: xi(2)         !! parent coordinates (xi, eta)
      real(dp), intent(out) :: modes(:, :)  !! (6, n_eas), Voigt rows 11 22 33 12 13 23
      modes = 0.0_dp
      if (n_eas < 4) return
      modes(1, 1) = xi(1)
      modes(2, 2) = xi(2)
      modes(4, 3) = xi(1)
      modes(4, 4) = xi(2)
   end subroutine plane_eas_modes

   !> Voigt matrix of the congruence X -> P X P^T acting on symmetric strain tensors stored
   !> with engineering shears on both sides: strain(P X P^T) = push strain(X).
   !> With P = J0^{-1} (J0_ij = dX_j/dxi_i at xi = 0) this is the T0^{-T} of Simo & Rifai
   !> (1990) / Andelfinger & Ramm (1993) that maps natural (covariant) strain components to
   !> Cartesian ones: E = J0^{-1} E_nat J0^{-T}.
   pure subroutine strain_push_matrix(p, push)
      real(dp), intent(in) :: p(3, 3)       !! the 3 x 3 map P
      real(dp), intent(out) :: push(6, 6)   !! Voigt 11 22 33 12 13 23, engineering shears
      integer, parameter :: first(6) = [1, 2, 3, 1, 1, 2], second(6) = [1, 2, 3, 2, 3, 3]
      integer :: row, column, i, j, k, l
      do column = 1, 6
         k = first(column)
         l = second(column)
         do row = 1, 6
            i = first(row)
            j = second(row)
            if (column <= 3) then
               ! input normal component X_kk
               push(row, column) = p(i, k)*p(j, k)
            else
               ! input engineering shear gamma_kl = 2 X_kl: (P X P^T)_ij gets (P_ik P_jl + P_il P_jk) X_kl
               push(row, column) = 0.5_dp*(p(i, k)*p(j, l) + p(i, l)*p(j, k))
            end if
            ! output engineering shear = 2 (P X P^T)_ij
            if (row > 3) push(row, column) = 2.0_dp*push(row, column)
         end do
      end do
   end subroutine strain_push_matrix
end module frix_eas_modes
