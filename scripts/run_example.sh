#!/usr/bin/env bash
# Installs and builds what is needed (scripts/setup.sh), then runs an example.
#   scripts/run_example.sh                 benchmark S1 (block on a rigid base with Coulomb
#                                          friction) with its plot against the theory
#   scripts/run_example.sh DECK [opts...]  any deck, options passed to frix (e.g. --out DIR)
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
echo "run_example: installing and building (log: build.setup.log) ..."
"$root/scripts/setup.sh" "$root/build" > "$root/build.setup.log" 2>&1 ||
  { tail -40 "$root/build.setup.log"; exit 1; }
if [ $# -eq 0 ]; then
  exec "$root/scripts/example_s1.sh"
fi
deck=$1
shift
exec "$root/build/frix" "$deck" "$@"
