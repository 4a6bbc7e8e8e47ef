"""hmira.view, Mesh._repr_html_ and hmira.render: the page is the CLI's self-contained viewer
page with the mesh's counts and buffers, and render() draws it through headless Chromium.

These need the viewer bundle compiled in (scripts/python.sh runs viewer/build.sh first) and, for
render(), Chromium; a missing piece fails the test with the reason instead of skipping it."""
import base64
import html
import importlib.util
import json
import os
import re
import sys

import numpy as np
import pytest

import hmira
from hmira import viewer

# A unit cube of six quads: V 8, E 12, F 6, genus 0, closed; 12 triangles once fanned.
CUBE_V = [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]]
CUBE_F = [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]]
BACKGROUND = (0xF4, 0xF5, 0xF7)  # the page's clear colour (viewer/src/viewer.js palette.background)


def box(sx, sy, sz):
    return hmira.Mesh(np.array(CUBE_V, float) * [sx, sy, sz], CUBE_F)


def scene_of(page):
    block = re.search(r'<script type="application/json" id="hmira-scene">(.*?)</script>', page, re.S)
    assert block, "the page has no hmira-scene block"
    return json.loads(block.group(1))


def buffer_of(page, mesh, name, dtype):
    block = re.search(rf'<script type="application/octet-stream" id="hmira-m{mesh}-{name}">([A-Za-z0-9+/=]*)</script>', page)
    return None if block is None else np.frombuffer(base64.b64decode(block.group(1)), dtype=np.dtype(dtype).newbyteorder("<"))


def test_the_bundle_is_compiled_in():
    assert hmira._core._viewer_bundle_available(), (
        "hmira was built without the viewer bundle: run viewer/build.sh before pip install . (scripts/python.sh does)")


def test_page_is_self_contained():
    page = hmira.view(box(1, 1, 1)).html
    assert page.startswith("<!doctype html>")
    tags = re.findall(r"<(script|link|img|iframe|object|embed|source)\b([^>]*)>", page, re.I)
    assert tags and all(kind.lower() == "script" for kind, _ in tags), "only inline scripts may appear"
    assert not any(re.search(r"\bsrc\s*=", attributes, re.I) for _, attributes in tags), "a <script src=...> would fetch"
    # The only URL in the page is the XHTML namespace name three.js passes to createElementNS (never fetched).
    assert set(re.findall(r"https?://[^\s\"'<>)]*", page)) <= {"http://www.w3.org/1999/xhtml"}
    for fetching in ("fetch(", "XMLHttpRequest", "importScripts", "@import"):
        assert fetching not in page


def test_page_carries_counts_and_buffers():
    page = hmira.view(box(2, 1, 1)).html
    scene = scene_of(page)
    assert scene["version"] == 1 and len(scene["meshes"]) == 1
    entry = scene["meshes"][0]
    assert entry["triangles"] == 12
    assert entry["info"] == {"vertices": 8, "edges": 12, "faces": 6, "genus": 0, "closed": True, "boundary_edges": 0,
                             "non_manifold_edges": 0}
    positions = buffer_of(page, 0, "positions", np.float32).reshape(-1, 3)
    assert positions.shape == (8, 3)
    # Relative to the bounding-box centre (1, 0.5, 0.5): the 2 x 1 x 1 box spans +-1, +-0.5, +-0.5.
    np.testing.assert_array_equal(positions.min(axis=0), [-1, -0.5, -0.5])
    np.testing.assert_array_equal(positions.max(axis=0), [1, 0.5, 0.5])
    triangles = buffer_of(page, 0, "triangles", np.uint32)
    assert triangles.size == 36 and triangles.max() == 7
    assert buffer_of(page, 0, "boundary", np.uint32) is None  # closed: no boundary buffer


def test_open_mesh_reports_its_boundary():
    square = hmira.Mesh([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], [[0, 1, 2, 3]])
    page = hmira.view(square).html
    info = scene_of(page)["meshes"][0]["info"]
    assert (info["vertices"], info["edges"], info["faces"], info["closed"], info["boundary_edges"]) == (4, 4, 1, False, 4)
    assert buffer_of(page, 0, "boundary", np.uint32).size == 8


def test_view_takes_arrays_objects_and_compare(tmp_path):
    vertices, faces = np.array(CUBE_V, float), np.array(CUBE_F)

    class Duck:
        pass

    duck = Duck()
    duck.vertices, duck.faces = vertices, faces
    from_mesh = hmira.view(hmira.Mesh(vertices, faces)).html
    assert hmira.view((vertices, faces)).html == from_mesh
    assert hmira.view(duck).html == from_mesh
    # Triangles from marching cubes (int32 faces) go in as they are.
    x, y, z = np.mgrid[-1:1:20j, -1:1:20j, -1:1:20j]
    v, f = hmira.marching_cubes(x**2 + y**2 + z**2 - 0.5, 0.0)
    info = scene_of(hmira.view((v, f)).html)["meshes"][0]["info"]
    assert (info["vertices"], info["faces"], info["genus"], info["closed"]) == (len(v), len(f), 0, True)

    pair = hmira.view(box(1, 1, 1), compare=(vertices * 2, faces)).html
    meshes = scene_of(pair)["meshes"]
    assert [m["info"]["faces"] for m in meshes] == [6, 6]
    # Both share the first mesh's origin (0.5, 0.5, 0.5), so the doubled cube shows where it is.
    second = buffer_of(pair, 1, "positions", np.float32).reshape(-1, 3)
    np.testing.assert_array_equal(second.min(axis=0), [-0.5, -0.5, -0.5])
    np.testing.assert_array_equal(second.max(axis=0), [1.5, 1.5, 1.5])

    out = tmp_path / "cube.html"
    shown = hmira.view(box(1, 1, 1), out=out)
    assert out.read_text(encoding="utf-8") == shown.html


def test_points_without_faces_are_shown_as_points():
    page = hmira.view((np.array([[0, 0, 0], [1, 2, 3], [4, 0, 1]], float), np.zeros((0, 3), int))).html
    info = scene_of(page)["meshes"][0]
    assert info["triangles"] == 0 and info["info"]["vertices"] == 3 and info["info"]["faces"] == 0
    assert buffer_of(page, 0, "triangles", np.uint32) is None
    assert buffer_of(page, 0, "positions", np.float32).size == 9


def test_bad_input_is_refused():
    with pytest.raises(ValueError, match="no vertices"):
        hmira.view(hmira.Mesh())
    with pytest.raises(ValueError):
        hmira.view(([[0, 0, 0], [1, 0, 0]], [[0, 1, 5]]))  # vertex 5 does not exist
    with pytest.raises(ValueError, match="expected a hmira.Mesh"):
        hmira.view(42)


def test_repr_html_is_the_page_in_an_iframe(monkeypatch):
    # The page with its viewer script replaced by the loader (the script goes to the notebook once:
    # test_notebook_repr.py).
    monkeypatch.setitem(viewer._notebook, "sent", True)
    mesh = box(1, 1, 1)
    shown = mesh._repr_html_()
    frame = re.fullmatch(r'<iframe srcdoc="([^"]*)" [^>]*></iframe>', shown, re.S)
    assert frame, shown[:200]
    before, _bundle, after = viewer._split_page(hmira.view(mesh).html)
    assert html.unescape(frame.group(1)) == before + viewer._LOADER + after
    assert "hmira-scene" in html.unescape(frame.group(1))
    assert mesh._repr_html_() == shown
    assert hmira.Mesh()._repr_html_() == "<pre>hmira.Mesh(vertices=0, faces=0)</pre>"


def test_render_refuses_bad_options_and_says_how_to_get_chromium(tmp_path, monkeypatch):
    with pytest.raises(ValueError, match="view must be one of"):
        hmira.render(box(1, 1, 1), tmp_path / "x.png", view="diagonal")
    with pytest.raises(ValueError, match="up must be"):
        hmira.render(box(1, 1, 1), tmp_path / "x.png", up="x")
    with pytest.raises(ValueError, match="size"):
        hmira.render(box(1, 1, 1), tmp_path / "x.png", size=(0, 100))
    monkeypatch.setenv("HMIRA_CHROMIUM", str(tmp_path / "no-such-chromium"))
    with pytest.raises(RuntimeError, match="apt install chromium"):
        hmira.render(box(1, 1, 1), tmp_path / "x.png")
    assert not (tmp_path / "x.png").exists()


def chromium_or_fail():
    found = viewer.find_chromium()
    assert found, "Chromium is missing: install it (apt install chromium; scripts/install-deps.sh does)"
    return found


def mesh_pixels(png_path):
    """A boolean (h, w) mask of the pixels that differ from the page's background."""
    from PIL import Image

    with Image.open(png_path) as image:
        rgb = np.asarray(image.convert("RGB")).astype(int)
    return np.abs(rgb - BACKGROUND).sum(axis=2) > 24


def extent(mask):
    rows, cols = np.nonzero(mask)
    return cols.max() - cols.min() + 1, rows.max() - rows.min() + 1


def test_render_writes_a_png_of_the_mesh(tmp_path):
    chromium_or_fail()
    x, y, z = np.mgrid[-1:1:40j, -1:1:40j, -1:1:40j]
    sphere = hmira.Mesh(*hmira.marching_cubes(x**2 + y**2 + z**2 - 0.5, 0.0))
    out = tmp_path / "sphere.png"
    hmira.render(sphere, out, size=(320, 240))
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    mask = mesh_pixels(out)
    assert mask.shape == (240, 320)
    assert 0.10 <= mask.mean() <= 0.90, f"the mesh covers {mask.mean():.1%} of the frame"


def test_render_views_look_from_where_they_say(tmp_path):
    chromium_or_fail()
    # A bar 4 long along x: wide from the front (looking along -z) and from the top, square from the side.
    bar = box(4, 1, 1)
    for name, wide in (("front", True), ("top", True), ("side", False)):
        out = tmp_path / f"{name}.png"
        hmira.render(bar, out, view=name, size=(400, 400))
        w, h = extent(mesh_pixels(out))
        ratio = w / h
        assert (ratio > 2.5) if wide else (0.7 < ratio < 1.4), f"{name}: extent {w} x {h}"
    # up=z: the bar stands along z, so from the front (looking along +y) it is tall, not wide.
    tower = box(1, 1, 4)
    out = tmp_path / "tower.png"
    hmira.render(tower, out, view="front", up="z", size=(400, 400))
    w, h = extent(mesh_pixels(out))
    assert h / w > 2.5, f"front, z up: extent {w} x {h}"


def test_render_compare_draws_one_mesh_in_each_half(tmp_path):
    chromium_or_fail()
    out = tmp_path / "pair.png"
    hmira.render(box(1, 1, 1), out, compare=box(1, 1, 1), size=(480, 240))
    mask = mesh_pixels(out)
    left, right = mask[:, :240], mask[:, 240:]
    assert left.mean() > 0.05 and right.mean() > 0.05
    assert not mask[:, 236:244].any(), "the two halves' meshes should not touch the middle"


def without_playwright(monkeypatch):
    """render() then takes Chromium's own --screenshot path (as where Playwright is not installed)."""
    for name in ("playwright", "playwright.sync_api"):
        monkeypatch.setitem(sys.modules, name, None)


def test_render_never_leaves_a_partial_file(tmp_path, monkeypatch):
    out = tmp_path / "keep.png"
    out.write_bytes(b"old")
    monkeypatch.setenv("HMIRA_CHROMIUM", "/bin/false")  # 'runs' but writes no screenshot
    with monkeypatch.context() as patch:
        without_playwright(patch)
        with pytest.raises(RuntimeError, match="exited with 1 without a screenshot"):
            hmira.render(box(1, 1, 1), out)
    if importlib.util.find_spec("playwright") is not None:  # and the Playwright path, where it is installed
        with pytest.raises(RuntimeError, match="failed under Playwright"):
            hmira.render(box(1, 1, 1), out)
    assert out.read_bytes() == b"old"
    assert sorted(os.listdir(tmp_path)) == ["keep.png"]


def test_render_without_playwright_uses_chromium_screenshot(tmp_path, monkeypatch):
    chromium_or_fail()
    without_playwright(monkeypatch)
    out = tmp_path / "cube.png"
    hmira.render(box(1, 1, 1), out, view="front", size=(300, 200))
    w, h = extent(mesh_pixels(out))
    assert mesh_pixels(out).shape == (200, 300) and 0.8 < w / h < 1.25 and 0.1 < mesh_pixels(out).mean() < 0.9


def test_without_the_bundle_view_says_how_to_build_it(monkeypatch, tmp_path):
    monkeypatch.setattr(hmira._core, "_viewer_bundle_available", lambda: False)
    for call in (lambda: hmira.view(box(1, 1, 1)), lambda: hmira.render(box(1, 1, 1), tmp_path / "x.png")):
        with pytest.raises(RuntimeError, match=r"without the viewer bundle: run viewer/build.sh"):
            call()
    assert "run viewer/build.sh" in box(1, 1, 1)._repr_html_()
    assert not (tmp_path / "x.png").exists()


def test_removed_vertices_are_left_out():
    mesh = box(1, 1, 1)
    _, spoke = mesh.make_edge_vertex(mesh.find_halfedge(0, 1), [5.0, 5.0, 5.0])  # a dangling edge far away
    mesh.kill_edge_vertex(spoke)  # ... removed again: its slot stays until collect_garbage
    assert mesh._positions().shape[0] == 9 and mesh.vertex_count == 8
    page = hmira.view(mesh).html
    positions = buffer_of(page, 0, "positions", np.float32).reshape(-1, 3)
    assert positions.shape == (8, 3)
    np.testing.assert_array_equal(positions.max(axis=0), [0.5, 0.5, 0.5])  # the far point is not in the box
    assert scene_of(page)["meshes"][0]["info"]["vertices"] == 8
    assert mesh._positions().shape[0] == 9  # the shown mesh is a compacted copy; this one is untouched
