!> The initial (in-situ) stress of the model's integration points (INITIAL STRESS,
!> docs/deck-format.md; theory and verification in docs/verification/soil_insitu.md).
!>
!> Each definition (initial_stress_t) is evaluated at the reference position X_g of every
!> integration point of its elements (element_t%point_positions) and kept in the model
!> (model%point_initial_stress): it is input, fixed for the whole analysis, and a restart,
!> which reads the same deck, evaluates the same numbers. The elements pass it to their
!> material (element_t%evaluate, material_t%initial_stress_response), so that every law starts
!> from sigma0 and every output's stress includes it.
!>
!> Geostatic stress, tension positive (frix's convention), vertical axis z (or AXIS) pointing
!> up, z0 the datum, gamma the unit weight, q the vertical stress at the datum (compression
!> positive: a surcharge, or the weight of the layers above):
!>   sigma_v = -(q + gamma (z0 - z)),  sigma_h = K0 sigma_v,  no shear.
!> It satisfies div sigma0 + b = 0 with the body force b = -gamma e_z (BODY FORCE GRAVITY
!> 0 0 -g on a material of DENS rho = gamma / g), and sigma0 n = -q e_z on the datum plane.
module frix_initial_stress
   use frix_kinds, only: dp
   use frix_error, only: error_t, fatal_error
   use frix_strings, only: to_string
   use frix_model, only: model_t, initial_stress_t
   use frix_element, only: kinematics_total_lagrangian
   implicit none
   private

   public :: initial_stress_at, apply_initial_stress

   !> A point's initial stress is admissible when the law, asked for its stress at zero strain,
   !> gives back sigma0 to this fraction of |sigma0| (a state on the yield surface returns onto
   !> itself to round-off).
   real(dp), parameter :: admissible_tolerance = 1.0e-9_dp

contains

   !> sigma0 of `definition` at the reference position `position` (Voigt xx yy zz xy xz yz,
   !> tensor shears).
   pure function initial_stress_at(definition, position) result(stress)
      type(initial_stress_t), intent(in) :: definition
      real(dp), intent(in) :: position(3)
      real(dp) :: stress(6)
      real(dp) :: vertical
      if (.not. definition%geostatic) then
         stress = definition%stress
         return
      end if
      vertical = -(definition%surcharge + definition%unit_weight*(definition%datum - position(definition%axis)))
      stress = 0.0_dp
      stress(1:3) = definition%k0*vertical
      stress(definition%axis) = vertical
   end function initial_stress_at

   !> Evaluate definition `k` at the points of its elements into model%point_initial_stress
   !> (allocated at the first definition). An error (the first of each kind) when an element
   !> already has an initial stress, a point lies above a geostatic datum, or the stress of a
   !> point lies outside its material's elastic domain (check_admissible).
   subroutine apply_initial_stress(model, k, error)
      type(model_t), intent(inout) :: model
      integer, intent(in) :: k
      type(error_t), allocatable, intent(out) :: error
      real(dp), allocatable :: coords(:, :), positions(:, :)
      integer :: j, e, g, n_points
      if (.not. allocated(model%initial_stress_source)) call allocate_point_stresses(model)
      associate (definition => model%initial_stresses(k))
         do j = 1, size(definition%elements)
            e = definition%elements(j)
            if (model%initial_stress_source(e) /= 0) then
               call fatal_error(error, 'element '//to_string(model%mesh%element_ids(e))// &
                                ' already has an initial stress (line '// &
                                to_string(model%initial_stresses(model%initial_stress_source(e))%line)//')')
               return
            end if
            associate (element => model%blocks(model%mesh%element_block(e))%element%formulation)
               n_points = element%n_points()
               coords = model%mesh%coords(:, model%mesh%connectivity(:element%n_nodes(), e))
               if (allocated(positions)) deallocate (positions)
               allocate (positions(3, n_points))
               call element%point_positions(coords, positions)
            end associate
            do g = 1, n_points
               if (definition%geostatic .and. positions(definition%axis, g) > definition%datum) then
                  call fatal_error(error, 'element '//to_string(model%mesh%element_ids(e))//', integration point '// &
                                   to_string(g)//' lies above the datum ('//axis_name(definition%axis)//' = '// &
                                   to_string(positions(definition%axis, g))//' > '//to_string(definition%datum)//')')
                  return
               end if
               model%point_initial_stress(:, g, e) = initial_stress_at(definition, positions(:, g))
            end do
            model%initial_stress_source(e) = k
            call check_admissible(model, e, n_points, positions, error)
            if (allocated(error)) return
         end do
      end associate
   end subroutine apply_initial_stress

   subroutine allocate_point_stresses(model)
      type(model_t), intent(inout) :: model
      integer :: b, max_points
      max_points = 0
      do b = 1, size(model%blocks)
         max_points = max(max_points, model%blocks(b)%element%formulation%n_points())
      end do
      allocate (model%point_initial_stress(6, max_points, model%mesh%n_elements), source=0.0_dp)
      allocate (model%initial_stress_source(model%mesh%n_elements), source=0)
   end subroutine allocate_point_stresses

   !> Each point of element `e` asked for its stress at zero strain from sigma0 and a virgin
   !> history: a plastic law returns a sigma0 beyond its yield surface onto it, and the soil
   !> would then not start in equilibrium with its weight. Such a state is a mistake of the
   !> deck (a K0 outside the range the strength admits, a layer without cohesion above a
   !> surcharge that needs one), reported rather than returned: a returned state would flow
   !> plastically in the first increment, under no load, from a state the deck did not give.
   subroutine check_admissible(model, e, n_points, positions, error)
      type(model_t), intent(in) :: model
      integer, intent(in) :: e, n_points
      real(dp), intent(in) :: positions(:, :)
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: law_error
      real(dp), allocatable :: state_old(:), state_new(:)
      real(dp) :: stress(6), tangent(6, 6)
      integer :: g, material
      material = model%blocks(model%mesh%element_block(e))%material
      associate (law => model%materials(material)%law, &
                 element => model%blocks(model%mesh%element_block(e))%element%formulation)
         allocate (state_old(law%n_state()), state_new(law%n_state()), source=0.0_dp)
         do g = 1, n_points
            associate (sigma0 => model%point_initial_stress(:, g, e))
               call law%initial_stress_response([0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp], &
                                                element%kinematics == kinematics_total_lagrangian, sigma0, &
                                                state_old, state_new, stress, tangent, law_error)
               if (.not. allocated(law_error)) then
                  if (maxval(abs(stress - sigma0)) <= admissible_tolerance*maxval(abs(sigma0))) cycle
               end if
               call fatal_error(error, 'the initial stress '//voigt_text(sigma0)//' of element '// &
                                to_string(model%mesh%element_ids(e))//', integration point '//to_string(g)// &
                                ' at ('//to_string(positions(1, g))//', '//to_string(positions(2, g))//', '// &
                                to_string(positions(3, g))//') lies outside the elastic domain of material '// &
                                to_string(model%material_ids(material))//' ('//law%name//'), which returns it to '// &
                                voigt_text(stress)//': choose K0 (or the stress) inside the yield surface')
               return
            end associate
         end do
      end associate
   end subroutine check_admissible

   pure function voigt_text(stress) result(text)
      real(dp), intent(in) :: stress(6)
      character(len=:), allocatable :: text
      integer :: i
      text = '('//to_string(stress(1))
      do i = 2, 6
         text = text//', '//to_string(stress(i))
      end do
      text = text//')'
   end function voigt_text

   pure function axis_name(axis) result(name)
      integer, intent(in) :: axis
      character(len=1) :: name
      name = 'xyz'(axis:axis)
   end function axis_name
end module frix_initial_stress
