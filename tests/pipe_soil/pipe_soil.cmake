# Buried pipe pulled sideways and upwards through sand and clay against the design formulas of
# ALA (2001) and DNV (docs/verification/pipe_soil.md). Included from tests/cases.cmake
# (FRIX_BIN defined there). Each test runs one deck of inputs/pipe_soil with
# tests/harness/run_deck_check.sh and checks with check_pipe_soil.py: the pull reached, a
# plateau of the force over the last quarter of the pull, the plateau inside the band 0.7 x
# the lowest ... 1.3 x the highest design value, the pipe's reaction equal to the contact
# resultant and the vertical reactions equal to the soil's weight (statics).
set(pipe_soil_dir ${CMAKE_CURRENT_SOURCE_DIR}/pipe_soil)
set(pipe_soil_decks ${PROJECT_SOURCE_DIR}/inputs/pipe_soil)

# One test per (deck, plateau tolerance, labels, timeout).
function(pipe_soil_test deck plateau labels timeout)
  add_test(NAME ${deck}
           COMMAND bash ${run_deck_check} ${FRIX_BIN} ${pipe_soil_decks}/${deck}.dck ${pipe_soil_dir}/check_pipe_soil.py
                   ${plateau})
  set_tests_properties(${deck} PROPERTIES LABELS "${labels}" TIMEOUT ${timeout})
endfunction()

# Default run: the tiny meshes (m = 4; 116 / 232 soil HEX8 EAS 3), 10-12 increments, 3-10 s
# CPU: sand uplift (measured 22.66 kN/m, band 8.27-23.91), the same with the pipe free in the
# geostatic step and pulled by a force under path control (22.66), clay uplift (98.66, band
# 57.2-130.0), clay lateral (136.21, band 103.5-192.3).
foreach(deck pipe_sand_uplift_tiny pipe_sand_uplift_tiny_free pipe_clay_uplift_tiny pipe_clay_lateral_tiny)
  pipe_soil_test(${deck} 0.02 "regression;plasticity" ${scaled_300})
endforeach()

# Slow: the coarse meshes (m = 8; 300 soil HEX8 in the half model), 40 increments, 25-95 s CPU
# (sand uplift 21.64, smooth 19.73, clay uplift 93.13 kN/m, peak 97.96), and the tiny decks that cut back
# often where soil elements reach the cone's apex (docs/verification/pipe_soil.md): sand
# lateral (107.85, band 65.1-120.8; 12 cut-backs, 30 s), sand uplift with psi = 5 degrees
# (16.71; 58 cut-backs, 25 s), clay uplift with the pipe free in the geostatic step (98.67).
foreach(deck pipe_sand_uplift pipe_sand_uplift_smooth pipe_clay_uplift pipe_sand_lateral_tiny
             pipe_sand_uplift_tiny_psi5 pipe_clay_uplift_tiny_free)
  pipe_soil_test(${deck} 0.02 "regression;plasticity;slow" ${scaled_600})
endforeach()
