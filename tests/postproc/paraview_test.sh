#!/bin/bash
# ParaView reads frix's output (docs/output.md, "ParaView"): pvpython, headless under
# xvfb-run, opens the .pvd of inputs/examples/block_tension (a 2 x 1 x 1 bar, E = 1000, nu = 0,
# pulled by a traction 1 at x = 2), warps it by 100 x the displacement, colours it by u_x and
# saves a PNG. Checks: the last time step is t = 2; the warped bar ends at
# x = 2 + 100 u_x = 2.2, with u_x = p L / E = 2e-3 (closed form); the colour range is u_x's,
# 0 to 2e-3; the PNG is 640 x 480 and the bar covers part of it (pixels unlike the background).
# Exit 77 (ctest: skipped) without pvpython or xvfb-run (Debian: apt-get install paraview xvfb).
# Usage: paraview_test.sh FRIX
set -u
frix=$1
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
for tool in pvpython xvfb-run; do
    command -v "$tool" > /dev/null || { echo "SKIPPED: $tool not installed"; exit 77; }
done
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
"$frix" "$root/inputs/examples/block_tension/block_tension.dck" --out "$work" --quiet || { echo "FAIL: frix run"; exit 1; }
# xvfb-run with an authority file of its own (-f): xvfb-runs at the same time otherwise share
# ~/.Xauthority, and one's cookie can replace another's ("bad X server connection"); up to 3
# attempts for that message, and only for it
for attempt in 1 2 3; do
    xvfb-run -a -f "$work/Xauthority" pvpython "$here/paraview_render.py" "$work/block_tension.pvd" 100 "$work/bar.png" \
        > "$work/pv.log" 2>&1 && break
    grep -q "bad X server connection" "$work/pv.log" && [ $attempt -lt 3 ] && { sleep 2; continue; }
    echo "FAIL: pvpython"; cat "$work/pv.log"; exit 1
done
cat "$work/pv.log"
/usr/bin/python3 - "$work/pv.log" "$work/bar.png" <<'PY'
import sys
import numpy as np
import matplotlib.image
values = {}
for line in open(sys.argv[1]):
    words = line.split()
    if words and words[0] in ("time", "bounds", "colour_range"):
        values[words[0]] = [float(w) for w in words[1:]]
fail = 0
def check(ok, text):
    global fail
    fail |= not ok
    print(("ok   " if ok else "FAIL ") + text)
check(abs(values["time"][0] - 2.0) < 1e-12, "last time step t = 2")
x_max = values["bounds"][1]
check(abs(x_max - 2.2) < 1e-9, f"warped bar ends at x = {x_max:.9g} (2 + 100 x 2e-3 = 2.2)")
low, high = values["colour_range"]
check(abs(low) < 1e-12 and abs(high - 2e-3) < 1e-12, f"colour range {low:.3g} .. {high:.6g} (0 .. 2e-3)")
image = matplotlib.image.imread(sys.argv[2])
background = image[0, 0, :3]
covered = np.mean(np.any(np.abs(image[:, :, :3] - background) > 0.02, axis=2))
check(image.shape[:2] == (480, 640) and 0.02 < covered < 0.9,
      f"PNG {image.shape[1]} x {image.shape[0]}, the bar on {100 * covered:.1f} % of it")
sys.exit(fail)
PY
