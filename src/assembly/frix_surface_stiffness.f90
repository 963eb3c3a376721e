!> The normal stiffness of the elements under a surface, from which an automatic contact
!> penalty is derived (docs/contact.md, "Choosing the penalties").
!>
!> A face of an element of modulus M and size h normal to the face behaves, under a pressure
!> p on the face, like a spring of stiffness M/h per unit area (force/area/length, the unit of
!> eps_N): the face moves by about p h / M. With eps_N = c M/h the penetration p / eps_N is 1/c
!> of that motion.
!>   M  = (C_11 + C_22 + C_33)/3 of the material's small-strain elastic tangent (6 x 6 Voigt,
!>        at zero strain): the constrained (oedometric) modulus, lambda + 2 mu =
!>        E (1 - nu)/((1 + nu)(1 - 2 nu)) for an isotropic law, the stiffness of an element
!>        compressed across a face while its neighbours hold it sideways (force/area);
!>   h  = V / A, the element's reference volume over the face's reference area (length): its
!>        thickness normal to the face for a prism on the face, e.g. a brick element; for a
!>        plane element its area over the edge's length (the thickness, or 2 pi r, cancels:
!>        exactly in plane strain, to the ratio of the edge's mean radius to the element's
!>        centroid radius in axisymmetry).
!> A surface's value is the mean of M/h over its faces (each face counts once, whatever its
!> area).
module frix_surface_stiffness
   use frix_kinds, only: dp
   use frix_material, only: material_t
   use frix_model, only: model_t
   implicit none
   private

   public :: representative_modulus, face_stiffness, surface_stiffness

contains

   !> M = (C_11 + C_22 + C_33)/3 of the elastic tangent at zero strain (force/area).
   pure real(dp) function representative_modulus(material) result(modulus)
      class(material_t), intent(in) :: material
      real(dp) :: tangent(6, 6)
      call material%elastic_tangent(tangent)
      modulus = (tangent(1, 1) + tangent(2, 2) + tangent(3, 3))/3.0_dp
   end function representative_modulus

   !> M/h (force/area/length) of local face `face` of element `element`, h = V/A in the
   !> reference configuration; the element's block gives its formulation (V: volume_weights, A:
   !> face_weights, a HEX8's bilinear face or a plane element's edge with its thickness or
   !> 2 pi r, whose factor cancels in A/V) and material (for M).
   real(dp) function face_stiffness(model, element, face) result(stiffness)
      type(model_t), intent(in) :: model
      integer, intent(in) :: element   !! internal element number
      integer, intent(in) :: face      !! local face number
      real(dp), allocatable :: coords(:, :), face_coords(:, :), weights(:), area_weights(:)
      real(dp) :: volume, area, scale, modulus, ratio
      integer :: block
      block = model%mesh%element_block(element)
      coords = model%mesh%coords(:, model%mesh%element_nodes(element))
      ! A/V from the element scaled to unit size (no overflow or underflow for any finite
      ! coordinates), then A/V = (A'/V') / scale; a degenerate element gives 0, a value beyond
      ! the range of reals huge(): the caller reports either
      stiffness = 0.0_dp
      scale = maxval(abs(coords))
      if (.not. (scale > 0.0_dp .and. scale <= huge(1.0_dp))) return
      coords = coords/scale
      face_coords = model%mesh%coords(:, model%mesh%face_nodes(element, face))/scale
      allocate (weights(size(coords, 2)), area_weights(max(4, size(face_coords, 2))))
      associate (formulation => model%blocks(block)%element%formulation)
         call formulation%volume_weights(coords, weights)
         call formulation%face_weights(model%mesh%cells(model%mesh%face_cell_of(element))%cell, face_coords, &
                                       area_weights)
      end associate
      volume = sum(weights)
      area = sum(area_weights(1:size(face_coords, 2)))
      if (.not. (volume > 0.0_dp .and. area > 0.0_dp)) return
      ratio = area/volume
      modulus = representative_modulus(model%materials(model%blocks(block)%material)%law)
      if (.not. (modulus > 0.0_dp .and. modulus <= huge(1.0_dp))) return
      ! M A/V = M (A'/V') / scale overflows only where (A'/V') / scale > 1 and M beyond huge / that
      if (ratio > scale) then
         if (modulus > huge(1.0_dp)/(ratio/scale)) then
            stiffness = huge(1.0_dp)
            return
         end if
      end if
      stiffness = modulus*(ratio/scale)
   end function face_stiffness

   !> Mean of M/h over the faces of surface `surface` (index into model%mesh%surfaces); 0 for a
   !> surface without faces.
   real(dp) function surface_stiffness(model, surface) result(mean)
      type(model_t), intent(in) :: model
      integer, intent(in) :: surface
      integer :: k, n_faces
      mean = 0.0_dp
      associate (faces => model%mesh%surfaces(surface))
         n_faces = size(faces%elements)
         do k = 1, n_faces
            mean = mean + face_stiffness(model, faces%elements(k), faces%faces(k))
         end do
      end associate
      if (n_faces > 0) mean = mean/n_faces
   end function surface_stiffness
end module frix_surface_stiffness
