#!/usr/bin/env bash
# Installs and builds what is needed (scripts/setup.sh), then runs the default test set:
# every ctest except those labelled `slow` or `long` (run those with: ctest --test-dir build
# -L slow; scripts/check.sh long runs the `long` ones, as CI does).
#   scripts/test.sh [extra ctest arguments]
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$root/scripts/setup.sh" "$root/build"
cd "$root/build"
ctest --output-on-failure -LE "slow|long" -j2 "$@"
