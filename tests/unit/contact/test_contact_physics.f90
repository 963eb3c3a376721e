!> Physics of the contact kernel against hand calculations on the flat rectangle
!> [0, 2] x [0, 1] x {0} (xi1 = x - 1, xi2 = 2y - 1, n = +z) and on a rigid plane:
!>   - normal: a slave at depth d gets f = eps_N d A n; master node a gets -N_a(xi) f, N_a the
!>     bilinear shape functions at the hand-computed xi; the forces sum to zero;
!>   - stick: t = -eps_T (I - n n)(x_s - x_A);
!>   - slip: |t| = mu p_N, t parallel and opposite to the elastic slip g_T;
!>   - the updated anchor reproduces t at the same configuration, and the slip increment is the
!>     distance between the old and new anchor;
!>   - the anchor is a material point of the master: a rigid rotation and translation of slave
!>     and master together rotates the traction and leaves p_N unchanged (history follows
!>     large sliding);
!>   - beyond an edge without clamp the kernel reports `outside` and gives no force;
!>   - clamped beyond a free edge of the master surface, the force is faded by the smoothstep
!>     1 - 3 s^2 + 2 s^3 over the outer half of the extension zone (0.1 of the face's length
!>     across the edge, here 0.2): 1 at 0.05 beyond, 1/2 at 0.15, 0 at 0.2 and farther;
!>   - a friction scale f (the driver's friction continuation) gives exactly the response with
!>     mu replaced by f mu, on a face and on a plane, in slip and where it turns slip into stick;
!>   - smoothed normals: on a flat patch they give the facet formulation's forces; on a curved
!>     patch the normal, gap and pressure of a slave below a point of an edge shared by two
!>     faces are the same whichever face it is evaluated on (the facet normals differ there),
!>     and the contact point is the normal projection (x_s - x(xi) parallel to n(xi)).
module test_contact_physics
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_testing, only: unittest_t, new_unittest, check, check_close
   use frix_strings, only: to_string
   use frix_contact_kernel, only: contact_point_result_t, node_face_contact, node_plane_contact, &
                                  contact_open, contact_stick, contact_slip
   use frix_contact_parameters, only: contact_parameters_t
   use frix_face_projection, only: face_position
   use test_contact_fixtures, only: flat_face, warped_face, make_parameters, slave_below, grid_patch, &
                                    slave_below_smoothed
   use frix_smoothed_normals, only: patch_normals, smooth_normal_at
   use frix_face_projection, only: face_normal
   implicit none
   private

   public :: collect_contact_physics

   real(dp), parameter :: area = 0.5_dp, depth = 0.01_dp, mu = 0.3_dp
   real(dp), parameter :: eps_n = 1.0e4_dp, eps_t = 1.0e3_dp   !! as in make_parameters
   !> Slave above-below (x, y) = (0.5, 0.25): xi = (-0.5, -0.5), N = (9, 3, 1, 3)/16.
   real(dp), parameter :: slave_xy(2) = [0.5_dp, 0.25_dp]
   real(dp), parameter :: expected_shape(4) = [9.0_dp, 3.0_dp, 1.0_dp, 3.0_dp]/16.0_dp

contains

   subroutine collect_contact_physics(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('flat face: f = eps_N d A n, split by N_a, sum zero', test_normal_force), &
               new_unittest('flat face: stick traction = -eps_T g_T', test_stick_traction), &
               new_unittest('flat face: slip |t| = mu p_N opposite g_T', test_slip_traction), &
               new_unittest('slip: the new anchor reproduces t, slip increment', test_anchor_update), &
               new_unittest('warped face: new anchor reproduces t', test_anchor_update_warped), &
               new_unittest('rigid motion: traction rotates with the master', test_rigid_motion), &
               new_unittest('beyond an edge without clamp: outside, no force', test_outside), &
               new_unittest('rigid plane: normal force, stick and slip', test_plane_physics), &
               new_unittest('separated node: open, anchor = closest point', test_open_anchor), &
               new_unittest('crossing an edge with clamp: force continuous', test_edge_continuity), &
               new_unittest('beyond a free edge: force faded over the zone''s outer half', test_free_edge_fade), &
               new_unittest('friction scale f: the response of f mu', test_friction_scale), &
               new_unittest('smoothed normals on a flat patch: the facet forces', test_smoothed_flat), &
               new_unittest('smoothed normals: continuous across a shared edge', test_smoothed_continuity)]
   end subroutine collect_contact_physics

   subroutine test_normal_force(error)
      type(error_t), allocatable, intent(out) :: error
      type(contact_point_result_t) :: result
      real(dp) :: fint(15), tangent(15, 15), force
      integer :: a
      call node_face_contact(make_parameters(0.0_dp), [slave_xy(1), slave_xy(2), -depth], flat_face, area, &
                             [0.0_dp, 0.0_dp], .false., .false., result, fint, tangent)
      call check(error, result%status == contact_slip .and. .not. result%outside, 'frictionless contact')
      if (allocated(error)) return
      call check_close(error, result%gap, -depth, 1.0e-13_dp, message='gap')
      if (allocated(error)) return
      call check_close(error, result%xi(1), -0.5_dp, 0.0_dp, 1.0e-14_dp, 'xi1')
      if (allocated(error)) return
      call check_close(error, result%xi(2), -0.5_dp, 0.0_dp, 1.0e-14_dp, 'xi2')
      if (allocated(error)) return
      call check_close(error, result%pressure, eps_n*depth, 1.0e-13_dp, message='p_N')
      if (allocated(error)) return
      force = eps_n*depth*area
      ! fint = -(force on the slave) = -(0, 0, force); master node a: +N_a (0, 0, force).
      call check_close(error, fint(3), -force, 1.0e-13_dp, message='slave fint z')
      if (allocated(error)) return
      call check(error, maxval(abs(fint(1:2))) <= 1.0e-13_dp*force, 'slave fint x, y = 0')
      if (allocated(error)) return
      do a = 1, 4
         call check_close(error, fint(3*a + 3), expected_shape(a)*force, 1.0e-13_dp, &
                          message='master node '//to_string(a)//' fint z')
         if (allocated(error)) return
      end do
      call check(error, abs(sum(fint(3::3))) <= 1.0e-13_dp*force .and. abs(sum(fint(1::3))) <= 1.0e-13_dp*force &
                 .and. abs(sum(fint(2::3))) <= 1.0e-13_dp*force, 'action = reaction: forces sum to zero')
      if (allocated(error)) return
      ! Normal stiffness: d fint_slave_z / d u_slave_z = eps_N A.
      call check_close(error, tangent(3, 3), eps_n*area, 1.0e-12_dp, message='K_zz slave')
   end subroutine test_normal_force

   subroutine test_stick_traction(error)
      type(error_t), allocatable, intent(out) :: error
      type(contact_point_result_t) :: result
      real(dp) :: fint(15), tangent(15, 15), anchor(3), expected(3)
      ! Anchor at xi = (-0.49, -0.52): x_A = (0.51, 0.24, 0); g_T = (-0.01, 0.01, 0).
      call node_face_contact(make_parameters(mu), [slave_xy(1), slave_xy(2), -depth], flat_face, area, &
                             [-0.49_dp, -0.52_dp], .true., .false., result, fint, tangent)
      call check(error, result%status == contact_stick, 'stick expected, got '//to_string(result%status))
      if (allocated(error)) return
      anchor = [0.51_dp, 0.24_dp, 0.0_dp]
      expected = -eps_t*([slave_xy(1), slave_xy(2), 0.0_dp] - anchor)
      call check(error, maxval(abs(result%traction - expected)) <= 1.0e-12_dp*norm2(expected), &
                 'stick traction -eps_T g_T')
      if (allocated(error)) return
      call check(error, maxval(abs(fint(1:2) + area*expected(1:2))) <= 1.0e-12_dp*norm2(area*expected), &
                 'slave tangential fint = -A t')
      if (allocated(error)) return
      call check_close(error, result%slip_increment, 0.0_dp, 0.0_dp, 0.0_dp, 'no slip in stick')
   end subroutine test_stick_traction

   subroutine test_slip_traction(error)
      type(error_t), allocatable, intent(out) :: error
      type(contact_point_result_t) :: result
      real(dp) :: fint(15), tangent(15, 15), slip(3)
      ! Anchor at xi = (-0.4, -0.5): x_A = (0.6, 0.25, 0); g_T = (-0.1, 0, 0): |t_trial| = 100 > 30.
      call node_face_contact(make_parameters(mu), [slave_xy(1), slave_xy(2), -depth], flat_face, area, &
                             [-0.4_dp, -0.5_dp], .true., .false., result, fint, tangent)
      call check(error, result%status == contact_slip, 'slip expected')
      if (allocated(error)) return
      call check_close(error, norm2(result%traction), mu*eps_n*depth, 1.0e-13_dp, message='|t| = mu p_N')
      if (allocated(error)) return
      slip = [-0.1_dp, 0.0_dp, 0.0_dp]
      call check(error, maxval(abs(result%traction/norm2(result%traction) + slip/norm2(slip))) <= 1.0e-13_dp, &
                 't opposite the elastic slip')
   end subroutine test_slip_traction

   !> After slip, evaluating again at the same configuration with the returned anchor gives the
   !> same traction (the anchor sits where -eps_T g_T = t). Slip increment by hand: the new
   !> anchor is x_s,foot + t/eps_T = (0.5 + 0.03, 0.25, 0) since t = (30, 0, 0), so the
   !> increment from x_A = (0.6, 0.25, 0) is 0.07.
   subroutine test_anchor_update(error)
      type(error_t), allocatable, intent(out) :: error
      type(contact_point_result_t) :: first, second
      real(dp) :: fint(15), tangent(15, 15)
      call node_face_contact(make_parameters(mu), [slave_xy(1), slave_xy(2), -depth], flat_face, area, &
                             [-0.4_dp, -0.5_dp], .true., .false., first, fint, tangent)
      call check_close(error, first%slip_increment, 0.07_dp, 1.0e-12_dp, message='slip increment')
      if (allocated(error)) return
      call check(error, maxval(abs(first%new_anchor - [0.53_dp, 0.25_dp, 0.0_dp])) <= 1.0e-13_dp, 'new anchor')
      if (allocated(error)) return
      call node_face_contact(make_parameters(mu), [slave_xy(1), slave_xy(2), -depth], flat_face, area, &
                             first%new_anchor_xi, .true., .false., second, fint, tangent)
      call check(error, maxval(abs(second%traction - first%traction)) <= 1.0e-12_dp*norm2(first%traction), &
                 'traction at the new anchor')
      if (allocated(error)) return
      call check(error, second%slip_increment <= 1.0e-12_dp, 'no further slip at the new anchor')
   end subroutine test_anchor_update

   !> On a warped face the new anchor is a projection onto the curved face, so the traction
   !> is reproduced up to the face's curvature over the elastic slip t/eps_T (here 0.03 on a
   !> face of size 2): checked to 1e-3 relative.
   subroutine test_anchor_update_warped(error)
      type(error_t), allocatable, intent(out) :: error
      type(contact_point_result_t) :: first, second
      real(dp) :: fint(15), tangent(15, 15), slave(3)
      slave = slave_below(warped_face, [0.2_dp, -0.3_dp], depth)
      call node_face_contact(make_parameters(mu), slave, warped_face, area, [0.3_dp, -0.25_dp], .true., .false., &
                             first, fint, tangent)
      call check(error, first%status == contact_slip, 'slip expected')
      if (allocated(error)) return
      call node_face_contact(make_parameters(mu), slave, warped_face, area, first%new_anchor_xi, .true., .false., &
                             second, fint, tangent)
      call check(error, maxval(abs(second%traction - first%traction)) <= 1.0e-3_dp*norm2(first%traction), &
                 'traction at the new anchor: '//to_string(maxval(abs(second%traction - first%traction))))
   end subroutine test_anchor_update_warped

   !> Rotate (about an oblique axis, 0.7 rad) and translate the slave and the master face
   !> together, with the same anchor face coordinates: the pressure is unchanged and the
   !> traction is rotated (objectivity of the anchor form).
   subroutine test_rigid_motion(error)
      type(error_t), allocatable, intent(out) :: error
      type(contact_point_result_t) :: before, after
      real(dp) :: fint(15), tangent(15, 15), rotation(3, 3), axis(3), shift(3), slave(3), moved_face(3, 4)
      real(dp) :: angle, cross_matrix(3, 3)
      integer, parameter :: expected_status(2) = [contact_slip, contact_stick]
      integer :: k, a
      axis = [1.0_dp, 2.0_dp, 2.0_dp]/3.0_dp
      angle = 0.7_dp
      shift = [3.0_dp, -1.0_dp, 0.5_dp]
      cross_matrix = reshape([0.0_dp, axis(3), -axis(2), -axis(3), 0.0_dp, axis(1), axis(2), -axis(1), 0.0_dp], [3, 3])
      rotation = matmul(cross_matrix, cross_matrix)*(1.0_dp - cos(angle)) + sin(angle)*cross_matrix
      do k = 1, 3
         rotation(k, k) = rotation(k, k) + 1.0_dp   ! Rodrigues: R = I + sin W + (1 - cos) W^2
      end do
      slave = slave_below(warped_face, [0.2_dp, -0.3_dp], depth)
      do a = 1, 4
         moved_face(:, a) = matmul(rotation, warped_face(:, a)) + shift
      end do
      do k = 1, 2   ! k = 1: slip case, k = 2: stick case
         if (k == 1) then
            call node_face_contact(make_parameters(mu), slave, warped_face, area, [0.3_dp, -0.25_dp], .true., &
                                   .false., before, fint, tangent)
            call node_face_contact(make_parameters(mu), matmul(rotation, slave) + shift, moved_face, area, &
                                   [0.3_dp, -0.25_dp], .true., .false., after, fint, tangent)
         else
            call node_face_contact(make_parameters(mu), slave, warped_face, area, [0.21_dp, -0.29_dp], .true., &
                                   .false., before, fint, tangent)
            call node_face_contact(make_parameters(mu), matmul(rotation, slave) + shift, moved_face, area, &
                                   [0.21_dp, -0.29_dp], .true., .false., after, fint, tangent)
         end if
         call check(error, before%status == after%status .and. before%status == expected_status(k), &
                    'status '//to_string(after%status))
         if (allocated(error)) return
         call check_close(error, after%pressure, before%pressure, 1.0e-12_dp, message='pressure')
         if (allocated(error)) return
         call check(error, maxval(abs(after%traction - matmul(rotation, before%traction))) <= &
                    1.0e-12_dp*norm2(before%traction), 'traction rotates with the master')
         if (allocated(error)) return
      end do
   end subroutine test_rigid_motion

   subroutine test_outside(error)
      type(error_t), allocatable, intent(out) :: error
      type(contact_point_result_t) :: result
      real(dp) :: fint(15), tangent(15, 15)
      ! (x, y) = (2.2, 0.5): xi1 = 1.2 beyond the edge x = 2.
      call node_face_contact(make_parameters(mu), [2.2_dp, 0.5_dp, -depth], flat_face, area, [0.0_dp, 0.0_dp], &
                             .false., .false., result, fint, tangent)
      call check(error, result%outside .and. result%status == contact_open, 'outside and open')
      if (allocated(error)) return
      call check(error, all(fint == 0.0_dp) .and. all(tangent == 0.0_dp), 'no force, no tangent')
      if (allocated(error)) return
      call check_close(error, result%xi(1), 1.2_dp, 1.0e-13_dp, message='extrapolated xi1')
      if (allocated(error)) return
      ! With clamp: contact at the edge point (2, 0.5, 0), g = -d (the normal is +z).
      call node_face_contact(make_parameters(mu), [2.2_dp, 0.5_dp, -depth], flat_face, area, [0.0_dp, 0.0_dp], &
                             .false., .true., result, fint, tangent)
      call check(error, result%outside .and. result%clamped .and. result%status == contact_stick, &
                 'clamped contact in stick')
      if (allocated(error)) return
      call check(error, abs(result%xi(1) - 1.0_dp) <= 1.0e-15_dp .and. abs(result%xi(2)) <= 1.0e-14_dp, &
                 'clamped point on the edge')
      if (allocated(error)) return
      call check_close(error, result%pressure, eps_n*depth, 1.0e-12_dp, message='clamped p_N')
   end subroutine test_outside

   !> Frictionless slaves at depth d beyond the free edge x = 2 of the flat face (edge 2,
   !> xi1 = +1): p_N = w eps_N d with w the fade at beyond / zone = 0.25, 0.75, 1.1 (zone 0.2).
   subroutine test_free_edge_fade(error)
      type(error_t), allocatable, intent(out) :: error
      type(contact_point_result_t) :: result
      real(dp) :: fint(15), tangent(15, 15)
      real(dp), parameter :: beyond(3) = [0.05_dp, 0.15_dp, 0.22_dp], fade(3) = [1.0_dp, 0.5_dp, 0.0_dp]
      logical, parameter :: free(4) = [.false., .true., .false., .false.]
      integer :: k
      do k = 1, 3
         call node_face_contact(make_parameters(0.0_dp), [2.0_dp + beyond(k), 0.5_dp, -depth], flat_face, area, &
                                [0.0_dp, 0.0_dp], .false., .true., result, fint, tangent, free_edges=free)
         call check(error, result%clamped, 'clamped onto the free edge')
         if (allocated(error)) return
         call check_close(error, result%pressure, fade(k)*eps_n*depth, 1.0e-12_dp, &
                          message='p_N at '//to_string(beyond(k))//' beyond the edge')
         if (allocated(error)) return
         call check(error, abs(sum(fint(3::3)) ) <= 1.0e-12_dp .and. &
                    abs(fint(3) + fade(k)*area*eps_n*depth) <= 1.0e-10_dp, 'slave force -w A p n, forces sum to zero')
         if (allocated(error)) return
      end do
   end subroutine test_free_edge_fade

   subroutine test_plane_physics(error)
      type(error_t), allocatable, intent(out) :: error
      type(contact_point_result_t) :: result
      real(dp) :: fint(3), tangent(3, 3), slave(3)
      real(dp), parameter :: point(3) = [0.0_dp, 0.0_dp, 1.0_dp], normal(3) = [0.0_dp, 0.0_dp, 2.0_dp]
      slave = [0.3_dp, 0.4_dp, 1.0_dp - depth]
      ! Stick: anchor (0.31, 0.39, 1): t = -eps_T (-0.01, 0.01, 0) = (10, -10, 0).
      call node_plane_contact(make_parameters(mu), slave, point, normal, area, [0.31_dp, 0.39_dp, 1.0_dp], .true., &
                              result, fint, tangent)
      call check(error, result%status == contact_stick, 'stick')
      if (allocated(error)) return
      call check(error, maxval(abs(fint - (-area)*[10.0_dp, -10.0_dp, eps_n*depth])) <= 1.0e-11_dp, &
                 'fint = -A (p_N n + t)')
      if (allocated(error)) return
      call check(error, maxval(abs(tangent - area*reshape([eps_t, 0.0_dp, 0.0_dp, 0.0_dp, eps_t, 0.0_dp, &
                                                            0.0_dp, 0.0_dp, eps_n], [3, 3]))) <= 1.0e-9_dp, &
                 'stick tangent A diag(eps_T, eps_T, eps_N)')
      if (allocated(error)) return
      ! Slip: anchor (0.5, 0.4, 1): t_trial = (200, 0, 0) > mu p_N = 30 -> t = (30, 0, 0);
      ! new anchor = foot + t/eps_T = (0.33, 0.4, 1), increment 0.17.
      call node_plane_contact(make_parameters(mu), slave, point, normal, area, [0.5_dp, 0.4_dp, 1.0_dp], .true., &
                              result, fint, tangent)
      call check(error, result%status == contact_slip, 'slip')
      if (allocated(error)) return
      call check(error, maxval(abs(result%traction - [30.0_dp, 0.0_dp, 0.0_dp])) <= 1.0e-11_dp, 'slip traction')
      if (allocated(error)) return
      call check(error, maxval(abs(result%new_anchor - [0.33_dp, 0.4_dp, 1.0_dp])) <= 1.0e-14_dp, 'new anchor')
      if (allocated(error)) return
      call check_close(error, result%slip_increment, 0.17_dp, 1.0e-12_dp, message='slip increment')
   end subroutine test_plane_physics

   subroutine test_open_anchor(error)
      type(error_t), allocatable, intent(out) :: error
      type(contact_point_result_t) :: result
      real(dp) :: fint(15), tangent(15, 15)
      call node_face_contact(make_parameters(mu), [1.5_dp, 0.75_dp, 0.2_dp], flat_face, area, [0.0_dp, 0.0_dp], &
                             .true., .false., result, fint, tangent)
      call check(error, result%status == contact_open .and. all(fint == 0.0_dp), 'open, no force')
      if (allocated(error)) return
      call check_close(error, result%gap, 0.2_dp, 1.0e-14_dp, message='gap')
      if (allocated(error)) return
      call check(error, maxval(abs(result%new_anchor_xi - [0.5_dp, 0.5_dp])) <= 1.0e-14_dp, &
                 'new anchor = closest point (0.5, 0.5)')
   end subroutine test_open_anchor

   !> A slave moved across the edge xi1 = +1 of the warped face, from inside (unconstrained
   !> closest point) to 4e-6 beyond (clamped, past the 1e-6 edge tolerance): fint must change
   !> no more than a Lipschitz bound 2 max|K| |dx| (continuity: no jump, no chattering).
   subroutine test_edge_continuity(error)
      type(error_t), allocatable, intent(out) :: error
      type(contact_point_result_t) :: inside, beyond
      real(dp) :: f_inside(15), f_beyond(15), k_inside(15, 15), k_beyond(15, 15), x_inside(3), x_beyond(3)
      integer :: k
      real(dp), parameter :: anchors(2, 2) = reshape([0.99_dp, 0.41_dp, 0.8_dp, 0.5_dp], [2, 2])
      do k = 1, 2   ! stick, then slip
         x_inside = slave_below(warped_face, [1.0_dp - 1.0e-6_dp, 0.4_dp], depth)
         x_beyond = slave_below(warped_face, [1.0_dp + 4.0e-6_dp, 0.4_dp], depth)
         call node_face_contact(make_parameters(mu), x_inside, warped_face, area, anchors(:, k), .true., .true., &
                                inside, f_inside, k_inside)
         call node_face_contact(make_parameters(mu), x_beyond, warped_face, area, anchors(:, k), .true., .true., &
                                beyond, f_beyond, k_beyond)
         call check(error, .not. inside%clamped .and. beyond%clamped .and. inside%status == beyond%status .and. &
                    inside%status == k, 'inside unclamped, beyond clamped, same status')
         if (allocated(error)) return
         call check(error, maxval(abs(f_beyond - f_inside)) <= 2.0_dp*maxval(abs(k_inside))*norm2(x_beyond - x_inside), &
                    'force jump '//to_string(maxval(abs(f_beyond - f_inside))))
         if (allocated(error)) return
      end do
   end subroutine test_edge_continuity
   !> The slip configuration of test_slip_traction (|t_trial| = 100 against mu p_N = 30): with
   !> the scale 2.5 it still slips (75), with 5 it sticks (150 > 100); each must equal the
   !> kernel's answer for the coefficient f mu without a scale, to round-off.
   subroutine test_friction_scale(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp), parameter :: scales(2) = [2.5_dp, 5.0_dp]
      integer, parameter :: expected_status(2) = [contact_slip, contact_stick]
      type(contact_point_result_t) :: scaled, reference
      real(dp) :: fint_scaled(15), fint_reference(15), tangent_scaled(15, 15), tangent_reference(15, 15)
      real(dp) :: x_slave(3)
      integer :: k
      x_slave = [slave_xy(1), slave_xy(2), -depth]
      do k = 1, size(scales)
         call node_face_contact(make_parameters(mu), x_slave, flat_face, area, [-0.4_dp, -0.5_dp], .true., &
                                .false., scaled, fint_scaled, tangent_scaled, friction_scale=scales(k))
         call node_face_contact(make_parameters(scales(k)*mu), x_slave, flat_face, area, [-0.4_dp, -0.5_dp], &
                                .true., .false., reference, fint_reference, tangent_reference)
         call check(error, scaled%status == expected_status(k) .and. reference%status == expected_status(k), &
                    'face, scale '//to_string(k)//': status '//to_string(scaled%status)//' and '// &
                    to_string(reference%status)//', expected '//to_string(expected_status(k)))
         if (allocated(error)) return
         call check(error, maxval(abs(fint_scaled - fint_reference)) <= 1.0e-13_dp*maxval(abs(fint_reference)) &
                    .and. maxval(abs(tangent_scaled - tangent_reference)) <= &
                    1.0e-13_dp*maxval(abs(tangent_reference)) .and. &
                    maxval(abs(scaled%traction - reference%traction)) <= 1.0e-13_dp*norm2(reference%traction), &
                    'face, scale '//to_string(k)//': force, tangent or traction differ from those of f mu')
         if (allocated(error)) return
         call node_plane_contact(make_parameters(mu), x_slave, [0.0_dp, 0.0_dp, 0.0_dp], [0.0_dp, 0.0_dp, 1.0_dp], &
                                 area, [0.6_dp, 0.25_dp, 0.0_dp], .true., scaled, fint_scaled(:3), &
                                 tangent_scaled(:3, :3), friction_scale=scales(k))
         call node_plane_contact(make_parameters(scales(k)*mu), x_slave, [0.0_dp, 0.0_dp, 0.0_dp], &
                                 [0.0_dp, 0.0_dp, 1.0_dp], area, [0.6_dp, 0.25_dp, 0.0_dp], .true., reference, &
                                 fint_reference(:3), tangent_reference(:3, :3))
         call check(error, scaled%status == expected_status(k) .and. reference%status == expected_status(k) .and. &
                    maxval(abs(fint_scaled(:3) - fint_reference(:3))) <= 1.0e-13_dp*maxval(abs(fint_reference(:3))) &
                    .and. maxval(abs(tangent_scaled(:3, :3) - tangent_reference(:3, :3))) <= &
                    1.0e-13_dp*maxval(abs(tangent_reference(:3, :3))), &
                    'plane, scale '//to_string(k)//': status, force or tangent differ from those of f mu')
         if (allocated(error)) return
      end do
   end subroutine test_friction_scale

   !> grid_patch flattened onto z = 0 (still irregular in the plane): every nodal normal is
   !> +z, so the smoothed kernel gives the facet kernel's status, gap, traction and force (the
   !> tangents differ: lifting a ring node tilts the nodal normals).
   subroutine test_smoothed_flat(error)
      type(error_t), allocatable, intent(out) :: error
      type(contact_point_result_t) :: facet, smoothed
      real(dp) :: x_face(3, 4), f_facet(15), k_facet(15, 15), x_slave(3)
      real(dp), allocatable :: x_ring(:, :), f_smoothed(:), k_smoothed(:, :)
      integer, allocatable :: patch_faces(:, :)
      integer :: k
      real(dp), parameter :: anchors(2, 2) = reshape([0.205_dp, -0.305_dp, 0.3_dp, -0.25_dp], [2, 2])
      call grid_patch(2, 2, x_face, x_ring, patch_faces)
      x_face(3, :) = 0.0_dp
      x_ring(3, :) = 0.0_dp
      allocate (f_smoothed(15 + size(x_ring)), k_smoothed(15 + size(x_ring), 15 + size(x_ring)))
      x_slave = slave_below(x_face, [0.2_dp, -0.3_dp], depth)
      do k = 1, 2   ! stick, then slip
         call node_face_contact(make_parameters(mu), x_slave, x_face, area, anchors(:, k), .true., .true., &
                                facet, f_facet, k_facet)
         call node_face_contact(make_parameters(mu), x_slave, x_face, area, anchors(:, k), .true., .true., &
                                smoothed, f_smoothed, k_smoothed, x_ring=x_ring, patch_faces=patch_faces)
         call check(error, facet%status == k .and. smoothed%status == k, 'status stick, then slip')
         if (allocated(error)) return
         call check(error, maxval(abs(f_smoothed(:15) - f_facet)) <= 1.0e-12_dp*maxval(abs(f_facet)) .and. &
                    all(f_smoothed(16:) == 0.0_dp) .and. abs(smoothed%gap - facet%gap) <= 1.0e-15_dp .and. &
                    maxval(abs(smoothed%traction - facet%traction)) <= 1.0e-12_dp*norm2(facet%traction), &
                    'smoothed = facet on a flat patch: force difference '// &
                    to_string(maxval(abs(f_smoothed(:15) - f_facet))))
         if (allocated(error)) return
      end do
   end subroutine test_smoothed_flat

   !> The edge xi1 = +1 of face (2, 2) is the edge xi1 = -1 of face (3, 2) (same nodes, same
   !> direction of xi2). At xi2 = 0.4 on it the facet normals of the two faces differ; the
   !> smoothed normals, and a slave's gap and pressure, do not (to round-off). The kernel finds
   !> the slave's projection point (the xi it was placed below).
   subroutine test_smoothed_continuity(error)
      type(error_t), allocatable, intent(out) :: error
      type(contact_point_result_t) :: left, right
      real(dp) :: x_left(3, 4), x_right(3, 4), x_slave(3), normal_left(3), normal_right(3)
      real(dp), allocatable :: ring_left(:, :), ring_right(:, :), f_left(:), k_left(:, :), f_right(:), k_right(:, :)
      integer, allocatable :: patch_left(:, :), patch_right(:, :)
      call grid_patch(2, 2, x_left, ring_left, patch_left)
      call grid_patch(3, 2, x_right, ring_right, patch_right)
      call check(error, norm2(face_normal(x_left, [1.0_dp, 0.4_dp]) - face_normal(x_right, [-1.0_dp, 0.4_dp])) > 1.0e-2_dp, &
                 'the facet normals should differ on the edge')
      if (allocated(error)) return
      normal_left = smooth_normal_at(patch_normals(x_left, ring_left, patch_left), [1.0_dp, 0.4_dp])
      normal_right = smooth_normal_at(patch_normals(x_right, ring_right, patch_right), [-1.0_dp, 0.4_dp])
      call check(error, norm2(normal_left - normal_right) <= 1.0e-14_dp, 'smoothed normals on the edge differ by '// &
                 to_string(norm2(normal_left - normal_right)))
      if (allocated(error)) return
      x_slave = slave_below_smoothed(x_left, ring_left, patch_left, [1.0_dp, 0.4_dp], depth)
      allocate (f_left(15 + size(ring_left)), k_left(15 + size(ring_left), 15 + size(ring_left)))
      allocate (f_right(15 + size(ring_right)), k_right(15 + size(ring_right), 15 + size(ring_right)))
      call node_face_contact(make_parameters(mu), x_slave, x_left, area, [0.99_dp, 0.41_dp], .true., .true., &
                             left, f_left, k_left, x_ring=ring_left, patch_faces=patch_left)
      call node_face_contact(make_parameters(mu), x_slave, x_right, area, [-1.01_dp, 0.41_dp], .true., .true., &
                             right, f_right, k_right, x_ring=ring_right, patch_faces=patch_right)
      call check(error, .not. left%clamped .and. .not. right%clamped .and. &
                 maxval(abs(left%xi - [1.0_dp, 0.4_dp])) <= 1.0e-10_dp .and. &
                 maxval(abs(right%xi - [-1.0_dp, 0.4_dp])) <= 1.0e-10_dp, 'projection onto the edge point from both faces')
      if (allocated(error)) return
      call check(error, abs(left%gap + depth) <= 1.0e-12_dp .and. abs(right%gap + depth) <= 1.0e-12_dp .and. &
                 norm2(left%normal - right%normal) <= 1.0e-12_dp .and. &
                 abs(left%pressure - right%pressure) <= 1.0e-8_dp*left%pressure, &
                 'gap, normal and pressure from the two faces: '//to_string(left%gap)//' '//to_string(right%gap))
   end subroutine test_smoothed_continuity
end module test_contact_physics
