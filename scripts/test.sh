#!/usr/bin/env bash
# Installs and builds what is needed (scripts/setup.sh), then runs the default test set:
# every ctest except those labelled `slow` (run those with: ctest --test-dir build -L slow).
#   scripts/test.sh [extra ctest arguments]
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$root/scripts/setup.sh" "$root/build"
cd "$root/build"
ctest --output-on-failure -LE slow -j2 "$@"
