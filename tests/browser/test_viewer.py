# tests/browser/test_viewer.py
# `hmira view` in a real browser (Debian's headless Chromium through Playwright): the mesh fills
# a sane part of the frame, nothing logs an error, boundary edges light up exactly when there are
# some, --compare draws one shape per half; plus the page's embedded buffers and the CLI's errors.
#   HMIRA_BIN=build/apps/hmira/hmira python test_viewer.py   (tests/browser/run.sh does this)
import base64
import io
import json
import os
import re
import struct
import subprocess
import sys
import tempfile
import unittest

from PIL import Image

import browser

HMIRA = os.environ.get("HMIRA_BIN", "")
BACKGROUND = (0xF4, 0xF5, 0xF7)  # palette.background in viewer/src/viewer.js


def hmira(*args):
    return subprocess.run([HMIRA, *map(str, args)], capture_output=True, text=True, timeout=120)


def is_background(p):
    return all(abs(a - b) <= 6 for a, b in zip(p[:3], BACKGROUND))


def is_boundary_colour(p):  # palette.boundary 0xff2000, allowing for antialiasing
    return p[0] > 200 and p[1] < 90 and p[2] < 70


def is_non_manifold_colour(p):  # palette.nonManifold 0xff00ff
    return p[0] > 200 and p[1] < 90 and p[2] > 200


def pixels(png):
    image = Image.open(io.BytesIO(png)).convert("RGB")
    return image, list(image.get_flattened_data())


def coverage(png):
    _, data = pixels(png)
    return sum(not is_background(p) for p in data) / len(data)


def count(png, predicate):
    _, data = pixels(png)
    return sum(1 for p in data if predicate(p))


def blobs(png, x0, x1, step=4):
    """Connected groups of non-background pixels in columns [x0, x1), on a grid of `step` pixels,
    ignoring specks of fewer than 4 grid cells."""
    image, data = pixels(png)
    w, h = image.size
    cells = {(x, y) for y in range(0, h, step) for x in range(x0, x1, step) if not is_background(data[y * w + x])}
    seen, groups = set(), 0
    for c in cells:
        if c in seen:
            continue
        stack, size = [c], 0
        seen.add(c)
        while stack:
            x, y = stack.pop()
            size += 1
            for n in ((x + step, y), (x - step, y), (x, y + step), (x, y - step)):
                if n in cells and n not in seen:
                    seen.add(n)
                    stack.append(n)
        groups += size >= 4
    return groups


def read_text(path):
    with open(path, encoding="utf-8") as f:
        return f.read()


def page_buffers(html):
    """The page's scene JSON and its decoded buffers {id: bytes}."""
    text = read_text(html)
    scene = json.loads(re.search(r'<script type="application/json" id="hmira-scene">(.*?)</script>', text, re.S).group(1))
    buffers = {m.group(1): base64.b64decode(m.group(2)) for m in
               re.finditer(r'<script type="application/octet-stream" id="([^"]+)">(.*?)</script>', text, re.S)}
    return scene, buffers


CUBE_OPEN = """v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1
f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 4 8 7 3
"""  # the cube without its x = 0 face: one boundary loop of 4 edges
FIN = """v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nf 1 2 3\nf 2 1 4\nf 1 2 5
"""  # three triangles on the edge 1-2: one non-manifold edge
GREEN_TETRA = """ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z
property uchar red\nproperty uchar green\nproperty uchar blue\nelement face 4\nproperty list uchar int vertex_indices\nend_header
0 0 0 0 200 0\n1 0 0 0 200 0\n0 1 0 0 200 0\n0 0 1 0 200 0\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3
"""


class ViewerTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        if not HMIRA or not os.access(HMIRA, os.X_OK):
            raise RuntimeError(f"HMIRA_BIN={HMIRA!r} is not an executable hmira")
        cls.tmp = tempfile.TemporaryDirectory(prefix="hmira-browser-")
        cls.dir = cls.tmp.name
        cls.browser_context = browser.chromium()
        cls.browser = cls.browser_context.__enter__()

    @classmethod
    def tearDownClass(cls):
        cls.browser_context.__exit__(None, None, None)
        cls.tmp.cleanup()

    def path(self, name):
        return os.path.join(self.dir, name)

    def write(self, name, text):
        with open(self.path(name), "w") as f:
            f.write(text)
        return self.path(name)

    def view(self, *args):
        r = hmira("view", *args)
        self.assertEqual(r.returncode, 0, r.stderr)
        return r

    def open(self, html, fragment=""):
        opened = browser.open_page(self.browser, html, fragment)
        self.addCleanup(opened.page.close)
        return opened

    def assert_no_console_errors(self, opened):
        errors = [text for kind, text in opened.messages if kind == "error"]
        self.assertEqual(errors, [])

    def test_closed_cube_fills_part_of_the_frame_with_no_boundary_colour(self):
        self.assertEqual(hmira("generate", "cube", self.path("cube.obj"), "--quiet").returncode, 0)
        self.view(self.path("cube.obj"))  # default output: cube.html beside it
        opened = self.open(self.path("cube.html"))
        shot = opened.screenshot(hide_ui=True)
        self.assert_no_console_errors(opened)
        self.assertTrue(0.10 <= coverage(shot) <= 0.90, coverage(shot))
        self.assertEqual(count(shot, is_boundary_colour), 0)
        self.assertEqual(count(shot, is_non_manifold_colour), 0)
        info = opened.page.text_content(".hmira-info")
        self.assertIn("V 8   E 12   F 6", info)
        self.assertIn("genus 0   closed", info)

    def test_open_cube_shows_its_boundary_in_the_highlight_colour(self):
        self.view(self.write("open.obj", CUBE_OPEN), self.path("open.html"))
        opened = self.open(self.path("open.html"))
        shot = opened.screenshot(hide_ui=True)
        self.assert_no_console_errors(opened)
        self.assertTrue(0.10 <= coverage(shot) <= 0.90, coverage(shot))
        self.assertGreater(count(shot, is_boundary_colour), 0)
        self.assertIn("open", opened.page.text_content(".hmira-info"))
        # Turning the highlight off leaves no pixel of its colour.
        opened.page.keyboard.press("b")
        opened.page.wait_for_timeout(200)
        self.assertEqual(count(opened.screenshot(hide_ui=True), is_boundary_colour), 0)

    def test_non_manifold_edge_is_highlighted(self):
        self.view(self.write("fin.obj", FIN), self.path("fin.html"))
        opened = self.open(self.path("fin.html"), "view=front")
        shot = opened.screenshot(hide_ui=True)
        self.assert_no_console_errors(opened)
        self.assertGreater(count(shot, is_non_manifold_colour), 0)

    def test_compare_draws_one_shape_in_each_half(self):
        self.assertEqual(hmira("generate", "cube", self.path("a.obj"), "--quiet").returncode, 0)
        self.assertEqual(hmira("extrude", self.path("a.obj"), self.path("b.obj"), "--face", 4, "--distance", 2, "--quiet").returncode, 0)
        self.view(self.path("a.obj"), "--compare", self.path("b.obj"), self.path("ab.html"))
        opened = self.open(self.path("ab.html"))
        shot = opened.screenshot(hide_ui=True)
        self.assert_no_console_errors(opened)
        self.assertEqual(blobs(shot, 0, 400), 1)
        self.assertEqual(blobs(shot, 400, 800), 1)
        self.assertEqual(len(opened.page.query_selector_all(".hmira-info")), 2)

    def test_compare_cameras_are_linked(self):
        self.assertEqual(hmira("generate", "cube", self.path("c.obj"), "--quiet").returncode, 0)
        self.view(self.path("c.obj"), "--compare", self.path("c.obj"), self.path("cc.html"))
        opened = self.open(self.path("cc.html"))
        page = opened.page
        page.mouse.move(200, 300)
        page.mouse.down()
        page.mouse.move(260, 330, steps=5)
        page.mouse.up()
        page.wait_for_timeout(200)
        image, _ = pixels(opened.screenshot(hide_ui=True))
        left, right = image.crop((0, 0, 400, 600)), image.crop((400, 0, 800, 600))
        self.assertEqual(list(left.get_flattened_data()), list(right.get_flattened_data()))  # the same mesh seen by one camera

    def test_shading_and_edge_toggles_change_the_picture(self):
        self.assertEqual(hmira("generate", "icosahedron", self.path("ico.obj"), "--quiet").returncode, 0)
        self.view(self.path("ico.obj"))
        opened = self.open(self.path("ico.html"))
        page = opened.page
        self.assertEqual(page.evaluate("[window.hmiraViewer.state.smooth, window.hmiraViewer.state.edges]"), [False, True])
        flat = opened.screenshot(hide_ui=True)
        for key, state in (("s", "smooth"), ("e", "edges")):
            page.keyboard.press(key)
            page.wait_for_timeout(200)
            self.assertEqual(page.evaluate(f"window.hmiraViewer.state.{state}"), state == "smooth")
            after = opened.screenshot(hide_ui=True)
            self.assertNotEqual(pixels(after)[1], pixels(flat)[1], f"toggling {state} changed nothing")
            flat = after
        self.assert_no_console_errors(opened)

    def test_normals_from_the_file_are_embedded_and_shown_smooth(self):
        self.assertEqual(hmira("mc", "sphere", self.path("sphere.ply"), "-n", 24, "--normals", "--quiet").returncode, 0)
        self.view(self.path("sphere.ply"))
        scene, buffers = page_buffers(self.path("sphere.html"))
        vertices = scene["meshes"][0]["info"]["vertices"]
        self.assertEqual(len(buffers["hmira-m0-normals"]), vertices * 3 * 4)
        normals = struct.unpack(f"<{3 * vertices}f", buffers["hmira-m0-normals"])
        for i in range(0, len(normals), 3):
            self.assertAlmostEqual(normals[i] ** 2 + normals[i + 1] ** 2 + normals[i + 2] ** 2, 1.0, places=3)
        opened = self.open(self.path("sphere.html"))
        self.assertTrue(opened.page.evaluate("window.hmiraViewer.state.smooth"))
        shot = opened.screenshot(hide_ui=True)
        self.assert_no_console_errors(opened)
        self.assertTrue(0.10 <= coverage(shot) <= 0.90, coverage(shot))
        self.assertEqual(count(shot, is_boundary_colour), 0)

    def test_vertex_colours_are_shown(self):
        self.view(self.write("green.ply", GREEN_TETRA), self.path("green.html"))
        opened = self.open(self.path("green.html"))
        shot = opened.screenshot(hide_ui=True)
        self.assert_no_console_errors(opened)
        self.assertGreater(count(shot, lambda p: p[1] > p[0] + 60 and p[1] > p[2] + 60), 1000)

    def test_vertices_without_faces_are_points(self):
        self.view(self.write("points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 1\n"), self.path("points.html"))
        opened = self.open(self.path("points.html"))
        shot = opened.screenshot(hide_ui=True)
        self.assert_no_console_errors(opened)
        self.assertGreater(count(shot, lambda p: not is_background(p)), 4 * 4)
        self.assertIn("points", opened.page.text_content(".hmira-info"))

    def test_page_embeds_binary_buffers_for_each_polygon_edge_once(self):
        self.view(self.write("open2.obj", CUBE_OPEN), self.path("open2.html"))
        scene, buffers = page_buffers(self.path("open2.html"))
        self.assertEqual(scene["meshes"][0]["info"], {"vertices": 8, "edges": 12, "faces": 5, "genus": 0, "closed": False,
                                                      "boundary_edges": 4, "non_manifold_edges": 0})
        self.assertEqual(len(buffers["hmira-m0-positions"]), 8 * 3 * 4)
        self.assertEqual(len(buffers["hmira-m0-triangles"]), 10 * 3 * 4)  # 5 quads, 2 triangles each
        self.assertEqual(sum(bin(b).count("1") for b in buffers["hmira-m0-edge_mask"]), 12)  # no fan diagonal
        boundary = struct.unpack("<8I", buffers["hmira-m0-boundary"])
        self.assertEqual(sorted(tuple(sorted(boundary[i:i + 2])) for i in range(0, 8, 2)), [(0, 3), (0, 4), (3, 7), (4, 7)])
        self.assertNotIn("http", re.sub(r"<script>.*?</script>", "", read_text(self.path("open2.html")), flags=re.S))

    def test_page_fetches_nothing(self):
        self.assertEqual(hmira("generate", "cube", self.path("n.obj"), "--quiet").returncode, 0)
        self.view(self.path("n.obj"))
        page = self.browser.new_page()
        self.addCleanup(page.close)
        requests = []
        page.on("request", lambda r: requests.append(r.url))
        page.goto("file://" + self.path("n.html"))
        page.wait_for_function("window.hmiraRenderDone === true", timeout=60000)
        self.assertEqual(requests, ["file://" + self.path("n.html")])

    def test_file_without_vertices_is_invalid_input(self):
        r = hmira("view", self.write("empty.obj", "# nothing\n"), self.path("empty.html"))
        self.assertEqual(r.returncode, 1)
        self.assertIn("empty.obj: no vertices to show", r.stderr)
        self.assertFalse(os.path.exists(self.path("empty.html")))

    def test_unreadable_file_is_an_io_error_and_writes_nothing(self):
        r = hmira("view", self.path("missing.obj"), self.path("missing.html"))
        self.assertEqual(r.returncode, 3, r.stderr)
        self.assertEqual(r.stderr.count("\n"), 1)
        self.assertFalse(os.path.exists(self.path("missing.html")))
        r = hmira("view", self.write("good.obj", CUBE_OPEN), "--compare", self.path("missing.obj"), self.path("x.html"))
        self.assertEqual(r.returncode, 3, r.stderr)
        self.assertFalse(os.path.exists(self.path("x.html")))

    def test_failed_write_leaves_the_existing_page_untouched(self):
        target = self.write("keep.html", "old page\n")
        r = hmira("view", self.write("bad.obj", "v 0 0 0\nf 1 2 3\n"), target)
        self.assertNotEqual(r.returncode, 0)
        self.assertEqual(read_text(target), "old page\n")
        r = hmira("view", self.write("ok.obj", CUBE_OPEN), os.path.join(self.dir, "no-such-folder", "x.html"))
        self.assertEqual(r.returncode, 3, r.stderr)
        self.assertEqual([f for f in os.listdir(self.dir) if f.startswith(".tmp-")], [])


if __name__ == "__main__":
    # A skipped test is a failed one here: the browser tests must really run in CI.
    result = unittest.main(exit=False, verbosity=2).result
    if result.skipped:
        print(f"{len(result.skipped)} test(s) skipped: a skip counts as a failure", file=sys.stderr)
    sys.exit(0 if result.wasSuccessful() and not result.skipped and result.testsRun > 0 else 1)
