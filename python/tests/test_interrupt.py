"""Ctrl-C during smoothing and subdivision: KeyboardInterrupt comes promptly, through the
progress hook the bindings pass to the C++ call, and the mesh is left exactly as it was (the
smoothers restore every position, the schemes their copy)."""
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


def icosphere(levels):
    t = (1 + 5**0.5) / 2
    v = [[-1, t, 0], [1, t, 0], [-1, -t, 0], [1, -t, 0], [0, -1, t], [0, 1, t], [0, -1, -t], [0, 1, -t],
         [t, 0, -1], [t, 0, 1], [-t, 0, -1], [-t, 0, 1]]
    f = [[0, 11, 5], [0, 5, 1], [0, 1, 7], [0, 7, 10], [0, 10, 11], [1, 5, 9], [5, 11, 4], [11, 10, 2], [10, 7, 6],
         [7, 1, 8], [3, 9, 4], [3, 4, 2], [3, 2, 6], [3, 6, 8], [3, 8, 9], [4, 9, 5], [2, 4, 11], [6, 2, 10],
         [8, 6, 7], [9, 8, 1]]
    m = hmira.Mesh(v, f)
    if levels:
        m.subdivide(scheme="loop", levels=levels)
    return m


def state(m):
    return np.array(m.vertices).copy(), m.polygons


def interrupted(call, after=0.3):
    """Runs call() in the main thread with an interrupt arriving `after` seconds in; returns
    the seconds until KeyboardInterrupt."""
    timer = threading.Timer(after, _thread.interrupt_main)
    timer.start()
    start = time.perf_counter()
    try:
        with pytest.raises(KeyboardInterrupt):
            call()
    finally:
        timer.cancel()
        timer.join()
    return time.perf_counter() - start


@pytest.mark.parametrize("method", ["taubin_smooth", "laplacian_smooth"])
def test_ctrl_c_stops_a_billion_smoothing_iterations_and_restores_the_positions(method):
    m = icosphere(2)
    rng = np.random.default_rng(1)
    noisy = np.array(m.vertices) + rng.uniform(-0.05, 0.05, (m.vertex_count, 3))
    m = hmira.Mesh(noisy, m.polygons)
    before = state(m)
    seconds = interrupted(lambda: getattr(m, method)(iterations=10**9))
    assert seconds < 5, seconds
    after = state(m)
    assert m.validate() == []
    assert np.array_equal(after[0], before[0])  # bit for bit
    assert after[1] == before[1]
    # Still usable, and a short run moves the vertices.
    getattr(m, method)(iterations=2)
    assert not np.array_equal(np.array(m.vertices), before[0])


@pytest.mark.parametrize("scheme,levels", [("loop", 8), ("sqrt3", 11), ("catmull-clark", 8)])
def test_ctrl_c_stops_a_long_subdivision_and_leaves_the_mesh_unchanged(scheme, levels):
    m = icosphere(1)  # 80 faces: loop 8 levels would make 5.2M, sqrt3 11 levels 14M, catmull-clark 8 levels 3.9M
    before = state(m)
    seconds = interrupted(lambda: m.subdivide(scheme=scheme, levels=levels))
    assert seconds < 5, seconds
    after = state(m)
    assert m.validate() == []
    assert np.array_equal(after[0], before[0])
    assert after[1] == before[1]
    assert m.subdivide(scheme=scheme, levels=1)["faces"] > 80
