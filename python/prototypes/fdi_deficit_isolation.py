"""Prototype: isolate a thruster fault from the commanded-vs-realised impulse deficit (6-DOF).
For each hypothesis i, the deficit is delta_i(k) = a + b T_on,i(k) (a: constant part, stuck open 1,
leak ~m; b: command-proportional part, stuck closed -1, loss -m). Least squares on a window:
  torque rows (body, every period): I (w(k+1)-w(k))/T + w x I w - M_C T_on,cmd(k) = M_C,i delta_i(k)
  position rows (LVLH, lidar = truth + 1 mm noise): r(k) = r0 + v0 t + sum_j T (t_k - t_j - T/2)
      (R(j) M_F T_on,cmd(j) + R(j) M_F,i delta_i(j)) / m      (HCW terms neglected: < 1e-4 N equivalent)
unknowns r0, v0, a, b; score = weighted residual sum of squares; isolated = argmin.

OFFLINE PROTOTYPE of the impulse-deficit isolation (docs/fdi.md, "Proposal"), not part of the product: it
reads the truth position plus synthetic 1 mm noise (raw LIDAR is not in telemetry) and hard-codes
the MSR mass and inertia. Usage, on a matrix made with python/fdi_matrix.py (recovery off):
  /usr/bin/python3 python/prototypes/fdi_deficit_isolation.py OUT/runs PRE_S POST_S
(window PRE_S before to POST_S after the first alarm; measured: 104/104 right over seeds 1-4
with 2 s before and 3 s after).
"""
import sys
import json, numpy as np
from geom import MF, MC, n, qmat
from load import load, ton
I = np.diag([2000.0, 2500.0, 3000.0]); m = 2500.0; T = 0.1

def fit(d, k0, k1, rng, sig_r=1e-3, onsets=None):
    t, s = load(d)
    tt = t['t_s']; c = ton(t)
    w = np.column_stack([t[f'omega_est_body_{x}_radps'] for x in 'xyz'])
    q = np.column_stack([t[f'q_est_inertial_from_body_{x}' ] for x in 'wxyz'])
    r_true = np.column_stack([t[f'r_lvlh_{x}_m'] for x in 'xyz'])
    r_meas = r_true + rng.normal(0, sig_r, r_true.shape)
    R = []
    for k in range(k0, k1):
        th = n * tt[k]; Rz = np.array([[np.cos(th), -np.sin(th), 0], [np.sin(th), np.cos(th), 0], [0, 0, 1]])
        R.append(Rz.T @ qmat(q[k]))
    R = np.array(R)
    # torque rows
    ks = np.arange(k0, k1 - 1)
    y_tau = (w[ks + 1] - w[ks]) @ I.T / T + np.cross(w[ks], w[ks] @ I.T) - c[ks] @ MC.T
    # noise level of the torque rows from a fault-free stretch (10 s before k0 - 10 s)
    kk = np.arange(max(k0 - 300, 1), k0 - 100)
    y0 = (w[kk + 1] - w[kk]) @ I.T / T + np.cross(w[kk], w[kk] @ I.T) - c[kk] @ MC.T
    sig_tau0 = y0.std(0) + 1e-6
    # thruster errors (1 % thrust, misalignment, delay): 1 % of the commanded torque
    sig_tau = np.sqrt(sig_tau0**2 + (0.01 * (c[ks] @ np.abs(MC).T))**2)
    # position rows: kernel K[k, j] = T (t_k - t_j - T/2) for j < k
    N = k1 - k0; tk = np.arange(N) * T
    K = np.where(np.arange(N)[:, None] > np.arange(N)[None, :], T * (tk[:, None] - tk[None, :] - T / 2), 0.0)
    f_cmd = np.einsum('kab,bj,kj->ka', R, MF, c[k0:k1]) / m
    y_r = r_meas[k0:k1] - K @ f_cmd
    scores, params = [], []
    onsets = onsets or [k0]
    for i in range(8):
      best_i = (np.inf, None)
      for kf in onsets:
        step = (np.arange(k0, k1) >= kf)[:, None].astype(float)   # the deficit exists from the onset
        step_t = (ks >= kf)[:, None].astype(float)
        fi = R @ MF[:, i] / m                    # N x 3 force direction per unit deficit
        cols_r = [np.kron(np.ones((N, 1)), np.eye(3)[a]) for a in range(3)]  # r0
        cols_r = [np.tile(np.eye(3)[a], (N, 1)) for a in range(3)] + [np.outer(tk, np.eye(3)[a]) for a in range(3)]
        cols_r += [K @ (fi * step), K @ (fi * c[k0:k1, i:i + 1] * step)]
        Ar = np.column_stack([cc.reshape(-1) for cc in cols_r]) / sig_r
        At = np.zeros((len(ks) * 3, 8))
        At[:, 6] = (step_t * MC[:, i] / sig_tau).reshape(-1)
        At[:, 7] = ((step_t * c[ks, i:i + 1] * MC[:, i]) / sig_tau).reshape(-1)
        A = np.vstack([Ar, At]); y = np.concatenate([(y_r / sig_r).reshape(-1), (y_tau / sig_tau).reshape(-1)])
        th, *_ = np.linalg.lstsq(A, y, rcond=None)
        rss = float(np.sum((A @ th - y) ** 2))
        if rss < best_i[0]: best_i = (rss, np.append(th[6:], (kf - k0) * T))
      scores.append(best_i[0]); params.append(best_i[1])
    A0 = np.vstack([Ar[:, :6], np.zeros((len(ks) * 3, 6))])  # no fault: r0, v0 only
    th0, *_ = np.linalg.lstsq(A0, y, rcond=None)
    rss0 = float(np.sum((A0 @ th0 - y) ** 2))
    best = int(np.argmin(scores))
    return best, scores, params[best], rss0

if __name__ == '__main__':
    base = sys.argv[1]; pre, post = float(sys.argv[2]), float(sys.argv[3])
    rng = np.random.default_rng(1)
    tot = {}
    for case in ['stuck_open', 'stuck_closed', 'leak', 'loss']:
        out = []
        for k in range(1, 9):
            d = f'{base}/{case}_T{k}'
            s = json.load(open(d + '/summary.json'))
            al = [s['fdir'][f'{x}_scheme']['alarm_s'] for x in ('position', 'attitude')]
            al = [a for a in al if a is not None]
            if not al: out.append(f'T{k}: -'); continue
            ka = int(round(min(al) / T))
            best, sc, ab, _ = fit(d, ka - int(pre / T), ka + int(post / T), rng, onsets=list(range(ka - int(pre / T), ka + 1)))
            srt = np.sort(sc)
            ok = best == k - 1
            tot[case] = tot.get(case, 0) + ok
            out.append(f"T{k}:{'ok' if ok else 'T'+str(best+1)} a={ab[0]:.2f} b={ab[1]:.2f} onset={ab[2]-pre:+.1f}s margin={srt[1]-srt[0]:.0f}")
        print(case, tot.get(case, 0), '|', '; '.join(out))
