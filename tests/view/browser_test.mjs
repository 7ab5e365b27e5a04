// `chaser view`'s page in a real browser (Debian's Chromium, headless, WebGL 2 through SwiftShader),
// driven by playwright-core. Flies a run, writes its page, opens it from disk and checks it against
// the telemetry file read here, independently of the page:
//   - it loads with no console error and no page error, within the page-size limit;
//   - the chaser and the target are where (and turned as) the telemetry puts them at several times;
//   - the thruster plumes match the period's realised on-times; faulty and isolated marks appear
//     from the fault's onset and its isolation;
//   - the slider, the event buttons, the timeline and play move the time;
//   - a screenshot shows the scene (many distinct colours), from each camera.
// Usage: node browser_test.mjs CHASER_BINARY msr|sync|capture   (run from the repository root)
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import zlib from 'node:zlib';
import { createRequire } from 'node:module';

const require = createRequire(path.resolve('view/package.json'));
let chromium;
try {
  ({ chromium } = require('playwright-core'));
} catch (e) {
  console.error('playwright-core is not installed in view/node_modules: run scripts/install-deps');
  process.exit(1);
}

const [chaserBinary, runName] = process.argv.slice(2);
const runs = {
  msr: ['scenarios/msr_terminal.yaml', '--set', 'faults=[{thruster: T8, kind: stuck_open, onset_s: 1000}]'],
  sync: ['scenarios/comrade_sync.yaml'],
  capture: ['scenarios/comrade_capture.yaml'],
};
if (!runs[runName]) { console.error('usage: browser_test.mjs CHASER_BINARY msr|sync|capture'); process.exit(1); }

let failures = 0;
function check(ok, what) {
  if (!ok) { failures += 1; console.error('FAIL: ' + what); } else console.log('ok: ' + what);
}

// ---- The run and its page --------------------------------------------------------------------
const dir = fs.mkdtempSync(path.join(os.tmpdir(), `chaser-view-${runName}-`));
execFileSync(chaserBinary, ['run', runs[runName][0], '--out', dir, ...runs[runName].slice(1)], { stdio: 'inherit' });
const pagePath = path.join(dir, 'view.html');
const viewStart = process.hrtime.bigint();
execFileSync(chaserBinary, ['view', dir], { stdio: 'inherit' });
const viewSeconds = Number(process.hrtime.bigint() - viewStart) / 1e9;
const pageBytes = fs.statSync(pagePath).size;
console.log(`page: ${(pageBytes / 1e6).toFixed(2)} MB, written in ${viewSeconds.toFixed(2)} s`);
check(pageBytes < 10e6, `the page is under 10 MB (${pageBytes} bytes)`);

// ---- The telemetry, read here ----------------------------------------------------------------
const lines = fs.readFileSync(path.join(dir, 'telemetry.csv'), 'utf8').trimEnd().split('\n');
const header = lines[0].split(',');
const col = Object.fromEntries(header.map((h, i) => [h, i]));
const rows = lines.slice(1).map(l => l.split(',').map(Number));
const geometry = JSON.parse(fs.readFileSync(path.join(dir, 'geometry.json'), 'utf8'));
const summary = JSON.parse(fs.readFileSync(path.join(dir, 'summary.json'), 'utf8'));
const n = geometry.lvlh.mean_motion_radps;
const T = summary.control_period_s;
const nThr = geometry.chaser.thrusters.length;
const value = (r, name) => rows[r][col[name]];

// Quaternions as [w, x, y, z].
function qmul(a, b) {
  return [a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
    a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
    a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
    a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0]];
}
function qrot(q, v) {
  const p = qmul(qmul(q, [0, ...v]), [q[0], -q[1], -q[2], -q[3]]);
  return p.slice(1);
}
const qAngle = (a, b) => 2 * Math.acos(Math.min(1, Math.abs(a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3])));
function quatOf(r, base) { return ['w', 'x', 'y', 'z'].map(c => value(r, `${base}_${c}`)); }
// LVLH turns about z at n from the run's inertial frame (LVLH at t = 0): q_lvlh_from_inertial.
const qLvlhFromInertial = t => [Math.cos(n * t / 2), 0, 0, -Math.sin(n * t / 2)];
// The truth at a row's time, in LVLH.
function truthAt(r) {
  const t = value(r, 't_s');
  return {
    t,
    r: ['x', 'y', 'z'].map(c => value(r, `r_lvlh_${c}_m`)),
    qb: qmul(qLvlhFromInertial(t), quatOf(r, 'q_inertial_from_body')),
    qt: qmul(qLvlhFromInertial(t), quatOf(r, 'q_inertial_from_target')),
  };
}

// ---- PNG decoding for the screenshot's colours (8-bit RGB or RGBA, no interlace) ---------------
function decodePng(buf) {
  let pos = 8, width = 0, height = 0, channels = 4;
  const idat = [];
  while (pos < buf.length) {
    const len = buf.readUInt32BE(pos), type = buf.toString('ascii', pos + 4, pos + 8);
    const data = buf.subarray(pos + 8, pos + 8 + len);
    if (type === 'IHDR') { width = data.readUInt32BE(0); height = data.readUInt32BE(4); channels = data[9] === 6 ? 4 : 3; }
    if (type === 'IDAT') idat.push(data);
    pos += 12 + len;
  }
  const raw = zlib.inflateSync(Buffer.concat(idat));
  const stride = width * channels, out = Buffer.alloc(height * stride);
  for (let y = 0; y < height; ++y) {
    const filter = raw[y * (stride + 1)];
    for (let x = 0; x < stride; ++x) {
      const cur = raw[y * (stride + 1) + 1 + x];
      const a = x >= channels ? out[y * stride + x - channels] : 0;
      const b = y > 0 ? out[(y - 1) * stride + x] : 0;
      const c = x >= channels && y > 0 ? out[(y - 1) * stride + x - channels] : 0;
      let v;
      if (filter === 0) v = cur;
      else if (filter === 1) v = cur + a;
      else if (filter === 2) v = cur + b;
      else if (filter === 3) v = cur + ((a + b) >> 1);
      else { const p = a + b - c, pa = Math.abs(p - a), pb = Math.abs(p - b), pc = Math.abs(p - c); v = cur + (pa <= pb && pa <= pc ? a : pb <= pc ? b : c); }
      out[y * stride + x] = v & 255;
    }
  }
  return { width, height, channels, pixels: out };
}
function colourFigures(png) {
  const colours = new Set();
  const bg = [5, 7, 13];
  let lit = 0;
  for (let i = 0; i < png.width * png.height; ++i) {
    const p = i * png.channels;
    const r = png.pixels[p], g = png.pixels[p + 1], b = png.pixels[p + 2];
    colours.add((r << 16) | (g << 8) | b);
    if (Math.abs(r - bg[0]) + Math.abs(g - bg[1]) + Math.abs(b - bg[2]) > 30) lit += 1;
  }
  return { distinct: colours.size, litFraction: lit / (png.width * png.height) };
}

// ---- The browser -----------------------------------------------------------------------------
const browser = await chromium.launch({
  executablePath: process.env.CHASER_CHROMIUM || '/usr/bin/chromium',
  headless: true,
  args: ['--no-sandbox', '--enable-unsafe-swiftshader', '--use-angle=swiftshader', '--disable-background-networking',
    '--disable-component-update', '--disable-sync', '--no-first-run', '--disable-quic'],
});
const problems = [];
try {
  const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
  page.on('console', m => { if (m.type() === 'error') problems.push('console error: ' + m.text()); });
  page.on('pageerror', e => problems.push('page error: ' + e.message));
  page.on('request', r => { if (!r.url().startsWith('file:') && !r.url().startsWith('data:')) problems.push('network request: ' + r.url()); });
  await page.goto('file://' + pagePath);
  await page.waitForFunction(() => window.chaserView !== undefined, null, { timeout: 60000 });
  const loadMs = await page.evaluate(() => window.chaserView.loadMs);
  const steps = await page.evaluate(() => window.chaserView.loadSteps);
  console.log(`load: ${loadMs.toFixed(0)} ms from navigation to the first frame (page and three.js read ${steps.scriptStartMs.toFixed(0)}, ` +
    `data parsed ${(steps.dataParsedMs - steps.scriptStartMs).toFixed(0)}, scene built ${(steps.sceneBuiltMs - steps.dataParsedMs).toFixed(0)}, ` +
    `first frame ${(steps.firstFrameMs - steps.sceneBuiltMs).toFixed(0)})`);
  check(loadMs < 10000, `the page loads (first frame in ${loadMs.toFixed(0)} ms)`);
  // CHASER_VIEW_LOADS=N reloads the page N times more and prints every load time and their median.
  const reloads = Number(process.env.CHASER_VIEW_LOADS || 0);
  if (reloads > 0) {
    const loads = [loadMs];
    for (let i = 0; i < reloads; ++i) {
      await page.reload();
      await page.waitForFunction(() => window.chaserView !== undefined, null, { timeout: 60000 });
      loads.push(await page.evaluate(() => window.chaserView.loadMs));
    }
    const sorted = [...loads].sort((a, b) => a - b);
    console.log(`loads: ${loads.map(l => l.toFixed(0)).join(', ')} ms; median ${sorted[Math.floor(sorted.length / 2)].toFixed(0)} ms`);
  }
  const webgl2 = await page.evaluate(() => !!document.querySelector('#scene canvas').getContext('webgl2'));
  check(webgl2, 'the scene draws through WebGL 2');
  const meta = await page.evaluate(() => window.chaserView.meta);
  check(meta.telemetry_rows === rows.length, `the page read every telemetry row (${meta.telemetry_rows} of ${rows.length})`);
  const state = () => page.evaluate(() => window.chaserView.state());
  const setTime = t => page.evaluate(t => window.chaserView.setTime(t), t);

  // Bodies where the telemetry puts them: at rows (some kept, most dropped by the decimation) and
  // half-way between rows; tolerance: the decimation's (5 mm, 0.2 deg), and the data's rounding.
  const picks = [0, 1, 7, Math.floor(rows.length / 7), Math.floor(rows.length / 3), Math.floor(rows.length / 2) + 3,
    Math.floor(0.77 * rows.length), Math.floor(0.93 * rows.length), rows.length - 1];
  let worstR = 0, worstQb = 0, worstQt = 0;
  for (const r of picks) {
    for (const half of r + 1 < rows.length ? [false, true] : [false]) {
      const a = truthAt(r), b = half ? truthAt(r + 1) : a;
      const t = half ? (a.t + b.t) / 2 : a.t;
      await setTime(t);
      const s = await state();
      check(Math.abs(s.t - t) < 1e-9, `setTime(${t}) puts the page at ${s.t}`);
      // Half-way, the truth itself moves: the midpoint of two rows 0.1 s apart, within the tolerance.
      const rExp = a.r.map((v, k) => (v + b.r[k]) / 2);
      worstR = Math.max(worstR, Math.hypot(...s.chaser.r_lvlh_m.map((v, k) => v - rExp[k])));
      worstQb = Math.max(worstQb, Math.min(qAngle(s.chaser.q_lvlh_from_body, a.qb), qAngle(s.chaser.q_lvlh_from_body, b.qb)));
      worstQt = Math.max(worstQt, Math.min(qAngle(s.target.q_lvlh_from_target, a.qt), qAngle(s.target.q_lvlh_from_target, b.qt)));
    }
  }
  console.log(`worst: position ${(worstR * 1000).toFixed(2)} mm, chaser attitude ${(worstQb * 180 / Math.PI).toFixed(3)} deg, target ${(worstQt * 180 / Math.PI).toFixed(3)} deg`);
  check(worstR <= 0.0052, `the chaser is where the telemetry puts it (worst ${(worstR * 1000).toFixed(2)} mm <= 5.2 mm)`);
  // Half-way between rows the tumbling target turns 0.05 s x 2.5 deg/s = 0.125 deg more; the nearer row is within that plus the tolerance.
  check(worstQb * 180 / Math.PI <= 0.35, `the chaser is turned as the telemetry turns it (worst ${(worstQb * 180 / Math.PI).toFixed(3)} deg)`);
  check(worstQt * 180 / Math.PI <= 0.35, `the target is turned as the telemetry turns it (worst ${(worstQt * 180 / Math.PI).toFixed(3)} deg)`);

  // Plumes: the period's realised on-times (quantised to 1/255), in periods where thrusters fire.
  let firingPeriods = 0, worstPlume = 0, lit = 0;
  const candidates = [];
  for (let r = 0; r < rows.length && candidates.length < 12; r += Math.max(1, Math.floor(rows.length / 400)))
    if (geometry.chaser.thrusters.some((_, i) => value(r, `ton_real_${i + 1}`) > 0.02)) candidates.push(r);
  for (const r of candidates) {
    await setTime(value(r, 't_s') + T / 2);
    const s = await state();
    for (let i = 0; i < nThr; ++i) {
      const expected = value(r, `ton_real_${i + 1}`);
      worstPlume = Math.max(worstPlume, Math.abs(s.plumes[i] - expected));
      if (s.plumes[i] > 0) lit += 1;
    }
    firingPeriods += 1;
  }
  check(firingPeriods >= 5 && lit >= 5, `plumes lit in ${firingPeriods} firing periods (${lit} plumes)`);
  check(worstPlume <= 0.5 / 255 + 1e-9, `plumes match the on-times (worst ${worstPlume.toFixed(5)})`);

  // Events: the page's, against the telemetry's alarms and the summary's faults and phases.
  const events = await page.evaluate(() => window.chaserView.events);
  for (const p of summary.phases_flown)
    check(events.some(e => e.kind === 'phase' && Math.abs(e.t - p.start_s) < 1e-6), `phase ${p.name} at ${p.start_s} s is an event`);
  for (const scheme of ['position', 'attitude', 'deficit']) {
    if (col[`alarm_${scheme}`] === undefined) continue;
    let last = 0;
    for (let r = 0; r < rows.length; ++r) {
      const a = value(r, `alarm_${scheme}`);
      if (a > 0.5 && last <= 0.5) {
        const t = value(r, 't_s');
        check(events.some(e => e.kind === 'alarm' && Math.abs(e.t - t) < 1e-9), `the ${scheme} alarm at ${t} s is an event`);
      }
      last = a;
    }
  }
  // Next-event steps through every event in order, from the start.
  await setTime(meta.t0_s);
  const times = [...new Set(events.map(e => e.t))].filter(t => t > meta.t0_s + 1e-6).sort((a, b) => a - b);
  let stepped = 0;
  for (const t of times.slice(0, 6)) {
    await page.click('#next-event');
    const s = await state();
    check(Math.abs(s.t - t) < 1e-9, `next event moves the time to ${t} s (at ${s.t})`);
    stepped += 1;
  }
  check(stepped === Math.min(6, times.length) && times.length > 0, `the event button stepped through ${stepped} events`);
  if (times.length > 1) {
    await page.click('#prev-event');
    check(Math.abs((await state()).t - times[Math.min(6, times.length) - 2]) < 1e-9, 'previous event moves the time back');
  }

  // Faults and isolations marked from their times (the MSR run's T8 stuck open).
  for (const f of summary.faults) {
    const i = Number(f.thruster.slice(1)) - 1;
    await setTime(f.onset_s - 1);
    check((await state()).thrusters[i] !== 'faulty', `${f.thruster} unmarked before its onset`);
    await setTime(f.onset_s + 0.05);
    check((await state()).thrusters[i] === 'faulty', `${f.thruster} marked faulty from its onset`);
    const iso = summary.fdir.isolation_time_s;
    if (summary.fdir.isolated_thruster === f.thruster && iso !== null) {
      await setTime(f.onset_s + iso + 0.05);
      check((await state()).thrusters[i] === 'isolated', `${f.thruster} marked isolated from ${f.onset_s + iso} s`);
    }
  }

  // The arm, where the run has one: the tool point where the telemetry's figure puts it.
  if (col.tool_target_x_m !== undefined) {
    const awake = rows.findIndex(row => Number.isFinite(row[col.tool_target_x_m]));
    check(awake >= 0, `the arm wakes in this run (at row ${awake})`);
    const r = Math.min(rows.length - 1, Math.max(0, awake) + 200);
    const truth = truthAt(r);
    await setTime(truth.t);
    const s = await state();
    const expected = qrot(truth.qt, ['x', 'y', 'z'].map(c => value(r, `tool_target_${c}_m`)));
    const err = s.arm ? Math.hypot(...s.arm.tool_lvlh_m.map((v, k) => v - expected[k])) : Infinity;
    check(err < 0.05, `the arm's tool point is where the telemetry puts it (${(err * 1000).toFixed(1)} mm off)`);
  }

  // The slider and the timeline move the time.
  const tSlider = Math.round(meta.t0_s + 0.4 * (meta.t_end_s - meta.t0_s));
  await page.locator('#slider').fill(String(tSlider));
  check(Math.abs((await state()).t - tSlider) < 1e-6, `the slider set to ${tSlider} moves the time there`);
  const sliderBox = await page.locator('#slider').boundingBox();
  await page.mouse.click(sliderBox.x + 0.25 * sliderBox.width, sliderBox.y + sliderBox.height / 2);
  const tDragged = (await state()).t;
  check(Math.abs(tDragged - (meta.t0_s + 0.25 * (meta.t_end_s - meta.t0_s))) < 0.03 * (meta.t_end_s - meta.t0_s),
    `a click on the slider a quarter along moves the time there (to ${tDragged.toFixed(1)} s)`);
  const box = await page.locator('#timeline').boundingBox();
  await page.mouse.click(box.x + 0.75 * box.width, box.y + box.height / 2);
  const tTimeline = (await state()).t;
  check(Math.abs(tTimeline - (meta.t0_s + 0.75 * (meta.t_end_s - meta.t0_s))) < 0.01 * (meta.t_end_s - meta.t0_s),
    `a click on the timeline moves the time (to ${tTimeline.toFixed(1)} s)`);

  // Play at x100 moves the time on; pause holds it.
  await page.selectOption('#speed', '100');
  await setTime(meta.t0_s);
  await page.click('#play');
  await page.waitForTimeout(1500);
  await page.click('#pause');
  const played = await state();
  const intervals = await page.evaluate(() => window.chaserView.frameIntervalsMs());
  const work = await page.evaluate(() => window.chaserView.frameWorkMs());
  const mean = a => a.reduce((x, y) => x + y, 0) / Math.max(1, a.length);
  console.log(`play: ${played.t.toFixed(1)} s of run in 1.5 s at x100; mean frame interval ${mean(intervals).toFixed(1)} ms over ${intervals.length} frames, the page's work ${mean(work).toFixed(1)} ms a frame (SwiftShader)`);
  check(played.t > meta.t0_s + 50 && played.t < meta.t_end_s && !played.playing && played.speed === 100, `play moves the time on (to ${played.t.toFixed(1)} s) and pause stops it`);
  await page.waitForTimeout(300);
  check((await state()).t === played.t, 'paused, the time holds');
  // The keyboard: space plays and pauses, the arrows step through the events.
  await page.locator('#scene canvas').click();
  await page.keyboard.press('Space');
  check((await state()).playing, 'space plays');
  await page.keyboard.press('Space');
  check(!(await state()).playing, 'space again pauses');
  await setTime(meta.t0_s);
  await page.keyboard.press('ArrowRight');
  check(times.length === 0 || Math.abs((await state()).t - times[0]) < 1e-9, 'the right arrow goes to the first event');

  // Screenshots from each camera: the scene, not a blank canvas.
  const tShot = summary.faults.length ? summary.faults[0].onset_s + 0.3 : meta.t0_s + 0.8 * (meta.t_end_s - meta.t0_s);
  await setTime(tShot);
  const scene = await page.locator('#scene').boundingBox();
  for (const cam of ['lvlh', 'target', 'chaser']) {
    await page.selectOption('#camera', cam);
    await page.waitForTimeout(200);
    const shot = await page.screenshot({ clip: scene, path: path.join(dir, `view-${cam}.png`) });
    const figures = colourFigures(decodePng(shot));
    console.log(`screenshot ${cam}: ${figures.distinct} colours, ${(100 * figures.litFraction).toFixed(1)} % of pixels off the background`);
    // A blank canvas has one colour. The LVLH camera sees the whole scene: hundreds of colours; from
    // close in (the chaser's camera at a capture's hold point) a face of the target may fill the view.
    const least = cam === 'lvlh' ? 100 : 30;
    check(figures.distinct >= least && figures.litFraction > 0.005, `the ${cam} camera shows the scene (${figures.distinct} colours, at least ${least})`);
  }
  // CHASER_VIEW_SHOTS=DIR keeps the screenshots (DIR/view-RUN-CAMERA.png).
  if (process.env.CHASER_VIEW_SHOTS)
    for (const cam of ['lvlh', 'target', 'chaser'])
      fs.copyFileSync(path.join(dir, `view-${cam}.png`), path.join(process.env.CHASER_VIEW_SHOTS, `view-${runName}-${cam}.png`));
} finally {
  await browser.close();
}
for (const p of problems) check(false, p);
check(problems.length === 0, 'no console error, page error or network request');
if (failures === 0) fs.rmSync(dir, { recursive: true, force: true });
else console.error(`kept ${dir} for a look`);
console.log(failures === 0 ? 'all checks passed' : `${failures} checks failed`);
process.exit(failures === 0 ? 0 : 1);
