#!/usr/bin/env python3
"""Frequency responses of a `chaser control design` (docs/control.md, "Six-axis design").

Usage: /usr/bin/python3 python/plot_control.py DESIGN.json [--out DIR]

Reads the JSON that `chaser control design SCENARIO --out DESIGN.json` writes and draws, per loop
(x, y, z, rx, ry, rz):
  - sensitivity.png: |S| and |T| against the synthesis bounds gamma / |W_S| (on S) and |K S| against
    gamma / |W_KS|, with the achieved bandwidth and the |S| peak marked (singular values of a SISO
    loop are its magnitudes);
  - loop.png: the Bode plot of the loop L = G K e^{-s tau}, with the gain crossover and the phase
    margin, and the phase crossover and the gain margin where there is one;
  - mu.png (when the design checked control.hinf.robustness): SLICOT AB13MD's upper bound on the
    structured singular value of each loop's gain x delay LFT over frequency, with its peak and the
    margin 1 / peak. AB13MD bounds mu for the blocks as given: the "complex" curve lets the gain be
    complex and is conservative for a real parameter; the "mixed" curve keeps the gain real. The
    delay enters as a covering complex disk in both; the flexible modes are left to the grid check.
DIR defaults to the JSON file's folder.
"""
import argparse
import json
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def db(x):
    return 20.0 * np.log10(np.asarray(x, dtype=float))


def designed(axes):
    return [a for a in axes if a.get("status") == "ok"]


def plot_sensitivity(design, out):
    axes = designed(design["axes"])
    fig, grid = plt.subplots(2, 3, figsize=(15, 8), sharex=False, squeeze=False)
    for ax, loop in zip(grid.flat, axes):
        r = loop["frequency_response"]
        w = np.asarray(r["omega_radps"])
        ax.loglog(w, r["S_mag"], label="|S|")
        ax.loglog(w, r["T_mag"], label="|T|")
        ax.loglog(w, r["S_bound"], "--", color="C0", alpha=0.6, label="gamma / |W_S|")
        unit = loop["authority_unit"]
        ax.loglog(w, np.asarray(r["KS_mag"]) / loop["authority"], label=f"|K S| / authority [1/{loop['weights']['error_scale_unit']}]")
        ax.loglog(w, np.asarray(r["KS_bound"]) / loop["authority"], ":", color="C2", alpha=0.8, label="gamma / |W_KS| / authority")
        m = loop["margins"]
        if m["bandwidth_radps"] is not None:
            ax.axvline(m["bandwidth_radps"], color="grey", lw=0.8)
        ax.plot([m["sensitivity_peak_radps"]], [m["sensitivity_peak"]], "o", color="C0")
        ax.set_title(f"{loop['axis']}: gamma {loop['gamma']:.4g}, norm {loop['closed_loop_norm']:.4g}, "
                     f"|S| peak {m['sensitivity_peak']:.3g}\nauthority {loop['authority']:.3g} {unit}")
        ax.set_xlabel("omega [rad/s]")
        ax.grid(True, which="both", alpha=0.3)
        ax.set_ylim(1e-5, 1e3)
    grid.flat[0].legend(fontsize=7, loc="lower left")
    fig.suptitle(f"{design['scenario']}: sensitivities and their H-infinity bounds (loop delay {design['delay_s']:.4g} s)")
    fig.tight_layout()
    fig.savefig(out / "sensitivity.png", dpi=110)
    plt.close(fig)


def plot_loop(design, out):
    axes = designed(design["axes"])
    fig, grid = plt.subplots(2, 6, figsize=(22, 7), sharex="col", squeeze=False)
    for col, loop in enumerate(axes):
        r = loop["frequency_response"]
        w = np.asarray(r["omega_radps"])
        phase = np.unwrap(np.radians(r["L_phase_deg"])) * 180.0 / np.pi
        # A double integrator starts near -180 deg: put the low-frequency end there (the delay winds the
        # high-frequency end down by many turns).
        phase -= 360.0 * np.round((phase[0] + 180.0) / 360.0)
        m = loop["margins"]
        mag, ph = grid[0, col], grid[1, col]
        mag.semilogx(w, db(r["L_mag"]))
        mag.axhline(0.0, color="grey", lw=0.8)
        ph.semilogx(w, phase)
        ph.axhline(-180.0, color="grey", lw=0.8)
        if m["gain_crossover_radps"] is not None:
            wc = m["gain_crossover_radps"]
            mag.axvline(wc, color="C1", lw=0.8)
            ph.axvline(wc, color="C1", lw=0.8)
            ph.annotate(f"PM {m['phase_margin_deg']:.1f} deg", (wc, -180.0), textcoords="offset points", xytext=(5, 10),
                        fontsize=8, color="C1")
        if m["phase_crossover_radps"] is not None:
            wp = m["phase_crossover_radps"]
            mag.axvline(wp, color="C3", lw=0.8)
            mag.annotate(f"GM {m['gain_margin_up_db']:.1f} dB", (wp, 0.0), textcoords="offset points", xytext=(5, -15),
                         fontsize=8, color="C3")
        mag.set_title(f"{loop['axis']}: L = G K e^(-s tau)")
        mag.set_ylabel("|L| [dB]")
        ph.set_ylabel("arg L [deg]")
        ph.set_xlabel("omega [rad/s]")
        for a in (mag, ph):
            a.grid(True, which="both", alpha=0.3)
    fig.suptitle(f"{design['scenario']}: loop transfer functions with the exact delay ({design['delay_s']:.4g} s)")
    fig.tight_layout()
    fig.savefig(out / "loop.png", dpi=100)
    plt.close(fig)


MU_NOTE = ("AB13MD upper bound. complex: gain and delay blocks complex (conservative for the real gain); "
           "mixed: gain real. Delay as a covering complex disk; modes left to the grid check.")


def plot_mu(design, out):
    axes = [a for a in designed(design["axes"]) if "mu" in a]
    if not axes:
        return False
    fig, grid = plt.subplots(2, 3, figsize=(15, 8), squeeze=False)
    for ax, loop in zip(grid.flat, axes):
        mu = loop["mu"]
        w = np.asarray(mu["omega_radps"])
        ax.loglog(w, mu["mu_complex"], label="mu bound, complex blocks")
        ax.loglog(w, mu["mu_mixed"], "--", label="mu bound, gain real (spikes where L is real)")
        ax.plot([mu["peak_complex_radps"]], [mu["peak_complex"]], "o", color="C0")
        ax.plot([mu["peak_mixed_radps"]], [mu["peak_mixed"]], "s", color="C1")
        ax.axhline(1.0, color="C3", lw=0.8)
        lft = mu["lft"]

        def margin(key):
            return "inf" if mu[key] is None else f"{mu[key]:.3g}"

        ax.set_title(f"{loop['axis']}: k {lft['gain_nominal']:.3f} +- {100 * lft['gain_radius']:.1f} %, "
                     f"tau {lft['delay_nominal_s']:.4f} +- {lft['delay_radius_s']:.4f} s\n"
                     f"peak {mu['peak_complex']:.3g} (margin {margin('margin_complex')}), "
                     f"gain real {mu['peak_mixed']:.3g} (margin {margin('margin_mixed')})"
                     + ("" if mu["nominal_stable"] else "\nNOMINAL LOOP UNSTABLE: mu means nothing"), fontsize=9)
        ax.set_xlabel("omega [rad/s]")
        ax.set_ylabel("mu upper bound [-]")
        ax.set_ylim(1e-4, max(3.0, 2.0 * mu["peak_complex"]))
        ax.grid(True, which="both", alpha=0.3)
    grid.flat[0].legend(fontsize=7, loc="upper left")
    fig.suptitle(f"{design['scenario']}: structured singular value of the gain x delay uncertainty (1 = the box's edge "
                 f"of guaranteed stability)\n{MU_NOTE}", fontsize=10)
    fig.tight_layout()
    fig.savefig(out / "mu.png", dpi=110)
    plt.close(fig)
    return True


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("design", type=Path)
    parser.add_argument("--out", type=Path)
    args = parser.parse_args()
    design = json.loads(args.design.read_text())
    out = args.out or args.design.parent
    out.mkdir(parents=True, exist_ok=True)
    if not designed(design["axes"]):
        raise SystemExit(f"{args.design}: no loop was designed (see each axis's status)")
    plot_sensitivity(design, out)
    plot_loop(design, out)
    wrote = [out / "sensitivity.png", out / "loop.png"]
    if plot_mu(design, out):
        wrote.append(out / "mu.png")
    print("wrote " + ", ".join(str(p) for p in wrote))


if __name__ == "__main__":
    main()
