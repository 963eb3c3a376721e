!> The faces of a contact surface and the smoothed-normal patches of its faces.
!>
!> A master surface is a list of HEX8 element faces; as contact faces they are (4, n) mesh node
!> numbers in outward (HEX8 face) order, so that the face normal points out of the master body
!> (docs/contact.md, "Kinematics"). The patch of face f is the set of faces that share a node
!> with f and whose reference unit normal at the face centre makes an angle of at most the
!> feature angle with f's (NORMALS Auto; 180 degrees, every face sharing a node, for NORMALS
!> Smoothed): the averaged nodal normals of f's 4 nodes (frix_contact_kernel's patch_normals)
!> are averaged over that patch, so that across an edge sharper than the feature angle f's
!> nodal normals come from f's side only (facet-like), and they enter the kernel's tangent:
!> f's own 4 nodes and its ring, the patch's other nodes (12 on a structured surface, at most
!> max_ring_nodes). The decision is taken once, in the reference configuration.
!>
!> The free edges of a surface (free_edges) are its boundary: the face edges that belong to
!> no other face of the surface (docs/contact.md, "Edges and corners").
module frix_contact_patches
   use frix_error, only: error_t, fatal_error
   use frix_strings, only: to_string
   use frix_kinds, only: dp
   use frix_mesh, only: mesh_t, surface_t
   use frix_vector_algebra, only: cross_product
   use frix_contact_kernel, only: max_ring_nodes
   implicit none
   private

   public :: surface_patches_t, surface_faces, surface_patches, largest_patch_ring, check_patch_rings
   public :: ring_nodes_of, patch_faces_of, all_faces_angle, surface_is_curved, free_edges, faces_around_nodes

   !> A feature angle (degrees) at or above which every face sharing a node is in the patch
   !> (NORMALS Smoothed), without computing an angle: bit-for-bit the unfiltered patches.
   real(dp), parameter :: all_faces_angle = 180.0_dp
   !> Faces whose normals differ by less than this (radians) count as coplanar
   !> (surface_is_curved): 1e-6, far above the round-off of a flat mesh's normals.
   real(dp), parameter :: flat_angle = 1.0e-6_dp

   !> The patch of every face of a surface, compressed rows over the faces:
   !> ring_nodes(ring_start(f) + 1 : ring_start(f + 1)) are the mesh numbers of face f's ring
   !> nodes; patch_faces(:, patch_start(f) + 1 : patch_start(f + 1)) the patch's faces (f among
   !> them) in local node numbers (1-4 face f's nodes, 4 + j ring node j), as node_face_contact
   !> takes them.
   type :: surface_patches_t
      integer, allocatable :: ring_start(:), ring_nodes(:), patch_start(:), patch_faces(:, :)
   end type surface_patches_t

contains

   !> The faces of a surface of HEX8 element faces, as (4, n) mesh node numbers in outward
   !> (HEX8 face) order.
   pure function surface_faces(mesh, surface) result(faces)
      type(mesh_t), intent(in) :: mesh
      type(surface_t), intent(in) :: surface
      integer :: faces(4, size(surface%elements))
      integer :: k
      do k = 1, size(surface%elements)
         faces(:, k) = mesh%face_nodes(surface%elements(k), surface%faces(k))
      end do
   end function surface_faces

   !> The patch of every face of a surface (faces(4, n), mesh node numbers): the faces sharing
   !> a node with it within the feature angle (reference centre normals).
   pure subroutine surface_patches(coords, faces, feature_angle, patches)
      real(dp), intent(in) :: coords(:, :)    !! reference coordinates (3, n_nodes)
      integer, intent(in) :: faces(:, :)      !! (4, n_faces)
      real(dp), intent(in) :: feature_angle   !! degrees; >= all_faces_angle: no filtering
      type(surface_patches_t), intent(out) :: patches
      integer, allocatable :: node_start(:), node_faces(:), adjacent(:), ring(:), local(:, :)
      real(dp), allocatable :: centre_normal(:, :)
      integer :: n_faces, f
      n_faces = size(faces, 2)
      call faces_around_nodes(size(coords, 2), faces, node_start, node_faces)
      centre_normal = centre_normals(coords, faces)
      allocate (patches%ring_start(n_faces + 1), patches%patch_start(n_faces + 1))
      allocate (patches%ring_nodes(max(1, max_ring_nodes*n_faces)), patches%patch_faces(4, max(1, 9*n_faces)))
      patches%ring_start(1) = 0
      patches%patch_start(1) = 0
      do f = 1, n_faces
         adjacent = adjacent_faces(faces, f, node_start, node_faces)
         if (feature_angle < all_faces_angle) &
            adjacent = pack(adjacent, adjacent == f .or. &
                            within_feature_angle(centre_normal(:, f), centre_normal(:, adjacent), feature_angle))
         call local_patch(faces, f, adjacent, ring, local)
         call append_patch(patches, f, ring, local)
      end do
   end subroutine surface_patches

   !> Whether two faces of the surface that share a node meet at an angle above flat_angle and
   !> at most the feature angle (degrees), in the reference configuration: a curved surface,
   !> which NORMALS Auto smooths; a flat one (or one whose edges are all sharper than the
   !> feature angle) keeps the facet normals, exact for it and giving a symmetric tangent.
   pure logical function surface_is_curved(coords, faces, feature_angle) result(curved)
      real(dp), intent(in) :: coords(:, :)    !! reference coordinates (3, n_nodes)
      integer, intent(in) :: faces(:, :)      !! (4, n_faces)
      real(dp), intent(in) :: feature_angle   !! degrees
      integer, allocatable :: node_start(:), node_faces(:), adjacent(:)
      real(dp), allocatable :: centre_normal(:, :)
      integer :: f
      call faces_around_nodes(size(coords, 2), faces, node_start, node_faces)
      centre_normal = centre_normals(coords, faces)
      curved = .false.
      do f = 1, size(faces, 2)
         adjacent = adjacent_faces(faces, f, node_start, node_faces)
         curved = any(within_feature_angle(centre_normal(:, f), centre_normal(:, adjacent), feature_angle) .and. &
                      .not. within_feature_angle(centre_normal(:, f), centre_normal(:, adjacent), &
                                                 flat_angle*180.0_dp/acos(-1.0_dp)))
         if (curved) return
      end do
   end function surface_is_curved

   !> face_centre_normal of every face (3, n_faces).
   pure function centre_normals(coords, faces) result(normals)
      real(dp), intent(in) :: coords(:, :)
      integer, intent(in) :: faces(:, :)
      real(dp) :: normals(3, size(faces, 2))
      integer :: f
      do f = 1, size(faces, 2)
         normals(:, f) = face_centre_normal(coords(:, faces(:, f)))
      end do
   end function centre_normals

   !> The unit normal at the centre of a face (HEX8 face order: outward), computed on the face
   !> scaled to unit size, so that no finite coordinates overflow or underflow; zero for a
   !> degenerate face (zero area), which then is within no feature angle of another.
   pure function face_centre_normal(x_face) result(normal)
      real(dp), intent(in) :: x_face(3, 4)
      real(dp) :: normal(3), scaled(3, 4), scale, length
      normal = 0.0_dp
      scale = maxval(abs(x_face))
      if (.not. (scale > 0.0_dp .and. scale <= huge(1.0_dp))) return
      scaled = x_face/scale
      normal = cross_product(0.5_dp*(scaled(:, 3) - scaled(:, 1)), 0.5_dp*(scaled(:, 4) - scaled(:, 2)))
      length = norm2(normal)
      if (length > 0.0_dp) then
         normal = normal/length
      else
         normal = 0.0_dp
      end if
   end function face_centre_normal

   !> Whether each unit normal normals(:, k) makes an angle of at most feature_angle (degrees)
   !> with the unit normal `own`: acos(own . n) <= feature_angle (the cosine clamped to [-1, 1]).
   pure function within_feature_angle(own, normals, feature_angle) result(within)
      real(dp), intent(in) :: own(3), normals(:, :), feature_angle
      logical :: within(size(normals, 2))
      real(dp), parameter :: degree = acos(-1.0_dp)/180.0_dp
      integer :: k
      do k = 1, size(normals, 2)
         within(k) = acos(max(-1.0_dp, min(1.0_dp, dot_product(own, normals(:, k))))) <= feature_angle*degree
      end do
   end function within_feature_angle

   !> Whether each edge of each face of a surface (faces(4, n), mesh node numbers) is free: it
   !> belongs to no other face of the surface, i.e. it is part of the surface's boundary. Edge k
   !> of a face joins its nodes k and mod(k, 4) + 1 (in parent coordinates edge 1 lies at
   !> xi2 = -1, 2 at xi1 = +1, 3 at xi2 = +1, 4 at xi1 = -1).
   pure function free_edges(n_nodes, faces) result(free)
      integer, intent(in) :: n_nodes          !! mesh nodes (faces hold numbers 1 .. n_nodes)
      integer, intent(in) :: faces(:, :)      !! (4, n_faces)
      logical :: free(4, size(faces, 2))
      integer, allocatable :: node_start(:), node_faces(:)
      integer :: f, k, j, first, second
      call faces_around_nodes(n_nodes, faces, node_start, node_faces)
      do f = 1, size(faces, 2)
         do k = 1, 4
            first = faces(k, f)
            second = faces(mod(k, 4) + 1, f)
            free(k, f) = .true.
            do j = node_start(first) + 1, node_start(first + 1)
               if (node_faces(j) /= f .and. has_edge(faces(:, node_faces(j)), first, second)) free(k, f) = .false.
            end do
         end do
      end do
   end function free_edges

   !> Whether a face (4 node numbers, in order around it) has the edge joining two nodes.
   pure logical function has_edge(face, first, second)
      integer, intent(in) :: face(4), first, second
      integer :: k
      has_edge = .false.
      do k = 1, 4
         associate (a => face(k), b => face(mod(k, 4) + 1))
            if ((a == first .and. b == second) .or. (a == second .and. b == first)) has_edge = .true.
         end associate
      end do
   end function has_edge

   !> The faces around each node as compressed rows over the mesh's nodes:
   !> node_faces(node_start(n) + 1 : node_start(n + 1)) hold node n's faces, in face order.
   pure subroutine faces_around_nodes(n_nodes, faces, node_start, node_faces)
      integer, intent(in) :: n_nodes, faces(:, :)
      integer, allocatable, intent(out) :: node_start(:), node_faces(:)
      integer, allocatable :: fill(:)
      integer :: f, a, node
      allocate (node_start(n_nodes + 1), source=0)
      do f = 1, size(faces, 2)
         node_start(faces(:, f) + 1) = node_start(faces(:, f) + 1) + 1
      end do
      do node = 1, n_nodes
         node_start(node + 1) = node_start(node + 1) + node_start(node)
      end do
      allocate (node_faces(node_start(n_nodes + 1)))
      fill = node_start(:n_nodes)
      do f = 1, size(faces, 2)
         do a = 1, 4
            fill(faces(a, f)) = fill(faces(a, f)) + 1
            node_faces(fill(faces(a, f))) = f
         end do
      end do
   end subroutine faces_around_nodes

   !> The faces that share a node with face f, in the order met over f's nodes.
   pure function adjacent_faces(faces, f, node_start, node_faces) result(adjacent)
      integer, intent(in) :: faces(:, :), f, node_start(:), node_faces(:)
      integer, allocatable :: adjacent(:)
      integer :: a, k, node
      allocate (adjacent(0))
      do a = 1, 4
         node = faces(a, f)
         do k = node_start(node) + 1, node_start(node + 1)
            if (all(adjacent /= node_faces(k))) adjacent = [adjacent, node_faces(k)]
         end do
      end do
   end function adjacent_faces

   !> Face f's patch in local node numbers: the ring (mesh numbers of the patch's nodes other
   !> than f's, in the order met) and local(:, g), adjacent face g's nodes as 1-4 (f's nodes)
   !> or 4 + j (ring node j).
   pure subroutine local_patch(faces, f, adjacent, ring, local)
      integer, intent(in) :: faces(:, :), f, adjacent(:)
      integer, allocatable, intent(out) :: ring(:), local(:, :)
      integer :: g, b, node, position
      allocate (ring(0), local(4, size(adjacent)))
      do g = 1, size(adjacent)
         do b = 1, 4
            node = faces(b, adjacent(g))
            position = findloc(faces(:, f), node, dim=1)
            if (position == 0) then
               position = findloc(ring, node, dim=1)
               if (position == 0) then
                  ring = [ring, node]
                  position = size(ring)
               end if
               position = 4 + position
            end if
            local(b, g) = position
         end do
      end do
   end subroutine local_patch

   !> Store face f's ring and local patch faces after those of faces 1 .. f - 1 (growing the
   !> rows where a surface has more than the structured 12 ring nodes and 9 faces per patch).
   pure subroutine append_patch(patches, f, ring, local)
      type(surface_patches_t), intent(inout) :: patches
      integer, intent(in) :: f, ring(:), local(:, :)
      integer, allocatable :: grown_ring(:), grown(:, :)
      integer :: n_ring, n_adjacent
      n_ring = size(ring)
      n_adjacent = size(local, 2)
      associate (ring_start => patches%ring_start, patch_start => patches%patch_start)
         if (ring_start(f) + n_ring > size(patches%ring_nodes)) then
            allocate (grown_ring(2*(ring_start(f) + n_ring)))
            grown_ring(:ring_start(f)) = patches%ring_nodes(:ring_start(f))
            call move_alloc(grown_ring, patches%ring_nodes)
         end if
         patches%ring_nodes(ring_start(f) + 1:ring_start(f) + n_ring) = ring
         ring_start(f + 1) = ring_start(f) + n_ring
         if (patch_start(f) + n_adjacent > size(patches%patch_faces, 2)) then
            allocate (grown(4, 2*(patch_start(f) + n_adjacent)))
            grown(:, :patch_start(f)) = patches%patch_faces(:, :patch_start(f))
            call move_alloc(grown, patches%patch_faces)
         end if
         patches%patch_faces(:, patch_start(f) + 1:patch_start(f) + n_adjacent) = local
         patch_start(f + 1) = patch_start(f) + n_adjacent
      end associate
   end subroutine append_patch

   !> Mesh numbers of face f's ring nodes.
   pure function ring_nodes_of(patches, f) result(nodes)
      type(surface_patches_t), intent(in) :: patches
      integer, intent(in) :: f
      integer, allocatable :: nodes(:)
      nodes = patches%ring_nodes(patches%ring_start(f) + 1:patches%ring_start(f + 1))
   end function ring_nodes_of

   !> Face f's patch faces in local node numbers (4, n).
   pure function patch_faces_of(patches, f) result(local)
      type(surface_patches_t), intent(in) :: patches
      integer, intent(in) :: f
      integer, allocatable :: local(:, :)
      local = patches%patch_faces(:, patches%patch_start(f) + 1:patches%patch_start(f + 1))
   end function patch_faces_of

   !> The face whose ring has the most nodes (1 for no face).
   pure integer function largest_ring_face(patches) result(f)
      type(surface_patches_t), intent(in) :: patches
      f = 1
      associate (ring_start => patches%ring_start)
         if (size(ring_start) > 1) f = maxloc(ring_start(2:) - ring_start(:size(ring_start) - 1), dim=1)
      end associate
   end function largest_ring_face

   !> An error if a face has more ring nodes than the kernel takes (max_ring_nodes); the deck
   !> reader reports it first, at the NORMALS keyword, through largest_patch_ring.
   pure subroutine check_patch_rings(patches, error)
      type(surface_patches_t), intent(in) :: patches
      type(error_t), allocatable, intent(out) :: error
      integer :: f, n_ring
      if (size(patches%ring_start) < 2) return
      f = largest_ring_face(patches)
      n_ring = patches%ring_start(f + 1) - patches%ring_start(f)
      if (n_ring > max_ring_nodes) &
         call fatal_error(error, 'smoothed normals: a master face has '//to_string(n_ring)// &
                          ' nodes around it, at most '//to_string(max_ring_nodes)//' are supported')
   end subroutine check_patch_rings

   !> The master surface's largest smoothed-normal ring (patches within the feature angle): its
   !> size and the face that has it (for the deck reader's check of NORMALS Smoothed and Auto
   !> against max_ring_nodes).
   subroutine largest_patch_ring(mesh, surface, feature_angle, n_ring, face_nodes)
      type(mesh_t), intent(in) :: mesh
      type(surface_t), intent(in) :: surface
      real(dp), intent(in) :: feature_angle   !! degrees (surface_patches)
      integer, intent(out) :: n_ring          !! ring nodes of that face
      integer, intent(out) :: face_nodes(4)   !! mesh node numbers of that face
      integer, allocatable :: faces(:, :)
      type(surface_patches_t) :: patches
      integer :: f
      n_ring = 0
      face_nodes = 0
      if (size(surface%elements) == 0) return
      faces = surface_faces(mesh, surface)
      if (feature_angle < all_faces_angle) then
         if (.not. surface_is_curved(mesh%coords, faces, feature_angle)) return   ! facet normals
      end if
      call surface_patches(mesh%coords, faces, feature_angle, patches)
      f = largest_ring_face(patches)
      n_ring = patches%ring_start(f + 1) - patches%ring_start(f)
      face_nodes = faces(:, f)
   end subroutine largest_patch_ring
end module frix_contact_patches
