#!/bin/sh
# Runs frix on tests/pos3d/pos3d_block.dck (RESULTS: VTK Yes POS3D Yes) and checks the
# POS3D neutral file against the run's VTK files (tests/pos3d/check_roundtrip.py).
# Usage: tests/pos3d/pos3d_roundtrip_test.sh FRIX_BINARY
# Exit 0 pass, 1 fail, 77 skipped (frix wrote no .pos: POS3D output not wired yet).
set -u
if [ $# -ne 1 ]; then echo "usage: $0 FRIX_BINARY" >&2; exit 2; fi
frix=$1
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/frix_pos3d_roundtrip.XXXXXX") || exit 1
trap 'rm -rf "$work"' EXIT
if ! "$frix" "$here/pos3d_block.dck" --out "$work/run" --quiet > "$work/frix.log" 2>&1; then
    cat "$work/frix.log"; echo "FAILED: frix run"; exit 1
fi
if [ ! -f "$work/run/pos3d_block.pos" ]; then
    echo "SKIPPED: frix wrote no run/pos3d_block.pos (POS3D output not wired into the driver)"; exit 77
fi
/usr/bin/python3 "$here/../../postproc/pos3d_reader.py" "$work/run/pos3d_block.pos" --summary || exit 1
/usr/bin/python3 "$here/check_roundtrip.py" "$work/run/pos3d_block"
