"""Surface queries from Python: winding numbers and signed distances against numpy brute force
(solid angles, distances to vertices), float32 in and out, NaN handling, the Mesh methods,
sampling reproducible from a seed, and the Hausdorff distance of a translated copy."""
from __future__ import annotations

import numpy as np
import pytest

import hmira


def octahedron():
    v = np.array([[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]], dtype=np.float64)
    f = np.array([[0, 2, 4], [2, 1, 4], [1, 3, 4], [3, 0, 4], [2, 0, 5], [1, 2, 5], [3, 1, 5], [0, 3, 5]])
    return v, f


def brute_winding(v, f, p):
    a, b, c = (v[f[:, k]][None, :, :] - p[:, None, :] for k in range(3))
    la, lb, lc = (np.linalg.norm(x, axis=2) for x in (a, b, c))
    num = np.einsum("ijk,ijk->ij", a, np.cross(b, c))
    den = la * lb * lc + np.einsum("ijk,ijk->ij", a, b) * lc + np.einsum("ijk,ijk->ij", b, c) * la
    den += np.einsum("ijk,ijk->ij", c, a) * lb
    return (2 * np.arctan2(num, den)).sum(axis=1) / (4 * np.pi)


def test_winding_number_matches_numpy_solid_angles():
    v, f = octahedron()
    p = np.random.default_rng(1).uniform(-1.5, 1.5, (200, 3))
    w = hmira.winding_number(v, f, p, method="direct")
    assert w.dtype == np.float64 and w.shape == (200,)
    np.testing.assert_allclose(w, brute_winding(v, f, p), atol=1e-12)
    np.testing.assert_allclose(hmira.winding_number(v, f, p), w, atol=0.05)
    inside = np.abs(p).sum(axis=1) < 1
    assert np.array_equal(hmira.signed_distance(v, f, p) < 0, inside)


def test_float32_in_float32_out_and_nan_policy():
    v, f = octahedron()
    p = np.array([[0.1, 0.1, 0.1], [3, 0, 0], [np.nan, 0, 0]], dtype=np.float32)
    with pytest.raises(ValueError, match="query point 2"):
        hmira.winding_number(v, f, p)
    w = hmira.winding_number(v, f, p, nan="propagate")
    assert w.dtype == np.float32
    assert np.isnan(w[2]) and abs(w[0] - 1) < 1e-3 and abs(w[1]) < 1e-3
    d = hmira.signed_distance(v, f, p, nan="propagate")
    assert d.dtype == np.float32 and d[0] < 0 < d[1] and np.isnan(d[2])
    with pytest.raises(ValueError, match="sign"):
        hmira.signed_distance(v, f, p, sign="nope")


def test_mesh_methods_and_sampling():
    v, f = octahedron()
    mesh = hmira.Mesh(v, f)
    p = np.array([[0.0, 0.0, 0.0], [2.0, 0.0, 0.0]])
    assert mesh.contains(p).tolist() == [True, False]
    np.testing.assert_allclose(mesh.winding_number(p), [1, 0], atol=1e-3)
    d = mesh.signed_distance(p)
    np.testing.assert_allclose(d, [-1 / np.sqrt(3), 1.0], atol=1e-12)
    s1 = mesh.sample_surface(1000, seed=3)
    s2 = mesh.sample_surface(1000, seed=3)
    assert np.array_equal(s1["points"], s2["points"])
    assert s1["points"].shape == (1000, 3)
    # Every sample lies on the octahedron |x| + |y| + |z| = 1 and is its corners' weighted sum.
    np.testing.assert_allclose(np.abs(s1["points"]).sum(axis=1), 1, atol=1e-12)
    pv = np.asarray(mesh.vertices)
    rebuilt = np.einsum("ik,ikj->ij", s1["barycentrics"], pv[s1["corners"]])
    np.testing.assert_allclose(rebuilt, s1["points"], atol=1e-12)
    blue = mesh.sample_surface(200, method="poisson_disk")
    assert blue["points"].shape == (200, 3)
    with pytest.raises(ValueError, match="no faces"):
        hmira.Mesh().winding_number(p)


def test_hausdorff_of_a_parallel_copy_is_the_shift():
    v = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], dtype=np.float64)
    f = np.array([[0, 1, 2], [0, 2, 3]])
    h = hmira.hausdorff_distance((v, f), (v + [0, 0, 0.25], f), min_samples=2000)
    assert h["symmetric"] == pytest.approx(0.25, abs=1e-12)
    assert h["a_to_b"]["mean"] == pytest.approx(0.25, abs=1e-12)
    assert h["b_to_a"]["samples"] >= 2000
    o, of = octahedron()
    assert hmira.hausdorff_distance(hmira.Mesh(o, of), (o, of), min_samples=1000)["symmetric"] == pytest.approx(
        0, abs=1e-12
    )
    with pytest.raises(ValueError, match="Mesh or a"):
        hmira.hausdorff_distance(v, (v, f))
