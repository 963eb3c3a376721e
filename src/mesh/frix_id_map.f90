!> Map from user ids (any default integers, e.g. gmsh or deck node ids) to internal numbers
!> 1..n, as an open-addressing hash table with linear probing (expected O(1) per look-up).
!>
!> Hash: Knuth's multiplicative hashing, h(k) = ((k * 2654435761) mod 2**32) >> (32 - p) for a
!> table of 2**p slots, computed in 64-bit integers so that no product overflows
!> (|k| < 2**31, 2654435761 < 2**32). The table is kept at most half full.
module frix_id_map
   use frix_kinds, only: i8
   implicit none
   private

   public :: id_map_t

   integer(i8), parameter :: knuth_multiplier = 2654435761_i8
   integer(i8), parameter :: low_32_bits = 4294967295_i8

   type :: id_map_t
      integer, allocatable, private :: keys(:)     !! (0:capacity-1) ids
      integer, allocatable, private :: values(:)   !! (0:capacity-1) internal numbers, 0 = empty slot
      integer, private :: bits = 0                 !! capacity = 2**bits
      integer, private :: count = 0
   contains
      procedure :: build
      procedure :: insert
      procedure :: lookup
      procedure :: size => map_size
      procedure :: clear
   end type id_map_t

contains

   !> Map `ids(i)` to `i`. `duplicate` is 0, or the position of the first id that repeats an
   !> earlier one (that later occurrence is not stored; the earlier position is kept).
   subroutine build(self, ids, duplicate)
      class(id_map_t), intent(inout) :: self
      integer, intent(in) :: ids(:)
      integer, intent(out) :: duplicate
      integer :: i, existing
      call self%clear(size(ids))
      duplicate = 0
      do i = 1, size(ids)
         call self%insert(ids(i), i, existing)
         if (existing /= 0 .and. duplicate == 0) duplicate = i
      end do
   end subroutine build

   !> Store `id -> value` (value >= 1). If `id` is already present, nothing changes and
   !> `existing` returns its stored value; otherwise `existing` is 0.
   subroutine insert(self, id, value, existing)
      class(id_map_t), intent(inout) :: self
      integer, intent(in) :: id, value
      integer, intent(out) :: existing
      integer :: slot
      if (.not. allocated(self%keys)) call self%clear(16)
      if (2*(self%count + 1) > 2**self%bits) call grow(self)
      slot = find_slot(self, id)
      existing = self%values(slot)
      if (existing /= 0) return
      self%keys(slot) = id
      self%values(slot) = value
      self%count = self%count + 1
   end subroutine insert

   !> Internal number of `id`, 0 if unknown.
   pure integer function lookup(self, id) result(value)
      class(id_map_t), intent(in) :: self
      integer, intent(in) :: id
      value = 0
      if (.not. allocated(self%keys)) return
      value = self%values(find_slot(self, id))
   end function lookup

   !> Number of ids stored.
   pure integer function map_size(self)
      class(id_map_t), intent(in) :: self
      map_size = self%count
   end function map_size

   !> Empty the map, with room for `expected` ids without growing.
   subroutine clear(self, expected)
      class(id_map_t), intent(inout) :: self
      integer, intent(in) :: expected
      integer :: bits
      bits = 4
      do while (2**bits < 2*max(expected, 1) .and. bits < 30)
         bits = bits + 1
      end do
      if (allocated(self%keys)) deallocate (self%keys, self%values)
      allocate (self%keys(0:2**bits - 1), self%values(0:2**bits - 1))
      self%keys = 0
      self%values = 0
      self%bits = bits
      self%count = 0
   end subroutine clear

   ! ---- private ---------------------------------------------------------------------------

   !> Slot holding `id`, or the empty slot where it would go.
   pure integer function find_slot(self, id) result(slot)
      type(id_map_t), intent(in) :: self
      integer, intent(in) :: id
      integer :: mask
      mask = 2**self%bits - 1
      slot = int(ishft(iand(int(id, i8)*knuth_multiplier, low_32_bits), -(32 - self%bits)))
      slot = iand(slot, mask)
      do
         if (self%values(slot) == 0) return
         if (self%keys(slot) == id) return
         slot = iand(slot + 1, mask)
      end do
   end function find_slot

   subroutine grow(self)
      type(id_map_t), intent(inout) :: self
      integer, allocatable :: old_keys(:), old_values(:)
      integer :: i, slot, count
      count = self%count
      call move_alloc(self%keys, old_keys)
      call move_alloc(self%values, old_values)
      call self%clear(2*count + 2)
      do i = lbound(old_keys, 1), ubound(old_keys, 1)
         if (old_values(i) == 0) cycle
         slot = find_slot(self, old_keys(i))
         self%keys(slot) = old_keys(i)
         self%values(slot) = old_values(i)
      end do
      self%count = count
   end subroutine grow
end module frix_id_map
