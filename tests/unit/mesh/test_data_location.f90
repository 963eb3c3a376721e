!> Where the mesh tests find their data files: $FRIX_SOURCE_DIR/tests/unit/mesh/data (set by
!> ctest), else ../tests/unit/mesh/data or tests/unit/mesh/data relative to the working directory.
module test_data_location
   implicit none
   private

   public :: data_path, tests_path

contains

   !> Path of the data file `name`; if the data directory cannot be found, the bare name
   !> (the reader's "cannot open" error then says which file was missing).
   function data_path(name) result(path)
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: path
      character(len=4096) :: source_dir
      integer :: length, status
      logical :: exists
      call get_environment_variable('FRIX_SOURCE_DIR', source_dir, length, status)
      if (status == 0 .and. length > 0) then
         path = trim(source_dir)//'/tests/unit/mesh/data/'//name
         return
      end if
      inquire (file='../tests/unit/mesh/data/block.geo', exist=exists)
      if (exists) then
         path = '../tests/unit/mesh/data/'//name
         return
      end if
      path = 'tests/unit/mesh/data/'//name
   end function data_path
   !> Path of `name` relative to the tests folder (e.g. 'inp/plate2d.inp'): found as data_path's
   !> folder is.
   function tests_path(name) result(path)
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: path
      character(len=*), parameter :: data_folder = 'unit/mesh/data/'
      path = data_path('')
      path = path(1:len(path) - len(data_folder))//name
   end function tests_path
end module test_data_location
