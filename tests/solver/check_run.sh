#!/usr/bin/env bash
# Runs frix on a deck that must fail in a controlled way and checks what the user sees.
#   check_run.sh FRIX DECK EXPECTED_STATUS "fragment[|fragment...]" [file that must exist ...]
# Passes when: the exit status equals EXPECTED_STATUS, stderr+stdout contain every fragment
# (several are separated by '|'),
# there is no Fortran runtime error or backtrace, every listed result file exists (the
# results of converged increments are kept when a run fails), no text result file holds
# NaN or an infinity (the finite-value guard, docs/solver.md), and neither the output nor a
# result file holds the asterisks of a number too wide for its edit descriptor.
set -u
frix=$1; deck=$2; expected_status=$3; fragment=$4; shift 4
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
"$frix" "$deck" --out "$out" > "$out/stdout" 2> "$out/stderr"
status=$?
fail=0
if [ "$status" -ne "$expected_status" ]; then
  echo "FAIL: exit status $status, expected $expected_status"; fail=1
fi
IFS='|' read -ra fragments <<< "$fragment"
for piece in "${fragments[@]}"; do
  if ! grep -qF -- "$piece" "$out/stdout" "$out/stderr"; then
    echo "FAIL: output lacks \"$piece\""; fail=1
  fi
done
if grep -qE 'Fortran runtime error|Backtrace|SIGSEGV|ERROR STOP' "$out/stdout" "$out/stderr"; then
  echo "FAIL: crash output"; fail=1
fi
nonfinite=$(find "$out" -type f ! -name stdout ! -name stderr -exec grep -IliE '(^|[^a-z])(nan|inf|infinity)([^a-z]|$)' {} +)
if [ -n "$nonfinite" ]; then echo "FAIL: NaN or Inf in $nonfinite"; fail=1; fi
overflowed=$(find "$out" -type f -exec grep -IlF '*****' {} +)
if [ -n "$overflowed" ]; then echo "FAIL: a number printed as asterisks in $overflowed"; fail=1; fi
for f in "$@"; do
  if [ ! -s "$out/$f" ]; then echo "FAIL: result file $f missing"; fail=1; fi
done
if [ $fail -ne 0 ]; then
  echo "--- stdout (tail)"; tail -20 "$out/stdout"; echo "--- stderr"; cat "$out/stderr"
  exit 1
fi
echo "ok: $(basename "$deck"): status $status, \"$fragment\" found"
