# SOLVER Petsc (src/linalg/frix_petsc_solver.F90, docs/solver.md). In a build with PETSc
# (FRIX_PETSC=ON, scripts/setup.sh --petsc) regression decks run with SOLVER Petsc (MUMPS LU by
# default, and GMRES with algebraic multigrid through PETSC_OPTIONS) must reproduce the
# deck's own solver (CHOLMOD or UMFPACK) to 1e-8 (tests/solver/solver_equivalence.sh), label
# petsc. Without PETSc the deck check rejects SOLVER Petsc with a clear message.
if(FRIX_PETSC)
  set(petsc_cases
    s1_deformable_base ${PROJECT_SOURCE_DIR}/inputs/s1_block/s1_deformable_base.dck
    s4_block ${PROJECT_SOURCE_DIR}/inputs/s4_block/s4_block.dck
    v5_2pass ${PROJECT_SOURCE_DIR}/inputs/v5_contact_patch/v5_u3_2pass.dck
    v6_hertz ${PROJECT_SOURCE_DIR}/inputs/v6_hertz/v6_hertz.dck
    block_tension ${PROJECT_SOURCE_DIR}/inputs/examples/block_tension/block_tension.dck)
  set(mpi_cases s1_deformable_base s4_block v5_2pass)   # also on 2 MPI processes (below)
  list(LENGTH petsc_cases n_items)
  math(EXPR last "${n_items} - 1")
  foreach(i RANGE 0 ${last} 2)
    math(EXPR j "${i} + 1")
    list(GET petsc_cases ${i} name)
    list(GET petsc_cases ${j} deck)
    add_test(NAME petsc_mumps_${name}
             COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/solver/solver_equivalence.sh ${FRIX_BIN} ${deck} Petsc)
    set_tests_properties(petsc_mumps_${name} PROPERTIES LABELS "petsc;regression" TIMEOUT ${scaled_300})
    if(name IN_LIST mpi_cases)
      add_test(NAME mpi2_${name}
               COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/solver/solver_equivalence.sh ${FRIX_BIN} ${deck} Petsc
                       --ranks 2)
      set_tests_properties(mpi2_${name} PROPERTIES LABELS "petsc;mpi;regression" TIMEOUT ${scaled_300})
    endif()
  endforeach()
  # the iterative path: GMRES preconditioned by GAMG, solved to 1e-12
  add_test(NAME petsc_gamg_block_tension
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/solver/solver_equivalence.sh ${FRIX_BIN}
                   ${PROJECT_SOURCE_DIR}/inputs/examples/block_tension/block_tension.dck Petsc)
  set_tests_properties(petsc_gamg_block_tension PROPERTIES LABELS "petsc;regression" TIMEOUT ${scaled_300}
    ENVIRONMENT "PETSC_OPTIONS=-ksp_type gmres -pc_type gamg -ksp_rtol 1e-12")
  # mpirun -n 2 (docs/parallel.md), labels petsc and mpi: the plastic restart deck (material
  # history) on 2 processes and restarted between 1 and 2 processes; and (mpi_cases, in the
  # loop above, and a rigid punch on mortar contact driven through a kinematic coupling,
  # whose reference nodes belong to no element) the deck with SOLVER Petsc on 2 processes
  # against the deck's own solver on one, listing and every CSV column to 1e-8: S1 (contact,
  # deformable base), V5 (two passes), S4 (Coulomb friction).
  add_test(NAME mpi2_rigid_punch_mortar
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/solver/solver_equivalence.sh ${FRIX_BIN}
                   ${CMAKE_CURRENT_SOURCE_DIR}/coupling/rigid_punch_mortar.dck Petsc --ranks 2)
  set_tests_properties(mpi2_rigid_punch_mortar PROPERTIES LABELS "petsc;mpi;regression" TIMEOUT ${scaled_300})
  add_test(NAME mpi2_restart_plastic
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/solver/mpi_restart_test.sh ${FRIX_BIN}
                   ${CMAKE_CURRENT_SOURCE_DIR}/restart/restart_plastic.dck 2.2)
  set_tests_properties(mpi2_restart_plastic PROPERTIES LABELS "petsc;mpi;regression;plasticity"
    TIMEOUT ${scaled_300})
else()
  add_test(NAME errors_petsc_unavailable
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/errors/check_error_case.sh ${FRIX_BIN}
                   ${CMAKE_CURRENT_SOURCE_DIR}/solver/petsc_unavailable.dck)
  set_tests_properties(errors_petsc_unavailable PROPERTIES LABELS errors)
endif()
