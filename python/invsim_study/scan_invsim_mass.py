#!/usr/bin/env python3
"""The chaser's mass, which Zhou 2018 does not print, against the Zhou 2018 targets (1)-(6): an exploration, not
a calibration (docs/invsim.md, "The chaser's mass").

Usage: /usr/bin/python3 python/invsim_study/scan_invsim_mass.py [SCENARIO] [--masses M,M,...] [--lateral T] [--arms]
           [--arms-d D,D,...] [--arms-e E,E,...] [--chaser BIN] [--csv OUT]

For each mass (the inertia and every thrust stay the scenario's: the paper prints the thrusts, 60
and 25 N, and neither mass nor inertia), the `paper` reading is calibrated on the nominal row
exactly as calibrate_invsim.py does (the same grids, objective and descent), then the 41
modes of the baseline layout are flown with that calibration fixed and scored against the Zhou 2018
targets (1)-(6) (calibrate_invsim.targets). The objective J of each mass's calibration says which mass the
nominal row itself prefers; the targets say what the fault rows would need.

--arms also scans the lever arms of the x and y groups at each mass, under both readings (`smooth`
and the mass's calibrated `paper`): d1, d1~ at y = +D and d2, d2~ at y = -D; e1, e1~ at x = -E and
e2, e2~ at x = +E (the shipped layout: D = 1.4 m, E = 1.6 m), and reports at which (D, E) the
paper's four Table 5 modes, and only they, are lost (target 6).

Deterministic: fixed grids, one `chaser fmea` per point.
"""
import argparse
import collections
import copy
import csv
import itertools
import pathlib
import sys
import tempfile

import yaml

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import calibrate_invsim as cal  # noqa: E402

DEFAULT_MASSES = [1000.0, 2000.0, 4000.0, 8000.0]  # [kg]
DEFAULT_ARMS_D = [1.4, 1.8, 2.2, 2.6, 3.0, 3.4, 3.8]  # [m] |y| of the x group's thrusters
DEFAULT_ARMS_E = [1.6, 2.0, 2.4, 2.8, 3.2, 3.6, 4.0]  # [m] |x| of the y group's thrusters


def with_mass(scenario, mass_kg):
    doc = dict(scenario)
    doc["chaser"] = dict(scenario["chaser"], mass_kg=mass_kg)
    return doc


def with_arms(doc, arm_d_m, arm_e_m):
    """A copy of the study `doc` with the x group's thrusters at y = +-arm_d_m and the y group's at
    x = -+arm_e_m (signs as shipped: d1, d1~ at +y; e1, e1~ at -x), the other coordinates kept."""
    out = copy.deepcopy(doc)
    for thruster in out["thrusters"]:
        name, position = thruster["name"], thruster["position_body_m"]
        if name in ("d1", "d1~", "d2", "d2~"):
            position[1] = arm_d_m if name in ("d1", "d1~") else -arm_d_m
        elif name in ("e1", "e1~", "e2", "e2~"):
            position[0] = -arm_e_m if name in ("e1", "e1~") else arm_e_m
    return out


def lost_table5(rows):
    """The Table 5 modes a layout's rows (mode -> fmea.csv row) do not fly."""
    return {mode for mode, row in rows.items() if row["table"] == "table5" and row["controllable"] != "true"}


def study_mass(chaser, scenario, mass_kg, workdir, lateral=None):
    """Calibrate at this mass on the nominal row (the lateral time constant held at `lateral` if
    given), fly the baseline's modes, score the targets."""
    doc = with_mass(scenario, mass_kg)
    params, (j, counts, k_p), runs = cal.calibrate(chaser, doc, workdir, log=lambda _line: None, lateral=lateral)
    rows = cal.read_layout(cal.run_fmea(chaser, cal.paper_study(doc, params), workdir))
    return doc, params, j, cal.targets(rows)


def scan_arms(chaser, study, arms_d, arms_e, workdir):
    """(D, E) -> the lost Table 5 modes, with the study's reading."""
    return {(d, e): lost_table5(cal.read_layout(cal.run_fmea(chaser, with_arms(study, d, e), workdir)))
            for d, e in itertools.product(arms_d, arms_e)}


def describe_arms(found):
    exact = [f"({d:g}, {e:g})" for (d, e), lost in found.items() if lost == cal.PAPER_LOST]
    sizes = collections.Counter(len(lost) for lost in found.values())
    spread = ", ".join(f"{n} lost at {count}" for n, count in sorted(sizes.items()))
    return f"the paper's four exactly at {len(exact)} of {len(found)} points {' '.join(exact)}; {spread}"


def floats(text):
    return [float(v) for v in text.split(",")]


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("scenario", nargs="?", default="scenarios/manual_rvd.yaml")
    ap.add_argument("--chaser", default="build/cli/chaser")
    ap.add_argument("--masses", type=floats, default=DEFAULT_MASSES, help="chaser masses [kg]")
    ap.add_argument("--lateral", type=float, metavar="T",
                    help="hold the lateral time constant at T [s] in every calibration (0: y held at 0)")
    ap.add_argument("--arms", action="store_true", help="also scan the x and y groups' lever arms")
    ap.add_argument("--arms-d", type=floats, default=DEFAULT_ARMS_D, help="|y| of d1, d2, d1~, d2~ [m]")
    ap.add_argument("--arms-e", type=floats, default=DEFAULT_ARMS_E, help="|x| of e1, e2, e1~, e2~ [m]")
    ap.add_argument("--csv", type=pathlib.Path, help="write one row per mass here")
    args = ap.parse_args()
    scenario = yaml.safe_load(pathlib.Path(args.scenario).read_text())
    header = ["mass_kg", "J", "pulse_width_s", "q_vx", "q_vy", "q_vz", "range_sigma_m", "angle_sigma_deg",
              "lateral_time_constant_s", *cal.DIRECTIONS, "nominal_within", "k_p_within", "rise_within",
              "z_doubles_worst", "table5_in_band", "table5_flown", "same_four_lost", "spearman", "lost"]
    print("| mass [kg] | J | calibrated (w; q_v; range, angle sigma; lateral) | nominal | (1) | (2) | (3) | (4) "
          "| (5) | (6) lost | Spearman |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    table = []
    arms_lines = []
    with tempfile.TemporaryDirectory() as tmp:
        workdir = pathlib.Path(tmp)
        for mass in args.masses:
            doc, params, j, t = study_mass(args.chaser, scenario, mass, workdir, args.lateral)
            nominal = t["table4"][0]["ours"]
            ratios = t["table5_ratios"]
            span = f"{min(ratios):.2f}-{max(ratios):.2f}x" if ratios else "none flown"
            print(f"| {mass:g} | {j:.3f} | {params['w']} s; {params['qv']}; {params['range']} m, {params['angle']} deg; "
                  f"{params['lateral']:g} s | {'/'.join(map(str, nominal))} | {t['nominal_within']} | "
                  f"{t['k_p_within']} | {t['rise_within']} | {'yes' if t['z_doubles_worst'] else 'no'} | "
                  f"{t['table5_in_band']} of {len(ratios)} ({span}) | "
                  f"{'the four' if t['same_four_lost'] else (', '.join(sorted(t['lost'])) or 'none')} | "
                  f"{t['spearman']:.2f} |", flush=True)
            table.append([mass, j, params["w"], *params["qv"], params["range"], params["angle"], params["lateral"],
                          *nominal, t["nominal_within"], t["k_p_within"], t["rise_within"], t["z_doubles_worst"],
                          t["table5_in_band"], len(ratios), t["same_four_lost"], t["spearman"],
                          " ".join(sorted(t["lost"]))])
            if args.arms:
                paper = cal.paper_study(doc, params)
                smooth = dict(paper, pulses=dict(paper["pulses"], reading="smooth"))
                for name, study in (("smooth", smooth), ("paper", paper)):
                    found = scan_arms(args.chaser, study, args.arms_d, args.arms_e, workdir)
                    arms_lines.append(f"- {mass:g} kg, `{name}`: {describe_arms(found)}")
    for line in arms_lines:
        print(line)
    if args.csv:
        with open(args.csv, "w", newline="") as f:
            writer = csv.writer(f)
            writer.writerow(header)
            writer.writerows(table)
    return 0


if __name__ == "__main__":
    sys.exit(main())
