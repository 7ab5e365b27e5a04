#!/usr/bin/env python3
"""Which readings of Zhou 2018's pulse count can give its nominal row (Table 4): a bound from the
paper's own numbers and the x impulse balance, independent of the chaser's mass and of the pilot
model (docs/invsim.md, "Why Zhou's nominal x counts are unreachable").

Usage: /usr/bin/python3 python/invsim_study/zhou_pulse_bounds.py [--dock-x M] [--z-excursion M] [--attitude DEG]

A reading counts C_d = sum over the openings i of direction d's group of c(dtau_i) pulses. Its
spread rho is the ratio of the largest to the smallest impulse one counted pulse can carry,
sup / inf of F dtau / c(dtau) over the openings App. B allows (k tau < dtau <= tau, eq. 3). rho = 1:
the count is proportional to opening time (any width w, k, horizon, Q, inverse model). ceil(dtau/w)
(Chaser's `paper` reading): rho = ceil_count_spread(w, k). One count per opening or per step
(Chaser's `smooth`): rho = 1/k. Counting per thruster instead of per group multiplies c by the two
thrusters a group switches and leaves rho as it is.

The bound (mass-free; eq. 2 of the paper: x'' - 2 n z' = u_x). With I+ and I- the x+ and x-
impulses over the run divided by the mass, n the orbital rate, Z a bound on |z(t) - z(0)|:
  (i)  the chaser docks at rest or closing (final x' <= 0): I+ - I- <= -x'(0) + 2 n Z = A;
  (ii) it covers x(0) - x_dock in T = 1300 s, and x'(t) >= x'(0) - I- - 2 n Z:
       I- >= (x(0) - x_dock) / T + x'(0) - 2 n Z = B.
The counts are per body axis; with pitch and yaw within theta the Hill x part of the body-x impulses
is at least cos(theta) I+ - I-, and the y and z groups' impulses I_o add at most sin(theta) I_o
to either side. A reading with spread rho gives C j <= I <= rho C j per direction (j: the smallest
impulse per counted pulse over the mass, the same for every group), so (i) and (ii) hold together
only if D / E <= A / B or D <= 0, with D = cos(theta) C+ - rho (C- + sin(theta) C_o) and
E = rho (C- + sin(theta) C_o); rho_star is the smallest such rho. theta = 0 in the nominal run
(balanced pairs, no environmental torque in the paper's truth; Chaser's nominal attitude is 0 to
rounding). n is bounded by the rate of an orbit at the Earth's surface (the paper prints no
altitude). Eq. 1's terms that eq. 2 drops are below 1e-9 m/s over the run.
"""
import argparse
import json
import math
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from calibrate_invsim import ROW, TABLES_CPP  # noqa: E402  the paper's tables, one copy (C++)

MU_EARTH = 3.986004418e14  # [m^3/s^2]
R_EARTH = 6378137.0  # [m]
N_MAX = math.sqrt(MU_EARTH / R_EARTH**3)  # [rad/s] no Earth orbit turns faster

# Zhou 2018, Table 3.
X0_M = 100.038
Z0_M = -0.023
VX0_MPS = -0.0076
DURATION_S = 1300.0
STEP_S = 1.0
ENVELOPE_M = (4.0, 2.42, 2.42)
K_TABLE3 = 0.35


def paper_rows(path=TABLES_CPP):
    """Zhou 2018, Tables 4 and 5 as printed: {label: (x+, x-, y+, y-, z+, z-)}, the `---` rows left out."""
    text = path.read_text()
    split = text.index("kTable5")
    rows = ({}, {})
    for m in ROW.finditer(text):
        if m[2] == "true":
            rows[m.start() > split][m[1]] = tuple(int(v) for v in m[3].split(","))
    return rows


PAPER_TABLE4, PAPER_TABLE5 = paper_rows()
PAPER_NOMINAL = PAPER_TABLE4["nominal"]

TOLERANCE = 0.15  # Zhou 2018 target (1): within 15 % of Table 4
# Our assumptions where the paper prints nothing: the docking point at most Chaser's 10 m plus the
# envelope's half length; z held within the envelope's half width of its start (the inverse model
# moves the chaser "along the desired trajectory", section 2, and z* = 0 in the corridor).
DOCK_X_MAX_M = 10.0 + ENVELOPE_M[0] / 2.0
Z_EXCURSION_M = ENVELOPE_M[2] / 2.0 + abs(Z0_M)


def x_balance_terms(dock_x_m=DOCK_X_MAX_M, z_excursion_m=Z_EXCURSION_M, n=N_MAX):
    """(A, B) of (i) and (ii), in m/s."""
    coupling = 2.0 * n * z_excursion_m
    a = -VX0_MPS + coupling
    b = (X0_M - dock_x_m) / DURATION_S + VX0_MPS - coupling
    return a, b


def fits(rho, c_pos, c_neg, c_other, a, b, attitude_rad=0.0):
    """Whether a reading of spread rho can give counts c_pos, c_neg on x (c_other on y and z)."""
    if b <= 0.0:
        return True  # (ii) is empty: the balance does not constrain the counts
    cross = c_neg + math.sin(attitude_rad) * c_other
    d = math.cos(attitude_rad) * c_pos - rho * cross
    return d <= 0.0 or d / (rho * cross) <= a / b


def rho_star(c_pos, c_neg, c_other, a, b, attitude_rad=0.0):
    """Smallest spread rho for which the x counts satisfy (i) and (ii)."""
    if fits(1e-9, c_pos, c_neg, c_other, a, b, attitude_rad):
        return 0.0
    lo, hi = 1e-9, 1e3
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (lo, mid) if fits(mid, c_pos, c_neg, c_other, a, b, attitude_rad) else (mid, hi)
    return hi


def paper_x(counts, tolerance=0.0):
    """(x+, x-, y and z) of a row, each moved by the tolerance the way that eases the bound."""
    return (counts[0] * (1.0 - tolerance), counts[1] * (1.0 + tolerance), sum(counts[2:]) * (1.0 + tolerance))


def z_excursion_for(rho, counts, dock_x_m=DOCK_X_MAX_M, attitude_rad=0.0, n=N_MAX):
    """The smallest bound Z on |z - z0| with which a reading of spread rho can give the x counts."""
    lo, hi = 0.0, 100.0
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        a, b = x_balance_terms(dock_x_m, mid, n)
        lo, hi = (lo, mid) if fits(rho, *counts, a, b, attitude_rad) else (mid, hi)
    return hi


def attitude_for(rho, counts, a, b):
    """The smallest attitude bound theta [deg] with which a reading of spread rho can give the x counts."""
    lo, hi = 0.0, 30.0
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        lo, hi = (lo, mid) if fits(rho, *counts, a, b, math.radians(mid)) else (mid, hi)
    return hi


def ceil_count_spread(w, k=K_TABLE3, tau=STEP_S):
    """rho of the count ceil(dtau / w) over the openings k tau < dtau <= tau.

    On ((n-1) w, n w] the count is n and the impulse per pulse dtau / n runs from (n-1) w / n
    (not reached) to n w / n; the first and the last interval are cut by k tau and tau.
    """
    n_first = max(1, math.floor(k * tau / w) + 1)
    n_last = math.ceil(tau / w - 1e-12)
    sup, inf = 0.0, math.inf
    for n in range(n_first, n_last + 1):
        sup = max(sup, min(n * w, tau) / n)
        inf = min(inf, max((n - 1) * w, k * tau) / n)
    return sup / inf


def largest_excluded_width(rho, k=K_TABLE3, lo=1e-3, hi=1.0, steps=20000):
    """Largest w of a fine grid below which every ceil(dtau / w) reading has spread < rho."""
    last = None
    for i in range(steps + 1):
        w = lo + (hi - lo) * i / steps
        if ceil_count_spread(w, k) >= rho:
            return last
        last = w
    return last


def most_pulses_per_axis(row):
    return max(row[0] + row[1], row[2] + row[3], row[4] + row[5])


# Which direction a failed thruster's group pushes (Table 1): d +x, d~ -x, e -y, e~ +y, f +z, f~ -z.
GROUP_DIRECTION = {("d", False): 0, ("d", True): 1, ("e", True): 2, ("e", False): 3, ("f", False): 4, ("f", True): 5}


def lost_directions(label):
    """The directions (0..5, x+ ... z-) that lose one thruster in a Table 2/5 label ("d1/d2~+e2/e1~")."""
    return [GROUP_DIRECTION[(tok[0], tok.endswith("~"))] for part in label.split("+") for tok in part.split("/")]


def share_rise(nominal, label):
    """Rise of P over nominal [%] if each direction that loses one of its two thrusters doubles its
    nominal count and the others stay: the sum of those directions' shares of P."""
    return 100.0 * sum(nominal[d] for d in lost_directions(label)) / sum(nominal)


def printed_rise(row):
    return 100.0 * (sum(row) / sum(PAPER_NOMINAL) - 1.0)


def share_scorecard(nominal):
    """Targets (3)-(5) predicted from nominal counts by the share model, against the paper's rows."""
    rises = {m: share_rise(nominal, m) for m in PAPER_TABLE4 if m != "nominal"}
    within = sum(abs(r - printed_rise(PAPER_TABLE4[m])) <= 10.0 for m, r in rises.items())
    worst4 = set(sorted(rises, key=lambda m: -rises[m])[:4])
    ratios = [1.0 + share_rise(nominal, m) / 100.0 for m in PAPER_TABLE5]
    return {"rise_within": within, "z_doubles_worst": worst4 == {"f1/f1~", "f2/f1~", "f1/f2~", "f2/f2~"},
            "table5": (min(ratios), max(ratios)), "table5_in_band": sum(1.3 <= r <= 1.6 for r in ratios)}


def report_shares():
    err4 = max(abs(share_rise(PAPER_NOMINAL, m) - printed_rise(r)) for m, r in PAPER_TABLE4.items() if m != "nominal")
    err5 = max(abs(share_rise(PAPER_NOMINAL, m) - printed_rise(r)) for m, r in PAPER_TABLE5.items())
    print(f"share model on the paper's own rows: rise = the lost directions' nominal shares of P, "
          f"off the printed rise by at most {err4:.1f} points (16 Table 4 rows), {err5:.1f} (12 Table 5 rows)")
    mean_x = (PAPER_NOMINAL[0] + PAPER_NOMINAL[1]) / 2.0
    cases = [("the paper's nominal", PAPER_NOMINAL),
             (f"the paper's, x+ = x- = {mean_x:g} (what the balance allows)", (mean_x, mean_x) + PAPER_NOMINAL[2:]),
             ("Chaser `paper` without noise (w = 0.06 s, Q diag(1, 1, 1, 10, 3, 0.03))",
              (164, 157, 183, 322, 99, 332))]
    print("| nominal counts | z share | y share | rises within 10 pt | z doubles worst | Table 5 ratio (in 1.3-1.6) |")
    print("|---|---|---|---|---|---|")
    for name, counts in cases:
        s = share_scorecard(counts)
        total = sum(counts)
        print(f"| {name}: {'/'.join(f'{c:g}' for c in counts)} | {100 * (counts[4] + counts[5]) / total:.0f} % | "
              f"{100 * (counts[2] + counts[3]) / total:.0f} % | {s['rise_within']} of 16 | "
              f"{'yes' if s['z_doubles_worst'] else 'no'} | {s['table5'][0]:.2f}-{s['table5'][1]:.2f} "
              f"({s['table5_in_band']} of {len(PAPER_TABLE5)}) |")


def report(dock_x_m, z_excursion_m, attitude_deg):
    a, b = x_balance_terms(dock_x_m, z_excursion_m)
    theta = math.radians(attitude_deg)
    exact, box = paper_x(PAPER_NOMINAL), paper_x(PAPER_NOMINAL, TOLERANCE)
    rho_exact, rho_box = rho_star(*exact, a, b, theta), rho_star(*box, a, b, theta)
    print(f"n <= {N_MAX:.4e} rad/s; dock x <= {dock_x_m:g} m; |z - z0| <= {z_excursion_m:g} m; "
          f"|pitch|, |yaw| <= {attitude_deg:g} deg")
    print(f"(i)  I+ - I- <= A = {a:.4f} m/s;  (ii) I- >= B = {b:.4f} m/s;  A/B = {a / b:.3f}")
    print(f"paper nominal x+/x- = {PAPER_NOMINAL[0]}/{PAPER_NOMINAL[1]}: needs spread rho >= {rho_exact:.3f}")
    print(f"x+ >= {box[0]:.1f}, x- <= {box[1]:.1f}, y and z <= {box[2]:.0f} (within {TOLERANCE:.0%}): "
          f"needs rho >= {rho_box:.3f}")
    for rho in (1.0,):
        print(f"  rho = {rho:.3f} fits the exact x counts only with |z - z0| >= "
              f"{z_excursion_for(rho, exact, dock_x_m, theta):.2f} m or attitude >= {attitude_for(rho, exact, a, b):.2f} deg; "
              f"within {TOLERANCE:.0%}: {z_excursion_for(rho, box, dock_x_m, theta):.2f} m or "
              f"{attitude_for(rho, box, a, b):.2f} deg")
    for x_dock in (0.0, 12.0, 30.0, 50.0):
        aa, bb = x_balance_terms(x_dock, z_excursion_m)
        print(f"  dock x <= {x_dock:g} m: rho >= {rho_star(*exact, aa, bb, theta):.3f} exact, "
              f"{rho_star(*box, aa, bb, theta):.3f} within {TOLERANCE:.0%}")
    print()
    spreads = bounds(dock_x_m, z_excursion_m, attitude_deg)

    def verdict(rho):
        return "no" if rho < spreads["rho_needed"] else "not excluded"
    print(f"| count per opening | spread rho (k = {K_TABLE3}) | can give x+/x- within {TOLERANCE:.0%} |")
    print("|---|---|---|")
    print(f"| proportional to opening time (dtau / w, any w) | {spreads['proportional']:.3f} | "
          f"{verdict(spreads['proportional'])} |")
    for c in spreads["ceil"]:
        print(f"| ceil(dtau / {c['width_s']:g} s) | {c['rho']:.3f} | {verdict(c['rho'])} |")
    print(f"| one per opening or per step (`smooth`) | {spreads['smooth']:.3f} | {verdict(spreads['smooth'])} |")
    for k in (0.35, 0.2, 0.1, 0.05):
        w = largest_excluded_width(rho_box, k)
        print(f"k = {k:g}: every ceil(dtau / w) with w <= {w:.3f} s has rho < {rho_box:.3f}" if w else
              f"k = {k:g}: no ceil(dtau / w) with w >= 1 ms has rho < {rho_box:.3f}")
    print()
    steps = int(DURATION_S / STEP_S)
    rows = {**PAPER_TABLE4, **PAPER_TABLE5}
    over = [f"{m} {most_pulses_per_axis(r)}" for m, r in rows.items() if most_pulses_per_axis(r) > steps]
    print(f"pulses on one axis beyond its {steps} steps: {', '.join(over)}: a count of at most one pulse "
          f"per opening (one opening per axis and step) {'cannot' if over else 'can'} be the paper's")
    odd = sum(c % 2 for r in rows.values() for c in r)
    print(f"odd counts: {odd} of {6 * len(rows)} printed: a count per thruster of a group's two "
          f"thrusters switched together (always even) {'cannot' if odd else 'can'} be the paper's")
    print()
    report_shares()


def bounds(dock_x_m, z_excursion_m, attitude_deg):
    """What report() prints of the count's spread, as data: the spread a reading needs for x+ and x-
    within the tolerance, and each count's spread at Table 3's k."""
    a, b = x_balance_terms(dock_x_m, z_excursion_m)
    rho_box = rho_star(*paper_x(PAPER_NOMINAL, TOLERANCE), a, b, math.radians(attitude_deg))
    return {"k": K_TABLE3, "tolerance": TOLERANCE, "rho_needed": rho_box,
            "proportional": 1.0, "smooth": 1.0 / K_TABLE3,
            "ceil": [{"width_s": w, "rho": ceil_count_spread(w)}
                     for w in (0.02, 0.04, 0.06, 0.1, 0.12, 0.15, 0.2, 0.3, 0.5, 1.0)],
            "largest_excluded_width_s": largest_excluded_width(rho_box, K_TABLE3)}


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--dock-x", type=float, default=DOCK_X_MAX_M, help="largest final x [m]")
    ap.add_argument("--z-excursion", type=float, default=Z_EXCURSION_M, help="bound on |z - z0| [m]")
    ap.add_argument("--attitude", type=float, default=0.0, help="bound on |pitch|, |yaw| [deg]")
    ap.add_argument("--out", type=pathlib.Path, help="also write DIR/pulse_bounds.json: the spreads and the bound "
                                              "(docs/invsim.md's table is made from it)")
    args = ap.parse_args()
    report(args.dock_x, args.z_excursion, args.attitude)
    if args.out:
        args.out.mkdir(parents=True, exist_ok=True)
        (args.out / "pulse_bounds.json").write_text(json.dumps(bounds(args.dock_x, args.z_excursion, args.attitude),
                                                               indent=1) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
