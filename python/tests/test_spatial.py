"""hmira.BVH, Mesh.closest_point and Mesh.ray_intersect against a numpy brute force over every
triangle (plane projection or edge clamping; plane hit plus barycentric signs), in float64 and
float32; concave faces cut in their plane; NaN queries, empty meshes and stale trees refused."""
from __future__ import annotations

import numpy as np
import pytest

import hmira


def terrain(n: int = 6, seed: int = 1) -> tuple[np.ndarray, np.ndarray]:
    rng = np.random.default_rng(seed)
    i, j = np.meshgrid(np.arange(n + 1), np.arange(n + 1), indexing="xy")
    v = np.column_stack([(i.ravel() + rng.uniform(-0.3, 0.3, i.size)) / n,
                         (j.ravel() + rng.uniform(-0.3, 0.3, i.size)) / n, rng.uniform(-0.5, 0.5, i.size)])
    f = []
    for y in range(n):
        for x in range(n):
            a, b, c, d = y * (n + 1) + x, y * (n + 1) + x + 1, (y + 1) * (n + 1) + x + 1, (y + 1) * (n + 1) + x
            f += [[a, b, c], [a, c, d]]
    return v, np.array(f)


def seg_dist(p: np.ndarray, a: np.ndarray, b: np.ndarray) -> np.ndarray:
    d = b - a
    t = np.clip(np.einsum("ptk,tk->pt", p[:, None, :] - a[None], d) / np.einsum("tk,tk->t", d, d), 0, 1)
    return np.linalg.norm(p[:, None, :] - (a[None] + t[..., None] * d[None]), axis=2)


def brute_closest(v: np.ndarray, f: np.ndarray, p: np.ndarray) -> np.ndarray:
    a, b, c = v[f[:, 0]], v[f[:, 1]], v[f[:, 2]]
    n = np.cross(b - a, c - a)
    n2 = np.einsum("tk,tk->t", n, n)
    h = np.einsum("ptk,tk->pt", p[:, None, :] - a[None], n) / n2
    q = p[:, None, :] - h[..., None] * n[None]
    inside = np.ones(h.shape, bool)
    for u, w in ((a, b), (b, c), (c, a)):
        inside &= np.einsum("ptk,tk->pt", np.cross((w - u)[None], q - u[None]), n) >= 0
    d = np.where(inside, np.abs(h) * np.sqrt(n2), np.inf)
    d = np.minimum(d, np.minimum(seg_dist(p, a, b), np.minimum(seg_dist(p, b, c), seg_dist(p, c, a))))
    return d.min(axis=1)


def brute_first(v: np.ndarray, f: np.ndarray, o: np.ndarray, r: np.ndarray) -> np.ndarray:
    a, b, c = v[f[:, 0]], v[f[:, 1]], v[f[:, 2]]
    n = np.cross(b - a, c - a)
    den = np.einsum("pk,tk->pt", r, n)
    with np.errstate(divide="ignore", invalid="ignore"):
        t = np.einsum("ptk,tk->pt", a[None] - o[:, None, :], n) / den
    q = o[:, None, :] + t[..., None] * r[:, None, :]
    inside = (t >= 0) & np.isfinite(t)
    for u, w in ((a, b), (b, c), (c, a)):
        inside &= np.einsum("ptk,tk->pt", np.cross((w - u)[None], q - u[None]), n) >= 0
    return np.where(inside, t, np.inf).min(axis=1)


def queries(count: int = 300, seed: int = 2) -> tuple[np.ndarray, np.ndarray]:
    rng = np.random.default_rng(seed)
    p = rng.uniform(-0.2, 1.2, (count, 3))
    d = rng.uniform(-1, 1, (count, 3))
    d[::2] = np.array([0.5, 0.5, 0.0]) - p[::2]  # every other ray aims at the surface
    return p, d


def test_closest_point_matches_brute_force() -> None:
    v, f = terrain()
    m = hmira.Mesh(v, f)
    bvh = hmira.BVH(m)
    assert bvh.triangle_count == len(f)
    p, _ = queries()
    points, faces, bary, dist = bvh.closest_point(p)
    np.testing.assert_allclose(dist, brute_closest(v, f, p), rtol=1e-9, atol=1e-12)
    np.testing.assert_allclose(np.linalg.norm(points - p, axis=1), dist, rtol=1e-9, atol=1e-12)
    # The point is the barycentric combination of its face's corners.
    np.testing.assert_allclose(np.einsum("pk,pkj->pj", bary, v[f[faces]]), points, atol=1e-12)
    # The one-shot method gives the same answers; max_distance cuts them off.
    np.testing.assert_array_equal(m.closest_point(p)[3], dist)
    cut = bvh.closest_point(p, max_distance=float(np.median(dist)))
    assert np.all((cut[1] == -1) == (dist > np.median(dist)))


def test_first_and_any_hits_match_brute_force() -> None:
    v, f = terrain()
    bvh = hmira.BVH(hmira.Mesh(v, f))
    o, d = queries()
    t, faces, bary, points = bvh.ray_intersect(o, d)
    expected = brute_first(v, f, o, d)
    hit = np.isfinite(expected)
    assert hit.sum() > 50
    np.testing.assert_array_equal(np.isfinite(t), hit)
    np.testing.assert_allclose(t[hit], expected[hit], rtol=1e-9)
    assert np.all(faces[~hit] == -1)
    np.testing.assert_allclose(np.einsum("pk,pkj->pj", bary[hit], v[f[faces[hit]]]), points[hit], atol=1e-9)
    np.testing.assert_array_equal(bvh.ray_intersect(o, d, mode="any"), hit)


def test_float32_queries_answer_as_their_float64_values() -> None:
    v, f = terrain()
    bvh = hmira.BVH(hmira.Mesh(v, f))
    p, d = queries()
    p32, d32 = p.astype(np.float32), d.astype(np.float32)
    np.testing.assert_array_equal(bvh.closest_point(p32)[3], bvh.closest_point(p32.astype(np.float64))[3])
    np.testing.assert_array_equal(bvh.ray_intersect(p32, d32)[0],
                                  bvh.ray_intersect(p32.astype(np.float64), d32.astype(np.float64))[0])
    # Strided input is read as it is.
    wide = np.zeros((len(p), 6))
    wide[:, ::2] = p
    np.testing.assert_array_equal(bvh.closest_point(wide[:, ::2])[3], bvh.closest_point(p)[3])


def test_a_concave_face_is_cut_in_its_plane() -> None:
    # An L-shaped hexagon whose first corner is reflex: a fan from it would cover the notch.
    v = np.array([[1, 1, 0], [1, 2, 0], [0, 2, 0], [0, 0, 0], [2, 0, 0], [2, 1, 0]], float)
    m = hmira.Mesh(v, [[0, 1, 2, 3, 4, 5]])
    o = np.array([[1.5, 1.5, 1.0], [0.5, 0.5, 1.0], [1.5, 0.5, 1.0], [0.5, 1.5, 1.0]])
    t, faces, _, _ = m.ray_intersect(o, np.tile([0.0, 0.0, -1.0], (4, 1)))
    np.testing.assert_array_equal(faces, [-1, 0, 0, 0])
    np.testing.assert_array_equal(t[1:], [1, 1, 1])
    dist = m.closest_point(o)[3]
    np.testing.assert_allclose(dist, [np.sqrt(1.25), 1, 1, 1])


def test_nan_queries_raise_naming_the_index_or_propagate() -> None:
    bvh = hmira.BVH(hmira.Mesh(*terrain(2)))
    p = np.array([[0.1, 0.1, 1.0], [np.nan, 0, 0], [0.2, 0.2, 0.2]])
    with pytest.raises(ValueError, match="query 1"):
        bvh.closest_point(p)
    points, faces, _, dist = bvh.closest_point(p, nan="propagate")
    assert np.isnan(dist[1]) and faces[1] == -1 and np.isfinite(dist[[0, 2]]).all()
    with pytest.raises(ValueError, match="query 1"):
        bvh.ray_intersect(np.zeros((3, 3)), p)
    assert np.isnan(bvh.ray_intersect(np.zeros((3, 3)), p, nan="propagate")[0][1])
    with pytest.raises(ValueError, match="nan must be"):
        bvh.closest_point(p, nan="ignore")
    with pytest.raises(ValueError, match=r"shape \(n, 3\)"):
        bvh.closest_point(np.zeros((2, 2)))
    with pytest.raises(ValueError, match="float64 or float32"):
        bvh.closest_point(np.zeros((2, 3), dtype=np.int32))


def test_an_empty_mesh_and_a_stale_tree_are_refused() -> None:
    with pytest.raises(ValueError, match="no faces"):
        hmira.BVH(hmira.Mesh())
    with pytest.raises(ValueError, match="no faces"):
        hmira.Mesh().closest_point(np.zeros((1, 3)))
    m = hmira.Mesh(*terrain(2))
    bvh = hmira.BVH(m)
    m.subdivide()
    with pytest.raises(ValueError, match="rebuild"):
        bvh.closest_point(np.zeros((1, 3)))
    # Moved in place: refit follows the positions.
    m2 = hmira.Mesh(*terrain(2))
    bvh2 = hmira.BVH(m2)
    m2.vertices[:, 2] += 1.0
    bvh2.refit()
    np.testing.assert_allclose(bvh2.closest_point(np.array([[0.5, 0.5, 5.0]]))[3],
                               hmira.BVH(m2).closest_point(np.array([[0.5, 0.5, 5.0]]))[3])
