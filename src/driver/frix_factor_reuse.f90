!> Whether the factorization of the last tangent may serve a further Newton correction
!> (frix_newton_solver's reuse_factors: the re-solutions of an increment after an augmented
!> Lagrangian update of the multipliers, frix_augmentation). The multipliers enter the contact
!> forces, not the tangent (dp_N = -eps_N dg whatever lambda, frix_augmented_normal_law), so
!> the tangent of the last Newton solution is still the tangent of the next one while the
!> contact state it was assembled with holds: every slave node with the same status (open,
!> stick, slip) on the same master face, the penalties not grown, the sparse pattern not
!> rebuilt. The corrections are then those of the modified Newton method (Crisfield,
!> *Non-linear Finite Element Analysis of Solids and Structures*, vol. 1, Wiley 1991, 9.1),
!> each costing a residual evaluation and a forward and back substitution instead of a
!> tangent assembly and a factorization.
module frix_factor_reuse
   use frix_analysis_state, only: analysis_state_t
   use frix_contact_pass, only: contact_pass_t
   implicit none
   private

   public :: factor_reuse_t

   !> The contact state the factorized tangent was assembled with.
   type :: factor_reuse_t
      logical :: usable = .false.          !! a factorization of this increment's tangent exists
      integer :: pattern_id = 0            !! the sparse pattern it was factorized with
      integer, allocatable :: statuses(:)  !! per slave node of every pass: status, then master face
   contains
      procedure :: record => record_factors
      procedure :: discard => discard_factors
      procedure :: matches => factors_match
   end type factor_reuse_t

contains

   !> The tangent of `state` (sparse pattern `pattern_id`) was just factorized.
   subroutine record_factors(reuse, state, pattern_id)
      class(factor_reuse_t), intent(inout) :: reuse
      type(analysis_state_t), intent(in) :: state
      integer, intent(in) :: pattern_id
      reuse%usable = .true.
      reuse%pattern_id = pattern_id
      reuse%statuses = contact_signature(state)
   end subroutine record_factors

   !> The factorization is no longer the tangent (a new increment, a grown penalty).
   subroutine discard_factors(reuse)
      class(factor_reuse_t), intent(inout) :: reuse
      reuse%usable = .false.
   end subroutine discard_factors

   !> Whether the recorded factorization is the tangent of `state`, whose residual was just
   !> evaluated (the contact statuses and faces of that evaluation), with the matrix's sparse
   !> pattern `pattern_id`.
   logical function factors_match(reuse, state, pattern_id)
      class(factor_reuse_t), intent(in) :: reuse
      type(analysis_state_t), intent(in) :: state
      integer, intent(in) :: pattern_id
      integer, allocatable :: signature(:)
      factors_match = .false.
      if (.not. reuse%usable .or. pattern_id /= reuse%pattern_id .or. .not. allocated(reuse%statuses)) return
      signature = contact_signature(state)
      if (size(signature) /= size(reuse%statuses)) return
      factors_match = all(signature == reuse%statuses)
   end function factors_match

   !> The status and master face of every slave node of the node-to-segment passes, one after
   !> the other (empty without contact).
   function contact_signature(state) result(signature)
      type(analysis_state_t), intent(in) :: state
      integer, allocatable :: signature(:)
      integer :: p
      allocate (signature(0))
      if (.not. state%has_contact) return
      do p = 1, size(state%contact%passes)
         signature = [signature, pass_signature(state%contact%passes(p))]
      end do
   end function contact_signature

   !> Pass `pass`'s statuses followed by its nodes' master faces (empty for a pass without
   !> per-node results: a tie).
   pure function pass_signature(pass) result(signature)
      type(contact_pass_t), intent(in) :: pass
      integer, allocatable :: signature(:)
      allocate (signature(0))
      if (.not. allocated(pass%result)) return
      signature = pass%result%status
      if (allocated(pass%face)) signature = [signature, pass%face]
   end function pass_signature
end module frix_factor_reuse
