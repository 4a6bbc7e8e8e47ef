"""Ctrl-C during Mesh.fill_holes and Mesh.fill_hole: KeyboardInterrupt comes promptly and the
mesh is left exactly as it was (the fill is rolled back), as remesh and decimate do."""
import _thread
import signal
import threading
import time

import numpy as np
import pytest

import hmira


@pytest.fixture(autouse=True)
def sigint_raises_keyboard_interrupt():
    """Python's own Ctrl-C handler (a background process may inherit SIGINT ignored)."""
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    yield
    signal.signal(signal.SIGINT, previous)


def ring_around_hole(n):
    """A flat annulus one edge wide around a round hole of n edges (and an outer loop)."""
    a = 2 * np.pi * np.arange(n) / n
    r = n / (2 * np.pi)
    inner = np.stack([r * np.cos(a), r * np.sin(a), np.zeros(n)], axis=1)
    outer = np.stack([(r + 1) * np.cos(a), (r + 1) * np.sin(a), np.zeros(n)], axis=1)
    v = np.ascontiguousarray(np.concatenate([inner, outer]))
    i = np.arange(n)
    j = (i + 1) % n
    f = np.concatenate([np.stack([i, j, n + j], axis=1), np.stack([i, n + j, n + i], axis=1)])
    return hmira.Mesh(v, f)


def _seconds(call):
    start = time.perf_counter()
    call()
    return time.perf_counter() - start


@pytest.fixture(scope="module")
def slow_fill():
    """A hole whose O(n^3) dynamic programme (asked for up to n edges) takes at least a second
    on this machine, so that the 50 ms interrupt polling is small against it."""
    n = 300
    while True:
        seconds = _seconds(lambda: ring_around_hole(n).fill_holes(n, max_dynamic_programming_edges=n))
        if seconds >= 1.0 or n >= 1600:
            return n, seconds
        n = min(1600, int(n * (1.2 / max(seconds, 1e-3)) ** (1 / 3)) + 1)


@pytest.mark.parametrize("call", ["fill_holes", "fill_hole"])
def test_ctrl_c_interrupts_a_long_fill_and_leaves_the_mesh_unchanged(slow_fill, call):
    n, seconds = slow_fill
    m = ring_around_hole(n)
    vertices, faces = np.array(m.vertices), m.faces.copy()
    assert m.topology().boundary_loops == 2
    if call == "fill_holes":
        run = lambda: m.fill_holes(n, max_dynamic_programming_edges=n)  # noqa: E731
    else:
        h = m.find_halfedge(1, 0)  # the faces run 0 -> 1 along the hole: the boundary runs back
        run = lambda: m.fill_hole(h, max_dynamic_programming_edges=n)  # noqa: E731
    timer = threading.Timer(seconds / 10, _thread.interrupt_main)
    timer.start()
    start = time.perf_counter()
    with pytest.raises(KeyboardInterrupt):
        run()
    elapsed = time.perf_counter() - start
    timer.join()
    assert elapsed < seconds * 0.7, (elapsed, seconds)
    # Rolled back: the same vertices and faces, bit for bit, in the same order.
    assert np.array_equal(m.vertices, vertices)
    assert np.array_equal(m.faces, faces)
    assert m.validate() == []
    assert m.topology().boundary_loops == 2
    # The mesh still takes the whole fill afterwards.
    run()
    assert m.topology().boundary_loops == (0 if call == "fill_holes" else 1)  # fill_holes closes the outer loop too
    assert m.validate() == []


def test_fill_holes_names_each_hole_it_leaves_open():
    m = ring_around_hole(64)
    r = m.fill_holes(10)
    assert r["filled"] == 0 and r["skipped"] == 2
    assert sorted(h["edges"] for h in r["open"]) == [64, 64]
    for h in r["open"]:
        assert "64 edges > max_edges 10" in h["reason"]
        assert 0 <= h["vertex"] < 128
