!> The extension zone of a free edge of a master surface (an edge of only one master face of
!> the pass: the surface's boundary; docs/contact.md, "Edges and corners"), shared by the
!> contact search, which opens a slave node beyond it, and the contact kernel, which fades the
!> force of a node clamped onto the edge over the zone's outer half.
!>
!> Edge k of a face joins its nodes k and mod(k, 4) + 1 (face order); along it parent
!> coordinate edge_coordinate(k) is held at edge_value(k). The face's length across edge k is
!> the mean of the two face edges that meet it, |x_after - x_second| and |x_first - x_before|
!> (edge_nodes), current configuration.
module frix_free_edge_zone
   use frix_kinds, only: dp
   implicit none
   private

   public :: extension_zone, fade_start, edge_nodes, clamped_on_edge

   !> The zone, as a fraction of the face's length across the edge: a slave node up to this far
   !> beyond the edge still gets the face (so that a node of coextensive surfaces that round-off
   !> or the deformation puts just beyond the boundary is not lost), farther it is open. 0.1 is
   !> Abaqus' default for node-to-surface contact (*CONTACT PAIR, EXTENSION ZONE: "a fraction of
   !> the end segment or facet edge length", default 0.1; Abaqus Keywords Reference).
   real(dp), parameter :: extension_zone = 0.1_dp
   !> Where the fade begins, as a fraction of the zone: the force of a node clamped onto a free
   !> edge is multiplied by w = 1 - 3 s^2 + 2 s^3, s = (b - fade_start z) / ((1 - fade_start) z)
   !> in [0, 1], b its distance beyond the edge, z the zone's length (smoothstep: w and dw/db
   !> continuous, w = 1 up to half the zone, 0 at its end, where the search opens the node).
   !> A node carrying a large share of the load at the zone's end (a slab resting on the
   !> master's edge) was dropped at once and the run stopped there
   !> (tests/contact_robustness, slide_off_end_far); nodes of coextensive surfaces lie well
   !> inside the first half.
   real(dp), parameter :: fade_start = 0.5_dp

   !> The parent coordinate held along edge k, and its value there.
   integer, parameter :: edge_coordinate(4) = [2, 1, 2, 1]
   real(dp), parameter :: edge_value(4) = [-1.0_dp, 1.0_dp, 1.0_dp, -1.0_dp]

contains

   !> The face's local nodes of edge k (first, second: the edge in face order) and the two
   !> across it (after: next to second, before: next to first).
   pure subroutine edge_nodes(k, first, second, after, before)
      integer, intent(in) :: k
      integer, intent(out) :: first, second, after, before
      first = k
      second = mod(k, 4) + 1
      after = mod(k + 1, 4) + 1
      before = mod(k + 2, 4) + 1
   end subroutine edge_nodes

   !> Whether the clamped closest point xi (closest_point_in_face's, `fixed` its clamped
   !> coordinates, set to exactly -1 or +1) lies on edge k (an edge point or one of its corners).
   pure logical function clamped_on_edge(k, xi, fixed)
      integer, intent(in) :: k
      real(dp), intent(in) :: xi(2)
      logical, intent(in) :: fixed(2)
      clamped_on_edge = fixed(edge_coordinate(k)) .and. xi(edge_coordinate(k)) == edge_value(k)
   end function clamped_on_edge
end module frix_free_edge_zone
