#!/bin/bash
# Error-case test: check_error_case.sh <frix binary> <deck>
# Runs `<frix> --check <deck>` and asserts that
#   - the exit status is non-zero, but neither 2 (usage error) nor >= 128 (signal / crash),
#   - stderr contains every fragment given on the deck's `// EXPECT: <fragment>` lines
#     (fixed strings; at least one EXPECT line is required),
#   - the output holds no "Fortran runtime error", "Backtrace" or "SIGSEGV",
#   - with a `// EXPECT_ERRORS: <n>` line, the deck is rejected with exactly n errors (the
#     summary line "<deck>: n error(s) in the deck"): no mistake missed, none reported twice.
# Exit 0 when all hold, 1 otherwise (with a message saying which check failed).
set -u
if [ $# -ne 2 ]; then
  echo "usage: $0 <frix binary> <deck>" >&2
  exit 2
fi
frix=$1
deck=$2
if [ ! -x "$frix" ]; then echo "FAIL: no executable $frix" >&2; exit 1; fi
if [ ! -f "$deck" ]; then echo "FAIL: no deck $deck" >&2; exit 1; fi

# frix ends a rejected deck with exit status 1 through exit_with_status (src/core/frix_process.f90,
# C exit(): no STOP banner, no backtrace). gfortran's runtime prints a backtrace on `error stop`
# and on runtime errors unless GFORTRAN_ERROR_BACKTRACE=0; it is switched off so that the
# output holds only frix's messages and, on a crash, the runtime error message, which is what
# the checks below look for (a signal shows as exit status >= 128).
export GFORTRAN_ERROR_BACKTRACE=0

workdir=$(mktemp -d)
trap 'rm -rf "$workdir"' EXIT
"$frix" --check "$deck" >"$workdir/stdout" 2>"$workdir/stderr"
status=$?

failed=0
fail() { echo "FAIL: $*" >&2; failed=1; }

if [ "$status" -eq 0 ]; then
  fail "exit status 0: the deck was accepted"
elif [ "$status" -eq 2 ]; then
  fail "exit status 2 (usage error)"
elif [ "$status" -ge 128 ]; then
  fail "exit status $status (killed by a signal: a crash)"
fi
for word in "Fortran runtime error" "Backtrace" "SIGSEGV"; do
  if grep -qF "$word" "$workdir/stdout" "$workdir/stderr"; then fail "output contains \"$word\""; fi
done

n_expect=0
while IFS= read -r fragment; do
  n_expect=$((n_expect + 1))
  if ! grep -qF -- "$fragment" "$workdir/stderr"; then
    fail "stderr lacks the expected fragment: $fragment"
  fi
done < <(sed -n 's/^[[:space:]]*\/\/[[:space:]]*EXPECT:[[:space:]]*//p' "$deck" | sed 's/[[:space:]]*$//')
if [ "$n_expect" -eq 0 ]; then fail "the deck has no // EXPECT: line"; fi

n_errors=$(sed -n 's/^[[:space:]]*\/\/[[:space:]]*EXPECT_ERRORS:[[:space:]]*\([0-9]*\).*/\1/p' "$deck")
if [ -n "$n_errors" ] && ! grep -q ": $n_errors error(s) in the deck" "$workdir/stderr"; then
  fail "expected exactly $n_errors error(s) in the deck"
fi

if [ "$failed" -ne 0 ]; then
  echo "---- exit status: $status; stderr of $frix --check $deck:" >&2
  cat "$workdir/stderr" >&2
  exit 1
fi
echo "ok: $(basename "$deck") rejected as expected (exit status $status)"
exit 0
