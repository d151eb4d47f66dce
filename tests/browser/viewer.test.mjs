// The page of `routh animate` in headless Chromium (WebGL through SwiftShader), driven as a
// user would: no console error and no network request, the 3D canvas is not blank, the time
// slider moves the ball, and the ball is drawn where the samples put it.
//
// Run by .ci/run: `npm ci` here, then `node --test tests/browser/viewer.test.mjs` with the
// release binary built (ROUTH_BIN overrides its path, CHROMIUM that of the browser). With
// ROUTH_SCREENSHOT=FILE.png it also writes the screenshot shown in the README.
import { test, before, after } from "node:test";
import assert from "node:assert/strict";
import { execFileSync } from "node:child_process";
import { mkdtempSync, readFileSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { join, resolve } from "node:path";
import { analyse, launch, openPage, pixelStats } from "./common.mjs";

const root = resolve(import.meta.dirname, "..", "..");
const routhBin = process.env.ROUTH_BIN ?? join(root, "target", "release", "routh");
// The default case: R = 1, a = 0.3 (cases/default.toml).
const R = 1, A = 0.3;
const T_END = 4, SAMPLES = 401;

let browser, dir, casePage, csvPage, samples;

function routh(...args) {
  return execFileSync(routhBin, args, { encoding: "utf8" });
}

// The CSV of `routh simulate --full` as rows of named numbers.
function readCsv(path) {
  const [header, ...lines] = readFileSync(path, "utf8").trim().split("\n");
  const names = header.split(",");
  return lines.map(line => Object.fromEntries(line.split(",").map((v, i) => [names[i], Number(v)])));
}

before(async () => {
  dir = mkdtempSync(join(tmpdir(), "routh-viewer-"));
  routh("animate", "--t-end", String(T_END), "--samples", String(SAMPLES), "--out", join(dir, "case"));
  casePage = join(dir, "case", "animation.html");
  const csv = join(dir, "full.csv");
  routh("simulate", "--full", "--t-end", String(T_END), "--samples", String(SAMPLES), "--out", csv);
  routh("animate", "--csv", csv, "--out", join(dir, "csv"));
  csvPage = join(dir, "csv", "animation.html");
  samples = readCsv(csv);
  browser = await launch();
});

after(async () => { await browser?.close(); });

// The viewer loaded, drawn, and paused (it starts playing).
async function openViewer(path, width, height) {
  const { page, log } = await openPage(width, height);
  await page.goto("file://" + path);
  await page.waitForFunction(() => window.routhViewer?.rendered(), null, { timeout: 30000 });
  await page.click("#play");
  return { page, log };
}

// Wait until the page has drawn the change and two more frames have been presented, so that
// a screenshot shows the new picture.
async function drawn(page) {
  await page.waitForFunction(() => window.routhViewer.rendered());
  await page.evaluate(() => new Promise(r => requestAnimationFrame(() => requestAnimationFrame(r))));
}

async function setTime(page, t) {
  await page.$eval("#time", (el, t) => { el.value = t; el.dispatchEvent(new Event("input")); }, t);
  await drawn(page);
  return page.evaluate(() => window.routhViewer.time());
}

async function setFollow(page, on) {
  if ((await page.isChecked("#follow")) !== on) await page.click("#follow");
  await drawn(page);
}

// For each disc [x, y, r], the fraction of its pixels that differ by more than 24 between two
// screenshots.
const differenceIn = discs => (a, b) => discs.map(([cx, cy, r]) => {
  let inside = 0, changed = 0;
  for (let y = Math.max(0, Math.floor(cy - r)); y < Math.min(a.height, cy + r); y++) {
    for (let x = Math.max(0, Math.floor(cx - r)); x < Math.min(a.width, cx + r); x++) {
      if ((x - cx) ** 2 + (y - cy) ** 2 > r * r) continue;
      const i = 4 * (y * a.width + x);
      inside++;
      const d = Math.abs(a.data[i] - b.data[i]) + Math.abs(a.data[i + 1] - b.data[i + 1])
              + Math.abs(a.data[i + 2] - b.data[i + 2]);
      if (d > 24) changed++;
    }
  }
  return changed / inside;
});
async function difference(discs, a, b) {
  return analyse(`(${differenceIn.toString()})(${JSON.stringify(discs)})`, a, b);
}

// The ball's centre on the screen and a radius safely inside its outline: 0.8 of the screen
// length of a vertical radius (shortened by the camera's elevation, never longer than R).
async function ballDisc(page) {
  return page.evaluate(([a, R]) => {
    const v = window.routhViewer, centre = v.bodyToWorld([0, 0, a]);
    const [x, y] = v.screenOf(centre), [, top] = v.screenOf([centre[0], centre[1], centre[2] + R]);
    return [x, y, 0.8 * Math.abs(y - top)];
  }, [A, R]);
}

test("no console error and no network request, from a case and from a CSV file", async () => {
  for (const path of [casePage, csvPage]) {
    const { page, log } = await openViewer(path);
    await setTime(page, T_END / 2);
    await page.click("#play");
    await page.waitForTimeout(300);
    await page.click("#play");
    assert.deepEqual(log.errors, [], path);
    assert.deepEqual(log.requests.filter(u => !u.startsWith("file://") && !u.startsWith("data:")), [], path);
    assert.equal(log.requests.filter(u => u.startsWith("file://")).length, 1, "only the page itself");
    await page.close();
  }
});

test("negative control: the same listener catches the error of the old blank page", async () => {
  // The page was blank because `const top` clashed with window.top.
  const { page, log } = await openPage();
  await page.setContent("<script>const top = 1;</script>");
  assert.equal(log.errors.length, 1);
  assert.match(log.errors[0], /top/);
  await page.close();
});

test("the 3D canvas is not blank", async t => {
  const { page } = await openViewer(casePage);
  await setTime(page, 1);
  const shot = await page.locator("#view canvas").screenshot();
  const stats = await analyse(pixelStats.toString(), shot);
  t.diagnostic(`3D canvas: ${JSON.stringify(stats)}`);
  // A lit, textured ball, its shadow, the trail and the grid on a plane of one colour:
  // measured 10% of the pixels away from the most common colour and hundreds of colours; a
  // blank canvas has none away and one colour.
  assert.ok(stats.width > 600 && stats.height > 300, JSON.stringify(stats));
  assert.ok(stats.spread > 0.03, `spread ${stats.spread}`);
  assert.ok(stats.colours > 100, `colours ${stats.colours}`);
  // Negative control: a blank element of the same size fails both thresholds.
  await page.evaluate(() => {
    const blank = document.createElement("div");
    blank.id = "blank";
    blank.style.cssText = "position:fixed;left:0;top:0;width:800px;height:500px;background:#eef1f5";
    document.body.append(blank);
  });
  const empty = await analyse(pixelStats.toString(), await page.locator("#blank").screenshot());
  t.diagnostic(`blank element: ${JSON.stringify(empty)}`);
  assert.ok(empty.spread < 0.03 && empty.colours < 100, JSON.stringify(empty));
  await page.close();
});

test("moving the time slider moves the ball", async t => {
  const { page } = await openViewer(casePage);
  // Overview camera: the ball moves on the screen.
  await setFollow(page, false);
  await setTime(page, 0);
  const discA = await ballDisc(page), shotA = await page.locator("#view canvas").screenshot();
  await setTime(page, 2);
  const discB = await ballDisc(page), shotB = await page.locator("#view canvas").screenshot();
  const moved = Math.hypot(discA[0] - discB[0], discA[1] - discB[1]);
  assert.ok(moved > discA[2] + discB[2], `the ball moved ${moved} px, radii ${discA[2]}, ${discB[2]}`);
  const [atA, atB] = await difference([discA, discB], shotA, shotB);
  t.diagnostic(`overview: moved ${moved.toFixed(1)} px; changed ${atA.toFixed(3)} of the first disc, ${atB.toFixed(3)} of the second`);
  // Where the ball was and where it is now, the picture changes (measured: 0.55 to 1 of the
  // discs; parts of the ivory octants and the plane can differ by less than the threshold).
  assert.ok(atA > 0.3 && atB > 0.3, `changed ${atA}, ${atB}`);
  // Negative control: back to the same time, the same picture.
  await setTime(page, 0);
  const [again] = await difference([discA], shotA, await page.locator("#view canvas").screenshot());
  assert.ok(again < 0.01, `changed ${again} at the same time`);

  // Following camera: the ball stays in place on the screen and its markings turn.
  await setFollow(page, true);
  await setTime(page, 1);
  const discC = await ballDisc(page), shotC = await page.locator("#view canvas").screenshot();
  await setTime(page, 1.25);
  const discD = await ballDisc(page), shotD = await page.locator("#view canvas").screenshot();
  assert.ok(Math.hypot(discC[0] - discD[0], discC[1] - discD[1]) < 2, `${discC} vs ${discD}`);
  const [turned] = await difference([discC], shotC, shotD);
  t.diagnostic(`following: the ball moved ${Math.hypot(discC[0] - discD[0], discC[1] - discD[1]).toFixed(2)} px, its markings changed on ${turned.toFixed(3)} of its disc`);
  assert.ok(turned > 0.1, `the markings changed on ${turned} of the ball`);
  await page.close();
});

// |u - v| for 3-vectors.
const distance = (u, v) => Math.hypot(u[0] - v[0], u[1] - v[1], u[2] - v[2]);

test("the ball is drawn where the samples put it: quaternion body to space", async t => {
  const { page } = await openViewer(csvPage);
  let worst = 0, worstConjugate = Infinity;
  for (let k = 0; k < samples.length; k += 25) {
    const s = samples[k];
    const t = await setTime(page, s.t);
    assert.ok(Math.abs(t - s.t) < 1e-9, `${t} vs ${s.t}`);
    // The body point r = R gamma + a e3 (from the gamma columns) is at the contact point.
    const r = [R * s.gamma1, R * s.gamma2, R * s.gamma3 + A];
    const drawn = await page.evaluate(r => window.routhViewer.bodyToWorld(r), r);
    worst = Math.max(worst, distance(drawn, [s.contact_x, s.contact_y, 0]));
    // Negative control: the conjugate quaternion (space to body) misplaces it.
    const { position, quaternion: [x, y, z, w] } = await page.evaluate(() => window.routhViewer.pose());
    const conjugate = rotate([-x, -y, -z, w], r).map((v, i) => v + position[i]);
    worstConjugate = Math.min(worstConjugate,
      Math.max(distance(conjugate, [s.contact_x, s.contact_y, 0]), distance(drawn, conjugate)));
  }
  t.diagnostic(`contact point: worst ${worst.toExponential(2)}; conjugate quaternion: at least ${worstConjugate.toExponential(2)} off`);
  // The samples are embedded as float32 (relative 6e-8): positions of order 10 R agree to 1e-5 R.
  assert.ok(worst < 1e-5, `the body point at the contact is ${worst} away from it`);
  assert.ok(worstConjugate > 1e-2, `the conjugate convention is only ${worstConjugate} off`);
  // At t = 0 the marker of the first contact point is at the bottom of the ball.
  await setTime(page, 0);
  const [marker, centre] = await page.evaluate(([g, R, A]) => [
    window.routhViewer.bodyToWorld([R * g[0], R * g[1], R * g[2] + A]),
    window.routhViewer.bodyToWorld([0, 0, A])], [[samples[0].gamma1, samples[0].gamma2, samples[0].gamma3], R, A]);
  assert.ok(distance(marker, [centre[0], centre[1], centre[2] - R]) < 1e-5, `${marker} vs ${centre}`);
  await page.close();
});

// Rotate v by the unit quaternion (x, y, z, w): v + 2w (u x v) + 2 u x (u x v).
function rotate([x, y, z, w], v) {
  const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
  const u = [x, y, z], c1 = cross(u, v), c2 = cross(u, c1);
  return v.map((vi, i) => vi + 2 * (w * c1[i] + c2[i]));
}

test("between samples: positions linear, the quaternion by slerp", async t => {
  const { page } = await openViewer(csvPage);
  let worstContact = 0;
  for (let k = 10; k + 1 < samples.length; k += 50) {
    const a = samples[k], b = samples[k + 1];
    await setTime(page, (a.t + b.t) / 2);
    const { position, quaternion } = await page.evaluate(() => window.routhViewer.pose());
    const mid = ["x", "y", "z"].map(n => (a[n] + b[n]) / 2);
    assert.ok(distance(position, mid) < 1e-5, `${position} vs ${mid}`);
    // slerp halfway: the normalised sum of the two quaternions (same hemisphere).
    const qa = [a.qx, a.qy, a.qz, a.qw], qb = [b.qx, b.qy, b.qz, b.qw];
    const sign = qa.reduce((s, v, i) => s + v * qb[i], 0) < 0 ? -1 : 1;
    const sum = qa.map((v, i) => v + sign * qb[i]), norm = Math.hypot(...sum);
    const half = sum.map(v => v / norm);
    const err = Math.min(Math.hypot(...half.map((v, i) => v - quaternion[i])),
                         Math.hypot(...half.map((v, i) => v + quaternion[i])));
    assert.ok(err < 1e-6, `slerp off by ${err}`);
    // Not a step function: the pose differs from both ends.
    assert.ok(Math.hypot(...qa.map((v, i) => v - quaternion[i])) > 1e-4);
    // The interpolated ball still touches the plane near the interpolated contact point.
    const bottom = await page.evaluate(a => {
      const c = window.routhViewer.bodyToWorld([0, 0, a]);
      return [c[0], c[1], c[2] - 1];
    }, A);
    worstContact = Math.max(worstContact, distance(bottom, [(a.contact_x + b.contact_x) / 2,
                                                           (a.contact_y + b.contact_y) / 2, 0]));
  }
  t.diagnostic(`halfway between samples the ball misses the contact point by at most ${worstContact.toExponential(2)}`);
  // Linear interpolation errs by (acceleration) dt^2 / 8: the centre and the contact point
  // accelerate by ~ 1 m/s^2 in the default case, dt = 0.01 s, so ~ 1e-5 (measured 1.5e-5).
  assert.ok(worstContact < 1e-4, `the interpolated ball misses the contact by ${worstContact}`);
  await page.close();
});

test("screenshot for the README (only with ROUTH_SCREENSHOT)", async t => {
  const out = process.env.ROUTH_SCREENSHOT;
  if (!out) { t.skip("ROUTH_SCREENSHOT not set"); return; }
  const page20 = join(dir, "docs");
  routh("animate", "--t-end", "20", "--out", page20);
  const { page } = await openViewer(join(page20, "animation.html"), 1280, 720);
  await setTime(page, 6.4);
  writeFileSync(out, await page.screenshot());
  await page.close();
});

// The purple to magenta pixels of a PNG (red and blue both above green by 40), the colours of
// a slipping trail: none of the ball's (orange, ivory, the blue cap, the red tip), the plane's
// or a rolling trail's blue.
const slipping = () => shot => {
  let count = 0;
  for (let i = 0; i < shot.data.length; i += 4) {
    const [r, g, b] = [shot.data[i], shot.data[i + 1], shot.data[i + 2]];
    if (r > g + 40 && b > g + 40) count++;
  }
  return count;
};

test("the tippe top turns over in the viewer, its slipping trail shaded apart", async t => {
  // issue 35: `routh animate --case cases/tippe_top.toml` (sliding contact, viscous friction):
  // the centre of mass drawn at R - a = 0.7 at t = 0 and at R + a = 1.3 at t = 20 (within
  // 0.01: the samples' height), no console error, and the trail of the contact point shaded
  // by its slip (magenta to purple where it slips; a rolling ball's page has none).
  routh("animate", "--case", join(root, "cases", "tippe_top.toml"), "--samples", "801",
        "--out", join(dir, "tippe"));
  const { page, log } = await openViewer(join(dir, "tippe", "animation.html"));
  const height = () => page.evaluate(() => window.routhViewer.bodyToWorld([0, 0, 0])[2]);
  await setTime(page, 0);
  const low = await height();
  await setTime(page, 20);
  const high = await height();
  t.diagnostic(`centre of mass at t = 0: ${low}, at t = 20: ${high}`);
  assert.ok(Math.abs(low - 0.7) < 0.01 && Math.abs(high - 1.3) < 0.01, `${low} ${high}`);
  const shot = await page.locator("#view canvas").screenshot();
  const purple = await analyse(`(${slipping.toString()})()`, shot);
  t.diagnostic(`slipping trail pixels: ${purple}`);
  assert.ok(purple > 100, `slipping trail pixels ${purple}`);
  if (process.env.ROUTH_TIPPE_SCREENSHOT) writeFileSync(process.env.ROUTH_TIPPE_SCREENSHOT, shot);
  const rolling = await openViewer(casePage);
  await setTime(rolling.page, T_END);
  const control = await analyse(`(${slipping.toString()})()`,
                                await rolling.page.locator("#view canvas").screenshot());
  assert.ok(control < purple / 4, `a rolling ball's page: ${control} slipping pixels`);
  assert.deepEqual(log.errors, []);
  await rolling.page.close();
  await page.close();
});
