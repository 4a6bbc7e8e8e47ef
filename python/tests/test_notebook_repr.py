"""Mesh._repr_html_ in a notebook: the viewer script (three.js and the viewer) goes to the page
once per session, as a global the later frames load, so every later cell carries only its mesh.
The sizes are printed (pytest -s) for the record; the bound checked is on the ratio."""
from __future__ import annotations

import html
import json
import re

import numpy as np
import pytest

import hmira
from hmira import viewer

CUBE_V = [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]]
CUBE_F = [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]]


@pytest.fixture
def fresh_session(monkeypatch):
    if not hmira._core._viewer_bundle_available():
        pytest.fail("hmira was built without the viewer bundle (viewer/build.sh)")
    monkeypatch.setitem(viewer._notebook, "sent", False)


def test_the_script_is_sent_once_and_later_cells_carry_only_their_mesh(fresh_session):
    cube = hmira.Mesh(CUBE_V, CUBE_F)
    x, y, z = np.mgrid[-1:1:30j, -1:1:30j, -1:1:30j]
    ball = hmira.Mesh(*hmira.marching_cubes(np.sqrt(x**2 + y**2 + z**2) - 0.7, 0.0))
    inline_page = len(viewer.iframe(hmira.view(cube).html))  # what every cell carried before
    first, second, third = cube._repr_html_(), cube._repr_html_(), ball._repr_html_()
    bundle = viewer._split_page(hmira.view(cube).html)[1]
    assert len(bundle) > 100_000
    # The first cell defines the global with the very script, once.
    defined = re.match(r"<script>window\.hmiraViewerBundle=(.*?);</script><iframe ", first, re.S)
    assert defined and json.loads(defined.group(1).replace("<\\/", "</")) == bundle
    assert first.count("window.hmiraViewerBundle=") == 1
    # Later cells: no script, only the frame with the mesh and the loader.
    for later in (second, third):
        assert "window.hmiraViewerBundle=" not in later and later.startswith("<iframe ")
        page = html.unescape(re.fullmatch(r'<iframe srcdoc="([^"]*)" [^>]*></iframe>', later, re.S).group(1))
        assert bundle[:2000] not in page and "window.parent.hmiraViewerBundle" in page and "hmira-scene" in page
    assert 'sandbox="allow-scripts allow-same-origin"' in second
    print(f"\nrepr sizes: before {inline_page} B per cell; now first {len(first)} B, later cube {len(second)} B, "
          f"later ball ({ball.face_count} faces) {len(third)} B")
    assert len(second) < 0.05 * inline_page


def test_notebook_script_redefines_the_global_for_a_reopened_notebook(fresh_session):
    script = viewer.notebook_script()
    bundle = viewer._split_page(hmira.view(hmira.Mesh(CUBE_V, CUBE_F)).html)[1]
    assert script.startswith("<script>window.hmiraViewerBundle=") and "</script" not in script[8:-9]
    assert json.loads(script[len("<script>window.hmiraViewerBundle="):-len(";</script>")].replace("<\\/", "</")) == bundle
