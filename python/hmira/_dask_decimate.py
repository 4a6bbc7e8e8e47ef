"""Out-of-core quadric decimation on Dask, block by block, welded exactly (hmira.dask.decimate and
``hmira.dask.marching_cubes(..., decimate=...)``).

The blocks are a fixed grid in space (an origin and a block size), never the input's Dask chunks,
so the result is the same, bit for bit, for every chunking and worker count.

Pass 1: every block decimates its own triangles. The vertices it shares with another block are
locked, and the triangles of other blocks around them come along as a halo whose vertices are all
locked: the halo never changes, it only adds its planes to the quadrics of the shared vertices, so a
collapse onto the seam is priced as it would be on the whole mesh. Marching cubes makes its own
halo: each block is meshed with one more cube on every side. The vertices next to the locked ones
stay too (_next_to), and the interior goes to the ratio of the triangles that do not touch them.

Pass 2: the grid is offset by half a block, so the seams of pass 1 lie inside the new blocks. A
triangle goes to the offset block holding its centroid clamped to its pass-1 block, so every
pass-1 block feeds the eight offset blocks it overlaps, and an offset block reads eight pass-1
results. Each vertex carries the quadric pass 1 left it (the planes of the full-resolution faces
it stands for), and pass 2 starts from those quadrics instead of the planes of the coarse faces:
the error of pass 1 is not forgotten, so pass 2 decimates the whole offset block, seams and
interiors, as one decimation of the whole mesh would go on: towards the ratio of its input
triangles, and no further than the error pass 1 reached in the blocks around it.
A vertex is free in pass 2 when all its triangles went to one offset block, and a seam vertex of
pass 1 only in the offset block holding its position (the one that sees every pass-1 block around
it, which holds while input triangles are under half a block across; hmira.dask.decimate checks it).

Every vertex keeps an integer key (its marching-cubes grid edge, or its input index), decimation
keeps the keys of the survivors, and a vertex two blocks both output was locked in both, so its
positions are equal: the blocks weld by key, exactly.
"""
from __future__ import annotations

import os
import tempfile
from typing import Any, Optional, Sequence, Union

import numpy as np

from . import _core

_OPTION_NAMES = ("max_normal_angle", "max_aspect_ratio", "min_angle", "area_weighted", "fix_boundary", "feature_angle")


def _options(decimate: Any) -> dict:
    """{'ratio', 'max_error', and the decimation options} from a ratio or a dict."""
    if isinstance(decimate, dict):
        o = dict(decimate)
    else:
        o = {"target_ratio": decimate}
    ratio = o.pop("target_ratio", o.pop("ratio", None))
    max_error = o.pop("max_error", None)
    if ratio is None and max_error is None:
        raise ValueError("hmira.dask.decimate: give target_ratio (a number in [0, 1]) or max_error")
    if ratio is not None and not 0 <= float(ratio) <= 1:
        raise ValueError(f"hmira.dask.decimate: target_ratio must lie in [0, 1], got {ratio}")
    unknown = set(o) - set(_OPTION_NAMES)
    if unknown:
        raise ValueError(f"hmira.dask.decimate: unknown options {sorted(unknown)} (supported: target_ratio, max_error, "
                         f"{', '.join(_OPTION_NAMES)})")
    return {"ratio": None if ratio is None else float(ratio),
            "max_error": None if max_error is None else float(max_error),
            "options": o}


def _target(count: int, opts: dict) -> int:
    ratio = opts["ratio"]
    return 0 if ratio is None else int(np.floor(ratio * count + 0.5))


def _fans(triangles, nv):
    """For each corner (3 f + c) of the triangles, a label of the fan of faces it lies in around its
    vertex: corners of one vertex whose triangles share an edge at it have one label."""
    t = np.asarray(triangles, dtype=np.int64)
    v = t.ravel()
    keys = np.concatenate([v * nv + np.roll(t, -1, axis=1).ravel(), v * nv + np.roll(t, 1, axis=1).ravel()])
    ids = np.concatenate([np.arange(len(v))] * 2)
    order = np.argsort(keys, kind="stable")
    k, i = keys[order], ids[order]
    same = k[1:] == k[:-1]
    a, b = i[:-1][same], i[1:][same]
    label = np.arange(len(v))
    while True:  # the smallest corner id spreads through each fan (a fan has a few corners)
        m = np.minimum(label[a], label[b])
        new = label.copy()
        np.minimum.at(new, a, m)
        np.minimum.at(new, b, m)
        new = new[new]
        if np.array_equal(new, label):
            return label
        label = new


def _split_fans(positions, triangles, locked):
    """A block's triangles where a vertex joins separate fans of faces (possible only where the
    block's triangles meet others, so the vertex is locked) get one copy of it per fan, which
    the halfedge mesh needs; returns the new arrays and each row's original row."""
    nv = len(positions)
    label = _fans(triangles, nv)
    v = np.asarray(triangles, dtype=np.int64).ravel()
    roots = np.flatnonzero(label == np.arange(len(v)))  # one corner per fan
    fans_per_vertex = np.bincount(v[roots], minlength=nv)
    if len(v) == 0 or fans_per_vertex.max() <= 1:
        return positions, triangles, locked, np.arange(nv)
    # The first fan of each vertex keeps its row; every further fan gets a new row.
    first = np.full(nv, len(v))
    np.minimum.at(first, v[roots], roots)
    extra = roots[first[v[roots]] != roots]
    row_of_root = np.empty(len(v), dtype=np.int64)
    row_of_root[roots] = v[roots]
    row_of_root[extra] = nv + np.arange(len(extra))
    origin = np.concatenate([np.arange(nv), v[extra]])
    if not np.all(np.asarray(locked)[v[extra]]):
        raise ValueError("hmira.dask.decimate: a vertex inside a block joins separate fans of faces (the input is "
                         "not a 2-manifold)")
    tris = row_of_root[label].reshape(-1, 3).astype(np.int32)
    return positions[origin], tris, np.asarray(locked)[origin], origin


def _decimate_block(positions, triangles, locked, own, target, opts, quadrics=None):
    """Decimates a block (_core._decimate_block after _split_fans): (positions, triangles, kept
    input rows, error, quadrics of the kept rows). With `quadrics` (10 per row), the vertices start
    from them instead of the planes of the triangles."""
    positions, triangles, locked, origin = _split_fans(np.asarray(positions, dtype=np.float64), triangles, locked)
    seeds = None if quadrics is None else np.ascontiguousarray(np.asarray(quadrics, dtype=np.float64)[origin])
    pos, tris, kept, error, q = _core._decimate_block(
        np.ascontiguousarray(positions), np.ascontiguousarray(triangles, dtype=np.int32),
        np.ascontiguousarray(locked, dtype=bool), own=int(own), target_faces=int(target) + (len(triangles) - int(own)),
        max_error=opts["max_error"], quadrics=seeds, **opts["options"])
    rows = origin[kept]
    if len(rows) and np.any(rows[1:] <= rows[:-1]):  # copies of one vertex (locked: one position) join again
        uniq, first, inverse = np.unique(rows, return_index=True, return_inverse=True)
        # Each copy holds the planes of its own fan (on top of the seed it started from, when given).
        joined = np.zeros((len(uniq), 10))
        np.add.at(joined, inverse, q)
        if quadrics is not None:
            joined -= (np.bincount(inverse, minlength=len(uniq)) - 1)[:, None] * np.asarray(quadrics)[uniq]
        return pos[first], inverse[tris].astype(np.int32), uniq, error, joined
    return pos, tris, rows, error, q


def _on_boundary(triangles, n):
    """The vertices on an edge of only one of the triangles."""
    t = np.asarray(triangles, dtype=np.int64)
    e = np.sort(np.concatenate([t[:, [0, 1]], t[:, [1, 2]], t[:, [2, 0]]]), axis=1)
    key = e[:, 0] * n + e[:, 1]
    u, c = np.unique(key, return_counts=True)
    out = np.zeros(n, dtype=bool)
    once = u[c == 1]
    out[once // n] = True
    out[once % n] = True
    return out


def _next_to(held, triangles):
    """The vertices that share a triangle with a vertex in `held`.

    Blocks decimate side by side, each with the vertices it shares with others locked. A collapse
    onto a locked vertex would give it new edges, and two blocks could each add the same one (the
    link condition of each sees only the other's triangles before it changed them). So the
    vertices next to a locked one stay too: no collapse ever reaches a vertex another block sees,
    and no two blocks ever change the same ring."""
    out = np.zeros(len(held), dtype=bool)
    out[triangles[held[triangles].any(axis=1)].ravel()] = True
    return out


class _Grid:
    """The fixed block grid: block coordinates g = (p - origin) / size per axis; pass-1 block
    floor(g), pass-2 (offset) block floor(g + 1/2)."""

    def __init__(self, origin, size, shape):
        self.origin = np.asarray(origin, dtype=np.float64)
        self.size = np.asarray(size, dtype=np.float64)
        self.shape = tuple(int(s) for s in shape)  # pass-1 blocks per axis
        self.shifted = tuple(s + 1 for s in self.shape)  # pass-2 blocks per axis

    def coords(self, p):
        return (np.asarray(p, dtype=np.float64) - self.origin) / self.size


def _pass1(positions, keys, triangles, own, index, grid, opts):
    """Decimates one pass-1 block (its `own` first triangles, a locked halo after them) and splits
    the result for the eight offset blocks it overlaps: a list of 8 parts (None when empty), each
    (positions, keys, own triangles, halo triangles, free flags, quadrics), the input triangle
    count of each of the eight (the pass-2 targets), and the error pass 1 reached here."""
    index = np.asarray(index, dtype=np.int64)
    shared_before = np.zeros(len(positions), dtype=bool)
    shared_before[triangles[own:].ravel()] = True
    locked = shared_before | _next_to(shared_before, triangles[:own])
    lo, hi = index.astype(np.float64), index.astype(np.float64) + 1

    def corner_of(p, tris):
        """The offset block (0..7 among the eight this block overlaps) of each triangle."""
        if len(tris) == 0:
            return np.zeros(0, dtype=np.int64)
        c = grid.coords(p[tris].sum(axis=1) / 3.0)
        c = np.clip(c, lo, hi)
        s = np.floor(c + 0.5).astype(np.int64) - index  # 0 or 1 per axis
        s = np.clip(s, 0, 1)
        return (s[:, 0] * 2 + s[:, 1]) * 2 + s[:, 2]

    counts = np.bincount(corner_of(positions, triangles[:own]), minlength=8)
    if own:
        # The triangles at the seams stay for pass 2: the target is the ratio of the others, so
        # that the interior is not decimated further to make up for them.
        # So are the triangles at a boundary of the mesh (kept in place, as in-memory decimation keeps them).
        held = locked | _on_boundary(triangles, len(positions)) if opts["options"].get("fix_boundary", True) else locked
        seam = int(held[triangles[:own]].any(axis=1).sum())
        pos, tris, kept, error, quadrics = _decimate_block(positions, triangles, locked, own,
                                                           seam + _target(own - seam, opts), opts)
    else:
        pos, tris, kept = np.zeros((0, 3)), np.zeros((0, 3), dtype=np.int32), np.zeros(0, dtype=np.int64)
        quadrics, error = np.zeros((0, 10)), 0.0
    k = np.asarray(keys)[kept]
    face = shared_before[kept]  # vertices other blocks share
    corner = corner_of(pos, tris)
    home = np.floor(grid.coords(pos) + 0.5).astype(np.int64) - index  # the offset block holding each vertex
    home_ok = np.all((home >= 0) & (home <= 1), axis=1)
    home_c = np.where(home_ok, (np.clip(home[:, 0], 0, 1) * 2 + np.clip(home[:, 1], 0, 1)) * 2
                      + np.clip(home[:, 2], 0, 1), -1)
    # Per vertex, the offset blocks its triangles here go to (a bit each).
    bits = np.zeros(len(pos), dtype=np.int64)
    for c in range(3):
        np.bitwise_or.at(bits, tris[:, c], np.left_shift(1, corner))
    parts = []
    for b in range(8):
        mine = corner == b
        own_t = tris[mine]
        # Vertices of interest: used by the triangles going to b, or shared with other blocks and held by b.
        interest = np.zeros(len(pos), dtype=bool)
        interest[own_t.ravel()] = True
        interest |= face & (home_c == b)
        if not interest.any():
            parts.append(None)
            continue
        halo_t = tris[~mine & interest[tris].any(axis=1)]
        used = np.zeros(len(pos), dtype=bool)
        used[own_t.ravel()] = True
        used[halo_t.ravel()] = True
        rows = np.flatnonzero(used)
        remap = np.full(len(pos), -1, dtype=np.int64)
        remap[rows] = np.arange(len(rows))
        free = (bits[rows] == (1 << b)) & (~face[rows] | (home_c[rows] == b))
        parts.append((pos[rows], k[rows], remap[own_t].astype(np.int32), remap[halo_t].astype(np.int32), free,
                      quadrics[rows]))
    return parts, counts, error


def _pass2(parts, count, opts, error=None):
    """Merges the pass-1 parts of one offset block by key and decimates it: (positions, keys,
    triangles, shared flags), the shared vertices being those other offset blocks also output."""
    parts = [p for p in parts if p is not None]
    empty = (np.zeros((0, 3)), np.zeros(0, dtype=np.uint64), np.zeros((0, 3), dtype=np.int32), np.zeros(0, dtype=bool))
    if not parts:
        return empty
    keys = np.concatenate([p[1] for p in parts])
    uniq, first, inverse = np.unique(keys, return_index=True, return_inverse=True)
    positions = np.concatenate([p[0] for p in parts])[first]
    quadrics = np.concatenate([p[5] for p in parts])[first]
    free = np.ones(len(uniq), dtype=bool)
    np.logical_and.at(free, inverse, np.concatenate([p[4] for p in parts]))
    starts = np.cumsum([0] + [len(p[1]) for p in parts])
    own = [inverse[starts[i]:starts[i + 1]][p[2]] for i, p in enumerate(parts)]
    halo = [inverse[starts[i]:starts[i + 1]][p[3]] for i, p in enumerate(parts)]
    own = np.concatenate(own).reshape(-1, 3)
    halo = np.concatenate(halo).reshape(-1, 3)
    if len(own) == 0:
        return empty
    triangles = np.concatenate([own, halo]).astype(np.int32)
    free &= ~_next_to(~free, triangles)
    # Every vertex goes on from the quadric pass 1 left it (the planes of the full-resolution
    # faces it stands for), so the whole block decimates towards the ratio of its input triangles,
    # cheapest first, up to the error pass 1 reached around it (`error`, for a ratio): the seams
    # end as coarse as the interiors, and no block is forced past that error to make up for the
    # vertices it must keep.
    o = opts
    if error is not None and opts["ratio"] is not None:
        o = dict(opts, max_error=error if opts["max_error"] is None else min(error, opts["max_error"]))
    pos, tris, kept, _error, _q = _decimate_block(positions, triangles, ~free, len(own), _target(count, opts), o,
                                                  quadrics)
    return pos, uniq[kept], tris, ~free[kept]


class _Welder:
    """Welds blocks of (positions, keys, triangles, shared) in order into global ids: a vertex gets
    the next id at its first appearance; only shared keys are remembered."""

    def __init__(self):
        self.ids = {}
        self.n_vertices = 0

    def add(self, positions, keys, triangles, shared):
        ids = np.empty(len(keys), dtype=np.int64)
        new = np.ones(len(keys), dtype=bool)
        for row in np.flatnonzero(shared):
            got = self.ids.get(int(keys[row]))
            if got is not None:
                ids[row] = got
                new[row] = False
        rows = np.flatnonzero(new)
        ids[rows] = self.n_vertices + np.arange(len(rows))
        self.n_vertices += len(rows)
        for row in rows[shared[rows]]:
            self.ids[int(keys[row])] = int(ids[row])
        return positions[rows], ids[triangles] if len(triangles) else np.zeros((0, 3), dtype=np.int64)


def _results_in_order(tasks):
    """The tasks' results in order, a few at a time: hmira.dask's scheduling, with a window of two
    tasks per core on the local schedulers."""
    from . import dask as _hd  # imported here: hmira.dask imports this module at its end

    return _hd._results_in_order(tasks, 2 * (os.cpu_count() or 1))


def _assemble(tasks, out, zarr_out):
    """Welds the offset blocks' results, in order: (vertices, faces), or streamed to a PLY and/or
    a zarr group (then None)."""
    welder = _Welder()
    if out is None and zarr_out is None:
        vs, fs = [], []
        for r in _results_in_order(tasks):
            v, f = welder.add(*r)
            vs.append(v)
            fs.append(f)
        vertices = np.concatenate(vs) if vs else np.zeros((0, 3))
        faces = np.concatenate(fs).astype(np.int32) if fs else np.zeros((0, 3), dtype=np.int32)
        return vertices, faces
    sinks = []
    if out is not None:
        sinks.append(_PlySink(os.fspath(out)))
    if zarr_out is not None:
        sinks.append(_ZarrSink(zarr_out))
    try:
        for r in _results_in_order(tasks):
            v, f = welder.add(*r)
            for s in sinks:
                s.add(v, f)
        for s in sinks:
            s.finish(welder.n_vertices)
    finally:
        for s in sinks:
            s.close()
    return None


class _PlySink:
    """Binary little-endian PLY written in one pass of the blocks: vertices and faces into two
    temporary files, then the header and both behind it, renamed into place."""

    def __init__(self, path):
        self.path = path
        directory = os.path.dirname(os.path.abspath(path))
        self.directory = directory
        self.vfile = tempfile.NamedTemporaryFile(dir=directory, prefix=".hmira-vertices-", delete=False)
        self.ffile = tempfile.NamedTemporaryFile(dir=directory, prefix=".hmira-faces-", delete=False)
        self.n_faces = 0
        self.final = None

    def add(self, v, f):
        self.vfile.write(np.ascontiguousarray(v, dtype="<f8").tobytes())
        rec = np.empty(len(f), dtype=np.dtype([("n", "u1"), ("v", "<i4", (3,))]))
        rec["n"] = 3
        rec["v"] = f
        self.ffile.write(rec.tobytes())
        self.n_faces += len(f)

    def finish(self, n_vertices):
        self.vfile.close()
        self.ffile.close()
        header = ("ply\nformat binary_little_endian 1.0\ncomment hmira.dask decimated\n"
                  f"element vertex {n_vertices}\nproperty double x\nproperty double y\nproperty double z\n"
                  f"element face {self.n_faces}\nproperty list uchar int vertex_indices\nend_header\n").encode()
        fd, self.final = tempfile.mkstemp(dir=self.directory, prefix=".hmira-ply-")
        with os.fdopen(fd, "wb") as dst:
            dst.write(header)
            for part in (self.vfile.name, self.ffile.name):
                with open(part, "rb") as src:
                    while True:
                        buf = src.read(1 << 24)
                        if not buf:
                            break
                        dst.write(buf)
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(self.final, 0o666 & ~umask)
        os.replace(self.final, self.path)
        self.final = None

    def close(self):
        for f in (self.vfile, self.ffile):
            f.close()
            if os.path.exists(f.name):
                os.unlink(f.name)
        if self.final is not None and os.path.exists(self.final):
            os.unlink(self.final)


class _ZarrSink:
    """A zarr group with 'vertices' (n, 3) float64 and 'faces' (m, 3) int32, appended block by block."""

    def __init__(self, store):
        import zarr

        self.group = zarr.open_group(store, mode="w")
        self.vertices = self.group.create_array("vertices", shape=(0, 3), chunks=(1 << 18, 3), dtype="f8")
        self.faces = self.group.create_array("faces", shape=(0, 3), chunks=(1 << 18, 3), dtype="i4")

    def add(self, v, f):
        if len(v):
            self.vertices.append(np.asarray(v, dtype=np.float64))
        if len(f):
            self.faces.append(np.asarray(f, dtype=np.int32))

    def finish(self, n_vertices):
        self.group.attrs["vertices"] = int(n_vertices)
        self.group.attrs["faces"] = int(self.faces.shape[0])

    def close(self):
        pass


def _pass2_tasks(pass1, grid, opts, label):
    """One delayed per offset block, in C order, reading the parts of the (up to) eight pass-1
    blocks it overlaps; pass1 maps a pass-1 block index to its delayed (parts, counts)."""
    from dask.base import tokenize
    from dask.delayed import Delayed
    from dask.highlevelgraph import HighLevelGraph

    deps = list(pass1.values())
    name = label + tokenize([d.key for d in deps], opts)
    graph = {}
    for s in np.ndindex(*grid.shifted):
        keys, corners = [], []
        for step in np.ndindex(2, 2, 2):
            d = pass1.get(tuple(si - 1 + st for si, st in zip(s, step)))
            if d is not None:
                keys.append(d.key)
                corners.append(((1 - step[0]) * 2 + (1 - step[1])) * 2 + (1 - step[2]))
        if keys:
            graph[(name,) + tuple(int(x) for x in s)] = (_pass2_of, keys, corners, opts)
    hlg = HighLevelGraph.from_collections(name, graph, dependencies=deps)
    return [Delayed(key, hlg, layer=name) for key in graph]


def _pass2_of(results, corners, opts):
    parts = [r[0][c] for r, c in zip(results, corners)]
    count = int(sum(r[1][c] for r, c in zip(results, corners)))
    # The error level pass 1 reached around this block, weighted by the input triangles each
    # pass-1 block sends here.
    weights = [float(r[1][c]) for r, c in zip(results, corners)]
    error = sum(w * r[2] for w, r in zip(weights, results)) / sum(weights) if sum(weights) else 0.0
    return _pass2(parts, count, opts, error)


# ---------------------------------------------------------------- marching cubes, then decimation


def _mc_pass1(samples, lo, block, index, whole, iso, spacing, origin, inside, grid, opts):
    """Marching cubes of one pass-1 block with one more cube on every side (the halo), then _pass1."""
    positions, keys, triangles, cubes = _core._marching_cubes_block(
        [samples], float(iso), steps=[[0, 0, 0]], core=list(samples.shape), offset=list(lo), whole=list(whole),
        spacing=list(spacing), origin=list(origin), inside=inside, threads=1)
    nz, ny, nx = whole
    ci = cubes % nx
    cj = (cubes // nx) % ny
    ck = cubes // (nx * ny)
    b0 = [index[a] * block for a in range(3)]
    own = ((ck >= b0[0]) & (ck < b0[0] + block) & (cj >= b0[1]) & (cj < b0[1] + block) & (ci >= b0[2])
           & (ci < b0[2] + block))
    used = np.zeros(len(positions), dtype=bool)
    used[triangles[own].ravel()] = True
    halo = ~own & used[triangles].any(axis=1)
    tris = np.concatenate([triangles[own], triangles[halo]])
    rows, local = np.unique(tris.ravel(), return_inverse=True)
    return _pass1(positions[rows], keys[rows], local.reshape(-1, 3).astype(np.int32), int(own.sum()), index, grid, opts)


def _sample_block(darr, lo, hi):
    """The samples [lo, hi) of a dask array as one numpy array (a delayed)."""
    import dask

    piece = darr[lo[0]:hi[0], lo[1]:hi[1], lo[2]:hi[2]]
    return dask.delayed(np.ascontiguousarray)(piece)


def marching_cubes_decimated(darr, iso, decimate, *, block=128, spacing=(1.0, 1.0, 1.0), origin=(0.0, 0.0, 0.0),
                             inside="below", out=None, zarr=None):
    """See hmira.dask.marching_cubes(..., decimate=...)."""
    import dask
    import dask.array as da

    opts = _options(decimate)
    darr = da.asarray(darr)
    if darr.ndim != 3 or any(s < 2 for s in darr.shape):
        raise ValueError(f"hmira.dask.marching_cubes: needs a 3-d array of at least 2 samples per axis, "
                         f"got {darr.shape}")
    block = int(block)
    if block < 2:
        raise ValueError(f"hmira.dask.marching_cubes: block must be at least 2 cubes, got {block}")
    spacing = tuple(float(s) for s in spacing)
    origin = tuple(float(o) for o in origin)
    whole = tuple(int(s) for s in darr.shape)
    cubes = [s - 1 for s in whole]
    shape = tuple(-(-c // block) for c in cubes)
    grid = _Grid(origin, [block * s for s in spacing], shape)
    pass1 = {}
    for index in np.ndindex(*shape):
        lo = [max(index[a] * block - 1, 0) for a in range(3)]
        hi = [min((index[a] + 1) * block + 2, whole[a]) for a in range(3)]
        samples = _sample_block(darr, lo, hi)
        pass1[index] = dask.delayed(_mc_pass1, pure=True)(samples, lo, block, list(index), whole, float(iso),
                                                                      spacing, origin, inside, grid, opts)
    tasks = _pass2_tasks(pass1, grid, opts, "hmira-mc-decimate-")
    return _assemble(tasks, out, zarr)


# ---------------------------------------------------------------- an existing mesh


def _mesh_arrays(mesh):
    """(vertices, faces) of a Mesh, a (V, F) pair or a PLY path (memory-mapped when binary)."""
    if isinstance(mesh, (str, os.PathLike)):
        from . import read_mesh

        m = read_mesh(os.fspath(mesh), repair=False)
        return np.asarray(m.vertices, dtype=np.float64), np.asarray(m.faces, dtype=np.int64)
    if hasattr(mesh, "vertices") and hasattr(mesh, "faces"):
        return np.asarray(mesh.vertices, dtype=np.float64), np.asarray(mesh.faces, dtype=np.int64)
    v, f = mesh
    return np.asarray(v, dtype=np.float64), np.asarray(f, dtype=np.int64)


def _split_blocks(vertices, faces, grid):
    """Pass-1 blocks of an existing mesh: per block index, (positions, keys, triangles, own count)."""
    centroid = grid.coords(vertices[faces].sum(axis=1) / 3.0)
    bidx = np.clip(np.floor(centroid).astype(np.int64), 0, np.asarray(grid.shape) - 1)
    lin = np.ravel_multi_index(bidx.T, grid.shape)
    # Vertices used by more than one block, and the blocks around each such vertex.
    nv = len(vertices)
    lo = np.full(nv, np.iinfo(np.int64).max)
    hi = np.full(nv, -1)
    for c in range(3):
        np.minimum.at(lo, faces[:, c], lin)
        np.maximum.at(hi, faces[:, c], lin)
    shared = (lo != hi) & (hi >= 0)
    seam = shared[faces].any(axis=1)
    seam_f = np.flatnonzero(seam)
    # (vertex, block) pairs of the seam faces' corners, then for each seam face and each block
    # around one of its shared corners other than its own: a halo entry.
    corners_v = faces[seam_f].ravel()
    corners_b = np.repeat(lin[seam_f], 3)
    keep = shared[corners_v]
    pairs = np.unique(np.stack([corners_v[keep], corners_b[keep]], axis=1), axis=0)
    order_v = pairs[:, 0]
    halo_face, halo_block = [], []
    starts = np.searchsorted(order_v, faces[seam_f].ravel(), side="left")
    ends = np.searchsorted(order_v, faces[seam_f].ravel(), side="right")
    face_of_corner = np.repeat(seam_f, 3)
    for s, e, f in zip(starts, ends, face_of_corner):
        for b in pairs[s:e, 1]:
            if b != lin[f]:
                halo_face.append(f)
                halo_block.append(b)
    halo = np.unique(np.array([halo_block, halo_face], dtype=np.int64).reshape(2, -1).T, axis=0)
    order = np.argsort(lin, kind="stable")
    bounds = np.searchsorted(lin[order], np.arange(np.prod(grid.shape) + 1))
    hb = np.searchsorted(halo[:, 0], np.arange(np.prod(grid.shape) + 1))
    for b in range(int(np.prod(grid.shape))):
        own = order[bounds[b]:bounds[b + 1]]
        if len(own) == 0:
            continue
        hf = halo[hb[b]:hb[b + 1], 1]
        tris = faces[np.concatenate([own, hf])]
        rows, local = np.unique(tris.ravel(), return_inverse=True)
        yield np.unravel_index(b, grid.shape), (vertices[rows], rows.astype(np.uint64),
                                                local.reshape(-1, 3).astype(np.int32), len(own))


def decimate(mesh: Any, decimate: Union[float, dict], *, block_size: Optional[float] = None, blocks: int = 8,
             out: Optional[str] = None, zarr: Any = None):
    """Quadric decimation of a large triangle mesh on Dask, block by block, welded exactly.

    Parameters
    ----------
    mesh : hmira.Mesh, (vertices, faces) or a path to a mesh file
        Triangles only.
    decimate : float or dict
        The target ratio of faces, or a dict with ``target_ratio`` and/or ``max_error`` and any
        of ``max_normal_angle``, ``max_aspect_ratio``, ``min_angle``, ``area_weighted``,
        ``fix_boundary``, ``feature_angle`` (as :meth:`hmira.Mesh.decimate`).
    block_size : float, keyword-only
        The edge of a block in model units (default: the longest side of the bounding box over
        ``blocks``). Every triangle must be under half a block across.
    out, zarr : keyword-only
        Stream the result to this PLY path and/or zarr store (a group with ``vertices`` and
        ``faces``) and return None; otherwise return ``(vertices, faces)``.

    Returns
    -------
    vertices : ndarray of float64, shape (n, 3); faces : ndarray of int32, shape (m, 3)
        The same for every scheduler and worker count.

    Examples
    --------
    >>> import numpy as np, hmira, hmira.dask
    >>> x = np.linspace(-1, 1, 24)
    >>> v, f = hmira.marching_cubes(x[:, None, None] ** 2 + x[None, :, None] ** 2 + x ** 2, 0.5)
    >>> dv, df = hmira.dask.decimate((v, f), 0.25, blocks=2)
    >>> bool(len(df) < len(f) / 2)
    True
    """
    import dask

    opts = _options(decimate)
    vertices, faces = _mesh_arrays(mesh)
    if faces.ndim != 2 or faces.shape[1] != 3:
        raise ValueError("hmira.dask.decimate: needs triangles, an (m, 3) face array")
    lo = vertices.min(axis=0)
    ext = vertices.max(axis=0) - lo
    if block_size is None:
        block_size = float(ext.max()) / max(int(blocks), 1) or 1.0
    block_size = float(block_size)
    if not block_size > 0:
        raise ValueError(f"hmira.dask.decimate: block_size must be positive, got {block_size}")
    across = np.abs(vertices[faces] - vertices[faces].mean(axis=1, keepdims=True)).max() if len(faces) else 0.0
    if across >= block_size / 2:
        raise ValueError(f"hmira.dask.decimate: a triangle is {across:g} from its centroid, not under half a block "
                         f"({block_size / 2:g}); choose a larger block_size")
    shape = tuple(max(int(np.floor(e / block_size)) + 1, 1) for e in ext)
    grid = _Grid(lo, [block_size] * 3, shape)
    pass1 = {}
    for index, (pos, keys, tris, own) in _split_blocks(vertices, faces, grid):
        pass1[tuple(int(i) for i in index)] = dask.delayed(_pass1, pure=True)(
            pos, keys, tris, own, [int(i) for i in index], grid, opts)
    tasks = _pass2_tasks(pass1, grid, opts, "hmira-decimate-")
    return _assemble(tasks, out, zarr)


# ---------------------------------------------------------------- quality


def _min_angles(vertices, faces):
    """The smallest angle of each triangle, in degrees."""
    p = np.asarray(vertices, dtype=np.float64)[np.asarray(faces)]
    out = np.full(len(p), 180.0)
    for i in range(3):
        a, b, c = p[:, i], p[:, (i + 1) % 3], p[:, (i + 2) % 3]
        u, v = b - a, c - a
        cos = np.einsum("ij,ij->i", u, v) / np.maximum(np.linalg.norm(u, axis=1) * np.linalg.norm(v, axis=1), 1e-300)
        out = np.minimum(out, np.degrees(np.arccos(np.clip(cos, -1.0, 1.0))))
    return out


def decimation_quality(full: Any, decimated: Any, *, per_triangle: int = 10, min_samples: int = 1_000_000,
                       bins: Sequence[float] = (0, 5, 10, 15, 20, 25, 30, 40, 50, 60)) -> dict:
    """How far a decimated surface lies from the full-resolution one, and the shape of its triangles.

    Parameters
    ----------
    full, decimated : hmira.Mesh or (vertices, faces)
        Both held in memory (the distances are :func:`hmira.hausdorff_distance`'s, sampled at
        ``per_triangle`` points per triangle and at least ``min_samples`` per surface).
    bins : sequence of float, keyword-only
        Edges, in degrees, of the minimum-angle histogram.

    Returns
    -------
    dict
        ``hausdorff`` (symmetric), ``mean`` (the larger of the two directed means), each also
        ``*_relative`` (over the bounding-box diagonal of ``full``), ``diagonal``, ``faces``
        and ``full_faces``, ``min_angle_histogram`` (counts per bin) with ``min_angle_bins``,
        and ``hausdorff_distance``'s whole report under ``report``.
    """
    from . import hausdorff_distance

    fv, ff = _mesh_arrays(full)
    dv, df = _mesh_arrays(decimated)
    r = hausdorff_distance((fv, ff), (dv, df), per_triangle=int(per_triangle), min_samples=int(min_samples))
    diagonal = float(np.linalg.norm(fv.max(axis=0) - fv.min(axis=0))) if len(fv) else 0.0
    h = float(r["symmetric"]["max"] if isinstance(r["symmetric"], dict) else r["symmetric"])
    mean = max(float(r["a_to_b"]["mean"]), float(r["b_to_a"]["mean"]))
    hist, edges = np.histogram(_min_angles(dv, df), bins=np.asarray(bins, dtype=np.float64))
    return {"hausdorff": h, "mean": mean, "hausdorff_relative": h / diagonal if diagonal else 0.0,
            "mean_relative": mean / diagonal if diagonal else 0.0, "diagonal": diagonal, "faces": int(len(df)),
            "full_faces": int(len(ff)), "min_angle_histogram": hist.tolist(), "min_angle_bins": edges.tolist(),
            "report": r}


def _block_distances(samples, lo, whole, iso, spacing, origin, inside, cubes_lo, cubes_hi, dv, df, grid, margin,
                     per_triangle):
    """Both directed distances of one block: from the full-resolution triangles of its own cubes
    to the whole decimated mesh, and from the decimated triangles whose centroid lies in the
    block to the full-resolution triangles of the block grown by `margin` cubes (exact while
    the Hausdorff distance is under the margin). (max, sum, samples) per direction."""
    from . import hausdorff_distance

    positions, _keys, triangles, cubes = _core._marching_cubes_block(
        [samples], float(iso), steps=[[0, 0, 0]], core=list(samples.shape), offset=list(lo), whole=list(whole),
        spacing=list(spacing), origin=list(origin), inside=inside, threads=1)
    nz, ny, nx = whole
    c = np.stack([cubes // (nx * ny), (cubes // nx) % ny, cubes % nx], axis=1)
    own = np.all((c >= cubes_lo) & (c < cubes_hi), axis=1)
    out = []
    centroid = grid.coords(dv[df].sum(axis=1) / 3.0)
    index = np.asarray(cubes_lo) // np.asarray(grid.block)
    mine = np.all(np.clip(np.floor(centroid).astype(np.int64), 0, np.asarray(grid.shape) - 1) == index, axis=1)
    for a, b in (((positions, triangles[own]), (dv, df)), ((dv, df[mine]), (positions, triangles))):
        if len(a[1]) == 0 or len(b[1]) == 0:
            out.append((0.0, 0.0, 0))
            continue
        r = hausdorff_distance(a, b, per_triangle=int(per_triangle), min_samples=0)["a_to_b"]
        out.append((float(r["max"]), float(r["mean"]) * int(r["samples"]), int(r["samples"])))
    return out


def volume_decimation_quality(darr: Any, iso: float, decimated: Any, *, block: int = 128, margin: int = 8,
                              spacing: Sequence[float] = (1.0, 1.0, 1.0), origin: Sequence[float] = (0.0, 0.0, 0.0),
                              inside: str = "below", per_triangle: int = 10) -> dict:
    """decimation_quality against the marching cubes of a volume larger than memory, block by
    block: the full-resolution surface is made again per block and never held whole (the
    decimated mesh is). Distances from the decimated surface are exact while the Hausdorff
    distance is under `margin` cubes. Returns ``hausdorff``, ``mean`` (the larger directed
    mean), their ``*_relative`` to the volume's diagonal, ``samples`` per direction."""
    import dask
    import dask.array as da

    darr = da.asarray(darr)
    dv, df = _mesh_arrays(decimated)
    whole = tuple(int(s) for s in darr.shape)
    spacing = tuple(float(s) for s in spacing)
    origin = tuple(float(o) for o in origin)
    shape = tuple(-(-(s - 1) // block) for s in whole)
    grid = _Grid(origin, [block * s for s in spacing], shape)
    grid.block = (block, block, block)
    dvd, dfd = dask.delayed(dv), dask.delayed(df)
    tasks = []
    for index in np.ndindex(*shape):
        lo = [max(index[a] * block - margin, 0) for a in range(3)]
        hi = [min((index[a] + 1) * block + margin + 1, whole[a]) for a in range(3)]
        clo = [index[a] * block for a in range(3)]
        chi = [(index[a] + 1) * block for a in range(3)]
        tasks.append(dask.delayed(_block_distances, pure=True)(
            _sample_block(darr, lo, hi), lo, whole, float(iso), spacing, origin, inside, clo, chi, dvd, dfd, grid,
            margin, per_triangle))
    results = dask.compute(*tasks)
    out = {}
    for d, name in ((0, "full_to_decimated"), (1, "decimated_to_full")):
        mx = max((r[d][0] for r in results), default=0.0)
        n = sum(r[d][2] for r in results)
        out[name] = {"max": mx, "mean": sum(r[d][1] for r in results) / n if n else 0.0, "samples": n}
    diagonal = float(np.linalg.norm((np.asarray(whole) - 1) * np.asarray(spacing)))
    h = max(out["full_to_decimated"]["max"], out["decimated_to_full"]["max"])
    mean = max(out["full_to_decimated"]["mean"], out["decimated_to_full"]["mean"])
    hist, edges = np.histogram(_min_angles(dv, df), bins=np.asarray((0, 5, 10, 15, 20, 25, 30, 40, 50, 60), float))
    return {"hausdorff": h, "mean": mean, "hausdorff_relative": h / diagonal, "mean_relative": mean / diagonal,
            "diagonal": diagonal, "faces": int(len(df)), "min_angle_histogram": hist.tolist(),
            "min_angle_bins": edges.tolist(), **out}


