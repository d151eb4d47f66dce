/* The 3D view of the rolling ball and its charts: one script for the pages of `routh animate`
   (one precomputed run) and `routh explore` (runs computed in the page). It needs three.js
   (the global THREE) and the page's elements with ids view, theta, drift, play, speed, time,
   clock, follow and reset. RouthViewer.create() builds the scene once; show(D) puts a motion
   in it:
     D.radius, D.a        the ball's R and offset a of the centre of mass
     D.gamma0             gamma at the first sample
     D.columns            arrays by name: t, qw, qx, qy, qz, x, y, z, contact_x, contact_y,
                          theta (degrees); optional slip: of a sliding contact, 0 to 1, the
                          slip speed on a log scale over the four decades below its largest,
                          which shades the trail from blue (rolling) to magenta (the fastest)
     D.drift              [{name, values}]: the running maximum relative drift of each integral
     D.thetaExtra         optional [{name, values}]: more curves on the theta chart (the exact
                          solution), at the same times
   Frames (crates/routh-io/src/animate.rs): the body group has its origin at the centre of mass
   and is turned by the samples' quaternion (body to space); the sphere is centred at +a e3. */
"use strict";
const RouthViewer = (() => {
// Lines 10^n or 2·10^n or 5·10^n apart, about `rough`.
function niceStep(rough) {
  const p = Math.pow(10, Math.floor(Math.log10(rough))), f = rough / p;
  return p * (f < 1.5 ? 1 : f < 3.5 ? 2 : f < 7.5 ? 5 : 10);
}
function ticks(lo, hi, count) {
  const step = niceStep((hi - lo) / count), out = [];
  for (let v = Math.ceil(lo / step) * step; v <= hi + 1e-9 * step; v += step) out.push(v);
  return out;
}
function label(v) {
  return Math.abs(v) < 1e-12 ? "0" : Number(v.toPrecision(4)).toString();
}
const PALETTE = ["#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b"];

// The sample interval [k, k + 1] of the increasing array xs holding x, and the fraction s of
// the way through it.
function locate(xs, x) {
  const n = xs.length;
  if (n < 2 || x <= xs[0]) return [0, 0];
  if (x >= xs[n - 1]) return [n - 2, 1];
  let lo = 0, hi = n - 1;
  while (hi - lo > 1) {
    const mid = (lo + hi) >> 1;
    if (xs[mid] <= x) lo = mid; else hi = mid;
  }
  return [lo, (x - xs[lo]) / (xs[lo + 1] - xs[lo])];
}
function lerp(column, k, s) {
  return s === 0 ? column[k] : column[k + 1] === undefined ? column[k]
                                                           : column[k] + s * (column[k + 1] - column[k]);
}

/* A 2D chart on `canvas`: series [{name, x, y, color?, dots?}] against x, `log` for a log
   scale of y, `xLabel`, `marks` [{x, y, color, name}] drawn as large dots; `onPick(x)` when
   the chart is clicked. Returns cursor(x): redraws with a vertical line and dots at x. */
function chart(canvas, { title, xLabel = "t (s)", series, log = false, marks = [], onPick }) {
  const dpr = window.devicePixelRatio || 1;
  const w = canvas.clientWidth, h = canvas.clientHeight;
  canvas.width = Math.round(w * dpr); canvas.height = Math.round(h * dpr);
  const ctx = canvas.getContext("2d");
  ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
  ctx.clearRect(0, 0, w, h);
  const left = 58, right = 10, top = 24, bottom = 30;
  const value = v => (log ? (v > 0 ? Math.log10(v) : NaN) : v);
  let lo = Infinity, hi = -Infinity, x0 = Infinity, x1 = -Infinity;
  const points = series.concat(marks.map(m => ({ x: [m.x], y: [m.y] })));
  for (const s of points) {
    for (let i = 0; i < s.y.length; i++) {
      const u = value(s.y[i]);
      if (Number.isFinite(u) && Number.isFinite(s.x[i])) {
        lo = Math.min(lo, u); hi = Math.max(hi, u);
        x0 = Math.min(x0, s.x[i]); x1 = Math.max(x1, s.x[i]);
      }
    }
  }
  if (!(hi >= lo)) { lo = 0; hi = 1; }
  if (!(x1 >= x0)) { x0 = 0; x1 = 1; }
  if (log) { lo = Math.floor(lo); hi = Math.max(Math.ceil(hi), lo + 1); }
  else { const pad = 0.06 * (hi - lo || 1); lo -= pad; hi += pad; }
  const px = x => left + (w - left - right) * (x - x0) / (x1 - x0 || 1);
  const py = u => h - bottom - (h - top - bottom) * (u - lo) / (hi - lo);
  ctx.font = "12px 'DejaVu Sans', Verdana, sans-serif";
  ctx.fillStyle = "#222"; ctx.textBaseline = "top"; ctx.textAlign = "left";
  ctx.fillText(title, left, 5);
  ctx.strokeStyle = "#ddd"; ctx.lineWidth = 1; ctx.fillStyle = "#444";
  ctx.textAlign = "right"; ctx.textBaseline = "middle";
  const yTicks = log ? Array.from({ length: hi - lo + 1 }, (_, i) => lo + i)
                          .filter((_, i, all) => all.length <= 7 || i % Math.ceil(all.length / 6) === 0)
                     : ticks(lo, hi, 4);
  for (const u of yTicks) {
    ctx.beginPath(); ctx.moveTo(left, py(u)); ctx.lineTo(w - right, py(u)); ctx.stroke();
    ctx.fillText(log ? "1e" + u : label(u), left - 5, py(u));
  }
  ctx.textAlign = "center"; ctx.textBaseline = "top";
  for (const x of ticks(x0, x1, 5)) {
    ctx.beginPath(); ctx.moveTo(px(x), top); ctx.lineTo(px(x), h - bottom); ctx.stroke();
    ctx.fillText(label(x), px(x), h - bottom + 4);
  }
  ctx.textAlign = "right";
  ctx.fillText(xLabel, w - right - 2, h - 13);
  ctx.strokeStyle = "#888"; ctx.strokeRect(left, top, w - left - right, h - top - bottom);
  const colour = (s, j) => s.color || PALETTE[j % PALETTE.length];
  series.forEach((s, j) => {
    ctx.strokeStyle = colour(s, j); ctx.lineWidth = 1.4; ctx.beginPath();
    let pen = false;
    for (let i = 0; i < s.y.length; i++) {
      const u = value(s.y[i]);
      if (!Number.isFinite(u)) { pen = false; continue; }
      if (pen) ctx.lineTo(px(s.x[i]), py(u)); else ctx.moveTo(px(s.x[i]), py(u));
      pen = true;
    }
    ctx.setLineDash(s.dash || []);
    ctx.stroke();
    ctx.setLineDash([]);
  });
  for (const m of marks) {
    ctx.fillStyle = m.color; ctx.beginPath();
    ctx.arc(px(m.x), py(value(m.y)), 5, 0, 2 * Math.PI); ctx.fill();
  }
  const named = series.map((s, j) => ({ name: s.name, color: colour(s, j) }))
    .concat(marks.map(m => ({ name: m.name, color: m.color }))).filter(s => s.name);
  if (named.length > 1) {
    ctx.textAlign = "left"; ctx.textBaseline = "middle";
    const widths = named.map(s => 19 + ctx.measureText(s.name).width);
    let x = w - right - 4 - widths.reduce((a, b) => a + b, 0);
    named.forEach((s, j) => {    // bottom right: drift curves start at round-off, high up
      const y = h - bottom - 10;
      ctx.fillStyle = s.color; ctx.fillRect(x, y - 4, 8, 8);
      ctx.fillStyle = "#222"; ctx.fillText(s.name, x + 11, y);
      x += widths[j];
    });
  }
  const background = ctx.getImageData(0, 0, canvas.width, canvas.height);
  canvas.onpointerdown = onPick && (e => {
    const r = canvas.getBoundingClientRect();
    const x = x0 + (x1 - x0) * (e.clientX - r.left - left) / (w - left - right);
    onPick(Math.min(x1, Math.max(x0, x)));
  });
  return x => {
    ctx.putImageData(background, 0, 0);
    ctx.strokeStyle = "#000"; ctx.lineWidth = 1;
    ctx.beginPath(); ctx.moveTo(px(x), top); ctx.lineTo(px(x), h - bottom); ctx.stroke();
    series.forEach((s, j) => {
      const [k, f] = locate(s.x, x), u = value(lerp(s.y, k, f));
      if (!Number.isFinite(u)) return;
      ctx.fillStyle = colour(s, j);
      ctx.beginPath(); ctx.arc(px(x), py(u), 3.5, 0, 2 * Math.PI); ctx.fill();
    });
  };
}

// The ball's texture: the octants of its body frame, polar caps at +-e3.
function octantTexture() {
  const canvas = document.createElement("canvas"), w = 1024, h = 512;
  canvas.width = w; canvas.height = h;
  const ctx = canvas.getContext("2d");
  // Columns: longitude about e3 in quarters (seams at ±e1, ±e2); rows: the two hemispheres.
  for (let q = 0; q < 4; q++) {
    for (let half = 0; half < 2; half++) {
      ctx.fillStyle = (q + half) % 2 ? "#f5efe0" : "#f08a24";
      ctx.fillRect(q * w / 4, half * h / 2, w / 4, h / 2);
    }
  }
  ctx.fillStyle = "#3a2a1a";
  for (let q = 0; q <= 4; q++) ctx.fillRect(q * w / 4 - 3, 0, 6, h);
  ctx.fillRect(0, h / 2 - 3, w, 6);
  const cap = h * 14 / 180;               // polar caps of 14 degrees
  ctx.fillStyle = "#d62728"; ctx.fillRect(0, 0, w, cap);          // +e3
  ctx.fillStyle = "#2c4a7a"; ctx.fillRect(0, h - cap, w, cap);    // -e3
  const texture = new THREE.CanvasTexture(canvas);
  texture.colorSpace = THREE.SRGBColorSpace;
  texture.anisotropy = 4;
  return texture;
}

function create() {
  // ---- the scene: space frame z up, the plane z = 0 ----
  const container = document.getElementById("view");
  const renderer = new THREE.WebGLRenderer({ antialias: true });
  renderer.setPixelRatio(window.devicePixelRatio || 1);
  renderer.shadowMap.enabled = true;
  container.appendChild(renderer.domElement);
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0xeef1f5);
  scene.add(new THREE.HemisphereLight(0xffffff, 0x8a96a8, 1.6));
  const sun = new THREE.DirectionalLight(0xffffff, 2.2);
  sun.castShadow = true;
  sun.shadow.mapSize.set(1024, 1024);
  sun.shadow.radius = 3;
  scene.add(sun, sun.target);
  const texture = octantTexture();
  const camera = new THREE.PerspectiveCamera(35, 1, 0.01, 200);
  camera.up.set(0, 0, 1);
  const controls = new THREE.OrbitControls(camera, renderer.domElement);
  const follow = document.getElementById("follow");

  // ---- the motion shown: its samples and the objects built from them ----
  let C = null, N = 0, R = 1, A = 0, T0 = 0, T1 = 1, motion = null, body = null, ball = null;
  let contactDot = null, ribbon = null, mid = [0, 0], reach = 1;
  let thetaCursor = () => {}, driftCursor = () => {};
  const ballCentre = new THREE.Vector3();
  let now = 0, playing = true, dirty = true, last = null, dragging = false;

  function dispose(object) {
    object.traverse(o => {
      if (o.geometry) o.geometry.dispose();
      if (o.material && o.material.map !== texture) o.material.dispose();
    });
  }

  // Everything that depends on the motion, in one group replaced by each show(D).
  function build(D) {
    if (motion) { scene.remove(motion); dispose(motion); }
    motion = new THREE.Group();
    scene.add(motion);
    Object.assign(sun.shadow.camera, { left: -2 * R, right: 2 * R, top: 2 * R, bottom: -2 * R,
                                       near: 0.1 * R, far: 20 * R });
    sun.shadow.camera.updateProjectionMatrix();
    // The extent of the motion on the plane.
    let xmin = Infinity, xmax = -Infinity, ymin = Infinity, ymax = -Infinity;
    for (let i = 0; i < N; i++) {
      for (const [x, y] of [[C.contact_x[i], C.contact_y[i]], [C.x[i], C.y[i]]]) {
        xmin = Math.min(xmin, x); xmax = Math.max(xmax, x);
        ymin = Math.min(ymin, y); ymax = Math.max(ymax, y);
      }
    }
    mid = [(xmin + xmax) / 2, (ymin + ymax) / 2];
    reach = Math.hypot(xmax - xmin, ymax - ymin) / 2 + 1.5 * R;
    camera.near = 0.01 * R; camera.far = 200 * reach; camera.updateProjectionMatrix();

    // The plane and a grid of lines about R/2 apart.
    const gridStep = niceStep(R / 2);
    const cells = 2 * Math.ceil((reach + R) / gridStep);
    const gridCentre = mid.map(v => gridStep * Math.round(v / gridStep));
    const floor = new THREE.Mesh(new THREE.PlaneGeometry(40 * cells * gridStep, 40 * cells * gridStep),
                                 new THREE.MeshStandardMaterial({ color: 0xdfe4ea, roughness: 0.95 }));
    floor.position.set(gridCentre[0], gridCentre[1], 0);
    floor.receiveShadow = true;
    motion.add(floor);
    const grid = new THREE.GridHelper(cells * gridStep, cells, 0x9aa4b1, 0xc3cad3);
    grid.rotation.x = Math.PI / 2;
    grid.position.set(gridCentre[0], gridCentre[1], 1e-3 * R);
    motion.add(grid);

    // The trail of the contact point: the whole path faint, the part up to now a ribbon.
    const path = new THREE.BufferGeometry();
    const pathPoints = new Float32Array(3 * N);
    for (let i = 0; i < N; i++) pathPoints.set([C.contact_x[i], C.contact_y[i], 2e-3 * R], 3 * i);
    path.setAttribute("position", new THREE.Float32BufferAttribute(pathPoints, 3));
    motion.add(new THREE.Line(path, new THREE.LineBasicMaterial({ color: 0x1f77b4, transparent: true,
                                                                   opacity: 0.6 })));
    ribbon = new THREE.BufferGeometry();
    {
      const half = 0.025 * R, corners = new Float32Array(6 * N), index = [];
      for (let i = 0; i < N; i++) {
        const a = Math.max(i - 1, 0), b = Math.min(i + 1, N - 1);
        let dx = C.contact_x[b] - C.contact_x[a], dy = C.contact_y[b] - C.contact_y[a];
        const len = Math.hypot(dx, dy) || 1;
        dx /= len; dy /= len;
        corners.set([C.contact_x[i] - half * dy, C.contact_y[i] + half * dx, 3e-3 * R,
                     C.contact_x[i] + half * dy, C.contact_y[i] - half * dx, 3e-3 * R], 6 * i);
        if (i > 0) index.push(2 * i - 2, 2 * i - 1, 2 * i, 2 * i - 1, 2 * i + 1, 2 * i);
      }
      ribbon.setAttribute("position", new THREE.Float32BufferAttribute(corners, 3));
      ribbon.setIndex(index);
      if (C.slip) {
        // A sliding contact: each sample's colour from the rolling blue to the slipping magenta.
        const rolling = new THREE.Color(0x1f77b4), slipping = new THREE.Color(0xc51b7d);
        const colours = new Float32Array(6 * N), c = new THREE.Color();
        for (let i = 0; i < N; i++) {
          c.copy(rolling).lerp(slipping, Math.min(Math.max(C.slip[i], 0), 1));
          colours.set([c.r, c.g, c.b, c.r, c.g, c.b], 6 * i);
        }
        ribbon.setAttribute("color", new THREE.Float32BufferAttribute(colours, 3));
      }
    }
    // Pulled towards the camera in depth, so that from afar it does not sink into the floor.
    const lifted = { polygonOffset: true, polygonOffsetFactor: -4, polygonOffsetUnits: -4 };
    motion.add(new THREE.Mesh(ribbon, C.slip
      ? new THREE.MeshBasicMaterial({ vertexColors: true, ...lifted })
      : new THREE.MeshBasicMaterial({ color: 0x1f77b4, ...lifted })));
    contactDot = new THREE.Mesh(new THREE.CylinderGeometry(0.06 * R, 0.06 * R, 4e-3 * R, 24),
                                new THREE.MeshBasicMaterial({ color: 0x0b3c66 }));
    contactDot.rotation.x = Math.PI / 2;
    motion.add(contactDot);

    // The ball: a group in the body frame (origin at the centre of mass, e3 the symmetry axis),
    // turned by the quaternion of the samples (body to space) and placed at the centre of mass.
    body = new THREE.Group();
    motion.add(body);
    // The sphere's own pole axis is its y axis: a quarter turn about x puts it along e3.
    ball = new THREE.Mesh(new THREE.SphereGeometry(R, 96, 48),
                          new THREE.MeshStandardMaterial({ map: texture, roughness: 0.5 }));
    ball.rotation.x = Math.PI / 2;
    ball.position.set(0, 0, A);
    ball.castShadow = true;
    body.add(ball);
    const rod = new THREE.Mesh(new THREE.CylinderGeometry(0.015 * R, 0.015 * R, 2.6 * R, 12),
                               new THREE.MeshStandardMaterial({ color: 0x333333 }));
    rod.rotation.x = Math.PI / 2;
    rod.position.set(0, 0, A);
    rod.castShadow = true;
    body.add(rod);
    const tip = new THREE.Mesh(new THREE.SphereGeometry(0.05 * R, 16, 8),
                               new THREE.MeshStandardMaterial({ color: 0xd62728 }));
    tip.position.set(0, 0, A + 1.3 * R);
    body.add(tip);
    const com = new THREE.Mesh(new THREE.SphereGeometry(0.055 * R, 16, 8),
                               new THREE.MeshBasicMaterial({ color: 0x111111, depthTest: false,
                                                             transparent: true, opacity: 0.85 }));
    com.renderOrder = 10;
    body.add(com);
    // The body point that touched the plane at the first sample: r = R gamma + a e3 from the
    // centre of mass (gamma from the samples' gamma columns, not from the quaternion).
    const touched = new THREE.Mesh(new THREE.SphereGeometry(0.07 * R, 16, 8),
                                   new THREE.MeshStandardMaterial({ color: 0x2b2b2b }));
    touched.position.set(R * D.gamma0[0], R * D.gamma0[1], R * D.gamma0[2] + A);
    body.add(touched);
  }

  // ---- camera: following the ball from 9 R away, or the whole motion from above ----
  function resetView() {
    const direction = new THREE.Vector3(0.35, -1, 0.55).normalize();
    if (follow.checked) {
      controls.target.copy(ballCentre);
      camera.position.copy(ballCentre).addScaledVector(direction, 9 * R);
    } else {
      controls.target.set(mid[0], mid[1], 0);
      camera.position.copy(controls.target)
        .addScaledVector(direction, 0.7 * reach / Math.sin(17.5 * Math.PI / 180));
    }
    controls.update();
  }

  // ---- the state at time t: linear positions, quaternion slerp ----
  const qa = new THREE.Quaternion(), qb = new THREE.Quaternion();
  function pose(t) {
    const [k, s] = locate(C.t, t), k1 = Math.min(k + 1, N - 1);
    qa.set(C.qx[k], C.qy[k], C.qz[k], C.qw[k]).normalize();
    qb.set(C.qx[k1], C.qy[k1], C.qz[k1], C.qw[k1]).normalize();
    body.quaternion.slerpQuaternions(qa, qb, s);
    const before = ballCentre.clone();
    body.position.set(lerp(C.x, k, s), lerp(C.y, k, s), lerp(C.z, k, s));
    body.updateMatrixWorld(true);
    ball.getWorldPosition(ballCentre);
    contactDot.position.set(lerp(C.contact_x, k, s), lerp(C.contact_y, k, s), 2e-3 * R);
    ribbon.setDrawRange(0, 6 * (k + (s > 0.5 ? 1 : 0)));
    if (follow.checked) {
      const shift = ballCentre.clone().sub(before);
      camera.position.add(shift);
      controls.target.add(shift);
      controls.update();
    }
    sun.target.position.copy(ballCentre);
    sun.position.copy(ballCentre).add(new THREE.Vector3(2.5 * R, -3.5 * R, 7 * R));
  }

  // ---- controls and the animation loop ----
  const playButton = document.getElementById("play"), speed = document.getElementById("speed");
  const slider = document.getElementById("time"), clock = document.getElementById("clock");
  function seek(t) { now = t; dirty = true; }
  function setPlaying(on) { playing = on; playButton.textContent = on ? "Pause" : "Play"; }
  playButton.onclick = () => setPlaying(!playing);
  // While the slider is held, playing does not move it.
  slider.addEventListener("input", () => seek(Number(slider.value)));
  slider.addEventListener("pointerdown", () => { dragging = true; });
  window.addEventListener("pointerup", () => { dragging = false; });
  document.getElementById("reset").onclick = () => { resetView(); dirty = true; };
  follow.addEventListener("change", () => { resetView(); dirty = true; });
  controls.addEventListener("change", () => { dirty = true; });
  document.addEventListener("keydown", e => {
    if (e.key === " " && !["INPUT", "SELECT", "BUTTON"].includes(e.target.tagName)) {
      e.preventDefault(); setPlaying(!playing);
    }
  });

  function charts(D) {
    const thetaCanvas = document.getElementById("theta"), driftCanvas = document.getElementById("drift");
    const thetaSeries = [{ name: "θ", x: C.t, y: C.theta }].concat(
      (D.thetaExtra || []).map(s => ({ name: s.name, x: C.t, y: s.values, dash: [6, 4] })));
    if (thetaSeries.length > 1) thetaSeries[0].name = "θ integrated";
    thetaCursor = chart(thetaCanvas, { title: "tilt θ(t) in degrees, cos θ = γ3",
                                       series: thetaSeries, onPick: seek });
    driftCursor = chart(driftCanvas, {
      title: D.drift.length ? "integrals: running max of |H − H(0)| / |H(0)|"
                            : "no integral columns in the samples",
      series: D.drift.map(s => ({ name: s.name, x: C.t, y: s.values })), log: true, onPick: seek });
  }

  function resize() {
    const w = container.clientWidth, h = container.clientHeight;
    renderer.setSize(w, h);
    camera.aspect = w / h;
    camera.updateProjectionMatrix();
    dirty = true;
  }
  new ResizeObserver(resize).observe(container);
  resize();

  // Show the motion D (see the top of this file), keeping the time if it is within it.
  function show(D) {
    C = D.columns; N = C.t.length; R = D.radius; A = D.a; T0 = C.t[0]; T1 = C.t[N - 1];
    const first = motion === null;
    build(D);
    charts(D);
    slider.min = T0; slider.max = T1;
    now = first ? T0 : Math.min(Math.max(now, T0), T1);
    slider.value = now;
    pose(now);
    if (first) resetView();
    dirty = true;
  }

  function loop(time) {
    if (C && playing && last !== null && N > 1) {
      now += Number(speed.value) * (time - last) / 1000;
      if (now > T1) now = T0 + (now - T1) % (T1 - T0);
      dirty = true;
    }
    last = time;
    if (C && dirty) {
      pose(now);
      renderer.render(scene, camera);
      thetaCursor(now); driftCursor(now);
      clock.textContent = "t = " + now.toFixed(3) + " s";
      if (!dragging) slider.value = now;
      dirty = false;
    }
    requestAnimationFrame(loop);
  }
  requestAnimationFrame(loop);
  let lastShown = null;
  addEventListener("resize", () => { if (C) { charts(lastShown); dirty = true; } });

  return {
    show: D => { lastShown = D; show(D); },
    // More curves on the theta chart for the motion shown (D.thetaExtra), without building
    // its 3D objects again.
    setThetaExtra: extra => {
      if (!C) return;
      lastShown = Object.assign({}, lastShown, { thetaExtra: extra });
      charts(lastShown);
      dirty = true;
    },
    setPlaying,
    seek,
    // For tests and the console: the current time, seeking, and where things are drawn.
    api: {
      get samples() { return N; },
      get radius() { return R; },
      get a() { return A; },
      time: () => now,
      bodyToWorld: p => new THREE.Vector3(...p).applyMatrix4(body.matrixWorld).toArray(),
      pose: () => ({ position: body.position.toArray(), quaternion: body.quaternion.toArray() }),
      // CSS pixels from the top left corner of the 3D canvas.
      screenOf: p => {
        const v = new THREE.Vector3(...p).project(camera), el = renderer.domElement;
        return [(v.x + 1) / 2 * el.clientWidth, (1 - v.y) / 2 * el.clientHeight];
      },
      rendered: () => !dirty,
    },
  };
}

return { create, chart, PALETTE };
})();
