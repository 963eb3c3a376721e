!> Tests of frix_id_map: look-ups, unknown ids, duplicates, growth.
module test_id_map
   use frix_error, only: error_t
   use frix_testing, only: unittest_t, new_unittest, check
   use frix_strings, only: to_string
   use frix_id_map, only: id_map_t
   implicit none
   private

   public :: collect_id_map

contains

   subroutine collect_id_map(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('build_and_lookup', test_build_and_lookup), &
               new_unittest('duplicate_detected', test_duplicate), &
               new_unittest('growth_with_strided_ids', test_growth)]
   end subroutine collect_id_map

   subroutine test_build_and_lookup(error)
      type(error_t), allocatable, intent(out) :: error
      type(id_map_t) :: map
      ! negative, zero, extreme and scattered ids
      integer, parameter :: ids(7) = [17, -3, 0, huge(1), -huge(1), 100000, 4]
      integer :: duplicate, i
      call map%build(ids, duplicate)
      call check(error, duplicate == 0 .and. map%size() == 7, 'seven distinct ids')
      if (allocated(error)) return
      do i = 1, size(ids)
         call check(error, map%lookup(ids(i)) == i, 'id '//to_string(ids(i))//' maps to '//to_string(i))
         if (allocated(error)) return
      end do
      call check(error, map%lookup(5) == 0 .and. map%lookup(-17) == 0, 'unknown ids give 0')
   end subroutine test_build_and_lookup

   subroutine test_duplicate(error)
      type(error_t), allocatable, intent(out) :: error
      type(id_map_t) :: map
      integer :: duplicate, existing
      call map%build([5, 8, 13, 8, 5], duplicate)
      call check(error, duplicate == 4, 'first repeated id at position 4, got '//to_string(duplicate))
      if (allocated(error)) return
      call check(error, map%lookup(8) == 2, 'the first occurrence is kept')
      if (allocated(error)) return
      call map%insert(13, 99, existing)
      call check(error, existing == 3 .and. map%lookup(13) == 3, 'insert of a present id reports it')
      if (allocated(error)) return
      call map%insert(21, 4, existing)
      call check(error, existing == 0 .and. map%lookup(21) == 4, 'insert of a new id')
   end subroutine test_duplicate

   !> Ids that are multiples of 1024 defeat a hash taking the low bits; 20000 inserts one by
   !> one also make the table grow several times.
   subroutine test_growth(error)
      type(error_t), allocatable, intent(out) :: error
      type(id_map_t) :: map
      integer :: i, existing, wrong
      do i = 1, 20000
         call map%insert(1024*i, i, existing)
         if (existing /= 0) then
            call check(error, .false., 'id '//to_string(1024*i)//' reported present')
            return
         end if
      end do
      wrong = 0
      do i = 1, 20000
         if (map%lookup(1024*i) /= i) wrong = wrong + 1
      end do
      call check(error, wrong == 0 .and. map%size() == 20000, to_string(wrong)//' wrong look-ups')
      if (allocated(error)) return
      call check(error, map%lookup(1024*20001) == 0 .and. map%lookup(1023) == 0, 'unknown ids give 0')
   end subroutine test_growth
end module test_id_map
