#!/usr/bin/env bash
# The P1 cube (bench/p1_cube.sh) solved by PETSc: MUMPS LU against GMRES with GAMG (rigid-body
# near-null space from the node positions), and frix's own direct solver (CHOLMOD), one
# linear solve each (docs/performance.md, "Iterative path").
#
# Usage: bench/p1_gamg.sh [n ...]   (default: 20 30)
# Environment:
#   FRIX        a frix built with PETSc (default: <repo>/build-petsc/frix; scripts/setup.sh --petsc)
#   P1_WORK     directory for decks and outputs (default: /tmp/frix-p1-gamg)
#   SOLVERS     which runs (default: "cholmod mumps gamg")
#   GAMG_OPTIONS  PETSc options of the iterative runs
#               (default: -ksp_type cg -pc_type gamg -ksp_rtol 1e-10 -ksp_converged_reason)
# Prints one line per run: n, equations, solver, wall s, factorize (set-up) s, solve s,
# peak memory MB (GNU time), KSP iterations (iterative runs).
set -euo pipefail
script_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo_dir=$(cd "${script_dir}/.." && pwd)
frix=${FRIX:-${repo_dir}/build-petsc/frix}
work=${P1_WORK:-/tmp/frix-p1-gamg}
solvers=${SOLVERS:-"cholmod mumps gamg"}
gamg_options=${GAMG_OPTIONS:-"-ksp_type cg -pc_type gamg -ksp_rtol 1e-10 -ksp_converged_reason"}
sizes=("$@")
[ ${#sizes[@]} -gt 0 ] || sizes=(20 30)
mkdir -p "$work"
printf '%5s %10s %8s %9s %9s %9s %8s %6s\n' n equations solver wall_s setup_s solve_s peak_MB ksp_it
for n in "${sizes[@]}"; do
   for solver in $solvers; do
      deck=$work/cube_${n}_${solver}.dck
      case $solver in
         cholmod) keyword=Cholmod ;;
         *) keyword=Petsc ;;
      esac
      cat > "$deck" <<DECK
 P1 cube ${n}^3 HEX8, ${solver}
---------------------------------------------------------PROBLEM TYP
PROBLEMTYP Structure
--------------------------------------------------------------STATIC
KINTYP Geo_Lin
MAXITER 3
SOLVER ${keyword}
---------------------------------------------------------LOAD CURVES
CURVE 1 POINTS 0.0 0.0 1.0 1.0
-----------------------------------------------------------MATERIALS
MAT 1 MAT_Struct_LinearElastic YOUNG 1000.0 NUE 0.3
----------------------------------------------------------MESH BLOCK
BLOCK cube ORIGIN 0 0 0 SIZE 1 1 1 DIVISIONS ${n} ${n} ${n}
--------------------------------------------------STRUCTURE ELEMENTS
SET cube SOLID HEX8 MAT 1
------------------------------------------------DIRICHLET CONDITIONS
SET cube_zmin DOF 1 1 1 VAL 0.0 0.0 0.0
--------------------------------------------------NEUMANN CONDITIONS
SURF cube_zmax PRESSURE 1.0 CURVE 1
---------------------------------------------------------------STEPS
STEP 1 NUMSTEP 1 CONTROL Load
-------------------------------------------------------------RESULTS
VTK No  LISTING No
-----------------------------------------------------------------END
DECK
      options=""
      [ "$solver" = gamg ] && options=$gamg_options
      log=$work/cube_${n}_${solver}.log
      PETSC_OPTIONS="$options" OPENBLAS_NUM_THREADS=1 /usr/bin/time -f 'peak_kb %M wall %e' \
         "$frix" "$deck" --out "$work/out_${n}_${solver}" > "$log" 2>&1 || { echo "run failed: $log" >&2; continue; }
      equations=$(awk '/stat equations/ {print $NF}' "$log")
      factorize=$(awk '/stat factorize_seconds/ {print $NF}' "$log")
      solve=$(awk '/stat solve_seconds/ {print $NF}' "$log")
      peak=$(awk '/^peak_kb/ {printf "%.0f", $2 / 1024}' "$log")
      wall=$(awk '/^peak_kb/ {print $4}' "$log")
      iterations=$(grep -o 'iterations [0-9]*' "$log" | grep -v "^iterations 0" | head -1 | awk '{print $2}')
      printf '%5s %10s %8s %9s %9s %9s %8s %6s\n' "$n" "$equations" "$solver" "$wall" "${factorize:--}" \
         "${solve:--}" "$peak" "${iterations:--}"
   done
done
