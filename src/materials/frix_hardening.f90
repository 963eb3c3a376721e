!> Isotropic hardening of von Mises plasticity: the yield stress K(alpha) as a function of the
!> equivalent plastic strain alpha = integral of sqrt(2/3) |d eps_p| (Simo & Hughes,
!> Computational Inelasticity, Springer 1998, 2.3 and 3.3), in one of three forms:
!>   linear     K = SIGY + HARD alpha
!>   saturation K = SIGY + HARD alpha + (SIGINF - SIGY)(1 - exp(-DELTA alpha))
!>              (the saturation law of Voce with a linear term, as in Simo & Hughes 1998,
!>              3.3, and Simo, CMAME 99 (1992) 61-112, section 5)
!>   table      K piecewise linear through (0, SIGY), (EPSP1, SIGY1), (EPSP2, SIGY2), ...;
!>              constant beyond the last point (as Abaqus' *PLASTIC table).
!> Units: stresses in the deck's stress unit; alpha dimensionless.
module frix_hardening
   use frix_kinds, only: dp
   use frix_error, only: error_t, append_error
   use frix_strings, only: to_string
   use frix_property_list, only: property_list_t
   implicit none
   private

   public :: hardening_t, read_hardening, hardening_names, max_table_points

   integer, parameter :: max_table_points = 50   !! EPSP1 .. EPSP50

   type :: hardening_t
      real(dp) :: initial = 0.0_dp     !! SIGY: yield stress at alpha = 0
      real(dp) :: modulus = 0.0_dp     !! HARD: linear isotropic hardening modulus
      real(dp) :: saturation = 0.0_dp  !! SIGINF - SIGY (0: no exponential term)
      real(dp) :: rate = 0.0_dp        !! DELTA
      real(dp), allocatable :: strains(:)   !! table abscissae, 0 first, increasing
      real(dp), allocatable :: stresses(:)  !! table ordinates, SIGY first
   contains
      procedure :: yield_stress
      procedure :: slope
   end type hardening_t

contains

   !> The property names hardening takes: SIGY HARD SIGINF DELTA EPSP1 SIGY1 ... EPSP50 SIGY50.
   pure function hardening_names() result(names)
      character(len=8) :: names(4 + 2*max_table_points)
      integer :: k
      names(1:4) = [character(len=8) :: 'SIGY', 'HARD', 'SIGINF', 'DELTA']
      do k = 1, max_table_points
         names(3 + 2*k) = 'EPSP'//to_string(k)
         names(4 + 2*k) = 'SIGY'//to_string(k)
      end do
   end function hardening_names

   !> Hardening from the properties; every mistake is appended to `error`, prefixed by the law.
   !> SIGY > 0 required; HARD >= 0 (default 0); SIGINF >= SIGY with DELTA > 0 (both or neither);
   !> a table EPSPk/SIGYk, k = 1..n without gaps, EPSP strictly increasing from > 0, SIGYk > 0,
   !> excludes HARD, SIGINF and DELTA.
   subroutine read_hardening(properties, hardening, error)
      type(property_list_t), intent(in) :: properties
      type(hardening_t), intent(out) :: hardening
      type(error_t), allocatable, intent(inout) :: error
      character(len=:), allocatable :: law
      real(dp) :: limit
      logical :: has_initial, has_modulus, has_limit, has_rate
      law = trim(properties%owner)
      call properties%take_real('SIGY', hardening%initial, has_initial, error)
      call properties%take_real('HARD', hardening%modulus, has_modulus, error, default=0.0_dp)
      call properties%take_real('SIGINF', limit, has_limit, error, default=-1.0_dp)
      call properties%take_real('DELTA', hardening%rate, has_rate, error, default=0.0_dp)
      if (has_initial .and. .not. (hardening%initial > 0.0_dp .and. hardening%initial < huge(1.0_dp))) &
         call append_error(error, law//': SIGY must be > 0, got '//to_string(hardening%initial))
      if (.not. (hardening%modulus >= 0.0_dp .and. hardening%modulus < huge(1.0_dp))) &
         call append_error(error, law//': HARD must be >= 0, got '//to_string(hardening%modulus))
      if (given(properties, 'SIGINF') .neqv. given(properties, 'DELTA')) &
         call append_error(error, law//': SIGINF and DELTA go together (saturation hardening)')
      if (given(properties, 'SIGINF') .and. .not. (limit >= hardening%initial)) &
         call append_error(error, law//': SIGINF must be >= SIGY, got '//to_string(limit))
      if (given(properties, 'DELTA') .and. .not. (hardening%rate > 0.0_dp .and. hardening%rate < huge(1.0_dp))) &
         call append_error(error, law//': DELTA must be > 0, got '//to_string(hardening%rate))
      if (given(properties, 'SIGINF')) hardening%saturation = limit - hardening%initial
      call read_table(properties, law, hardening, error)
   end subroutine read_hardening

   !> The table EPSPk / SIGYk, if any, after the initial point (0, SIGY).
   subroutine read_table(properties, law, hardening, error)
      type(property_list_t), intent(in) :: properties
      character(len=*), intent(in) :: law
      type(hardening_t), intent(inout) :: hardening
      type(error_t), allocatable, intent(inout) :: error
      integer :: n, k
      logical :: found
      n = 0
      do k = 1, max_table_points
         if (.not. (given(properties, 'EPSP'//to_string(k)) .or. given(properties, 'SIGY'//to_string(k)))) exit
         n = k
      end do
      do k = n + 2, max_table_points
         if (given(properties, 'EPSP'//to_string(k)) .or. given(properties, 'SIGY'//to_string(k))) then
            call append_error(error, law//': the hardening table has a gap before point '//to_string(k))
            exit
         end if
      end do
      allocate (hardening%strains(n + 1), hardening%stresses(n + 1))
      hardening%strains(1) = 0.0_dp
      hardening%stresses(1) = hardening%initial
      if (n == 0) return
      if (given(properties, 'HARD') .or. given(properties, 'SIGINF') .or. given(properties, 'DELTA')) &
         call append_error(error, law//': a hardening table (EPSPk, SIGYk) excludes HARD, SIGINF and DELTA')
      do k = 1, n
         call properties%take_real('EPSP'//to_string(k), hardening%strains(k + 1), found, error)
         call properties%take_real('SIGY'//to_string(k), hardening%stresses(k + 1), found, error)
         if (.not. (hardening%strains(k + 1) > hardening%strains(k) .and. hardening%strains(k + 1) < huge(1.0_dp))) &
            call append_error(error, law//': EPSP'//to_string(k)//' must exceed the previous plastic strain, got '// &
                              to_string(hardening%strains(k + 1)))
         if (.not. (hardening%stresses(k + 1) > 0.0_dp .and. hardening%stresses(k + 1) < huge(1.0_dp))) &
            call append_error(error, law//': SIGY'//to_string(k)//' must be > 0, got '// &
                              to_string(hardening%stresses(k + 1)))
      end do
   end subroutine read_table

   logical function given(properties, name)
      type(property_list_t), intent(in) :: properties
      character(len=*), intent(in) :: name
      given = any(properties%names == name)
   end function given

   !> K(alpha), stress unit.
   pure real(dp) function yield_stress(self, alpha)
      class(hardening_t), intent(in) :: self
      real(dp), intent(in) :: alpha   !! equivalent plastic strain, >= 0
      integer :: k
      if (has_table(self)) then
         k = segment(self, alpha)
         if (k == 0) then
            yield_stress = self%stresses(size(self%stresses))
         else
            yield_stress = self%stresses(k) + (alpha - self%strains(k))* &
                           (self%stresses(k + 1) - self%stresses(k))/(self%strains(k + 1) - self%strains(k))
         end if
      else
         yield_stress = self%initial + self%modulus*alpha + self%saturation*(1.0_dp - exp(-self%rate*alpha))
      end if
   end function yield_stress

   !> K'(alpha) = dK/dalpha; on a table the slope of the segment holding alpha (the right
   !> one at a breakpoint), 0 beyond the last point.
   pure real(dp) function slope(self, alpha)
      class(hardening_t), intent(in) :: self
      real(dp), intent(in) :: alpha
      integer :: k
      if (has_table(self)) then
         k = segment(self, alpha)
         if (k == 0) then
            slope = 0.0_dp
         else
            slope = (self%stresses(k + 1) - self%stresses(k))/(self%strains(k + 1) - self%strains(k))
         end if
      else
         slope = self%modulus + self%saturation*self%rate*exp(-self%rate*alpha)
      end if
   end function slope

   pure logical function has_table(self)
      type(hardening_t), intent(in) :: self
      has_table = .false.
      if (allocated(self%strains)) has_table = size(self%strains) > 1
   end function has_table

   !> k with strains(k) <= alpha < strains(k + 1); 0 beyond the last point.
   pure integer function segment(self, alpha)
      type(hardening_t), intent(in) :: self
      real(dp), intent(in) :: alpha
      integer :: k
      segment = 0
      do k = 1, size(self%strains) - 1
         if (alpha < self%strains(k + 1)) then
            segment = k
            return
         end if
      end do
   end function segment
end module frix_hardening
