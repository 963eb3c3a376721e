!> The results of one converged increment, computed once after it is committed
!> (frix_results_collection) and handed to every writer (frix_results_output): no writer
!> evaluates an element or reads the solver. Units are the deck's.
module frix_increment_results
   use frix_kinds, only: dp
   implicit none
   private

   public :: increment_results_t, named_field_t, contact_pass_results_t

   !> A scalar per integration point, named by its material (an equivalent plastic strain, say):
   !> values(n_points, n_elements), zero in the elements whose material does not have it.
   type :: named_field_t
      character(len=:), allocatable :: name
      real(dp), allocatable :: values(:, :)
   end type named_field_t

   !> The contact table of one pass: its slave nodes and, per node, the columns of
   !> contact_table_labels (gap, pressure, traction x y z, slip, status, normal x y z); the committed slip
   !> history of the pass (restart data).
   type :: contact_pass_results_t
      integer :: pair_id = 0                 !! the deck's pair id
      integer, allocatable :: nodes(:)       !! internal node numbers of the slave nodes
      real(dp), allocatable :: values(:, :)  !! (10, n_slave_nodes)
      real(dp), allocatable :: history(:, :) !! the pass's slip history, as restart reads it
      !> the multipliers of an augmented pass (force/area; restart data), unallocated otherwise
      real(dp), allocatable :: multiplier(:)
      !> the tangential multipliers (3, n) of a pass with augmented friction, unallocated otherwise
      real(dp), allocatable :: tangential_multiplier(:, :)
      !> an augmented pass's committed factors on eps_N and eps_T (penalty growth; restart
      !> data), unallocated otherwise
      real(dp), allocatable :: penalty_scale(:)
      !> an augmented pass with PREDICT: the committed multiplier rates (4, n: d lambda / dt and
      !> d lambda_T / dt, force/area per unit pseudo time; restart data), unallocated otherwise
      real(dp), allocatable :: multiplier_rate(:, :)
      !> a contact (not tie) pass: its pair's eps_N and eps_T as given or chosen by frix
      !> (automatic penalties), and 1 / 0 whether each was automatic; unallocated for a tie
      real(dp), allocatable :: penalty(:)
   end type contact_pass_results_t

   type :: increment_results_t
      integer :: step = 0
      integer :: increment = 0          !! within the step
      real(dp) :: time = 0.0_dp         !! pseudo time (load factor)
      integer :: iterations = 0         !! Newton iterations of the increment
      !> (3, 0:iterations): ||r||, ||r|| / reference and |du . r| per residual evaluation
      real(dp), allocatable :: iteration_log(:, :)
      !> (3, n_nodes) the reported displacements: the total ones less the reference of the last
      !> RESET_DISPLACEMENT step (frix_analysis_state's reported_displacement), what every
      !> writer reports as `displacement`
      real(dp), allocatable :: displacement(:, :)
      real(dp), allocatable :: total_displacement(:, :)      !! (3, n_nodes) the total displacements
      !> (3, n_nodes) the reference taken by the last RESET_DISPLACEMENT step; unallocated when
      !> no step has taken one (then `displacement` is the total)
      real(dp), allocatable :: reference_displacement(:, :)
      real(dp), allocatable :: reaction(:, :)       !! (3, n_nodes), zero on free equations
      !> one value per RESULTS HISTORY request (model%results%history, docs/output.md): a node's
      !> displacement or reaction component, their sum or mean over a node set, a contact pair's
      !> resultant force
      real(dp), allocatable :: history_values(:)
      logical, allocatable :: constrained(:, :)     !! (3, n_nodes) equations with a Dirichlet condition
      !> integration points whose law flags them as yielding in this increment (history
      !> variable YIELDED = 1); -1 when no material of the model has such a variable
      integer :: yielding_points = -1
      !> whether the increment is written in full: listing, VTK, POS3D, HDF5 (RESULTS EVERY,
      !> and the last increment of every step); the CSV files receive every increment
      logical :: full = .false.
      !> whether the integration-point fields below are computed (`full`, with a VTK, POS3D or
      !> HDF5 file to receive them)
      logical :: has_fields = .false.
      real(dp), allocatable :: stress(:, :, :)      !! (6, n_points, n_elements) Cauchy, frix Voigt
      real(dp), allocatable :: strain(:, :, :)      !! (6, n_points, n_elements) engineering shears
      type(named_field_t), allocatable :: point_fields(:)   !! the materials' named history variables
      real(dp), allocatable :: alpha(:, :)          !! (max EAS parameters, n_elements) committed
      real(dp), allocatable :: history(:, :, :)     !! (n_state, n_points, n_elements) committed
      !> the increment control after this increment, for an exact restart (HDF5 group
      !> `control`, docs/hdf5-layout.md): the size of the next increment of the step [pseudo
      !> time] after cut-backs and growth, the driven displacement per nominal increment of a
      !> CONTROL Path step [length], the last increment's displacement rate (3, n_nodes) and
      !> the pseudo time at which that increment began (frix_analysis_state's rate, rate_start)
      real(dp) :: increment_size = 0.0_dp
      real(dp) :: path_increment = 0.0_dp
      real(dp), allocatable :: displacement_rate(:, :)
      real(dp) :: rate_start = -1.0_dp
      logical :: has_contact = .false.
      type(contact_pass_results_t), allocatable :: contact(:)   !! one per contact pass
      !> per node, over all passes: pressure, traction (3, n), gap, status (0 open, 1 stick,
      !> 2 slip), slip, normal (3, n: unit, out of the master body, the traction tangential to
      !> it); on nodes that are no pass's slave node the status is -1, the rest zero
      real(dp), allocatable :: contact_pressure(:), contact_traction(:, :), contact_gap(:), contact_normal(:, :)
      real(dp), allocatable :: contact_status(:), contact_slip(:)
   end type increment_results_t
end module frix_increment_results
