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
#   augmentations, and of the run with the least CPU time among REPEATS runs:
#   cpu_s    the process's CPU seconds, user + system (GNU time; on a loaded machine the
#            least disturbed measure), with the reading, output and set-up both laws share
#   solve_s  the solution's wall seconds, assembly + analyse + factorize + solve (frix's stat
#            lines: the work of the Newton iterations)
# Environment: FRIX the binary (default build/frix of the project root), REPEATS (default 3).
# The derived decks and logs go to OUTDIR (default a temporary directory, removed).
set -u
root=$(cd "$(dirname "$0")/.." && pwd)
frix=${FRIX:-$root/build/frix}
repeats=${REPEATS:-3}
[ -x "$frix" ] || { echo "augmented_cost.sh: no frix binary at $frix (set FRIX)" >&2; exit 2; }
command -v /usr/bin/time > /dev/null || { echo "augmented_cost.sh: needs GNU time (apt-get install time)" >&2; exit 2; }
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

# run NAME DECK METHOD: the least CPU time of REPEATS runs of DECK, its CSV row
run() {
    local name=$1 deck=$2 method=$3 best="" r rc log=$out/$1.log cpu
    for ((r = 1; r <= repeats; r++)); do
        OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1 /usr/bin/time -f '%U %S' -o "$out/time" \
            "$frix" "$deck" --out "$out/$name" > "$log.$r" 2>&1
        rc=$?
        cpu=$(awk '{printf "%.2f", $1 + $2}' "$out/time")
        if [ -z "$best" ] || awk -v a="$cpu" -v b="$best" 'BEGIN {exit !(a < b)}'; then
            best=$cpu; cp "$log.$r" "$log"
        fi
    done
    echo "$name,$method,$rc,$(stat "$log" newton_iterations),$(grep -c ' reused .* iter' "$log")," \
         "$(stat "$log" factorizations_total),$(stat "$log" assemblies),$(stat "$log" augmentations),$best," \
         "$(solution_seconds "$log")" | tr -d ' '
}

echo "deck,method,exit,newton,reused,factorizations,assemblies,augmentations,cpu_s,solve_s"
for deck in "${decks[@]}"; do
    name=$(basename "$deck" .dck)
    run "$name" "$root/$deck" Augmented
    sed -e "/^PAIR /{s/ \(METHOD\|TMETHOD\|PENTOL\|PREDICT\|MAXAUG\|PENGROW\|PENRATE\|PENCAP\) [^ ]*//g}" \
        "$root/$deck" > "$out/${name}_penalty.dck"
    run "${name}_penalty" "$out/${name}_penalty.dck" Penalty
done
