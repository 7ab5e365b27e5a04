#!/usr/bin/env python3
"""A PD controller written in Python flies the Mars Sample Return approach against Chaser's plant.

Usage: PYTHONPATH=build/python /usr/bin/python3 examples/python_pd_controller.py [--out DIR] [--quick]

Each control period chaser.Simulation.step(flight=...) hands the controller the flight side's view
only (LIDAR position, star-tracker attitude, gyro rate, the time, and the LVLH frame of the flight
software's orbit model) and flies the body-axes wrench it returns through Chaser's TMU, thruster
allocation and thruster hardware. The controller is this file's: an alpha-beta filter for the
velocity, a straight-line approach reference, PD laws on position and attitude. Chaser's own flight
software flies the same scenario and seed for comparison. Writes DIR/pd_controller.png (default:
the current folder). --quick flies a 300 s approach instead of the scenario's.
"""
import argparse
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import yaml  # noqa: E402

import chaser  # noqa: E402

REPO = Path(__file__).resolve().parents[1]


def qmul(a, b):
    """Hamilton product of quaternions (w, x, y, z)."""
    w1, v1, w2, v2 = a[0], a[1:], b[0], b[1:]
    return np.concatenate([[w1 * w2 - v1 @ v2], w1 * v2 + w2 * v1 + np.cross(v1, v2)])


def qconj(q):
    return np.concatenate([q[:1], -q[1:]])


def rotate(q, v):
    """v expressed in the frame q rotates to: q v q*."""
    return qmul(qmul(q, np.concatenate([[0.0], v])), qconj(q))[1:]


class PDController:
    """Position and attitude PD laws on measured states; returns [F_body, C_body] in N and N m."""

    def __init__(self, document):
        g = document["guidance"]
        self.T = document["control_period_s"]
        self.axis = np.array(g["approach_axis_lvlh"], float)
        self.d0, self.d1, self.t_app = g["start_distance_m"], g["capture_distance_m"], g["approach_duration_s"]
        mass, inertia = document["chaser"]["mass_kg"], np.diag(document["chaser"]["inertia_kgm2"])
        w_pos, w_att, zeta = 0.04, 0.15, 0.9          # [rad/s] natural frequencies, damping
        self.kp, self.kd = mass * w_pos**2, 2 * zeta * w_pos * mass
        self.kq, self.kw = inertia * w_att**2, 2 * zeta * w_att * inertia
        self.alpha, self.beta = 0.2, 0.01              # velocity from the LIDAR: alpha-beta filter
        self.r = self.v = self.q_lvlh_from_body = self.q_prev = None

    def reference(self, t):
        """Straight line along the approach axis, smoothstep in time: at rest at both ends."""
        s = min(t / self.t_app, 1.0)
        d = self.d0 + (self.d1 - self.d0) * (3 * s**2 - 2 * s**3)
        speed = (self.d1 - self.d0) * (6 * s - 6 * s**2) / self.t_app
        return d * self.axis, speed * self.axis

    def estimate_velocity(self, r):
        if self.r is None:
            self.r, self.v = r.copy(), np.zeros(3)
            return
        predicted = self.r + self.v * self.T
        residual = r - predicted
        self.r = predicted + self.alpha * residual
        self.v = self.v + self.beta / self.T * residual

    def __call__(self, m):
        q_ib, q_il = m["q_inertial_from_body"], m["q_inertial_from_lvlh"]
        self.estimate_velocity(m["r_lvlh_m"])
        r_ref, v_ref = self.reference(m["t_s"])
        force_lvlh = -self.kp * (self.r - r_ref) - self.kd * (self.v - v_ref)
        force_body = rotate(qconj(q_ib), rotate(q_il, force_lvlh))

        if self.q_lvlh_from_body is None:  # hold the start's attitude in LVLH: pointing at the target
            self.q_lvlh_from_body, self.q_prev = qmul(qconj(q_il), q_ib), q_il
        q_des = qmul(q_il, self.q_lvlh_from_body)
        q_err = qmul(qconj(q_des), q_ib)   # body from desired
        q_err = q_err if q_err[0] >= 0 else -q_err
        turn = qmul(qconj(self.q_prev), q_il)  # LVLH's rotation over the last period, LVLH axes
        omega_des = rotate(qconj(self.q_lvlh_from_body), 2 * turn[1:] / self.T)
        self.q_prev = q_il
        torque = -self.kq * 2 * q_err[1:] - self.kw * (m["omega_body_radps"] - omega_des)
        return np.concatenate([force_body, torque])


def scenario(quick):
    overrides = {"duration_s": 300.0, "guidance.approach_duration_s": 250.0} if quick else None
    return chaser.load_scenario(str(REPO / "scenarios" / "msr_terminal.yaml"), overrides=overrides)


def fly_pd(loaded, seed=1):
    """The whole run flown by PDController; its chaser.RunResult."""
    sim = chaser.Simulation(loaded, seed=seed)
    sim.step(sim_periods(loaded), flight=PDController(yaml.safe_load(loaded.yaml)))
    return sim.result()


def sim_periods(loaded):
    document = yaml.safe_load(loaded.yaml)
    return round(document["duration_s"] / document["control_period_s"])


def plot(pd, own, path):
    fig, axes = plt.subplots(3, 1, figsize=(9, 9), sharex=True, constrained_layout=True)
    for result, name in ((own, "Chaser's flight software"), (pd, "PD controller in Python")):
        t = result.telemetry
        axes[0].plot(t["t_s"], np.hypot(np.hypot(t["r_lvlh_x_m"], t["r_lvlh_y_m"]), t["r_lvlh_z_m"]), label=name)
        axes[1].plot(t["t_s"], np.degrees(np.linalg.norm(
            [t["att_err_body_x_rad"], t["att_err_body_y_rad"], t["att_err_body_z_rad"]], axis=0)), label=name)
        on = sum(t[k] for k in t if k.startswith("ton_cmd_"))
        axes[2].plot(t["t_s"], np.cumsum(on) * 0.1, label=name)
    axes[0].set_ylabel("range to target [m]")
    axes[1].set_ylabel("attitude error [deg]")
    axes[1].set_yscale("log")
    axes[1].set_ylim(bottom=1e-5)
    axes[2].set_ylabel("on-time, all thrusters [s]")
    axes[2].set_xlabel("time [s]")
    for ax in axes:
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    fig.savefig(path, dpi=100)
    plt.close(fig)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--out", type=Path, default=Path("."))
    ap.add_argument("--quick", action="store_true", help="a 300 s approach (tests)")
    args = ap.parse_args()
    loaded = scenario(args.quick)
    pd, own = fly_pd(loaded), chaser.run(loaded, seed=1)
    for result, name in ((pd, "PD in Python"), (own, "Chaser")):
        s = result.summary
        print(f"{name:>13}: capture {s['capture_achieved']}, final error {s['final_position_error_m']:.3f} m, "
              f"{s['final_speed_mps']:.4f} m/s, {s['final_attitude_error_deg']:.2f} deg, "
              f"propellant {s['propellant_used_kg']:.3f} kg")
    args.out.mkdir(parents=True, exist_ok=True)
    plot(pd, own, args.out / "pd_controller.png")
    print(f"wrote {args.out / 'pd_controller.png'}")


if __name__ == "__main__":
    main()
