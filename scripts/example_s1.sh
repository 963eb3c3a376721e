#!/usr/bin/env bash
# Benchmark S1 (elastic block on a rigid base with Coulomb friction, Hird & Russell): runs
# inputs/s1_block/s1_rigid_plane.dck with build/frix and plots the interface displacement at
# every load level against the analytical solution (postproc/s1_analytical.py).
#   scripts/example_s1.sh [--out DIR]       (default DIR: inputs/s1_block/results)
# The frix executable is build/frix, or $FRIX if set. Needs /usr/bin/python3 with numpy,
# matplotlib and meshio (scripts/setup.sh installs them).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
out=$root/inputs/s1_block/results
while [ $# -gt 0 ]; do
    case "$1" in
        --out) [ $# -ge 2 ] || { echo "example_s1.sh: --out needs a folder" >&2; exit 2; }
               out=$2; shift 2 ;;
        -h|--help) sed -n '2,7p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; exit 0 ;;
        *) echo "example_s1.sh: unknown argument '$1' (usage: example_s1.sh [--out DIR])" >&2
           exit 2 ;;
    esac
done
frix=${FRIX:-$root/build/frix}
[ -x "$frix" ] || { echo "example_s1.sh: no frix executable at $frix (build first: scripts/setup.sh)" >&2; exit 1; }
python=/usr/bin/python3
deck=$root/inputs/s1_block/s1_rigid_plane.dck
mkdir -p "$out"
"$frix" "$deck" --out "$out" --quiet
# interface -u_x at every load level of step 2 against w(x) of the theory (plot), the table
# (free-end error, slipping nodes, slip front per level) and the values per node (CSV)
"$python" "$root/postproc/s1_analytical.py" curves --sign -1 -o "$out/s1_theory.csv"
"$python" "$root/postproc/s1_analytical.py" compare "$out/s1_rigid_plane.pvd" \
    --json "$out/s1_comparison.json" --csv "$out/s1_interface.csv" \
    --plot "$out/s1_interface_ux.png" | tee "$out/s1_comparison.txt"
echo "results: $out/s1_rigid_plane.pvd (ParaView), $out/s1_rigid_plane_listing.txt, $out/s1_rigid_plane_contact.csv"
echo "plot:    $out/s1_interface_ux.png (theory: $out/s1_theory.csv; table: $out/s1_comparison.txt)"
