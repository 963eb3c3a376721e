!> Dual mortar weights of a tie (docs/contact.md, "Tied contact"): the constraint of slave
!> node s is
!>
!>     u_s = sum_a w_sa u_a,   w_sa = M_sa / sum_b M_sb,   M_sa = int_{Gamma_s} phi_s N_a dA,
!>
!> with N_a the master surface's bilinear shape functions and phi_s the dual (biorthogonal)
!> basis of the slave surface, int phi_j N_k dA = delta_jk int N_k dA on each slave face
!> (Wohlmuth, SIAM J. Numer. Anal. 38 (2000) 989-1012; for tying, Puso, IJNME 59 (2004)
!> 315-336). Where the master covers the slave node's faces, sum_b M_sb = int N_s dA, the
!> slave node's tributary area. Then the elimination transmits a constant stress exactly
!> (the slave force p A_s spreads over the master nodes as p int N_a dA) and a linear
!> displacement field satisfies the constraint: the tie passes the patch test on
!> non-matching meshes, which a constraint to the closest point does not.
!>
!> Integration: segment-wise over the clipped overlaps of slave and master faces
!> (frix_mortar_segments, shared with mortar contact). Reference configuration; computed once.
module frix_tie_mortar
   use frix_kinds, only: dp
   use frix_surface_load, only: face_area_weights
   use frix_mortar_segments, only: triplets_t, mortar_triplets, compress_rows
   implicit none
   private

   public :: tie_coupling_t, mortar_coupling

   !> The weights of every slave node as compressed rows: node i's master nodes
   !> nodes(start(i) + 1 : start(i + 1)) with weights weight(same); covered(i) is the
   !> fraction of node i's slave area the master covers (1 where it covers it all).
   type :: tie_coupling_t
      integer, allocatable :: start(:), nodes(:)
      real(dp), allocatable :: weight(:), covered(:)
   end type tie_coupling_t

contains

   !> The dual mortar weights of `slave_nodes` (mesh numbers) over the slave faces
   !> slave_faces(4, :) against master_faces(4, :), in the reference coordinates `coords`.
   !> A master face is paired with a slave face when their bounding boxes, widened by
   !> `distance`, meet, its centre lies within `distance` of the slave face's plane and it
   !> faces the other way. Cost: every slave face is tested against every master face's box.
   subroutine mortar_coupling(coords, slave_nodes, slave_faces, master_faces, distance, coupling)
      real(dp), intent(in) :: coords(:, :)
      integer, intent(in) :: slave_nodes(:), slave_faces(:, :), master_faces(:, :)
      real(dp), intent(in) :: distance
      type(tie_coupling_t), intent(out) :: coupling
      type(triplets_t) :: m
      real(dp), allocatable :: area(:)
      integer, allocatable :: position_of(:)
      real(dp) :: face_weights(4)
      integer :: f, j
      allocate (position_of(size(coords, 2)), source=0)
      do j = 1, size(slave_nodes)
         position_of(slave_nodes(j)) = j
      end do
      allocate (area(size(slave_nodes)), source=0.0_dp)
      do f = 1, size(slave_faces, 2)
         ! the slave nodes' tributary areas, as frix_contact_pass's set_slave_nodes takes them
         call face_area_weights(coords(:, slave_faces(:, f)), face_weights)
         area(position_of(slave_faces(:, f))) = area(position_of(slave_faces(:, f))) + face_weights
      end do
      call mortar_triplets(coords, slave_nodes, slave_faces, master_faces, distance, m)
      call compress(m, area, coupling)
   end subroutine mortar_coupling

   !> Rows of M as weights w_sa = M_sa / sum_b M_sb (compress_rows: repeats summed, entries
   !> below 1e-12 of the row's largest dropped); covered = sum_b M_sb / area.
   subroutine compress(m, area, coupling)
      type(triplets_t), intent(in) :: m
      real(dp), intent(in) :: area(:)
      type(tie_coupling_t), intent(out) :: coupling
      integer :: j
      real(dp) :: row_sum
      call compress_rows(m, size(area), coupling%start, coupling%nodes, coupling%weight)
      allocate (coupling%covered(size(area)))
      do j = 1, size(area)
         associate (values => coupling%weight(coupling%start(j) + 1:coupling%start(j + 1)))
            row_sum = sum(values)
            coupling%covered(j) = row_sum/area(j)
            if (row_sum /= 0.0_dp) values = values/row_sum
         end associate
      end do
   end subroutine compress
end module frix_tie_mortar
