!> Shared fixtures of the contact tests: faces, parameters, and the central-difference check
!> of the contact tangents.
module test_contact_fixtures
   use frix_kinds, only: dp
   use frix_error, only: error_t, fatal_error
   use frix_strings, only: to_string
   use frix_coulomb_friction, only: new_coulomb_friction
   use frix_penalty_normal_law, only: new_penalty_normal_law
   use frix_contact_parameters, only: contact_parameters_t
   use frix_contact_kernel, only: contact_point_result_t, node_face_contact, node_plane_contact
   use frix_smoothed_normals, only: patch_normals, smooth_normal_at
   use frix_face_projection, only: face_position, face_normal
   implicit none
   private

   public :: warped_face, flat_face, make_parameters, check_face_tangent, check_plane_tangent
   public :: asymmetry, slave_below, grid_patch, slave_below_smoothed, grid_faces, fold_surface, profile_normal

   !> A warped, skewed face (no two edges parallel, nodes not coplanar), counter-clockwise
   !> seen from +z: outward normal roughly +z. Size about 2.
   real(dp), parameter :: warped_face(3, 4) = reshape([0.0_dp, 0.0_dp, 0.0_dp, 2.1_dp, 0.2_dp, 0.3_dp, &
                                                        1.8_dp, 1.7_dp, -0.2_dp, -0.3_dp, 1.2_dp, 0.4_dp], [3, 4])
   !> The rectangle [0, 2] x [0, 1] in the plane z = 0, outward normal +z; xi1 = x - 1,
   !> xi2 = 2 y - 1.
   real(dp), parameter :: flat_face(3, 4) = reshape([0.0_dp, 0.0_dp, 0.0_dp, 2.0_dp, 0.0_dp, 0.0_dp, &
                                                      2.0_dp, 1.0_dp, 0.0_dp, 0.0_dp, 1.0_dp, 0.0_dp], [3, 4])

   !> Relative step of the central differences (times the face size) and the tolerance on
   !> max |K_fd - K| relative to max |K|: the central difference error is O(h^2) ~ 1e-14 plus
   !> round-off ~ 1e-16 |f| / h ~ 1e-9 |f|, with |f| / max|K| ~ the penetration (0.01-0.02):
   !> about 1e-11 to 1e-10 measured (max 4e-10), hence 1e-8. A tangent missing the
   !> closest-point derivative errs by 5e-3, one missing the anchor's motion by 1e-2 or more.
   real(dp), parameter :: relative_step = 1.0e-7_dp
   real(dp), parameter :: tangent_tolerance = 1.0e-8_dp

contains

   !> eps_N = 1e4, eps_T = 1e3 (force/area/length), Coulomb mu (0: frictionless).
   function make_parameters(coefficient) result(parameters)
      real(dp), intent(in) :: coefficient
      type(contact_parameters_t) :: parameters
      allocate (parameters%normal, source=new_penalty_normal_law(1.0e4_dp))
      parameters%tangential_penalty = 1.0e3_dp
      parameters%gap_tolerance = 1.0e-4_dp
      allocate (parameters%friction, source=new_coulomb_friction(coefficient))
   end function make_parameters

   !> The point at depth `depth` below the face point of coordinates xi (along -n there):
   !> its closest point is xi (for a depth small against the curvature radius).
   pure function slave_below(face, xi, depth) result(point)
      real(dp), intent(in) :: face(3, 4), xi(2), depth
      real(dp) :: point(3)
      point = face_position(face, xi) - depth*face_normal(face, xi)
   end function slave_below

   !> max |K - K^T| / max |K|.
   pure real(dp) function asymmetry(tangent)
      real(dp), intent(in) :: tangent(:, :)
      asymmetry = maxval(abs(tangent - transpose(tangent)))/maxval(abs(tangent))
   end function asymmetry

   !> The patch of face (i, j) (i, j = 1..3) of a curved, irregular 4 x 4 node grid of 3 x 3
   !> faces (counter-clockwise seen from +z, outward normal roughly +z, unit spacing): the
   !> face's nodes, the other nodes of the faces sharing a node with it (x_ring) and those
   !> faces in local node numbers (1-4 the face's, 4 + k x_ring(:, k)), as node_face_contact
   !> takes them for smoothed normals. Face (2, 2) has the full ring of 12 nodes; a face on
   !> the grid's border has a smaller one. The surface z = 0.15 (x - 1.5)^2 - 0.1 (y - 1.5)^2
   !> + 0.05 x y, with x, y perturbed by up to 0.07, makes the averaged nodal normals differ
   !> from every facet normal.
   subroutine grid_patch(i, j, x_face, x_ring, patch_faces)
      integer, intent(in) :: i, j
      real(dp), intent(out) :: x_face(3, 4)
      real(dp), allocatable, intent(out) :: x_ring(:, :)
      integer, allocatable, intent(out) :: patch_faces(:, :)
      integer, allocatable :: ring(:)
      integer :: gi, gj, b, k, corner(4), nodes(4)
      allocate (ring(0), patch_faces(4, 0))
      corner = face_corners(i, j)
      do gj = max(1, j - 1), min(3, j + 1)
         do gi = max(1, i - 1), min(3, i + 1)
            nodes = face_corners(gi, gj)
            do b = 1, 4
               if (all(corner /= nodes(b)) .and. all(ring /= nodes(b))) ring = [ring, nodes(b)]
            end do
            patch_faces = reshape([reshape(patch_faces, [size(patch_faces)]), (local(nodes(b)), b=1, 4)], &
                                  [4, size(patch_faces, 2) + 1])
         end do
      end do
      do b = 1, 4
         x_face(:, b) = grid_point(corner(b))
      end do
      allocate (x_ring(3, size(ring)))
      do k = 1, size(ring)
         x_ring(:, k) = grid_point(ring(k))
      end do
   contains
      !> Nodes of face (fi, fj), numbered n = 1 + gi + 4 gj for grid point (gi, gj), gi, gj = 0..3.
      pure function face_corners(fi, fj) result(nodes)
         integer, intent(in) :: fi, fj
         integer :: nodes(4)
         nodes = [fi + 4*(fj - 1), fi + 1 + 4*(fj - 1), fi + 1 + 4*fj, fi + 4*fj]
      end function face_corners
      integer function local(n)
         integer, intent(in) :: n
         local = findloc(corner, n, dim=1)
         if (local == 0) local = 4 + findloc(ring, n, dim=1)
      end function local
      pure function grid_point(n) result(x)
         integer, intent(in) :: n
         real(dp) :: x(3), gx, gy
         gx = real(mod(n - 1, 4), dp)
         gy = real((n - 1)/4, dp)
         x(1) = gx + 0.07_dp*sin(1.3_dp*gx + 0.4_dp*gy)
         x(2) = gy + 0.05_dp*cos(0.7_dp*gx + 1.1_dp*gy)
         x(3) = 0.15_dp*(x(1) - 1.5_dp)**2 - 0.1_dp*(x(2) - 1.5_dp)**2 + 0.05_dp*x(1)*x(2)
      end function grid_point
   end subroutine grid_patch

   !> A master surface with a 90-degree fold and a gentle curve: a profile in the x-z plane of
   !> 6 unit segments, segment s leaving its start point P(s - 1) in the direction
   !> (cos t_s, 0, sin t_s), t = 0, 0, -90, -100, -110, -120 degrees from P0 = (-2, 0, 0) (a
   !> convex 90-degree edge at P2 = origin, then 10-degree turns), extruded over y = 0, 1, 2.
   !> Node 1 + k + 7 r is P(k) at y = r; face s + 6 (r - 1) (s = 1..6, r = 1, 2) has the
   !> corners P(s - 1), P(s) at y = r - 1, then P(s), P(s - 1) at y = r, outward normal
   !> profile_normal(t_s) = (-sin t_s, 0, cos t_s).
   subroutine fold_surface(coords, faces)
      real(dp), intent(out) :: coords(3, 21)
      integer, intent(out) :: faces(4, 12)
      real(dp), parameter :: turn(6) = [0.0_dp, 0.0_dp, -90.0_dp, -100.0_dp, -110.0_dp, -120.0_dp]
      real(dp), parameter :: degree = acos(-1.0_dp)/180.0_dp
      real(dp) :: point(3)
      integer :: k, r, s
      do r = 0, 2
         point = [-2.0_dp, real(r, dp), 0.0_dp]
         coords(:, 1 + 7*r) = point
         do k = 1, 6
            point = point + [cos(turn(k)*degree), 0.0_dp, sin(turn(k)*degree)]
            coords(:, 1 + k + 7*r) = point
         end do
      end do
      do r = 1, 2
         do s = 1, 6
            faces(:, s + 6*(r - 1)) = [s + 7*(r - 1), s + 1 + 7*(r - 1), s + 1 + 7*r, s + 7*r]
         end do
      end do
   end subroutine fold_surface

   !> The outward unit normal (-sin t, 0, cos t) of fold_surface's segments at angle t (degrees).
   pure function profile_normal(turn) result(normal)
      real(dp), intent(in) :: turn
      real(dp) :: normal(3)
      real(dp), parameter :: degree = acos(-1.0_dp)/180.0_dp
      normal = [-sin(turn*degree), 0.0_dp, cos(turn*degree)]
   end function profile_normal

   !> The faces of an (n + 1) x (n + 1) grid of nodes numbered 1 + i + (n + 1) j (i, j = 0..n,
   !> i along x): face 1 + i + n j has corners (i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1),
   !> counter-clockwise seen from +z.
   pure function grid_faces(n) result(faces)
      integer, intent(in) :: n
      integer :: faces(4, n*n)
      integer :: i, j, corner
      do j = 0, n - 1
         do i = 0, n - 1
            corner = 1 + i + (n + 1)*j
            faces(:, 1 + i + n*j) = [corner, corner + 1, corner + n + 2, corner + n + 1]
         end do
      end do
   end function grid_faces

   !> The point at depth `depth` below x(xi) along the smoothed normal there: its projection
   !> along the smoothed normals is xi.
   function slave_below_smoothed(x_face, x_ring, patch_faces, xi, depth) result(point)
      real(dp), intent(in) :: x_face(3, 4), x_ring(:, :), xi(2), depth
      integer, intent(in) :: patch_faces(:, :)
      real(dp) :: point(3)
      point = face_position(x_face, xi) - depth*smooth_normal_at(patch_normals(x_face, x_ring, patch_faces), xi)
   end function slave_below_smoothed

   !> Tangent of node_face_contact against central differences of fint, all 15 unknowns (27
   !> with an anchor on another face, x_anchor_face; 3 more per ring node with smoothed
   !> normals, x_ring and patch_faces); fails if the status (or the clamped flag)
   !> differs from `expected_status` at the base point or at any perturbed point (the
   !> difference must not cross a branch).
   subroutine check_face_tangent(error, parameters, x_slave, x_master, area, anchor_xi, has_anchor, clamp, &
                                 expected_status, tangent, x_anchor_face, x_ring, patch_faces, tangential_multiplier, &
                                 free_edges)
      type(error_t), allocatable, intent(out) :: error
      type(contact_parameters_t), intent(in) :: parameters
      real(dp), intent(in) :: x_slave(3), x_master(3, 4), area, anchor_xi(2)
      logical, intent(in) :: has_anchor, clamp
      integer, intent(in) :: expected_status
      !> (n, n), n = 15, + 12 with x_anchor_face, + 3 size(x_ring, 2) with smoothed normals
      real(dp), intent(out) :: tangent(:, :)
      real(dp), intent(in), optional :: x_anchor_face(3, 4)
      real(dp), intent(in), optional :: x_ring(:, :)
      integer, intent(in), optional :: patch_faces(:, :)
      real(dp), intent(in), optional :: tangential_multiplier(3)   !! augmented friction's lambda_T
      logical, intent(in), optional :: free_edges(4)   !! the master face's free edges (the fade)
      type(contact_point_result_t) :: base, plus, minus
      real(dp), allocatable :: q(:), qp(:), fint(:), f_plus(:), f_minus(:), k_other(:, :), column(:)
      real(dp) :: h, scale, worst
      integer :: j, n, ring_first

      n = merge(27, 15, present(x_anchor_face))
      ring_first = n + 1
      if (present(x_ring)) n = n + size(x_ring)
      allocate (q(n), fint(n), f_plus(n), f_minus(n), k_other(n, n), column(n))
      q(1:3) = x_slave
      q(4:15) = reshape(x_master, [12])
      if (present(x_anchor_face)) q(16:27) = reshape(x_anchor_face, [12])
      if (present(x_ring)) q(ring_first:) = reshape(x_ring, [size(x_ring)])
      h = relative_step*maxval(abs(x_master))
      call evaluate(q, base, fint, tangent)
      if (base%status /= expected_status) then
         call fatal_error(error, 'status '//to_string(base%status)//', expected '//to_string(expected_status))
         return
      end if
      scale = maxval(abs(tangent))
      worst = 0.0_dp
      do j = 1, n
         qp = q
         qp(j) = q(j) + h
         call evaluate(qp, plus, f_plus, k_other)
         qp(j) = q(j) - h
         call evaluate(qp, minus, f_minus, k_other)
         if (plus%status /= expected_status .or. minus%status /= expected_status .or. &
             (plus%clamped .neqv. base%clamped) .or. (minus%clamped .neqv. base%clamped)) then
            call fatal_error(error, 'the difference of unknown '//to_string(j)//' crosses a branch')
            return
         end if
         column = (f_plus - f_minus)/(2.0_dp*h)
         worst = max(worst, maxval(abs(column - tangent(:, j))))
      end do
      if (expected_status == 0) then
         if (maxval(abs(fint)) > 0.0_dp .or. scale > 0.0_dp .or. worst > 0.0_dp) &
            call fatal_error(error, 'open contact must give exactly zero force and tangent')
         return
      end if
      if (.not. (worst <= tangent_tolerance*scale)) &
         call fatal_error(error, 'tangent vs central differences: max error '//to_string(worst)// &
                          ', max |K| '//to_string(scale))
   contains
      subroutine evaluate(unknowns, result, force, stiffness)
         real(dp), intent(in) :: unknowns(:)
         type(contact_point_result_t), intent(out) :: result
         real(dp), intent(out) :: force(:), stiffness(:, :)
         ! unallocated: absent
         real(dp), allocatable :: anchor_face(:, :), ring(:, :)
         if (present(x_anchor_face)) anchor_face = reshape(unknowns(16:27), [3, 4])
         if (present(x_ring)) ring = reshape(unknowns(ring_first:), [3, size(x_ring, 2)])
         call node_face_contact(parameters, unknowns(1:3), reshape(unknowns(4:15), [3, 4]), area, anchor_xi, &
                                has_anchor, clamp, result, force, stiffness, x_anchor_face=anchor_face, &
                                x_ring=ring, patch_faces=patch_faces, tangential_multiplier=tangential_multiplier, &
                                free_edges=free_edges)
      end subroutine evaluate
   end subroutine check_face_tangent

   !> Tangent of node_plane_contact against central differences (3 unknowns), same rules.
   subroutine check_plane_tangent(error, parameters, x_slave, plane_point, plane_normal, area, anchor, &
                                  expected_status, tangent, tangential_multiplier)
      type(error_t), allocatable, intent(out) :: error
      type(contact_parameters_t), intent(in) :: parameters
      real(dp), intent(in) :: x_slave(3), plane_point(3), plane_normal(3), area, anchor(3)
      integer, intent(in) :: expected_status
      real(dp), intent(out) :: tangent(3, 3)
      real(dp), intent(in), optional :: tangential_multiplier(3)   !! augmented friction's lambda_T
      type(contact_point_result_t) :: base, plus, minus
      real(dp) :: xp(3), fint(3), f_plus(3), f_minus(3), k_other(3, 3), column(3), h, worst
      integer :: j

      h = relative_step*max(1.0_dp, maxval(abs(x_slave)))
      call node_plane_contact(parameters, x_slave, plane_point, plane_normal, area, anchor, .true., base, &
                              fint, tangent, tangential_multiplier=tangential_multiplier)
      if (base%status /= expected_status) then
         call fatal_error(error, 'status '//to_string(base%status)//', expected '//to_string(expected_status))
         return
      end if
      worst = 0.0_dp
      do j = 1, 3
         xp = x_slave
         xp(j) = x_slave(j) + h
         call node_plane_contact(parameters, xp, plane_point, plane_normal, area, anchor, .true., plus, &
                                 f_plus, k_other, tangential_multiplier=tangential_multiplier)
         xp(j) = x_slave(j) - h
         call node_plane_contact(parameters, xp, plane_point, plane_normal, area, anchor, .true., minus, &
                                 f_minus, k_other, tangential_multiplier=tangential_multiplier)
         if (plus%status /= expected_status .or. minus%status /= expected_status) then
            call fatal_error(error, 'the difference of unknown '//to_string(j)//' crosses a branch')
            return
         end if
         column = (f_plus - f_minus)/(2.0_dp*h)
         worst = max(worst, maxval(abs(column - tangent(:, j))))
      end do
      if (.not. (worst <= tangent_tolerance*maxval(abs(tangent)))) &
         call fatal_error(error, 'tangent vs central differences: max error '//to_string(worst)// &
                          ', max |K| '//to_string(maxval(abs(tangent))))
   end subroutine check_plane_tangent
end module test_contact_fixtures
