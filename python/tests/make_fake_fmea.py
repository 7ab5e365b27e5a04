#!/usr/bin/env python3
"""A synthetic `chaser fmea SCENARIO --out DIR --history` directory, in the format of cli/fmea_report.cpp
and cli/fmea_history.cpp.

Usage: /usr/bin/python3 python/tests/make_fake_fmea.py OUTDIR [--seed S]

For testing python/plot_invsim.py without the C++ engine. Writes OUTDIR/fmea.csv (every column the
engine writes), OUTDIR/history/index.csv and one 1300-step history per layout and mode, for two
layouts (baseline, scheme_II) and three modes each: nominal, the single fault e1~ and the
multi-axis fault d1/d2~+e2/e1~ (Zhou 2018, Figs. 6, 7 and 13/16). The signals are plausible, not
simulated: x follows the desired 100 m -> 10 m approach (constant speed, then exponential damping
from 800 s), y and z stay within a metre, a fault adds a yaw excursion that the azimuth follows
(15 deg, out of the 10 deg field of view, for the multi-axis fault on the baseline: Class III; 3 deg
on scheme_II: Class II). fmea.csv agrees with the histories: pulse counts, peaks, k_p = P / 3000
(eq. 22), the risk classes and ranks of docs/invsim.md.
"""
import argparse
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from plot_invsim import HISTORY_HEADER  # noqa: E402  the history columns, in one place

FMEA_HEADER = (  # as cli/fmea_report.cpp writes it
    "configuration,mode,table,failed,x_pos,x_neg,y_pos,y_neg,z_pos,z_neg,total_pulses,k_p,"
    "peak_azimuth_deg,azimuth_limit_deg,peak_elevation_deg,elevation_limit_deg,"
    "peak_roll_deg,peak_pitch_deg,peak_yaw_deg,attitude_limit_deg,deviation_ratio,"
    "target_always_in_view,attitude_within_limits,docked,diverged,propellant_kg,"
    "attitude_propellant_kg,roll_on_time_s,pitch_on_time_s,yaw_on_time_s,controllable,risk_class,risk_rank"
).split(",")
STEPS, DT_S = 1300, 1.0
BASIC_PULSE_AMOUNT = 3000.0  # P_thrust, Table 3
AZIMUTH_LIMIT_DEG = ELEVATION_LIMIT_DEG = 10.0
ATTITUDE_LIMIT_DEG = 1.0
LARGE_DEVIATION_FRACTION = 0.5  # of the field of view: Class II above (invsim/fmea.hpp)
# (index in the engine's mode list, label, table, failed thrusters, yaw excursion [deg] per layout)
MODES = ((0, "nominal", "nominal", "", {"baseline": 0.0, "scheme_II": 0.0}),
         (11, "e1~", "table2", "e1~", {"baseline": 0.6, "scheme_II": 0.4}),
         (31, "d1/d2~+e2/e1~", "table5", "d1 d2~ e2 e1~", {"baseline": 15.0, "scheme_II": 3.0}))


def desired_x(t):
    """100 m -> 20 m at constant speed until 800 s, then exponential damping towards 10 m."""
    return np.where(t < 800.0, 100.0 - 0.1 * t, 10.0 + 10.0 * np.exp(-(t - 800.0) / 100.0))


def limit_cycle(rng, t, amplitude_deg, period_s):
    """A small attitude limit cycle with a random phase: what the phase-plane controller keeps."""
    return amplitude_deg * np.sin(2 * np.pi * t / period_s + rng.uniform(0, 2 * np.pi))


def pulses(rng, steps, p_pos, p_neg):
    """-1, 0 or +1 per step: the direction in which one axis' translation group fired."""
    draw = rng.random(steps)
    return np.where(draw < p_pos, 1, np.where(draw < p_pos + p_neg, -1, 0))


def history(rng, yaw_excursion_deg):
    """{column: array} of one mode's 1300 steps, in the paper's Hill frame."""
    t = np.arange(STEPS) * DT_S
    h = {"t_s": t, "x_desired_m": desired_x(t), "y_desired_m": np.zeros(STEPS), "z_desired_m": np.zeros(STEPS)}
    fault = yaw_excursion_deg > 0
    h["x_m"] = h["x_desired_m"] + 0.02 * np.sin(t / 37.0)
    h["y_m"] = (1.0 if fault else 0.1) * np.sin(t / 12.0) * np.exp(-t / 40.0) + 0.01 * np.sin(t / 23.0)
    h["z_m"] = -0.02 * np.exp(-t / 60.0) + 0.01 * np.sin(t / 17.0)
    for axis in "xyz":
        h[f"v{axis}_mps"] = np.gradient(h[f"{axis}_m"], DT_S)
    excursion = yaw_excursion_deg * (1.0 - np.exp(-t / 15.0)) * np.exp(-t / 150.0)
    h["roll_deg"] = limit_cycle(rng, t, 0.3 + 0.1 * fault, 160.0)
    h["pitch_deg"] = limit_cycle(rng, t, 0.25, 210.0)
    h["yaw_deg"] = limit_cycle(rng, t, 0.3, 130.0) + excursion
    h["azimuth_deg"] = 1.04 * h["yaw_deg"] + np.degrees(np.arctan2(h["y_m"], h["x_m"]))
    h["elevation_deg"] = h["pitch_deg"] - np.degrees(np.arctan2(h["z_m"], h["x_m"]))
    for axis in "xyz":
        h[f"u{axis}_mps2"] = np.gradient(h[f"v{axis}_mps"], DT_S) + rng.normal(0.0, 1e-3, STEPS)
    extra = 0.02 if fault else 0.0
    h["pulse_x"] = pulses(rng, STEPS, 0.03 + extra, 0.02)
    h["pulse_y"] = pulses(rng, STEPS, 0.025, 0.03 + extra)
    h["pulse_z"] = pulses(rng, STEPS, 0.005, 0.03)
    for axis in "xyz":  # the smooth reading: one pulse per fired step
        h[f"count_{axis}"] = np.abs(h[f"pulse_{axis}"])
    return h


def fmea_row(configuration, label, table, failed, h):
    """The fmea.csv fields of one mode, computed from its history (risk_rank filled in later)."""
    counts = {f"{axis}_{name}": int(np.sum(h[f"pulse_{axis}"] == sign))
              for axis in "xyz" for sign, name in ((1, "pos"), (-1, "neg"))}
    total = sum(counts.values())
    peak = {name: float(np.max(np.abs(h[f"{name}_deg"]))) for name in ("azimuth", "elevation", "roll", "pitch", "yaw")}
    deviation = max(peak["azimuth"] / AZIMUTH_LIMIT_DEG, peak["elevation"] / ELEVATION_LIMIT_DEG)
    in_view = deviation <= 1.0
    attitude_ok = max(peak["roll"], peak["pitch"], peak["yaw"]) <= ATTITUDE_LIMIT_DEG
    controllable = in_view  # docked in every fake mode
    risk = "III" if not controllable else ("II" if deviation > LARGE_DEVIATION_FRACTION or not attitude_ok else "I")
    return {"configuration": configuration, "mode": label, "table": table, "failed": failed, **counts,
            "total_pulses": total, "k_p": total / BASIC_PULSE_AMOUNT,
            "peak_azimuth_deg": peak["azimuth"], "azimuth_limit_deg": AZIMUTH_LIMIT_DEG,
            "peak_elevation_deg": peak["elevation"], "elevation_limit_deg": ELEVATION_LIMIT_DEG,
            "peak_roll_deg": peak["roll"], "peak_pitch_deg": peak["pitch"], "peak_yaw_deg": peak["yaw"],
            "attitude_limit_deg": ATTITUDE_LIMIT_DEG, "deviation_ratio": deviation,
            "target_always_in_view": in_view, "attitude_within_limits": attitude_ok, "docked": True,
            "diverged": False, "propellant_kg": 3.2 + 0.004 * total, "attitude_propellant_kg": 0.01 * peak["yaw"],
            "roll_on_time_s": 0.0, "pitch_on_time_s": 0.0, "yaw_on_time_s": 4.0 * peak["yaw"],
            "controllable": controllable, "risk_class": risk, "risk_rank": 0}


def rank(rows):
    """invsim::risk_order: most severe class first, then the larger k_p, then the larger deviation."""
    severity = {"III": 0, "II": 1, "I": 2}
    order = sorted(range(len(rows)), key=lambda i: (severity[rows[i]["risk_class"]], -rows[i]["k_p"],
                                                    -rows[i]["deviation_ratio"]))
    for k, i in enumerate(order):
        rows[i]["risk_rank"] = k + 1


def cell(value):
    if isinstance(value, (bool, np.bool_)):
        return "true" if value else "false"
    return f"{value:.4f}" if isinstance(value, float) else str(value)


def file_stem(index, label):
    """cli/fmea_history.cpp: "d1/d2~+e2/e1~" -> "31_d1-d2n+e2-e1n"."""
    return f"{index:02d}_" + label.replace("/", "-").replace("~", "n")


def write_history(path, h):
    data = np.column_stack([h[c] for c in HISTORY_HEADER])
    formats = ["%.1f"] + ["%.5f"] * 3 + ["%.6f"] * 3 + ["%.5f"] * 8 + ["%.6e"] * 3 + ["%d"] * 6
    np.savetxt(path, data, fmt=formats, delimiter=",", header=",".join(HISTORY_HEADER), comments="")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("out", type=Path)
    ap.add_argument("--seed", type=int, default=1)
    args = ap.parse_args()
    rng = np.random.default_rng(args.seed)
    index, fmea = ["configuration,mode,file"], []
    for configuration in ("baseline", "scheme_II"):
        (args.out / "history" / configuration).mkdir(parents=True, exist_ok=True)
        rows = []
        for number, label, table, failed, yaw in MODES:
            h = history(rng, yaw[configuration])
            file = f"{configuration}/{file_stem(number, label)}.csv"
            write_history(args.out / "history" / file, h)
            index.append(f"{configuration},{label},{file}")
            rows.append(fmea_row(configuration, label, table, failed, h))
        rank(rows)
        fmea += rows
    (args.out / "history" / "index.csv").write_text("\n".join(index) + "\n")
    lines = [",".join(FMEA_HEADER)] + [",".join(cell(row[c]) for c in FMEA_HEADER) for row in fmea]
    (args.out / "fmea.csv").write_text("\n".join(lines) + "\n")
    classes = ", ".join(f"{r['configuration']} {r['mode']}: {r['risk_class']}" for r in fmea)
    print(f"wrote {len(fmea)} modes in {args.out} (classes {classes})")


if __name__ == "__main__":
    main()
