"""What a matplotlib figure really draws: its texts that are visible, and where each lands in pixels
(a 3D text placed as it is drawn); used by the tests of the notebooks' figures."""
from matplotlib import cbook
from matplotlib.text import Text
from mpl_toolkits.mplot3d import proj3d
from mpl_toolkits.mplot3d.art3d import Text3D


def drawn(fig):
    fig.canvas.draw()
    return fig.canvas.get_renderer()


def visible_texts(fig):
    """Every text drawn: tick labels of ticks outside an axis's limits exist but are not drawn."""
    hidden = set()
    for ax in fig.axes:
        for axis in ax._axis_map.values():
            lo, hi = sorted(axis.get_view_interval())
            eps = 1e-9 * max(abs(lo), abs(hi), 1)
            for tick in [*axis.majorTicks, *axis.minorTicks]:
                if not lo - eps <= tick.get_loc() <= hi + eps:
                    hidden.update({id(tick.label1), id(tick.label2)})
    return [t for t in fig.findobj(Text) if t.get_visible() and t.get_text().strip() and id(t) not in hidden]


def text_box(text, renderer):
    """Where a text is drawn (pixels). A 3D text keeps its 3D position and is placed only while it is
    drawn, so it is placed here the same way: projected with its axes' last projection."""
    if isinstance(text, Text3D):
        x, y, _ = proj3d.proj_transform(*text.get_position_3d(), text.axes.M)
        with cbook._setattr_cm(text, _x=x, _y=y):
            return text.get_window_extent(renderer)
    return text.get_window_extent(renderer)
