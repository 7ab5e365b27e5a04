// The side panel (time, phase, errors against the requirements, thrusters, events) and the
// timeline of phases and events.

// ---- Panel -------------------------------------------------------------------------------
const $ = (id) => document.getElementById(id);
const timeEl = $('time'), phaseEl = $('phase'), statusEl = $('status'), slider = $('slider');
slider.min = t0; slider.max = tEnd;
const thrCells = thrusters.map((th) => {
  const d = document.createElement('div');
  d.className = 'thr';
  d.textContent = th.name;
  const bar = document.createElement('div');
  bar.className = 'bar';
  d.appendChild(bar);
  $('thrusters').appendChild(d);
  return { cell: d, bar };
});
const eventItems = data.events.map((e) => {
  const li = document.createElement('li');
  li.className = 'kind-' + e.kind;
  li.textContent = e.t.toFixed(1) + ' s  ' + e.label;
  li.addEventListener('click', () => setTime(e.t));
  $('events').appendChild(li);
  return li;
});
if (data.events.length === 0) $('events').innerHTML = '<li>none</li>';
const notes = [];
notes.push(`${data.meta.kept_rows} of ${data.meta.telemetry_rows} rows of ${data.meta.telemetry_file} drawn (positions within ${data.meta.tolerance.position_m * 1000} mm, attitudes within ${data.meta.tolerance.attitude_deg.toFixed(2)} deg of every row); thruster on-times and events at every period.`);
if (!geo.lvlh.exact) notes.push('LVLH is drawn turning at the mean motion: the perturbed orbit\'s frame departs from it by a fraction of a degree over an hour.');
if (!onTimes) notes.push('No on-time channels in this telemetry: no plumes.');
if (!track.arm) notes.push(geo.chaser.arm ? 'The arm\'s figure is not in this telemetry: the arm is not drawn.' : '');
else notes.push('The arm is drawn from when it wakes (its figure in the telemetry).');
if (!geo.target.body) notes.push('The target (MSR\'s sample container) is drawn 0.3 m across: the scenario gives no size.');
$('notes').textContent = notes.filter(Boolean).join(' ');
// The timeline: phases as coloured bands, events as ticks.
const timeline = $('timeline');
const span = Math.max(tEnd - t0, 1e-9);
const colours = ['#3b6fb6', '#5a8f3b', '#a3702e', '#7a3fa3', '#2e8f8a', '#a33f5a', '#6f6f2e', '#3f5aa3', '#8a5a2e', '#2e6f3f', '#a3a33f'];
phases.forEach((p, i) => {
  const d = document.createElement('div');
  d.className = 'seg';
  d.style.left = (100 * (p.start_s - t0) / span) + '%';
  d.style.width = (100 * (p.end_s - p.start_s) / span) + '%';
  d.style.background = colours[i % colours.length];
  d.textContent = p.name;
  d.title = p.name;
  timeline.appendChild(d);
});
const tickColour = { fault: '#ff6b6b', alarm: '#ffb347', isolation: '#d27bff', recovery: '#7bd8ff', phase: '#ffd27a', capture: '#8fe388', diverged: '#ff3b3b' };
for (const e of data.events) {
  if (e.kind === 'phase') continue;
  const d = document.createElement('div');
  d.className = 'tick';
  d.style.left = (100 * (e.t - t0) / span) + '%';
  d.style.background = tickColour[e.kind] || '#fff';
  d.title = e.t.toFixed(1) + ' s ' + e.label;
  timeline.appendChild(d);
}
const cursor = document.createElement('div');
cursor.className = 'cursor';
timeline.appendChild(cursor);
timeline.addEventListener('click', (e) => {
  const rect = timeline.getBoundingClientRect();
  setTime(t0 + span * (e.clientX - rect.left) / rect.width);
});

// Distance from a point (target axes) to the union of the keep-out boxes (model/keep_out.hpp).
function keepOutDistance(p) {
  let best = Infinity;
  for (const b of boxes) {
    const d = [0, 1, 2].map(k => Math.abs(p[k] - b.centre_target_m[k]) - b.half_extents_m[k]);
    const outside = Math.hypot(Math.max(d[0], 0), Math.max(d[1], 0), Math.max(d[2], 0));
    best = Math.min(best, outside > 0 ? outside : Math.max(d[0], d[1], d[2]));
  }
  return best;
}

function fmt(v, digits) { return Number.isFinite(v) ? v.toFixed(digits) : '–'; }
function updatePanel(t, phaseIdx, errors) {
  timeEl.textContent = t.toFixed(1);
  phaseEl.textContent = phaseIdx >= 0 ? phases[phaseIdx].name : '';
  statusEl.textContent = `x${state.speed}  ${state.playing ? 'playing' : 'paused'}  range ${fmt(errors.range, 2)} m`;
  const p = phases[phaseIdx];
  const v = p && verdicts.find(q => q.phase === p.name && Math.abs(q.start_s - p.start_s) < 1e-6);
  const limits = {};
  if (v) for (const r of v.requirements) limits[r.name] = r;
  const rows = [
    ['position error [m]', errors.position_m, 'position_error_m', 3],
    ['attitude error [deg]', errors.attitude_deg, 'attitude_error_deg', 2],
    ['clearance [m]', errors.clearance_m, 'clearance_m', 2, true],
    ['off corridor axis [deg]', errors.corridor_deg, null, 2],
  ];
  const tbody = document.querySelector('#errors tbody');
  tbody.innerHTML = '';
  for (const [name, value, key, digits, atLeast] of rows) {
    if (!Number.isFinite(value)) continue;
    const req = key ? limits[key] : null;
    const limit = req ? req.limit : (key === null ? approach.corridor_half_angle_deg : null);
    const ok = limit === null ? null : (atLeast ? value >= limit : value <= limit);
    const tr = document.createElement('tr');
    if (ok !== null) tr.className = ok ? 'good' : 'bad';
    tr.innerHTML = `<td>${name}</td><td>${fmt(value, digits)}</td><td>${limit === null ? '' : (atLeast ? '≥ ' : '≤ ') + limit}</td><td>${req ? fmt(req.value, digits) + (req.met ? ' ✓' : ' ✗') : ''}</td>`;
    tbody.appendChild(tr);
  }
  if (v) for (const r of v.requirements) {
    if (['position_error_m', 'attitude_error_deg', 'clearance_m'].includes(r.name)) continue;
    const tr = document.createElement('tr');
    tr.className = r.met ? 'good' : 'bad';
    tr.innerHTML = `<td>${r.name}</td><td></td><td>${r.limit === null ? '' : r.limit}</td><td>${r.value === null ? '' : fmt(r.value, 3)}${r.met ? ' ✓' : ' ✗'}</td>`;
    tbody.appendChild(tr);
  }
  eventItems.forEach((li, i) => {
    const e = data.events[i];
    li.classList.toggle('past', e.t <= t + 1e-9);
    li.classList.toggle('current', Math.abs(e.t - t) < 1e-6);
  });
  cursor.style.left = (100 * (t - t0) / span) + '%';
}
