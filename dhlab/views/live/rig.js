// The browser's half of dhlab/views/live/rig.py: the chain's kinematics, and the picture moved with it.
//
// When a slider moves, its new value is here at once; the kernel's picture of the new pose comes
// a round trip later. With the chain's kinematics program (the same steps dhlab.kinematics runs)
// this module computes every node of the chain (world, then the running product after each
// step), and moves each rigged point to node * local: the picture moves in the animation frame
// of the slider; the sliders then need to tell the kernel less often (spaceOut). No DOM here:
// node imports this file and tests/views/test_rig.py checks it against Python (every catalogue robot,
// random poses).

// node k as a row-major 4x4 in nodes[16k .. 16k+15]; node 0 is the world (identity)
export function chainNodes(steps, q) {
  const out = new Float64Array(16 * (steps.length + 1));
  let T = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1];
  out.set(T, 0);
  steps.forEach((step, s) => {
    const [kind] = step;
    if (kind === "const") T = mul(T, step[1]);
    else {
      const [, axis, joint, sign, offset] = step;
      const value = sign * q[joint] + offset;
      T = kind === "move" ? moved(T, axis, value) : turned(T, axis, value);
    }
    out.set(T, 16 * (s + 1));
  });
  return out;
}

function mul(A, B) {
  const C = new Array(16);
  for (let r = 0; r < 4; r++) {
    for (let c = 0; c < 4; c++) {
      C[4 * r + c] = A[4 * r] * B[c] + A[4 * r + 1] * B[4 + c] + A[4 * r + 2] * B[8 + c] + A[4 * r + 3] * B[12 + c];
    }
  }
  return C;
}

// T * Translation(value along axis): only the position column changes
function moved(T, axis, value) {
  const C = T.slice();
  for (let r = 0; r < 3; r++) C[4 * r + 3] += T[4 * r + axis] * value;
  return C;
}

// T * Rotation(value about axis): only the two other columns mix
function turned(T, axis, value) {
  const C = T.slice();
  const a = (axis + 1) % 3, b = (axis + 2) % 3, c = Math.cos(value), s = Math.sin(value);
  for (let r = 0; r < 3; r++) {
    C[4 * r + a] = T[4 * r + a] * c + T[4 * r + b] * s;
    C[4 * r + b] = T[4 * r + b] * c - T[4 * r + a] * s;
  }
  return C;
}

// the joint vector the sliders show: display units (degrees, lengths) times the rig's scales
export function slidersQ(values, scales) {
  return values.map((v, j) => v * scales[j]);
}

export function sameQ(a, b) {
  if (!a || !b || a.length !== b.length) return false;
  return a.every((v, j) => Math.abs(v - b[j]) <= 1e-9 * Math.max(1, Math.abs(v)));
}

const KEYS = { line: "points", polys: "faces", glyphs: "anchors" };

// a copy of the scene's numbers with every rigged point of `items` moved to its node at q;
// an item whose point count is not what the rig was made for keeps the kernel's points
export function rigged(rig, rigData, items, data, q) {
  const N = chainNodes(rig.steps, q);
  const out = data.slice();
  for (const item of items) {
    const entries = rig.artists[String(item.artist)];
    if (!entries || item.space < 0) continue;
    for (const entry of entries) {
      if (entry.key !== KEYS[item.kind]) continue;
      const where = item[entry.key];
      const count = entry.key === "faces" ? where[1] * where[2] : where[1];
      if (count !== entry.count) continue;
      movePoints(out, where[0], rigData, entry, N);
    }
  }
  return out;
}

// true if the rig moves every point of every item (no -1 node): a newer kernel scene of the same
// items then changes nothing the browser shows while it is ahead of the kernel
export function coversAll(rig, rigData, items) {
  return items.every((item) => {
    const key = KEYS[item.kind], where = item[key];
    if (!key || !where || item.space < 0) return false;
    const count = key === "faces" ? where[1] * where[2] : where[1];
    const entry = (rig.artists[String(item.artist)] || []).find((e) => e.key === key && e.count === count);
    if (!entry) return false;
    for (let v = 0; v < count; v++) if (rigData[entry.nodes + v] === -1) return false;
    return true;
  });
}

function movePoints(out, at, rigData, entry, N) {
  for (let v = 0; v < entry.count; v++) {
    const node = rigData[entry.nodes + v];
    if (node < 0) continue;                   // -1: not rigged (kernel's point), -2: padding
    const l = entry.local + 3 * v, x = rigData[l], y = rigData[l + 1], z = rigData[l + 2];
    const T = 16 * node, p = at + 3 * v;
    out[p] = N[T] * x + N[T + 1] * y + N[T + 2] * z + N[T + 3];
    out[p + 1] = N[T + 4] * x + N[T + 5] * y + N[T + 6] * z + N[T + 7];
    out[p + 2] = N[T + 8] * x + N[T + 9] * y + N[T + 10] * z + N[T + 11];
  }
}

export const SLIDER_MESSAGE_MS = 250;   // a linked slider tells the kernel at most this often

// A slider being dragged changes on every mouse move; ipywidgets sends its value to the kernel
// whenever no earlier one is still being handled, and each message costs the page a kernel status
// round (busy, idle: JupyterLab's toolbar then measures its items again and the tab's icon is
// reloaded), the echo and the new readouts, ~60 ms of the page's main thread in all on the 2-core
// machine: that, not the painting, is what slowed a drag (a 2-s drag in JupyterLab, 100 ms against
// 250 ms in one run: 23-26 against 39-40 frames/s at pixel ratio 1, 20-23 against 27-35 at 2; the
// readouts still change 4 times a second). The picture follows the slider here (the rig), so the
// kernel needs fewer values: after each message the slider's own throttle (ipywidgets'
// pending-message count) is held SLIDER_MESSAGE_MS longer, and the values it merged meanwhile go
// out as one when the time is up (the same call the kernel's "idle" makes), so the last value
// always reaches the kernel.
export function spaceOut(slider) {
  if (slider.__dhlabSpacedOut || typeof slider.send_sync_message !== "function"
      || typeof slider._handle_status !== "function") return;   // another ipywidgets: left as it is
  slider.__dhlabSpacedOut = true;
  const send = slider.send_sync_message;
  slider.send_sync_message = function (...args) {
    const id = send.apply(this, args);
    this._pending_msgs += 1;
    setTimeout(() => this._handle_status({ content: { execution_state: "idle" } }), SLIDER_MESSAGE_MS);
    return id;
  };
}
