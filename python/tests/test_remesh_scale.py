"""Mesh.remesh at scales far from unit size: the default length (the mean edge length) is
computed without squaring coordinates, so a mesh at 1e-170 or 1e200 remeshes like one at unit
size; an input whose vertices all coincide is refused naming that, and the mesh is unchanged."""
import numpy as np
import pytest

import hmira


def octahedron(s):
    v = [[s, 0, 0], [-s, 0, 0], [0, s, 0], [0, -s, 0], [0, 0, s], [0, 0, -s]]
    f = [[0, 2, 4], [2, 1, 4], [1, 3, 4], [3, 0, 4], [2, 0, 5], [1, 2, 5], [3, 1, 5], [0, 3, 5]]
    return hmira.Mesh(v, f)


@pytest.mark.parametrize('s', [1e-170, 1e-140, 1e140, 1e200])
def test_far_scales_remesh_at_their_mean_edge_length_like_unit_size(s):
    unit = octahedron(1.0)
    unit.remesh(iterations=2)
    m = octahedron(s)
    m.remesh(iterations=2)  # the default length: the mean edge length, s * sqrt(2)
    v = np.array(m.vertices)
    assert np.all(np.isfinite(v))
    assert m.polygons == unit.polygons
    # Scaled by s, the result is the unit one (the octahedron at s is not exactly s times the
    # one at 1, so up to rounding).
    np.testing.assert_allclose(v / s, np.array(unit.vertices), rtol=0, atol=1e-12)


def test_coinciding_vertices_are_refused_naming_that():
    m = hmira.Mesh([[2, 2, 2]] * 4, [[0, 1, 2], [0, 2, 3], [0, 3, 1], [1, 3, 2]])
    before = (np.array(m.vertices).tolist(), m.polygons)
    with pytest.raises(ValueError, match='all vertices coincide'):
        m.remesh()
    assert (np.array(m.vertices).tolist(), m.polygons) == before
