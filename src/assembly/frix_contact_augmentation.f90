!> The multipliers of augmented Lagrangian contact (METHOD Augmented,
!> frix_augmented_normal_law; TMETHOD Augmented for friction) in the global system: after a
!> converged Newton solution of an increment, the largest |g| of the pressed nodes of every
!> augmented pass against its tolerance (a pressed node has g = 0 at the multipliers' fixed
!> point: a penetration, or a gap that opened while lambda still presses the node, is a
!> violation either way) (and, with augmented friction, the largest elastic slip
!> |t - lambda_T| / eps_T of its sticking nodes against the stick tolerance), and Uzawa's
!> update lambda <- p_N = max(0, lambda + eps_N (-g)), lambda_T <- t of every slave node
!> (Simo & Laursen, Comput. Struct. 42 (1992) 97-116; Laursen & Simo, IJNME 36 (1993)
!> 3451-3485, for the frictional part); the driver then solves the increment again
!> (frix_augmentation). The multipliers are committed with the contact state
!> (frix_contact_assembly's commit_contact) and go back to the committed ones when an
!> increment is given up (restore_multipliers).
!> Penalty growth (the method of multipliers' rule: Bertsekas, *Constrained Optimization and
!> Lagrange Multiplier Methods*, Academic Press 1982, 2.2; Laursen 2002, 5.3): the nested
!> iteration reduces the gap at each augmentation by about the ratio of the bodies'
!> stiffness to eps_N, slowly where eps_N is soft. After each augmentation of an increment,
!> a pass whose largest |g| of a pressed node (largest stick slip) is still beyond its tolerance and
!> did not fall below growth_rate times the previous augmentation's has eps_N (eps_T)
!> multiplied by growth_factor for the next solutions, up to growth_limit times the given
!> value (grow_penalties). The multipliers are updated before, with the penalty of the
!> solution they come from (lambda <- p_N), so each solution stays an exact equilibrium. The
!> grown factors are part of the contact state: committed with the increment, so that the
!> next increment starts from the penalty that converged fast (start_penalty_growth), rolled
!> back with the multipliers, written to HDF5 and restored by restart.
!> Predictor (PREDICT, predict_multipliers): an increment starts from the committed
!> multipliers extrapolated with the rates of the last converged increment (commit_contact),
!> the predictor of the converged multipliers under proportional loading.
module frix_contact_augmentation
   use frix_kinds, only: dp
   use frix_model, only: model_t
   use frix_normal_contact_law, only: augmentation_t
   use frix_contact_parameters, only: contact_parameters_t
   use frix_contact_kernel, only: contact_open, contact_stick
   use frix_contact_pass, only: contact_pass_t
   use frix_contact_assembly, only: contact_system_t
   implicit none
   private

   public :: penetration_check_t, check_penetrations, augment_multipliers, restore_multipliers
   public :: max_augmentations, grow_penalties, start_penalty_growth, predict_multipliers

   !> Default penetration tolerance: this fraction of the master's mean face size (against a
   !> rigid plane: the square root of the slave nodes' mean tributary area) (S1: with
   !> 1e-3 the step-2 pressure changes stay below eps_N times the tolerance and the result
   !> keeps the penalty's dependence on EPSN, 4 % over 1e4 ... 1e7; with 1e-5 0.01 %).
   real(dp), parameter :: default_tolerance_fraction = 1.0e-5_dp

   !> The worst penetration (and elastic stick slip) relative to its tolerance over the
   !> augmented passes.
   type :: penetration_check_t
      logical :: within = .true.        !! every active node's penetration (slip) within its tolerance
      real(dp) :: penetration = 0.0_dp  !! the largest ratio's |g| or elastic slip (length)
      real(dp) :: tolerance = 0.0_dp    !! its pass's tolerance (length)
      integer :: node = 0               !! its slave node (internal number), 0: none active
      integer :: n_over = 0             !! active nodes beyond their tolerance
      logical :: slip = .false.         !! the worst is an elastic stick slip
   end type penetration_check_t

contains

   !> The augmentation settings of pass p's contact pair (none for a tie).
   function pass_augmentation(model, system, p) result(settings)
      type(model_t), intent(in) :: model
      type(contact_system_t), intent(in) :: system
      integer, intent(in) :: p
      type(augmentation_t) :: settings
      settings = augmentation_t()
      associate (pair => model%contact_pairs(system%passes(p)%pair))
         if (.not. pair%tied) settings = pair%parameters%normal%augmentation()
      end associate
   end function pass_augmentation

   !> Most augmentations any pass allows (0: no augmented pass).
   integer function max_augmentations(model, system)
      type(model_t), intent(in) :: model
      type(contact_system_t), intent(in) :: system
      type(augmentation_t) :: settings
      integer :: p
      max_augmentations = 0
      do p = 1, size(system%passes)
         settings = pass_augmentation(model, system, p)
         if (settings%augmented) max_augmentations = max(max_augmentations, settings%max_augmentations)
      end do
   end function max_augmentations

   !> The |g| (penetration or opening) of the active slave nodes of the augmented passes at the last
   !> evaluation, against each pass's tolerance (given, or default_tolerance_fraction times
   !> its master's mean face size), and with augmented friction the elastic slips
   !> |t - (I - n n) lambda_T| / eps_T of the sticking nodes against the stick tolerance (the
   !> same default).
   function check_penetrations(model, system) result(check)
      type(model_t), intent(in) :: model
      type(contact_system_t), intent(in) :: system
      type(penetration_check_t) :: check
      type(augmentation_t) :: settings
      real(dp) :: tolerance, stick_tolerance, worst
      integer :: p, i
      worst = 0.0_dp
      do p = 1, size(system%passes)
         settings = pass_augmentation(model, system, p)
         if (.not. settings%augmented) cycle
         associate (pass => system%passes(p), parameters => model%contact_pairs(system%passes(p)%pair)%parameters)
            call pass_tolerances(settings, parameters, pass, tolerance, stick_tolerance)
            do i = 1, size(pass%slave_nodes)
               if (pass%result(i)%status == contact_open) cycle
               call compare(pass%slave_nodes(i), abs(pass%result(i)%gap), tolerance, .false.)
               if (parameters%tangential_augmented .and. pass%result(i)%status == contact_stick) &
                  call compare(pass%slave_nodes(i), stick_slip(pass, i, parameters), stick_tolerance, .true.)
            end do
         end associate
      end do
   contains
      subroutine compare(node, value, limit, slip)
         integer, intent(in) :: node
         real(dp), intent(in) :: value, limit
         logical, intent(in) :: slip
         if (value <= limit) return
         check%within = .false.
         check%n_over = check%n_over + 1
         if (value/limit <= worst) return
         worst = value/limit
         check%penetration = value
         check%tolerance = limit
         check%node = node
         check%slip = slip
      end subroutine compare
   end function check_penetrations

   !> Pass `pass`'s penetration (|g|) and stick tolerances [length]: the given ones, or
   !> default_tolerance_fraction times surface_size.
   subroutine pass_tolerances(settings, parameters, pass, tolerance, stick_tolerance)
      type(augmentation_t), intent(in) :: settings
      type(contact_parameters_t), intent(in) :: parameters
      type(contact_pass_t), intent(in) :: pass
      real(dp), intent(out) :: tolerance, stick_tolerance
      tolerance = settings%penetration_tolerance
      if (tolerance < 0.0_dp) tolerance = default_tolerance_fraction*surface_size(pass)
      stick_tolerance = parameters%stick_tolerance
      if (stick_tolerance < 0.0_dp) stick_tolerance = default_tolerance_fraction*surface_size(pass)
   end subroutine pass_tolerances


   !> The size the default tolerances scale with (length): the master's mean face size, or
   !> against a rigid plane the square root of the slave nodes' mean tributary area.
   pure real(dp) function surface_size(pass)
      type(contact_pass_t), intent(in) :: pass
      surface_size = pass%face_size
      if (pass%rigid .and. size(pass%area) > 0) surface_size = sqrt(sum(pass%area)/size(pass%area))
   end function surface_size

   !> |t - (I - n n) lambda_T| / eps_T of slave i (length): the elastic slip of a sticking node
   !> of an augmented-friction pass, eps_T the pass's current (possibly grown) one.
   pure real(dp) function stick_slip(pass, i, parameters)
      type(contact_pass_t), intent(in) :: pass
      integer, intent(in) :: i
      type(contact_parameters_t), intent(in) :: parameters
      real(dp) :: lambda(3), normal(3)
      normal = pass%result(i)%normal
      lambda = pass%tangential_multiplier(:, i)
      lambda = lambda - dot_product(lambda, normal)*normal
      stick_slip = norm2(pass%result(i)%traction - lambda)/(pass%tangential_scale*parameters%tangential_penalty)
   end function stick_slip

   !> Uzawa's update of every augmented pass: lambda <- p_N of the last evaluation (0 for an
   !> open node), with augmented friction lambda_T <- t. Returns the largest change of a normal
   !> multiplier (force/area).
   real(dp) function augment_multipliers(model, system) result(largest_change)
      type(model_t), intent(in) :: model
      type(contact_system_t), intent(inout) :: system
      type(augmentation_t) :: settings
      real(dp) :: updated
      integer :: p, i
      largest_change = 0.0_dp
      do p = 1, size(system%passes)
         settings = pass_augmentation(model, system, p)
         if (.not. settings%augmented) cycle
         associate (pass => system%passes(p))
            do i = 1, size(pass%slave_nodes)
               updated = merge(pass%result(i)%pressure, 0.0_dp, pass%result(i)%status /= contact_open)
               largest_change = max(largest_change, abs(updated - pass%multiplier(i)))
               pass%multiplier(i) = updated
               if (.not. model%contact_pairs(pass%pair)%parameters%tangential_augmented) cycle
               if (pass%result(i)%status == contact_open) then
                  pass%tangential_multiplier(:, i) = 0.0_dp
               else
                  pass%tangential_multiplier(:, i) = pass%result(i)%traction
               end if
            end do
         end associate
      end do
   end function augment_multipliers

   !> After an augmentation (module head): for each augmented pass, eps_N's factor grows by
   !> the pass's growth_factor when its largest |g| of a pressed node is beyond the tolerance and above
   !> growth_rate times the previous augmentation's; with augmented friction eps_T's likewise
   !> with the largest stick slip; each up to growth_limit. `grown`: some factor grew.
   subroutine grow_penalties(model, system, grown)
      type(model_t), intent(in) :: model
      type(contact_system_t), intent(inout) :: system
      logical, intent(out) :: grown
      type(augmentation_t) :: settings
      real(dp) :: penetration, slip, tolerance, stick_tolerance
      integer :: p, i
      grown = .false.
      do p = 1, size(system%passes)
         settings = pass_augmentation(model, system, p)
         if (.not. settings%augmented) cycle
         associate (pass => system%passes(p), parameters => model%contact_pairs(system%passes(p)%pair)%parameters)
            penetration = 0.0_dp
            slip = 0.0_dp
            do i = 1, size(pass%slave_nodes)
               if (pass%result(i)%status == contact_open) cycle
               penetration = max(penetration, abs(pass%result(i)%gap))
               if (parameters%tangential_augmented .and. pass%result(i)%status == contact_stick) &
                  slip = max(slip, stick_slip(pass, i, parameters))
            end do
            call pass_tolerances(settings, parameters, pass, tolerance, stick_tolerance)
            call grow(pass%normal_scale, penetration, pass%previous_penetration, tolerance)
            if (parameters%tangential_augmented) call grow(pass%tangential_scale, slip, pass%previous_slip, &
                                                           stick_tolerance)
         end associate
      end do
   contains
      subroutine grow(scale, violation, previous, limit)
         real(dp), intent(inout) :: scale, previous
         real(dp), intent(in) :: violation, limit
         if (previous > 0.0_dp .and. violation > limit .and. violation > settings%growth_rate*previous &
             .and. scale < settings%growth_limit) then
            scale = min(scale*settings%growth_factor, settings%growth_limit)
            grown = .true.
         end if
         previous = violation
      end subroutine grow
   end subroutine grow_penalties

   !> The start of an increment attempt: the penalty factors of the last converged increment,
   !> and no previous augmentation.
   subroutine start_penalty_growth(system)
      type(contact_system_t), intent(inout) :: system
      integer :: p
      do p = 1, size(system%passes)
         system%passes(p)%normal_scale = system%passes(p)%committed_normal_scale
         system%passes(p)%tangential_scale = system%passes(p)%committed_tangential_scale
         system%passes(p)%previous_penetration = -1.0_dp
         system%passes(p)%previous_slip = -1.0_dp
      end do
   end subroutine start_penalty_growth

   !> The multipliers' predictor at the start of an increment attempt of length dt (pseudo
   !> time), in every augmented pass with PREDICT: lambda = lambda_n + dt (d lambda / dt)_n,
   !> lambda_T likewise, the rates of the last converged increment (commit_contact; 0 for a
   !> node not pressed at both its ends, which keeps its committed multipliers), lambda >= 0.
   !> Under proportional loading the multipliers grow linearly with the load factor and the
   !> prediction is the increment's converged multiplier. The caller passes dt = 0 in the
   !> first increment of a step (the load's direction can change between steps). The
   !> committed multipliers are untouched, so a cut-back (restore_multipliers) undoes the
   !> prediction.
   subroutine predict_multipliers(model, system, dt, predicted)
      type(model_t), intent(in) :: model
      type(contact_system_t), intent(inout) :: system
      real(dp), intent(in) :: dt
      logical, intent(out) :: predicted   !! some multiplier changed
      type(augmentation_t) :: settings
      integer :: p
      predicted = .false.
      if (dt <= 0.0_dp) return
      do p = 1, size(system%passes)
         settings = pass_augmentation(model, system, p)
         if (.not. (settings%augmented .and. model%contact_pairs(system%passes(p)%pair)%parameters%predict)) cycle
         associate (pass => system%passes(p))
            pass%multiplier = max(0.0_dp, pass%committed_multiplier + dt*pass%multiplier_rate)
            predicted = predicted .or. any(pass%multiplier_rate /= 0.0_dp)
            if (model%contact_pairs(pass%pair)%parameters%tangential_augmented) &
               pass%tangential_multiplier = pass%committed_tangential_multiplier + dt*pass%tangential_multiplier_rate
         end associate
      end do
   end subroutine predict_multipliers

   !> The multipliers and penalty factors of the last converged increment (after a failed
   !> attempt).
   subroutine restore_multipliers(system)
      type(contact_system_t), intent(inout) :: system
      integer :: p
      do p = 1, size(system%passes)
         system%passes(p)%multiplier = system%passes(p)%committed_multiplier
         system%passes(p)%tangential_multiplier = system%passes(p)%committed_tangential_multiplier
         system%passes(p)%normal_scale = system%passes(p)%committed_normal_scale
         system%passes(p)%tangential_scale = system%passes(p)%committed_tangential_scale
      end do
   end subroutine restore_multipliers
end module frix_contact_augmentation
