// The three cameras (LVLH, target axes, from the chaser) and the mouse's turn and zoom.

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
