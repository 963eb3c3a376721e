#!/usr/bin/env bash
# Kinematic couplings against closed forms (the references are in the decks' headers):
#   check_coupling.sh FRIX DIR_OF_DECKS
# cantilever_axial (reaction E A u / L), cantilever_loads (force and moment at the reference
# and rotation nodes: beam theory, exact for nu = 0), cantilever_torsion (Saint-Venant, mesh
# tolerance) and rigid_rotation (a free block moved rigidly: u = u_R + theta x (X - X_R),
# zero strain and reactions), rigid_punch (coupled nodes in contact: a rigid punch pressed onto a
# foundation, uniform pressure; node-to-segment and mortar contact).
set -eu
frix=$1; here=$2
out=$(mktemp -d); trap 'rm -rf "$out"' EXIT
for deck in cantilever_axial cantilever_loads cantilever_torsion rigid_rotation rigid_punch rigid_punch_mortar; do
  "$frix" "$here/$deck.dck" --out "$out" --quiet
done
/usr/bin/python3 - "$out" <<'PY'
import sys, math
import h5py
import numpy as np
out = sys.argv[1]
fail = 0
def check(label, ok, text):
    global fail
    fail |= not ok
    print(f"{'ok  ' if ok else 'FAIL'} {label}: {text}")
def relative(label, got, expected, tol):
    err = abs(got - expected) / abs(expected)
    check(label, err <= tol, f"{got:.12g} expected {expected:.12g} (rel. error {err:.1e}, tol {tol:.0e})")
def history(name):
    return np.atleast_1d(np.genfromtxt(f"{out}/{name}_history.csv", delimiter=',', names=True))[-1]
def last_increment(name):
    f = h5py.File(f"{out}/{name}.h5", 'r')
    g = f['increments'][sorted(f['increments'])[-1]]
    return f['mesh/coordinates'][()], f['mesh/node_ids'][()], g
def rigid_motion_error(name, x_ref, u_ref, theta, nodes):
    """max |u - (u_R + theta x (X - X_R))| over `nodes` (a mask), over max |u| there."""
    coords, ids, g = last_increment(name)
    u = g['displacement'][()]
    expected = u_ref + np.cross(theta, coords[nodes(coords, ids)] - x_ref)
    return np.abs(u[nodes(coords, ids)] - expected).max() / np.abs(expected).max()

E, L, A, I = 1000.0, 10.0, 1.0, 1.0 / 12.0
x_ref = np.array([10.0, 0.5, 0.5])
end_face = lambda coords, ids: (ids < 1000) & np.isclose(coords[:, 0], 10.0)

# Axial: u = 0.01 at the reference node, rotations held: R = E A u / L, exact (uniform strain).
h = history('cantilever_axial')
relative("axial: reaction at the reference node", h['r1_n1001'], E * A * 0.01 / L, 1e-12)
err = rigid_motion_error('cantilever_axial', x_ref, np.array([0.01, 0, 0]), np.zeros(3), end_face)
check("axial: end face follows the reference node", err <= 1e-12, f"rel. error {err:.1e}, tol 1e-12")

# Force F = 2 at the reference node, moment M_y = 0.01 at the rotation node (EAS 9 represents
# uniform tension and pure bending exactly; the solve's round-off is a few 1e-12).
F, M = 2.0, 0.01
h = history('cantilever_loads')
relative("loads: u_x of the reference node = F L / (E A)", h['u1_n1001'], F * L / (E * A), 1e-10)
relative("loads: theta_y = M L / (E I)", h['u2_n1002'], M * L / (E * I), 1e-10)
relative("loads: u_z of the reference node = -M L^2 / (2 E I)", h['u3_n1001'], -M * L**2 / (2 * E * I), 1e-10)
err = rigid_motion_error('cantilever_loads', x_ref, np.array([F * L / (E * A), 0, -M * L**2 / (2 * E * I)]),
                         np.array([0, M * L / (E * I), 0]), end_face)
check("loads: end face = u_R + theta x (X - X_R)", err <= 1e-10, f"rel. error {err:.1e}, tol 1e-10")

# Torsion: theta_x = 0.01; Saint-Venant T = G J theta / L, J of a square by its series.
G, theta = E / 2.0, 0.01
J = (1 - 192 / math.pi**5 * sum(math.tanh(n * math.pi / 2) / n**5 for n in range(1, 200, 2))) / 3
T_sv = G * J * theta / L
h = history('cantilever_torsion')
excess = h['r1_n100002'] / T_sv - 1
check("torsion: moment at the rotation node against Saint-Venant", 0.0 <= excess <= 0.02,
      f"T = {h['r1_n100002']:.9g}, G J theta / L = {T_sv:.9g}, T / T_SV - 1 = {excess:.4f} (in [0, 0.02])")

# Rigid motion of a free block through its coupled face.
x_ref, u_ref, theta = np.array([3.0, -1.0, 2.0]), np.array([0.001, -0.002, 0.0005]), np.array([0.002, -0.001, 0.003])
block = lambda coords, ids: ids < 1000
err = rigid_motion_error('rigid_rotation', x_ref, u_ref, theta, block)
check("rigid: every node u = u_R + theta x (X - X_R)", err <= 1e-12, f"rel. error {err:.1e}, tol 1e-12")
_, _, g = last_increment('rigid_rotation')
strain, reaction = np.abs(g['strain'][()]).max(), np.abs(g['reaction'][()]).max()
check("rigid: zero strain", strain <= 1e-14, f"max |strain| {strain:.1e} (tol 1e-14; the motion is of size 1e-2)")
check("rigid: zero reactions", reaction <= 1e-11, f"max |reaction| {reaction:.1e} (tol 1e-11; E = 1000)")

# Rigid punch on a foundation through contact: p = F / A = 2, u_z(R) = -p (H / E + 1 / EPSN).
p, H, eps_n = 8.0 / 4.0, 1.0, 1.0e4
h = history('rigid_punch')
relative("punch: u_z of the reference node = -p (H / E + 1 / EPSN)", h['u3_n9001'], -p * (H / E + 1 / eps_n), 1e-10)
moment = max(abs(h['r1_n9002']), abs(h['r2_n9002']))
check("punch: no moment at the rotation node", moment <= 1e-10, f"max |M_x|, |M_y| = {moment:.1e} (tol 1e-10; F L = 8)")
contact = np.atleast_1d(np.genfromtxt(f"{out}/rigid_punch_contact.csv", delimiter=',', names=True))
err = np.abs(contact['pressure'] / p - 1).max()
check(f"punch: contact pressure p at all {contact.size} slave nodes", contact.size == 25 and err <= 1e-10,
      f"max rel. error {err:.1e} (tol 1e-10)")
h = history('rigid_punch_mortar')
relative("punch, mortar contact: u_z of the reference node", h['u3_n9001'], -p * (H / E + 1 / eps_n), 1e-10)
sys.exit(fail)
PY
