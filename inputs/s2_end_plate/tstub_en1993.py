#!/usr/bin/python3
"""Closed forms for the S2 T-stub (docs/verification/s2.md), for the geometry of
generate_s2_decks.py, and the reading of a run's history.

usage: tstub_en1993.py [HISTORY_CSV ...]

Without arguments prints the EN 1993-1-8 resistances and stiffnesses of the T-stub; with the
histories of S2 runs (<base>_history.csv) also each run's force at 1 and 2 mm, initial
stiffness and plastic resistance. Standard library only. Forces in kN, lengths in mm unless
the name says _m.

Sources (all partial factors gamma = 1):
- EN 1993-1-8:2005 6.2.4.1, Table 6.2: resistances of a T-stub flange, modes 1 (Method 1 and
  the alternative Method 2), 2 and 3; n = e_min <= 1.25 m; M_pl = 0.25 sum(l_eff) t_f^2 f_y;
  e_w = d_w / 4; L_b the bolt elongation length.
- EN 1993-1-8 6.2.6.4.1 and Figure 6.8: m = w/2 - t_w/2 - 0.8 r for a rolled column.
- EN 1993-1-8 Table 3.4: F_t,Rd = k_2 f_ub A_s, k_2 = 0.9.
- EN 1993-1-8 6.3.2, Table 6.11: stiffness coefficients of a bolt row, column flange in bending
  k_4 = 0.9 l_eff t_f^3 / m^3, bolts in tension k_10 = 1.6 A_s / L_b; in series, the rows in
  parallel; force per displacement = E k.
- The elastic beam model of the T-stub (below, beam_stiffness): the flange a beam clamped at
  the plastic hinge line (m from the bolt), the bolt a spring at m, the tip at m + n resting on
  the rigid plate; Euler-Bernoulli deflections of a cantilever under a point load (Roark,
  Table 8.1 case 1a).
"""
import csv
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import generate_s2_decks as geo  # noqa: E402

F_Y = geo.SIGY_PLATE / 1000.0                 # N/mm^2 = MPa: 240
F_Y_BOLT = geo.SIGY_BOLT / 1000.0             # 1000 (the seed's bolt; also f_ub of a 10.9 bolt)
E = geo.YOUNG / 1000.0                        # 210000 MPa
L_EFF = 2 * geo.L_HALF                        # the T-stub's length: 300 (Table 6.4: 300.6)
N_BOLTS = 4                                   # two rows of two bolts
D_WASHER = 37.0


def hinge_distance():
    """m of EN 1993-1-8 Figure 6.8: bolt axis to 0.8 r from the web's face: 36.1 mm."""
    return geo.X_BOLT - geo.T_W / 2 - 0.8 * geo.R_ROOT


def prying_distance():
    """n = e_min <= 1.25 m: 45 mm."""
    return min(geo.B_HALF - geo.X_BOLT, 1.25 * hinge_distance())


def plastic_moment():
    """M_pl = 0.25 sum(l_eff) t_f^2 f_y, N mm."""
    return 0.25 * L_EFF * geo.T_F ** 2 * F_Y


def resistances():
    """The T-stub's design resistances (kN), gamma = 1: a dict by name."""
    m, n, mpl = hinge_distance(), prying_distance(), plastic_moment()
    e_w = D_WASHER / 4
    bt_en = N_BOLTS * 0.9 * F_Y_BOLT * geo.A_S            # sum F_t,Rd = 882 kN (in N)
    bt_model = N_BOLTS * F_Y_BOLT * geo.A_S                # the mesh's bolts yield: 980 kN
    return {
        "mode1_method1": 4 * mpl / m / 1000,
        "mode1_method2": (8 * n - 2 * e_w) * mpl / (2 * m * n - e_w * (m + n)) / 1000,
        "mode2": (2 * mpl + n * bt_en) / (m + n) / 1000,
        "mode2_model_bolts": (2 * mpl + n * bt_model) / (m + n) / 1000,
        "mode3": bt_en / 1000,
        "mode3_model_bolts": bt_model / 1000,
    }


def en_stiffness():
    """E (k_4 + k_10 in series, two rows in parallel), kN/mm: EN 1993-1-8 Table 6.11 with the
    row's effective length in the group, l_eff = L_EFF / 2."""
    m = hinge_distance()
    k4 = 0.9 * (L_EFF / 2) * geo.T_F ** 3 / m ** 3
    k10 = 1.6 * geo.A_S / geo.L_B
    return 2 * E / (1 / k4 + 1 / k10) / 1000


def beam_stiffness(width=L_EFF):
    """Initial stiffness (kN/mm) of the beam model: a flange strip of the given width
    (E / (1 - nu^2), plate bending), clamped at the hinge line, the bolts (2 per width of the
    full T-stub: N_BOLTS / 2) a spring E A_s / L_b at m, the tip at m + n on the rigid plate.
    The clamp moves by d; compatibility at the bolt (w = B / k_b) and at the tip (w = 0) gives
    the bolt force B and the prying force Q; the force is F = B - Q."""
    m, n = hinge_distance(), prying_distance()
    a = m + n
    ei = E / (1 - geo.NU ** 2) * width * geo.T_F ** 3 / 12
    k_b = N_BOLTS / 2 * E * geo.A_S / geo.L_B
    # cantilever deflection at x under a point load P at s (upward +): P x^2 (3 s - x) / (6 EI)
    # for x <= s, P s^2 (3 x - s) / (6 EI) for x >= s. Unknowns B (bolt, down) and Q (tip, up)
    # for d = 1: d + w(m) = B / k_b, d + w(a) = 0.
    c_bm = -m ** 3 / (3 * ei)                              # w(m) per unit B
    c_qm = m ** 2 * (3 * a - m) / (6 * ei)                 # w(m) per unit Q
    c_ba = -m ** 2 * (3 * a - m) / (6 * ei)                # w(a) per unit B
    c_qa = a ** 3 / (3 * ei)                               # w(a) per unit Q
    # [c_bm - 1/k_b, c_qm; c_ba, c_qa] [B; Q] = [-1; -1]
    det = (c_bm - 1 / k_b) * c_qa - c_qm * c_ba
    b = (-c_qa + c_qm) / det
    q = (-(c_bm - 1 / k_b) + c_ba) / det
    return (b - q) / 1000


def read_history(path):
    """Columns of a history CSV as lists of floats, by name."""
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: [float(r[k]) for r in rows] for k in rows[0]}


def tstub_curve(history):
    """(web displacement mm, T-stub force kN, bolt force per bolt kN, prying force of the
    T-stub kN) over the last step of a history (the web's pull; a preloaded deck preloads in
    step 1): the model is a quarter of the T-stub with one bolt."""
    rows = [i for i, s in enumerate(history["step"]) if s == history["step"][-1]]
    u = [1000 * history["u3_mean_web_top"][i] for i in rows]
    force = [4 * history["r3_sum_web_top"][i] for i in rows]
    bolt = [-history["r3_sum_bolt_end"][i] for i in rows]
    prying = [4 * history["c3_pair1"][i] for i in rows]
    return u, force, bolt, prying


def plastic_resistance(u, force, plastic_from=1.0):
    """The intersection of the elastic tangent (the first increment's secant from the origin)
    and the plastic tangent (least-squares line through the points with u >= plastic_from):
    returns (F_p, u_p, elastic slope, plastic slope)."""
    k_el = force[0] / u[0]
    pts = [(x, f) for x, f in zip(u, force) if x >= plastic_from - 1e-9]
    mx = sum(x for x, _ in pts) / len(pts)
    mf = sum(f for _, f in pts) / len(pts)
    k_pl = sum((x - mx) * (f - mf) for x, f in pts) / sum((x - mx) ** 2 for x, _ in pts)
    f0 = mf - k_pl * mx
    u_p = f0 / (k_el - k_pl)
    return f0 + k_pl * u_p, u_p, k_el, k_pl


def value_at(u, values, target):
    """Linear interpolation of values at the displacement target."""
    for (u0, v0), (u1, v1) in zip(zip(u, values), zip(u[1:], values[1:])):
        if u0 - 1e-12 <= target <= u1 + 1e-12:
            return v0 + (v1 - v0) * (target - u0) / (u1 - u0)
    raise ValueError("displacement %g outside the run" % target)


def main():
    if any(a in ("-h", "--help") for a in sys.argv[1:]):
        print(__doc__)
        return 0
    print("m = %.2f mm, n = %.2f mm, sum l_eff = %.0f mm, M_pl = %.4f kNm" % (
        hinge_distance(), prying_distance(), L_EFF, plastic_moment() / 1e6))
    for name, value in resistances().items():
        print("%-20s %8.1f kN" % (name, value))
    print("EN 1993-1-8 Table 6.11 stiffness %.0f kN/mm; beam model %.0f kN/mm" % (
        en_stiffness(), beam_stiffness()))
    for path in sys.argv[1:]:
        u, force, bolt, prying = tstub_curve(read_history(path))
        f_p, u_p, k_el, k_pl = plastic_resistance(u, force)
        print("%s: F(1 mm) %.1f, F(2 mm) %.1f kN; bolt %.1f kN, prying %.1f kN at 2 mm; "
              "k_el %.0f kN/mm, k_pl %.1f kN/mm, F_p %.1f kN at %.3f mm" % (
                  os.path.basename(path), value_at(u, force, 1.0), value_at(u, force, 2.0),
                  value_at(u, bolt, 2.0), value_at(u, prying, 2.0), k_el, k_pl, f_p, u_p))
    return 0


if __name__ == "__main__":
    sys.exit(main())
