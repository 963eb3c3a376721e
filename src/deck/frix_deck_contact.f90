!> CONTACT CONDITIONS of a deck: one contact pair per line (docs/deck-format.md,
!> docs/contact.md); its friction law comes from frix_friction_law_registry.
module frix_deck_contact
   use frix_kinds, only: dp
   use frix_error, only: error_t
   use frix_strings, only: to_string, to_upper
   use frix_friction_law, only: friction_law_t
   use frix_property_list, only: property_list_t, property_spec_t, joined, spec_names, keyword_index
   use frix_friction_law_registry, only: create_pair_friction_law, friction_property_specs, default_friction_law
   use frix_contact_parameters, only: new_contact_parameters
   use frix_contact_kernel, only: max_ring_nodes
   use frix_contact_assembly, only: largest_patch_ring
   use frix_model, only: model_t, contact_pair_t
   use frix_deck_context, only: deck_reader_t, require, s_contact
   implicit none
   private

   public :: read_contact_pairs

contains

   !> CONTACT CONDITIONS: one pair per line,
   !> `PAIR <id> SLAVE <surface> MASTER <surface>|RIGID_PLANE [POINT x y z NORMAL nx ny nz]
   !>  EPSN <eps_N> [EPST <eps_T>] [MU <mu>] [LAW Coulomb|Frictionless] [GAPTOL <g>] [PASSES 1|2]
   !>  [NORMALS Facet|Smoothed]`.
   !> The friction properties (MU) and the law a pair without LAW gets come from the friction
   !> registry (MU > 0: Coulomb; else frictionless, EPST not needed).
   subroutine read_contact_pairs(reader, model)
      type(deck_reader_t), intent(inout) :: reader
      type(model_t), intent(inout) :: model
      type(contact_pair_t) :: pair
      class(friction_law_t), allocatable :: law
      type(error_t), allocatable :: law_error
      character(len=:), allocatable :: name, word, law_keyword
      type(property_spec_t), allocatable :: friction_specs(:)
      type(property_list_t) :: friction
      real(dp) :: eps_n, eps_t, gap_tolerance, length
      integer :: i, position, k, law_token, passes, normals_token, normals_choice, n_ring, face_nodes(4)
      logical :: ok, has_eps_n, has_eps_t, has_point, has_normal, smoothed
      friction_specs = friction_property_specs()
      allocate (model%contact_pairs(0))
      do i = reader%first(s_contact), reader%last(s_contact)
         associate (line => reader%lines(i))
            if (line%n_tokens() == 0) cycle
            ok = .true.
            position = 1
            call reader%expect_keyword(line, position, 'PAIR', ok)
            call reader%take_integer(line, position, 'a pair id', pair%id, ok)
            if (.not. ok) cycle
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
               end if
            end if
            has_eps_n = .false.; has_eps_t = .false.
            has_point = .false.; has_normal = .false.
            eps_n = 0.0_dp; eps_t = 0.0_dp; gap_tolerance = 0.0_dp
            friction = property_list_t()
            passes = 1
            smoothed = .false.
            law_keyword = ''
            law_token = 0
            pair%plane_point = 0.0_dp
            pair%plane_normal = 0.0_dp
            do while (ok .and. position <= line%n_tokens())
               word = line%keyword(position)
               position = position + 1
               select case (word)
               case ('POINT')
                  call reader%take_reals(line, position, 'a coordinate', pair%plane_point, ok)
                  has_point = ok
               case ('NORMAL')
                  call reader%take_reals(line, position, 'a normal component', pair%plane_normal, ok)
                  has_normal = ok
               case ('EPSN')
                  call reader%take_real(line, position, 'EPSN', eps_n, ok)
                  call require(reader, ok, eps_n > 0.0_dp, line, position - 1, 'EPSN must be positive')
                  has_eps_n = ok
               case ('EPST')
                  call reader%take_real(line, position, 'EPST', eps_t, ok)
                  call require(reader, ok, eps_t > 0.0_dp, line, position - 1, 'EPST must be positive')
                  has_eps_t = ok
               case ('GAPTOL')
                  call reader%take_real(line, position, 'GAPTOL', gap_tolerance, ok)
                  call require(reader, ok, gap_tolerance >= 0.0_dp, line, position - 1, &
                               'GAPTOL must not be negative')
               case ('PASSES')
                  call reader%take_integer(line, position, 'PASSES', passes, ok)
                  call require(reader, ok, passes == 1 .or. passes == 2, line, position - 1, &
                               'PASSES must be 1 or 2')
               case ('LAW')
                  law_token = position
                  call reader%take_word(line, position, 'a friction law', law_keyword, ok)
               case ('NORMALS')
                  normals_token = position
                  call reader%take_choice(line, position, 'Facet or Smoothed', &
                                          [character(len=8) :: 'FACET', 'SMOOTHED'], &
                                          'NORMALS must be Facet or Smoothed', normals_choice, ok)
                  smoothed = normals_choice == 2
                  if (ok .and. smoothed .and. pair%master_surface == 0) then
                     call reader%report(line, position - 1, 'NORMALS Smoothed needs a deformable master surface')
                     ok = .false.
                  end if
               case default
                  k = keyword_index(spec_names(friction_specs), word)
                  if (k > 0) then
                     call reader%take_property(line, position, friction_specs(k), friction, ok)
                  else
                     call reader%report(line, position - 1, 'unknown keyword (expected POINT, NORMAL, '// &
                                        'EPSN, EPST, '//joined(spec_names(friction_specs))// &
                                        ', LAW, GAPTOL, PASSES or NORMALS)')
                     ok = .false.
                  end if
               end select
            end do
            if (.not. ok) cycle
            if (.not. has_eps_n) then
               call reader%report(line, 1, 'contact pair without EPSN (normal penalty)')
               cycle
            end if
            if (pair%master_surface == 0) then
               if (.not. (has_point .and. has_normal)) then
                  call reader%report(line, 1, 'a RIGID_PLANE master needs POINT x y z and NORMAL nx ny nz')
                  cycle
               end if
               length = norm2(pair%plane_normal)
               if (length == 0.0_dp) then
                  call reader%report(line, 1, 'the rigid plane''s NORMAL is zero')
                  cycle
               end if
               pair%plane_normal = pair%plane_normal/length
               if (passes == 2) then
                  call reader%report(line, 1, 'PASSES 2 needs a deformable master surface')
                  cycle
               end if
            else if (has_point .or. has_normal) then
               call reader%report(line, 1, 'POINT and NORMAL belong to a RIGID_PLANE master')
               cycle
            end if
            if (len(law_keyword) == 0) law_keyword = default_friction_law(friction)
            call create_pair_friction_law(trim(law_keyword), friction, law, law_error)
            if (allocated(law_error)) then
               call reader%report(line, max(1, law_token), law_error%message)
               deallocate (law_error)
               cycle
            end if
            if (.not. law%frictionless() .and. .not. has_eps_t) then
               call reader%report(line, 1, 'a contact pair with friction needs EPST (tangential penalty)')
               cycle
            end if
            call new_contact_parameters(eps_n, eps_t, gap_tolerance, law, pair%parameters, law_error)
            if (allocated(law_error)) then
               call reader%report(line, 1, law_error%message)
               deallocate (law_error)
               cycle
            end if
            if (smoothed) then
               ! the kernel's unknowns bound the nodes around a master face (docs/contact.md)
               call largest_patch_ring(model%mesh, model%mesh%surfaces(pair%master_surface), n_ring, face_nodes)
               if (n_ring > max_ring_nodes) then
                  call reader%report(line, normals_token, 'NORMALS Smoothed: the master face of nodes '// &
                                     to_string(model%mesh%node_ids(face_nodes(1)))//' '// &
                                     to_string(model%mesh%node_ids(face_nodes(2)))//' '// &
                                     to_string(model%mesh%node_ids(face_nodes(3)))//' '// &
                                     to_string(model%mesh%node_ids(face_nodes(4)))//' has '// &
                                     to_string(n_ring)//' nodes around it, at most '// &
                                     to_string(max_ring_nodes)//' are supported (4 faces at each of its nodes)')
                  cycle
               end if
            end if
            pair%parameters%smoothed_normals = smoothed
            pair%passes = passes
            pair%line = i
            model%contact_pairs = [model%contact_pairs, pair]
         end associate
      end do
   end subroutine read_contact_pairs
end module frix_deck_contact
