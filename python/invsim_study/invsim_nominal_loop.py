#!/usr/bin/env python3
"""A translation-only model of the nominal inverse-simulation loop (docs/invsim.md, "Readings of App. B").

Usage: /usr/bin/python3 python/invsim_study/invsim_nominal_loop.py

The Hill-frame CW dynamics (x along the target's velocity, z to the Earth), the inverse model of
eqs. 17-21 over 3 steps, App. B's pulse (dead zone k, opening dtau = |u| tau / u_max at the step's
start), the shipped trajectory and Table 3's initial state; no attitude (the nominal run's couples
do not fire). With Q = I and k = 0.35 it reproduces `chaser fmea`'s nominal smooth counts
(41/28/37/46/8/44) and opening times. Used to try readings quickly: a smaller k (it lowers z+),
a relay over the whole step, holding u over the horizon. Prints those variants' nominal counts.
"""
import numpy as np
from scipy.linalg import expm

N = np.sqrt(3.986004418e14 / (6378137.0 + 400e3) ** 3)  # [rad/s]
U_MAX = 120.0 / 8000.0                                   # [m/s^2] one translation group
X0 = np.array([100.038, -0.0167, -0.023, -0.0076, 0.131, -0.0087])
DOCK_X, DAMPING_START, DAMPING_T = 10.0, 800.0, 100.0

A = np.zeros((6, 6))
A[0:3, 3:6] = np.eye(3)
A[3, 5], A[4, 1], A[5, 3], A[5, 2] = 2 * N, -N * N, -2 * N, 3 * N * N
B = np.vstack([np.zeros((3, 3)), np.eye(3)])


def transition(t):
    m = np.zeros((9, 9))
    m[:6, :6], m[:6, 6:] = A * t, B * t
    e = expm(m)
    return e[:6, :6], e[:6, 6:]


def desired(t):
    v = -(X0[0] - DOCK_X) / (DAMPING_START + DAMPING_T)
    x = np.zeros(6)
    if t <= DAMPING_START:
        x[0], x[3] = X0[0] + v * t, v
        return x
    xs, d = X0[0] + v * DAMPING_START, np.exp(-(t - DAMPING_START) / DAMPING_T)
    x[0], x[3] = DOCK_X + (xs - DOCK_X) * d, -(xs - DOCK_X) / DAMPING_T * d
    return x


def run(weights=(1, 1, 1, 1, 1, 1), k=0.35, width=None, relay=False, hold=1, steps=1300):
    """Nominal counts per direction (x+, x-, ...) and opening times; width: paper-reading count."""
    phi, phi_u = transition(3.0)
    q = np.diag(weights)
    gain = np.linalg.solve(phi_u.T @ q @ phi_u, phi_u.T @ q)
    x, count, on = X0.copy(), np.zeros(6), np.zeros(6)
    for s in range(steps):
        if s % hold == 0:
            u = gain @ (desired(s + 3.0) - phi @ x)
        pieces = []
        for axis in range(3):
            if abs(u[axis]) / U_MAX > k:
                i = 2 * axis + (0 if u[axis] > 0 else 1)
                dtau = 1.0 if relay else min(abs(u[axis]) / U_MAX, 1.0)
                count[i] += 1 if width is None else np.ceil(dtau / width - 1e-9)
                on[i] += dtau
                pieces.append((dtau, axis, np.sign(u[axis]) * U_MAX))
        edges = sorted({0.0, 1.0, *[p[0] for p in pieces]})
        for a, b in zip(edges[:-1], edges[1:]):
            acc = np.zeros(3)
            for dtau, axis, value in pieces:
                if a < dtau:
                    acc[axis] += value
            p, pu = transition(b - a)
            x = p @ x + pu @ acc
    return count.astype(int), on


if __name__ == "__main__":
    print("smooth, Q = I:", *run())
    print("paper reading without noise (w = 0.06 s, Q diag(1, 1, 1, 10, 3, 0.03)):",
          run((1, 1, 1, 10, 3, 0.03), width=0.06)[0])
    for k in (0.05, 0.1, 0.2):
        print(f"paper reading, k = {k}:", run((1, 1, 1, 10, 3, 0.03), k=k, width=0.06)[0])
    print("relay over the whole step:", run(relay=True)[0])
    print("u held over the 3-step horizon:", run(hold=3)[0])
