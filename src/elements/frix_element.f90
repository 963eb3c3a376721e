!> The element interface. An element object describes one formulation (shape, integration,
!> enhanced strains, kinematics) and is shared by every element of a block; the per-element
!> data (coordinates, displacements, EAS parameters, history) are passed in.
!>
!> Element vectors are node-major: entry 3*(a-1)+i is direction i (1=x, 2=y, 3=z) of local
!> node a. `fint` is the internal force vector (the residual is fext - fint) and `tangent` is
!> d fint / d u, consistent with `fint` (statically condensed for EAS).
module frix_element
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_material, only: material_t
   use frix_reference_cell, only: reference_cell_t
   use frix_surface_load, only: pressure_load, face_area_weights
   implicit none
   private

   public :: element_t, element_slot_t
   public :: kinematics_linear, kinematics_total_lagrangian, kinematics_name

   integer, parameter :: kinematics_linear = 1            !! geometrically linear (small strain)
   integer, parameter :: kinematics_total_lagrangian = 2  !! Green-Lagrange strain, 2nd PK stress

   type, abstract :: element_t
      character(len=:), allocatable :: name        !! formulation name as printed, e.g. HEX8-EAS9
      integer :: kinematics = kinematics_linear
   contains
      procedure(count_interface), deferred :: n_nodes     !! nodes per element
      procedure(count_interface), deferred :: n_points    !! integration points per element
      procedure(count_interface), deferred :: n_enhanced  !! EAS parameters kept per element (0 if none)
      !> Internal force and tangent for one element.
      procedure(evaluate_interface), deferred :: evaluate
      !> Reference-configuration volume integral of the shape functions: nodal lumping
      !> weights (sum of N_a over the volume), used for body forces.
      procedure(weights_interface), deferred :: volume_weights
      !> Reference positions of the integration points, X_g = sum_a N_a(xi_g) X_a (where a
      !> point's initial stress is evaluated, frix_initial_stress).
      procedure(positions_interface), deferred :: point_positions
      !> Equivalent nodal forces (and follower load stiffness) of a uniform pressure on one
      !> face of this element; by default the surface load of a 3D element's face
      !> (frix_surface_load); 2D elements integrate over their edges (frix_plane_solid).
      procedure :: face_pressure => element_face_pressure
      !> Whether the element's own stiffness resists a rigid translation in `direction` (1-3):
      !> .false. for a solid; an axisymmetric element resists u_r (its hoop strain u_r / r).
      !> The deck's support check (frix_deck_supports) asks.
      procedure :: resists_translation => element_resists_translation
      !> Tributary measures of one face's nodes, integral of N_a dA0 over the reference face
      !> (area unit; the contact slave nodes' areas): by default a HEX8's bilinear face; a plane
      !> element integrates over its edge with its thickness or 2 pi r.
      procedure :: face_weights => element_face_weights
   end type element_t

   type :: element_slot_t
      class(element_t), allocatable :: formulation
   end type element_slot_t

   abstract interface
      pure function count_interface(self) result(n)
         import :: element_t
         class(element_t), intent(in) :: self
         integer :: n
      end function count_interface

      !> Evaluate one element at total displacement `u`.
      !> EAS: `alpha` enters as the last iterate of the element's enhanced parameters and leaves
      !> solved so that the enhanced residual vanishes at this `u` (local Newton, tolerance
      !> relative 1e-12); fint and tangent are then the statically condensed ones.
      !> `state_old` is the material history at the start of the increment, (n_state, n_points);
      !> `state_new` receives the history at this `u`.
      !> `stress` receives the Cauchy stress and `strain` the small strain (linear kinematics) or
      !> Green-Lagrange strain (total Lagrangian) at each integration point, Voigt order.
      !> `initial_stress` (optional) is each point's initial (in-situ) stress sigma0: the
      !> material is called through material_t%initial_stress_response, so that the stress at
      !> zero strain is sigma0 (Cauchy = S at the reference state); without it, `response`.
      subroutine evaluate_interface(self, material, coords, u, alpha, state_old, state_new, &
                                    fint, tangent, stress, strain, error, initial_stress)
         import :: element_t, material_t, dp, error_t
         class(element_t), intent(in) :: self
         class(material_t), intent(in) :: material
         real(dp), intent(in) :: coords(:, :)       !! (3, n_nodes) reference coordinates
         real(dp), intent(in) :: u(:, :)            !! (3, n_nodes) total displacements
         real(dp), intent(inout) :: alpha(:)        !! (n_enhanced) EAS parameters
         real(dp), intent(in) :: state_old(:, :)    !! (n_state, n_points)
         real(dp), intent(inout) :: state_new(:, :) !! (n_state, n_points)
         real(dp), intent(out) :: fint(:)           !! (3*n_nodes)
         real(dp), intent(out), optional :: tangent(:, :)  !! (3*n_nodes, 3*n_nodes)
         real(dp), intent(out), optional :: stress(:, :)   !! (6, n_points) Cauchy stress
         real(dp), intent(out), optional :: strain(:, :)   !! (6, n_points)
         type(error_t), allocatable, intent(out) :: error  !! e.g. non-positive Jacobian
         real(dp), intent(in), optional :: initial_stress(:, :)  !! (6, n_points) sigma0, tensor shears
      end subroutine evaluate_interface

      pure subroutine positions_interface(self, coords, positions)
         import :: element_t, dp
         class(element_t), intent(in) :: self
         real(dp), intent(in) :: coords(:, :)     !! (3, n_nodes) reference coordinates
         real(dp), intent(out) :: positions(:, :) !! (3, n_points) reference point positions
      end subroutine positions_interface

      pure subroutine weights_interface(self, coords, weights)
         import :: element_t, dp
         class(element_t), intent(in) :: self
         real(dp), intent(in) :: coords(:, :)   !! (3, n_nodes)
         real(dp), intent(out) :: weights(:)    !! (n_nodes): integral of N_a dV0
      end subroutine weights_interface
   end interface

contains

   !> A uniform pressure on the face `face` (the face's reference cell) of a 3D element:
   !> pressure_load of frix_surface_load, with its conventions (p > 0 pushes into the body;
   !> follower: current geometry and the unsymmetric load stiffness d fext / d u; dead:
   !> reference geometry, zero tangent).
   pure subroutine element_face_pressure(self, face, coords, u, pressure, follower, force, tangent)
      class(element_t), intent(in) :: self
      class(reference_cell_t), intent(in) :: face   !! the face's cell
      real(dp), intent(in) :: coords(:, :)    !! (3, face nodes) reference coordinates
      real(dp), intent(in) :: u(:, :)         !! (3, face nodes) total displacements
      real(dp), intent(in) :: pressure        !! p (stress unit), > 0 pushes into the body
      logical, intent(in) :: follower         !! .true.: current normal and area
      real(dp), intent(out) :: force(:)       !! (3 face nodes) fext, node-major
      real(dp), intent(out), optional :: tangent(:, :)  !! (3 face nodes, same) d fext / d u
      if (present(tangent)) then
         call pressure_load(face, coords, u, pressure, follower, force, tangent)
      else
         call pressure_load(face, coords, u, pressure, follower, force)
      end if
   end subroutine element_face_pressure

   !> The tributary areas of a solid's face: a bilinear (QUAD4) face of a HEX8, the faces
   !> contact takes (face_area_weights of frix_surface_load).
   pure subroutine element_face_weights(self, face, coords, weights)
      class(element_t), intent(in) :: self
      class(reference_cell_t), intent(in) :: face   !! the face's cell (QUAD4)
      real(dp), intent(in) :: coords(:, :)    !! (3, 4) reference coordinates
      real(dp), intent(out) :: weights(:)     !! (4) integral of N_a dA0
      call face_area_weights(coords(:, 1:4), weights(1:4))
   end subroutine element_face_weights

   pure logical function element_resists_translation(self, direction)
      class(element_t), intent(in) :: self
      integer, intent(in) :: direction
      element_resists_translation = .false.
   end function element_resists_translation

   pure function kinematics_name(kinematics) result(name)
      integer, intent(in) :: kinematics
      character(len=:), allocatable :: name
      select case (kinematics)
      case (kinematics_linear)
         name = 'Geo_Lin'
      case (kinematics_total_lagrangian)
         name = 'Tot_Lagr'
      case default
         name = 'unknown'
      end select
   end function kinematics_name
end module frix_element
