"""Shared fixtures: where the libcgal-demo data is (HMIRA_TEST_DATA), the C++ CLI to compare
with (HMIRA_CLI), canonical relabelling of meshes, and a small INR volume reader."""
from __future__ import annotations

import gzip
import os
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest


def data_dir() -> Path:
    return Path(os.environ.get("HMIRA_TEST_DATA", "build/test-data"))


@pytest.fixture(scope="session")
def data() -> Path:
    d = data_dir()
    if not (d / "meshes").is_dir():
        pytest.fail(f"libcgal-demo data not found at {d} (set HMIRA_TEST_DATA; scripts/test-data.sh extracts it)")
    return d


@pytest.fixture(scope="session")
def cli() -> str:
    """The hmira CLI binary; the comparisons skip only when HMIRA_CLI is unset."""
    path = os.environ.get("HMIRA_CLI")
    if not path:
        pytest.skip("HMIRA_CLI is not set: no C++ CLI to compare with")
    if not (os.path.isfile(path) and os.access(path, os.X_OK)):
        pytest.fail(f"HMIRA_CLI={path} is not an executable")
    return path


def run_cli(cli: str, *args: str) -> str:
    r = subprocess.run([cli, *map(str, args)], capture_output=True, text=True)
    assert r.returncode == 0, f"hmira {' '.join(map(str, args))} failed: {r.stderr}"
    return r.stdout


def canonical(vertices, faces):
    """Vertices sorted lexicographically, faces renumbered, each rotated to start at its
    smallest index (winding kept), and sorted."""
    v = np.asarray(vertices, dtype=np.float64)
    order = np.lexsort(v.T[::-1])
    rank = np.empty(len(v), dtype=np.int64)
    rank[order] = np.arange(len(v))
    polys = []
    for f in faces:
        f = [int(rank[i]) for i in f]
        k = f.index(min(f))
        polys.append(tuple(f[k:] + f[:k]))
    polys.sort()
    return v[order], polys


def read_inr(path: Path):
    """(volume as an array indexed [x, y, z], spacing) of an INRIMAGE-4 file (.inr or .inr.gz)."""
    raw = gzip.open(path).read() if str(path).endswith(".gz") else path.read_bytes()
    end = raw.index(b"##}\n") + 4
    header = dict(line.split("=", 1) for line in raw[:end].decode().splitlines() if "=" in line)
    dims = [int(header[k]) for k in ("XDIM", "YDIM", "ZDIM")]
    bits = int(header["PIXSIZE"].split()[0])
    kind = header["TYPE"]
    dtype = {("float", 32): "<f4", ("float", 64): "<f8", ("unsigned fixed", 8): "u1", ("unsigned fixed", 16): "<u2",
             ("signed fixed", 16): "<i2"}[(kind, bits)]
    samples = np.frombuffer(raw, dtype=dtype, count=dims[0] * dims[1] * dims[2], offset=end)
    spacing = tuple(float(header.get(k, 1)) for k in ("VX", "VY", "VZ"))
    return samples.reshape(dims, order="F"), spacing


def signed_volume(vertices, faces) -> float:
    a, b, c = (vertices[faces[:, i]] for i in range(3))
    return float(np.einsum("ij,ij->i", a, np.cross(b, c)).sum() / 6.0)
