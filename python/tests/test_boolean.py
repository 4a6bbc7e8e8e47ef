"""hmira.mesh_boolean: volumes checked by the volume identity and by hand, the face origins checked
against the input faces' planes, arrays and Mesh inputs alike, empty results and refused ops."""
from __future__ import annotations

import numpy as np
import pytest

import hmira

QUADS = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]]


def box_arrays(lo, hi, rotation=None):
    v = np.array([[hi[0] if i & 1 else lo[0], hi[1] if i & 2 else lo[1], hi[2] if i & 4 else lo[2]]
                  for i in range(8)], dtype=np.float64)
    if rotation is not None:  # about the box's centre
        centre = (np.asarray(lo, dtype=np.float64) + hi) / 2
        v = (v - centre) @ rotation.T + centre
    return v, np.array(QUADS)


def box(lo, hi, rotation=None):
    return hmira.Mesh(*box_arrays(lo, hi, rotation))


def rotation(seed):
    q = np.random.default_rng(seed).normal(size=4)
    w, x, y, z = q / np.linalg.norm(q)
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                     [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                     [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])


PAIRS = {
    "axis_aligned": (([0, 0, 0], [2, 2, 2], None), ([1, 0.5, 0.5], [3, 1.5, 3], None)),
    "rotated": (([0, 0, 0], [2, 2, 2], rotation(1)), ([0.5, 0.25, 0.75], [2.5, 2.25, 2.75], rotation(2))),
}


@pytest.mark.parametrize("pair", sorted(PAIRS))
def test_volume_identity(pair):
    (la, ha, ra), (lb, hb, rb) = PAIRS[pair]
    a, b = box(la, ha, ra), box(lb, hb, rb)
    vol = {op: hmira.mesh_boolean(a, b, op=op).mesh.volume() for op in ("union", "intersection", "difference", "xor")}
    assert vol["intersection"] > 0.1  # the boxes do overlap
    assert vol["union"] + vol["intersection"] == pytest.approx(a.volume() + b.volume(), rel=1e-12)
    assert vol["difference"] == pytest.approx(a.volume() - vol["intersection"], rel=1e-12)
    assert vol["xor"] == pytest.approx(vol["union"] - vol["intersection"], rel=1e-12)
    assert hmira.mesh_boolean(a, b).mesh.volume() == vol["union"]  # union is the default


def test_the_volumes_known_by_hand():
    a, b = box([0, 0, 0], [2, 2, 2]), box([1, 0.5, 0.5], [3, 1.5, 3])
    r = hmira.mesh_boolean(a, b, op="difference")
    assert isinstance(r, hmira.BooleanResult)
    assert r.mesh.volume() == pytest.approx(8 - 1.5, rel=1e-14)
    assert r.cut_triangles > 0 and r.rounding_intersections == 0 and r.degenerate_faces == 0
    assert r.mesh.topology().boundary_loops == 0 and r.mesh.topology().genus == 0
    assert r.mesh.validate() == [] and r.mesh.repairs == ""
    # xor's two parts meet along the intersection curve: the Mesh holds it with those edges split.
    x = hmira.mesh_boolean(a, b, op="xor")
    assert "non-manifold edges" in x.mesh.repairs
    assert x.mesh.volume() == pytest.approx(8 + 5 - 2 * 1.5, rel=1e-14) and x.mesh.validate() == []


@pytest.mark.parametrize("pair", sorted(PAIRS))
def test_each_output_face_lies_in_the_plane_of_its_origin(pair):
    (la, ha, ra), (lb, hb, rb) = PAIRS[pair]
    inputs = [box_arrays(la, ha, ra), box_arrays(lb, hb, rb)]
    r = hmira.mesh_boolean(hmira.Mesh(*inputs[0]), hmira.Mesh(*inputs[1]), op="xor")
    n = r.mesh.face_count
    assert r.origin_mesh.dtype == np.uint8 and r.origin_face.dtype == np.int64
    assert r.origin_mesh.shape == (n,) and r.origin_face.shape == (n,)
    assert set(np.unique(r.origin_mesh)) == {0, 1}
    out_v = np.asarray(r.mesh.vertices)
    out_f = r.mesh.faces
    for i in range(n):
        v, quads = inputs[r.origin_mesh[i]]
        corners = v[quads[r.origin_face[i]]]  # the input quad the output triangle came from
        normal = np.cross(corners[1] - corners[0], corners[2] - corners[0])
        normal /= np.linalg.norm(normal)
        d = (out_v[out_f[i]] - corners[0]) @ normal
        assert np.abs(d).max() < 1e-12, (i, d)


def test_arrays_and_meshes_give_the_same_result():
    va, fa = box_arrays([0, 0, 0], [2, 2, 2], rotation(3))
    vb, fb = box_arrays([0.5, 0.5, 0.5], [2.5, 2.5, 2.5], rotation(4))
    from_meshes = hmira.mesh_boolean(hmira.Mesh(va, fa), hmira.Mesh(vb, fb), op="intersection")
    from_arrays = hmira.mesh_boolean((va, fa), (vb, fb), op="intersection")
    mixed = hmira.mesh_boolean((va, fa), hmira.Mesh(vb, fb), op="intersection")
    for r in (from_arrays, mixed):
        assert r.mesh.face_count == from_meshes.mesh.face_count
        assert r.mesh.volume() == pytest.approx(from_meshes.mesh.volume(), rel=1e-14)
        assert np.array_equal(np.sort(r.origin_mesh), np.sort(from_meshes.origin_mesh))


def test_a_minus_a_is_empty():
    a = box([0, 0, 0], [1, 1, 1], rotation(5))
    r = hmira.mesh_boolean(a, a.copy(), op="difference")
    assert r.mesh.face_count == 0 and r.mesh.vertex_count == 0
    assert len(r.origin_mesh) == 0 and len(r.origin_face) == 0
    same = hmira.mesh_boolean(a, a, op="intersection")
    assert same.mesh.volume() == pytest.approx(a.volume(), rel=1e-14)


def test_inputs_are_left_alone():
    a, b = box([0, 0, 0], [2, 2, 2]), box([1, 1, 1], [3, 3, 3])
    before = (np.array(a.vertices), a.faces)
    hmira.mesh_boolean(a, b, op="union")
    assert np.array_equal(before[0], a.vertices) and np.array_equal(before[1], a.faces)


def test_a_bad_op_is_a_value_error():
    a = box([0, 0, 0], [1, 1, 1])
    with pytest.raises(ValueError, match="unknown op 'minus'.*'union', 'intersection', 'difference', 'xor'"):
        hmira.mesh_boolean(a, a, op="minus")
    with pytest.raises(ValueError, match="must be a Mesh or a \\(vertices, faces\\) pair"):
        hmira.mesh_boolean(a, [1, 2, 3])
    with pytest.raises(TypeError):
        hmira.mesh_boolean(a, a, "union")  # op is keyword-only


def test_a_non_finite_coordinate_is_a_value_error():
    v, f = box_arrays([0, 0, 0], [1, 1, 1])
    v[3, 1] = np.nan
    with pytest.raises(ValueError):
        hmira.mesh_boolean((v, f), box([0, 0, 0], [1, 1, 1]))


@pytest.fixture
def sigint_raises_keyboard_interrupt():
    """Python's own Ctrl-C handler (a background process may inherit SIGINT ignored)."""
    import signal
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    yield
    signal.signal(signal.SIGINT, previous)


def test_ctrl_c_interrupts_a_long_boolean_and_leaves_the_inputs_alone(sigint_raises_keyboard_interrupt):
    import _thread
    import threading
    import time

    # Two spheres of 20 * 4^5 = 20480 triangles each, the second moved off-centre: the boolean
    # runs long against the 50 ms interrupt polling.
    t = (1 + 5**0.5) / 2
    v = [[-1, t, 0], [1, t, 0], [-1, -t, 0], [1, -t, 0], [0, -1, t], [0, 1, t], [0, -1, -t], [0, 1, -t],
         [t, 0, -1], [t, 0, 1], [-t, 0, -1], [-t, 0, 1]]
    f = [[0, 11, 5], [0, 5, 1], [0, 1, 7], [0, 7, 10], [0, 10, 11], [1, 5, 9], [5, 11, 4], [11, 10, 2], [10, 7, 6],
         [7, 1, 8], [3, 9, 4], [3, 4, 2], [3, 2, 6], [3, 6, 8], [3, 8, 9], [4, 9, 5], [2, 4, 11], [6, 2, 10],
         [8, 6, 7], [9, 8, 1]]
    a = hmira.Mesh(v, f)
    a.subdivide(scheme="loop", levels=5)
    b = hmira.Mesh(np.array(a.vertices) + [0.3, 0.2, 0.1], a.faces)
    start = time.perf_counter()
    full = hmira.mesh_boolean(a, b, op="union")
    seconds = time.perf_counter() - start
    if seconds < 0.3:
        pytest.skip(f"the boolean took only {seconds:.3f} s here")
    before = np.array(a.vertices)
    timer = threading.Timer(seconds / 3, _thread.interrupt_main)
    timer.start()
    start = time.perf_counter()
    try:
        with pytest.raises(KeyboardInterrupt):
            hmira.mesh_boolean(a, b, op="union")
    finally:
        timer.cancel()
        timer.join()
    assert time.perf_counter() - start < seconds / 3 + 0.25 + seconds / 4
    assert np.array_equal(before, a.vertices)
    again = hmira.mesh_boolean(a, b, op="union")  # the meshes are free again
    assert again.mesh.face_count == full.mesh.face_count


def test_repair_solid_of_two_overlapping_boxes_in_one_mesh_is_their_union():
    (va, fa), (vb, fb) = box_arrays([0, 0, 0], [2, 2, 2]), box_arrays([1, 0.5, 0.5], [3, 1.5, 3])
    both = (np.vstack([va, vb]), np.vstack([fa, fb + 8]))
    for mesh in (both, hmira.Mesh(*both)):
        r = hmira.repair(mesh)
        assert isinstance(r, hmira.BooleanResult)
        assert r.mesh.volume() == pytest.approx(8 + 5 - 1.5, rel=1e-14)
        assert r.mesh.topology().boundary_loops == 0 and r.mesh.validate() == []
        assert r.cut_triangles > 0 and np.all(r.origin_mesh == 0)
    # A self-intersecting operand of mesh_boolean counts as the solid it bounds.
    c = box([0.5, 1, 1], [2.5, 2.5, 2.5])
    u = hmira.mesh_boolean(both, c).mesh.volume()
    assert u == pytest.approx(hmira.mesh_boolean(hmira.repair(both).mesh, c).mesh.volume(), rel=1e-12)
    # Without solid=True, a copy as the readers' repair holds it: both boxes, overlapping.
    assert hmira.repair(both, solid=False).mesh.volume() == pytest.approx(13, rel=1e-14)
