!> Tests of the deck reader (frix_deck_reader) and its token helpers on small decks written
!> to temporary files. Reference values are counts and values fixed by the deck text itself.
module test_deck_reader
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_testing, only: unittest_t, new_unittest, check, check_close, check_message_contains
   use frix_model, only: model_t
   use frix_element, only: kinematics_total_lagrangian
   use frix_deck_reader, only: read_deck
   use frix_deck_tokens, only: deck_line_t, split_line, parse_real, parse_integer
   implicit none
   private
   public :: collect_deck_reader

   character(len=*), parameter :: nl = new_line('a')
   !> A 2 x 1 x 1 BLOCK bar, clamped at x = 0 (in y at node 1), pulled at x = 2 (the block_tension example).
   character(len=*), parameter :: valid_deck = &
      ' title line'//nl// &
      '---------------STATIC'//nl// &
      'KINTYP Tot_Lagr MAXITER 12 // two pairs'//nl// &
      '---------------LOAD CURVES'//nl// &
      'CURVE 4 POINTS 0 0 1 0.5 2 1'//nl// &
      '---------------MATERIALS'//nl// &
      'MAT 3 MAT_Struct_LinearElastic YOUNG 1000 NUE 0 DENS 2'//nl// &
      '---------------MESH BLOCK'//nl// &
      'BLOCK bar ORIGIN 0 0 0 SIZE 2 1 1 DIVISIONS 2 1 1'//nl// &
      '---------------STRUCTURE ELEMENTS'//nl// &
      'SET bar SOLID HEX8 MAT 3 EAS 9'//nl// &
      '---------------SURFACES'//nl// &
      'SURF outside BOX -1 -1 -1 3 3 3'//nl// &
      '---------------DIRICHLET CONDITIONS'//nl// &
      'SET bar_xmin DOF 1 0 1 VAL 0 0 0.5 CURVE 0 0 4'//nl// &
      'NODE 1 DOF 0 1 0 VAL 0 0 0'//nl// &
      '---------------NEUMANN CONDITIONS'//nl// &
      'SURF bar_xmax PRESSURE -1.0 CURVE 4 FOLLOWER'//nl// &
      'NODE 3 FORCE 0 0 -2'//nl// &
      '---------------STEPS'//nl// &
      'STEP 1 NUMSTEP 2'//nl// &
      'STEP 2 NUMSTEP 3 CONTROL Displacement'//nl// &
      '---------------RESULTS'//nl// &
      'VTK No EVERY 2 HISTORY NODE 3 DOF 1 KIND R'//nl// &
      '---------------END'//nl

contains

   subroutine collect_deck_reader(tests)
      type(unittest_t), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('split_line_columns', test_split_line), &
               new_unittest('number_parsing', test_numbers), &
               new_unittest('valid_deck', test_valid_deck), &
               new_unittest('box_surfaces', test_box_surfaces), &
               new_unittest('all_errors_reported', test_all_errors), &
               new_unittest('contact_normals_default_auto', test_contact_normals)]
   end subroutine collect_deck_reader

   subroutine write_text(path, text)
      character(len=*), intent(in) :: path, text
      integer :: unit
      open (newunit=unit, file=path, status='replace', access='stream', form='unformatted')
      write (unit) text
      close (unit)
   end subroutine write_text

   subroutine test_split_line(error)
      type(error_t), allocatable, intent(out) :: error
      type(deck_line_t) :: line
      line = split_line(7, '  NODE 12,COORD'//achar(9)//'1.5 // comment 3')
      call check(error, line%n_tokens() == 4, 'four tokens before the comment')
      if (allocated(error)) return
      call check(error, all(line%first == [3, 8, 11, 17]) .and. line%token(4) == '1.5', 'token columns')
      if (allocated(error)) return
      call check(error, line%keyword(3) == 'COORD' .and. line%number == 7, 'keyword and line number')
   end subroutine test_split_line

   subroutine test_numbers(error)
      type(error_t), allocatable, intent(out) :: error
      real(dp) :: value
      integer :: integer_value
      logical :: ok
      character(len=:), allocatable :: message
      call parse_real('1.5D2', value, ok, message)
      call check(error, ok .and. value == 150.0_dp, '1.5D2 = 150')
      if (allocated(error)) return
      call parse_real('-NaN', value, ok, message)
      call check(error, .not. ok .and. message == 'not a finite number', 'NaN rejected')
      if (allocated(error)) return
      call parse_real('inf', value, ok, message)
      call check(error, .not. ok .and. message == 'not a finite number', 'Inf rejected')
      if (allocated(error)) return
      call parse_real('1e999', value, ok, message)
      call check(error, .not. ok .and. message == 'not a finite number', '1e999 rejected')
      if (allocated(error)) return
      call parse_real('1.0abc', value, ok, message)
      call check(error, .not. ok .and. message == 'expected a number', 'text rejected')
      if (allocated(error)) return
      call parse_integer('-2147483647', integer_value, ok, message)
      call check(error, ok .and. integer_value == -huge(1), '-huge(1) accepted')
      if (allocated(error)) return
      call parse_integer('2147483648', integer_value, ok, message)
      call check(error, .not. ok .and. message == 'integer out of range', 'huge(1)+1 rejected')
      if (allocated(error)) return
      call parse_integer('3.0', integer_value, ok, message)
      call check(error, .not. ok .and. message == 'expected an integer', 'a real is no integer')
   end subroutine test_numbers

   subroutine test_valid_deck(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(error_t), allocatable :: deck_error
      integer :: k
      call write_text('test_deck_valid.dck', valid_deck)
      call read_deck('test_deck_valid.dck', model, deck_error)
      if (allocated(deck_error)) then
         error = deck_error
         return
      end if
      call check(error, model%mesh%n_nodes == 12 .and. model%mesh%n_elements == 2, 'BLOCK 2x1x1: 12 nodes, 2 elements')
      if (allocated(error)) return
      call check(error, size(model%blocks) == 1 .and. all(model%mesh%element_block == 1), 'one element block')
      if (allocated(error)) return
      call check(error, model%blocks(1)%element%formulation%kinematics == kinematics_total_lagrangian, &
                 'STATIC KINTYP is the default kinematics')
      if (allocated(error)) return
      call check(error, model%controls%max_iterations == 12 .and. model%title == ' title line', 'controls and title')
      if (allocated(error)) return
      ! DOF 1 0 1: two records (x and z) on the 4 nodes of x = 0, the z one with curve 4 = index 1;
      ! then node 1 held in y (the supports check)
      call check(error, size(model%dirichlet) == 3, 'one record per flagged DOF')
      if (allocated(error)) return
      call check(error, model%dirichlet(1)%component == 1 .and. model%dirichlet(2)%component == 3 .and. &
                 model%dirichlet(2)%curve == 1 .and. model%dirichlet(1)%curve == 0 .and. &
                 size(model%dirichlet(1)%nodes) == 4, 'Dirichlet records')
      if (allocated(error)) return
      call check_close(error, model%dirichlet(2)%value, 0.5_dp, 0.0_dp, 0.0_dp, 'prescribed z value')
      if (allocated(error)) return
      call check(error, size(model%pressures) == 1 .and. model%pressures(1)%follower .and. &
                 model%pressures(1)%curve == 1, 'pressure record')
      if (allocated(error)) return
      call check(error, size(model%mesh%surfaces(model%pressures(1)%surface)%faces) == 1, 'x = 2 side has 1 face')
      if (allocated(error)) return
      ! FORCE 0 0 -2: only the non-zero component gives a record
      call check(error, size(model%nodal_forces) == 1 .and. model%nodal_forces(1)%component == 3, 'nodal force record')
      if (allocated(error)) return
      call check(error, size(model%steps) == 2 .and. model%steps(2)%n_increments == 3 .and. &
                 model%steps(2)%control == 'DISPLACEMENT', 'steps')
      if (allocated(error)) return
      k = model%results%history(1)%node
      call check(error, size(model%results%history) == 1 .and. model%mesh%node_ids(k) == 3 .and. &
                 model%results%history(1)%kind == 'R' .and. .not. model%results%vtk .and. model%results%every == 2, &
                 'results request')
      if (allocated(error)) return
      call check_close(error, model%curves(1)%factors(2), 0.5_dp, 0.0_dp, 0.0_dp, 'curve factor')
   end subroutine test_valid_deck

   !> On the 2 x 1 x 1 bar: a box around everything holds all 10 boundary faces (2 x 5 faces of
   !> two cubes minus the shared one counted from both sides); a box around the plane x = 1
   !> holds only the shared interior face, which is no boundary face: that deck is rejected.
   subroutine test_box_surfaces(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(error_t), allocatable :: deck_error
      integer :: index_middle
      call write_text('test_deck_surfaces.dck', replace(valid_deck, 'SURF outside BOX -1 -1 -1 3 3 3', &
                                                        'SURF outside BOX -1 -1 -1 3 3 3'//nl//'SURF middle BOX 0.5 -1 -1 1.5 3 3'))
      call read_deck('test_deck_surfaces.dck', model, deck_error)
      call check_message_contains(error, deck_error, 'test_deck_surfaces.dck:14:')
      if (allocated(error)) return
      call check_message_contains(error, deck_error, 'empty surface: the BOX holds no boundary face')
      if (allocated(error)) return
      call write_text('test_deck_surfaces.dck', valid_deck)
      call read_deck('test_deck_surfaces.dck', model, deck_error)
      call check(error, .not. allocated(deck_error), 'deck without the middle surface is valid')
      if (allocated(error)) return
      index_middle = model%mesh%find_surface('outside')
      call check(error, size(model%mesh%surfaces(index_middle)%faces) == 10, 'outside: 10 boundary faces')
   end subroutine test_box_surfaces

   subroutine test_all_errors(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(error_t), allocatable :: deck_error
      character(len=:), allocatable :: text
      text = replace(valid_deck, 'MAXITER 12', 'MAXITER x')
      text = replace(text, 'NUMSTEP 3', 'NUMSTEP 0')
      text = replace(text, '---------------END'//nl, '')
      call write_text('test_deck_errors.dck', text)
      call read_deck('test_deck_errors.dck', model, deck_error)
      call check_message_contains(error, deck_error, 'test_deck_errors.dck:3:25: error: expected an integer for MAXITER near "x"')
      if (allocated(error)) return
      call check_message_contains(error, deck_error, 'test_deck_errors.dck:22:16: error: NUMSTEP must be positive')
      if (allocated(error)) return
      call check_message_contains(error, deck_error, 'missing END section')
      if (allocated(error)) return
      call check(error, index(deck_error%message, ':3:') < index(deck_error%message, ':22:'), 'sorted by line')
      if (allocated(error)) return
      call check_message_contains(error, deck_error, '3 error(s) in the deck')
   end subroutine test_all_errors

   !> NORMALS of five pairs: none (Auto, 30 degrees), FEATURE_ANGLE 45 (Auto), Smoothed (180),
   !> Facet, and a rigid plane without NORMALS (its plane normal, no smoothing).
   subroutine test_contact_normals(error)
      type(error_t), allocatable, intent(out) :: error
      type(model_t) :: model
      type(error_t), allocatable :: deck_error
      character(len=:), allocatable :: text
      character(len=*), parameter :: pair = 'PAIR 1 SLAVE bar_zmin MASTER base_zmax EPSN 1e6'
      logical, parameter :: smoothed(5) = [.true., .true., .true., .false., .false.]
      real(dp), parameter :: angle(3) = [30.0_dp, 45.0_dp, 180.0_dp]
      integer :: k
      text = replace(valid_deck, 'DIVISIONS 2 1 1'//nl, 'DIVISIONS 2 1 1'//nl// &
                     'BLOCK base ORIGIN 0 0 -1 SIZE 2 1 1 DIVISIONS 2 1 1'//nl)
      text = replace(text, 'EAS 9'//nl, 'EAS 9'//nl//'SET base SOLID HEX8 MAT 3'//nl)
      text = replace(text, '---------------STEPS', '---------------CONTACT CONDITIONS'//nl//pair//nl// &
                     replace(pair, '1', '2')//' FEATURE_ANGLE 45'//nl//replace(pair, '1', '3')//' NORMALS Smoothed'//nl// &
                     replace(pair, '1', '4')//' NORMALS Facet'//nl// &
                     'PAIR 5 SLAVE bar_zmin MASTER RIGID_PLANE POINT 0 0 -5 NORMAL 0 0 1 EPSN 1e6'//nl// &
                     '---------------STEPS')
      call write_text('test_deck_normals.dck', text)
      call read_deck('test_deck_normals.dck', model, deck_error)
      if (allocated(deck_error)) then
         call move_alloc(deck_error, error)
         return
      end if
      call check(error, size(model%contact_pairs) == 5, 'five pairs')
      if (allocated(error)) return
      do k = 1, 5
         call check(error, model%contact_pairs(k)%parameters%smoothed_normals .eqv. smoothed(k), &
                    'pair '//achar(48 + k)//': smoothed normals')
         if (allocated(error)) return
      end do
      do k = 1, 3
         call check_close(error, model%contact_pairs(k)%parameters%feature_angle, angle(k), 0.0_dp, 0.0_dp, &
                          'pair '//achar(48 + k)//': feature angle')
         if (allocated(error)) return
      end do
   end subroutine test_contact_normals

   pure function replace(text, old, new) result(replaced)
      character(len=*), intent(in) :: text, old, new
      character(len=:), allocatable :: replaced
      integer :: i
      i = index(text, old)
      replaced = text
      if (i > 0) replaced = text(1:i - 1)//new//text(i + len(old):)
   end function replace
end module test_deck_reader
