# Contact robustness decks (docs/testing.md "Robustness decks"), included by tests/cases.cmake,
# which defines FRIX_BIN. Small models built as users build them (MESH BLOCKs, automatic
# penalties, pressure or prescribed-displacement loads), each run to the end of its steps with
# its Newton iterations bounded; run_case.sh runs one deck and check_robustness.py checks it:
# the time reached, the converged increments (the deck's NUMSTEPs without cut-backs, at least
# that many with cut-backs), the cut-backs (the `cut-back:` lines of the run's output), the
# iterations of every increment, the sum of the reactions against the applied load (1e-6) and the closed forms
# named in each deck's title (uniform pressure, support normal force, Coulomb force mu N once
# sliding). Every deck runs in under 5 s; the ones that fail are registered DISABLED, with how
# they fail (numbers measured with the Release build, 2026-11-27).
set(robustness ${CMAKE_CURRENT_SOURCE_DIR}/contact_robustness)
function(robustness_case name)
  add_test(NAME contact_robustness_${name}
           COMMAND bash ${robustness}/run_case.sh ${FRIX_BIN} ${robustness}/${name}.dck ${ARGN})
  set_tests_properties(contact_robustness_${name} PROPERTIES LABELS "regression;contact")
endfunction()

# 1. Slave nodes on interior edges of the master surface (matching meshes, facet normals).
# The slab exactly as wide as the block, rollers: uniform uniaxial stress, p = 10 at every
# slave node (measured: 5 increments of 1 iteration, p = 10 to 1e-10).
robustness_case(edge_exact --time 1 --increments 5 --max-iterations 4
                --applied 0 0 -10 --support 1 6 --normal-force 10 --uniform-pressure 10)
# The master extending beyond the slab, frictionless, facet normals. The slab dishes the
# master, so the faces on either side of each master edge under a slave node tilt towards each
# other by 1e-5 to 1e-4 rad; each face's push along its own normal left the node nearer the
# other face, and the node changed face at every iteration (nodes 52, 54-56, 58): Newton froze at
# a relative residual of 1.9e-5 at the first increment and no increment converged, whatever
# the solver, law, MAXITER or slab mesh (t = 0.2 never reached, 6 cut-backs). With the contact
# search keeping a node's face unless another is nearer by 1e-3 of its distance
# (frix_contact_search, face_hysteresis): 5 increments of 2 iterations. Converged before with
# NORMALS Smoothed, PASSES 2, friction, or the slab moved off the master's edges.
robustness_case(edge_wide --time 1 --increments 5 --max-iterations 4
                --applied 0 0 -10 --support 1 25 --normal-force 10)
# The same pressed by u_z = -0.001 of the slab's top (froze the same way at 5.33e-5 before the
# face hysteresis; now 5 increments of 2 iterations).
robustness_case(edge_wide_disp --time 1 --increments 5 --max-iterations 4 --applied 0 0 0 --support 1 25)
# With mu = 0.3 (measured 5 x 2 iterations), with smoothed normals (5 x 2), and with mu = 0.3
# and PENALTY_FACTOR 1e4 (2, 2, 2, 2, 1).
robustness_case(edge_wide_mu --time 1 --increments 5 --max-iterations 4
                --applied 0 0 -10 --support 1 25 --normal-force 10)
robustness_case(edge_wide_smoothed --time 1 --increments 5 --max-iterations 4
                --applied 0 0 -10 --support 1 25 --normal-force 10)
robustness_case(edge_wide_stiff --time 1 --increments 5 --max-iterations 4
                --applied 0 0 -10 --support 1 25 --normal-force 10)

# 2. A slab dragged over the master, its nodes crossing master face edges (friction, Total
# Lagrangian, EXTRAPOLATION Linear). Step 1 presses (2 increments), step 2 drags by 1 in 10.
# The support's friction force is -mu N once sliding (per node |t| = mu p to 1e-6, the total to
# 1e-3: the faces' normals turn by 5e-5 under load, check_robustness.py). Measured: facet
# 5 2 15 4 2 1 2 2 2 2 2 2 2 2 2 2 2 iterations, 3 cut-backs (all in the first drag increment,
# where every node goes from stick to slip), friction force error 1.7e-5; smoothed 2 cut-backs,
# at most 11 iterations; mu = 0.05 1 cut-back, at most 8.
robustness_case(slide_edges --time 2 --increments 12 --max-iterations 20 --max-cutbacks 3
                --applied 0 0 -3 --support 1 28 --normal-force 3 --friction 2 0.3 -1)
robustness_case(slide_edges_smoothed --time 2 --increments 12 --max-iterations 15 --max-cutbacks 2
                --applied 0 0 -3 --support 1 28 --normal-force 3 --friction 2 0.3 -1)
robustness_case(slide_edges_mu005 --time 2 --increments 12 --max-iterations 20 --max-cutbacks 1
                --applied 0 0 -3 --support 1 28 --normal-force 3 --friction 2 0.05 -1)
# Without EXTRAPOLATION (the default): every increment of 0.1 starts from the last converged
# state with the slab's top moved alone, and the first correction lifts half the slab off
# (contact 12 -> 6 nodes): 5 cut-backs, 21 increments, up to 23 iterations (13 cut-backs and
# 39 increments while the line search accepted no rise of the residual). Bounded here so that
# it does not get worse; the margin is for round-off, which moves the counts.
robustness_case(slide_edges_default --time 2 --increments 12 --max-iterations 25 --max-cutbacks 8
                --applied 0 0 -3 --support 1 28 --normal-force 3 --friction 2 0.3 -1)
# The slab's middle row on the master edge y = 0.5 (master 6 x 2). Before the face hysteresis
# it stopped at the first drag increment: after 6 cut-backs the residual froze at 2.93e-5 at
# slave node 49 (0.6, 0.5) and master node 30 (1, 0.5), both on the edge, in y. Now 1 cut-back
# (the first drag increment, where every node goes from stick to slip), at most 19 iterations.
robustness_case(slide_edges_row --time 2 --increments 12 --max-iterations 20 --max-cutbacks 3
                --applied 0 0 -3 --support 1 21 --normal-force 3 --friction 2 0.3 -1)
# Stiff penalties (PENALTY_FACTOR 1e4). Failed at the first drag increment (t = 1 -> 1.1) before
# the line search's first-touch trial and the singular tangent's predicted-contact solve
# (frix_newton_solver; docs/testing.md): after 2 nodes held in stick were released, the full
# Newton step pushed the open slave node 61 1.7e-4 into the master and the line search kept
# 5 % of each step, so node 61 never entered the active set (the relative residual fell 3 %
# per iteration); where the whole slab left the master in an iterate the tangent was
# singular (slave node 63, z). Measured now: t = 2 with 10 cut-backs, 28 increments, at most
# 21 Newton iterations in one, 224 in all (1.2 s CPU). Bounds: MAXITER, 12 cut-backs.
robustness_case(slide_edges_stiff --time 2 --increments 12 --max-iterations 25 --max-cutbacks 12
                --applied 0 0 -3 --support 1 28 --normal-force 3 --friction 2 0.3 -1)

# 3. A slab dragged past the free edge of its master (drag 0.44 in 11 increments: the front
# column open beyond the extension zone, the next one clamped 0.04 beyond the edge). Measured:
# facet 2 cut-backs, at most 13 iterations; smoothed none, at most 9; mu = 0.1 none, at most 6
# (25, MAXITER, in the first drag increment while the line search accepted no rise of the
# residual). The faces near the free edge turn more under the slab's edge
# load (normals 1.6e-4 off z), so the friction force is mu N to n_x / mu only: 3e-3
# (measured 6.5e-4 with mu = 0.3, 1.5e-3 with mu = 0.1).
robustness_case(slide_off_end --time 2 --increments 13 --max-iterations 15 --max-cutbacks 2
                --applied 0 0 -3 --support 1 20 --normal-force 3 --friction 2 0.3 -1
                --friction-tolerance 3e-3)
robustness_case(slide_off_end_smoothed --time 2 --increments 13 --max-iterations 10 --max-cutbacks 1
                --applied 0 0 -3 --support 1 20 --normal-force 3 --friction 2 0.3 -1
                --friction-tolerance 3e-3)
robustness_case(slide_off_end_mu01 --time 2 --increments 13 --max-iterations 25
                --applied 0 0 -3 --support 1 20 --normal-force 3 --friction 2 0.1 -1
                --friction-tolerance 3e-3)
# Dragged on to 0.52: the third column (slave nodes 43, 47, 51) leaves the extension zone at
# t = 1.8668 (drag 0.451) carrying the largest pressures (22.6, 25.6, 22.6 against 4.6-7.1 on
# the column behind it: the slab rests on the master's edge, its load's centre passes beyond
# the edge). When the search dropped it at once, the first correction's residual was 18 x the
# reference, the next iterate had no node in contact and the run stopped at t = 1.8668 after 12
# cut-backs (also with NORMALS Smoothed, mu = 0.1, PASSES 2). With the force of a node clamped
# onto a free edge faded over the zone's outer half (frix_free_edge_zone) it reaches t = 2:
# 9 cut-backs, all from t = 1.79 on (UMFPACK finds the matrix singular at slave node 46, z:
# the slab held on the edge is near a tipping mechanism), at most 13 iterations, 27 increments.
robustness_case(slide_off_end_far --time 2 --increments 15 --max-iterations 15 --max-cutbacks 12
                --applied 0 0 -3 --support 1 20 --normal-force 3 --friction 2 0.3 -1
                --friction-tolerance 3e-3)

# 4. Stick-slip reversal: press, drag +0.05 (5 increments), back to -0.05 (10); the friction
# force is -mu N at the end of step 2 and +mu N at the end of step 3 (error 1.1e-4, the faces'
# turn). Measured: no cut-back, at most 11 iterations (the reversal's first increment); mu = 0.1
# 2 cut-backs, at most 18; PENALTY_FACTOR 1e4 14 cut-backs, at most 16 iterations (the counts
# follow round-off: 14 and 25 with threaded BLAS before the nonmonotone line search).
robustness_case(reversal --time 3 --increments 17 --max-iterations 15
                --applied 0 0 -3.6 --support 1 16 --normal-force 3.6 --friction 2 0.3 -1 --friction 3 0.3 1)
robustness_case(reversal_mu01 --time 3 --increments 17 --max-iterations 20 --max-cutbacks 2
                --applied 0 0 -3.6 --support 1 16 --normal-force 3.6 --friction 2 0.1 -1 --friction 3 0.1 1)
robustness_case(reversal_stiff --time 3 --increments 17 --max-iterations 25 --max-cutbacks 18
                --applied 0 0 -3.6 --support 1 16 --normal-force 3.6 --friction 2 0.3 -1 --friction 3 0.3 1)
# On a 2 x 2 master (the slab's middle rows on its edges, its centre node on the vertex).
# Before the face hysteresis it stopped at the first drag increment (residual frozen at 4.73e-5
# at master vertex node 14 and slave centre node 23, y; 9.69e-6 after 6 cut-backs). Now 2
# cut-backs at the reversal (t = 2 -> 2.1, as reversal_mu01), 20 increments, at most 15
# iterations.
robustness_case(reversal_vertex --time 3 --increments 17 --max-iterations 15 --max-cutbacks 2
                --applied 0 0 -3.6 --support 1 9 --normal-force 3.6 --friction 2 0.3 -1 --friction 3 0.3 1)
