// The 3D scene in LVLH: lights, LVLH's axes, the approach corridor, the target with its keep-out
// volume and fixture, the arm, the chaser with its thrusters and plumes, the trajectory.

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
