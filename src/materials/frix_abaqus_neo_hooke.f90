!> Compressible neo-Hookean hyperelasticity in the form of Abaqus and CalculiX (deck keyword
!> MAT_Struct_NeoHookeAbaqus), so that an Abaqus or CalculiX hyperelastic material gives the
!> same stresses with the same numbers. Sources: Abaqus Theory Manual, 4.6.1 "Hyperelastic
!> material behavior" (polynomial potential with N = 1, C01 = 0); CalculiX CrunchiX User's
!> Manual, *HYPERELASTIC, NEO HOOKE:
!>
!>   W(C) = C10 (I1bar - 3) + (J - 1)^2 / D1,   I1bar = J^(-2/3) I1,  I1 = tr C,  J = sqrt(det C),
!>
!> initial shear modulus mu0 = 2 C10, initial bulk modulus K0 = 2 / D1. The volumetric term is
!> (J - 1)^2, not the (ln J)^2 of MAT_Struct_NeoHooke (frix_neo_hookean): the two laws agree
!> only to first order in the strain. D1 = 0 (incompressible) needs a mixed (hybrid) element,
!> which frix does not have: D1 > 0 is required.
!>
!> Derivation (with C = I + 2 E the right Cauchy-Green tensor, C^-1 its inverse; the derivatives
!> of the invariants as in Holzapfel, Nonlinear Solid Mechanics, Wiley 2000, ch. 6):
!>   dI1/dC = I,   dJ/dC = J/2 C^-1,   dJ^(-2/3)/dC = -1/3 J^(-2/3) C^-1,
!>   dC^-1_ij/dC_kl = -I_ijkl(C^-1),  I_ijkl(C^-1) = (C^-1_ik C^-1_jl + C^-1_il C^-1_jk) / 2, so
!>   dI1bar/dC = J^(-2/3) (I - I1/3 C^-1) and
!>   S = 2 dW/dC = mu0 J^(-2/3) (I - I1/3 C^-1) + K0 J (J - 1) C^-1.
!> Differentiating S once more (dS/dE = 2 dS/dC):
!>   C_ijkl = 4 d2W/dC_ij dC_kl
!>          = mu0 J^(-2/3) [ 2/9 I1 C^-1_ij C^-1_kl - 2/3 (delta_ij C^-1_kl + C^-1_ij delta_kl)
!>                           + 1/3 I1 (C^-1_ik C^-1_jl + C^-1_il C^-1_jk) ]
!>          + K0 J [ (2 J - 1) C^-1_ij C^-1_kl - (J - 1) (C^-1_ik C^-1_jl + C^-1_il C^-1_jk) ],
!> symmetric in (ij), (kl) and between the pairs. Pushed forward, sigma = F S F^T / J gives the
!> Cauchy stress of the Abaqus Theory Manual, sigma = mu0/J (bbar - 1/3 tr(bbar) I) + K0 (J - 1) I,
!> bbar = J^(-2/3) F F^T. At C = I: S = 0 and C_ijkl = (K0 - 2/3 mu0) delta_ij delta_kl
!> + mu0 (delta_ik delta_jl + delta_il delta_jk), Hooke's law with mu = mu0 and bulk modulus K0,
!> i.e. E = 9 K0 mu0 / (3 K0 + mu0), nu = (3 K0 - 2 mu0) / (2 (3 K0 + mu0)).
!>
!> Voigt (frix_material): as in frix_neo_hookean, the input E carries engineering shears
!> (C_12 = 2 E_12 = gamma_12), S tensor shears, and the 6 x 6 tangent is C_ijkl with the Voigt
!> index map (11 22 33 12 13 23) and no factors of 2. Under small strain kinematics the strain eps
!> is used as if it were E, as frix_neo_hookean does (only meaningful in the small-strain limit,
!> where the law is Hooke's with mu0 and K0).
module frix_abaqus_neo_hooke
   use frix_kinds, only: dp
   use frix_vector_algebra, only: invert3
   use frix_symmetric_tensor, only: voigt_i, voigt_j, right_cauchy_green
   use frix_error, only: error_t, fatal_error, append_error
   use frix_strings, only: to_string
   use frix_material, only: material_t
   use frix_property_list, only: property_list_t
   implicit none
   private

   public :: abaqus_neo_hooke_t, new_abaqus_neo_hooke, abaqus_neo_hooke_from_properties

   !> Row i and column j of the symmetric 3 x 3 tensor behind Voigt index 1..6.

   !> Abaqus/CalculiX neo-Hookean material; no history.
   type, extends(material_t) :: abaqus_neo_hooke_t
      real(dp) :: c10 = 0.0_dp            !! C10 (stress unit)
      real(dp) :: d1 = 0.0_dp             !! D1 (1 / stress unit)
      real(dp) :: shear_modulus = 0.0_dp  !! mu0 = 2 C10
      real(dp) :: bulk_modulus = 0.0_dp   !! K0 = 2 / D1
      real(dp) :: young = 0.0_dp          !! small-strain E = 9 K0 mu0 / (3 K0 + mu0)
      real(dp) :: poisson = 0.0_dp        !! small-strain nu = (3 K0 - 2 mu0) / (2 (3 K0 + mu0))
   contains
      procedure :: n_state => abaqus_neo_hooke_n_state
      procedure :: response => abaqus_neo_hooke_response
      procedure :: elastic_tangent => abaqus_neo_hooke_elastic_tangent
   end type abaqus_neo_hooke_t

contains

   !> The material named by the deck keyword MAT_Struct_NeoHookeAbaqus.
   pure function new_abaqus_neo_hooke(c10, d1, density) result(material)
      real(dp), intent(in) :: c10      !! C10 (stress unit), > 0
      real(dp), intent(in) :: d1       !! D1 (1 / stress unit), > 0
      real(dp), intent(in) :: density  !! mass per unit reference volume, >= 0
      type(abaqus_neo_hooke_t) :: material
      material%name = 'MAT_Struct_NeoHookeAbaqus'
      material%c10 = c10
      material%d1 = d1
      material%density = density
      material%shear_modulus = 2.0_dp*c10
      material%bulk_modulus = 2.0_dp/d1
      associate (mu => material%shear_modulus, kappa => material%bulk_modulus)
         material%young = 9.0_dp*kappa*mu/(3.0_dp*kappa + mu)
         material%poisson = (3.0_dp*kappa - 2.0_dp*mu)/(2.0_dp*(3.0_dp*kappa + mu))
      end associate
   end function new_abaqus_neo_hooke

   !> The material of deck properties C10 (required, > 0), D1 (required, > 0; D1 = 0, the
   !> incompressible law, is not supported) and DENS (optional, >= 0, default 0).
   subroutine abaqus_neo_hooke_from_properties(properties, material, error)
      type(property_list_t), intent(in) :: properties
      class(material_t), allocatable, intent(out) :: material
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: c10, d1, density
      logical :: has_c10, has_d1, has_density
      character(len=:), allocatable :: law
      law = trim(properties%owner)
      call properties%check_names([character(len=4) :: 'C10', 'D1', 'DENS'], error)
      call properties%take_real('C10', c10, has_c10, error)
      call properties%take_real('D1', d1, has_d1, error)
      call properties%take_real('DENS', density, has_density, error, default=0.0_dp)
      if (has_c10 .and. .not. (c10 > 0.0_dp .and. c10 < huge(1.0_dp))) &
         call append_error(error, law//': C10 must be > 0, got '//to_string(c10))
      if (has_d1 .and. .not. (d1 > 0.0_dp .and. d1 < huge(1.0_dp))) then
         if (d1 == 0.0_dp) then
            call append_error(error, law//': D1 must be > 0, got 0 (D1 = 0, the incompressible law, '// &
                              'needs a mixed element and is not supported; give the D1 of the bulk modulus, D1 = 2/K)')
         else
            call append_error(error, law//': D1 must be > 0, got '//to_string(d1))
         end if
      end if
      if (has_density .and. .not. (density >= 0.0_dp)) &
         call append_error(error, law//': DENS must be >= 0, got '//to_string(density))
      if (.not. allocated(error)) allocate (material, source=new_abaqus_neo_hooke(c10, d1, density))
   end subroutine abaqus_neo_hooke_from_properties

   pure function abaqus_neo_hooke_n_state(self) result(n)
      class(abaqus_neo_hooke_t), intent(in) :: self
      integer :: n
      n = 0
   end function abaqus_neo_hooke_n_state

   !> Second Piola-Kirchhoff stress and tangent dS/dE for a Green-Lagrange strain E (module
   !> header). Fails if det C <= 0 (inverted or degenerate deformation).
   subroutine abaqus_neo_hooke_response(self, strain, finite, state_old, state_new, stress, tangent, error)
      class(abaqus_neo_hooke_t), intent(in) :: self
      real(dp), intent(in) :: strain(6)        !! Green-Lagrange E, Voigt, engineering shears
      logical, intent(in) :: finite            !! unused: the same law under both kinematics
      real(dp), intent(in) :: state_old(:)     !! unused (no history)
      real(dp), intent(inout) :: state_new(:)  !! unused (no history)
      real(dp), intent(out) :: stress(6)       !! S, Voigt, tensor shears
      real(dp), intent(out) :: tangent(6, 6)   !! dS/dE, Voigt
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: c(3, 3), inverse(3, 3), det_c, jacobian, first_invariant
      real(dp) :: iso, vol, delta_ij, delta_kl
      integer :: a, b, i, j, k, l

      stress = 0.0_dp
      tangent = 0.0_dp
      c = right_cauchy_green(strain)
      call invert3(c, inverse, det_c)
      if (.not. (det_c > 0.0_dp)) then
         call fatal_error(error, self%name//': det C = '//to_string(det_c)// &
                          ' <= 0 (inverted or degenerate deformation)')
         return
      end if
      jacobian = sqrt(det_c)
      first_invariant = c(1, 1) + c(2, 2) + c(3, 3)
      iso = self%shear_modulus*jacobian**(-2.0_dp/3.0_dp)   ! mu0 J^(-2/3)
      vol = self%bulk_modulus*jacobian                       ! K0 J

      do a = 1, 6
         i = voigt_i(a)
         j = voigt_j(a)
         delta_ij = merge(1.0_dp, 0.0_dp, i == j)
         stress(a) = iso*(delta_ij - first_invariant/3.0_dp*inverse(i, j)) &
                     + vol*(jacobian - 1.0_dp)*inverse(i, j)
         do b = 1, 6
            k = voigt_i(b)
            l = voigt_j(b)
            delta_kl = merge(1.0_dp, 0.0_dp, k == l)
            associate (outer => inverse(i, j)*inverse(k, l), &
                       cross => inverse(i, k)*inverse(j, l) + inverse(i, l)*inverse(j, k))
               tangent(a, b) = iso*(2.0_dp/9.0_dp*first_invariant*outer &
                                    - 2.0_dp/3.0_dp*(delta_ij*inverse(k, l) + inverse(i, j)*delta_kl) &
                                    + first_invariant/3.0_dp*cross) &
                               + vol*((2.0_dp*jacobian - 1.0_dp)*outer - (jacobian - 1.0_dp)*cross)
            end associate
         end do
      end do
   end subroutine abaqus_neo_hooke_response

   !> Tangent at E = 0: Hooke's matrix of mu0 and K0 (lambda = K0 - 2/3 mu0; engineering shears).
   pure subroutine abaqus_neo_hooke_elastic_tangent(self, tangent)
      class(abaqus_neo_hooke_t), intent(in) :: self
      real(dp), intent(out) :: tangent(6, 6)
      integer :: i
      tangent = 0.0_dp
      tangent(1:3, 1:3) = self%bulk_modulus - 2.0_dp/3.0_dp*self%shear_modulus
      do i = 1, 3
         tangent(i, i) = tangent(i, i) + 2.0_dp*self%shear_modulus
         tangent(i + 3, i + 3) = self%shear_modulus
      end do
   end subroutine abaqus_neo_hooke_elastic_tangent

end module frix_abaqus_neo_hooke
