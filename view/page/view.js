// Chaser view: replays one run in 3D from the data `chaser view` put in the page (docs/view.md).
// The scene is in LVLH (x zenith, y along-track, z orbit normal), metres, the target's centre of
// mass at the origin. Everything drawn at a time t is read from the data at t: the state a test
// reads (window.chaserView.state()) is taken from the scene's objects themselves.
'use strict';

(function () {
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

  // ---- Scene -------------------------------------------------------------------------------
  const host = document.getElementById('scene');
  const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(Math.min(window.devicePixelRatio || 1, 2));
  host.appendChild(renderer.domElement);
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0x05070d);
  scene.add(new THREE.AmbientLight(0xffffff, 0.55));
  const sun = new THREE.DirectionalLight(0xffffff, 1.6);
  sun.position.set(0.6, -0.4, 0.7);
  scene.add(sun);
  const camera = new THREE.PerspectiveCamera(45, 1, 0.05, 5000);

  // The run's extent: how far the chaser goes, for the camera, the axes and the corridor.
  let range = 1;
  for (let i = 0; i < N; ++i) range = Math.max(range, Math.hypot(track.r[3 * i], track.r[3 * i + 1], track.r[3 * i + 2]));

  function v3(a) { return new THREE.Vector3(a[0], a[1], a[2]); }
  // A text sprite, `height` metres tall, anchored at its left end.
  function label(text, color, height) {
    const canvas = document.createElement('canvas');
    const ctx = canvas.getContext('2d');
    const font = 'bold 40px sans-serif';
    ctx.font = font;
    canvas.width = Math.ceil(ctx.measureText(text).width) + 8;
    canvas.height = 56;
    ctx.font = font;
    ctx.fillStyle = color;
    ctx.fillText(text, 4, 42);
    const sprite = new THREE.Sprite(new THREE.SpriteMaterial({ map: new THREE.CanvasTexture(canvas), depthTest: false, transparent: true }));
    sprite.center.set(0, 0.5);
    sprite.scale.set(height * canvas.width / canvas.height, height, 1);
    return sprite;
  }

  // LVLH axes at the target.
  const axisLength = Math.max(3, 0.25 * range);
  const axes = new THREE.Group();
  [['x zenith', 0xff5555, [1, 0, 0]], ['y along-track', 0x55ff55, [0, 1, 0]], ['z orbit normal', 0x5599ff, [0, 0, 1]]].forEach(([name, color, dir]) => {
    const d = v3(dir);
    axes.add(new THREE.ArrowHelper(d, new THREE.Vector3(), axisLength, color, 0.06 * axisLength, 0.03 * axisLength));
    const l = label('LVLH ' + name, '#' + color.toString(16).padStart(6, '0'), 0.07 * axisLength);
    l.position.copy(d.clone().multiplyScalar(axisLength * 1.05));
    axes.add(l);
  });
  scene.add(axes);

  // The approach corridor: a cone about the approach axis from the target, out to the run's range.
  const approach = geo.approach;
  {
    const half = approach.corridor_half_angle_deg / DEG;
    const length = range * 1.05;
    const cone = new THREE.ConeGeometry(Math.tan(half) * length, length, 48, 1, true);
    cone.translate(0, -length / 2, 0);  // apex at the origin, opening along -y
    const mesh = new THREE.Mesh(cone, new THREE.MeshBasicMaterial({ color: 0x3fae5a, transparent: true, opacity: 0.07, side: THREE.DoubleSide, depthWrite: false }));
    mesh.quaternion.setFromUnitVectors(new THREE.Vector3(0, -1, 0), v3(approach.axis_lvlh).normalize());
    const edges = new THREE.LineSegments(new THREE.EdgesGeometry(cone, 30), new THREE.LineBasicMaterial({ color: 0x3fae5a, transparent: true, opacity: 0.35 }));
    mesh.add(edges);
    scene.add(mesh);
  }

  // The target, turning as the truth turns.
  const target = new THREE.Group();
  scene.add(target);
  const gold = new THREE.MeshPhongMaterial({ color: 0xc9a24a, shininess: 40 });
  const panelMat = new THREE.MeshPhongMaterial({ color: 0x1d3d8f, shininess: 60, emissive: 0x050a20 });
  const keepOutZone = new THREE.Group();
  target.add(keepOutZone);
  let targetSize = 0.3;
  const boxes = geo.target.keep_out || [];
  if (!geo.target.body || boxes.length === 0) {
    // MSR's orbiting sample container: a sphere (the scenario gives no size: drawn 0.3 m across).
    const s = new THREE.Mesh(new THREE.SphereGeometry(0.15, 32, 16), new THREE.MeshPhongMaterial({ color: 0xe8e8e8, shininess: 40 }));
    target.add(s);
    const band = new THREE.Mesh(new THREE.TorusGeometry(0.151, 0.012, 8, 48), gold);
    target.add(band);
  } else {
    for (const b of boxes) {
      const h = b.half_extents_m;
      const thin = Math.min(h[0], h[1], h[2]) < 0.2;  // a solar array's wing
      const mesh = new THREE.Mesh(new THREE.BoxGeometry(2 * h[0], 2 * h[1], 2 * h[2]), thin ? panelMat : gold);
      mesh.position.copy(v3(b.centre_target_m));
      target.add(mesh);
      if (thin) {  // the array's cells
        const grid = new THREE.LineSegments(new THREE.EdgesGeometry(new THREE.BoxGeometry(2 * h[0], 2 * h[1], 2 * h[2], 7, 2, 1)),
          new THREE.LineBasicMaterial({ color: 0x8aa6e8 }));
        mesh.add(grid);
      }
      targetSize = Math.max(targetSize, v3(b.centre_target_m).length() + v3(h).length());
      // The keep-out volume grown by the phase's clearance limit, resized on each phase (below).
      const zone = new THREE.Mesh(new THREE.BoxGeometry(1, 1, 1), new THREE.MeshBasicMaterial({ color: 0xff3030, transparent: true, opacity: 0.08, depthWrite: false }));
      zone.add(new THREE.LineSegments(new THREE.EdgesGeometry(new THREE.BoxGeometry(1, 1, 1)), new THREE.LineBasicMaterial({ color: 0xff5050, transparent: true, opacity: 0.5 })));
      zone.position.copy(mesh.position);
      zone.userData.half = h;
      keepOutZone.add(zone);
    }
    const fx = geo.target.fixture;
    if (fx) {
      const normal = v3(fx.normal_target);
      if (fx.kind === 'ring') {  // the launcher adapter ring, its rim the grasp point
        const ring = new THREE.Mesh(new THREE.TorusGeometry(fx.radius_m, 0.04, 12, 64), new THREE.MeshPhongMaterial({ color: 0xb0b6c0, shininess: 40 }));
        ring.quaternion.setFromUnitVectors(new THREE.Vector3(0, 0, 1), normal);
        ring.position.copy(v3(fx.centre_target_m).add(normal.clone().multiplyScalar(0.06)));
        target.add(ring);
      } else {  // a berthing drogue: a cone opening outwards
        const cone = new THREE.Mesh(new THREE.ConeGeometry(fx.radius_m, 0.15, 24, 1, true), new THREE.MeshPhongMaterial({ color: 0xd0d0d0, side: THREE.DoubleSide }));
        cone.quaternion.setFromUnitVectors(new THREE.Vector3(0, -1, 0), normal);
        cone.position.copy(v3(fx.centre_target_m).add(normal.clone().multiplyScalar(0.075)));
        target.add(cone);
      }
    }
    if (geo.target.grasp_point_target_m) {
      const g = new THREE.Mesh(new THREE.SphereGeometry(0.05, 12, 8), new THREE.MeshBasicMaterial({ color: 0x8fe388 }));
      g.position.copy(v3(geo.target.grasp_point_target_m));
      target.add(g);
    }
  }
  const targetAxes = new THREE.AxesHelper(Math.max(1, 0.6 * targetSize));
  target.add(targetAxes);

  // The clearance limit that applies in a phase (phase_verdicts' clearance_m), or none.
  function clearanceLimit(phaseIdx) {
    if (phaseIdx < 0 || !phases[phaseIdx]) return null;
    const v = verdicts.find(p => p.phase === phases[phaseIdx].name && Math.abs(p.start_s - phases[phaseIdx].start_s) < 1e-6);
    const r = v && v.requirements.find(q => q.name === 'clearance_m');
    return r ? r.limit : null;
  }
  function sizeKeepOut(limit) {
    keepOutZone.visible = limit !== null;
    if (limit === null) return;
    for (const z of keepOutZone.children) {
      const h = z.userData.half;
      z.scale.set(2 * (h[0] + limit), 2 * (h[1] + limit), 2 * (h[2] + limit));
    }
  }

  // The arm, in the target's axes (its figure: hub, joints 1 to 7, tool point).
  const arm = new THREE.Group();
  target.add(arm);
  const armLinks = [];
  const armJoints = [];
  if (track.arm) {
    const linkMat = new THREE.MeshPhongMaterial({ color: 0xe0e4ea, shininess: 40 });
    const jointMat = new THREE.MeshPhongMaterial({ color: 0x5a6478 });
    for (let i = 0; i < 8; ++i) {
      const link = new THREE.Mesh(new THREE.CylinderGeometry(i < 1 ? 0.03 : 0.06, i < 1 ? 0.03 : 0.06, 1, 12), linkMat);
      arm.add(link); armLinks.push(link);
    }
    for (let i = 0; i < 9; ++i) {
      const j = new THREE.Mesh(new THREE.SphereGeometry(i === 8 ? 0.07 : 0.085, 12, 8), i === 8 ? new THREE.MeshPhongMaterial({ color: 0x8fe388 }) : jointMat);
      arm.add(j); armJoints.push(j);
    }
  }
  const armPoints = Array.from({ length: 9 }, () => new THREE.Vector3());
  const up = new THREE.Vector3(0, 1, 0);
  function placeArm(i, f) {
    if (!track.arm) return false;
    const j = Math.min(i + 1, N - 1);
    const a = 27 * i, b = 27 * j;
    if (track.arm[a] === null || track.arm[b] === null) { arm.visible = false; return false; }
    for (let p = 0; p < 9; ++p)
      armPoints[p].set(...[0, 1, 2].map(k => track.arm[a + 3 * p + k] + f * (track.arm[b + 3 * p + k] - track.arm[a + 3 * p + k])));
    for (let p = 0; p < 9; ++p) armJoints[p].position.copy(armPoints[p]);
    for (let s = 0; s < 8; ++s) {
      const from = armPoints[s], to = armPoints[s + 1];
      const d = to.clone().sub(from);
      const len = d.length();
      armLinks[s].visible = len > 1e-6;
      if (len <= 1e-6) continue;
      armLinks[s].position.copy(from).addScaledVector(d, 0.5);
      armLinks[s].quaternion.setFromUnitVectors(up, d.divideScalar(len));
      armLinks[s].scale.set(1, len, 1);
    }
    arm.visible = true;
    return true;
  }

  // The chaser: its bus, every thruster and its plume. Body points are from the reference point;
  // the group's origin is the centre of mass (where r_lvlh is).
  const chaser = new THREE.Group();
  scene.add(chaser);
  const body = new THREE.Group();
  body.position.copy(v3(geo.chaser.com_body_m).negate());
  chaser.add(body);
  const bus = geo.chaser.bus;
  const busMesh = new THREE.Mesh(new THREE.BoxGeometry(2 * bus.half_extents_m[0], 2 * bus.half_extents_m[1], 2 * bus.half_extents_m[2]),
    new THREE.MeshPhongMaterial({ color: 0xd9dde3, shininess: 40 }));
  busMesh.position.copy(v3(bus.centre_body_m));
  body.add(busMesh);
  busMesh.add(new THREE.LineSegments(new THREE.EdgesGeometry(busMesh.geometry), new THREE.LineBasicMaterial({ color: 0x6b7384 })));
  const face = new THREE.Mesh(new THREE.PlaneGeometry(0.6 * bus.half_extents_m[1], 0.6 * bus.half_extents_m[2]), new THREE.MeshBasicMaterial({ color: 0x2e8bff }));
  face.rotation.y = Math.PI / 2;  // the +x face (the approach face): a blue mark
  face.position.set(bus.centre_body_m[0] + bus.half_extents_m[0] + 0.005, bus.centre_body_m[1], bus.centre_body_m[2]);
  body.add(face);
  const chaserAxes = new THREE.AxesHelper(1.2 * Math.max(...bus.half_extents_m));
  chaser.add(chaserAxes);
  const thrusterViews = thrusters.map((th) => {
    const g = new THREE.Group();
    g.position.copy(v3(th.position_body_m));
    const exhaust = v3(th.direction_body).normalize().negate();  // the plume leaves opposite the force
    g.quaternion.setFromUnitVectors(up, exhaust);
    const nozzleMat = new THREE.MeshPhongMaterial({ color: 0x9aa3b5, shininess: 40 });
    const nozzle = new THREE.Mesh(new THREE.CylinderGeometry(0.03, 0.055, 0.1, 12), nozzleMat);
    nozzle.position.y = 0.05;
    g.add(nozzle);
    const plumeMat = new THREE.MeshBasicMaterial({ color: 0xffa53a, transparent: true, opacity: 0, blending: THREE.AdditiveBlending, depthWrite: false });
    const plumeGeom = new THREE.ConeGeometry(0.16, 1, 16, 1, true);
    plumeGeom.rotateX(Math.PI);  // apex at the nozzle, widening downstream
    plumeGeom.translate(0, 0.5, 0);
    const plume = new THREE.Mesh(plumeGeom, plumeMat);
    plume.position.y = 0.1;
    plume.visible = false;
    g.add(plume);
    const mark = new THREE.Mesh(new THREE.TorusGeometry(0.09, 0.018, 8, 24), new THREE.MeshBasicMaterial({ color: 0xff3030 }));
    mark.rotation.x = Math.PI / 2;
    mark.position.y = 0.1;
    mark.visible = false;
    g.add(mark);
    body.add(g);
    return { group: g, nozzleMat, plume, plumeMat, mark, intensity: 0, status: 'active' };
  });

  // The trajectory so far.
  const path = new Float32Array(3 * N);
  for (let i = 0; i < 3 * N; ++i) path[i] = track.r[i];
  const pathGeom = new THREE.BufferGeometry();
  pathGeom.setAttribute('position', new THREE.BufferAttribute(path, 3));
  const pathLine = new THREE.Line(pathGeom, new THREE.LineBasicMaterial({ color: 0x66ccff }));
  pathLine.frustumCulled = false;
  scene.add(pathLine);

  // ---- Cameras -----------------------------------------------------------------------------
  // LVLH and target-axes cameras orbit the midpoint of the two bodies at a distance that follows
  // their separation (drag turns, the wheel zooms).
  const view = { mode: 'lvlh', azimuth: -2.2, elevation: 0.45, zoom: 1 };
  const tmpV = new THREE.Vector3(), tmpQ = new THREE.Quaternion();
  function placeCamera() {
    if (view.mode === 'chaser') {  // at the chaser's approach face, looking along its +x, its +z up
      const q = chaser.quaternion;
      const eye = v3([bus.centre_body_m[0] + bus.half_extents_m[0] + 0.3, bus.centre_body_m[1], bus.centre_body_m[2]]).sub(v3(geo.chaser.com_body_m));
      camera.position.copy(eye.applyQuaternion(q).add(chaser.position));
      camera.up.set(0, 0, 1).applyQuaternion(q);
      camera.lookAt(tmpV.set(1, 0, 0).applyQuaternion(q).add(camera.position));
      return;
    }
    const ce = Math.cos(view.elevation);
    const separation = chaser.position.length();
    const distance = view.zoom * (1.4 * separation + 1.2 * targetSize + 3);
    // Spherical about the frame's x (zenith up): azimuth in the y-z plane.
    const offset = new THREE.Vector3(Math.sin(view.elevation), ce * Math.cos(view.azimuth), ce * Math.sin(view.azimuth)).multiplyScalar(distance);
    const upV = new THREE.Vector3(1, 0, 0);
    if (view.mode === 'target') { offset.applyQuaternion(target.quaternion); upV.applyQuaternion(target.quaternion); }
    const centre = chaser.position.clone().multiplyScalar(0.5);
    camera.position.copy(centre).add(offset);
    camera.up.copy(upV);
    camera.lookAt(centre);
  }
  let drag = null;
  renderer.domElement.addEventListener('pointerdown', (e) => { drag = { x: e.clientX, y: e.clientY }; });
  window.addEventListener('pointerup', () => { drag = null; });
  window.addEventListener('pointermove', (e) => {
    if (!drag) return;
    view.azimuth -= 0.006 * (e.clientX - drag.x);
    view.elevation = Math.max(-1.5, Math.min(1.5, view.elevation + 0.006 * (e.clientY - drag.y)));
    drag = { x: e.clientX, y: e.clientY };
    requestRender();
  });
  renderer.domElement.addEventListener('wheel', (e) => {
    e.preventDefault();
    view.zoom = Math.max(0.05, Math.min(20, view.zoom * Math.exp(0.001 * e.deltaY)));
    requestRender();
  }, { passive: false });

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

  // ---- State at a time ---------------------------------------------------------------------
  const state = { t: t0, playing: false, speed: 100, camera: 'lvlh', phase: -1, errors: {} };
  const pos = [0, 0, 0], ref = [0, 0, 0];
  function apply(t) {
    t = Math.max(t0, Math.min(tEnd, t));
    state.t = t;
    const [i, f] = locate(t);
    vecAt(track.r, i, f, pos);
    chaser.position.set(pos[0], pos[1], pos[2]);
    quatAt(track.qb, i, f, chaser.quaternion);
    quatAt(track.qt, i, f, target.quaternion);
    placeArm(i, f);
    pathGeom.setDrawRange(0, i + 1);
    const k = periodIndex(t);
    const mask = activeMask(t);
    thrusterViews.forEach((v, n) => {
      const on = k >= 0 ? onTimes[k * nThr + n] / 255 : 0;
      v.intensity = on;
      v.plume.visible = on > 0;
      v.plumeMat.opacity = 0.25 + 0.75 * on;
      v.plume.scale.set(0.6 + 0.6 * on, 0.4 + 2.0 * on, 0.6 + 0.6 * on);
      const faulty = t >= faultOnset[n], isolated = t >= isolatedAt[n];
      const standby = mask !== null && !((mask >>> n) & 1);
      v.status = isolated ? 'isolated' : faulty ? 'faulty' : standby ? 'standby' : 'active';
      v.mark.visible = faulty || isolated;
      v.mark.material.color.setHex(isolated ? 0xb05cff : 0xff3030);
      v.nozzleMat.color.setHex(isolated ? 0x6b3f80 : standby ? 0x4a5060 : 0x9aa3b5);
      const c = thrCells[n];
      c.cell.className = 'thr ' + (standby ? 'standby ' : '') + (faulty ? 'fault ' : '') + (isolated ? 'isolated' : '');
      c.bar.style.width = (100 * on) + '%';
      c.cell.title = `${thrusters[n].name}: on-time ${(100 * on).toFixed(0)} % of the period, ${v.status}`;
    });
    const phaseIdx = phaseAt(t);
    if (phaseIdx !== state.phase) { state.phase = phaseIdx; sizeKeepOut(clearanceLimit(phaseIdx)); }
    // The errors the panel shows, at t.
    vecAt(track.ref, i, f, ref);
    const j = Math.min(i + 1, N - 1);
    const att = track.att_err_deg[i] === null ? NaN : track.att_err_deg[i] + f * (track.att_err_deg[j] - track.att_err_deg[i]);
    const p = chaser.position;
    tmpQ.copy(target.quaternion).invert();
    const inTarget = p.clone().applyQuaternion(tmpQ);
    const axis = v3(approach.axis_lvlh).normalize();
    state.errors = {
      range: p.length(),
      position_m: Math.hypot(pos[0] - ref[0], pos[1] - ref[1], pos[2] - ref[2]),
      attitude_deg: att,
      clearance_m: boxes.length ? keepOutDistance([inTarget.x, inTarget.y, inTarget.z]) - geo.chaser.keep_out_radius_m : NaN,
      // The corridor as the mission monitor judges it: beyond its least range, not when synchronised.
      corridor_deg: approach.corridor_judged && p.length() > approach.corridor_min_distance_m ? Math.acos(Math.max(-1, Math.min(1, p.dot(axis) / p.length()))) * DEG : NaN,
    };
    slider.value = t;
    updatePanel(t, phaseIdx, state.errors);
    requestRender();
  }

  function setTime(t) { apply(t); }
  function nextEvent() {
    const e = data.events.find(q => q.t > state.t + 1e-6);
    if (e) setTime(e.t);
    return e ? e.t : null;
  }
  function prevEvent() {
    const list = data.events.filter(q => q.t < state.t - 1e-6);
    const e = list[list.length - 1];
    if (e) setTime(e.t);
    return e ? e.t : null;
  }

  // ---- Loop --------------------------------------------------------------------------------
  let needsRender = true;
  function requestRender() { needsRender = true; }
  function resize() {
    const w = host.clientWidth || 800, h = host.clientHeight || 600;
    renderer.setSize(w, h, true);
    camera.aspect = w / h;
    camera.updateProjectionMatrix();
    requestRender();
  }
  window.addEventListener('resize', resize);
  // While playing: the interval between frames and the page's own work per frame (the state at t,
  // the panel, the render), the last 600 of each.
  const frameTimes = [], frameWork = [];
  let lastFrame = null;
  function frame(now) {
    const workStart = performance.now();
    const playing = state.playing;
    if (state.playing) {
      if (lastFrame !== null) {
        const dt = (now - lastFrame) / 1000;
        frameTimes.push(now - lastFrame);
        if (frameTimes.length > 600) frameTimes.shift();
        apply(state.t + dt * state.speed);
        if (state.t >= tEnd) pause();
      }
      lastFrame = now;
    } else {
      lastFrame = null;
    }
    if (needsRender) {
      placeCamera();
      renderer.render(scene, camera);
      needsRender = false;
    }
    if (playing) {
      frameWork.push(performance.now() - workStart);
      if (frameWork.length > 600) frameWork.shift();
    }
    requestAnimationFrame(frame);
  }
  function play() { if (state.t >= tEnd) apply(t0); state.playing = true; apply(state.t); }
  function pause() { state.playing = false; apply(state.t); }

  $('play').addEventListener('click', play);
  $('pause').addEventListener('click', pause);
  $('next-event').addEventListener('click', nextEvent);
  $('prev-event').addEventListener('click', prevEvent);
  $('speed').addEventListener('change', (e) => { state.speed = Number(e.target.value); apply(state.t); });
  $('camera').addEventListener('change', (e) => { view.mode = state.camera = e.target.value; requestRender(); });
  slider.addEventListener('input', () => setTime(Number(slider.value)));
  window.addEventListener('keydown', (e) => {
    // Keys pressed on a control are the control's (space on the Play button clicks it once).
    if (e.target instanceof HTMLElement && e.target.closest('button, select, input')) return;
    if (e.code === 'Space') { e.preventDefault(); state.playing ? pause() : play(); }
    if (e.code === 'ArrowRight') nextEvent();
    if (e.code === 'ArrowLeft') prevEvent();
  });

  const sceneBuiltMs = performance.now();
  resize();
  apply(t0);
  placeCamera();
  renderer.render(scene, camera);
  renderer.getContext().finish();  // the first frame drawn, shaders compiled
  needsRender = false;
  requestAnimationFrame(frame);

  // ---- For tests and scripts ---------------------------------------------------------------
  function worldOf(obj) { return obj.getWorldPosition(new THREE.Vector3()).toArray(); }
  function quatWxyz(q) { return [q.w, q.x, q.y, q.z]; }
  window.chaserView = {
    loadMs: performance.now(),  // from the start of navigation to the first frame drawn
    // Where the load went: milliseconds from the start of navigation to each step's end.
    loadSteps: { scriptStartMs, dataParsedMs, sceneBuiltMs, firstFrameMs: performance.now() },
    t0, tEnd,
    events: data.events,
    meta: data.meta,
    setTime, nextEvent, prevEvent, play, pause,
    setSpeed(s) { state.speed = s; $('speed').value = String(s); apply(state.t); },
    setCamera(mode) { $('camera').value = mode; view.mode = state.camera = mode; requestRender(); },
    // The drawn scene at the current time, read from its objects.
    state() {
      chaser.updateMatrixWorld(true);
      target.updateMatrixWorld(true);
      return {
        t: state.t,
        playing: state.playing,
        speed: state.speed,
        camera: state.camera,
        phase: state.phase >= 0 ? phases[state.phase].name : null,
        chaser: { r_lvlh_m: chaser.position.toArray(), q_lvlh_from_body: quatWxyz(chaser.quaternion) },
        target: { q_lvlh_from_target: quatWxyz(target.quaternion) },
        plumes: thrusterViews.map(v => (v.plume.visible ? v.intensity : 0)),
        thrusters: thrusterViews.map(v => v.status),
        arm: arm.visible && track.arm ? { tool_lvlh_m: worldOf(armJoints[8]) } : null,
        errors: state.errors,
        slider: Number(slider.value),
        keepOutVisible: keepOutZone.visible,
      };
    },
    frameIntervalsMs() { return frameTimes.slice(); },
    frameWorkMs() { return frameWork.slice(); },
  };
  document.title = document.title + ' (ready)';
})();
