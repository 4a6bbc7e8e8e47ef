"""What Python users expect of a compiled library: the GIL is released during long calls,
Ctrl-C interrupts them, memory does not grow over repeated calls, nanobind reports no leaked
objects at exit, and every docstring example runs."""
import _thread
import doctest
import os
import signal
import subprocess
import sys
import threading
import time

import numpy as np
import pytest

import hmira


def gyroid(n):
    x, y, z = np.mgrid[0:6 * np.pi:n * 1j, 0:6 * np.pi:n * 1j, 0:6 * np.pi:n * 1j].astype(np.float32)
    return np.sin(x) * np.cos(y) + np.sin(y) * np.cos(z) + np.sin(z) * np.cos(x)


@pytest.fixture(autouse=True)
def sigint_raises_keyboard_interrupt():
    """Python's own Ctrl-C handler for each test. A process started in the background by a
    non-interactive shell inherits SIGINT ignored, and then Python installs no handler and
    _thread.interrupt_main() does nothing, which would fail the Ctrl-C tests for a reason that
    has nothing to do with hmira."""
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    yield
    signal.signal(signal.SIGINT, previous)


@pytest.fixture(scope="module")
def long_volume():
    """A volume whose single-threaded marching cubes takes at least a second on this machine,
    so that the 50 ms interrupt polling is small against it (a fast machine meshes 192^3 in
    60 ms): the gyroid is tiled along axis 0 until the call is long enough."""
    vol = gyroid(192)
    seconds = _seconds(lambda: hmira.marching_cubes(vol, 0.0, threads=1))
    if seconds < 1.0:
        copies = min(24, int(np.ceil(1.0 / max(seconds, 1e-3))))
        vol = np.ascontiguousarray(np.tile(vol, (copies, 1, 1)))
        seconds = _seconds(lambda: hmira.marching_cubes(vol, 0.0, threads=1))
    return vol, seconds


def _seconds(call):
    start = time.perf_counter()
    call()
    return time.perf_counter() - start


def test_another_thread_runs_during_a_long_call(long_volume):
    vol, seconds = long_volume
    count = 0
    stop = threading.Event()

    def spin():
        nonlocal count
        while not stop.is_set():
            count += 1

    t = threading.Thread(target=spin)
    t.start()
    time.sleep(0.02)
    before = count
    hmira.marching_cubes(vol, 0.0, threads=1)
    during = count - before
    stop.set()
    t.join()
    # With the GIL held the spinning thread would not get a single slice during the call.
    assert during > 1000, (during, seconds)


def test_ctrl_c_interrupts_a_long_marching_cubes(long_volume):
    vol, seconds = long_volume
    timer = threading.Timer(seconds / 10, _thread.interrupt_main)
    timer.start()
    start = time.perf_counter()
    with pytest.raises(KeyboardInterrupt):
        hmira.marching_cubes(vol, 0.0, threads=1)
    elapsed = time.perf_counter() - start
    timer.join()
    assert elapsed < seconds * 0.7, (elapsed, seconds)
    # The extension is still usable afterwards.
    assert len(hmira.marching_cubes(vol[:32, :32, :32], 0.0)[1]) > 0


def test_ctrl_c_interrupts_a_long_voxelization():
    v, f = hmira.marching_cubes(gyroid(96), 0.0)
    # Grow the resolution until the call takes at least half a second (time grows about as
    # resolution^2 for a surface voxelization), so the 50 ms polling is small against it.
    resolution = 400
    seconds = _seconds(lambda: hmira.voxelize(v, f, resolution=resolution, threads=1, mode="surface"))
    if seconds < 0.5:
        resolution = min(900, int(resolution * np.sqrt(0.5 / max(seconds, 1e-3))) + 1)
        seconds = _seconds(lambda: hmira.voxelize(v, f, resolution=resolution, threads=1, mode="surface"))
    timer = threading.Timer(seconds / 10, _thread.interrupt_main)
    timer.start()
    start = time.perf_counter()
    with pytest.raises(KeyboardInterrupt):
        hmira.voxelize(v, f, resolution=resolution, threads=1, mode="surface")
    timer.join()
    assert time.perf_counter() - start < seconds * 0.7, (resolution, seconds)


EDITS = {
    "truncate": lambda m: m.truncate(all=True, fraction=0.25),
    "bevel": lambda m: m.bevel(all=True, width=0.01),
    "extrude": lambda m: m.extrude(all=True, mode="individual", distance=0.1),
}


@pytest.fixture(scope="module")
def long_edit_mesh():
    """A gyroid surface whose truncate(all=True) takes at least a second on this machine (the
    time grows about as n^2 for an n^3 volume), so the 50 ms interrupt polling is small
    against it; bevel and extrude of every element take about as long."""
    n = 48
    while True:
        v, f = hmira.marching_cubes(gyroid(n), 0.0)
        mesh = hmira.Mesh(v, f)
        seconds = _seconds(lambda: EDITS["truncate"](mesh.copy()))
        if seconds >= 1.0 or n >= 400:
            return mesh, seconds
        n = min(400, int(n * np.sqrt(1.2 / max(seconds, 1e-3))) + 1)


@pytest.mark.parametrize("edit", sorted(EDITS))
def test_ctrl_c_interrupts_a_long_edit_and_leaves_the_mesh_unchanged(long_edit_mesh, edit):
    mesh, _ = long_edit_mesh
    m = mesh.copy()
    seconds = _seconds(lambda: EDITS[edit](mesh.copy()))
    vertices, faces = np.array(m.vertices), m.faces.copy()
    timer = threading.Timer(seconds / 10, _thread.interrupt_main)
    timer.start()
    start = time.perf_counter()
    with pytest.raises(KeyboardInterrupt):
        EDITS[edit](m)
    elapsed = time.perf_counter() - start
    timer.join()
    assert elapsed < seconds * 0.7, (elapsed, seconds)
    # Rolled back: the same vertices and faces, in the same order, and still a valid mesh.
    assert np.array_equal(m.vertices, vertices)
    assert np.array_equal(m.faces, faces)
    assert m.validate() == []
    # The mesh still takes the whole edit afterwards (a bevel clamped at half of a marching
    # cubes' tiny edges may make faces of zero area, as bevel() documents).
    EDITS[edit](m)
    assert [p for p in m.validate() if not p.endswith("zero area")] == []


def _other_thread_progress_during(call, min_seconds):
    """Runs `call` repeatedly for at least `min_seconds` while another thread wakes every
    millisecond and takes a time stamp, which needs the GIL. Returns the stamps taken well
    inside the calls (their middle 80%: none while a call holds the GIL) and the time spent in
    calls."""
    stamps, windows = [], []
    stop = threading.Event()

    def stamp():
        while not stop.is_set():
            stamps.append(time.perf_counter())
            time.sleep(0.001)

    t = threading.Thread(target=stamp)
    t.start()
    time.sleep(0.02)
    total = 0.0
    while total < min_seconds:
        start = time.perf_counter()
        call()
        end = time.perf_counter()
        windows.append((start + 0.1 * (end - start), end - 0.1 * (end - start)))
        total += end - start
    stop.set()
    t.join()
    inside = sum(1 for s in stamps if any(a < s < b for a, b in windows))
    return inside, total


@pytest.mark.parametrize("call", ["truncate", "bevel", "extrude", "topology", "validate", "vertex_normals", "write", "copy", "flip"])
def test_another_thread_runs_during_a_long_mesh_call(long_edit_mesh, tmp_path, call):
    mesh, _ = long_edit_mesh
    m = mesh.copy()
    calls = {
        "truncate": lambda: EDITS["truncate"](m.copy()),
        "bevel": lambda: EDITS["bevel"](m.copy()),
        "extrude": lambda: EDITS["extrude"](m.copy()),
        "topology": m.topology,
        "validate": m.validate,
        "vertex_normals": m.vertex_normals,
        "write": lambda: m.write(str(tmp_path / "m.ply")),
        "copy": m.copy,
        "flip": m.flip,
    }
    inside, total = _other_thread_progress_during(calls[call], 0.3)
    # Released, the other thread stamps about once a millisecond (less on a loaded machine);
    # held, it cannot stamp at all inside a call.
    assert inside >= max(3, 0.02 * total / 0.001), (inside, total)


def test_a_mesh_in_use_by_another_thread_refuses_calls_instead_of_racing(long_edit_mesh):
    mesh, _ = long_edit_mesh
    m = mesh.copy()
    started, refused, answered = threading.Event(), [], []

    def edit():
        started.set()
        EDITS["truncate"](m)

    t = threading.Thread(target=edit)
    t.start()
    started.wait()
    time.sleep(0.05)
    for call in (m.topology, lambda: m.vertices, lambda: m.truncate([0]), m.copy):
        try:
            call()
            answered.append(call)
        except RuntimeError as e:
            refused.append(str(e))
    t.join()
    assert len(refused) == 4, (refused, answered)
    assert all("another thread" in r for r in refused), refused
    assert m.validate() == []


def rss_bytes():
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * os.sysconf("SC_PAGE_SIZE")


def test_rss_grows_less_than_5_mb_over_1000_calls(tmp_path):
    vol = gyroid(12)
    points = np.random.default_rng(0).random((50, 2))
    path = tmp_path / "m.off"
    v, f = hmira.marching_cubes(vol, 0.0)
    hmira.write_mesh(path, (v, f))

    def work():
        v, f = hmira.marching_cubes(vol, 0.0)
        m = hmira.Mesh(v, f)
        m.vertices[0] += 0.0
        m.topology()
        m.vertex_normals()
        hmira.delaunay_triangulation(points, voronoi=True)
        hmira.voxelize(v, f, resolution=8)
        hmira.read_mesh(path).copy().truncate([0])
        try:
            hmira.marching_cubes(vol, np.nan)
        except ValueError:
            pass

    for _ in range(100):
        work()
    before = rss_bytes()
    for _ in range(1000):
        work()
    grown = rss_bytes() - before
    assert grown < 5 * 2**20, grown


LEAK_SCRIPT = """
import numpy as np, hmira, tempfile, os
x, y, z = np.mgrid[-1:1:24j, -1:1:24j, -1:1:24j]
v, f = hmira.marching_cubes(x**2 + y**2 + z**2 - 0.5, 0.0)
m = hmira.Mesh(v, f); view = m.vertices; t = m.topology(); m.truncate([0]); c = m.copy()
g = hmira.voxelize(v, f, resolution=8); d = hmira.delaunay_triangulation(v[:, :2], voronoi=True)
p = os.path.join(tempfile.mkdtemp(), "m.ply"); hmira.write_mesh(p, c); r = hmira.read_mesh(p)
try:
    hmira.Mesh(v, [[0, 1, 10**9]])
except ValueError:
    pass
{extra}
"""


@pytest.mark.parametrize("extra,leaks", [("", False), ("import ctypes; ctypes.pythonapi.Py_IncRef(ctypes.py_object(hmira.Mesh(v, f)))", True)])
def test_nanobind_reports_no_leak_at_exit(extra, leaks):
    # The second case leaks a reference to a Mesh on purpose, showing that the check can fail.
    r = subprocess.run([sys.executable, "-c", LEAK_SCRIPT.format(extra=extra)], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    assert ("leaked" in r.stderr) == leaks, r.stderr


def test_docstring_examples_run():
    finder = doctest.DocTestFinder()
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS)
    objects = [hmira, hmira.Mesh, hmira.Mesh.truncate, hmira.Mesh.bevel, hmira.Mesh.extrude, hmira.read_mesh, hmira.write_mesh,
               hmira.voxelize, hmira.marching_cubes, hmira.delaunay_triangulation]
    tested = 0
    for obj in objects:
        for test in finder.find(obj, name=getattr(obj, "__qualname__", "hmira"), globs={"hmira": hmira, "np": np}):
            tested += len(test.examples)
            runner.run(test)
    assert runner.failures == 0
    assert tested >= 20
