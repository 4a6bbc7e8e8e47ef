"""hmira.voxelize modes: `centres` against the enclosed volume (divergence theorem, computed
here) and against the CLI's --mode centres, and conservative == surface | centres."""
from __future__ import annotations

import subprocess

import numpy as np
import pytest

import hmira


def enclosed_volume(v, f):
    a, b, c = v[f[:, 0]], v[f[:, 1]], v[f[:, 2]]
    return abs(np.einsum("ij,ij->i", a, np.cross(b, c)).sum() / 6.0)


@pytest.mark.parametrize("name", ["elephant.off", "fandisk.off", "bunny00.off", "armadillo.off"])
def test_centres_count_is_within_half_a_percent_of_the_enclosed_volume_at_256(data, name):
    mesh = hmira.read_mesh(str(data / "meshes" / name))
    v, f = np.asarray(mesh.vertices), np.asarray(mesh.faces)
    grid, origin, pitch = hmira.voxelize(v, f, resolution=256, mode="centres")
    assert grid.dtype == bool
    assert grid.sum() * pitch ** 3 == pytest.approx(enclosed_volume(v, f), rel=0.005)
    conservative, _, _ = hmira.voxelize(v, f, resolution=256, mode="conservative")
    surface, _, _ = hmira.voxelize(v, f, resolution=256, mode="surface")
    assert np.array_equal(conservative, surface | grid)
    assert conservative.sum() > grid.sum()


def test_centres_of_a_box_on_voxel_boundaries_are_exactly_its_voxels():
    # A box whose faces lie on voxel boundaries: its voxels' centres are inside, no other.
    v = np.array([[0, 0, 0], [2, 0, 0], [2, 1, 0], [0, 1, 0], [0, 0, 0.5], [2, 0, 0.5], [2, 1, 0.5], [0, 1, 0.5]], float)
    f = np.array([[0, 2, 1], [0, 3, 2], [4, 5, 6], [4, 6, 7], [0, 1, 5], [0, 5, 4], [1, 2, 6], [1, 6, 5], [2, 3, 7], [2, 7, 6],
                  [3, 0, 4], [3, 4, 7]])
    grid, origin, pitch = hmira.voxelize(v, f, resolution=20, mode="centres", threads=1)
    assert pitch == 0.1
    assert grid.sum() == 20 * 10 * 5
    assert grid[2:22, 2:12, 2:7].all()


def test_centres_matches_the_cli(data, cli, tmp_path):
    path = str(data / "meshes" / "elephant.off")
    grid, _, _ = hmira.voxelize(hmira.read_mesh(path), resolution=48, mode="centres")
    out = str(tmp_path / "c.raw")
    subprocess.run([cli, "voxelize", path, out, "-n", "48", "-q", "--mode", "centres"], check=True)
    raw = np.fromfile(out, dtype=np.uint8).reshape(grid.shape[::-1]).transpose()
    assert np.array_equal(raw.astype(bool), grid)


def test_unknown_mode_names_the_choices():
    v = np.eye(3)
    with pytest.raises(ValueError, match="'conservative', 'centres' or 'surface'"):
        hmira.voxelize(v, [[0, 1, 2]], mode="center")
