# S6(b) pipe crossing a slope (docs/verification/s6.md). Included from tests/cases.cmake
# (FRIX_BIN defined there). Each test runs one deck of inputs/s6_pipe_slope with tests/harness/run_deck_check.sh and
# checks it with check_s6.py: the load reached; equilibrium of the reactions with the soil's
# weight (0.018 x the mesh's soil volume), the surcharge and the internal pressure (1e-6); the
# elastic hoop displacement in the open span against Lame in plane strain (2 %); the history
# values at t = 2 (1 x) and t = 3 (10 x) against the frix regression values in reference.txt
# (1e-6); for the 10 x runs the fully plastic pipe (every integration point yielded, von Mises
# of every element above 420).
set(s6_dir ${CMAKE_CURRENT_SOURCE_DIR}/contact_s6)
set(s6_decks ${PROJECT_SOURCE_DIR}/inputs/s6_pipe_slope)

# Default run: the coarse mesh (636 HEX8), mu = 0.3, steps 1 and 2 (geostatic, then 1 x in 7
# increments): 2 s on the 2-core VM (shared).
add_test(NAME contact_s6_mu0.3_1x
         COMMAND bash ${run_deck_check} ${FRIX_BIN} ${s6_decks}/s6_mu0.3_1x.dck ${s6_dir}/check_s6.py --end 2
                 --reference ${s6_dir}/reference.txt)
set_tests_properties(contact_s6_mu0.3_1x PROPERTIES LABELS "regression;contact;plasticity"
                     TIMEOUT ${scaled_600})

# The three friction coefficients to 10 x (coarse, 26 increments, 10-25 s each on the shared
# VM): mu = 0.3, the benchmark's own, in the default run; 0.1 and 0.6 slow.
foreach(mu 0.1 0.3 0.6)
  add_test(NAME contact_s6_mu${mu}
           COMMAND bash ${run_deck_check} ${FRIX_BIN} ${s6_decks}/s6_mu${mu}.dck ${s6_dir}/check_s6.py --plastic
                   --reference ${s6_dir}/reference.txt)
  if(mu STREQUAL "0.3")
    set(labels "regression;contact;plasticity")
  else()
    set(labels "regression;contact;plasticity;slow")
  endif()
  set_tests_properties(contact_s6_mu${mu} PROPERTIES LABELS "${labels}" TIMEOUT ${scaled_600})
endforeach()

# The variant with the pipe's end z = 0 free axially (friction alone restrains the buried pipe;
# the mu = 0.1 and 0.3 runs differ by 33 mm axially, s6.md "Variants"), coarse, 10-15 s: slow.
foreach(mu 0.1 0.3)
  add_test(NAME contact_s6_mu${mu}_free0
           COMMAND bash ${run_deck_check} ${FRIX_BIN} ${s6_decks}/s6_mu${mu}_free0.dck ${s6_dir}/check_s6.py --plastic
                   --axially-free --reference ${s6_dir}/reference.txt)
  set_tests_properties(contact_s6_mu${mu}_free0 PROPERTIES LABELS "regression;contact;plasticity;slow"
                       TIMEOUT ${scaled_600})
endforeach()

# The soil Mohr-Coulomb (c = 0.020, phi = 30, psi = 5; s6.md "S6(b) with Mohr-Coulomb soil"):
# steps 1-2 (5 s on the shared VM) in the default run, with the soil's plastic zone at 1 x not
# empty and its stresses admissible; the seed's loads to 10 x (25 s) slow.
add_test(NAME contact_s6_mu0.3_1x_mc
         COMMAND bash ${run_deck_check} ${FRIX_BIN} ${s6_decks}/s6_mu0.3_1x_mc.dck ${s6_dir}/check_s6.py --end 2
                 --mohr-coulomb 0.020,30 --reference ${s6_dir}/reference.txt)
set_tests_properties(contact_s6_mu0.3_1x_mc PROPERTIES LABELS "regression;contact;plasticity"
                     TIMEOUT ${scaled_600})
# The three friction coefficients to 10 x with it (20 s each): slow.
foreach(mu 0.1 0.3 0.6)
  add_test(NAME contact_s6_mu${mu}_mc
           COMMAND bash ${run_deck_check} ${FRIX_BIN} ${s6_decks}/s6_mu${mu}_mc.dck ${s6_dir}/check_s6.py --plastic
                   --mohr-coulomb 0.020,30 --reference ${s6_dir}/reference.txt)
  set_tests_properties(contact_s6_mu${mu}_mc PROPERTIES LABELS "regression;contact;plasticity;slow"
                       TIMEOUT ${scaled_600})
endforeach()
# The refined mesh (3840 HEX8) with it, psi = 5 (130 s on a quiet 2-core machine): slow.
add_test(NAME contact_s6_mu0.3_fine_mc
         COMMAND bash ${run_deck_check} ${FRIX_BIN} ${s6_decks}/s6_mu0.3_fine_mc.dck ${s6_dir}/check_s6.py --plastic
                 --mohr-coulomb 0.020,30 --reference ${s6_dir}/reference.txt)
set_tests_properties(contact_s6_mu0.3_fine_mc PROPERTIES LABELS "regression;contact;plasticity;slow"
                     TIMEOUT ${scaled_600})
