"""Framing keeps the view still while the robot moves, and the hysteresis returns:
a joint swept to its limit and back leaves the view as it was at the start
(it once stayed zoomed out after such a sweep, the robot smaller)."""
import matplotlib

matplotlib.use("Agg")

import numpy as np
import pytest

from dhlab import robots
from dhlab.views import framing
from dhlab.views.panels.teach import teach


def seen(panel):
    """What the student sees of the framing: the axis limits and where the frame origins are drawn."""
    ax = panel.view.ax
    limits = [ax.get_xlim(), ax.get_ylim()] + ([ax.get_zlim()] if ax.name == "3d" else [])
    return np.array(limits), framing.projected(ax, panel.view.frames[:, :3, 3])


def sweep(slider, to, steps=16):
    """Drag ``slider`` to ``to`` and back to where it was, in ``steps`` slider moves each way."""
    start = slider.value
    path = np.linspace(start, to, steps)
    for value in [*path[1:], *path[::-1][1:]]:
        slider.value = float(value)
    assert slider.value == start


@pytest.mark.parametrize("name", sorted(robots.catalogue()))
def test_sweep_to_a_limit_and_back_returns_to_the_same_view(name):
    robot = robots.catalogue()[name]()
    panel = teach(robot, backend="image", controls=False)
    limits, pixels = seen(panel)
    # the joint whose sweep moves the robot most: the widest range (the shoulder of a tie)
    widest = int(np.argmax([np.ptp(link.qlim) for link in robot.links]))
    slider = panel.sliders[widest]
    frames = []                   # the limits after each move: a new frame when they change
    slider.observe(lambda change: frames.append(framing.axes_limits(panel.view.ax)), names="value")
    for limit in (slider.max, slider.min):
        sweep(slider, limit)
        after_limits, after_pixels = seen(panel)
        np.testing.assert_allclose(after_limits, limits, atol=1e-9 * np.ptp(limits))
        np.testing.assert_allclose(after_pixels, pixels, atol=1e-6)
    reframes = sum(a != b for a, b in zip(frames, frames[1:]))
    assert reframes <= len(frames) / 2, "the view was framed again on nearly every step"


def test_back_home_notes_each_frame_and_says_when_the_pose_returns():
    panel = teach(robots.puma560(), backend="image", controls=False)
    ax, view = panel.view.ax, panel.view
    home = view.framed_points()
    assert not framing.back_home(ax, home)                       # where the current frame was made
    far = home + 0.2                                             # the robot moved away: a new frame
    framing.back_home(ax, far)
    ax.set_xlim(*(np.array(ax.get_xlim()) + 0.2))
    assert not framing.back_home(ax, far)                        # the new frame was made from `far`
    assert not framing.back_home(ax, far + 0.05)                 # near neither pose
    assert framing.back_home(ax, home + 1e-4)                    # back at the start's pose
