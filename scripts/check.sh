#!/usr/bin/env bash
# Extra checks beyond scripts/test.sh.
#   scripts/check.sh long [extra ctest arguments]
#       Builds frix (Release, in build, as scripts/test.sh) and runs the tests labelled `long`
#       (15-60 s each in Release, left out of the default set to keep it under 5 minutes:
#       the S3 path-following and friction-continuation runs, the necking bar to its peak, the
#       strip footing against Prandtl, S4b at finite strain), two at a time. Prints the wall
#       time.
#   scripts/check.sh sanitize [extra ctest arguments]
#       Installs what is missing and builds frix and its tests in build-sanitize with the
#       CMake build type Sanitize (scripts/setup.sh build-sanitize Sanitize): AddressSanitizer
#       with LeakSanitizer, UBSan, gfortran's -fcheck=all and floating-point traps (invalid,
#       division by zero, overflow). Then runs the default test set there (every ctest except
#       those labelled `slow`, two at a time), less the tests labelled `long` (over 5 minutes
#       each in this build; scripts/check.sh long runs them in Release; here: ctest -L long in
#       build-sanitize). Any sanitizer report (heap/stack overflow,
#       use after free, a leak at exit, undefined behaviour) aborts the program (SIGABRT), which
#       fails its test; so does a floating-point trap (SIGFPE) or a runtime check. Prints the
#       wall time. Exit status: ctest's (0 when every test passed).
#       Example: scripts/check.sh sanitize -R unit_io     (only the matching tests)
#   scripts/check.sh petsc [extra ctest arguments]
#       Installs Debian's PETSc (scripts/setup.sh --petsc), builds frix with it in build-petsc
#       and runs the tests labelled petsc there (SOLVER Petsc against the deck's own solver,
#       also on 2 MPI processes, tests/solver/petsc.cmake). Prints the wall time.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)

usage() { echo "usage: $0 long|sanitize|petsc [extra ctest arguments]" >&2; exit 2; }
[ $# -ge 1 ] || usage
mode=$1
shift

case "$mode" in
  long)
    start=$(date +%s)
    build_dir=$root/build
    "$root/scripts/setup.sh" "$build_dir"
    built=$(date +%s)
    status=0
    (cd "$build_dir" && ctest --output-on-failure -L long -LE slow -j2 "$@") || status=$?
    end=$(date +%s)
    echo "check.sh long: build $((built - start)) s, tests $((end - built)) s, wall time $((end - start)) s"
    exit $status
    ;;
  sanitize)
    start=$(date +%s)
    build_dir=$root/build-sanitize
    "$root/scripts/setup.sh" "$build_dir" Sanitize
    built=$(date +%s)
    # abort_on_error: a report ends the program with SIGABRT (exit status 134), which every
    # test script takes for a crash (an error case also accepts any status 1..127, so a plain
    # exit code would not do). Settings already in the environment are appended: they win.
    export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:halt_on_error=1${ASAN_OPTIONS:+:$ASAN_OPTIONS}"
    export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:abort_on_error=1${UBSAN_OPTIONS:+:$UBSAN_OPTIONS}"
    status=0
    (cd "$build_dir" && ctest --output-on-failure -LE "slow|long" -j2 "$@") || status=$?
    end=$(date +%s)
    echo "check.sh sanitize: build $((built - start)) s, tests $((end - built)) s, wall time $((end - start)) s"
    exit $status
    ;;
  petsc)
    start=$(date +%s)
    build_dir=$root/build-petsc
    FRIX_BUILD_TARGET=frix "$root/scripts/setup.sh" --petsc "$build_dir" Release
    built=$(date +%s)
    status=0
    (cd "$build_dir" && ctest --output-on-failure -L petsc -j2 "$@") || status=$?
    end=$(date +%s)
    echo "check.sh petsc: build $((built - start)) s, tests $((end - built)) s, wall time $((end - start)) s"
    exit $status
    ;;
  *)
    usage
    ;;
esac
