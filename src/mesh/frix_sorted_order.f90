!> Sorting helper of mesh selections: a stable bottom-up merge sort of integer keys (one or
!> several integers per key, compared lexicographically) in O(n log n) - used to sort node
!> sets and to find faces shared by two elements (keys = sorted face node numbers).
module frix_sorted_order
   implicit none
   private

   public :: sorted_order

contains

   !> Order (stable) that sorts the columns of `keys` (m, n) lexicographically.
   pure function sorted_order(keys) result(order)
      integer, intent(in) :: keys(:, :)
      integer, allocatable :: order(:)
      integer, allocatable :: work(:)
      integer :: n, width, left, middle, right, i, j, k
      n = size(keys, 2)
      allocate (order(n), work(n))
      order = [(i, i=1, n)]
      width = 1
      do while (width < n)
         left = 1
         do while (left <= n)
            middle = min(left + width - 1, n)
            right = min(left + 2*width - 1, n)
            i = left
            j = middle + 1
            k = left
            do while (i <= middle .and. j <= right)
               if (less(keys(:, order(j)), keys(:, order(i)))) then
                  work(k) = order(j)
                  j = j + 1
               else
                  work(k) = order(i)
                  i = i + 1
               end if
               k = k + 1
            end do
            do while (i <= middle)
               work(k) = order(i)
               i = i + 1
               k = k + 1
            end do
            do while (j <= right)
               work(k) = order(j)
               j = j + 1
               k = k + 1
            end do
            left = right + 1
         end do
         order = work
         width = 2*width
      end do
   end function sorted_order

   pure logical function less(a, b)
      integer, intent(in) :: a(:), b(:)
      integer :: i
      less = .false.
      do i = 1, size(a)
         if (a(i) /= b(i)) then
            less = a(i) < b(i)
            return
         end if
      end do
   end function less

end module frix_sorted_order
