#!/bin/bash
# check_ring_meshes.sh MESH...
#
# Each MESH was written by inputs/meshes/ring_mesh.py, which records its command line in the
# file's $Comments section ("command: ring_mesh.py ARGS -o NAME"). Run that command again in a
# scratch folder and require the same file, byte for byte: the committed meshes of the V4 and
# S6(a) decks are what the generator writes today. Exit 0 when all agree.
set -u
[ $# -ge 1 ] || { echo "usage: check_ring_meshes.sh MESH..." >&2; exit 2; }
here=$(cd "$(dirname "$0")" && pwd)
generator=$here/../../inputs/meshes/ring_mesh.py
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
status=0
for mesh in "$@"; do
    command=$(sed -n 's/^command: ring_mesh.py //p' "$mesh")
    if [ -z "$command" ]; then
        echo "FAIL $mesh: no 'command: ring_mesh.py ...' line"; status=1; continue
    fi
    name=$(basename "$mesh")
    # the recorded output name is the file's own name
    (cd "$work" && /usr/bin/python3 "$generator" $command 2>/dev/null) || { echo "FAIL $mesh: ring_mesh.py $command"; status=1; continue; }
    if cmp -s "$mesh" "$work/$name"; then
        echo "ok   $mesh: ring_mesh.py $command"
    else
        echo "FAIL $mesh differs from what ring_mesh.py $command writes now:"
        diff "$mesh" "$work/$name" | head -10
        status=1
    fi
done
exit $status
