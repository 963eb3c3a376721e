!> CONTACT CONDITIONS of a deck: one contact pair per line (docs/deck-format.md,
!> docs/contact.md); its normal contact law comes from frix_normal_contact_law_registry, its
!> friction law from frix_friction_law_registry. The reader names no law and no law property:
!> it reads the properties the registries describe and lets them validate.
module frix_deck_contact
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_strings, only: to_string, to_upper, scientific
   use frix_friction_law, only: friction_law_t
   use frix_normal_contact_law, only: normal_contact_law_t, augmentation_t
   use frix_property_list, only: property_list_t, property_spec_t, joined, spec_names, keyword_index
   use frix_friction_law_registry, only: create_pair_friction_law, friction_property_specs, default_friction_law
   use frix_normal_contact_law_registry, only: create_normal_contact_law, normal_property_specs, &
                                               default_normal_method
   use frix_contact_parameters, only: new_contact_parameters, default_feature_angle, default_penalty_factor
   use frix_contact_kernel, only: max_ring_nodes
   use frix_contact_patches, only: largest_patch_ring, all_faces_angle
   use frix_contact_pass, only: plane_edges
   use frix_model, only: model_t, contact_pair_t
   use frix_surface_stiffness, only: surface_stiffness
   use frix_deck_tokens, only: deck_line_t
   use frix_deck_context, only: deck_reader_t, require, resume_position, after_keyword, s_contact
   implicit none
   private

   public :: read_contact_pairs, set_automatic_penalties

   !> NORMALS choices (0: not given, Auto for a deformable master)
   integer, parameter :: normals_default = 0, normals_facet = 1, normals_smoothed = 2, normals_auto = 3
   character(len=8), parameter :: normals_names(3) = [character(len=8) :: 'Facet', 'Smoothed', 'Auto']

   !> The keywords of a pair's options besides the laws' properties (read_pair_option).
   character(len=14), parameter :: pair_keywords(14) = [character(len=14) :: 'POINT', 'NORMAL', 'EPST', &
      'PENALTY_FACTOR', 'GAPTOL', 'PASSES', 'METHOD', 'TMETHOD', 'PREDICT', 'STICKTOL', 'LAW', 'NORMALS', &
      'DISCRETIZATION', 'FEATURE_ANGLE']

   !> What a pair's line gives after its surfaces, as read.
   type :: pair_options_t
      logical :: rigid = .false.             !! the master is a RIGID_PLANE
      type(property_list_t) :: normal        !! the normal law's properties (EPSN)
      type(property_list_t) :: friction      !! the friction law's properties (MU)
      character(len=:), allocatable :: method   !! METHOD, '' if not given
      character(len=:), allocatable :: law      !! LAW, '' if not given
      integer :: method_token = 0            !! token of METHOD's value, 0 if not given
      integer :: law_token = 0               !! token of LAW's value, 0 if not given
      integer :: normals_token = 0           !! token of NORMALS' value
      integer :: normals = normals_default   !! normals_facet, normals_smoothed, normals_auto
      integer :: feature_token = 0           !! token of FEATURE_ANGLE's value, 0 if not given
      real(dp) :: feature_angle = default_feature_angle   !! degrees
      real(dp) :: plane_point(3) = 0.0_dp, plane_normal(3) = 0.0_dp
      real(dp) :: eps_t = 0.0_dp
      real(dp) :: penalty_factor = default_penalty_factor   !! PENALTY_FACTOR c
      integer :: factor_token = 0            !! token of PENALTY_FACTOR's value, 0 if not given
      real(dp) :: gap_tolerance = 0.0_dp
      integer :: passes = 1
      integer :: passes_token = 0            !! token of PASSES' value, 0 if not given
      logical :: mortar = .false.            !! DISCRETIZATION Mortar
      integer :: discretization_token = 0    !! token of DISCRETIZATION's value, 0 if not given
      logical :: has_eps_t = .false., has_point = .false., has_normal = .false.
      logical :: tangential_augmented = .false.   !! TMETHOD Augmented
      integer :: tmethod_token = 0           !! token of TMETHOD's value, 0 if not given
      real(dp) :: stick_tolerance = -1.0_dp  !! STICKTOL (length), < 0 if not given
      integer :: stick_token = 0             !! token of STICKTOL's value, 0 if not given
      logical :: predict = .true.            !! PREDICT Yes|No
      integer :: predict_token = 0           !! token of PREDICT's value, 0 if not given
      !> the laws' properties given (upper case) and the tokens of their values, in line order
      character(len=32), allocatable :: property_names(:)
      integer, allocatable :: property_tokens(:)
   end type pair_options_t

contains

   !> CONTACT CONDITIONS: one pair per line,
   !> `PAIR <id> SLAVE <surface> MASTER <surface>|RIGID_PLANE [POINT x y z NORMAL nx ny nz]
   !>  [METHOD Penalty] [EPSN <eps_N>] [EPST <eps_T>] [PENALTY_FACTOR <c>] [MU <mu>]
   !>  [LAW Coulomb|Frictionless] [GAPTOL <g>] [PASSES 1|2] [NORMALS Facet|Smoothed|Auto]
   !>  [FEATURE_ANGLE <degrees>] [DISCRETIZATION NodeToSegment|Mortar]`, the keywords after the surfaces in any order (a deformable
   !> master without NORMALS: Auto; without EPSN or EPST the penalty is automatic,
   !> set_automatic_penalties). The normal law's properties (EPSN) and the METHOD a pair without one gets
   !> come from the normal law registry; the friction properties (MU) and the law a pair without LAW gets from the
   !> friction registry (MU > 0: Coulomb; else frictionless, EPST not needed).
   subroutine read_contact_pairs(reader, model)
      type(deck_reader_t), intent(inout) :: reader
      type(model_t), intent(inout) :: model
      type(contact_pair_t) :: pair
      type(pair_options_t) :: options
      integer :: i, position
      logical :: ok
      allocate (model%contact_pairs(0))
      i = 0
      do while (reader%next_line(s_contact, i, position, ok))
         associate (line => reader%lines(i))
            if (line%keyword(position) == 'TIE') then
               call read_tie(reader, model, i, position, ok)
               cycle
            end if
            call read_pair_surfaces(reader, model, line, position, pair, ok)
            call read_pair_options(reader, line, position, pair%master_surface == 0, options, ok)
            if (.not. ok) cycle
            call make_pair_parameters(reader, model, line, options, pair, ok)
            if (.not. ok) cycle
            pair%line = i
            call append_pair(model%contact_pairs, pair)
         end associate
      end do
   end subroutine read_contact_pairs

   !> `TIE <id> SLAVE <surface> MASTER <surface> [TOLERANCE <d>]`: the slave nodes bonded to
   !> the master surface (frix_tie_pass; d the position tolerance, a length).
   subroutine read_tie(reader, model, i, position, ok)
      type(deck_reader_t), intent(inout) :: reader
      type(model_t), intent(inout) :: model
      integer, intent(in) :: i              !! the line's index in reader%lines
      integer, intent(inout) :: position
      logical, intent(inout) :: ok
      type(contact_pair_t) :: pair
      associate (line => reader%lines(i))
      call read_pair_surfaces(reader, model, line, position, pair, ok, 'TIE')
      if (ok .and. pair%master_surface == 0) then
         call reader%report(line, position - 1, 'a TIE needs a master surface, not a rigid plane')
         ok = .false.
      end if
      if (ok) call check_tied_once(reader, model, line, pair, ok)
      do while (ok .and. position <= line%n_tokens())
         if (line%keyword(position) /= 'TOLERANCE') then
            call reader%report(line, position, 'unknown keyword (expected TOLERANCE)')
            ok = .false.
            exit
         end if
         position = position + 1
         call reader%take_real(line, position, 'TOLERANCE', pair%tie_tolerance, ok)
         call require(reader, ok, pair%tie_tolerance >= 0.0_dp, line, position - 1, 'TOLERANCE must not be negative')
      end do
      end associate
      if (.not. ok) return
      pair%tied = .true.
      pair%line = i
      call append_pair(model%contact_pairs, pair)
   end subroutine read_tie

   !> A slave surface is tied once (a node tied to two surfaces is reported when the ties are
   !> set up, frix_tie_constraints).
   subroutine check_tied_once(reader, model, line, pair, ok)
      type(deck_reader_t), intent(inout) :: reader
      type(model_t), intent(in) :: model
      type(deck_line_t), intent(in) :: line
      type(contact_pair_t), intent(in) :: pair
      logical, intent(inout) :: ok
      integer :: k
      do k = 1, size(model%contact_pairs)
         if (.not. model%contact_pairs(k)%tied) cycle
         if (model%contact_pairs(k)%slave_surface /= pair%slave_surface) cycle
         call reader%report(line, 4, 'this slave surface is already tied (TIE '// &
                            to_string(model%contact_pairs(k)%id)//')')
         ok = .false.
         return
      end do
   end subroutine check_tied_once

   !> `PAIR <id> SLAVE <surface> MASTER <surface>|RIGID_PLANE` (or `TIE ...`): the id (new) and the surfaces.
   subroutine read_pair_surfaces(reader, model, line, position, pair, ok, head)
      type(deck_reader_t), intent(inout) :: reader
      type(model_t), intent(in) :: model
      type(deck_line_t), intent(in) :: line
      integer, intent(inout) :: position
      type(contact_pair_t), intent(inout) :: pair
      logical, intent(inout) :: ok
      character(len=*), intent(in), optional :: head   !! the line's first keyword (default PAIR)
      character(len=:), allocatable :: name, what
      integer :: k, slave_position
      what = 'contact'   ! what a surface of other faces than HEX8's cannot carry yet
      if (present(head)) then
         call reader%expect_keyword(line, position, head, ok)
         if (head == 'TIE') what = 'TIE'
      else
         call reader%expect_keyword(line, position, 'PAIR', ok)
      end if
      call reader%take_integer(line, position, 'a pair id', pair%id, ok)
      if (.not. ok) return
      do k = 1, size(model%contact_pairs)
         if (model%contact_pairs(k)%id == pair%id) then
            call reader%report(line, 2, 'duplicate contact pair id')
            ok = .false.
         end if
      end do
      call reader%expect_keyword(line, position, 'SLAVE', ok)
      call reader%take_word(line, position, 'a slave surface name', name, ok)
      if (ok) then
         pair%slave_surface = model%mesh%find_surface(name)
         if (pair%slave_surface == 0) then
            if (.not. reader%mesh_failed) call reader%report(line, position - 1, 'unknown surface')
            ok = .false.
         end if
      end if
      slave_position = position - 1
      call reader%expect_keyword(line, position, 'MASTER', ok)
      call reader%take_word(line, position, 'a master surface name or RIGID_PLANE', name, ok)
      pair%master_surface = 0
      if (ok .and. to_upper(name) /= 'RIGID_PLANE') then
         pair%master_surface = model%mesh%find_surface(name)
         if (pair%master_surface == 0) then
            if (.not. reader%mesh_failed) call reader%report(line, position - 1, 'unknown surface')
            ok = .false.
         else if (pair%master_surface == pair%slave_surface) then
            call reader%report(line, position - 1, 'a surface cannot be in contact with itself')
            ok = .false.
         else
            call check_plane_pair(reader, model, line, position - 1, pair, what, ok)
            if (ok .and. .not. plane_surface(model, pair%master_surface)) &
               call reader%require_hex8_faces(line, position - 1, model%mesh, pair%master_surface, what, ok)
         end if
      end if
      ! the edges of plane elements against a rigid line (RIGID_PLANE with a normal in the x-y
      ! plane) or against the edges of plane elements (node-to-segment: frix_contact_pass);
      ! a TIE between them is reported by check_plane_pair
      if (pair%slave_surface /= 0) then
         if (.not. plane_surface(model, pair%slave_surface)) &
            call reader%require_hex8_faces(line, slave_position, model%mesh, pair%slave_surface, what, ok)
      end if
   end subroutine read_pair_surfaces

   !> A TIE whose master surface (its name at token `column`) holds edges of plane elements:
   !> not supported yet. (A model's elements are all plane or all solids: a pair's surfaces
   !> are of one kind.)
   subroutine check_plane_pair(reader, model, line, column, pair, what, ok)
      type(deck_reader_t), intent(inout) :: reader
      type(model_t), intent(in) :: model
      type(deck_line_t), intent(in) :: line
      integer, intent(in) :: column
      type(contact_pair_t), intent(in) :: pair
      character(len=*), intent(in) :: what
      logical, intent(inout) :: ok
      if (.not. ok .or. what /= 'TIE') return
      if (.not. plane_surface(model, pair%master_surface)) return
      call reader%report(line, column, 'TIE between plane bodies is not supported yet (surface "'// &
                         model%mesh%surfaces(pair%master_surface)%name//'" holds edges of plane elements): '// &
                         'use a contact PAIR')
      ok = .false.
   end subroutine check_plane_pair

   !> Whether the faces of surface `surface` are edges of plane elements.
   logical function plane_surface(model, surface)
      type(model_t), intent(in) :: model
      integer, intent(in) :: surface
      plane_surface = plane_edges(model%mesh, model%mesh%surfaces(surface))
   end function plane_surface

   !> The keywords after the surfaces, in any order: the rigid plane, the laws, their
   !> properties (as the registries describe them), GAPTOL, PASSES, NORMALS, FEATURE_ANGLE.
   !> After a mistake (also one in the surfaces, `ok` false on entry) the line is read on from
   !> its next keyword, so that every mistake of the line is reported.
   subroutine read_pair_options(reader, line, position, rigid, options, ok)
      type(deck_reader_t), intent(inout) :: reader
      type(deck_line_t), intent(in) :: line
      integer, intent(inout) :: position
      logical, intent(in) :: rigid   !! the master is a RIGID_PLANE
      type(pair_options_t), intent(out) :: options
      logical, intent(inout) :: ok
      type(property_spec_t), allocatable :: normal_specs(:), friction_specs(:)
      character(len=32), allocatable :: keywords(:)
      integer :: start
      logical :: line_ok
      normal_specs = normal_property_specs()
      friction_specs = friction_property_specs()
      keywords = [character(len=32) :: pair_keywords, spec_names(normal_specs), spec_names(friction_specs)]
      options%rigid = rigid
      options%method = ''
      options%law = ''
      allocate (options%property_names(0), options%property_tokens(0))
      line_ok = ok
      if (.not. ok) position = resume_position(line, position, keywords)
      do while (position <= line%n_tokens())
         start = position
         ok = .true.
         call read_pair_option(reader, line, position, normal_specs, friction_specs, options, ok)
         call after_keyword(line, start, keywords, position, ok, line_ok)
      end do
      ok = line_ok
   end subroutine read_pair_options

   !> One keyword of a pair's options at `position`, with its value(s), into `options`.
   subroutine read_pair_option(reader, line, position, normal_specs, friction_specs, options, ok)
      type(deck_reader_t), intent(inout) :: reader
      type(deck_line_t), intent(in) :: line
      integer, intent(inout) :: position
      type(property_spec_t), intent(in) :: normal_specs(:), friction_specs(:)
      type(pair_options_t), intent(inout) :: options
      logical, intent(inout) :: ok
      character(len=:), allocatable :: word
      integer :: k
      word = line%keyword(position)
      position = position + 1
      select case (word)
      case ('POINT')
         call reader%take_reals(line, position, 'a coordinate', options%plane_point, ok)
         options%has_point = ok
      case ('NORMAL')
         call reader%take_reals(line, position, 'a normal component', options%plane_normal, ok)
         options%has_normal = ok
      case ('EPST')
         call reader%take_real(line, position, 'EPST', options%eps_t, ok)
         call require(reader, ok, options%eps_t > 0.0_dp, line, position - 1, 'EPST must be positive')
         options%has_eps_t = ok
      case ('PENALTY_FACTOR')
         options%factor_token = position
         call reader%take_real(line, position, 'PENALTY_FACTOR', options%penalty_factor, ok)
         call require(reader, ok, options%penalty_factor > 0.0_dp, line, position - 1, &
                      'PENALTY_FACTOR must be positive')
      case ('GAPTOL')
         call reader%take_real(line, position, 'GAPTOL', options%gap_tolerance, ok)
         call require(reader, ok, options%gap_tolerance >= 0.0_dp, line, position - 1, &
                      'GAPTOL must not be negative')
      case ('PASSES')
         options%passes_token = position
         call reader%take_integer(line, position, 'PASSES', options%passes, ok)
         call require(reader, ok, options%passes == 1 .or. options%passes == 2, line, position - 1, &
                      'PASSES must be 1 or 2')
      case ('METHOD')
         options%method_token = position
         call reader%take_word(line, position, 'a normal contact method', options%method, ok)
      case ('TMETHOD')
         call read_tangential_method(reader, line, position, options, ok)
      case ('PREDICT')
         options%predict_token = position
         call reader%take_yes_no(line, position, 'PREDICT', options%predict, ok)
      case ('STICKTOL')
         options%stick_token = position
         call reader%take_real(line, position, 'STICKTOL', options%stick_tolerance, ok)
         call require(reader, ok, options%stick_tolerance > 0.0_dp, line, position - 1, 'STICKTOL must be positive')
      case ('LAW')
         options%law_token = position
         call reader%take_word(line, position, 'a friction law', options%law, ok)
      case ('NORMALS')
         call read_normals(reader, line, position, options, ok)
      case ('DISCRETIZATION')
         call read_discretization(reader, line, position, options, ok)
      case ('FEATURE_ANGLE')
         options%feature_token = position
         call reader%take_real(line, position, 'FEATURE_ANGLE', options%feature_angle, ok)
         call require(reader, ok, options%feature_angle > 0.0_dp .and. options%feature_angle < 180.0_dp, &
                      line, position - 1, 'FEATURE_ANGLE must lie between 0 and 180 degrees (exclusive)')
      case default
         options%property_names = [character(len=32) :: options%property_names, word]
         options%property_tokens = [options%property_tokens, position]
         k = keyword_index(spec_names(normal_specs), word)
         if (k > 0) then
            call reader%take_property(line, position, normal_specs(k), options%normal, ok)
            return
         end if
         k = keyword_index(spec_names(friction_specs), word)
         if (k > 0) then
            call reader%take_property(line, position, friction_specs(k), options%friction, ok)
            return
         end if
         call reader%report(line, position - 1, 'unknown keyword (expected POINT, NORMAL, '// &
                            joined(spec_names(normal_specs))//', EPST, PENALTY_FACTOR, '// &
                            joined(spec_names(friction_specs))// &
                            ', METHOD, TMETHOD, STICKTOL, PREDICT, LAW, GAPTOL, PASSES, NORMALS, FEATURE_ANGLE '// &
                            'or DISCRETIZATION)')
         ok = .false.
      end select
   end subroutine read_pair_option

   !> `DISCRETIZATION NodeToSegment|Mortar` (after DISCRETIZATION): node-to-segment contact
   !> (the default) or mortar contact (frix_mortar_contact).
   subroutine read_discretization(reader, line, position, options, ok)
      type(deck_reader_t), intent(inout) :: reader
      type(deck_line_t), intent(in) :: line
      integer, intent(inout) :: position
      type(pair_options_t), intent(inout) :: options
      logical, intent(inout) :: ok
      integer :: choice
      options%discretization_token = position
      call reader%take_choice(line, position, 'NodeToSegment or Mortar', &
                              [character(len=13) :: 'NODETOSEGMENT', 'MORTAR'], &
                              'DISCRETIZATION must be NodeToSegment or Mortar', choice, ok)
      options%mortar = choice == 2
   end subroutine read_discretization

   !> DISCRETIZATION Mortar supports one pass against a deformable master with METHOD Penalty
   !> (with or without friction), and has no choice of normals (the slave surface's averaged nodal
   !> normals): anything else is reported at its keyword or value.
   subroutine check_mortar(reader, model, line, options, pair, ok)
      type(deck_reader_t), intent(inout) :: reader
      type(model_t), intent(in) :: model
      type(deck_line_t), intent(in) :: line
      type(pair_options_t), intent(in) :: options
      type(contact_pair_t), intent(in) :: pair
      logical, intent(inout) :: ok
      character(len=*), parameter :: what = 'DISCRETIZATION Mortar '
      if (.not. (ok .and. options%mortar)) return
      if (options%rigid) then
         call reader%report(line, 6, what//'needs a deformable master surface, not a RIGID_PLANE')
      else if (plane_surface(model, pair%master_surface)) then
         call reader%report(line, options%discretization_token, what//'between plane bodies is not supported '// &
                            'yet (surface "'//model%mesh%surfaces(pair%master_surface)%name//'" holds edges of '// &
                            'plane elements): use DISCRETIZATION NodeToSegment')
      else if (options%passes == 2) then
         call reader%report(line, options%passes_token, what//'has one pass: PASSES 2 is node-to-segment''s')
      else if (pair%parameters%normal%name /= 'PENALTY') then
         call reader%report(line, options%method_token, what//'supports METHOD Penalty only, not METHOD '// &
                            options%method)
      else if (options%normals_token > 0) then
         call reader%report(line, options%normals_token - 1, what//'takes no NORMALS (it uses the slave '// &
                            'surface''s averaged nodal normals)')
      else if (options%feature_token > 0) then
         call reader%report(line, options%feature_token - 1, what//'takes no FEATURE_ANGLE (it uses the slave '// &
                            'surface''s averaged nodal normals)')
      else
         return
      end if
      ok = .false.
   end subroutine check_mortar

   !> `TMETHOD Penalty|Augmented` (after TMETHOD): how the stick traction is enforced.
   subroutine read_tangential_method(reader, line, position, options, ok)
      type(deck_reader_t), intent(inout) :: reader
      type(deck_line_t), intent(in) :: line
      integer, intent(inout) :: position
      type(pair_options_t), intent(inout) :: options
      logical, intent(inout) :: ok
      integer :: choice
      options%tmethod_token = position
      call reader%take_choice(line, position, 'Penalty or Augmented', [character(len=9) :: 'PENALTY', 'AUGMENTED'], &
                              'TMETHOD must be Penalty or Augmented', choice, ok)
      options%tangential_augmented = choice == 2
   end subroutine read_tangential_method

   !> Augmented friction (TMETHOD Augmented, STICKTOL) needs friction and an augmented normal
   !> law (the augmentations are driven by the pair's MAXAUG); STICKTOL belongs to it. PREDICT
   !> needs an augmented normal law.
   subroutine set_tangential_method(reader, line, options, pair, ok)
      type(deck_reader_t), intent(inout) :: reader
      type(deck_line_t), intent(in) :: line
      type(pair_options_t), intent(in) :: options
      type(contact_pair_t), intent(inout) :: pair
      logical, intent(inout) :: ok
      type(augmentation_t) :: settings
      settings = pair%parameters%normal%augmentation()
      if (options%predict_token > 0) &
         call require(reader, ok, settings%augmented, line, options%predict_token - 1, &
                      'PREDICT belongs to METHOD Augmented')
      pair%parameters%predict = options%predict
      if (options%stick_token > 0) &
         call require(reader, ok, options%tangential_augmented, line, options%stick_token - 1, &
                      'STICKTOL belongs to TMETHOD Augmented')
      if (.not. (ok .and. options%tangential_augmented)) return
      call require(reader, ok, settings%augmented, line, options%tmethod_token, &
                   'TMETHOD Augmented needs METHOD Augmented')
      call require(reader, ok, .not. pair%parameters%friction%frictionless(), line, options%tmethod_token, &
                   'TMETHOD Augmented needs friction (MU > 0)')
      pair%parameters%tangential_augmented = ok
      pair%parameters%stick_tolerance = options%stick_tolerance
   end subroutine set_tangential_method

   !> `NORMALS Facet|Smoothed|Auto` (after NORMALS); Smoothed and Auto need a deformable master.
   subroutine read_normals(reader, line, position, options, ok)
      type(deck_reader_t), intent(inout) :: reader
      type(deck_line_t), intent(in) :: line
      integer, intent(inout) :: position
      type(pair_options_t), intent(inout) :: options
      logical, intent(inout) :: ok
      options%normals_token = position
      call reader%take_choice(line, position, 'Facet, Smoothed or Auto', &
                              [character(len=8) :: 'FACET', 'SMOOTHED', 'AUTO'], &
                              'NORMALS must be Facet, Smoothed or Auto', options%normals, ok)
      if (ok .and. options%normals /= normals_facet .and. options%rigid) then
         call reader%report(line, position - 1, 'NORMALS '//trim(normals_names(options%normals))// &
                            ' needs a deformable master surface')
         ok = .false.
      end if
   end subroutine read_normals

   !> FEATURE_ANGLE belongs to NORMALS Auto (given or the default of a deformable master).
   subroutine check_feature_angle(reader, line, options, ok)
      type(deck_reader_t), intent(inout) :: reader
      type(deck_line_t), intent(in) :: line
      type(pair_options_t), intent(in) :: options
      logical, intent(inout) :: ok
      if (options%feature_token == 0 .or. .not. ok) return
      if (options%rigid) then
         call reader%report(line, options%feature_token - 1, 'FEATURE_ANGLE needs a deformable master surface')
         ok = .false.
      else if (options%normals == normals_facet .or. options%normals == normals_smoothed) then
         call reader%report(line, options%feature_token - 1, 'FEATURE_ANGLE belongs to NORMALS Auto, not NORMALS '// &
                            trim(normals_names(options%normals)))
         ok = .false.
      end if
   end subroutine check_feature_angle

   !> The pair's laws, parameters, plane and passes from its options, in this order: the normal
   !> law, the rigid plane, the friction law, the parameters (EPST), PENALTY_FACTOR, the
   !> smoothed normals' patches. The first mistake is reported; ok false then.
   subroutine make_pair_parameters(reader, model, line, options, pair, ok)
      type(deck_reader_t), intent(inout) :: reader
      type(model_t), intent(in) :: model
      type(deck_line_t), intent(in) :: line
      type(pair_options_t), intent(in) :: options
      type(contact_pair_t), intent(inout) :: pair
      logical, intent(inout) :: ok
      class(normal_contact_law_t), allocatable :: normal
      class(friction_law_t), allocatable :: friction
      type(error_t), allocatable :: error
      character(len=:), allocatable :: method, law
      integer :: token
      call check_feature_angle(reader, line, options, ok)
      if (.not. ok) return
      pair%passes = options%passes
      pair%plane_point = options%plane_point
      pair%plane_normal = options%plane_normal
      method = options%method
      if (len(method) == 0) method = default_normal_method()
      call create_normal_contact_law(method, options%normal, normal, error)
      if (allocated(error)) token = property_token(options, error%message, max(1, options%method_token))
      call report_error(reader, line, token, error, ok)
      if (ok) call check_rigid_plane(reader, line, options, pair, ok)
      if (.not. ok) return
      law = options%law
      if (len(law) == 0) law = default_friction_law(options%friction)
      call create_pair_friction_law(trim(law), options%friction, friction, error)
      if (allocated(error)) token = property_token(options, error%message, max(1, options%law_token))
      call report_error(reader, line, token, error, ok)
      if (.not. ok) return
      call new_contact_parameters(normal, options%eps_t, options%gap_tolerance, friction, pair%parameters, error, &
                                  automatic_tangential=.not. options%has_eps_t)
      call report_error(reader, line, 1, error, ok)
      if (ok .and. options%factor_token > 0) &
         call require(reader, ok, pair%parameters%normal%automatic_penalty, line, options%factor_token - 1, &
                      'PENALTY_FACTOR belongs to an automatic EPSN (a pair without EPSN)')
      if (ok) call set_tangential_method(reader, line, options, pair, ok)
      pair%penalty_factor = options%penalty_factor
      call check_mortar(reader, model, line, options, pair, ok)
      pair%mortar = options%mortar
      if (ok .and. .not. pair%mortar) call set_normals(reader, model, line, options, pair, ok)
   end subroutine make_pair_parameters

   !> The pair's normal field: Facet; Smoothed (feature angle 180 degrees: every adjacent face);
   !> Auto, the default of a deformable master (the feature angle given or the default), each
   !> checked against the kernel's ring size on the master surface (and on the slave surface,
   !> master of the second pass, with PASSES 2).
   subroutine set_normals(reader, model, line, options, pair, ok)
      type(deck_reader_t), intent(inout) :: reader
      type(model_t), intent(in) :: model
      type(deck_line_t), intent(in) :: line
      type(pair_options_t), intent(in) :: options
      type(contact_pair_t), intent(inout) :: pair
      logical, intent(inout) :: ok
      integer :: normals, token
      normals = options%normals
      if (normals == normals_default .and. .not. options%rigid) normals = normals_auto
      pair%parameters%smoothed_normals = normals == normals_smoothed .or. normals == normals_auto
      if (.not. pair%parameters%smoothed_normals) return
      pair%parameters%feature_angle = all_faces_angle
      if (normals == normals_auto) pair%parameters%feature_angle = options%feature_angle
      token = max(1, options%normals_token)
      call check_patch_ring(reader, model, line, token, normals, pair%parameters%feature_angle, &
                            pair%master_surface, options%normals == normals_default, ok)
      if (pair%passes == 2) &
         call check_patch_ring(reader, model, line, token, normals, pair%parameters%feature_angle, &
                               pair%slave_surface, options%normals == normals_default, ok)
   end subroutine set_normals

   !> The token a law's message is about: the value of the property of the line the message
   !> names first (as a word: "PENRATE must be ...", "unknown property "PENTOL" (valid: EPSN)"),
   !> else `fallback` (METHOD's or LAW's value: an unknown law, a missing property).
   pure integer function property_token(options, message, fallback) result(token)
      type(pair_options_t), intent(in) :: options
      character(len=*), intent(in) :: message
      integer, intent(in) :: fallback
      integer :: k, at, last, first_at
      token = fallback
      first_at = len(message) + 1
      do k = 1, size(options%property_names)
         at = index(message, trim(options%property_names(k)))
         if (at == 0 .or. at >= first_at) cycle
         last = at + len_trim(options%property_names(k)) - 1
         if (at > 1) then
            if (word_character(message(at - 1:at - 1))) cycle
         end if
         if (last < len(message)) then
            if (word_character(message(last + 1:last + 1))) cycle
         end if
         token = options%property_tokens(k)
         first_at = at
      end do
      ! a property the law does not take: its keyword, not its value
      if (token /= fallback .and. index(message, 'unknown property') > 0) token = token - 1
   contains
      pure logical function word_character(c)
         character(len=1), intent(in) :: c
         word_character = verify(c, 'ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_') == 0
      end function word_character
   end function property_token

   !> Report `error`, if allocated, at token `position` (ok false then).
   subroutine report_error(reader, line, position, error, ok)
      type(deck_reader_t), intent(inout) :: reader
      type(deck_line_t), intent(in) :: line
      integer, intent(in) :: position
      type(error_t), allocatable, intent(inout) :: error
      logical, intent(inout) :: ok
      if (.not. allocated(error)) return
      call reader%report(line, position, error%message)
      deallocate (error)
      ok = .false.
   end subroutine report_error

   !> A RIGID_PLANE master needs POINT and NORMAL (normalised here) and one pass; a surface
   !> master takes neither.
   subroutine check_rigid_plane(reader, line, options, pair, ok)
      type(deck_reader_t), intent(inout) :: reader
      type(deck_line_t), intent(in) :: line
      type(pair_options_t), intent(in) :: options
      type(contact_pair_t), intent(inout) :: pair
      logical, intent(inout) :: ok
      real(dp) :: length
      if (.not. options%rigid) then
         call require(reader, ok, .not. (options%has_point .or. options%has_normal), line, 1, &
                      'POINT and NORMAL belong to a RIGID_PLANE master')
         return
      end if
      call require(reader, ok, options%has_point .and. options%has_normal, line, 1, &
                   'a RIGID_PLANE master needs POINT x y z and NORMAL nx ny nz')
      length = norm2(pair%plane_normal)
      call require(reader, ok, length /= 0.0_dp, line, 1, 'the rigid plane''s NORMAL is zero')
      if (ok) pair%plane_normal = pair%plane_normal/length
      call require(reader, ok, pair%passes /= 2, line, 1, 'PASSES 2 needs a deformable master surface')
   end subroutine check_rigid_plane

   !> NORMALS Smoothed or Auto (its value at token `token`, `default` when not given): the
   !> kernel's unknowns bound the nodes around a face of the master surface within the feature
   !> angle (docs/contact.md, "Normals").
   subroutine check_patch_ring(reader, model, line, token, normals, feature_angle, master_surface, default, ok)
      type(deck_reader_t), intent(inout) :: reader
      type(model_t), intent(in) :: model
      type(deck_line_t), intent(in) :: line
      integer, intent(in) :: token, normals, master_surface
      real(dp), intent(in) :: feature_angle   !! degrees
      logical, intent(in) :: default
      logical, intent(inout) :: ok
      character(len=:), allocatable :: what
      integer :: n_ring, face_nodes(4)
      if (.not. ok) return
      ! an edge of a plane body: its patch's ring is the 2 corners of each other edge at its
      ! two nodes, within max_ring_nodes unless more than 6 such edges meet there (then the
      ! contact setup reports it: check_patch_rings)
      if (plane_surface(model, master_surface)) return
      call largest_patch_ring(model%mesh, model%mesh%surfaces(master_surface), feature_angle, n_ring, face_nodes)
      if (n_ring <= max_ring_nodes) return
      what = 'NORMALS '//trim(normals_names(normals))
      if (default) what = what//' (the default; NORMALS Facet has no such limit)'
      call reader%report(line, token, what//': the master face of nodes '// &
                         to_string(model%mesh%node_ids(face_nodes(1)))//' '// &
                         to_string(model%mesh%node_ids(face_nodes(2)))//' '// &
                         to_string(model%mesh%node_ids(face_nodes(3)))//' '// &
                         to_string(model%mesh%node_ids(face_nodes(4)))//' has '// &
                         to_string(n_ring)//' nodes around it, at most '// &
                         to_string(max_ring_nodes)//' are supported (4 faces at each of its nodes)')
      ok = .false.
   end subroutine check_patch_ring

   !> The automatic penalties of the contact pairs without EPSN or (with friction) EPST, once the
   !> model is complete (mesh, materials, element blocks; docs/contact.md, "Choosing the
   !> penalties"):
   !>   eps_N = c min(S_slave, S_master),  S = mean over the surface's faces of M/h
   !> (frix_surface_stiffness; a rigid plane has no S_master), c = PENALTY_FACTOR (default
   !> 10); eps_T = eps_N (given or automatic) or, for a normal law without a penalty, the same
   !> c min(S_slave, S_master). Each such pair gets its penalty_note.
   subroutine set_automatic_penalties(reader, model)
      type(deck_reader_t), intent(inout) :: reader
      type(model_t), intent(inout) :: model
      integer :: p
      do p = 1, size(model%contact_pairs)
         associate (pair => model%contact_pairs(p))
            if (pair%tied) cycle
            if (.not. (pair%parameters%normal%automatic_penalty .or. &
                       pair%parameters%automatic_tangential_penalty)) cycle
            call set_pair_penalties(reader, model, pair)
         end associate
      end do
   end subroutine set_automatic_penalties

   !> One pair's automatic eps_N and eps_T and their note (set_automatic_penalties).
   subroutine set_pair_penalties(reader, model, pair)
      type(deck_reader_t), intent(inout) :: reader
      type(model_t), intent(in) :: model
      type(contact_pair_t), intent(inout) :: pair
      real(dp) :: stiffness, eps_n
      integer :: softer
      character(len=:), allocatable :: derived, note
      call softer_surface(model, pair, softer, stiffness)
      if (.not. (stiffness > 0.0_dp .and. pair%penalty_factor*stiffness < huge(1.0_dp))) then
         call reader%report(reader%lines(pair%line), 1, 'cannot derive the automatic penalty: M/h of surface '// &
                            model%mesh%surfaces(softer)%name//' is '//to_string(stiffness)//'; give EPSN and EPST')
         return
      end if
      derived = '(automatic: '//factor_text(pair%penalty_factor)//' x '//penalty_text(stiffness)// &
                ' = M/h of surface '//model%mesh%surfaces(softer)%name//')'
      associate (normal => pair%parameters%normal)
         if (normal%automatic_penalty) call normal%set_penalty(pair%penalty_factor*stiffness)
         eps_n = normal%penalty()
         if (normal%automatic_penalty) then
            note = 'EPSN '//penalty_text(eps_n)//' '//derived
         else if (eps_n > 0.0_dp) then
            note = 'EPSN '//penalty_text(eps_n)//' (given)'
         else
            note = 'METHOD '//normal%name
         end if
      end associate
      if (pair%parameters%automatic_tangential_penalty) then
         if (eps_n > 0.0_dp) then
            pair%parameters%tangential_penalty = eps_n
            note = note//', EPST '//penalty_text(eps_n)//' (automatic: = EPSN)'
         else
            pair%parameters%tangential_penalty = pair%penalty_factor*stiffness
            note = note//', EPST '//penalty_text(pair%parameters%tangential_penalty)//' '//derived
         end if
      else if (.not. pair%parameters%friction%frictionless()) then
         note = note//', EPST '//penalty_text(pair%parameters%tangential_penalty)//' (given)'
      end if
      pair%penalty_note = note
   end subroutine set_pair_penalties

   !> The softer of the pair's deformable surfaces (the slave's, and the master's unless it is a
   !> rigid plane): its index and its mean M/h (ties: the slave).
   subroutine softer_surface(model, pair, surface, stiffness)
      type(model_t), intent(in) :: model
      type(contact_pair_t), intent(in) :: pair
      integer, intent(out) :: surface
      real(dp), intent(out) :: stiffness   !! mean M/h (force/area/length)
      real(dp) :: master
      surface = pair%slave_surface
      stiffness = surface_stiffness(model, surface)
      if (pair%master_surface == 0) return
      master = surface_stiffness(model, pair%master_surface)
      if (master < stiffness) then
         surface = pair%master_surface
         stiffness = master
      end if
   end subroutine softer_surface

   !> PENALTY_FACTOR for messages: a whole number as such (10), else as penalty_text.
   pure function factor_text(value) result(text)
      real(dp), intent(in) :: value
      character(len=:), allocatable :: text
      if (value == aint(value) .and. value < 1.0e6_dp) then
         text = to_string(nint(value))
      else
         text = penalty_text(value)
      end if
   end function factor_text

   !> A penalty or stiffness for messages: 5 significant digits, e.g. 2.6923E+04 (1.0000E-300
   !> beyond two exponent digits).
   pure function penalty_text(value) result(text)
      real(dp), intent(in) :: value
      character(len=:), allocatable :: text
      text = scientific(value, 4)
   end function penalty_text

   !> `pairs` with `pair` appended, in a longer array (an array constructor would leak the
   !> laws' allocatable components with gfortran 12, docs/testing.md).
   subroutine append_pair(pairs, pair)
      type(contact_pair_t), allocatable, intent(inout) :: pairs(:)
      type(contact_pair_t), intent(in) :: pair
      type(contact_pair_t), allocatable :: grown(:)
      integer :: k
      allocate (grown(size(pairs) + 1))
      do k = 1, size(pairs)
         grown(k) = pairs(k)
      end do
      grown(size(grown)) = pair
      call move_alloc(grown, pairs)
   end subroutine append_pair
end module frix_deck_contact
