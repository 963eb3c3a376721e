!> Tied contact by elimination (docs/contact.md, "Tied contact"). Each tied slave node s
!> follows the master surface with its dual mortar weights (frix_tie_pass, frix_tie_mortar):
!>
!>     u_s = sum_a w_sa u_a,   per direction c = x, y, z,
!>
!> except in the directions where s has a Dirichlet condition (these keep it). These are rows
!> of the constraint equations that frix_constraint_equations eliminates from the Newton
!> system (add_tie_equations), with those of the kinematic couplings.
!> The bond force on the slave, f_s = -r_s before the elimination (r = f_ext - f_int), is the
!> tie's contact force: pressure and traction on the master's normal (record_tie_forces).
module frix_tie_constraints
   use frix_kinds, only: dp
   use frix_error, only: error_t, fatal_error
   use frix_strings, only: to_string
   use frix_mesh, only: mesh_t
   use frix_constraint_equations, only: constraint_equations_t
   use frix_face_projection, only: face_position, face_normal
   use frix_contact_kernel, only: contact_point_result_t, contact_stick
   use frix_contact_pass, only: contact_pass_t, pass_positions
   use frix_tie_pass, only: tie_masters, tie_weights
   implicit none
   private

   public :: check_tie_nodes, add_tie_equations, record_tie_forces

contains

   !> An error when a node is tied twice (slave of two ties) or is a tied slave and the master
   !> node of a tie (chains of ties are not eliminated); `tie_ids` are the deck ids of the
   !> passes' pairs; `culprit`, if present, the pass whose tie the error is about (0 without one).
   subroutine check_tie_nodes(mesh, passes, tie_ids, error, culprit)
      type(mesh_t), intent(in) :: mesh
      type(contact_pass_t), intent(in) :: passes(:)
      integer, intent(in) :: tie_ids(:)
      type(error_t), allocatable, intent(out) :: error
      integer, intent(out), optional :: culprit
      integer, allocatable :: slave_of(:), master_of(:)
      integer :: p, i, node
      if (present(culprit)) culprit = 0
      allocate (slave_of(mesh%n_nodes), master_of(mesh%n_nodes), source=0)
      do p = 1, size(passes)
         if (.not. passes(p)%tied) cycle
         do i = 1, size(passes(p)%slave_nodes)
            if (passes(p)%face(i) == 0) cycle
            node = passes(p)%slave_nodes(i)
            if (slave_of(node) > 0) then
               call fatal_error(error, 'TIE '//to_string(tie_ids(p))//': node '//to_string(mesh%node_ids(node))// &
                                ' is already a slave node of TIE '//to_string(tie_ids(slave_of(node)))// &
                                ' (a node can be tied once)')
               if (present(culprit)) culprit = p
               return
            end if
            slave_of(node) = p
            master_of(tie_masters(passes(p), i)) = p
         end do
      end do
      node = findloc(slave_of > 0 .and. master_of > 0, .true., dim=1)
      if (node == 0) return
      call fatal_error(error, 'TIE '//to_string(tie_ids(slave_of(node)))//': node '// &
                       to_string(mesh%node_ids(node))//' is a slave node and a master node of TIE '// &
                       to_string(tie_ids(master_of(node)))//' (chained ties are not supported)')
      if (present(culprit)) culprit = slave_of(node)
   end subroutine check_tie_nodes

   !> The rows u_(s,c) = sum_a w_sa u_(a,c) of every tied slave node s (pass by pass, slave by
   !> slave, c = x, y, z) appended to `constraints`.
   subroutine add_tie_equations(passes, constraints)
      type(contact_pass_t), intent(in) :: passes(:)
      type(constraint_equations_t), intent(inout) :: constraints
      integer :: p, i, s, c
      do p = 1, size(passes)
         if (.not. passes(p)%tied) cycle
         do i = 1, size(passes(p)%slave_nodes)
            if (passes(p)%face(i) == 0) cycle
            s = passes(p)%slave_nodes(i)
            associate (masters => tie_masters(passes(p), i), weights => tie_weights(passes(p), i))
               do c = 1, 3
                  call constraints%add_row(3*s - 3 + c, 3*masters - 3 + c, weights)
               end do
            end associate
         end do
      end do
   end subroutine add_tie_equations

   !> The bond force of every tied slave node from the residual r = f_ext - f_int before the
   !> elimination: f = -r on its dependent equations (0 in Dirichlet directions), written as
   !> the node's contact result: pressure p = f . n / A_s (compressive positive, negative in
   !> tension), tangential traction (f - (f . n) n) / A_s, n the master face's normal at the
   !> foot point (current), gap (x_s - x(xi_T)) . n, status stick.
   subroutine record_tie_forces(coords, u, dependent, residual, passes)
      real(dp), intent(in) :: coords(:, :), u(:)
      logical, intent(in) :: dependent(:)
      real(dp), intent(in) :: residual(:)
      type(contact_pass_t), intent(inout) :: passes(:)
      real(dp) :: x_face(3, 4), force(3), normal(3), x_slave(3)
      integer :: p, i, s
      do p = 1, size(passes)
         if (.not. passes(p)%tied) cycle
         associate (pass => passes(p))
            do i = 1, size(pass%slave_nodes)
               pass%result(i) = contact_point_result_t()
               if (pass%face(i) == 0) cycle
               s = pass%slave_nodes(i)
               x_face = pass_positions(pass, coords, u, pass%faces(:, pass%face(i)))
               x_slave = coords(:, s) + u(3*s - 2:3*s)
               normal = face_normal(x_face, pass%anchor_xi(:, i))
               force = merge(-residual(3*s - 2:3*s), 0.0_dp, dependent(3*s - 2:3*s))
               pass%result(i)%pressure = dot_product(force, normal)/pass%area(i)
               pass%result(i)%traction = (force - dot_product(force, normal)*normal)/pass%area(i)
               pass%result(i)%normal = normal
               pass%result(i)%xi = pass%anchor_xi(:, i)
               pass%result(i)%gap = dot_product(x_slave - face_position(x_face, pass%anchor_xi(:, i)), normal)
               pass%result(i)%status = contact_stick
               pass%result(i)%law_status = contact_stick
               pass%result(i)%new_anchor_xi = pass%anchor_xi(:, i)
            end do
         end associate
      end do
   end subroutine record_tie_forces
end module frix_tie_constraints
