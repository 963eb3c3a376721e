#!/bin/bash
# penalty_sweep.sh OUTDIR [BENCHMARK...]
#
# The penalty sweeps of docs/verification/penalty.md: each benchmark deck of inputs/ is run
# with the penalties and contact laws of its table, and one CSV per benchmark collects the key
# quantities, Newton iterations and augmentations. The decks are derived from inputs/ by editing
# the PAIR line only: METHOD, TMETHOD, EPSN, EPST, PENTOL and PREDICT are removed and the run's
# settings appended (a mesh FILE path is made absolute); they are written to OUTDIR/<benchmark>/
# with each run's console log and results.
#
# Benchmarks (default: all but s4b; the default set takes about 10 minutes on one core, s4b
# 2 more, most of it S3 with mu = 0.1):
#   v5   two-pass patch test, EPSN 1e7-1e13 penalty, 1e6-1e9 augmented (PENTOL 1e-12 / 1e-11,
#        and 1e-10 at 1e8)
#   s1   block on a deformable base, EPSN 1e3-1e7 (EPST = k_s = 1e4 held)
#   s5   buried pipe mu 0.5, EPSN 1e4-1e7 (EPST 1e6 held)
#   s3   punch, coarse mesh, mu 0.5 and 0.1, EPSN 1e5-1e8 (EPST 1e6 held)
#   s4   block on a rigid plane, EPST 1e3-1e6 (EPSN 1e8), friction augmented (TMETHOD Augmented);
#        the penalty also at EPST 1e7
#   s4b  the pull to full sliding, (EPSN, EPST) of its table, friction augmented
#   s3f  S3 coarse mu 0.5 and 0.1, EPSN 1e8 held, EPST 1e4-1e7, friction augmented
#   s5f  S5 mu 0.5, EPSN 1e6 held, EPST 1e4-1e7, friction augmented
# Each setting runs with the penalty law (no METHOD keywords) and with METHOD Augmented (and
# TMETHOD Augmented where the friction is augmented).
#
# Environment: FRIX the frix binary (default build/frix of the project root); PREDICT which
# augmented runs: both (default: the multipliers' predictor on, and `PREDICT No` as the
# tables' columns without it), yes (the default predictor only) or no.
# Output: OUTDIR/<benchmark>.csv, columns benchmark, deck, method, tmethod, EPSN, EPST, PENTOL,
# PREDICT, the quantities (bench/penalty_sweep_extract.py), t_end, Newton iterations,
# augmentations, increments ended at the augmentation limit, exit code, wall seconds. Exit
# status 1 when a run failed (its row says which).
set -u
root=$(cd "$(dirname "$0")/.." && pwd)
frix=${FRIX:-$root/build/frix}
predict=${PREDICT:-both}
extract="/usr/bin/python3 $root/bench/penalty_sweep_extract.py"

if [ $# -lt 1 ] || [ "$1" = -h ] || [ "$1" = --help ]; then
    sed -n '2,/^set -u/p' "$0" | sed '$d; s/^# \{0,1\}//'
    exit 2
fi
out=$1; shift
benchmarks=("$@")
[ ${#benchmarks[@]} -gt 0 ] || benchmarks=(v5 s1 s5 s3 s4 s3f s5f)
failed=0
for bench in "${benchmarks[@]}"; do
    case $bench in v5|s1|s5|s3|s4|s4b|s3f|s5f) ;;
    *) echo "penalty_sweep.sh: unknown benchmark $bench (v5 s1 s5 s3 s4 s4b s3f s5f)" >&2; exit 2 ;; esac
done
case $predict in both|yes|no) ;; *) echo "penalty_sweep.sh: PREDICT must be both, yes or no" >&2; exit 2 ;; esac
[ -x "$frix" ] || { echo "penalty_sweep.sh: no frix binary at $frix (set FRIX)" >&2; exit 2; }
mkdir -p "$out" || exit 2
out=$(cd "$out" && pwd)

# make_deck SRC DST SETTING...: SRC with its PAIR line's law keywords replaced by SETTING...
make_deck() {
    local src=$1 dst=$2; shift 2
    local dir; dir=$(cd "$(dirname "$src")" && pwd)
    sed -e "/^PAIR /{s/ \(METHOD\|TMETHOD\|EPSN\|EPST\|PENTOL\|PREDICT\) [^ ]*//g; s/ *\$/ $*/}" \
        -e "s#^FILE  *\([^/ ]\)#FILE $dir/\1#" "$src" > "$dst"
}

# value KEY SETTING...: the value of KEY among the settings, or "-"
value() {
    local key=$1; shift
    while [ $# -ge 2 ]; do
        [ "$1" = "$key" ] && { echo "$2"; return; }
        shift 2
    done
    echo -
}

# run BENCHMARK NAME SRC SETTING...: one frix run of SRC with SETTING... on its PAIR line, its
# row appended to OUTDIR/BENCHMARK.csv
run() {
    local bench=$1 name=$2 src=$3; shift 3
    local dir=$out/$bench
    mkdir -p "$dir"
    make_deck "$root/$src" "$dir/$name.dck" "$@"
    local method tmethod pred start rc seconds
    method=$(value METHOD "$@"); [ "$method" = - ] && method=Penalty
    tmethod=$(value TMETHOD "$@"); [ "$tmethod" = - ] && tmethod=Penalty
    pred=$(value PREDICT "$@"); [ "$method" = Augmented ] && [ "$pred" = - ] && pred=Yes
    start=$(date +%s%N)
    "$frix" "$dir/$name.dck" --out "$dir" > "$dir/$name.log" 2>&1
    rc=$?
    [ $rc -eq 0 ] || failed=$((failed + 1))
    seconds=$(( ($(date +%s%N) - start) / 1000000 ))
    # an extraction that fails (its error on stderr) leaves the row's quantities out and counts
    local fields
    fields=$($extract "$bench" "$dir/$name" "$dir/$name.log") || failed=$((failed + 1))
    echo "$bench,$(basename "$src" .dck),$method,$tmethod,$(value EPSN "$@"),$(value EPST "$@"),$(value PENTOL "$@"),$pred,$fields,$rc,$((seconds / 1000)).$(printf %03d $((seconds % 1000)))" \
        >> "$out/$bench.csv"
    tail -n 1 "$out/$bench.csv"
}

# penalty / augmented BENCHMARK NAME SRC SETTING...: the penalty law; the augmented one (the
# normal part, plus the friction where TMETHOD Augmented is among the settings), once per
# PREDICT variant
penalty() { run "$1" "$2_penalty" "$3" "${@:4}"; }
augmented() {
    [ "$predict" = no ] || run "$1" "$2_augmented" "$3" METHOD Augmented "${@:4}"
    [ "$predict" = yes ] || run "$1" "$2_augmented_pno" "$3" METHOD Augmented "${@:4}" PREDICT No
}

start_csv() {
    echo "benchmark,deck,method,tmethod,EPSN,EPST,PENTOL,PREDICT,$($extract --header "$1"),exit_code,seconds" \
        > "$out/$1.csv"
    rm -f "$out/$1"/*  2>/dev/null
}

for bench in "${benchmarks[@]}"; do
    case $bench in
    v5)
        start_csv v5; deck=inputs/v5_contact_patch/v5_u3_2pass_augmented.dck
        for e in 1.0e7 1.0e8 5.0e8 1.0e9 1.0e10 1.0e11 1.0e12 1.0e13; do penalty v5 "v5_epsn$e" $deck EPSN $e; done
        augmented v5 v5_epsn1.0e6_pentol1e-12 $deck EPSN 1.0e6 PENTOL 1.0e-12
        augmented v5 v5_epsn1.0e7_pentol1e-12 $deck EPSN 1.0e7 PENTOL 1.0e-12
        augmented v5 v5_epsn1.0e8_pentol1e-10 $deck EPSN 1.0e8 PENTOL 1.0e-10
        for e in 1.0e7 1.0e8 5.0e8 1.0e9; do augmented v5 "v5_epsn$e" $deck EPSN $e PENTOL 1.0e-11; done ;;
    s1)
        start_csv s1; deck=inputs/s1_block/s1_deformable_base.dck
        penalty s1 s1_epsn1.0e3 $deck EPSN 1.0e3 EPST 1.0e4
        for e in 1.0e4 1.0e5 1.0e6 1.0e7; do
            penalty s1 "s1_epsn$e" $deck EPSN $e EPST 1.0e4
            augmented s1 "s1_epsn$e" $deck EPSN $e EPST 1.0e4
        done ;;
    s5)
        start_csv s5; deck=inputs/s5_buried_pipe/s5_mu0.5_augmented_epsn1e6.dck
        for e in 1.0e4 1.0e5 1.0e6 1.0e7; do
            penalty s5 "s5_epsn$e" $deck EPSN $e EPST 1.0e6
            augmented s5 "s5_epsn$e" $deck EPSN $e EPST 1.0e6
        done ;;
    s3)
        start_csv s3
        for mu in 0.5 0.1; do
            for e in 1.0e5 1.0e6 1.0e7 1.0e8; do
                penalty s3 "s3_mu${mu}_epsn$e" inputs/s3_punch/s3_coarse_mu$mu.dck EPSN $e EPST 1.0e6
                augmented s3 "s3_mu${mu}_epsn$e" inputs/s3_punch/s3_coarse_mu$mu.dck EPSN $e EPST 1.0e6
            done
        done ;;
    s4)
        start_csv s4; deck=inputs/s4_block/s4_block.dck
        for t in 1.0e3 1.0e4 1.0e5 1.0e6; do
            penalty s4 "s4_epst$t" $deck EPSN 1.0e8 EPST $t
            augmented s4 "s4_epst$t" $deck EPSN 1.0e8 EPST $t TMETHOD Augmented
        done
        penalty s4 s4_epst1.0e7 $deck EPSN 1.0e8 EPST 1.0e7 ;;
    s4b)
        start_csv s4b; deck=inputs/s4_block/s4b_block.dck
        for pair in 1.0e8:1.0e3 1.0e8:1.0e4 1.0e8:1.0e5 1.0e8:1.0e6 1.0e6:1.0e4 1.0e7:1.0e4 1.0e9:1.0e4; do
            e=${pair%:*}; t=${pair#*:}
            penalty s4b "s4b_epsn${e}_epst$t" $deck EPSN $e EPST $t
            augmented s4b "s4b_epsn${e}_epst$t" $deck EPSN $e EPST $t TMETHOD Augmented
        done ;;
    s3f)
        start_csv s3f
        for mu in 0.5 0.1; do
            for t in 1.0e4 1.0e5 1.0e6 1.0e7; do
                penalty s3f "s3f_mu${mu}_epst$t" inputs/s3_punch/s3_coarse_mu$mu.dck EPSN 1.0e8 EPST $t
                augmented s3f "s3f_mu${mu}_epst$t" inputs/s3_punch/s3_coarse_mu$mu.dck EPSN 1.0e8 EPST $t TMETHOD Augmented
            done
        done ;;
    s5f)
        start_csv s5f; deck=inputs/s5_buried_pipe/s5_mu0.5_augmented_epsn1e6.dck
        for t in 1.0e4 1.0e5 1.0e6 1.0e7; do
            penalty s5f "s5f_epst$t" $deck EPSN 1.0e6 EPST $t
            augmented s5f "s5f_epst$t" $deck EPSN 1.0e6 EPST $t TMETHOD Augmented
        done ;;
    esac
done
if [ $failed -gt 0 ]; then
    echo "penalty_sweep.sh: $failed runs ended with a non-zero exit code (column exit_code)" >&2
    exit 1
fi
