// The browser side of dhlab's "canvas" backend (dhlab/views/live/canvas.py).
//
// Why: a slider step used to cost a full matplotlib render and a PNG (17 ms in the kernel and
// 10-20 ms of decoding here). Now the kernel sends, per step, the moving artists as numbers
// (dhlab/views/live/scene.py) and this module paints them over a background picture that matplotlib
// made once. When nothing has moved for REST_MS, it asks the kernel for matplotlib's own frame
// and shows that: at rest the picture is exactly matplotlib's. Dragging a 3D axes turns it
// here, with mplot3d's own maths (viewMatrix below), and the final view goes back to Python.
//
// The maths (viewMatrix, compose, project, depthOrder, dragView) uses no DOM, so node can
// import this file and tests/views/test_canvas_js.py checks it against matplotlib.

import { differsFromFullPaint, paintedBounds, union } from "./dirty.js";
import { coversAll, rigged, sameQ, slidersQ, spaceOut } from "./rig.js";

const REST_MS = 150;          // no new pose for this long: ask for the exact frame
const BOX_COLOR = "rgba(120,120,120,0.55)";

// --- maths, as mplot3d does it (axes3d.get_proj, proj3d) ---------------------------------------
const deg = (a) => (a * Math.PI) / 180;
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const norm = (a) => Math.hypot(a[0], a[1], a[2]);
const scaled = (a, s) => [a[0] * s, a[1] * s, a[2] * s];
const dot3 = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];

export function normAngle(a) {
  // matplotlib's art3d._norm_angle: -180 < a <= 180
  a = (((a + 360) % 360) + 360) % 360;
  return a > 180 ? a - 360 : a;
}

function rotationAbout(v, angle) {
  const [vx, vy, vz] = scaled(v, 1 / norm(v));
  const s = Math.sin(angle), c = Math.cos(angle), t = 2 * Math.sin(angle / 2) ** 2;
  return [[t * vx * vx + c, t * vx * vy - vz * s, t * vx * vz + vy * s],
          [t * vy * vx + vz * s, t * vy * vy + c, t * vy * vz - vx * s],
          [t * vz * vx - vy * s, t * vz * vy + vx * s, t * vz * vz + c]];
}

const matVec3 = (R, v) => R.map((row) => dot3(row, v));

function matMul(A, B) {
  return A.map((row) => B[0].map((_, j) => row.reduce((sum, a, k) => sum + a * B[k][j], 0)));
}

// ax.get_proj() for a z-up axes: cam has limits [x0,x1,y0,y1,z0,z1], aspect (box), dist, focal
export function viewMatrix(cam, elev, azim, roll) {
  const [x0, x1, y0, y1, z0, z1] = cam.limits;
  const [ax, ay, az] = cam.aspect;
  const dx = (x1 - x0) / ax, dy = (y1 - y0) / ay, dz = (z1 - z0) / az;
  const world = [[1 / dx, 0, 0, -x0 / dx], [0, 1 / dy, 0, -y0 / dy], [0, 0, 1 / dz, -z0 / dz], [0, 0, 0, 1]];
  const R = scaled(cam.aspect, 0.5);
  const e = deg(elev), a = deg(azim);
  const ps = [Math.cos(e) * Math.cos(a), Math.cos(e) * Math.sin(a), Math.sin(e)];
  const focal = cam.focal == null ? 1 : cam.focal;
  const eye = R.map((r, i) => r + cam.dist * ps[i] * focal);
  // _calc_view_axes with _view_axes
  const V = [0, 0, Math.abs(deg(normAngle(elev))) > Math.PI / 2 ? -1 : 1];
  const eyeR = R.map((r, i) => r + cam.dist * ps[i]);
  let w = eyeR.map((v, i) => v - R[i]);
  w = scaled(w, 1 / norm(w));
  let u = cross(V, w);
  u = scaled(u, 1 / norm(u));
  let v = cross(w, u);
  const r = deg(normAngle(roll));
  if (r !== 0) {
    const Rr = rotationAbout(w, -r);
    u = matVec3(Rr, u);
    v = matVec3(Rr, v);
  }
  const view = [[...u, -dot3(u, eye)], [...v, -dot3(v, eye)], [...w, -dot3(w, eye)], [0, 0, 0, 1]];
  const d = cam.dist;
  const proj = cam.focal == null
    ? [[2, 0, 0, 0], [0, 2, 0, 0], [0, 0, -2, 0], [0, 0, 0, 2 * d]]      // _ortho_transformation(-d, d)
    : [[focal, 0, 0, 0], [0, focal, 0, 0], [0, 0, 0, -d], [0, 0, -1, 0]]; // _persp_transformation(-d, d, f)
  return matMul(proj, matMul(view, world));
}

// (x, y, z, 1) -> (px, py, depth, w): transData's affine A (2x3, canvas pixels) after M
export function compose(A, M) {
  const row = (i) => M[0].map((_, j) => A[3 * i] * M[0][j] + A[3 * i + 1] * M[1][j] + A[3 * i + 2] * M[3][j]);
  return [row(0), row(1), M[2], M[3]].flat();
}

// canvas pixels [x, y, depth] of n points (flat x, y, z from `at`); NaN stays NaN
export function project(P, data, at, n) {
  const out = new Float64Array(3 * n);
  for (let i = 0; i < n; i++) {
    const x = data[at + 3 * i], y = data[at + 3 * i + 1], z = data[at + 3 * i + 2];
    const w = P[12] * x + P[13] * y + P[14] * z + P[15];
    out[3 * i] = (P[0] * x + P[1] * y + P[2] * z + P[3]) / w;
    out[3 * i + 1] = (P[4] * x + P[5] * y + P[6] * z + P[7]) / w;
    out[3 * i + 2] = (P[8] * x + P[9] * y + P[10] * z + P[11]) / w;
  }
  return out;
}

// the painting order of faces as mplot3d's zsort ("average", "min", "max"): farthest first
export function depthOrder(projected, faces, corners, sort) {
  const key = new Float64Array(faces);
  for (let f = 0; f < faces; f++) {
    let sum = 0, count = 0, lo = Infinity, hi = -Infinity;
    for (let k = 0; k < corners; k++) {
      const z = projected[3 * (f * corners + k) + 2];
      if (Number.isNaN(z)) continue;
      sum += z; count += 1; lo = Math.min(lo, z); hi = Math.max(hi, z);
    }
    key[f] = sort === "min" ? lo : sort === "max" ? hi : sum / count;
  }
  const order = Array.from({ length: faces }, (_, f) => f);
  order.sort((a, b) => key[a] - key[b] || a - b);       // numpy's argsort, then reversed
  return order.reverse();
}

// mplot3d's "azel" mouse rotation: a drag across the whole axes turns the view by 180 degrees
export function dragView(cam, dx, dy, width, height) {
  const r = deg(cam.roll);
  const elev = cam.elev + (dy / height) * 180 * Math.cos(r) + (dx / width) * 180 * Math.sin(r);
  const azim = cam.azim + (dy / height) * 180 * Math.sin(r) - (dx / width) * 180 * Math.cos(r);
  return [elev, azim];
}

// --- painting ---------------------------------------------------------------------------------
function path2d(piece, data, dx = 0, dy = 0) {
  const [at, n] = piece.vertices;
  const codes = piece.codes;
  const p = new Path2D();
  const X = (i) => data[at + 2 * i] + dx, Y = (i) => data[at + 2 * i + 1] + dy;
  for (let i = 0; i < n; i++) {
    const code = codes ? codes[i] : (i === 0 ? 1 : 2);
    if (code === 1) p.moveTo(X(i), Y(i));
    else if (code === 2) p.lineTo(X(i), Y(i));
    else if (code === 3) { p.quadraticCurveTo(X(i), Y(i), X(i + 1), Y(i + 1)); i += 1; }
    else if (code === 4) { p.bezierCurveTo(X(i), Y(i), X(i + 1), Y(i + 1), X(i + 2), Y(i + 2)); i += 2; }
    else if (code === 79) p.closePath();
  }
  return p;
}

const rgba = (c, i) => `rgba(${Math.round(255 * c[4 * i])},${Math.round(255 * c[4 * i + 1])},` +
  `${Math.round(255 * c[4 * i + 2])},${c[4 * i + 3]})`;

function drawLine(ctx, item, xy, data) {
  const n = item.points[1];
  if (item.color) {
    ctx.beginPath();
    let pen = false;
    for (let i = 0; i < n; i++) {
      const x = xy[3 * i], y = xy[3 * i + 1];
      if (!Number.isFinite(x) || !Number.isFinite(y)) { pen = false; continue; }
      if (pen) ctx.lineTo(x, y); else ctx.moveTo(x, y);
      pen = true;
    }
    ctx.strokeStyle = item.color;
    ctx.lineWidth = item.width;
    ctx.lineCap = item.cap;
    ctx.lineJoin = item.join;
    ctx.setLineDash(item.dash || []);
    ctx.lineDashOffset = item.dash_offset || 0;
    ctx.stroke();
    ctx.setLineDash([]);
  }
  const m = item.marker;
  if (!m) return;
  const shape = path2d(m, data);
  ctx.lineJoin = m.join;
  ctx.lineWidth = m.edge_width;
  for (let i = 0; i < n; i++) {
    const x = xy[3 * i], y = xy[3 * i + 1];
    if (!Number.isFinite(x) || !Number.isFinite(y)) continue;
    ctx.save();
    ctx.translate(x, y);
    if (m.fill) { ctx.fillStyle = m.fill; ctx.fill(shape); }
    if (m.edge && m.edge_width > 0) { ctx.strokeStyle = m.edge; ctx.stroke(shape); }
    ctx.restore();
  }
}

function drawPolys(ctx, item, xy, data) {
  const [, faces, corners] = item.faces;
  const order = item.sort ? depthOrder(xy, faces, corners, item.sort)
    : Array.from({ length: faces }, (_, f) => f);
  ctx.lineWidth = item.width;
  ctx.lineJoin = "round";
  const fill = data.subarray(item.fill), edge = data.subarray(item.edge);
  for (const f of order) {
    ctx.beginPath();
    let started = false;
    for (let k = 0; k < corners; k++) {
      const j = 3 * (f * corners + k), x = xy[j], y = xy[j + 1];
      if (!Number.isFinite(x) || !Number.isFinite(y)) continue;
      if (started) ctx.lineTo(x, y); else ctx.moveTo(x, y);
      started = true;
    }
    ctx.closePath();
    ctx.fillStyle = rgba(fill, f);
    ctx.fill();
    if (item.width > 0 && edge[4 * f + 3] > 0) { ctx.strokeStyle = rgba(edge, f); ctx.stroke(); }
  }
}

function drawGlyphs(ctx, item, xy, data) {
  const leaders = item.leaders;
  if (leaders) {
    ctx.strokeStyle = leaders.color;
    ctx.lineWidth = leaders.width;
    leaders.of.forEach((k, i) => {
      const d = leaders.deltas + 4 * i;
      ctx.beginPath();
      ctx.moveTo(xy[3 * k] + data[d], xy[3 * k + 1] + data[d + 1]);
      ctx.lineTo(xy[3 * k] + data[d + 2], xy[3 * k + 1] + data[d + 3]);
      ctx.stroke();
    });
  }
  ctx.fillStyle = item.fill;
  item.pieces.forEach((piece, i) => {
    if (!Number.isFinite(xy[3 * i])) return;
    const shape = path2d(piece, data, xy[3 * i], xy[3 * i + 1]);
    if (item.halo) {                 // a white stroke under the letters, as the course's labels have
      ctx.strokeStyle = item.halo.color;
      ctx.lineWidth = item.halo.width;
      ctx.lineJoin = "round";
      ctx.stroke(shape);
    }
    if (item.fill) ctx.fill(shape);
  });
}

const PAINTERS = { line: drawLine, polys: drawPolys, glyphs: drawGlyphs };
const IDENTITY = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1];

// the canvas pixels of every item's points; `P` overrides the matrix of some spaces (a view being turned)
export function projectItems(scene, data, P = {}) {
  return scene.items.map((item) => {
    const space = item.space;
    const matrix = space < 0 ? IDENTITY : (P[space] || scene.spaces[space].P);
    const where = item.kind === "line" ? item.points : item.kind === "polys" ?
      [item.faces[0], item.faces[1] * item.faces[2]] : item.anchors;
    return project(matrix, data, where[0], where[1]);
  });
}

// paint the scene's items (their points projected by projectItems)
export function paintItems(ctx, scene, data, P = {}, projected = projectItems(scene, data, P)) {
  for (const [i, item] of scene.items.entries()) {
    const xy = projected[i];
    ctx.save();
    if (item.clip) {
      const [x0, y0, x1, y1] = item.clip;
      ctx.beginPath(); ctx.rect(x0, y0, x1 - x0, y1 - y0); ctx.clip();
    }
    PAINTERS[item.kind](ctx, item, xy, data);
    ctx.restore();
  }
}

function paintBox(ctx, cam, P) {
  // the 12 edges of the axes' box: what the turned view shows until matplotlib redraws it
  const [x0, x1, y0, y1, z0, z1] = cam.limits;
  const corners = [];
  for (const x of [x0, x1]) for (const y of [y0, y1]) for (const z of [z0, z1]) corners.push(x, y, z);
  const xy = project(P, corners, 0, 8);
  ctx.beginPath();
  for (let a = 0; a < 8; a++) {
    for (const bit of [1, 2, 4]) {
      const b = a | bit;
      if (b === a) continue;
      ctx.moveTo(xy[3 * a], xy[3 * a + 1]);
      ctx.lineTo(xy[3 * b], xy[3 * b + 1]);
    }
  }
  ctx.strokeStyle = BOX_COLOR;
  ctx.lineWidth = 1;
  ctx.stroke();
}

// --- the widget ---------------------------------------------------------------------------------
function floats(view) {
  // a DataView / ArrayBuffer from the kernel -> Float32Array (copied: alignment)
  const bytes = view instanceof ArrayBuffer ? new Uint8Array(view) :
    new Uint8Array(view.buffer, view.byteOffset, view.byteLength);
  return new Float32Array(bytes.slice().buffer);
}

async function bitmap(view) {
  if (!view || !view.byteLength) return null;
  return createImageBitmap(new Blob([view], { type: "image/png" }));
}

function render({ model, el }) {
  const canvas = document.createElement("canvas");
  canvas.className = "dhlab-canvas";    // for a page (or a browser test) to find the figure
  canvas.style.display = "block";
  canvas.style.touchAction = "none";
  canvas.tabIndex = -1;
  el.appendChild(canvas);
  // opaque: the screen's compositor copies it instead of blending it over the page (the browser's
  // CPU time in a 2-s drag at pixel ratio 1: 3.2 s -> 2.7 s in one pair of runs); so every paint
  // starts from the figure's face colour, never from a cleared (black) canvas.
  // desynchronized (the low-latency hint): the canvas hands its pictures to the screen's compositor
  // itself instead of waiting for the page's own layer update; a 3D-view rotation at pixel ratio 2
  // (a full repaint per frame) went 38.8-45.0 -> 55.8-58.7 frames/s in JupyterLab, in alternated runs
  const ctx = canvas.getContext("2d", { alpha: false, desynchronized: true });
  // for the browser tests (tests/browser): when the last pose arrived, how long a paint took
  const trace = (globalThis.__dhlabCanvas = globalThis.__dhlabCanvas || { scenes: 0 });
  const state = { background: null, frame: null, frameSeq: -1, scene: null, data: null, seq: -1,
                  turning: null, timer: null, pending: false,
                  rig: null, rigData: null, sliders: [], qNow: null, movedAt: 0 };

  // the pose the browser shows ahead of the kernel (a slider moved, its scene not here yet)
  const ahead = () => state.rig && state.scene && state.qNow && !sameQ(state.qNow, state.scene.q);

  function fitSize(width, height) {
    const [cssW, cssH] = model.get("css_size");
    if (canvas.width !== width || canvas.height !== height) { canvas.width = width; canvas.height = height; }
    canvas.style.width = `${cssW}px`;
    canvas.style.height = `${cssH}px`;
  }

  function paint() {
    state.pending = false;
    const started = performance.now();
    const predicted = ahead();
    const image = state.turning || predicted || state.frameSeq < state.seq ? state.background : state.frame;
    if (image) fitSize(image.width, image.height);
    const face = (state.scene && state.scene.face) || "white";
    const moving = image !== state.frame && state.scene;
    const data = !moving ? null : predicted
      ? rigged(state.rig, state.rigData, state.scene.items, state.data, state.qNow) : state.data;
    const P = {};
    if (moving && state.turning) {
      const t = state.turning, cam = state.scene.spaces[t.space];
      P[t.space] = compose(cam.A, viewMatrix(cam, t.elev, t.azim, cam.roll));
    }
    const projected = moving ? projectItems(state.scene, data, P) : null;
    // over the same background, only what the last paint's items and these cover can change (dirty.js)
    const bounds = moving && !state.turning ? paintedBounds(state.scene.items, projected, data,
      canvas.width, canvas.height) : null;
    const last = state.painted;
    const dirty = image && bounds && last && last.bounds && last.image === image && last.face === face
      && last.width === canvas.width && last.height === canvas.height ? union(last.bounds, bounds) : null;
    state.painted = { image, face, bounds, width: canvas.width, height: canvas.height };
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    ctx.save();
    const [x, y, w, h] = dirty ? [dirty[0], dirty[1], dirty[2] - dirty[0], dirty[3] - dirty[1]]
      : [0, 0, canvas.width, canvas.height];
    if (dirty) { ctx.beginPath(); ctx.rect(x, y, w, h); ctx.clip(); }
    ctx.fillStyle = face;
    ctx.fillRect(x, y, w, h);
    if (image && w > 0 && h > 0) ctx.drawImage(image, x, y, w, h, x, y, w, h);
    if (moving) {
      if (state.turning) {
        const cam = state.scene.spaces[state.turning.space];
        const [x0, y0, x1, y1] = cam.bbox;
        ctx.fillStyle = face;
        ctx.fillRect(x0, y0, x1 - x0, y1 - y0);
        paintBox(ctx, cam, P[state.turning.space]);
      }
      paintItems(ctx, state.scene, data, P, projected);
    }
    ctx.restore();
    if (!moving) return;
    if (dirty && trace.verify) {      // the browser tests: the clipped paint equals a full one
      const wrong = differsFromFullPaint(ctx, image, face, (other) => paintItems(other, state.scene, data, {}, projected));
      trace.dirtyChecked = (trace.dirtyChecked || 0) + 1;
      trace.dirtyWrong = Math.max(trace.dirtyWrong || 0, wrong);
    }
    trace.paintMs = performance.now() - started;
    trace.paints = (trace.paints || 0) + 1;
    trace.paintedArea = (trace.paintedArea || 0) + (w * h) / (canvas.width * canvas.height);
    if (predicted) trace.predicted = (trace.predicted || 0) + 1;
  }

  function schedule() {
    if (!state.pending) { state.pending = true; requestAnimationFrame(paint); }
  }

  function askForRest() {
    clearTimeout(state.timer);
    state.timer = setTimeout(() => model.send({ kind: "rest", seq: state.seq }), REST_MS);
  }

  model.on("msg:custom", (msg, buffers) => {
    if (msg.kind === "rig") { linkSliders(msg, floats(buffers[0])); return; }
    if (msg.kind !== "scene") return;
    // a scene sent after a new background (the robot framed again) is drawn over that background,
    // never over the old one: it waits while the picture decodes (messages arrive in order)
    if (state.loadingBackground) { state.waiting = [msg, buffers]; return; }
    onScene(msg, buffers);
  });

  function onScene(msg, buffers) {
    trace.sceneAt = performance.now();
    trace.scenes += 1;
    state.scene = msg;
    state.data = floats(buffers[0]);
    state.seq = msg.seq;
    const t = state.turning;
    if (t && t.done) {
      // matplotlib has drawn the turned view (a scene never runs ahead of its background: see above)
      const cam = msg.spaces[t.space];
      if (cam && cam.elev === t.elev && cam.azim === t.azim) state.turning = null;
    }
    if (ahead() && performance.now() - state.movedAt > 2000) state.qNow = null;   // the kernel's pose wins
    if (ahead()) {                            // the kernel is behind: no rest frame yet, and
      // a repaint only if the new scene shows something the rig does not move (else: the same picture)
      if (!state.turning && !coversAll(state.rig, state.rigData, msg.items)) schedule();
      return;
    }
    if (!state.turning || state.turning.done) askForRest();
    if (!state.turning) schedule();
  }

  async function onBackground() {
    const ticket = (state.backgroundTicket = (state.backgroundTicket || 0) + 1);
    state.loadingBackground = true;
    let image = null;
    try {
      image = await bitmap(model.get("background"));
    } catch (error) {                                     // not a picture: paint on the face colour
      image = null;
    }
    if (ticket !== state.backgroundTicket) return;        // a newer background is on its way
    state.background = image;
    state.loadingBackground = false;
    if (state.turning && state.turning.done) state.turning = null;
    const waiting = state.waiting;
    state.waiting = null;
    if (waiting) onScene(...waiting);
    schedule();
  }

  async function onFrame() {
    const seq = model.get("frame_seq");
    const image = await bitmap(model.get("frame"));
    if (seq < state.frameSeq) return;
    state.frame = image;
    state.frameSeq = seq;
    state.seq = Math.max(state.seq, seq);
    if (!state.turning) schedule();
  }

  // the sliders of the rig: their values move the picture here, before the kernel hears of them
  function onSlider() {
    state.qNow = slidersQ(state.sliders.map((m) => m.get("value")), state.rig.scales);
    state.movedAt = performance.now();
    trace.movedAt = state.movedAt;
    clearTimeout(state.timer);                // no rest frame while the browser is ahead
    schedule();
  }

  async function linkSliders(rig, rigData) {
    unlinkSliders();
    let sliders;
    try {
      sliders = await Promise.all(rig.sliders.map((id) => model.widget_manager.get_model(id)));
    } catch (error) {
      return;                                 // no widget manager access: the kernel draws every pose
    }
    state.rig = rig;
    state.rigData = rigData;
    state.sliders = sliders;
    for (const slider of sliders) {
      slider.on("change:value", onSlider);
      spaceOut(slider);
    }
  }

  function unlinkSliders() {
    for (const slider of state.sliders) slider.off("change:value", onSlider);
    state.sliders = [];
    state.rig = null;
    state.qNow = null;
  }

  // turning a 3D view with the mouse
  const toPixels = (event) => {
    const r = canvas.getBoundingClientRect();
    return [(event.clientX - r.left) * canvas.width / r.width, (event.clientY - r.top) * canvas.height / r.height];
  };
  canvas.addEventListener("pointerdown", (event) => {
    if (!state.scene || event.button !== 0) return;
    const [x, y] = toPixels(event);
    const space = state.scene.spaces.findIndex((s) => s.three_d && s.turnable &&
      x >= s.bbox[0] && x <= s.bbox[2] && y >= s.bbox[1] && y <= s.bbox[3]);
    if (space < 0) return;
    const cam = state.scene.spaces[space];
    state.turning = { space, x, y, elev: cam.elev, azim: cam.azim };
    clearTimeout(state.timer);
    canvas.setPointerCapture(event.pointerId);
    event.preventDefault();
  });
  canvas.addEventListener("pointermove", (event) => {
    const t = state.turning;
    if (!t || t.done) return;
    const [x, y] = toPixels(event), cam = state.scene.spaces[t.space];
    [t.elev, t.azim] = dragView(cam, x - t.x, y - t.y, cam.bbox[2] - cam.bbox[0], cam.bbox[3] - cam.bbox[1]);
    schedule();
  });
  const release = () => {
    const t = state.turning;
    if (!t || t.done) return;
    const cam = state.scene.spaces[t.space];
    if (t.elev === cam.elev && t.azim === cam.azim) {    // a click, not a drag: nothing turned
      state.turning = null;
      schedule();
      askForRest();
      return;
    }
    t.done = true;                  // keep the turned picture until matplotlib's arrives
    model.send({ kind: "view", axes: t.space, elev: t.elev, azim: t.azim });
  };
  canvas.addEventListener("pointerup", release);
  canvas.addEventListener("pointercancel", release);

  model.on("change:background", onBackground);
  model.on("change:frame", onFrame);
  model.on("change:css_size", schedule);
  model.set("pixel_ratio", window.devicePixelRatio || 1);
  model.save_changes();
  onBackground();
  onFrame();
  model.send({ kind: "ready" });      // the kernel answers with the current scene
  return () => { clearTimeout(state.timer); unlinkSliders(); };
}

// runs once per widget, when the page creates its model (before any view: a notebook renders an
// output only when it is scrolled to): the kernel hears that this module runs here. A page that
// cannot run it (anywidget's front end missing) stays silent, and the kernel then sends PNG frames
// instead (dhlab/views/live/canvas.py, watch_front_end).
function initialize({ model }) {
  model.send({ kind: "loaded" });
}

export default { initialize, render };
