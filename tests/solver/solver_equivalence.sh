#!/bin/bash
# solver_equivalence.sh FRIX DECK SOLVER [--rel R] [--abs A] [--ranks P [--same-solver]]
#
# Runs DECK as written and again with "SOLVER <SOLVER>" in its STATIC section (a SOLVER line
# of the deck is replaced), each in a scratch folder, and compares the two listings with
# tests/compare.sh: every number within R of itself or A of its block's largest value
# (defaults 1e-8 and 1e-9; a block of round-off around zero, such as a sum of reactions of
# 1e-15, within 1e-12), the same steps and increments. Two solvers round differently: the
# residual norms of the iterations (the ITERATION LOG blocks) are round-off once converged,
# and an increment that converges at its tolerance's edge may take one iteration more, so
# those blocks and the iteration counts of the increments' titles are left out; what is
# compared is the converged answer of every increment. The environment
# (PETSC_OPTIONS, say) reaches both runs. --ranks P: the second run is `mpirun -n P` (a frix
# built with PETSc, docs/parallel.md; as root with --allow-run-as-root --oversubscribe), and
# every column of the CSV files both runs write (history, contact) is compared too, within R
# of itself or A of its column's largest value; with --same-solver the first run uses SOLVER
# <SOLVER> too (on one process), so that only the number of processes differs (for decks
# whose Newton tolerances leave more room than 1e-8 between two solvers). Exit status: 0 equal, 1 different or a run
# failed, 2 usage error.
set -u
[ $# -ge 3 ] || { echo "usage: solver_equivalence.sh FRIX DECK SOLVER [--rel R] [--abs A]" >&2; exit 2; }
frix=$1
deck=$2
solver=$3
shift 3
rel=1e-8
abs=1e-9
ranks=1
same_solver=0
while [ $# -gt 0 ]; do
    case "$1" in
        --rel) rel=$2; shift 2 ;;
        --abs) abs=$2; shift 2 ;;
        --ranks) ranks=$2; shift 2 ;;
        --same-solver) same_solver=1; shift ;;
        *) echo "solver_equivalence.sh: unknown option $1" >&2; exit 2 ;;
    esac
done
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
work=$(mktemp -d)
base=$(basename "$deck" .dck)
deck_dir=$(cd "$(dirname "$deck")" && pwd)
# the copy stays next to the original so that its mesh files are found
copy=$deck_dir/.${base}_solver_$$.dck
trap 'rm -rf "$work" "$copy"' EXIT
awk -v solver="$solver" '
    /^[[:space:]]*SOLVER[[:space:]]/ { next }
    { print }
    /-STATIC[[:space:]]*$/ { print "SOLVER       " solver }' "$deck" > "$copy"
grep -q "^SOLVER       $solver" "$copy" || { echo "solver_equivalence.sh: no STATIC section in $deck" >&2; exit 2; }
first_deck=$deck
first_base=$base
reference="the deck's solver"
if [ "$same_solver" = 1 ]; then
    first_deck=$copy
    first_base=.${base}_solver_$$
    reference="SOLVER $solver on one process"
fi
"$frix" "$first_deck" --out "$work/default" --quiet || { echo "FAIL: the run with $reference failed"; exit 1; }
launcher=()
if [ "$ranks" -gt 1 ]; then
    launcher=(mpirun -n "$ranks" --oversubscribe)
    [ "$(id -u)" -eq 0 ] && launcher+=(--allow-run-as-root)
fi
"${launcher[@]}" "$frix" "$copy" --out "$work/other" --quiet ||
    { echo "FAIL: the run with SOLVER $solver on $ranks processes failed"; exit 1; }
# the converged answers: without the ITERATION LOG blocks and the titles' iteration counts
answers() {
    awk '/^[^ \t#]/ { skip = ($0 ~ /^ITERATION LOG/) } !skip' "$1" | sed 's/ ITERATIONS *[0-9]*$//' > "$2"
}
answers "$work/default/${first_base}_listing.txt" "$work/default.answers"
answers "$work/other/.${base}_solver_$$_listing.txt" "$work/other.answers"
bash "$here/../compare.sh" "$work/default.answers" "$work/other.answers" \
    --rel "$rel" --abs "$abs" --floor 1e-12 || { echo "FAIL: SOLVER $solver differs from $reference"; exit 1; }
if [ "$ranks" -gt 1 ]; then
    n_csv=0
    for csv in "$work/default/${first_base}"*.csv; do
        [ -e "$csv" ] || continue
        other=$work/other/.${base}_solver_$$${csv#"$work/default/${first_base}"}
        [ -e "$other" ] || { echo "FAIL: $(basename "$csv") has no counterpart from $ranks processes"; exit 1; }
        python3 "$here/compare_csv_columns.py" "$csv" "$other" --rel "$rel" --abs "$abs" ||
            { echo "FAIL: $(basename "$csv") differs on $ranks processes"; exit 1; }
        n_csv=$((n_csv + 1))
    done
    echo "($n_csv CSV files compared column by column)"
fi
processes=
[ "$ranks" -gt 1 ] && processes=" on $ranks processes"
echo "PASS: SOLVER $solver$processes agrees with $reference (--rel $rel --abs $abs)"
