!> Kinematic (rigid) couplings (docs/couplings.md): the coupled nodes i of a coupling follow
!> the rigid motion of its reference node R, linearised for small rotations,
!>
!>     u_i = u_R + theta x (X_i - X_R),
!>
!> where u_R are the displacements of R and theta (a rotation vector, radians) the
!> displacements of the coupling's rotation node Q (as CalculiX's *RIGID BODY with REF NODE
!> and ROT NODE), X the reference coordinates. Per direction c the row reads
!> u_(i,c) = u_(R,c) + sum_d W_cd theta_d with W = -[r]x, r = X_i - X_R, the skew matrix of the
!> cross product: rows of the constraint equations that frix_constraint_equations eliminates
!> with those of the ties. Its transpose gathers the coupled nodes' forces f_i into R and Q:
!> sum_i f_i at R and sum_i r_i x f_i (the moment about X_R) at Q, so the reactions at fixed
!> directions of R and Q are the resultant force and moment the coupled nodes carry.
!> The rotation is exact to first order in theta only: a rigid rotation by |theta| changes the
!> distance of the coupled nodes to X_R by a relative 1/2 |theta|^2, strain that a geometrically
!> nonlinear element feels (docs/couplings.md, "Limits").
module frix_kinematic_coupling
   use frix_kinds, only: dp
   use frix_model, only: model_t
   use frix_constraint_equations, only: constraint_equations_t
   implicit none
   private

   public :: add_coupling_equations, rigid_motion_weights

contains

   !> The rows of every coupled node of every coupling (coupling by coupling, node by node,
   !> c = x, y, z) appended to `constraints`.
   subroutine add_coupling_equations(model, constraints)
      type(model_t), intent(in) :: model
      type(constraint_equations_t), intent(inout) :: constraints
      integer :: k, j
      if (.not. allocated(model%couplings)) return
      do k = 1, size(model%couplings)
         associate (coupling => model%couplings(k))
            do j = 1, size(coupling%nodes)
               call add_node_rows(coupling%nodes(j), coupling%reference_node, coupling%rotation_node, &
                                  model%mesh%coords(:, coupling%nodes(j)) - &
                                  model%mesh%coords(:, coupling%reference_node), constraints)
            end do
         end associate
      end do
   end subroutine add_coupling_equations

   !> Node i's three rows: u_(i,c) = u_(R,c) + sum_(d /= c) W_cd theta_d (module header).
   subroutine add_node_rows(node, reference, rotation, offset, constraints)
      integer, intent(in) :: node, reference, rotation
      real(dp), intent(in) :: offset(3)   !! r = X_i - X_R [length]
      type(constraint_equations_t), intent(inout) :: constraints
      real(dp) :: w(3, 3)
      integer :: c, d1, d2
      w = rigid_motion_weights(offset)
      do c = 1, 3
         d1 = modulo(c, 3) + 1       ! the two other directions, cyclic
         d2 = modulo(c + 1, 3) + 1
         call constraints%add_row(3*node - 3 + c, [3*reference - 3 + c, 3*rotation - 3 + d1, 3*rotation - 3 + d2], &
                                  [1.0_dp, w(c, d1), w(c, d2)])
      end do
   end subroutine add_node_rows

   !> W = -[r]x, so that theta x r = W theta: W = [[0, r3, -r2], [-r3, 0, r1], [r2, -r1, 0]].
   pure function rigid_motion_weights(r) result(w)
      real(dp), intent(in) :: r(3)
      real(dp) :: w(3, 3)
      w(1, :) = [0.0_dp, r(3), -r(2)]
      w(2, :) = [-r(3), 0.0_dp, r(1)]
      w(3, :) = [r(2), -r(1), 0.0_dp]
   end function rigid_motion_weights
end module frix_kinematic_coupling
