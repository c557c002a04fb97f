"""ipympl's canvas for a live figure under ``%matplotlib widget``, with a faster PNG packer.

:class:`~dhlab.views.live.livefigure.LiveFigure`'s "ipympl" backend (:mod:`dhlab.views.live.backend`)
gives its figure this canvas without going through pyplot. ipympl is imported on first use:
only ``%matplotlib widget`` needs it.
"""
from __future__ import annotations

import base64
import functools

import numpy as np

from .png import encode_png

__all__ = ["fast_canvas_class", "attach_ipympl_canvas"]


@functools.cache
def fast_canvas_class():
    """ipympl's canvas class with a faster PNG packer (made on first use: importing
    ipympl is only needed with ``%matplotlib widget``)."""
    from ipympl.backend_nbagg import Canvas  # lazy: only %matplotlib widget needs ipympl

    class FastCanvas(Canvas):
        """ipympl's canvas, with the changed pixels packed by :func:`encode_png`:
        Pillow's PNG writer took 9-10 of the 15 ms of an update."""

        def get_diff_image(self):
            # matplotlib's webagg logic (backend_webagg_core), with a faster encoder
            if not self._png_is_old:
                return None
            pixels = np.asarray(self.get_renderer().buffer_rgba())
            buff = pixels.view(np.uint32).squeeze(2)        # one uint32 per pixel: fast compare
            full = (self._force_full or buff.shape != self._last_buff.shape
                    or (pixels[:, :, 3] != 255).any())
            self.set_image_mode("full" if full else "diff")
            output = buff if full else np.where(buff != self._last_buff, buff, 0)
            self._last_buff = buff.copy()
            self._force_full = self._png_is_old = False
            return encode_png(output.view(np.uint8).reshape(*output.shape, 4), alpha=True)

        def send_binary(self, data):
            if self.syncing_data_url:
                # Until a browser shows the canvas, ipympl keeps the picture in
                # _data_url, but as bare base64: the browser then fails to draw it
                # ("broken" image) and the canvas stays empty. Store a real data URL.
                rgba = self._last_buff.view(np.uint8).reshape(*self._last_buff.shape, 4)
                self._data_url = "data:image/png;base64," + base64.b64encode(
                    encode_png(rgba, alpha=True)).decode("ascii")
            self.send({"data": '{"type": "binary"}'}, buffers=[data])

    return FastCanvas


def attach_ipympl_canvas(figure):
    """Give ``figure`` an ipympl canvas without going through pyplot (so that
    pyplot neither counts nor re-shows it)."""
    from ipympl.backend_nbagg import FigureManager  # lazy: as above

    canvas = fast_canvas_class()(figure)
    FigureManager(canvas, 0)          # ipympl's toolbar needs a manager
    canvas.header_visible = False     # no "Figure 0" caption
    canvas.resizable = False          # the panel's layout, not the user, sets the size
    return canvas
