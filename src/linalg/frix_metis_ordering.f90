!> Fill-reducing ordering by METIS nested dissection (METIS_NodeND, METIS 5, 32-bit idx_t)
!> computed on the NODE graph of a node-block matrix (3 x smaller than the DOF graph,
!> 9 x fewer edges) and expanded node-major to the DOFs.
!>
!> Convention (METIS 5 manual, section "METIS_NodeND"): with A' the permuted matrix, row i
!> of A' is row perm[i] of A, i.e. perm[k] = i means original row i is eliminated k-th.
!> This is exactly CHOLMOD's UserPerm convention ("Perm[k] = i means row i of A is the k-th
!> row of PAP'"), so `perm` (not `iperm`) is handed to CHOLMOD, as SuiteSparse_long for its
!> 64-bit interface (`cholmod_l_analyze_p`).
!>
!> Also the partition of a mesh among processes (`metis_mesh_partition`, METIS_PartMeshDual:
!> the elements by their dual graph, each node to one part; frix_process_group).
module frix_metis_ordering
   use, intrinsic :: iso_c_binding, only: c_int, c_int32_t, c_ptr, c_null_ptr
   use frix_kinds, only: i8, i4
   use frix_error, only: error_t, fatal_error
   use frix_strings, only: to_string
   use frix_sparse_matrix, only: sparse_matrix_t
   implicit none
   private

   public :: metis_dof_permutation, metis_mesh_partition

   integer, parameter :: metis_noptions = 40    !! METIS_NOPTIONS in metis.h
   integer(c_int), parameter :: metis_ok = 1    !! METIS_OK in metis.h

   interface
      function metis_set_default_options(options) bind(C, name='METIS_SetDefaultOptions') result(status)
         import :: c_int, c_int32_t
         integer(c_int32_t), intent(out) :: options(*)
         integer(c_int) :: status
      end function metis_set_default_options

      function metis_node_nd(n_vertices, xadj, adjncy, vertex_weights, options, perm, iperm) &
         bind(C, name='METIS_NodeND') result(status)
         import :: c_int, c_int32_t, c_ptr
         integer(c_int32_t), intent(inout) :: n_vertices
         integer(c_int32_t), intent(inout) :: xadj(*)
         integer(c_int32_t), intent(inout) :: adjncy(*)
         type(c_ptr), value :: vertex_weights
         integer(c_int32_t), intent(inout) :: options(*)
         integer(c_int32_t), intent(out) :: perm(*)
         integer(c_int32_t), intent(out) :: iperm(*)
         integer(c_int) :: status
      end function metis_node_nd

      function metis_part_mesh_dual(n_elements, n_nodes, eptr, eind, vwgt, vsize, ncommon, nparts, tpwgts, &
                                    options, objval, epart, npart) bind(C, name='METIS_PartMeshDual') result(status)
         import :: c_int, c_int32_t, c_ptr
         integer(c_int32_t), intent(in) :: n_elements, n_nodes
         integer(c_int32_t), intent(inout) :: eptr(*), eind(*)
         type(c_ptr), value :: vwgt, vsize
         integer(c_int32_t), intent(in) :: ncommon, nparts
         type(c_ptr), value :: tpwgts
         integer(c_int32_t), intent(inout) :: options(*)
         integer(c_int32_t), intent(out) :: objval
         integer(c_int32_t), intent(out) :: epart(*), npart(*)
         integer(c_int) :: status
      end function metis_part_mesh_dual
   end interface

contains

   !> The elements and nodes of a mesh divided into n_parts parts (METIS_PartMeshDual, METIS 5
   !> manual: elements are neighbours in the dual graph when they share `n_common` nodes, 2 here:
   !> an edge of a plane or a solid element). Each node goes to the part of its first element
   !> (METIS's own node partition leaves the nodes of no element undefined), a node of no
   !> element (a coupling's reference node) to part 0. Parts are 0-based. Error: METIS's status.
   subroutine metis_mesh_partition(connectivity, n_nodes, n_parts, element_part, node_part, error)
      integer, intent(in) :: connectivity(:, :)   !! (nodes per element, n_elements), 0: padding
      integer, intent(in) :: n_nodes, n_parts
      integer, allocatable, intent(out) :: element_part(:), node_part(:)
      type(error_t), allocatable, intent(out) :: error
      integer(c_int32_t), allocatable :: eptr(:), eind(:), epart(:), npart(:)
      integer(c_int32_t) :: options(metis_noptions), objval
      integer(c_int) :: status
      integer :: e, k, position
      allocate (eptr(size(connectivity, 2) + 1), eind(max(1, count(connectivity > 0))))
      allocate (epart(max(1, size(connectivity, 2))), npart(max(1, n_nodes)))
      position = 0
      eptr(1) = 0
      do e = 1, size(connectivity, 2)
         do k = 1, size(connectivity, 1)
            if (connectivity(k, e) <= 0) cycle
            position = position + 1
            eind(position) = int(connectivity(k, e) - 1, c_int32_t)
         end do
         eptr(e + 1) = int(position, c_int32_t)
      end do
      status = metis_set_default_options(options)
      status = metis_part_mesh_dual(int(size(connectivity, 2), c_int32_t), int(n_nodes, c_int32_t), eptr, eind, &
                                    c_null_ptr, c_null_ptr, 2_c_int32_t, int(n_parts, c_int32_t), c_null_ptr, &
                                    options, objval, epart, npart)
      if (status /= metis_ok) then
         call fatal_error(error, 'METIS_PartMeshDual failed with status '//to_string(int(status)))
         return
      end if
      element_part = int(epart(:size(connectivity, 2)))
      allocate (node_part(n_nodes), source=-1)
      do e = 1, size(connectivity, 2)
         do k = 1, size(connectivity, 1)
            if (connectivity(k, e) <= 0) cycle
            if (node_part(connectivity(k, e)) < 0) node_part(connectivity(k, e)) = element_part(e)
         end do
      end do
      where (node_part < 0) node_part = 0
   end subroutine metis_mesh_partition

   !> DOF permutation (0-based, size matrix%n) in the METIS/CHOLMOD `perm` convention:
   !> permutation(k+1) = original equation (0-based) eliminated k-th. Node k eliminated
   !> in position m gives DOFs 3*m, 3*m+1, 3*m+2 -> equations 3*(node-1) + 0, 1, 2.
   subroutine metis_dof_permutation(matrix, permutation, error)
      type(sparse_matrix_t), intent(in), target :: matrix
      integer(i8), allocatable, intent(out) :: permutation(:)
      type(error_t), allocatable, intent(out) :: error
      integer(c_int32_t), allocatable :: xadj(:), adjncy(:), node_perm(:), node_iperm(:)
      integer(c_int32_t) :: options(metis_noptions), n_vertices
      integer :: a, q, b, count, position
      integer(c_int) :: status
      integer(i4), pointer, contiguous :: node_ptr(:), node_adj(:)

      call matrix%node_graph(node_ptr, node_adj)
      allocate (permutation(matrix%n))
      n_vertices = int(matrix%n_nodes, c_int32_t)
      allocate (node_perm(max(1, matrix%n_nodes)), node_iperm(max(1, matrix%n_nodes)))
      ! METIS graph: 0-based CSR without self loops
      allocate (xadj(matrix%n_nodes + 1))
      allocate (adjncy(max(1, size(node_adj) - matrix%n_nodes)))
      position = 0
      xadj(1) = 0
      do a = 1, matrix%n_nodes
         do q = node_ptr(a), node_ptr(a + 1) - 1
            b = node_adj(q)
            if (b == a) cycle
            position = position + 1
            adjncy(position) = int(b - 1, c_int32_t)
         end do
         xadj(a + 1) = int(position, c_int32_t)
      end do
      count = position

      if (count == 0 .or. matrix%n_nodes < 2) then
         ! nothing to order (no couplings): natural order
         do a = 1, matrix%n_nodes
            node_perm(a) = int(a - 1, c_int32_t)
         end do
      else
         status = metis_set_default_options(options)
         status = metis_node_nd(n_vertices, xadj, adjncy, c_null_ptr, options, node_perm, node_iperm)
         if (status /= metis_ok) then
            call fatal_error(error, 'METIS_NodeND failed with status '//to_string(int(status)))
            return
         end if
      end if
      do position = 1, matrix%n_nodes
         do q = 1, 3
            permutation(3*(position - 1) + q) = 3_i8*node_perm(position) + q - 1
         end do
      end do
   end subroutine metis_dof_permutation
end module frix_metis_ordering
