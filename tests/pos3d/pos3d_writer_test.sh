#!/bin/sh
# Runs pos3d_writer_check (tests/pos3d/pos3d_writer_check.f90: writes neutral files from
# synthetic data and checks the writer's error returns), then tests/pos3d/check_synthetic.py on
# its files, and the reader's command line on a missing and a truncated file.
# Usage: tests/pos3d/pos3d_writer_test.sh PATH/TO/pos3d_writer_check
set -u
if [ $# -ne 1 ]; then echo "usage: $0 POS3D_WRITER_CHECK_BINARY" >&2; exit 2; fi
here=$(cd "$(dirname "$0")" && pwd)
reader="$here/../../postproc/pos3d_reader.py"
work=$(mktemp -d "${TMPDIR:-/tmp}/frix_pos3d_writer.XXXXXX") || exit 1
trap 'rm -rf "$work"' EXIT
"$1" "$work" || { echo "FAILED: pos3d_writer_check"; exit 1; }
/usr/bin/python3 "$here/check_synthetic.py" "$work" || exit 1
status=0
if /usr/bin/python3 "$reader" "$work/no_such.pos" 2> "$work/err.txt"; then
    echo "FAILED: reader accepted a missing file"; status=1
elif ! grep -q "no such file" "$work/err.txt"; then
    echo "FAILED: reader message for a missing file: $(cat "$work/err.txt")"; status=1
fi
sed "/^%END/d" "$work/synthetic.pos" > "$work/truncated.pos"
if /usr/bin/python3 "$reader" "$work/truncated.pos" 2> "$work/err.txt"; then
    echo "FAILED: reader accepted a truncated file"; status=1
elif ! grep -q "no %END" "$work/err.txt"; then
    echo "FAILED: reader message for a truncated file: $(cat "$work/err.txt")"; status=1
fi
sed 's/^5 1 2 /5 1 x /' "$work/synthetic.pos" > "$work/malformed.pos"
if /usr/bin/python3 "$reader" "$work/malformed.pos" 2> "$work/err.txt"; then
    echo "FAILED: reader accepted a malformed element record"; status=1
elif ! grep -q "malformed.pos:[0-9]*: ELEMENT.BRICK8: integration order: expected an integer" "$work/err.txt"; then
    echo "FAILED: reader message for a malformed record: $(cat "$work/err.txt")"; status=1
fi
[ $status -eq 0 ] && echo "reader error messages: 3 passed, 0 failed"
exit $status
