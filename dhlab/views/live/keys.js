// A focused slider takes its own keys; every other key still reaches JupyterLab's shortcuts;
// a figure's picture is never dragged away.
//
// JupyterLab reads the keyboard before the page's widgets do (lumino's command registry
// listens on `document` in the capture phase, unless the app sets `bubblingKeydown`, which
// JupyterLab 4.4 in the browser edition does not): the notebook's shortcuts (ArrowDown: next
// cell) and a lecture deck's (jupyterlab-slideshow: ArrowRight, next slide) would take the
// arrow keys before a focused slider sees them. Lumino skips every shortcut for a key whose
// target is inside an element with `data-lm-suppress-shortcuts`.
//
// That attribute left on a slider suppresses *every* shortcut, Space ("next slide") included:
// a lecturer who had dragged a slider could not go on with Space. So the slider
// carries it only while one of its own keys is being dispatched: a keydown listener on
// `window` in the capture phase runs before any listener on `document` (the capture phase
// goes window -> document -> ... -> target), so it marks the slider before lumino looks, and
// a zero-delay timer, which runs once the whole dispatch is over, takes the mark off again.
// Space, Escape, "n", ... typed on a slider meet no mark: the shortcuts act as if the slider
// were not there.
//
// It also stops the browser's own drag of an image (the inline backend's figure is an
// <img>): a drag on the figure would otherwise lift a ghost copy of the picture.

const SLIDERS = ".widget-slider, .noUi-handle";
const SUPPRESS = "data-lm-suppress-shortcuts";
// the keys noUiSlider (ipywidgets 8's sliders) moves a handle with
export const SLIDER_KEYS = new Set(["ArrowLeft", "ArrowRight", "ArrowUp", "ArrowDown",
                                    "PageUp", "PageDown", "Home", "End"]);

/** The element that holds the whole panel: the cell's output (JupyterLab, Voila), else the
 *  outermost widget box around `el`. */
export function panelRoot(el) {
  const output = el.closest(".jp-OutputArea-output, .output_subarea");
  if (output) return output;
  let root = el;
  for (let node = el.parentElement; node; node = node.parentElement) {
    if (node.classList && node.classList.contains("widget-box")) root = node;
  }
  return root;
}

/** Make the figures' pictures under `root` undraggable (widgets drawn late included). */
export function mark(root) {
  for (const img of root.querySelectorAll("img.widget-image")) img.draggable = false;
}

/** The slider of the panel `root` that `event` is a slider key for, or null. */
export function sliderKeyTarget(event, root) {
  if (!root || !SLIDER_KEYS.has(event.key) || !(event.target instanceof Element)) return null;
  const slider = event.target.closest(SLIDERS);
  return slider && root.contains(slider) ? slider : null;
}

function render({ el }) {
  el.classList.add("dhlab-keys");
  let root = null;
  // the panel's other widgets are drawn when their models arrive, before or after this one:
  // mark what is there, and whatever comes later
  const observer = new MutationObserver(() => mark(root));
  const noDrag = (event) => {
    if (event.target && event.target.tagName === "IMG") event.preventDefault();
  };
  // before lumino reads the key (see the top of this file): mark the slider for this key only
  const ownKeys = (event) => {
    const slider = sliderKeyTarget(event, root);
    if (!slider) return;
    slider.setAttribute(SUPPRESS, "true");
    setTimeout(() => slider.removeAttribute(SUPPRESS), 0);
  };
  const start = () => {
    root = panelRoot(el);
    mark(root);
    observer.observe(root, { childList: true, subtree: true });
    root.addEventListener("dragstart", noDrag);
  };
  window.addEventListener("keydown", ownKeys, true);
  // the widget's element is attached to the page just after render() returns
  requestAnimationFrame(start);
  return () => {
    window.removeEventListener("keydown", ownKeys, true);
    observer.disconnect();
    if (root) root.removeEventListener("dragstart", noDrag);
  };
}

export default { render };
