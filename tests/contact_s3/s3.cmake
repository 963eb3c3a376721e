# S3 elastic punch on a foundation, large deformation (docs/verification/s3.md).
# Included from tests/cases.cmake (FRIX_BIN defined there). Each test runs one deck of
# inputs/s3_punch and checks it with tests/contact_s3/check_s3.py: the full load reached,
# global equilibrium in z, and (where a stored frix value exists) the punch-top centre
# displacement and its mu-independence.
math(EXPR scaled_300 "300 * ${FRIX_TIMEOUT_SCALE}")
math(EXPR scaled_600 "600 * ${FRIX_TIMEOUT_SCALE}")
set(s3_dir ${CMAKE_CURRENT_SOURCE_DIR}/contact_s3)
set(s3_decks ${PROJECT_SOURCE_DIR}/inputs/s3_punch)
set(s3_reference ${s3_dir}/reference_coarse_epsn1e6.txt)

# The benchmark as specified (EPSN 1e8, EPST 1e6, HEX8 + EAS 3 = the seed's Hexa8-E3) with
# smoothed master normals (NORMALS Smoothed, docs/contact.md): coarse mesh, mu = 0.5, 0.25, 0.1:
# the full load, equilibrium, u_z against the stored value and within 2 % of mu = 0.5's.
# Measured: 6 / 6 / 22 increments, 2 / 7 / 40 s. With facet normals mu = 0.1 stops at t = 0.754
# (the facet model's load has a maximum at t = 0.7919: contact_s3_coarse_mu0.1_path).
foreach(mu 0.5 0.1 0.25)
  add_test(NAME contact_s3_coarse_mu${mu}
           COMMAND bash ${s3_dir}/run_s3.sh ${FRIX_BIN} ${s3_decks}/s3_coarse_mu${mu}.dck 1101 ${mu}
                   --reference ${s3_dir}/reference_coarse.txt)
  set_tests_properties(contact_s3_coarse_mu${mu} PROPERTIES LABELS "regression;contact" TIMEOUT ${scaled_300})
endforeach()

# HEX8 + EAS 9 instead of the seed's EAS 3, mu = 0.1 (smoothed normals): without friction
# continuation the run stops at t = 0.9935 (the punch corner node 1025 cutting into the
# foundation); with MU_CONTINUATION 5 3.5 2.5 1.8 1.3 the full load in 6 increments (3 solved
# through the continuation, 276 Newton iterations, 17-33 s), u_z against the stored value and
# within 2 % of the EAS 9 mu = 0.5 value. The mu = 0.5 anchor itself (5 s) is slow-labelled.
add_test(NAME contact_s3_coarse_mu0.1_eas9
         COMMAND bash ${s3_dir}/run_s3.sh ${FRIX_BIN} ${s3_decks}/s3_coarse_mu0.1_eas9.dck 1101 0.1
                 --reference ${s3_dir}/reference_coarse_eas9.txt)
set_tests_properties(contact_s3_coarse_mu0.1_eas9 PROPERTIES LABELS "regression;contact;long" TIMEOUT ${scaled_300})
add_test(NAME contact_s3_coarse_mu0.5_eas9
         COMMAND bash ${s3_dir}/run_s3.sh ${FRIX_BIN} ${s3_decks}/s3_coarse_mu0.5_eas9.dck 1101 0.5
                 --reference ${s3_dir}/reference_coarse_eas9.txt)
set_tests_properties(contact_s3_coarse_mu0.5_eas9 PROPERTIES LABELS "regression;contact;slow" TIMEOUT ${scaled_300})

# Facet normals, mu = 0.1 with friction continuation (MU_CONTINUATION 5 3.5 2.5 1.8 1.3,
# docs/solver.md): the run gets past the t = 0.754 of the plain deck to just below the load maximum t = 0.7919 of
# this discrete model (contact_s3_coarse_mu0.1_path) and stops there in order; measured
# t = 0.789062 (8 increments, 14 continuations, 45 s). Bounds: at least 0.785 (one increment of
# the last size, 1/256, short of the measured stop: a weaker continuation stops earlier) and at most the
# limit point plus the smallest increment 1/6/2^6 (a load-controlled run cannot pass it).
add_test(NAME contact_s3_coarse_mu0.1_continuation
         COMMAND bash ${s3_dir}/run_s3.sh ${FRIX_BIN} ${s3_decks}/s3_coarse_mu0.1_continuation.dck 1101 0.1
                 --stop-between 0.785 0.7945 --expect-log "friction continuation: mu x")
set_tests_properties(contact_s3_coarse_mu0.1_continuation PROPERTIES LABELS "regression;contact;long" TIMEOUT ${scaled_600})

# Without friction the coarse model has a limit point at t = 0.6106: path following (CONTROL
# Path on the punch corner's z displacement) passes it and ends on the falling branch (25 s).
add_test(NAME contact_s3_coarse_mu0_path
         COMMAND bash ${s3_dir}/run_s3.sh ${FRIX_BIN} ${s3_decks}/s3_coarse_mu0_path.dck --path-limit 0.61067)
set_tests_properties(contact_s3_coarse_mu0_path PROPERTIES LABELS "regression;contact;long" TIMEOUT ${scaled_300})
# With mu = 0.1 the facet model's maximum is t = 0.7919, below the full load: why facet
# normals cannot pass (11 min: slow).
add_test(NAME contact_s3_coarse_mu0.1_path
         COMMAND bash ${s3_dir}/run_s3.sh ${FRIX_BIN} ${s3_decks}/s3_coarse_mu0.1_path.dck --path-limit 0.7917)
set_tests_properties(contact_s3_coarse_mu0.1_path PROPERTIES LABELS "regression;contact;slow" TIMEOUT 3600)

# Reduced penalties (EPSN 1e6, EPST 1e4), coarse mesh: regression against the stored frix
# value of each mu and the mu-independence of the displacement.
foreach(mu 0.5 0.1 0.25)
  add_test(NAME contact_s3_coarse_mu${mu}_epsn1e6
           COMMAND bash ${s3_dir}/run_s3.sh ${FRIX_BIN} ${s3_decks}/s3_coarse_mu${mu}_epsn1e6.dck 1101 ${mu}
                   --reference ${s3_reference})
  set_tests_properties(contact_s3_coarse_mu${mu}_epsn1e6 PROPERTIES LABELS "regression;contact" TIMEOUT ${scaled_300})
endforeach()
set_tests_properties(contact_s3_coarse_mu0.1_epsn1e6 contact_s3_coarse_mu0.25_epsn1e6 PROPERTIES DISABLED TRUE)

# Refined mesh (punch 8 x 8 x 8 on 14 x 14 x 12), smoothed normals: slow. Full load and
# equilibrium. mu = 0.5 and 0.25: 6 / 8 increments, 64 / 120 s. mu = 0.1 without friction
# continuation stops at t = 0.0026 (Newton stalls while the edge nodes switch between stick
# and slip): disabled; with friction continuation, the next test.
foreach(mu 0.5 0.1 0.25)
  add_test(NAME contact_s3_refined_mu${mu}
           COMMAND bash ${s3_dir}/run_s3.sh ${FRIX_BIN} ${s3_decks}/s3_refined_mu${mu}.dck 10649 ${mu})
  set_tests_properties(contact_s3_refined_mu${mu} PROPERTIES LABELS "regression;contact;slow" TIMEOUT 3600)
endforeach()
set_tests_properties(contact_s3_refined_mu0.1 PROPERTIES DISABLED TRUE)

# Refined mesh, mu = 0.1, smoothed normals, friction continuation and MAXITER 50 (slow: 1731 s
# with another run on the other core): stops in order at t = 0.955729 (18 increments, 18
# continuations), asserted in [0.95, 1]: 0.9505 with MAXITER 30, 0.815 with facet normals
# (the punch edge wedged in the fold of the foundation surface, s3.md). Not a full-load test:
# when frix reaches t = 1 this test fails (frix then exits 0) and becomes one.
add_test(NAME contact_s3_refined_mu0.1_continuation
         COMMAND bash ${s3_dir}/run_s3.sh ${FRIX_BIN} ${s3_decks}/s3_refined_mu0.1_continuation.dck 10649 0.1
                 --stop-between 0.95 1.0 --expect-log "friction continuation: mu x")
set_tests_properties(contact_s3_refined_mu0.1_continuation PROPERTIES LABELS "regression;contact;slow" TIMEOUT 5400)
