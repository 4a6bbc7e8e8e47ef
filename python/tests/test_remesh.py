"""Mesh.remesh: isotropic remeshing reaches the target edge length on a sphere and a
real mesh, keeps the boundary and sharp edges where they are, refuses bad options with a
ValueError naming them and leaves the mesh unchanged."""
import os

import numpy as np
import pytest

import hmira


def sphere(n=16):
    x, y, z = np.mgrid[-1.5:1.5:n * 1j, -1.5:1.5:n * 1j, -1.5:1.5:n * 1j]
    v, f = hmira.marching_cubes(np.sqrt(x**2 + y**2 + z**2) - 1.0, 0.0, spacing=(3 / (n - 1),) * 3, origin=(-1.5,) * 3)
    return hmira.Mesh(v, f)


def edge_lengths(m):
    v = np.array(m.vertices)
    f = np.array(m.faces)
    e = np.sort(np.concatenate([f[:, [0, 1]], f[:, [1, 2]], f[:, [2, 0]]]), axis=1)
    e = np.unique(e, axis=0)
    return np.linalg.norm(v[e[:, 0]] - v[e[:, 1]], axis=1)


def in_band(m, length):
    lengths = edge_lengths(m)
    return np.mean((lengths >= 0.8 * length) & (lengths <= 4 / 3 * length))


def test_a_sphere_reaches_the_target_length_and_stays_on_it():
    m = sphere()
    r = m.remesh(target_edge_length=0.1, iterations=5)
    assert r['splits'] > 0 and r['collapses'] > 0 and r['flips'] > 0
    assert r['feature_edges'] == 0
    assert m.validate() == []
    t = m.topology()
    assert t.euler_characteristic == 2 and t.closed
    assert in_band(m, 0.1) >= 0.95
    radius = np.linalg.norm(np.array(m.vertices), axis=1)
    assert radius.min() > 0.95 and radius.max() < 1.05


def test_a_square_keeps_its_corners_and_its_plane():
    m = hmira.Mesh([[0, 0, 0], [4, 0, 0], [4, 4, 0], [0, 4, 0]], [[0, 1, 2], [0, 2, 3]])
    r = m.remesh(target_edge_length=0.5, iterations=4)
    assert r['feature_edges'] == 4
    assert m.validate() == []
    v = np.array(m.vertices)
    assert np.all(np.abs(v[:, 2]) < 1e-12)
    for corner in ([0, 0, 0], [4, 0, 0], [4, 4, 0], [0, 4, 0]):
        assert np.any(np.all(v == corner, axis=1)), corner
    assert in_band(m, 0.5) >= 0.9


def test_a_cube_keeps_its_sharp_edges_with_feature_angle():
    v = [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]]
    quads = [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]]
    m = hmira.Mesh(v, [t for q in quads for t in ([q[0], q[1], q[2]], [q[0], q[2], q[3]])])
    r = m.remesh(target_edge_length=0.2, feature_angle=45)
    assert r['feature_edges'] == 12
    assert m.validate() == []
    p = np.array(m.vertices)
    assert np.allclose(np.max(np.abs(p - 0.5), axis=1), 0.5, atol=1e-9)  # on the cube
    for corner in v:
        assert np.any(np.all(p == corner, axis=1)), corner


@pytest.mark.parametrize('kwargs, name', [
    (dict(target_edge_length=0.0), 'target_edge_length'),
    (dict(target_edge_length=float('nan')), 'target_edge_length'),
    (dict(target_edge_length=float('inf')), 'target_edge_length'),
    (dict(target_edge_length=1e-9), 'max_faces'),
    (dict(target_edge_length=0.1, feature_angle=270), 'feature_angle'),
    (dict(target_edge_length=0.1, feature_edges=[10**9]), 'feature_edges'),
    (dict(target_edge_length=0.1, feature_edges=[-1]), 'feature_edges'),
])
def test_bad_options_raise_and_change_nothing(kwargs, name):
    m = sphere(10)
    before = (np.array(m.vertices).tolist(), m.polygons)
    with pytest.raises(ValueError, match=name):
        m.remesh(**kwargs)
    assert (np.array(m.vertices).tolist(), m.polygons) == before


def test_polygons_are_refused():
    m = hmira.Mesh([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], [[0, 1, 2, 3]])
    with pytest.raises(ValueError, match='not a triangle'):
        m.remesh(target_edge_length=0.2)
    assert m.polygons == [[0, 1, 2, 3]]


def test_elephant_reaches_the_band_with_the_default_length():
    data = os.environ.get('HMIRA_TEST_DATA')
    path = os.path.join(data or '', 'meshes', 'elephant.off')
    if not data or not os.path.exists(path):
        pytest.skip('run scripts/test-data.sh first')
    m = hmira.read_mesh(path)
    mean = edge_lengths(m).mean()
    m.remesh()
    assert m.validate() == []
    assert in_band(m, mean) >= 0.95
