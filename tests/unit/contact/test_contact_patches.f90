!> Faces and smoothed-normal patches of a contact surface (frix_contact_patches). References:
!> on the top surface of a 3 x 3 x 1 block of HEX8 the patch of a face is the 2 x 2, 2 x 3 or
!> 3 x 3 block of faces around it (corner, edge, centre face), so its ring has 9 - 4 = 5,
!> 12 - 4 = 8 or 16 - 4 = 12 nodes; every patch face, mapped back from local to mesh node
!> numbers, is a surface face sharing a node with the face; a pinwheel of 8 faces around one
!> node has 17 - 4 = 13 ring nodes per face, one more than the kernel takes. Feature angle: on
!> test_contact_fixtures' fold_surface (a 90-degree fold, then 10-degree turns) the nodal normal
!> of a face is the normalised sum of the unit normals of the faces kept around the node, so
!> exactly the facet normal at the fold (only the face's own side kept) and the bisector
!> profile_normal(t_s + 5 degrees) between two 10-degree-apart segments. Free edges: on the
!> 3 x 3 grid of faces the edges on the grid's boundary, by hand; with the centre face taken
!> out also the four edges around the hole.
module test_contact_patches
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_testing, only: unittest_t, new_unittest, check, check_message_contains
   use frix_strings, only: to_string
   use frix_mesh, only: mesh_t, surface_t
   use frix_face_projection, only: face_normal
   use frix_contact_patches, only: surface_patches_t, surface_faces, surface_patches, largest_patch_ring, &
                                   check_patch_rings, ring_nodes_of, patch_faces_of, all_faces_angle, free_edges
   use frix_smoothed_normals, only: patch_normals
   use test_contact_fixtures, only: grid_faces, fold_surface, profile_normal
   implicit none
   private

   public :: collect_contact_patches

contains

   subroutine collect_contact_patches(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('surface faces: top faces of a block, outward normal', test_surface_faces), &
               new_unittest('structured surface: ring sizes 5 / 8 / 12 and local patch faces', test_structured), &
               new_unittest('largest ring: the centre face, within the kernel''s limit', test_largest_ring), &
               new_unittest('pinwheel of 8 faces: 13 ring nodes, error', test_pinwheel), &
               new_unittest('feature angle 30: facet normals at a 90-degree fold, averaged on a curve', &
                            test_fold_and_curve), &
               new_unittest('feature angle just below / above a 10-degree edge flips the patch', test_angle_flip), &
               new_unittest('free edges: the boundary of a 3 x 3 grid, and around a hole', test_free_edges)]
   end subroutine collect_contact_patches

   !> A 3 x 3 x 1 block of unit HEX8 (nodes 1 + i + 4 j + 16 k) and its top surface (face 2).
   subroutine block_mesh(mesh, top)
      type(mesh_t), intent(out) :: mesh
      type(surface_t), intent(out) :: top
      integer :: i, j, k, e, base
      mesh%n_nodes = 32
      mesh%n_elements = 9
      allocate (mesh%coords(3, 32), mesh%connectivity(8, 9))
      do k = 0, 1
         do j = 0, 3
            do i = 0, 3
               mesh%coords(:, 1 + i + 4*j + 16*k) = real([i, j, k], dp)
            end do
         end do
      end do
      do j = 0, 2
         do i = 0, 2
            e = 1 + i + 3*j
            base = 1 + i + 4*j
            mesh%connectivity(1:4, e) = [base, base + 1, base + 5, base + 4]
            mesh%connectivity(5:8, e) = mesh%connectivity(1:4, e) + 16
         end do
      end do
      top%name = 'top'
      top%elements = [(e, e=1, 9)]
      allocate (top%faces(9), source=2)
   end subroutine block_mesh

   subroutine test_surface_faces(error)
      type(error_t), allocatable, intent(out) :: error
      type(mesh_t) :: mesh
      type(surface_t) :: top
      integer, allocatable :: faces(:, :)
      integer :: k
      call block_mesh(mesh, top)
      faces = surface_faces(mesh, top)
      call check(error, all(faces == grid_faces(3) + 16), 'the top faces, counter-clockwise seen from +z')
      if (allocated(error)) return
      do k = 1, 9
         call check(error, maxval(abs(face_normal(mesh%coords(:, faces(:, k)), [0.3_dp, -0.2_dp]) - &
                                      [0.0_dp, 0.0_dp, 1.0_dp])) <= 1.0e-15_dp, 'outward normal +z, face '//to_string(k))
         if (allocated(error)) return
      end do
   end subroutine test_surface_faces

   !> Grid face 1 + i + 3 j: edge 1 (y = j) free for j = 0, 2 (x = i + 1) for i = 2, 3
   !> (y = j + 1) for j = 2, 4 (x = i) for i = 0; without the centre face 5 (i = j = 1) also
   !> the edges of faces 2, 4, 6, 8 toward it.
   subroutine test_free_edges(error)
      type(error_t), allocatable, intent(out) :: error
      integer :: faces(4, 9), i, j
      logical :: expected(4, 9), free(4, 9), holed(4, 8)
      faces = grid_faces(3)
      do j = 0, 2
         do i = 0, 2
            expected(:, 1 + i + 3*j) = [j == 0, i == 2, j == 2, i == 0]
         end do
      end do
      free = free_edges(16, faces)
      call check(error, all(free .eqv. expected), 'the boundary of the 3 x 3 grid')
      if (allocated(error)) return
      expected(3, 2) = .true.   ! face 2's top edge, face 4's right, face 6's left, face 8's bottom
      expected(2, 4) = .true.
      expected(4, 6) = .true.
      expected(1, 8) = .true.
      holed = free_edges(16, faces(:, [1, 2, 3, 4, 6, 7, 8, 9]))
      call check(error, all(holed .eqv. expected(:, [1, 2, 3, 4, 6, 7, 8, 9])), 'around the hole of face 5')
   end subroutine test_free_edges

   subroutine test_structured(error)
      type(error_t), allocatable, intent(out) :: error
      type(surface_patches_t) :: patches
      integer :: faces(4, 9), f
      integer, parameter :: ring_size(9) = [5, 8, 5, 8, 12, 8, 5, 8, 5], patch_size(9) = [4, 6, 4, 6, 9, 6, 4, 6, 4]
      faces = grid_faces(3)
      call surface_patches(flat_grid(3), faces, all_faces_angle, patches)
      do f = 1, 9
         call check(error, size(ring_nodes_of(patches, f)) == ring_size(f) .and. &
                    size(patch_faces_of(patches, f), 2) == patch_size(f), &
                    'face '//to_string(f)//': ring '//to_string(size(ring_nodes_of(patches, f)))// &
                    ', patch '//to_string(size(patch_faces_of(patches, f), 2)))
         if (allocated(error)) return
         call check_patch(error, faces, f, ring_nodes_of(patches, f), patch_faces_of(patches, f))
         if (allocated(error)) return
      end do
   end subroutine test_structured

   !> Face f's ring holds no node of f, twice; mapped back to mesh numbers, the patch faces
   !> are distinct surface faces that share a node with f, f itself as local [1, 2, 3, 4].
   subroutine check_patch(error, faces, f, ring, local)
      type(error_t), allocatable, intent(out) :: error
      integer, intent(in) :: faces(:, :), f, ring(:), local(:, :)
      integer, allocatable :: nodes(:), found(:)
      integer :: g, k, b
      allocate (nodes(4 + size(ring)), found(0))
      nodes(:4) = faces(:, f)
      nodes(5:) = ring
      do k = 1, size(ring)
         call check(error, all(faces(:, f) /= ring(k)) .and. count(ring == ring(k)) == 1, &
                    'face '//to_string(f)//': ring node '//to_string(ring(k)))
         if (allocated(error)) return
      end do
      do g = 1, size(local, 2)
         k = 0
         do b = 1, size(faces, 2)
            if (all(faces(:, b) == nodes(local(:, g)))) k = b
         end do
         call check(error, k > 0 .and. all(found /= k) .and. any([(any(faces(:, f) == faces(b, k)), b=1, 4)]), &
                    'face '//to_string(f)//': patch face '//to_string(g))
         if (allocated(error)) return
         found = [found, k]
      end do
      call check(error, any(found == f) .and. all(local(:, findloc(found, f, dim=1)) == [1, 2, 3, 4]), &
                 'face '//to_string(f)//' in its own patch as [1, 2, 3, 4]')
   end subroutine check_patch

   subroutine test_largest_ring(error)
      type(error_t), allocatable, intent(out) :: error
      type(mesh_t) :: mesh
      type(surface_t) :: top
      type(surface_patches_t) :: patches
      integer :: n_ring, face_nodes(4)
      call block_mesh(mesh, top)
      call largest_patch_ring(mesh, top, all_faces_angle, n_ring, face_nodes)
      call check(error, n_ring == 12 .and. all(face_nodes == [22, 23, 27, 26]), &
                 'the centre face with 12 ring nodes, got '//to_string(n_ring))
      if (allocated(error)) return
      call surface_patches(mesh%coords, surface_faces(mesh, top), all_faces_angle, patches)
      call check_patch_rings(patches, error)
   end subroutine test_largest_ring

   subroutine test_pinwheel(error)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: ring_error
      type(surface_patches_t) :: patches
      real(dp) :: coords(3, 17)
      integer :: faces(4, 8), k, f
      ! node 1 in the centre, rim nodes 2..17 on a circle in z = 0, counter-clockwise; face k
      ! spans rim nodes 2k .. 2k + 2
      coords(:, 1) = 0.0_dp
      do k = 2, 17
         coords(:, k) = [cos((k - 2)*acos(-1.0_dp)/8), sin((k - 2)*acos(-1.0_dp)/8), 0.0_dp]
      end do
      do k = 1, 8
         faces(:, k) = [1, 2*k, 2*k + 1, 2 + mod(2*k, 16)]
      end do
      call surface_patches(coords, faces, all_faces_angle, patches)
      do f = 1, 8
         call check(error, size(ring_nodes_of(patches, f)) == 13 .and. size(patch_faces_of(patches, f), 2) == 8, &
                    'face '//to_string(f)//': 13 ring nodes, 8 patch faces')
         if (allocated(error)) return
         call check_patch(error, faces, f, ring_nodes_of(patches, f), patch_faces_of(patches, f))
         if (allocated(error)) return
      end do
      call check_patch_rings(patches, ring_error)
      call check_message_contains(error, ring_error, &
                                  'smoothed normals: a master face has 13 nodes around it, at most 12 are supported')
      if (allocated(error)) return
      ! flat: the default feature angle keeps every face
      call surface_patches(coords, faces, 30.0_dp, patches)
      call check(error, size(ring_nodes_of(patches, 1)) == 13, 'feature angle 30, flat: 13 ring nodes')
   end subroutine test_pinwheel

   !> The nodes of an (n + 1) x (n + 1) unit grid in z = 0, numbered as grid_faces.
   pure function flat_grid(n) result(coords)
      integer, intent(in) :: n
      real(dp) :: coords(3, (n + 1)**2)
      integer :: i, j
      do j = 0, n
         do i = 0, n
            coords(:, 1 + i + (n + 1)*j) = [real(i, dp), real(j, dp), 0.0_dp]
         end do
      end do
   end function flat_grid

   !> Face f's averaged nodal normals (3, 4) with the patches of feature angle `angle`.
   function fold_nodal_normals(angle, f) result(nodal)
      real(dp), intent(in) :: angle
      integer, intent(in) :: f
      real(dp) :: nodal(3, 4), coords(3, 21)
      type(surface_patches_t) :: patches
      integer :: faces(4, 12)
      call fold_surface(coords, faces)
      call surface_patches(coords, faces, angle, patches)
      nodal = patch_normals(coords(:, faces(:, f)), coords(:, ring_nodes_of(patches, f)), patch_faces_of(patches, f))
   end function fold_nodal_normals

   !> Whether face f's nodal normals are `start` at its nodes 1 and 4 (profile point P(s - 1))
   !> and `finish` at nodes 2 and 3 (P(s)), to 1e-14; else an error naming `what`.
   subroutine check_nodal(error, nodal, start, finish, what)
      type(error_t), allocatable, intent(out) :: error
      real(dp), intent(in) :: nodal(3, 4), start(3), finish(3)
      character(len=*), intent(in) :: what
      real(dp) :: deviation
      deviation = max(maxval(abs(nodal(:, 1) - start)), maxval(abs(nodal(:, 4) - start)), &
                      maxval(abs(nodal(:, 2) - finish)), maxval(abs(nodal(:, 3) - finish)))
      call check(error, deviation <= 1.0e-14_dp, what//': nodal normals off by '//to_string(deviation))
   end subroutine check_nodal

   subroutine test_fold_and_curve(error)
      type(error_t), allocatable, intent(out) :: error
      ! face 2 (t = 0) ends at the fold: its own normal +z there with the feature angle,
      ! the bisector of +z and +x (t = -45) without
      call check_nodal(error, fold_nodal_normals(30.0_dp, 2), profile_normal(0.0_dp), profile_normal(0.0_dp), &
                       'face 2, angle 30')
      if (allocated(error)) return
      call check_nodal(error, fold_nodal_normals(all_faces_angle, 2), profile_normal(0.0_dp), &
                       profile_normal(-45.0_dp), 'face 2, angle 180')
      if (allocated(error)) return
      ! face 3 (t = -90) starts at the fold (facet side) and meets face 4 (t = -100) smoothly
      call check_nodal(error, fold_nodal_normals(30.0_dp, 3), profile_normal(-90.0_dp), profile_normal(-95.0_dp), &
                       'face 3, angle 30')
      if (allocated(error)) return
      ! on the curve the feature angle changes nothing
      call check_nodal(error, fold_nodal_normals(30.0_dp, 4), profile_normal(-95.0_dp), profile_normal(-105.0_dp), &
                       'face 4, angle 30')
      if (allocated(error)) return
      call check(error, maxval(abs(fold_nodal_normals(30.0_dp, 10) - fold_nodal_normals(all_faces_angle, 10))) &
                 == 0.0_dp, 'face 10 (curve, second row): angle 30 and 180 bit-for-bit')
   end subroutine test_fold_and_curve

   subroutine test_angle_flip(error)
      type(error_t), allocatable, intent(out) :: error
      type(surface_patches_t) :: below, above
      real(dp) :: coords(3, 21)
      integer :: faces(4, 12)
      call fold_surface(coords, faces)
      call surface_patches(coords, faces, 9.99_dp, below)
      call surface_patches(coords, faces, 10.01_dp, above)
      ! face 4 and its neighbours along the curve are 10 degrees apart
      call check(error, size(patch_faces_of(below, 4), 2) == 2 .and. size(patch_faces_of(above, 4), 2) == 6, &
                 'face 4: 2 patch faces at 9.99 degrees, 6 at 10.01, got '// &
                 to_string(size(patch_faces_of(below, 4), 2))//' and '//to_string(size(patch_faces_of(above, 4), 2)))
      if (allocated(error)) return
      call check_nodal(error, fold_nodal_normals(9.99_dp, 4), profile_normal(-100.0_dp), profile_normal(-100.0_dp), &
                       'face 4, angle 9.99')
      if (allocated(error)) return
      call check_nodal(error, fold_nodal_normals(10.01_dp, 4), profile_normal(-95.0_dp), profile_normal(-105.0_dp), &
                       'face 4, angle 10.01')
   end subroutine test_angle_flip
end module test_contact_patches
