# S3 elastic punch on a foundation, large deformation (docs/verification/s3.md).
# Included from tests/cases.cmake (FRIX_BIN defined there). Each test runs one deck of
# inputs/s3_punch and checks it with tests/contact_s3/check_s3.py: the full load reached,
# global equilibrium in z, and (where a stored frix value exists) the punch-top centre
# displacement and its mu-independence.
set(s3_dir ${CMAKE_CURRENT_SOURCE_DIR}/contact_s3)
set(s3_decks ${PROJECT_SOURCE_DIR}/inputs/s3_punch)
set(s3_reference ${s3_dir}/reference_coarse_epsn1e6.txt)

# The benchmark as specified (EPSN 1e8, EPST 1e6, HEX8 + EAS 3 = the seed's Hexa8-E3): coarse
# mesh, mu = 0.5, 0.1, 0.25. Convergence to the full load and equilibrium. mu = 0.5 and 0.25
# converge (6 increments, 1-4 s each); mu = 0.1 stops at t = 0.754: its test is disabled, the
# load of the coarse model having a maximum at t = 0.7919 (s3.md "A limit point of the discrete
# model", test contact_s3_coarse_mu0.1_path). (With EAS 9 mu = 0.25 stopped at t = 0.90.)
foreach(mu 0.5 0.1 0.25)
  add_test(NAME contact_s3_coarse_mu${mu}
           COMMAND bash ${s3_dir}/run_s3.sh ${FRIX_BIN} ${s3_decks}/s3_coarse_mu${mu}.dck 1101 ${mu}
                   --reference ${s3_dir}/reference_coarse.txt)
  set_tests_properties(contact_s3_coarse_mu${mu} PROPERTIES LABELS "regression;contact" TIMEOUT 300)
endforeach()
set_tests_properties(contact_s3_coarse_mu0.1 PROPERTIES DISABLED TRUE)

# Without friction the coarse model has a limit point at t = 0.6106: path following (CONTROL
# Path on the punch corner's z displacement) passes it and ends on the falling branch (25 s).
add_test(NAME contact_s3_coarse_mu0_path
         COMMAND bash ${s3_dir}/run_s3.sh ${FRIX_BIN} ${s3_decks}/s3_coarse_mu0_path.dck --path-limit 0.61067)
set_tests_properties(contact_s3_coarse_mu0_path PROPERTIES LABELS "regression;contact" TIMEOUT 300)
# With mu = 0.1 the maximum is t = 0.7919, below the full load: why contact_s3_coarse_mu0.1
# cannot pass (11 min: slow).
add_test(NAME contact_s3_coarse_mu0.1_path
         COMMAND bash ${s3_dir}/run_s3.sh ${FRIX_BIN} ${s3_decks}/s3_coarse_mu0.1_path.dck --path-limit 0.7917)
set_tests_properties(contact_s3_coarse_mu0.1_path PROPERTIES LABELS "regression;contact;slow" TIMEOUT 3600)

# Reduced penalties (EPSN 1e6, EPST 1e4), coarse mesh: regression against the stored frix
# value of each mu and the mu-independence of the displacement.
foreach(mu 0.5 0.1 0.25)
  add_test(NAME contact_s3_coarse_mu${mu}_epsn1e6
           COMMAND bash ${s3_dir}/run_s3.sh ${FRIX_BIN} ${s3_decks}/s3_coarse_mu${mu}_epsn1e6.dck 1101 ${mu}
                   --reference ${s3_reference})
  set_tests_properties(contact_s3_coarse_mu${mu}_epsn1e6 PROPERTIES LABELS "regression;contact" TIMEOUT 300)
endforeach()
set_tests_properties(contact_s3_coarse_mu0.1_epsn1e6 contact_s3_coarse_mu0.25_epsn1e6 PROPERTIES DISABLED TRUE)

# Refined mesh (punch 8 x 8 x 8 on 14 x 14 x 12): slow.
foreach(mu 0.5 0.1 0.25)
  add_test(NAME contact_s3_refined_mu${mu}
           COMMAND bash ${s3_dir}/run_s3.sh ${FRIX_BIN} ${s3_decks}/s3_refined_mu${mu}.dck 10649 ${mu})
  set_tests_properties(contact_s3_refined_mu${mu} PROPERTIES LABELS "regression;contact;slow" TIMEOUT 3600)
endforeach()
set_tests_properties(contact_s3_refined_mu0.1 contact_s3_refined_mu0.25 PROPERTIES DISABLED TRUE)
