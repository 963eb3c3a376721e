!> The bucket grid of face boxes (frix_face_grid). Reference: the definition itself, a test of
!> every face's box (inflated by the band) against the query box in increasing face order, as
!> the mortar integrals made it before the grid (frix_mortar_segments' mortar_triplets).
!> Faces: a 7 x 5 grid of quadrilaterals of size 0.3 on the wavy surface z = 0.2 sin(3 x) cos(2 y)
!> (boxes of different heights), band 0.05; queries: 60 boxes at points of a deterministic
!> sequence over [-0.5, 2.6] x [-0.5, 2] x [-0.4, 0.4], sides 0 to 0.9, some outside the grid.
module test_face_grid
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_testing, only: unittest_t, new_unittest, check
   use frix_strings, only: to_string
   use frix_face_grid, only: face_grid_t, build_face_grid, faces_meeting_box
   implicit none
   private

   public :: collect_face_grid

contains

   subroutine collect_face_grid(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('faces meeting a box: the same as a test of every box', test_faces_meeting_box)]
   end subroutine collect_face_grid

   subroutine test_faces_meeting_box(error)
      type(error_t), allocatable, intent(out) :: error
      integer, parameter :: nx = 7, ny = 5
      real(dp), parameter :: h = 0.3_dp, band = 0.05_dp
      real(dp) :: x_faces(3, 4, nx*ny), lower(3), upper(3), corner(2), box_lower(3), box_upper(3)
      type(face_grid_t) :: grid
      integer, allocatable :: visited(:), found(:), expected(:)
      integer :: i, j, a, f, q, n_found
      real(dp), parameter :: offset_x(4) = [0.0_dp, 1.0_dp, 1.0_dp, 0.0_dp], offset_y(4) = [0.0_dp, 0.0_dp, 1.0_dp, 1.0_dp]
      do j = 1, ny
         do i = 1, nx
            f = i + nx*(j - 1)
            do a = 1, 4
               corner = h*[i - 1 + offset_x(a), j - 1 + offset_y(a)]
               x_faces(:, a, f) = [corner, 0.2_dp*sin(3.0_dp*corner(1))*cos(2.0_dp*corner(2))]
            end do
         end do
      end do
      call build_face_grid(x_faces, band, grid)
      allocate (visited(nx*ny), source=0)
      do q = 1, 60
         ! fractional parts of multiples of irrational numbers: spread over the region
         lower = [-0.5_dp, -0.5_dp, -0.4_dp] + [3.1_dp, 2.5_dp, 0.8_dp]*[fraction_of(q*0.6180339887_dp), &
                 fraction_of(q*0.4142135624_dp), fraction_of(q*0.7320508076_dp)]
         upper = lower + 0.9_dp*fraction_of(q*0.2360679775_dp)*[1.0_dp, 0.7_dp, 0.5_dp]
         call faces_meeting_box(grid, lower, upper, q, visited, found, n_found)
         expected = [integer ::]
         do f = 1, nx*ny
            box_lower = minval(x_faces(:, :, f), dim=2) - band
            box_upper = maxval(x_faces(:, :, f), dim=2) + band
            if (any(upper < box_lower .or. lower > box_upper)) cycle
            expected = [expected, f]
         end do
         call check(error, n_found == size(expected), 'query '//to_string(q)//': '//to_string(n_found)// &
                    ' faces found, '//to_string(size(expected))//' expected')
         if (allocated(error)) return
         call check(error, all(found(:n_found) == expected), 'query '//to_string(q)//': other faces or order')
         if (allocated(error)) return
      end do
   contains
      pure real(dp) function fraction_of(value)
         real(dp), intent(in) :: value
         fraction_of = value - floor(value)
      end function fraction_of
   end subroutine test_faces_meeting_box
end module test_face_grid
