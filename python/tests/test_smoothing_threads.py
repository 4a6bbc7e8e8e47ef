"""Mesh smoothing with threads= and construction from arrays: the thread count never changes a
bit of the result; an (m, k) array builds the same mesh as the same faces given as lists, and
a bad array is refused with the same message as the lists."""
import numpy as np
import pytest

import hmira


def noisy_sphere(levels=3, seed=2):
    m = hmira.Mesh([[0, 0, 1], [0, 0, -1], [1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0]],
                   [[0, 2, 4], [0, 4, 3], [0, 3, 5], [0, 5, 2], [1, 4, 2], [1, 3, 4], [1, 5, 3], [1, 2, 5]])
    m.subdivide(scheme="loop", levels=levels)
    v = np.array(m.vertices)
    v += np.random.default_rng(seed).uniform(-0.02, 0.02, v.shape)
    return v, np.array(m.faces)


@pytest.mark.parametrize("smoother", ["laplacian_smooth", "taubin_smooth"])
@pytest.mark.parametrize("weights", ["uniform", "cotangent"])
def test_any_thread_count_gives_the_same_positions(smoother, weights):
    V, F = noisy_sphere()
    results = []
    for threads in (1, 2, 0):
        m = hmira.Mesh(V, F)
        getattr(m, smoother)(iterations=5, weights=weights, threads=threads)
        results.append(np.array(m.vertices))
    assert np.abs(results[0] - V).max() > 1e-4  # it moved
    for r in results[1:]:
        assert np.array_equal(r, results[0])


def test_frozen_cotangent_weights_differ_from_refreshed_ones():
    V, F = noisy_sphere()
    a, b = hmira.Mesh(V, F), hmira.Mesh(V, F)
    a.laplacian_smooth(iterations=8, weights="cotangent", refresh_weights=False)
    b.laplacian_smooth(iterations=8, weights="cotangent")
    assert np.abs(np.array(a.vertices) - np.array(b.vertices)).max() > 1e-9


@pytest.mark.parametrize("dtype", [np.int32, np.int64, np.uint32])
def test_an_array_builds_the_mesh_the_lists_build(dtype):
    V, F = noisy_sphere(levels=2)
    from_array = hmira.Mesh(V, F.astype(dtype))
    from_lists = hmira.Mesh(V.tolist(), F.tolist())
    assert from_array.polygons == from_lists.polygons == F.tolist()
    assert np.array_equal(np.array(from_array.vertices), np.array(from_lists.vertices))
    assert from_array.validate() == [] and repr(from_array.topology()) == repr(from_lists.topology())


def test_a_bad_array_is_refused_as_the_lists_are():
    V, F = noisy_sphere(levels=1)
    bad_index = F.copy()
    bad_index[3, 1] = len(V)
    non_finite = V.copy()
    non_finite[5, 2] = np.nan
    twice = np.vstack([F, F[:1]])  # a face repeated: an edge with three faces
    for vertices, faces in ((V, bad_index), (non_finite, F), (V, twice)):
        messages = []
        for f in (faces, faces.tolist()):
            with pytest.raises(ValueError) as e:
                hmira.Mesh(vertices, f)
            messages.append(str(e.value))
        assert messages[0] == messages[1]
