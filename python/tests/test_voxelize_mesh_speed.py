"""voxelize(Mesh) takes the same in-place path as voxelize(V, F): the same grid, no Python
lists for a mesh whose faces have one size, the GIL released during the work (another thread
runs meanwhile), and a time within a few percent of the arrays' (loose bound here; bench/ has
the tight one)."""
from __future__ import annotations

import threading
import time

import numpy as np

import hmira


def sphere(n=40):
    x, y, z = np.mgrid[-1:1:n * 1j, -1:1:n * 1j, -1:1:n * 1j]
    return hmira.marching_cubes(np.sqrt(x**2 + y**2 + z**2) - 0.7, 0.0)


def test_mesh_and_arrays_give_the_same_voxels():
    v, f = sphere()
    m = hmira.Mesh(v, f)
    for mode in ("surface", "conservative", "centres"):
        a = hmira.voxelize(v, f, resolution=48, mode=mode)
        b = hmira.voxelize(m, resolution=48, mode=mode)
        np.testing.assert_array_equal(a[0], b[0])
        np.testing.assert_array_equal(a[1], b[1])
        assert a[2] == b[2]


def test_mixed_polygons_still_voxelize_like_their_triangulation():
    cube_v = [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]]
    mixed = [[0, 3, 2], [0, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]]
    m = hmira.Mesh(cube_v, mixed)
    tri = m.copy()
    tri.triangulate_faces()
    np.testing.assert_array_equal(hmira.voxelize(m, resolution=8)[0], hmira.voxelize(tri.vertices, tri.faces,
                                                                                      resolution=8)[0])


def test_voxelize_mesh_never_builds_polygon_lists(monkeypatch):
    v, f = sphere(20)
    m = hmira.Mesh(v, f)

    def refuse(self):
        raise AssertionError("voxelize(Mesh) built the polygon lists")

    monkeypatch.setattr(hmira.Mesh, "polygons", property(refuse))
    assert hmira.voxelize(m, resolution=16)[0].any()


def test_voxelize_mesh_releases_the_gil_and_is_as_fast_as_arrays():
    v, f = sphere(90)
    m = hmira.Mesh(v, f)
    kwargs = dict(resolution=256, mode="conservative", threads=1)
    hmira.voxelize(v, f, **kwargs)  # warm up
    ticks = []
    stop = threading.Event()

    def count():
        while not stop.is_set():
            ticks.append(time.perf_counter())
            time.sleep(0.001)

    t = threading.Thread(target=count)
    t.start()
    start = time.perf_counter()
    hmira.voxelize(m, **kwargs)
    mesh_time = time.perf_counter() - start
    stop.set()
    t.join()
    # The ticker ran all along: no gap longer than half the call (a held GIL would stall it).
    gaps = np.diff([start] + [x for x in ticks if x >= start])
    assert len(gaps) > 3 and gaps.max() < 0.5 * mesh_time + 0.02
    # Interleaved, best of five each: the machine's load hits both alike.
    arrays, mesh = [], []
    for _ in range(5):
        arrays.append(_timed(lambda: hmira.voxelize(v, f, **kwargs)))
        mesh.append(_timed(lambda: hmira.voxelize(m, **kwargs)))
    assert min(mesh) < 1.5 * min(arrays) + 0.02, (min(mesh), min(arrays))


def _timed(call):
    start = time.perf_counter()
    call()
    return time.perf_counter() - start
