"""frontpack.fill: arrays without copies, certificates, determinism, progress, cancellation."""

import os
import signal
import subprocess
import sys
import threading
import time

import numpy as np
import pytest

import frontpack
from conftest import need, same_bits

L_SHAPE = "POLYGON((0 0,2 0,2 1,1 1,1 2,0 2,0 0))"


def test_disks_are_a_view_of_the_library_vector():
    p = frontpack.fill(L_SHAPE, "uniform:0.02,0.05", seed=1)
    a = p.disks
    assert a.dtype == np.float64 and a.ndim == 2 and a.shape[1] == 3 and len(p) == a.shape[0] > 100
    assert a.flags.c_contiguous
    assert not a.flags.owndata  # numpy did not allocate it: no copy was made
    assert type(a.base).__name__ == "PyCapsule"  # it views the std::vector the capsule owns
    assert p.disks is a  # the attribute is the one array, not a copy per access
    del p  # the array keeps the vector alive
    assert np.isfinite(a).all() and (a[:, 2] >= 0.02).all()


def test_fill_is_certified(square_with_hole):
    p = frontpack.fill(square_with_hole, frontpack.Radii.uniform(0.01, 0.03), seed=2)
    report = frontpack.certify(square_with_hole, p.disks)
    assert report and report.valid
    assert report.outside.size == 0 and report.overlapping.shape == (0, 2)
    assert p.certificate.exact and p.certificate.dropped == 0
    assert p.certificate.generated >= len(p)
    assert p.stats.attempts > 0 and p.stats.seconds_front >= 0
    assert not p.truncated and not p.cancelled
    # an independent check with shapely's floating point: centres in the polygon, not in the hole
    geometry = need("shapely.geometry")
    for x, y, r in p.disks[::7]:
        assert square_with_hole.contains(geometry.Point(x, y))
        assert square_with_hole.exterior.distance(geometry.Point(x, y)) >= r * (1 - 1e-9)
        assert square_with_hole.interiors[0].distance(geometry.Point(x, y)) >= r * (1 - 1e-9)


def test_same_seed_same_bits_other_seed_other_disks():
    a = frontpack.fill(L_SHAPE, "lognormal:0.02,1.5", seed=7).disks
    b = frontpack.fill(frontpack.Domain.from_wkt(L_SHAPE), frontpack.Radii("lognormal:0.02,1.5"), seed=7).disks
    c = frontpack.fill(L_SHAPE, "lognormal:0.02,1.5", seed=8).disks
    assert same_bits(a, b)
    assert not same_bits(a, c)


def test_the_same_disks_as_the_tool(tmp_path, shapes):
    tool = os.environ.get("FRONTPACK_TOOL")
    if not tool:
        pytest.skip("FRONTPACK_TOOL is not set (the build has no tool)")
    out = tmp_path / "tool.csv"
    subprocess.run([tool, "fill", str(shapes / "gear.wkt"), "--radius", "uniform:0.01,0.03", "--seed", "5",
                    "--method", "closed", "-q", "-o", str(out)], check=True)
    p = frontpack.fill(shapes / "gear.wkt", "uniform:0.01,0.03", seed=5, method="closed")
    assert same_bits(frontpack.read_disks(out), p.disks)


def test_radius_forms_and_options():
    assert len(frontpack.fill(L_SHAPE, 0.1)) > 10  # a number: constant radius
    closed = frontpack.fill(L_SHAPE, "constant:0.1", method="closed", start=(0.5, 0.5), window=0)
    assert frontpack.certify(L_SHAPE, closed.disks)
    assert (closed.disks[:, 2] == 0.1).all()
    with pytest.raises(frontpack.OptionError, match="method 'spiral'"):
        frontpack.fill(L_SHAPE, method="spiral")
    with pytest.raises(frontpack.OptionError, match=r"rmin \(0.2\) must not exceed rmax \(0.1\)") as e:
        frontpack.fill(L_SHAPE, "uniform:0.2,0.1")
    assert isinstance(e.value, ValueError)
    with pytest.raises(frontpack.LimitError) as e:
        frontpack.fill(L_SHAPE, "constant:0.001", max_disks=1000)
    assert e.value.estimate > 1000 and "max_disks" in str(e.value)
    truncated = frontpack.fill(L_SHAPE, "constant:0.01", max_disks=100_000)
    assert not truncated.truncated


def test_radii_constructors():
    assert frontpack.Radii.uniform(0.01, 0.05).describe() == frontpack.Radii("uniform:0.01,0.05").describe()
    n = frontpack.Radii.normal(0.02, 0.004, 0.01, 0.03)
    assert (n.min, n.max) == (0.01, 0.03)
    s = n.sample(1000, seed=3)
    assert s.shape == (1000,) and same_bits(s, n.sample(1000, seed=3))
    assert ((s >= 0.01) & (s <= 0.03)).all()
    d = frontpack.Radii.discrete([(1.0, 0.5), (2.0, 0.5)], kind="diameter")
    assert set(d.sample(100).tolist()) == {0.5, 1.0}
    g = frontpack.Radii.grading_curve([(0.1, 0.0), (0.2, 1.0)])
    assert g.min == 0.05 and g.max == 0.1 and g.quantile(0.0) == 0.05
    assert frontpack.Radii.lognormal(0.02, 1.5, 0.01, 0.04).cdf(0.04) == 1.0
    with pytest.raises(frontpack.OptionError, match="basis 'mass'"):
        frontpack.Radii.discrete([(1.0, 1.0)], basis="mass")


def test_progress_callback_sees_both_phases():
    seen = []
    p = frontpack.fill(L_SHAPE, "constant:0.004", progress=seen.append)
    phases = [s.phase for s in seen]
    assert phases[0] == "generate" and phases[-1] == "certify"
    assert phases == sorted(phases, key=("generate", "certify").index)
    generate = [s for s in seen if s.phase == "generate"]
    assert len(generate) >= 2 and generate[-1].fraction == 1.0
    assert [s.disks for s in generate] == sorted(s.disks for s in generate)
    assert seen[-1].fraction == 1.0 and not p.cancelled


def test_progress_returning_false_stops_generating():
    full = frontpack.fill(L_SHAPE, "constant:0.004")
    p = frontpack.fill(L_SHAPE, "constant:0.004", progress=lambda s: s.disks < 16384)
    assert p.cancelled and 0 < len(p) < len(full)
    assert frontpack.certify(L_SHAPE, p.disks)  # what was generated, certified


def test_exception_in_callback_cancels_and_propagates():
    calls = []

    def boom(progress):
        calls.append(progress)
        raise RuntimeError("stop here")

    with pytest.raises(RuntimeError, match="stop here") as e:
        frontpack.fill(L_SHAPE, "constant:0.004", progress=boom)
    assert len(calls) == 1  # the run stopped at once: no further callback
    if sys.version_info >= (3, 11):
        assert e.value.__notes__ == ["frontpack.fill was cancelled after %d disks" % calls[0].disks]


def test_sigint_from_callback_raises_keyboard_interrupt():
    calls = []

    def interrupt(progress):
        calls.append(progress)
        if len(calls) == 1:
            os.kill(os.getpid(), signal.SIGINT)

    with pytest.raises(KeyboardInterrupt) as e:
        frontpack.fill(L_SHAPE, "constant:0.004", progress=interrupt)
    assert len(calls) <= 2
    if sys.version_info >= (3, 11):
        assert e.value.__notes__[0].startswith("frontpack.fill was cancelled after ")


def test_ctrl_c_without_callback_cancels_a_long_fill():
    # About 4 million disks (several seconds): Ctrl-C 0.2 s in must end it with KeyboardInterrupt,
    # raised from inside the run (the note says the run was cancelled; a run that finished first
    # would get the interrupt only after returning, without the note).
    timer = threading.Timer(0.2, os.kill, (os.getpid(), signal.SIGINT))
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt) as e:
            frontpack.fill("POLYGON((0 0,12 0,12 12,0 12,0 0))", "constant:0.003")
    finally:
        timer.cancel()
    if sys.version_info >= (3, 11):
        (note,) = e.value.__notes__
        assert note.startswith("frontpack.fill was cancelled after ")
        assert int(note.split()[-2]) < 3_000_000


def test_stop_source_from_another_thread():
    stop = frontpack.StopSource()
    threading.Timer(0.1, stop.request_stop).start()
    with pytest.raises(frontpack.CancelledError):
        frontpack.fill("POLYGON((0 0,12 0,12 12,0 12,0 0))", "constant:0.003", stop=stop)
    assert stop.stop_requested


def test_gil_is_released_while_filling():
    # Another thread counts while the fill runs, giving the GIL up at every step (sleep(0)); the
    # switch interval is made long, so that nothing takes the GIL from a thread that holds it.
    # Between two progress callbacks (thousands of disks) the counter moves, which it cannot while
    # the fill holds the GIL: held, it would move in no interval at all. On a loaded machine (the
    # test suite runs two at a time on two cores) the counting thread may go unscheduled for a whole
    # interval, so the test asks for most intervals, not all but one (it failed so under load).
    counter = [0]
    running = threading.Event()
    running.set()

    def count():
        while running.is_set():
            counter[0] += 1
            time.sleep(0)

    interval = sys.getswitchinterval()
    sys.setswitchinterval(30.0)
    thread = threading.Thread(target=count)
    thread.start()
    marks = []
    try:
        frontpack.fill("POLYGON((0 0,3 0,3 3,0 3,0 0))", "constant:0.004",
                       progress=lambda s: marks.append(counter[0]) if s.phase == "generate" else None)
    finally:
        running.clear()
        thread.join()
        sys.setswitchinterval(interval)
    steps = np.diff(marks)
    assert len(steps) >= 4
    assert (steps > 0).sum() * 2 > len(steps), steps


def test_progress_bar(capfd):
    quiet = frontpack.fill(L_SHAPE, "constant:0.01", seed=3)
    with_bar = frontpack.fill(L_SHAPE, "constant:0.01", seed=3, progress=True)
    assert same_bits(quiet.disks, with_bar.disks)
    assert "%" in capfd.readouterr().err
    with pytest.raises(TypeError, match="progress must be"):
        frontpack.fill(L_SHAPE, progress=3)


def test_types_in_repr():
    p = frontpack.fill(L_SHAPE, "constant:0.05")
    assert repr(p).startswith("<frontpack.Packing %d disks, certified" % len(p))
    assert "generated" in repr(p.certificate)
    assert sys.getrefcount(p.disks) >= 2


def test_targets_fraction_count_height():
    square = "POLYGON((0 0,1 0,1 1,0 1,0 0))"
    assert frontpack.fill(square, "constant:0.05").target is None
    loose = frontpack.fill(square, "uniform:0.01,0.03", seed=4, fraction=0.6)
    area = float(np.sum(np.pi * loose.disks[:, 2] ** 2))
    assert abs(area - 0.6) <= 0.002 and loose.target["fraction_requested"] == 0.6
    assert loose.target["fraction_achieved"] == pytest.approx(area, rel=1e-12)
    assert frontpack.certify(square, loose.disks)
    counted = frontpack.fill(square, "constant:0.02", method="closed", count=300)
    assert len(counted) == 300 and counted.target["count_requested"] == 300
    assert counted.target["count_achieved"] == 300
    short = frontpack.fill(square, "uniform:0.01,0.05", method="open", count=5000)
    assert len(short) < 5000 and short.target["count_achieved"] == len(short)
    low = frontpack.fill(square, "uniform:0.01,0.03", seed=4, height=0.5)
    assert (low.disks[:, 1] + low.disks[:, 2] <= 0.5).all() and low.target["height"] == 0.5
    assert low.target["area_filled"] == 0.5
    with pytest.raises(frontpack.OptionError):
        frontpack.fill(square, "constant:0.02", count=300)  # the boundary method takes no count


@pytest.mark.parametrize("method", ["boundary", "closed"])
def test_periodic_cell_wraps_with_the_default_and_the_closed_form(method):
    cell = frontpack.Domain.periodic((0, 0, 1.5, 1.5))
    p = frontpack.fill(cell, "discrete:0.02:0.5,0.028:0.5", seed=3, method=method)
    assert len(p) > 800 and p.certificate.culled == 0 and p.certificate.dropped == 0
    report = frontpack.certify(cell, p.disks)
    assert report.valid and report.overlapping.shape == (0, 2)
    x, y, r = p.disks[:, 0], p.disks[:, 1], p.disks[:, 2]
    assert ((x >= 0) & (x < 1.5) & (y >= 0) & (y < 1.5)).all()
    assert ((x - r < 0) | (x + r > 1.5)).sum() > 10  # disks cross the sides
    # independent check through the nearest image, in floating point: no pair overlaps
    d = p.disks[:, None, :2] - p.disks[None, :, :2]
    d -= 1.5 * np.round(d / 1.5)
    gap = np.hypot(d[..., 0], d[..., 1]) - (r[:, None] + r[None, :])
    np.fill_diagonal(gap, 1)
    assert gap.min() > -1e-12
    assert np.pi * (r * r).sum() / 1.5**2 > 0.79


def test_open_form_refuses_a_periodic_cell():
    with pytest.raises(frontpack.OptionError, match="the open form does not wrap around a cell"):
        frontpack.fill(frontpack.Domain.periodic((0, 0, 1, 1)), "uniform:0.01,0.05", method="open")


def test_jam_is_denser_reports_its_phase_and_stops_when_asked():
    square = "POLYGON((0 0,1 0,1 1,0 1,0 0))"
    radii = "discrete:0.014:0.5,0.0196:0.5"
    plain = frontpack.fill(square, radii, seed=1)
    seen = []
    jammed = frontpack.fill(square, radii, seed=1, jam=True, progress=seen.append)
    assert frontpack.certify(square, jammed.disks)
    assert set(jammed.disks[:, 2]) == {0.014, 0.0196}
    area = lambda p: float(np.sum(np.pi * p.disks[:, 2] ** 2))  # noqa: E731
    assert area(jammed) > area(plain) + 0.01 and not jammed.cancelled
    phases = [s.phase for s in seen]
    assert "jam" in phases
    assert all(0.0 <= s.fraction <= 1.0 for s in seen)
    assert phases.index("jam") > max(i for i, s in enumerate(phases) if s == "generate")
    # False from the callback during the stage ends it: the rounds kept so far, certified.
    stopped = frontpack.fill(square, radii, seed=1, jam=True, progress=lambda s: s.phase != "jam")
    assert stopped.cancelled and len(plain) <= len(stopped) < len(jammed)
    assert frontpack.certify(square, stopped.disks)
    with pytest.raises(frontpack.OptionError, match="jam"):
        frontpack.fill(square, radii, jam=True, fraction=0.6)


@pytest.mark.parametrize("radius,kwargs,why", [
    ("constant:3e307", {}, "no disk fits: the smallest radius, 3e+307"),
    ("uniform:0.01,0.05", {"fraction": 1e-7}, "no disk was kept: fraction 1e-07"),
    ("uniform:0.01,0.05", {"method": "closed", "start": (5, 5)}, "the start point (5 5) lies outside"),
])
def test_no_disk_placed_raises_nothing_fits_naming_why(radius, kwargs, why):
    # The library says "no disk fits" to Python as the tool does with exit 8: never an empty packing.
    with pytest.raises(frontpack.NothingFitsError) as e:
        frontpack.fill("POLYGON((0 0,1 0,1 1,0 1,0 0))", radius, **kwargs)
    assert why in str(e.value) and isinstance(e.value, frontpack.Error)
