// Which pixels a paint of the moving items can touch: the canvas backend repaints only those.
//
// Why: while a slider is dragged the picture is the background (matplotlib's, without the moving
// artists) with the moving items painted over it, and only the items move. Copying the whole
// background and painting every item over the whole canvas cost 7.6 ms per frame at pixel ratio 2
// on the 2-core machine; the rectangle that holds the items before and after the step is often a
// third of it. canvas.js clips its paint to the union of the last paint's rectangle and this one:
// what is outside both did not change.
//
// A rectangle is [x0, y0, x1, y1] in canvas pixels; null when nothing is painted.
// No DOM here: node imports this file (tests/views/test_canvas_js.py checks that every pixel a paint
// touches lies inside the rectangle, for every catalogue robot).

const MITER_LIMIT = 10;       // the canvas default: a miter joint reaches miterLimit * width / 2
const ANTIALIAS_PX = 2;       // antialiased edges bleed a pixel; one more for rounding

// the largest |x| or |y| of a path's vertices (a marker's or a letter's shape, around its anchor)
function pathReach(piece, data) {
  const [at, n] = piece.vertices;
  let reach = 0;
  for (let i = 0; i < 2 * n; i++) {
    const v = Math.abs(data[at + i]);
    if (v > reach) reach = v;
  }
  return reach;
}

// how far an item's paint reaches beyond its anchor points: stroke widths, markers, letters
export function itemReach(item, data) {
  let reach = 0;
  if (item.kind === "line") {
    if (item.color) reach = (item.width / 2) * (item.join === "miter" ? MITER_LIMIT : 1);
    const m = item.marker;
    if (m) reach = Math.max(reach, pathReach(m, data) + (m.edge_width / 2) * (m.join === "miter" ? MITER_LIMIT : 1));
  } else if (item.kind === "polys") {
    reach = item.width / 2;                   // drawPolys joins round
  } else {                                    // glyphs: letters (and leaders) around each anchor
    const halo = item.halo ? item.halo.width / 2 : 0;
    for (const piece of item.pieces) reach = Math.max(reach, pathReach(piece, data) + halo);
    const leaders = item.leaders;
    if (leaders) {
      for (let i = 0; i < leaders.of.length; i++) {
        for (let k = 0; k < 4; k++) {
          reach = Math.max(reach, Math.abs(data[leaders.deltas + 4 * i + k]) + leaders.width / 2);
        }
      }
    }
  }
  return reach + ANTIALIAS_PX;
}

// the rectangle an item paints into, from its projected points `xy` ([x, y, depth] per point)
export function itemBounds(item, xy, data) {
  let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
  for (let i = 0; i < xy.length; i += 3) {
    const x = xy[i], y = xy[i + 1];
    if (!Number.isFinite(x) || !Number.isFinite(y)) continue;     // a gap: not drawn
    if (x < x0) x0 = x;
    if (x > x1) x1 = x;
    if (y < y0) y0 = y;
    if (y > y1) y1 = y;
  }
  if (x0 > x1) return null;
  const r = itemReach(item, data);
  let box = [x0 - r, y0 - r, x1 + r, y1 + r];
  if (item.clip) {                           // an edge pixel the clip cuts through is still painted
    const [c0, c1, c2, c3] = item.clip;
    box = intersect(box, [c0 - 1, c1 - 1, c2 + 1, c3 + 1]);
  }
  return box;
}

export function union(a, b) {
  if (!a) return b;
  if (!b) return a;
  return [Math.min(a[0], b[0]), Math.min(a[1], b[1]), Math.max(a[2], b[2]), Math.max(a[3], b[3])];
}

function intersect(a, b) {
  const box = [Math.max(a[0], b[0]), Math.max(a[1], b[1]), Math.min(a[2], b[2]), Math.min(a[3], b[3])];
  return box[0] < box[2] && box[1] < box[3] ? box : null;
}

// the union of the items' rectangles, on whole pixels inside a width x height canvas
export function paintedBounds(items, projected, data, width, height) {
  let box = null;
  items.forEach((item, i) => { box = union(box, itemBounds(item, projected[i], data)); });
  if (!box) return null;
  return intersect([Math.floor(box[0]), Math.floor(box[1]), Math.ceil(box[2]), Math.ceil(box[3])],
    [0, 0, width, height]);
}

// for the browser tests: how many pixels of `ctx`'s canvas differ (by more than 16 of 255) from a
// full repaint, the background `image` over `face` with `paintItemsOn(otherContext)` on top
export function differsFromFullPaint(ctx, image, face, paintItemsOn) {
  const { width, height } = ctx.canvas;
  const other = new OffscreenCanvas(width, height).getContext("2d", { alpha: false });
  other.fillStyle = face;
  other.fillRect(0, 0, width, height);
  other.drawImage(image, 0, 0);
  paintItemsOn(other);
  const a = ctx.getImageData(0, 0, width, height).data, b = other.getImageData(0, 0, width, height).data;
  let differ = 0;
  for (let i = 0; i < a.length; i += 4) {
    if (Math.abs(a[i] - b[i]) > 16 || Math.abs(a[i + 1] - b[i + 1]) > 16 || Math.abs(a[i + 2] - b[i + 2]) > 16) differ++;
  }
  return differ;
}
