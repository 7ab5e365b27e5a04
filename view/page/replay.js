// The replay: the scene and the panel at a time, the frame loop, the controls, and the state the
// tests read (window.chaserView).

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
