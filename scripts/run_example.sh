#!/usr/bin/env bash
# Installs and builds what is needed (scripts/setup.sh), then runs an example deck.
#   scripts/run_example.sh [DECK] [frix options...]
# Default deck: inputs/examples/block_tension/block_tension.dck. Results go beside the deck
# unless --out DIR is given.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$root/scripts/setup.sh" "$root/build" > "$root/build.setup.log" 2>&1 ||
  { tail -40 "$root/build.setup.log"; exit 1; }
deck=${1:-$root/inputs/examples/block_tension/block_tension.dck}
[ $# -gt 0 ] && shift
exec "$root/build/frix" "$deck" "$@"
