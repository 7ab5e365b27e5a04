// The run's data as the page reads it: the decimated track interpolated at any time, the
// on-times by period, the active set, the faults' and isolations' times, the phases.

const scriptStartMs = performance.now();  // the HTML, three.js and the data read by the browser
const data = JSON.parse(document.getElementById('chaser-data').textContent);
const dataParsedMs = performance.now();
const geo = data.geometry;
const summary = data.summary;
const track = data.track;
const N = track.t.length;
const t0 = data.meta.t0_s;
const tEnd = data.meta.t_end_s;
const DEG = 180 / Math.PI;

// ---- Data access -------------------------------------------------------------------------
// The kept row at or before t (binary search), and the fraction towards the next.
function locate(t) {
  let lo = 0, hi = N - 1;
  if (t <= track.t[0]) return [0, 0];
  if (t >= track.t[hi]) return [hi, 0];
  while (hi - lo > 1) {
    const mid = (lo + hi) >> 1;
    if (track.t[mid] <= t) lo = mid; else hi = mid;
  }
  return [lo, (t - track.t[lo]) / (track.t[lo + 1] - track.t[lo])];
}
function vecAt(arr, i, f, out) {
  const j = Math.min(i + 1, N - 1);
  for (let k = 0; k < 3; ++k) {
    const a = arr[3 * i + k], b = arr[3 * j + k];
    out[k] = (a === null || b === null) ? NaN : a + f * (b - a);
  }
  return out;
}
const qa = new THREE.Quaternion(), qb = new THREE.Quaternion();
function quatAt(arr, i, f, out) {
  const j = Math.min(i + 1, N - 1);
  // Data is (w, x, y, z); three.js is (x, y, z, w).
  qa.set(arr[4 * i + 1], arr[4 * i + 2], arr[4 * i + 3], arr[4 * i]);
  qb.set(arr[4 * j + 1], arr[4 * j + 2], arr[4 * j + 3], arr[4 * j]);
  return out.slerpQuaternions(qa, qb, f);
}

// Per-period on-times, uint8 (on-time x 255), row-major by thruster.
const thrusters = geo.chaser.thrusters;
const nThr = thrusters.length;
let onTimes = null;
if (data.ontimes) {
  const bin = atob(data.ontimes.base64);
  onTimes = new Uint8Array(bin.length);
  for (let i = 0; i < bin.length; ++i) onTimes[i] = bin.charCodeAt(i);
}
const period = geo.control_period_s;
function periodIndex(t) {
  if (!onTimes) return -1;
  const rows = data.ontimes.rows;
  return Math.max(0, Math.min(rows - 1, Math.floor((t - t0) / period + 1e-9)));
}
function activeMask(t) {
  let mask = null;
  for (const [ta, m] of data.active) { if (ta <= t + 1e-9) mask = m; else break; }
  return mask;
}

// Faults from their onsets, isolations from the scheme that confirmed them.
const faultOnset = new Array(nThr).fill(Infinity);
const isolatedAt = new Array(nThr).fill(Infinity);
for (const e of data.events) {
  if (e.thruster === null || e.thruster < 0 || e.thruster >= nThr) continue;
  if (e.kind === 'fault') faultOnset[e.thruster] = Math.min(faultOnset[e.thruster], e.t);
  if (e.kind === 'isolation') isolatedAt[e.thruster] = Math.min(isolatedAt[e.thruster], e.t);
}

// Phases and their requirements (summary.json's phases_flown and phase_verdicts).
const phases = summary.phases_flown || [];
const verdicts = summary.phase_verdicts || [];
function phaseAt(t) {
  let idx = -1;
  for (let i = 0; i < phases.length; ++i) if (phases[i].start_s <= t + 1e-9) idx = i;
  return idx;
}
