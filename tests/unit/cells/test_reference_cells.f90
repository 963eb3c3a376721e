!> Every cell of the registry against the properties a reference cell must have, from the
!> definitions (Zienkiewicz & Taylor, vol. 1, ch. 8-9): N_a(xi_b) = delta_ab; partition of unity
!> and sum_a dN_a/dxi = 0; derivatives equal central differences of the values; the Gauss rule
!> integrates 1 to the reference volume and the polynomials of its degree exactly; every face
!> turns outward; the extrapolation matrix, interpolated back to the points, gives back the
!> point values; the registry finds each cell by name, VTK and gmsh code.
module test_reference_cells
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_strings, only: to_string
   use frix_testing, only: unittest_t, new_unittest, check
   use frix_reference_cell, only: reference_cell_t
   use frix_cell_registry, only: cell_table, cell_entry_t, find_cell, cell_names, hex8_cell_index
   implicit none
   private

   public :: collect_reference_cells

   !> Round-off of sums of a few O(1) products.
   real(dp), parameter :: tight = 1.0e-14_dp

contains

   subroutine collect_reference_cells(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [ &
              new_unittest('shape functions interpolate the nodes, sum to 1', test_interpolation), &
              new_unittest('derivatives against central differences', test_derivatives), &
              new_unittest('Gauss rule: exact for the monomials of its degree', test_rule), &
              new_unittest('faces turn outward', test_faces_outward), &
              new_unittest('extrapolation then interpolation gives back the point values', test_extrapolation), &
              new_unittest('registry: by name, VTK code, gmsh code', test_registry) &
              ]
   end subroutine collect_reference_cells

   subroutine test_interpolation(error)
      type(error_t), allocatable, intent(out) :: error
      type(cell_entry_t), allocatable :: table(:)
      real(dp), allocatable :: values(:), derivatives(:, :)
      real(dp) :: xi(3)
      integer :: k, b, a
      table = cell_table()
      do k = 1, size(table)
         associate (cell => table(k)%cell)
            allocate (values(cell%n_nodes), derivatives(cell%dimension, cell%n_nodes))
            do b = 1, cell%n_nodes
               call cell%shape_functions(cell%node_coordinates(:, b), values, derivatives)
               do a = 1, cell%n_nodes
                  call check(error, abs(values(a) - merge(1.0_dp, 0.0_dp, a == b)) < tight, &
                             cell%name//': N_'//to_string(a)//' at node '//to_string(b))
                  if (allocated(error)) return
               end do
            end do
            xi = [0.3_dp, -0.7_dp, 0.45_dp]
            call cell%shape_functions(xi(1:cell%dimension), values, derivatives)
            call check(error, abs(sum(values) - 1.0_dp) < tight, cell%name//': sum N_a = 1')
            if (allocated(error)) return
            call check(error, maxval(abs(sum(derivatives, dim=2))) < tight, cell%name//': sum dN_a/dxi = 0')
            if (allocated(error)) return
            deallocate (values, derivatives)
         end associate
      end do
   end subroutine test_interpolation

   subroutine test_derivatives(error)
      type(error_t), allocatable, intent(out) :: error
      type(cell_entry_t), allocatable :: table(:)
      real(dp), allocatable :: values(:), plus(:), minus(:), derivatives(:, :), ignored(:, :)
      real(dp) :: xi(3), step(3)
      real(dp), parameter :: h = 1.0e-6_dp
      integer :: k, d
      table = cell_table()
      xi = [0.21_dp, -0.33_dp, 0.57_dp]
      do k = 1, size(table)
         associate (cell => table(k)%cell, n => table(k)%cell%dimension)
            allocate (values(cell%n_nodes), plus(cell%n_nodes), minus(cell%n_nodes), &
                      derivatives(n, cell%n_nodes), ignored(n, cell%n_nodes))
            call cell%shape_functions(xi(1:n), values, derivatives)
            do d = 1, n
               step = 0
               step(d) = h
               call cell%shape_functions(xi(1:n) + step(1:n), plus, ignored)
               call cell%shape_functions(xi(1:n) - step(1:n), minus, ignored)
               ! central differences of a polynomial of degree <= 2 per direction: exact but
               ! for the round-off of the difference quotient, ~1e-16 / h
               call check(error, maxval(abs((plus - minus)/(2*h) - derivatives(d, :))) < 1.0e-9_dp, &
                          cell%name//': dN/dxi_'//to_string(d))
               if (allocated(error)) return
            end do
            deallocate (values, plus, minus, derivatives, ignored)
         end associate
      end do
   end subroutine test_derivatives

   !> Each cell's rule against the exact integrals of the monomials xi_1^p_1 ... xi_n^p_n it
   !> claims (rule_degree): on [-1, 1]^n every p_d <= degree, int xi^p = 2/(p+1) for even p and
   !> 0 for odd p per direction; on the unit simplex p_1 + ... + p_n <= degree,
   !> int = p_1! ... p_n! / (p_1 + ... + p_n + n)! (the Dirichlet integral; Zienkiewicz &
   !> Taylor, vol. 1, 8.8, with the p = 0 case the simplex's volume 1/n!).
   subroutine test_rule(error)
      type(error_t), allocatable, intent(out) :: error
      type(cell_entry_t), allocatable :: table(:)
      integer :: k, m, k_d, powers(3)
      real(dp) :: expected, integrated
      table = cell_table()
      do k = 1, size(table)
         associate (cell => table(k)%cell, n => table(k)%cell%dimension)
            call check(error, cell%rule_degree > 0, cell%name//': no rule degree')
            if (allocated(error)) return
            do m = 0, (cell%rule_degree + 1)**n - 1
               powers = 0
               powers(1:n) = [(mod(m/(cell%rule_degree + 1)**(k_d - 1), cell%rule_degree + 1), k_d=1, n)]
               if (cell%simplex .and. sum(powers) > cell%rule_degree) cycle
               expected = exact_monomial_integral(powers(1:n), cell%simplex)
               integrated = sum(cell%weights*product(cell%points**spread(powers(1:n), 2, cell%n_points()), dim=1))
               call check(error, abs(integrated - expected) < tight, cell%name//': int of the monomial of powers '// &
                          to_string(powers(1))//' '//to_string(powers(2))//' '//to_string(powers(3))// &
                          ' is '//to_string(integrated)//', exact '//to_string(expected))
               if (allocated(error)) return
            end do
         end associate
      end do
   end subroutine test_rule

   !> The exact integral of prod_d xi_d^powers(d) over [-1, 1]^n or the unit simplex.
   pure real(dp) function exact_monomial_integral(powers, simplex) result(integral)
      integer, intent(in) :: powers(:)
      logical, intent(in) :: simplex
      integer :: d
      if (simplex) then
         integral = product([(gamma(real(powers(d) + 1, dp)), d=1, size(powers))]) &
                    /gamma(real(sum(powers) + size(powers) + 1, dp))
      else
         integral = product([(merge(2.0_dp/(powers(d) + 1), 0.0_dp, mod(powers(d), 2) == 0), &
                              d=1, size(powers))])
      end if
   end function exact_monomial_integral

   !> A face of a 3D cell: (x_2 - x_1) x (x_last - x_1) points away from the cell's centroid; an
   !> edge of a 2D cell: its direction turned clockwise by 90 degrees does.
   subroutine test_faces_outward(error)
      type(error_t), allocatable, intent(out) :: error
      type(cell_entry_t), allocatable :: table(:)
      real(dp) :: normal(3), centre(3), a(3), b(3), c(3)
      integer :: k, f
      table = cell_table()
      do k = 1, size(table)
         associate (cell => table(k)%cell)
            do f = 1, cell%n_faces()
               centre = 0
               centre(1:cell%dimension) = sum(cell%node_coordinates, dim=2)/cell%n_nodes
               a = 0
               b = 0
               c = 0
               if (cell%dimension == 3) then
                  a = cell%node_coordinates(:, cell%face_nodes(1, f))
                  b = cell%node_coordinates(:, cell%face_nodes(2, f))
                  c = cell%node_coordinates(:, cell%face_nodes(size(cell%face_nodes, 1), f))
                  normal = cross(b - a, c - a)
               else
                  a(1:2) = cell%node_coordinates(:, cell%face_nodes(1, f))
                  b(1:2) = cell%node_coordinates(:, cell%face_nodes(2, f))
                  normal = [b(2) - a(2), -(b(1) - a(1)), 0.0_dp]
               end if
               call check(error, dot_product(normal, a - centre) > 0.0_dp, &
                          cell%name//': face '//to_string(f)//' turns inward')
               if (allocated(error)) return
            end do
         end associate
      end do
   end subroutine test_faces_outward

   !> Any point values f, extrapolated to the nodes and interpolated back to the points, give f
   !> again: M E = I with M(g, a) = N_a(xi_g). Where the points are as many as the nodes this
   !> makes E = M^{-1}, so a field of the shape functions' span sampled at the points comes back
   !> exactly at the nodes; with fewer points (TET4's one) the nodes get the field the points
   !> determine (a constant).
   subroutine test_extrapolation(error)
      type(error_t), allocatable, intent(out) :: error
      type(cell_entry_t), allocatable :: table(:)
      real(dp), allocatable :: at_points(:), recovered(:)
      integer :: k, g
      table = cell_table()
      do k = 1, size(table)
         associate (cell => table(k)%cell)
            at_points = [(1.0_dp + 0.37_dp*g - 0.05_dp*g**2, g=1, cell%n_points())]
            recovered = matmul(matmul(at_points, transpose(cell%extrapolation())), cell%values_at_points())
            call check(error, maxval(abs(recovered - at_points)) < 1.0e-13_dp, &
                       cell%name//': extrapolated point values off by '//to_string(maxval(abs(recovered - at_points))))
            if (allocated(error)) return
         end associate
      end do
   end subroutine test_extrapolation

   subroutine test_registry(error)
      type(error_t), allocatable, intent(out) :: error
      type(cell_entry_t), allocatable :: table(:)
      class(reference_cell_t), allocatable :: cell
      logical :: found
      integer :: k
      table = cell_table()
      do k = 1, size(table)
         call find_cell(cell, found, name=table(k)%cell%name)
         call check(error, found, 'no cell named '//table(k)%cell%name)
         if (allocated(error)) return
         call find_cell(cell, found, vtk_type=table(k)%cell%vtk_type)
         call check(error, found .and. cell%name == table(k)%cell%name, 'VTK code of '//table(k)%cell%name)
         if (allocated(error)) return
         call find_cell(cell, found, gmsh_type=table(k)%cell%gmsh_type)
         call check(error, found .and. cell%name == table(k)%cell%name, 'gmsh code of '//table(k)%cell%name)
         if (allocated(error)) return
      end do
      call find_cell(cell, found, name='PYRAMID13')
      call check(error, .not. found .and. .not. allocated(cell), 'an unknown name is found')
      if (allocated(error)) return
      call check(error, cell_names() == 'HEX8 QUAD4 TET4 TRI3 TET10 TRI6 LINE2', 'cell names: '//cell_names())
      if (allocated(error)) return
      call check(error, table(hex8_cell_index)%cell%name == 'HEX8', 'hex8_cell_index is not HEX8''s line')
   end subroutine test_registry

   pure function cross(a, b) result(c)
      real(dp), intent(in) :: a(3), b(3)
      real(dp) :: c(3)
      c = [a(2)*b(3) - a(3)*b(2), a(3)*b(1) - a(1)*b(3), a(1)*b(2) - a(2)*b(1)]
   end function cross

end module test_reference_cells
