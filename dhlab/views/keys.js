// The keys of a focused slider go to the slider, and a figure's picture is never dragged away.
//
// JupyterLab reads the keyboard before the page's widgets do (lumino's command registry
// listens in the capture phase, unless the app sets `bubblingKeydown`, which JupyterLab 4.4
// in the browser edition does not): the notebook's shortcuts (ArrowRight: next heading,
// ArrowDown: next cell) and a lecture deck's (jupyterlab-slideshow: ArrowRight, next slide)
// take the arrow keys before a focused slider sees them. Lumino skips every shortcut for a
// key whose target is inside an element with `data-lm-suppress-shortcuts`: this module puts
// that attribute on the sliders of its panel, so arrow keys, Page Up/Down, Home and End
// move the focused slider in JupyterLab, the browser edition, Voila and the decks.
//
// It also stops the browser's own drag of an image (the inline backend's figure is an
// <img>): a drag on the figure would otherwise lift a ghost copy of the picture.

const SLIDERS = ".widget-slider, .noUi-handle";

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

/** Mark the sliders and figures under `root`; returns how many sliders are marked. */
export function mark(root) {
  const sliders = root.querySelectorAll(SLIDERS);
  for (const slider of sliders) slider.setAttribute("data-lm-suppress-shortcuts", "true");
  for (const img of root.querySelectorAll("img.widget-image")) img.draggable = false;
  return sliders.length;
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
  const start = () => {
    root = panelRoot(el);
    mark(root);
    observer.observe(root, { childList: true, subtree: true });
    root.addEventListener("dragstart", noDrag);
  };
  // the widget's element is attached to the page just after render() returns
  requestAnimationFrame(start);
  return () => {
    observer.disconnect();
    if (root) root.removeEventListener("dragstart", noDrag);
  };
}

export default { render };
