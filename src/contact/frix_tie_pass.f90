!> The slave side of a tie (deck `TIE`, docs/contact.md "Tied contact"): which slave nodes
!> are tied and to which master nodes, with the dual mortar weights of frix_tie_mortar,
!>
!>     u_s = sum_a w_sa u_a.
!>
!> The constraint is on displacements: an initial offset between the surfaces is kept. A
!> slave node is tied when the master surface covers at least half of its tributary area and
!> its closest point on the master surface lies within the tie's position tolerance
!> (reference configuration); that closest point (pass%face, pass%anchor_xi) gives the
!> normal of the output. The elimination from the global system is frix_tie_constraints'.
module frix_tie_pass
   use frix_kinds, only: dp
   use frix_face_projection, only: face_position
   use frix_contact_pass, only: contact_pass_t
   use frix_contact_search, only: initial_anchors
   use frix_tie_mortar, only: mortar_coupling
   implicit none
   private

   public :: setup_tie, tie_masters, tie_weights

   !> Default position tolerance: this factor times the master's mean face size
   !> (pass%face_size, frix_contact_pass's set_master_faces).
   real(dp), parameter :: default_tie_tolerance_factor = 0.1_dp
   !> least fraction of a slave node's area the master must cover for the node to be tied
   real(dp), parameter :: least_coverage = 0.5_dp

contains

   !> Ties of a pass whose slave nodes, master faces and state are set; slave_faces(4, :) are
   !> the slave surface's faces (mesh node numbers, outward order); tolerance < 0: default.
   !> pass%face(i) = 0 for the slave nodes left untied.
   subroutine setup_tie(coords, slave_faces, tolerance, pass)
      real(dp), intent(in) :: coords(:, :)   !! reference coordinates (3, n_nodes)
      integer, intent(in) :: slave_faces(:, :)
      real(dp), intent(in) :: tolerance      !! position tolerance (length), < 0: default
      type(contact_pass_t), intent(inout) :: pass
      real(dp) :: used_tolerance, distance
      integer :: i, f
      pass%tied = .true.
      used_tolerance = tolerance
      if (used_tolerance < 0.0_dp) used_tolerance = default_tie_tolerance_factor*pass%face_size
      pass%band = max(pass%band, used_tolerance)
      call initial_anchors(coords, 0.0_dp, pass)
      call mortar_coupling(coords, pass%slave_nodes, slave_faces, pass%faces, used_tolerance, pass%tie)
      do i = 1, size(pass%slave_nodes)
         f = pass%face(i)
         if (f == 0) cycle
         distance = norm2(coords(:, pass%slave_nodes(i)) - face_position(coords(:, pass%faces(:, f)), &
                                                                         pass%anchor_xi(:, i)))
         if (distance > used_tolerance .or. pass%tie%covered(i) < least_coverage) then
            pass%face(i) = 0
            pass%anchor_face(i) = 0
            pass%has_anchor(i) = .false.
         end if
      end do
   end subroutine setup_tie

   !> The master nodes slave i of a tied pass is bound to.
   pure function tie_masters(pass, i) result(nodes)
      type(contact_pass_t), intent(in) :: pass
      integer, intent(in) :: i
      integer, allocatable :: nodes(:)
      nodes = pass%tie%nodes(pass%tie%start(i) + 1:pass%tie%start(i + 1))
   end function tie_masters

   !> Their weights w_sa (summing to 1).
   pure function tie_weights(pass, i) result(weights)
      type(contact_pass_t), intent(in) :: pass
      integer, intent(in) :: i
      real(dp), allocatable :: weights(:)
      weights = pass%tie%weight(pass%tie%start(i) + 1:pass%tie%start(i + 1))
   end function tie_weights
end module frix_tie_pass
