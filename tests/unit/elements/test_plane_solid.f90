!> Unit tests of the plane strain and axisymmetric elements (frix_plane_solid on the QUAD4 and
!> TRI3 cells): the tangent against central differences of fint (linear and total Lagrangian
!> kinematics; Hooke, St. Venant-Kirchhoff, neo-Hookean, von Mises and Mohr-Coulomb plasticity),
!> zero z rows and columns, the constant strain states exact (a linear field in the plane, the
!> uniform radial expansion u_r = c R), self-equilibrium of fint, the volume weights (t A and
!> Pappus's 2 pi R_c A), the edge pressure (totals, closed contours, follower tangent), the 3D
!> default of face_pressure, the error of a point at R <= 0, and the registry options.
module test_plane_solid
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_strings, only: to_string
   use frix_testing, only: unittest_t, new_unittest, check
   use frix_material, only: material_t
   use frix_property_list, only: property_list_t
   use frix_element, only: element_t, kinematics_linear, kinematics_total_lagrangian
   use frix_element_registry, only: create_element
   use frix_plane_solid, only: plane_solid_t, new_plane_solid
   use frix_hex8, only: hex8_t, new_hex8
   use frix_surface_load, only: pressure_load
   use frix_reference_cell, only: reference_cell_t
   use frix_quad4_cell, only: new_quad4_cell
   use frix_tri3_cell, only: new_tri3_cell
   use frix_line2_cell, only: new_line2_cell
   use frix_linear_elastic, only: new_linear_elastic, hooke_tangent
   use frix_saint_venant_kirchhoff, only: new_saint_venant_kirchhoff
   use frix_neo_hookean, only: new_neo_hookean
   use frix_material_registry, only: create_material
   use test_tet4, only: check_tangent
   use test_element_fixtures, only: distorted_coords, sample_displacement
   implicit none
   private

   public :: collect_plane_solid

   real(dp), parameter :: young = 1000.0_dp, poisson = 0.3_dp, thickness = 0.7_dp
   real(dp), parameter :: pi = 4.0_dp*atan(1.0_dp)
   !> A distorted quadrilateral, counter-clockwise, x > 0 (edges about 1.2); z is not read.
   real(dp), parameter :: quad_coords(3, 4) = reshape([0.5_dp, 0.1_dp, 0.0_dp, 1.8_dp, 0.0_dp, 0.0_dp, &
                                                       1.6_dp, 1.2_dp, 0.0_dp, 0.4_dp, 0.9_dp, 0.0_dp], [3, 4])
   !> A general triangle, counter-clockwise, x > 0.
   real(dp), parameter :: tri_coords(3, 3) = reshape([0.6_dp, 0.2_dp, 0.0_dp, 1.7_dp, 0.4_dp, 0.0_dp, &
                                                      0.9_dp, 1.3_dp, 0.0_dp], [3, 3])
   !> An irregular displacement pattern (z entries are not read).
   real(dp), parameter :: pattern(3, 4) = reshape([0.3_dp, -0.2_dp, 0.5_dp, -0.4_dp, 0.5_dp, -0.3_dp, &
                                                   0.1_dp, 0.3_dp, 0.7_dp, 0.5_dp, -0.1_dp, -0.2_dp], [3, 4])
   !> Exact identities (patch, equilibrium, Pappus) hold to round-off: 1e-12 relative.
   real(dp), parameter :: tight = 1.0e-12_dp
   !> Central differences of the edge load (step 1e-6, size 1): as check_tangent's bound.
   real(dp), parameter :: fd_step = 1.0e-6_dp, fd_tolerance = 1.0e-8_dp

contains

   subroutine collect_plane_solid(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('tangent, elastic laws', test_tangent_elastic), &
               new_unittest('tangent, von Mises and Mohr-Coulomb plasticity', test_tangent_plastic), &
               new_unittest('z rows and columns zero, z not read', test_no_z), &
               new_unittest('plane strain patch: linear field exact', test_plane_patch), &
               new_unittest('axisymmetric patch: u_r = c R exact', test_axisymmetric_patch), &
               new_unittest('fint in equilibrium, rigid translation free', test_equilibrium), &
               new_unittest('volume weights t A and 2 pi R_c A', test_volume_weights), &
               new_unittest('edge pressure totals', test_edge_pressure_totals), &
               new_unittest('edge pressure follower tangent', test_edge_pressure_tangent), &
               new_unittest('3D face_pressure is pressure_load', test_face_pressure_3d), &
               new_unittest('axisymmetric point at R <= 0 is an error', test_radius_error), &
               new_unittest('registry shapes and options', test_registry), &
               new_unittest('EAS4 tangent, elastic and plastic, alpha re-solved', test_eas_tangent), &
               new_unittest('EAS4 patch: constant strain, alpha = 0, exact stress', test_eas_patch), &
               new_unittest('EAS4 pure bending of a rectangle exact', test_eas_bending), &
               new_unittest('EAS options of the registry', test_eas_registry), &
               new_unittest('EAS4 at rest under a geostatic initial stress: alpha = 0', test_eas_initial_stress)]
   end subroutine collect_plane_solid

   !> The element on QUAD4 (`quad`) or TRI3, axisymmetric or plane strain of thickness 0.7.
   function plane(quad, axisymmetric, kinematics) result(element)
      logical, intent(in) :: quad, axisymmetric
      integer, intent(in) :: kinematics
      type(plane_solid_t) :: element
      if (quad) then
         element = new_plane_solid(merge('AXISYM4', 'PLANE4 ', axisymmetric), new_quad4_cell(), kinematics, &
                                   axisymmetric, thickness)
      else
         element = new_plane_solid(merge('AXISYM3', 'PLANE3 ', axisymmetric), new_tri3_cell(), kinematics, &
                                   axisymmetric, thickness)
      end if
   end function plane

   !> The QUAD4 element with 4 enhanced strain parameters, axisymmetric or plane strain (t = 0.7).
   function enhanced(axisymmetric, kinematics) result(element)
      logical, intent(in) :: axisymmetric
      integer, intent(in) :: kinematics
      type(plane_solid_t) :: element
      element = new_plane_solid(merge('AXISYM4', 'PLANE4 ', axisymmetric), new_quad4_cell(), kinematics, &
                                axisymmetric, thickness, n_eas=4)
   end function enhanced

   pure function coords_of(quad) result(coords)
      logical, intent(in) :: quad
      real(dp), allocatable :: coords(:, :)
      if (quad) then
         coords = quad_coords
      else
         coords = tri_coords
      end if
   end function coords_of

   pure function pattern_of(quad, amplitude) result(u)
      logical, intent(in) :: quad
      real(dp), intent(in) :: amplitude
      real(dp), allocatable :: u(:, :)
      u = amplitude*pattern(:, 1:merge(4, 3, quad))
   end function pattern_of

   !> Hooke at 1 % strain (linear), St. Venant-Kirchhoff and neo-Hookean at displacements of
   !> 15 % of the size (total Lagrangian), on the four elements.
   subroutine test_tangent_elastic(error)
      type(error_t), allocatable, intent(out) :: error
      integer :: k
      logical :: quad, axisymmetric
      do k = 0, 3
         quad = k < 2
         axisymmetric = mod(k, 2) == 1
         call check_tangent(plane(quad, axisymmetric, kinematics_linear), new_linear_elastic(young, poisson, 0.0_dp), &
                            coords_of(quad), pattern_of(quad, 0.01_dp), error)
         if (allocated(error)) return
         call check_tangent(plane(quad, axisymmetric, kinematics_total_lagrangian), &
                            new_saint_venant_kirchhoff(young, poisson, 0.0_dp), coords_of(quad), &
                            pattern_of(quad, 0.15_dp), error)
         if (allocated(error)) return
         call check_tangent(plane(quad, axisymmetric, kinematics_total_lagrangian), &
                            new_neo_hookean(young, poisson, 0.0_dp), coords_of(quad), pattern_of(quad, 0.15_dp), error)
         if (allocated(error)) return
      end do
   end subroutine test_tangent_elastic

   !> Von Mises with saturation and kinematic hardening (sigma_y = 2) and associated
   !> Mohr-Coulomb (c = 2, phi = psi = 30 degrees): some point yields (checked by
   !> check_tangent), and K is still d fint / du, on the four elements, both kinematics.
   subroutine test_tangent_plastic(error)
      type(error_t), allocatable, intent(out) :: error
      class(material_t), allocatable :: mises, coulomb
      type(error_t), allocatable :: law_error
      integer :: k
      logical :: quad, axisymmetric
      call create_material('MAT_3DMisesPlastic', [character(len=6) :: 'YOUNG', 'NUE', 'SIGY', 'SIGINF', 'DELTA', &
                           'KINH'], [young, poisson, 2.0_dp, 3.0_dp, 50.0_dp, 20.0_dp], mises, law_error)
      call check(error, .not. allocated(law_error), 'von Mises law')
      if (allocated(error)) return
      call create_material('MAT_3DMohrCoulomb', [character(len=8) :: 'YOUNG', 'NUE', 'COHESION', 'PHI', 'PSI'], &
                           [young, poisson, 2.0_dp, 30.0_dp, 30.0_dp], coulomb, law_error)
      call check(error, .not. allocated(law_error), 'Mohr-Coulomb law')
      if (allocated(error)) return
      do k = 0, 3
         quad = k < 2
         axisymmetric = mod(k, 2) == 1
         call check_tangent(plane(quad, axisymmetric, kinematics_linear), mises, coords_of(quad), &
                            pattern_of(quad, 0.01_dp), error, plastic=.true.)
         if (allocated(error)) return
         call check_tangent(plane(quad, axisymmetric, kinematics_total_lagrangian), mises, coords_of(quad), &
                            pattern_of(quad, 0.15_dp), error, plastic=.true.)
         if (allocated(error)) return
         call check_tangent(plane(quad, axisymmetric, kinematics_linear), coulomb, coords_of(quad), &
                            pattern_of(quad, 0.01_dp), error, plastic=.true.)
         if (allocated(error)) return
         call check_tangent(plane(quad, axisymmetric, kinematics_total_lagrangian), coulomb, coords_of(quad), &
                            pattern_of(quad, 0.05_dp), error, plastic=.true.)
         if (allocated(error)) return
      end do
   end subroutine test_tangent_plastic

   !> The z entries of fint and every z row and column of K are exactly 0, and z of the
   !> coordinates and of the displacements changes nothing (bit for bit).
   subroutine test_no_z(error)
      type(error_t), allocatable, intent(out) :: error
      type(plane_solid_t) :: element
      real(dp) :: fint(12), tangent(12, 12), lifted_fint(12), lifted_tangent(12, 12), coords(3, 4), u(3, 4)
      real(dp) :: alpha(0), state_old(0, 4), state_new(0, 4)
      integer :: kinematics, k
      do kinematics = kinematics_linear, kinematics_total_lagrangian
         do k = 0, 1
            element = plane(.true., k == 1, kinematics)
            u = 0.1_dp*pattern
            u(3, :) = 0.0_dp
            call element%evaluate(new_linear_elastic(young, poisson, 0.0_dp), quad_coords, u, alpha, state_old, &
                                  state_new, fint, tangent, error=error)
            if (allocated(error)) return
            coords = quad_coords
            coords(3, :) = [0.3_dp, -0.2_dp, 0.7_dp, 0.1_dp]
            u(3, :) = 0.1_dp*pattern(3, :)
            call element%evaluate(new_linear_elastic(young, poisson, 0.0_dp), coords, u, alpha, state_old, &
                                  state_new, lifted_fint, lifted_tangent, error=error)
            if (allocated(error)) return
            call check(error, all(fint(3:12:3) == 0.0_dp) .and. all(tangent(3:12:3, :) == 0.0_dp) .and. &
                       all(tangent(:, 3:12:3) == 0.0_dp), element%name//': nonzero z entries')
            if (allocated(error)) return
            call check(error, all(fint == lifted_fint) .and. all(tangent == lifted_tangent), &
                       element%name//': z of the coordinates or displacements is read')
            if (allocated(error)) return
         end do
      end do
   end subroutine test_no_z

   !> u = A X + c (linear kinematics, Hooke): eps = (A11, A22, 0, A12 + A21, 0, 0) and
   !> sigma = D eps at every point (so sigma_33 = nu (sigma_11 + sigma_22)) on the distorted quad
   !> and the triangle; total Lagrangian: E = (F^T F - I)/2 of the constant F = I + A.
   subroutine test_plane_patch(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp), parameter :: gradient(2, 2) = reshape([0.01_dp, -0.003_dp, 0.004_dp, 0.02_dp], [2, 2])
      type(plane_solid_t) :: element
      real(dp), allocatable :: coords(:, :), u(:, :), fint(:), stress(:, :), strain(:, :)
      real(dp) :: expected(6), deformation(2, 2), right_cauchy(2, 2), alpha(0), state_old(0, 4), state_new(0, 4)
      integer :: g, k, kinematics
      do k = 0, 1
         do kinematics = kinematics_linear, kinematics_total_lagrangian
            element = plane(k == 0, .false., kinematics)
            coords = coords_of(k == 0)
            allocate (u(3, size(coords, 2)), source=0.0_dp)
            u(1:2, :) = matmul(gradient, coords(1:2, :)) + spread([0.05_dp, -0.02_dp], 2, size(coords, 2))
            allocate (fint(3*size(coords, 2)), stress(6, element%n_points()), strain(6, element%n_points()))
            call element%evaluate(new_linear_elastic(young, poisson, 0.0_dp), coords, u, alpha, state_old, state_new, fint, &
                                  stress=stress, strain=strain, error=error)
            if (allocated(error)) return
            if (kinematics == kinematics_linear) then
               expected = [gradient(1, 1), gradient(2, 2), 0.0_dp, gradient(1, 2) + gradient(2, 1), 0.0_dp, 0.0_dp]
            else
               deformation = gradient + reshape([1.0_dp, 0.0_dp, 0.0_dp, 1.0_dp], [2, 2])
               right_cauchy = matmul(transpose(deformation), deformation)
               expected = [(right_cauchy(1, 1) - 1)/2, (right_cauchy(2, 2) - 1)/2, 0.0_dp, right_cauchy(1, 2), &
                           0.0_dp, 0.0_dp]
            end if
            do g = 1, element%n_points()
               call check(error, maxval(abs(strain(:, g) - expected)) <= tight*maxval(abs(expected)), &
                          element%name//': strain at point '//to_string(g))
               if (allocated(error)) return
               if (kinematics == kinematics_linear) then
                  call check(error, maxval(abs(stress(:, g) - matmul(hooke_tangent(young, poisson), expected))) <= &
                             tight*young*maxval(abs(expected)) .and. abs(stress(3, g) - poisson*(stress(1, g) + &
                             stress(2, g))) <= tight*young*maxval(abs(expected)), element%name//': stress at point '// &
                             to_string(g))
                  if (allocated(error)) return
               end if
            end do
            deallocate (u, fint, stress, strain)
         end do
      end do
   end subroutine test_plane_patch

   !> u_r = c R, u_z = 0: eps_rr = eps_tt = c, the rest 0 (linear); E_rr = E_tt = c + c^2/2
   !> (total Lagrangian), at every point of the quad and the triangle.
   subroutine test_axisymmetric_patch(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp), parameter :: c = 0.01_dp
      type(plane_solid_t) :: element
      real(dp), allocatable :: coords(:, :), u(:, :), fint(:), strain(:, :)
      real(dp) :: expected(6), alpha(0), state_old(0, 4), state_new(0, 4)
      integer :: g, k, kinematics
      do k = 0, 1
         do kinematics = kinematics_linear, kinematics_total_lagrangian
            element = plane(k == 0, .true., kinematics)
            coords = coords_of(k == 0)
            allocate (u(3, size(coords, 2)), source=0.0_dp)
            u(1, :) = c*coords(1, :)
            allocate (fint(3*size(coords, 2)), strain(6, element%n_points()))
            call element%evaluate(new_linear_elastic(young, poisson, 0.0_dp), coords, u, alpha, state_old, state_new, fint, &
                                  strain=strain, error=error)
            if (allocated(error)) return
            expected = [c, 0.0_dp, c, 0.0_dp, 0.0_dp, 0.0_dp]
            if (kinematics == kinematics_total_lagrangian) expected([1, 3]) = c + c**2/2
            do g = 1, element%n_points()
               call check(error, maxval(abs(strain(:, g) - expected)) <= tight*c, element%name//': strain '// &
                          to_string(strain(1, g))//' '//to_string(strain(3, g))//' at point '//to_string(g))
               if (allocated(error)) return
            end do
            deallocate (u, fint, strain)
         end do
      end do
   end subroutine test_axisymmetric_patch

   !> Plane strain: sum_a fint_a = 0 for any u (the element is in equilibrium); a rigid
   !> translation gives fint = 0. Axisymmetric: the axial components sum to 0 (the radial ones
   !> balance the hoop stress), and an axial translation gives fint = 0.
   subroutine test_equilibrium(error)
      type(error_t), allocatable, intent(out) :: error
      type(plane_solid_t) :: element
      real(dp), allocatable :: coords(:, :), u(:, :), fint(:)
      real(dp) :: alpha(0), state_old(0, 4), state_new(0, 4), scale
      integer :: k, kinematics, n
      logical :: axisymmetric
      do k = 0, 3
         axisymmetric = mod(k, 2) == 1
         do kinematics = kinematics_linear, kinematics_total_lagrangian
            element = plane(k < 2, axisymmetric, kinematics)
            coords = coords_of(k < 2)
            n = size(coords, 2)
            u = pattern_of(k < 2, 0.05_dp)
            allocate (fint(3*n))
            call element%evaluate(new_linear_elastic(young, poisson, 0.0_dp), coords, u, alpha, state_old, state_new, fint, &
                                  error=error)
            if (allocated(error)) return
            scale = maxval(abs(fint))
            call check(error, abs(sum(fint(2:3*n:3))) <= tight*scale .and. (axisymmetric .or. &
                       abs(sum(fint(1:3*n:3))) <= tight*scale), element%name//': sum of fint '// &
                       to_string(sum(fint(1:3*n:3)))//' '//to_string(sum(fint(2:3*n:3))))
            if (allocated(error)) return
            u = 0.0_dp
            u(2, :) = 0.3_dp
            if (.not. axisymmetric) u(1, :) = -0.2_dp
            call element%evaluate(new_linear_elastic(young, poisson, 0.0_dp), coords, u, alpha, state_old, state_new, fint, &
                                  error=error)
            if (allocated(error)) return
            call check(error, maxval(abs(fint)) <= tight*scale, element%name//': force of a translation '// &
                       to_string(maxval(abs(fint))))
            if (allocated(error)) return
            deallocate (fint)
         end do
      end do
   end subroutine test_equilibrium

   !> Sum of the weights: t A (plane strain) and 2 pi R_c A (axisymmetric, Pappus's theorem)
   !> with the polygon's area A and centroid radius R_c (shoelace formulas).
   subroutine test_volume_weights(error)
      type(error_t), allocatable, intent(out) :: error
      type(plane_solid_t) :: element
      real(dp), allocatable :: coords(:, :), weights(:), positions(:, :)
      real(dp) :: area, moment, cross_term, expected
      integer :: k, a, b, n
      do k = 0, 3
         element = plane(k < 2, mod(k, 2) == 1, kinematics_linear)
         coords = coords_of(k < 2)
         n = size(coords, 2)
         area = 0.0_dp
         moment = 0.0_dp
         do a = 1, n
            b = mod(a, n) + 1
            cross_term = coords(1, a)*coords(2, b) - coords(1, b)*coords(2, a)
            area = area + cross_term/2
            moment = moment + (coords(1, a) + coords(1, b))*cross_term/6
         end do
         expected = thickness*area
         if (mod(k, 2) == 1) expected = 2*pi*moment   ! 2 pi R_c A, R_c A = moment
         allocate (weights(n), positions(3, element%n_points()))
         call element%volume_weights(coords, weights)
         call check(error, abs(sum(weights) - expected) <= tight*expected, element%name//': volume '// &
                    to_string(sum(weights))//', expected '//to_string(expected))
         if (allocated(error)) return
         call element%point_positions(coords, positions)
         call check(error, all(positions(3, :) == 0.0_dp) .and. abs(sum(positions(1, :))/element%n_points() - &
                    sum(coords(1, :))/n) <= tight, element%name//': point positions')
         if (allocated(error)) return
         deallocate (weights, positions)
      end do
   end subroutine test_volume_weights

   !> Plane strain: the total force of p on edge 2-3 is -p L t n. Axisymmetric: on an axial
   !> edge at radius R it is -p L 2 pi R along the outward normal (+x). Around the closed
   !> boundary of the element the forces sum to 0 (plane strain) and the axial ones to 0
   !> (axisymmetric: int r n_y ds = int dr/dy dA = 0).
   subroutine test_edge_pressure_totals(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp), parameter :: p = 3.0_dp
      !> A quadrilateral with the axial edge 2-3 at R = 1.7.
      real(dp), parameter :: ring(3, 4) = reshape([0.5_dp, 0.0_dp, 0.0_dp, 1.7_dp, 0.1_dp, 0.0_dp, &
                                                   1.7_dp, 1.0_dp, 0.0_dp, 0.4_dp, 1.1_dp, 0.0_dp], [3, 4])
      type(plane_solid_t) :: element
      real(dp) :: force(6), total(2), closed(2), edge(2), normal(2), u(3, 2)
      integer :: f, k
      integer, parameter :: edges(2, 4) = reshape([1, 2, 2, 3, 3, 4, 4, 1], [2, 4])
      u = 0.0_dp
      do k = 0, 1
         element = plane(.true., k == 1, kinematics_linear)
         closed = 0.0_dp
         do f = 1, 4
            call element%face_pressure(new_line2_cell(), ring(:, edges(:, f)), u, p, .false., force)
            closed = closed + force(1:2) + force(4:5)
            if (f /= 2) cycle
            total = force(1:2) + force(4:5)
            edge = ring(1:2, 3) - ring(1:2, 2)
            normal = [edge(2), -edge(1)]/norm2(edge)
            if (k == 0) then
               call check(error, maxval(abs(total + p*norm2(edge)*thickness*normal)) <= tight*p, &
                          'PLANE4 edge total '//to_string(total(1))//' '//to_string(total(2)))
            else
               call check(error, maxval(abs(total + p*norm2(edge)*2*pi*1.7_dp*[1.0_dp, 0.0_dp])) <= tight*p, &
                          'AXISYM4 edge total '//to_string(total(1))//' '//to_string(total(2)))
            end if
            if (allocated(error)) return
            call check(error, all(force(3:6:3) == 0.0_dp), 'z forces of an edge')
            if (allocated(error)) return
         end do
         call check(error, abs(closed(2)) <= tight*p .and. (k == 1 .or. abs(closed(1)) <= tight*p), &
                    element%name//': closed boundary total '//to_string(closed(1))//' '//to_string(closed(2)))
         if (allocated(error)) return
      end do
   end subroutine test_edge_pressure_totals

   !> Follower pressure on a slanted, displaced edge: the tangent against central differences
   !> of the force; a dead load does not depend on u and has a zero tangent.
   subroutine test_edge_pressure_tangent(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp), parameter :: p = 3.0_dp
      type(plane_solid_t) :: element
      real(dp) :: coords(3, 2), u(3, 2), perturbed(3, 2), force(6), plus(6), minus(6), tangent(6, 6), &
                  difference(6, 6), dead(6)
      integer :: a, i, k
      coords = quad_coords(:, 2:3)
      u = 0.1_dp*pattern(:, 1:2)
      do k = 0, 1
         element = plane(.true., k == 1, kinematics_total_lagrangian)
         call element%face_pressure(new_line2_cell(), coords, u, p, .true., force, tangent)
         do a = 1, 2
            do i = 1, 3
               perturbed = u
               perturbed(i, a) = u(i, a) + fd_step
               call element%face_pressure(new_line2_cell(), coords, perturbed, p, .true., plus)
               perturbed(i, a) = u(i, a) - fd_step
               call element%face_pressure(new_line2_cell(), coords, perturbed, p, .true., minus)
               difference(:, 3*(a - 1) + i) = tangent(:, 3*(a - 1) + i) - (plus - minus)/(2*fd_step)
            end do
         end do
         call check(error, maxval(abs(difference)) <= fd_tolerance*maxval(abs(tangent)), element%name// &
                    ': edge load tangent off by '//to_string(maxval(abs(difference)))//', max '// &
                    to_string(maxval(abs(tangent))))
         if (allocated(error)) return
         call element%face_pressure(new_line2_cell(), coords, u, p, .false., dead, tangent)
         call element%face_pressure(new_line2_cell(), coords, 0.0_dp*u, p, .false., force)
         call check(error, all(dead == force) .and. all(tangent == 0.0_dp), element%name//': dead edge load')
         if (allocated(error)) return
      end do
   end subroutine test_edge_pressure_tangent

   !> A HEX8's face_pressure (element_t's default) gives pressure_load's numbers bit for bit.
   subroutine test_face_pressure_3d(error)
      type(error_t), allocatable, intent(out) :: error
      type(hex8_t) :: element
      real(dp) :: coords(3, 8), u(3, 8), force(12), tangent(12, 12), reference(12), reference_tangent(12, 12)
      integer, parameter :: face(4) = [5, 6, 7, 8]
      element = new_hex8(0, kinematics_total_lagrangian)
      coords = distorted_coords()
      u = sample_displacement(0.1_dp)
      call element%face_pressure(new_quad4_cell(), coords(:, face), u(:, face), 2.5_dp, .true., force, tangent)
      call pressure_load(new_quad4_cell(), coords(:, face), u(:, face), 2.5_dp, .true., reference, reference_tangent)
      call check(error, all(force == reference) .and. all(tangent == reference_tangent), 'follower: not identical')
      if (allocated(error)) return
      call element%face_pressure(new_quad4_cell(), coords(:, face), u(:, face), 2.5_dp, .false., force)
      call pressure_load(new_quad4_cell(), coords(:, face), u(:, face), 2.5_dp, .false., reference)
      call check(error, all(force == reference), 'dead: not identical')
   end subroutine test_face_pressure_3d

   !> Axisymmetric: a node at x < 0 putting a point at R <= 0 is an error naming the point; an
   !> element with an edge on the axis (R = 0 at nodes, > 0 at the points) is fine.
   subroutine test_radius_error(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: element_error
      type(plane_solid_t) :: element
      real(dp) :: coords(3, 4), fint(12), alpha(0), state_old(0, 4), state_new(0, 4)
      element = plane(.true., .true., kinematics_linear)
      coords = reshape([0.0_dp, 0.0_dp, 0.0_dp, 1.0_dp, 0.0_dp, 0.0_dp, 1.0_dp, 1.0_dp, 0.0_dp, &
                        0.0_dp, 1.0_dp, 0.0_dp], [3, 4])
      call element%evaluate(new_linear_elastic(young, poisson, 0.0_dp), coords, 0.0_dp*coords, alpha, state_old, &
                            state_new, fint, error=element_error)
      call check(error, .not. allocated(element_error), 'an element on the axis fails')
      if (allocated(error)) return
      coords(1, [1, 4]) = -1.0_dp
      call element%evaluate(new_linear_elastic(young, poisson, 0.0_dp), coords, 0.0_dp*coords, alpha, state_old, &
                            state_new, fint, error=element_error)
      call check(error, allocated(element_error), 'no error for a point at R <= 0')
      if (allocated(error)) return
      call check(error, index(element_error%message, 'AXISYM4: non-positive radius (x)') > 0 .and. &
                 index(element_error%message, 'at integration point 1') > 0, 'message: '//element_error%message)
   end subroutine test_radius_error

   !> PLANE4 THICKNESS 2.5 is plane strain of that thickness; PLANE3 defaults to 1; THICKNESS 0
   !> and an option of AXISYM3 are errors.
   subroutine test_registry(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: create_error
      class(element_t), allocatable :: element
      type(property_list_t) :: options
      allocate (options%names(0), options%values(0))
      call options%add('THICKNESS', 2.5_dp)
      call create_element('plane4', options, kinematics_linear, element, create_error)
      call check(error, .not. allocated(create_error), 'PLANE4 THICKNESS 2.5')
      if (allocated(error)) return
      select type (element)
      type is (plane_solid_t)
         call check(error, element%name == 'PLANE4' .and. element%thickness == 2.5_dp .and. .not. &
                    element%axisymmetric .and. element%n_nodes() == 4 .and. element%n_points() == 4, 'PLANE4')
      class default
         call check(error, .false., 'PLANE4 is no plane_solid_t')
      end select
      if (allocated(error)) return
      deallocate (options%names, options%values)
      allocate (options%names(0), options%values(0))
      call create_element('PLANE3', options, kinematics_total_lagrangian, element, create_error)
      select type (element)
      type is (plane_solid_t)
         call check(error, element%name == 'PLANE3' .and. element%thickness == 1.0_dp .and. element%n_points() == 3, &
                    'PLANE3')
      class default
         call check(error, .false., 'PLANE3 is no plane_solid_t')
      end select
      if (allocated(error)) return
      call options%add('THICKNESS', 0.0_dp)
      call create_element('PLANE4', options, kinematics_linear, element, create_error)
      call check(error, allocated(create_error), 'THICKNESS 0 accepted')
      if (allocated(error)) return
      call create_element('AXISYM3', options, kinematics_linear, element, create_error)
      call check(error, allocated(create_error), 'AXISYM3 accepts THICKNESS')
   end subroutine test_registry

   !> The condensed tangent of PLANE4/AXISYM4 EAS 4 against central differences of fint with
   !> alpha re-solved (check_tangent): Hooke (linear), St. Venant-Kirchhoff and neo-Hookean
   !> (total Lagrangian), von Mises plasticity with hardening (both kinematics; points yield).
   subroutine test_eas_tangent(error)
      type(error_t), allocatable, intent(out) :: error
      class(material_t), allocatable :: mises
      type(error_t), allocatable :: law_error
      integer :: k
      logical :: axisymmetric
      call create_material('MAT_3DMisesPlastic', [character(len=6) :: 'YOUNG', 'NUE', 'SIGY', 'SIGINF', 'DELTA', &
                           'KINH'], [young, poisson, 2.0_dp, 3.0_dp, 50.0_dp, 20.0_dp], mises, law_error)
      call check(error, .not. allocated(law_error), 'von Mises law')
      if (allocated(error)) return
      do k = 0, 1
         axisymmetric = k == 1
         call check_tangent(enhanced(axisymmetric, kinematics_linear), new_linear_elastic(young, poisson, 0.0_dp), &
                            quad_coords, 0.01_dp*pattern, error)
         if (allocated(error)) return
         call check_tangent(enhanced(axisymmetric, kinematics_total_lagrangian), &
                            new_saint_venant_kirchhoff(young, poisson, 0.0_dp), quad_coords, 0.15_dp*pattern, error)
         if (allocated(error)) return
         call check_tangent(enhanced(axisymmetric, kinematics_total_lagrangian), new_neo_hookean(young, poisson, 0.0_dp), &
                            quad_coords, 0.15_dp*pattern, error)
         if (allocated(error)) return
         call check_tangent(enhanced(axisymmetric, kinematics_linear), mises, quad_coords, 0.01_dp*pattern, error, &
                            plastic=.true.)
         if (allocated(error)) return
         call check_tangent(enhanced(axisymmetric, kinematics_total_lagrangian), mises, quad_coords, 0.15_dp*pattern, &
                            error, plastic=.true.)
         if (allocated(error)) return
      end do
   end subroutine test_eas_tangent

   !> A constant strain state on the distorted quad: u = A X + c in plane strain (both
   !> kinematics) and u_r = c R in axisymmetry. int G dV = 0 makes h = 0 at alpha = 0: the
   !> local solve from alpha = 1e-3 returns alpha = 0 (to round-off) and fint and the strains
   !> equal those of the plain element.
   subroutine test_eas_patch(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp), parameter :: gradient(2, 2) = reshape([0.01_dp, -0.003_dp, 0.004_dp, 0.02_dp], [2, 2])
      type(plane_solid_t) :: plain, element
      real(dp) :: u(3, 4), fint(12), plain_fint(12), strain(6, 4), plain_strain(6, 4), alpha(4), none(0)
      real(dp) :: state_old(0, 4), state_new(0, 4)
      integer :: k, kinematics
      do k = 0, 1
         do kinematics = kinematics_linear, kinematics_total_lagrangian
            u = 0.0_dp
            if (k == 0) then
               u(1:2, :) = matmul(gradient, quad_coords(1:2, :)) + spread([0.05_dp, -0.02_dp], 2, 4)
            else
               u(1, :) = 0.01_dp*quad_coords(1, :)
            end if
            element = enhanced(k == 1, kinematics)
            plain = plane(.true., k == 1, kinematics)
            alpha = 1.0e-3_dp
            call element%evaluate(new_linear_elastic(young, poisson, 0.0_dp), quad_coords, u, alpha, state_old, &
                                  state_new, fint, strain=strain, error=error)
            if (allocated(error)) return
            call plain%evaluate(new_linear_elastic(young, poisson, 0.0_dp), quad_coords, u, none, state_old, &
                                state_new, plain_fint, strain=plain_strain, error=error)
            if (allocated(error)) return
            call check(error, maxval(abs(alpha)) <= tight*maxval(abs(u)), element%name//': alpha '// &
                       to_string(maxval(abs(alpha))))
            if (allocated(error)) return
            call check(error, maxval(abs(strain - plain_strain)) <= tight*maxval(abs(plain_strain)) .and. &
                       maxval(abs(fint - plain_fint)) <= tight*maxval(abs(plain_fint)), &
                       element%name//': strain or fint differ from the constant state')
            if (allocated(error)) return
         end do
      end do
   end subroutine test_eas_patch

   !> Pure bending of the rectangle [-1, 1] x [-1/4, 1/4] in plane strain, Hooke: the exact
   !> field sigma_xx = k y (all other stresses 0) is u = a x y, v = -(a x^2 + b y^2)/2 with
   !> a = (1 - nu^2) k / E, b = nu (1 + nu) k / E. Given its nodal values, EAS4 recovers the
   !> exact stress at every point (the modes E12 ~ xi and E22 ~ eta carry the parasitic shear and
   !> the Poisson strain the bilinear field lacks, as the incompatible modes x^2, y^2 of Wilson's
   !> element would), which the plain element does not (shear a x).
   subroutine test_eas_bending(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp), parameter :: k = 1.0_dp
      real(dp), parameter :: a = (1.0_dp - poisson**2)*k/young, b = poisson*(1.0_dp + poisson)*k/young
      real(dp), parameter :: rectangle(3, 4) = reshape([-1.0_dp, -0.25_dp, 0.0_dp, 1.0_dp, -0.25_dp, 0.0_dp, &
                                                        1.0_dp, 0.25_dp, 0.0_dp, -1.0_dp, 0.25_dp, 0.0_dp], [3, 4])
      type(plane_solid_t) :: element
      real(dp) :: u(3, 4), fint(12), stress(6, 4), positions(3, 4), expected(6), alpha(4), none(0)
      real(dp) :: state_old(0, 4), state_new(0, 4)
      integer :: g
      u(1, :) = a*rectangle(1, :)*rectangle(2, :)
      u(2, :) = -0.5_dp*(a*rectangle(1, :)**2 + b*rectangle(2, :)**2)
      u(3, :) = 0.0_dp
      element = new_plane_solid('PLANE4', new_quad4_cell(), kinematics_linear, .false., thickness, n_eas=4)
      alpha = 0.0_dp
      call element%evaluate(new_linear_elastic(young, poisson, 0.0_dp), rectangle, u, alpha, state_old, state_new, &
                            fint, stress=stress, error=error)
      if (allocated(error)) return
      call element%point_positions(rectangle, positions)
      do g = 1, 4
         expected = 0.0_dp
         expected(1) = k*positions(2, g)
         expected(3) = poisson*expected(1)
         call check(error, maxval(abs(stress(:, g) - expected)) <= tight*k, 'EAS4: stress at point '//to_string(g)// &
                    ' off by '//to_string(maxval(abs(stress(:, g) - expected))))
         if (allocated(error)) return
      end do
      element = plane(.true., .false., kinematics_linear)
      call element%evaluate(new_linear_elastic(young, poisson, 0.0_dp), rectangle, u, none, state_old, state_new, &
                            fint, stress=stress, error=error)
      if (allocated(error)) return
      call check(error, maxval(abs(stress(4, :))) > 0.1_dp*k, 'plain PLANE4 bends without shear')
   end subroutine test_eas_bending

   !> PLANE4 EAS 4 and AXISYM4 EAS 4 have 4 enhanced parameters; PLANE4 EAS 3 is an error
   !> listing the valid counts; PLANE3 and AXISYM3 take EAS 0 only.
   subroutine test_eas_registry(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: create_error
      class(element_t), allocatable :: element
      type(property_list_t) :: options
      character(len=7), parameter :: quads(2) = ['PLANE4 ', 'AXISYM4'], triangles(2) = ['PLANE3 ', 'AXISYM3']
      integer :: i
      allocate (options%names(0), options%values(0))
      call options%add('EAS', 4.0_dp)
      do i = 1, 2
         call create_element(trim(quads(i)), options, kinematics_linear, element, create_error)
         call check(error, .not. allocated(create_error), trim(quads(i))//' EAS 4 rejected')
         if (allocated(error)) return
         call check(error, element%n_enhanced() == 4 .and. element%name == trim(quads(i))//'-EAS4', &
                    trim(quads(i))//' EAS 4: '//element%name)
         if (allocated(error)) return
         call create_element(trim(triangles(i)), options, kinematics_linear, element, create_error)
         call check(error, allocated(create_error), trim(triangles(i))//' accepts EAS 4')
         if (allocated(error)) return
         call check(error, index(create_error%message, 'valid: 0)') > 0, 'message: '//create_error%message)
         if (allocated(error)) return
      end do
      call options%set('EAS', 3.0_dp)
      call create_element('PLANE4', options, kinematics_linear, element, create_error)
      call check(error, allocated(create_error), 'PLANE4 accepts EAS 3')
      if (allocated(error)) return
      call check(error, index(create_error%message, 'unsupported number of EAS parameters 3 (valid: 0, 4)') > 0, &
                 'message: '//create_error%message)
   end subroutine test_eas_registry

   !> A geostatic initial stress varying with depth, sigma0 = -gamma (10 - y) (K0, 1, K0, 0, 0,
   !> 0) (gamma = 18, K0 = 0.5), at u = 0, Hooke: the enhanced equations weigh S - S0 = 0, so the
   !> local solve from alpha = 1e-3 returns alpha = 0 and the plain element's fint (plane strain
   !> and axisymmetric, both kinematics).
   subroutine test_eas_initial_stress(error)
      type(error_t), allocatable, intent(out) :: error
      type(plane_solid_t) :: plain, element
      real(dp) :: initial(6, 4), positions(3, 4), u(3, 4), fint(12), plain_fint(12), alpha(4), none(0)
      real(dp) :: state_old(0, 4), state_new(0, 4)
      integer :: g, k, kinematics
      u = 0.0_dp
      do k = 0, 1
         do kinematics = kinematics_linear, kinematics_total_lagrangian
            element = enhanced(k == 1, kinematics)
            plain = plane(.true., k == 1, kinematics)
            call element%point_positions(quad_coords, positions)
            do g = 1, 4
               initial(:, g) = -18.0_dp*(10.0_dp - positions(2, g))*[0.5_dp, 1.0_dp, 0.5_dp, 0.0_dp, 0.0_dp, 0.0_dp]
            end do
            alpha = 1.0e-3_dp
            call element%evaluate(new_linear_elastic(young, poisson, 0.0_dp), quad_coords, u, alpha, state_old, &
                                  state_new, fint, error=error, initial_stress=initial)
            if (allocated(error)) return
            call plain%evaluate(new_linear_elastic(young, poisson, 0.0_dp), quad_coords, u, none, state_old, &
                                state_new, plain_fint, error=error, initial_stress=initial)
            if (allocated(error)) return
            call check(error, maxval(abs(alpha)) <= tight .and. maxval(abs(fint - plain_fint)) <= &
                       tight*maxval(abs(plain_fint)), element%name//': alpha '//to_string(maxval(abs(alpha)))// &
                       ', fint off by '//to_string(maxval(abs(fint - plain_fint))))
            if (allocated(error)) return
         end do
      end do
   end subroutine test_eas_initial_stress

end module test_plane_solid
