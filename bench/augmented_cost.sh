#!/bin/bash
# augmented_cost.sh [OUTDIR]
#
# The cost of the augmented Lagrangian law against the penalty law at the same penalties
# (docs/performance-contact.md, "Augmented Lagrangian against penalty"): each augmented deck of
# S1, S4 and V5 in inputs/ is run as it is (METHOD Augmented) and as a penalty deck (its PAIR
# line without METHOD, TMETHOD, PENTOL, PREDICT, MAXAUG, PENGROW, PENRATE, PENCAP: the same EPSN
# and EPST), one BLAS thread, and one CSV row per run is printed with frix's `frix: stat`
# counts:
#   newton   Newton corrections with a freshly assembled and factorized tangent
#   reused   corrections solved with the factors of an earlier tangent (the augmented law's
#            Uzawa updates between factorizations: progress lines marked `reused`)
#   factorizations, assemblies (every residual evaluation, line-search trials included),
#   augmentations, and of the run with the shortest solution time among REPEATS runs:
#   solve_s  the solution's seconds, assembly + analyse + factorize + solve (frix's stat
#            lines: the work the Newton iterations do), and total_s the whole run's (with
#            the reading, output and set-up that both laws share)
# Environment: FRIX the binary (default build/frix of the project root), REPEATS (default 3).
# The derived decks and logs go to OUTDIR (default a temporary directory, removed).
set -u
root=$(cd "$(dirname "$0")/.." && pwd)
frix=${FRIX:-$root/build/frix}
repeats=${REPEATS:-3}
[ -x "$frix" ] || { echo "augmented_cost.sh: no frix binary at $frix (set FRIX)" >&2; exit 2; }
if [ $# -ge 1 ]; then
    out=$1; mkdir -p "$out" || exit 2
else
    out=$(mktemp -d); trap 'rm -rf "$out"' EXIT
fi

decks=(inputs/s1_block/s1_deformable_base_augmented.dck
       inputs/s1_block/s1_deformable_base_augmented_eps1e4.dck
       inputs/s4_block/s4_block_augmented.dck
       inputs/s4_block/s4_block_augmented_epst1e3.dck
       inputs/v5_contact_patch/v5_u3_2pass_augmented.dck
       inputs/v5_contact_patch/v5_u3_2pass_augmented_eps1e7.dck)

# stat KEY LOG: the value of `frix: stat KEY` in LOG (0 when absent)
stat() {
    local v
    v=$(awk -v key="$2" '$1 == "frix:" && $2 == "stat" && $3 == key {print $4}' "$1")
    echo "${v:-0}"
}

# solution_seconds LOG: assembly + analyse + factorize + solve seconds of LOG
solution_seconds() {
    awk '$1 == "frix:" && $2 == "stat" && ($3 == "assembly_seconds" || $3 == "analyse_seconds" ||
         $3 == "factorize_seconds" || $3 == "solve_seconds") {s += $4} END {printf "%.4f", s}' "$1"
}

# run NAME DECK METHOD: the fastest of REPEATS runs of DECK, its CSV row
run() {
    local name=$1 deck=$2 method=$3 best="" r rc log=$out/$1.log seconds
    for ((r = 1; r <= repeats; r++)); do
        OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1 "$frix" "$deck" --out "$out/$name" > "$log.$r" 2>&1
        rc=$?
        seconds=$(solution_seconds "$log.$r")
        if [ -z "$best" ] || awk -v a="$seconds" -v b="$best" 'BEGIN {exit !(a < b)}'; then
            best=$seconds; cp "$log.$r" "$log"
        fi
    done
    echo "$name,$method,$rc,$(stat "$log" newton_iterations),$(grep -c ' reused .* iter' "$log")," \
         "$(stat "$log" factorizations_total),$(stat "$log" assemblies),$(stat "$log" augmentations),$best," \
         "$(stat "$log" total_seconds)" | tr -d ' '
}

echo "deck,method,exit,newton,reused,factorizations,assemblies,augmentations,solve_s,total_s"
for deck in "${decks[@]}"; do
    name=$(basename "$deck" .dck)
    run "$name" "$root/$deck" Augmented
    sed -e "/^PAIR /{s/ \(METHOD\|TMETHOD\|PENTOL\|PREDICT\|MAXAUG\|PENGROW\|PENRATE\|PENCAP\) [^ ]*//g}" \
        "$root/$deck" > "$out/${name}_penalty.dck"
    run "${name}_penalty" "$out/${name}_penalty.dck" Penalty
done
