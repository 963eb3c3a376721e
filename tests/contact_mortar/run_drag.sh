#!/bin/bash
# run_drag.sh FRIX DECK MU [--check KEY=LO:HI]...: frix on DECK in a scratch folder
# (tests/contact_v5v6/run_common.sh), then check_drag.py on its contact CSV.
set -u
[ $# -ge 3 ] || { echo "usage: run_drag.sh FRIX DECK MU [--check KEY=LO:HI]..." >&2; exit 2; }
frix=$1; deck=$2; mu=$3; shift 3
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../contact_v5v6/run_common.sh"
run_in_scratch run_drag.sh "$frix" "$deck"
awk '$2 == "stat" && $3 == "newton_iterations" { print "Newton iterations:", $4 }' "$work/run.log"
/usr/bin/python3 "$here/check_drag.py" "$work/$(basename "$deck" .dck)" --mu "$mu" "$@"
