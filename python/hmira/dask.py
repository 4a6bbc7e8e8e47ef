"""Volumes larger than memory, on Dask: marching cubes chunk by chunk, welded exactly.

Each chunk of a ``dask.array`` is meshed on its own, with one sample of overlap on its high
sides, by the same code as :func:`hmira.marching_cubes`. Every vertex carries a global key (the
grid edge it lies on, or the cube of an extra centre vertex), so the chunks weld by key into
exactly the mesh that :func:`hmira.marching_cubes` gives on the whole (C-ordered) array: the
same vertices in the same order, bit for bit, and the same triangles, whatever the chunking.

The result is put together in three ways:

* ``out=None`` on the threaded or synchronous scheduler (chunks run in this process): every
  row of chunks along the last axis, joined into one block, counts what it owns, the client
  lays out the whole result by prefix sums, and every row then writes its vertices and
  triangles straight into it (``_direct``); nothing is merged. A row is read in place when its
  chunks are views of one array (``da.from_array`` of a numpy array), else copied, with its
  one-sample overlap, into a buffer each worker thread reuses during the call (so a thread
  holds up to one row of chunks; rows above 256 MiB go a chunk per task instead).
* ``out=None`` on other schedulers: the client gathers every chunk's keyed mesh and welds them in C++, in parallel
  (``threads=``), reading the chunks' arrays in place: a chunk's own vertices are copied
  straight to their place, only those on its high faces are looked up in the neighbour that
  owns them. Memory in the client: all chunks' meshes (32 bytes per vertex, 20 per triangle)
  plus the result.
* ``out="mesh.ply"``: streaming. Chunks are computed a window at a time on the local
  schedulers, or all at once on a distributed Client (each result released once written),
  and their vertices and triangles appended to two temporary files in chunk order; the
  client keeps a window of chunk meshes and the global ids of the vertices that lie on inner
  chunk faces (the only ones two chunks share). A second pass writes the PLY header, with its
  counts, and copies the two files behind it, then renames the result into place.

Runs on any Dask scheduler: threaded, processes, or a ``distributed`` cluster.
"""
from __future__ import annotations

import operator
import os
import tempfile
import threading
from typing import Any, Optional, Sequence, Tuple

import numpy as np

from . import _core

__all__ = [
    "marching_cubes",
    "voxelize",
    "decimate",
    "decimation_quality",
    "volume_decimation_quality",
    "signed_distance",
]

_DTYPES = (np.float32, np.float64, np.uint8, np.uint16, np.int16)


def _block_label(index, offset, shape) -> str:
    ranges = ", ".join(f"{o}:{o + s}" for o, s in zip(offset, shape))
    return f"block {tuple(int(i) for i in index)} (samples [{ranges}])"


def _mesh_block(parts, iso, index, offset, core, whole, spacing, origin, inside):
    """One chunk plus its overlap to (positions, keys, triangles, cube keys); an error names the block."""
    try:
        arrays = [np.asarray(p) for _, p in parts]
        if arrays[0].dtype not in _DTYPES:
            raise ValueError(f"volume dtype must be float32, float64, uint8, uint16 or int16, got {arrays[0].dtype}")
        # Assembled in C++ into a buffer the thread reuses, with the GIL released.
        return _core._marching_cubes_block(arrays, iso, steps=[list(s) for s, _ in parts], core=list(core), offset=list(offset),
                                           whole=list(whole), spacing=list(spacing), origin=list(origin), inside=inside, threads=1)
    except Exception as e:  # one clear error naming the block, whatever the scheduler
        raise ValueError(f"hmira.dask.marching_cubes: {_block_label(index, offset, core)}: {e}") from e


def _count_block(parts, iso, index, offset, core, whole, spacing, origin, inside):
    """What one chunk owns of the surface (the direct path's first step); an error names the block."""
    try:
        arrays = [np.asarray(p) for _, p in parts]
        if arrays[0].dtype not in _DTYPES:
            raise ValueError(f"volume dtype must be float32, float64, uint8, uint16 or int16, got {arrays[0].dtype}")
        return _core._count_block(arrays, iso, steps=[list(s) for s, _ in parts], core=list(core), offset=list(offset),
                                  whole=list(whole), spacing=list(spacing), origin=list(origin), inside=inside)
    except Exception as e:
        raise ValueError(f"hmira.dask.marching_cubes: {_block_label(index, offset, core)}: {e}") from e


class _Into:
    """The whole result the chunks write into, and each chunk's counts, whose counted rows the
    chunk's writing task takes over (a graph argument dask does not look inside)."""

    def __init__(self, layout, counts, numblocks):
        self.layout = layout
        self.counts = counts
        self.numblocks = numblocks


def _write_block(parts, iso, index, offset, core, whole, spacing, origin, inside, into):
    """Writes one chunk's share straight into the whole result (the direct path's second step)."""
    try:
        arrays = [np.asarray(p) for _, p in parts]
        _core._write_block(arrays, iso, steps=[list(s) for s, _ in parts], core=list(core), offset=list(offset),
                           whole=list(whole), spacing=list(spacing), origin=list(origin), inside=inside, layout=into.layout,
                           counted=into.counts[int(np.ravel_multi_index(index, into.numblocks))])
    except Exception as e:
        raise ValueError(f"hmira.dask.marching_cubes: {_block_label(index, offset, core)}: {e}") from e


def _write_blocks(chunks, iso, whole, spacing, origin, inside, into):
    """Writes a row of chunks along x straight into the whole result, row by row in turn, so
    that the task writes long runs (the direct path's second step); an error names the row."""
    try:
        parts = [[np.asarray(p) for _, p in c[0]] for c in chunks]
        _core._write_blocks(parts, iso, steps=[[list(s) for s, _ in c[0]] for c in chunks], cores=[list(c[3]) for c in chunks],
                            offsets=[list(c[2]) for c in chunks], whole=list(whole), spacing=list(spacing), origin=list(origin),
                            inside=inside, layout=into.layout,
                            counted=[into.counts[int(np.ravel_multi_index(c[1], into.numblocks))] for c in chunks])
    except Exception as e:
        first, last = chunks[0], chunks[-1]
        raise ValueError(f"hmira.dask.marching_cubes: blocks {tuple(first[1])} to {tuple(last[1])}: {e}") from e


def _checked(darr, iso, spacing, origin, inside):
    """The array as a dask array, and the arguments, checked."""
    import dask.array as da

    darr = da.asarray(darr)
    if darr.ndim != 3:
        raise ValueError(f"hmira.dask.marching_cubes: the array must have 3 dimensions, got {darr.ndim}")
    if any(s < 2 for s in darr.shape):
        raise ValueError(f"hmira.dask.marching_cubes: every dimension needs at least 2 samples, got shape {darr.shape}")
    if np.dtype(darr.dtype) not in _DTYPES:
        raise ValueError(f"hmira.dask.marching_cubes: volume dtype must be float32, float64, uint8, uint16 or int16, got {darr.dtype}")
    if inside not in ("below", "above"):
        raise ValueError(f"hmira.dask.marching_cubes: inside must be 'below' or 'above', got {inside!r}")
    spacing = tuple(float(s) for s in spacing)
    origin = tuple(float(o) for o in origin)
    if len(spacing) != 3 or len(origin) != 3:
        raise ValueError("hmira.dask.marching_cubes: spacing and origin need 3 values each")
    if not np.isfinite(iso):
        raise ValueError("hmira.dask.marching_cubes: the iso value must be finite")
    return darr, spacing, origin


def _number(x):
    """A float as its shortest text, as the C++ messages print it ("12", "0.5", "1e+30")."""
    r = repr(float(x))
    return r[:-2] if r.endswith(".0") else r


def _refuse_outside_range(darr, iso):
    """Raises ValueError when `iso` lies outside the samples' range [min, max]: called only when
    the mesh came out empty (a surface needs samples on both sides of the iso value), so that
    the extra pass over the chunks is paid only then. The chunks hold no NaN or infinity: the
    meshing refused those."""
    import dask
    import dask.array as da

    darr = da.asarray(darr)
    lo, hi = (float(x) for x in dask.compute(darr.min(), darr.max()))
    if not lo <= float(iso) <= hi:
        raise ValueError(f"hmira.dask.marching_cubes: iso {_number(iso)} is outside the samples' range [{_number(lo)}, "
                         f"{_number(hi)}], so there is no surface; choose an iso between them")


def _chunk_inputs(darr):
    """For every chunk, in C order of the chunk grid: (parts, index, offset, core). The parts are
    the chunk and one-sample slices of up to seven neighbours after it (a plain getitem each),
    which the C++ side reads in place when they are views of one array, or pastes together:
    cheaper than dask's general overlap."""
    starts = [np.concatenate([[0], np.cumsum(c)[:-1]]).astype(int) for c in darr.chunks]
    numblocks = darr.numblocks
    for index in np.ndindex(*numblocks):
        offset = [int(starts[a][index[a]]) for a in range(3)]
        core = [int(darr.chunks[a][index[a]]) for a in range(3)]
        parts = []
        for step in np.ndindex(2, 2, 2):
            other = tuple(i + s for i, s in zip(index, step))
            if any(o >= n for o, n in zip(other, numblocks)):
                continue
            key = (darr.name,) + other
            if any(step):
                key = (operator.getitem, key, tuple(slice(0, 1) if s else slice(None) for s in step))
            parts.append([list(step), key])
        yield parts, list(index), offset, core


def _row_tasks(darr, iso, spacing, origin, inside, into):
    """One dask.delayed per row of chunks along x (array axis 2), each writing its chunks
    straight into the whole result (_write_blocks)."""
    from dask.base import tokenize
    from dask.delayed import Delayed
    from dask.highlevelgraph import HighLevelGraph

    name = "hmira-mc-write-" + tokenize(darr, iso, spacing, origin, inside, id(into))
    rows = {}
    for parts, index, offset, core in _chunk_inputs(darr):
        rows.setdefault(tuple(index[:2]), []).append([parts, index, offset, core])
    graph = {(name,) + row: (_write_blocks, chunks, float(iso), list(darr.shape), list(spacing), list(origin), inside, into)
             for row, chunks in rows.items()}
    hlg = HighLevelGraph.from_collections(name, graph, dependencies=[darr])
    return [Delayed((name,) + row, hlg, layer=name) for row in rows]


def _byte_bounds(a):
    bounds = getattr(getattr(np.lib, "array_utils", None), "byte_bounds", None) or np.byte_bounds
    return bounds(a)


def _join_x(arrays, copy=True):
    """The chunks of one row along x (array axis 2) as one array: a view when they are views of
    one array lying side by side in it (da.from_array of a numpy array), read in place by the
    C++ side; otherwise a copy (None with copy=False)."""
    arrays = [np.asarray(a) for a in arrays]
    if len(arrays) == 1:
        return arrays[0]
    first = arrays[0]
    at, ptr = 0, first.__array_interface__["data"][0]
    lined_up = True
    for a in arrays:
        if (a.dtype != first.dtype or a.strides != first.strides or a.shape[:2] != first.shape[:2]
                or a.__array_interface__["data"][0] != ptr + at * first.strides[2]):
            lined_up = False
            break
        at += a.shape[2]
    if lined_up and first.size:
        base = first
        while isinstance(base.base, np.ndarray):
            base = base.base
        view = np.lib.stride_tricks.as_strided(first, shape=first.shape[:2] + (at,), strides=first.strides, writeable=False)
        lo, hi = _byte_bounds(base)
        vlo, vhi = _byte_bounds(view)
        if lo <= vlo and vhi <= hi:  # inside the memory the chunks are views of
            return view
    return np.concatenate(arrays, axis=2) if copy else None


def _joined_rows(darr):
    """For every row of chunks along x, in C order of the chunk grid: (parts, index, offset,
    core, x_chunks). The row is one block spanning the whole x axis; its parts are, per step
    along (z, y), the keys of the row's chunks, or of one-sample slices of the next row's."""
    starts = [np.concatenate([[0], np.cumsum(c)[:-1]]).astype(int) for c in darr.chunks]
    nz, ny, nx = darr.numblocks
    for iz, iy in np.ndindex(nz, ny):
        parts = []
        for sz, sy in np.ndindex(2, 2):
            if iz + sz >= nz or iy + sy >= ny:
                continue
            keys = []
            for ix in range(nx):
                key = (darr.name, iz + sz, iy + sy, ix)
                if sz or sy:
                    key = (operator.getitem, key, (slice(0, 1) if sz else slice(None), slice(0, 1) if sy else slice(None)))
                keys.append(key)
            parts.append([[sz, sy, 0], keys])
        offset = [int(starts[0][iz]), int(starts[1][iy]), 0]
        core = [int(darr.chunks[0][iz]), int(darr.chunks[1][iy]), int(darr.shape[2])]
        yield parts, [iz, iy], offset, core, [int(c) for c in darr.chunks[2]]


class _Buffers:
    """Per thread, memory for joined rows that the thread reuses for its next row during one
    marching_cubes call (no fresh pages, so no page faults, per row); freed with the call. A
    graph argument dask does not look inside."""

    def __init__(self):
        self.rows = {}

    def row(self, shape, dtype):
        """An uninitialised array of this shape and dtype in the calling thread's buffer."""
        size = int(np.prod(shape)) * np.dtype(dtype).itemsize
        key = threading.get_ident()
        buf = self.rows.get(key)
        if buf is None or buf.size < size:
            buf = self.rows[key] = np.empty(size, dtype=np.uint8)
        return buf[:size].view(dtype).reshape(shape)


def _row_arrays(parts, buffers):
    """The row's parts, per step along (z, y), each its chunks joined along x: views when the
    chunks lie side by side in one array, else copied once into one array of the whole block
    (with its overlap), whose views the C++ side then reads in place."""
    joined = [[step, _join_x(pieces, copy=False)] for step, pieces in parts]
    if all(a is not None for _, a in joined):
        return joined
    first = [np.asarray(p) for p in parts[0][1]]
    shape = [first[0].shape[0], first[0].shape[1], sum(p.shape[2] for p in first)]
    for (sz, sy, _), _ in parts:
        shape[0] = max(shape[0], first[0].shape[0] + sz)
        shape[1] = max(shape[1], first[0].shape[1] + sy)
    block = buffers.row(shape, first[0].dtype)
    out = []
    for (sz, sy, sx), pieces in parts:
        z0, y0 = sz * first[0].shape[0], sy * first[0].shape[1]
        x0 = 0
        for p in pieces:
            p = np.asarray(p)
            block[z0:z0 + p.shape[0], y0:y0 + p.shape[1], x0:x0 + p.shape[2]] = p
            x0 += p.shape[2]
        out.append([[sz, sy, sx], block[z0:z0 + (1 if sz else first[0].shape[0]), y0:y0 + (1 if sy else first[0].shape[1])]])
    return out


def _name_failing_chunk(arrays, iso, index, offset, core, x_chunks, whole, spacing, origin, inside):
    """After a row failed: the row's chunks one by one (parts sliced from the row's), so that
    the error names the chunk, as on the other paths."""
    x0 = 0
    for ix, cx in enumerate(x_chunks):
        parts = []
        for step, a in arrays:
            parts.append([step, a[:, :, x0:x0 + cx]])
            if x0 + cx < whole[2]:
                parts.append([[step[0], step[1], 1], a[:, :, x0 + cx:x0 + cx + 1]])
        parts.sort(key=lambda p: tuple(p[0]))
        _count_block(parts, iso, [index[0], index[1], ix], [offset[0], offset[1], x0], [core[0], core[1], cx], whole,
                     spacing, origin, inside)
        x0 += cx


def _count_row(parts, iso, index, offset, core, x_chunks, whole, spacing, origin, inside, buffers):
    """What one row of chunks along x owns, counted as one block (long rows of samples); an
    error names the chunk."""
    arrays = _row_arrays(parts, buffers)
    try:
        if arrays[0][1].dtype not in _DTYPES:
            raise ValueError(f"volume dtype must be float32, float64, uint8, uint16 or int16, got {arrays[0][1].dtype}")
        return _core._count_block([a for _, a in arrays], iso, steps=[list(s) for s, _ in arrays], core=list(core),
                                  offset=list(offset), whole=list(whole), spacing=list(spacing), origin=list(origin), inside=inside)
    except Exception as e:
        _name_failing_chunk(arrays, iso, index, offset, core, x_chunks, whole, spacing, origin, inside)
        raise ValueError(f"hmira.dask.marching_cubes: row of blocks {tuple(index)}: {e}") from e


def _write_row(parts, iso, index, offset, core, x_chunks, whole, spacing, origin, inside, buffers, into):
    """Writes one row of chunks along x, as one block, straight into the whole result."""
    arrays = _row_arrays(parts, buffers)
    try:
        _core._write_block([a for _, a in arrays], iso, steps=[list(s) for s, _ in arrays], core=list(core), offset=list(offset),
                           whole=list(whole), spacing=list(spacing), origin=list(origin), inside=inside, layout=into.layout,
                           counted=into.counts[int(np.ravel_multi_index(index, into.numblocks))])
    except Exception as e:
        raise ValueError(f"hmira.dask.marching_cubes: row of blocks {tuple(index)}: {e}") from e


def _joined_row_tasks(darr, iso, spacing, origin, inside, func, extra, label):
    """One dask.delayed per row of chunks along x, in C order, each calling `func` on the row
    joined into one block."""
    from dask.base import tokenize
    from dask.delayed import Delayed
    from dask.highlevelgraph import HighLevelGraph

    name = label + tokenize(darr, iso, spacing, origin, inside, *[id(e) for e in extra])
    graph = {}
    for parts, index, offset, core, x_chunks in _joined_rows(darr):
        graph[(name,) + tuple(index)] = (func, parts, float(iso), index, offset, core, x_chunks, list(darr.shape), list(spacing),
                                         list(origin), inside) + tuple(extra)
    hlg = HighLevelGraph.from_collections(name, graph, dependencies=[darr])
    return [Delayed((name,) + index, hlg, layer=name) for index in np.ndindex(*darr.numblocks[:2])]


def _block_tasks(darr, iso, spacing, origin, inside, func=_mesh_block, extra=(), label="hmira-marching-cubes-"):
    """One dask.delayed per chunk, in C order of the chunk grid, each calling `func` on its chunk
    (by default meshing it)."""
    from dask.base import tokenize
    from dask.delayed import Delayed
    from dask.highlevelgraph import HighLevelGraph

    darr, spacing, origin = _checked(darr, iso, spacing, origin, inside)
    # A plain task graph (one task per block reading the chunk keys directly): building it
    # through dask.delayed costs seconds per hundred blocks.
    name = label + tokenize(darr, iso, spacing, origin, inside, *[id(e) for e in extra])
    graph = {}
    for parts, index, offset, core in _chunk_inputs(darr):
        graph[(name,) + tuple(index)] = (func, parts, float(iso), index, offset, core, list(darr.shape), list(spacing),
                                         list(origin), inside) + tuple(extra)
    hlg = HighLevelGraph.from_collections(name, graph, dependencies=[darr])
    tasks = [Delayed((name,) + index, hlg, layer=name) for index in np.ndindex(*darr.numblocks)]
    return darr, tasks


def marching_cubes(darr, iso: float = 0.0, *, spacing: Sequence[float] = (1.0, 1.0, 1.0),
                   origin: Sequence[float] = (0.0, 0.0, 0.0), inside: str = "below", out: Optional[str] = None,
                   window: int = 0, threads: int = 0, decimate: Any = None, block: int = 128,
                   zarr: Any = None) -> Optional[Tuple[np.ndarray, np.ndarray]]:
    """Marching cubes of a ``dask.array``, chunk by chunk, welded into exactly the whole-volume mesh.

    Parameters
    ----------
    darr : dask.array.Array (or anything ``dask.array.asarray`` takes), shape (n0, n1, n2)
        Samples, float32, float64, uint8, uint16 or int16, in chunks of any sizes (zarr,
        HDF5, a lazily generated field, ...). A NaN or infinite sample raises ValueError
        naming the block and the sample's index in the whole grid (x along array axis 2
        for C-ordered chunks).
    iso : float
        The iso value, within the samples' range [min, max]: when the mesh comes out empty,
        the range is computed (one more pass over the chunks) and an iso outside it raises
        ValueError naming the range; with ``out``, before the file is put in place.
    spacing, origin : sequences of 3 floats, keyword-only
        As in :func:`hmira.marching_cubes`.
    inside : {"below", "above"}, keyword-only
        As in :func:`hmira.marching_cubes`.
    out : str or os.PathLike, keyword-only
        None: return ``(vertices, faces)``, merged in the client. A path: stream the mesh to
        this binary little-endian PLY file (float64 coordinates, int32 indices) and return
        None; no process holds all chunks' vertices (see the module's notes). The file
        appears only when complete; a failure leaves an existing file untouched.
    window : int, keyword-only
        With ``out``: chunks computed at a time (0: twice the number of cores).
    threads : int, keyword-only
        Without ``out``, on a scheduler outside this process: threads of the merge in the
        client (0: all cores). The result does not depend on it.
    decimate : float or dict, keyword-only
        Decimate as it meshes: a target ratio of faces, or a dict as :func:`hmira.dask.decimate`
        takes. Marching cubes and decimation run block by block on a fixed grid of ``block``
        cubes (not the chunks: the result is the same for every chunking), then on the grid
        offset by half a block, so the full-resolution mesh never exists in one place; the blocks
        weld exactly (see ``hmira._dask_decimate``). ``window`` and ``threads`` do not apply.
    block : int, keyword-only
        With ``decimate``: the edge of a decimation block in cubes.
    zarr : str or zarr store, keyword-only
        With ``decimate``: also (or instead of returning) stream the result into this zarr group
        (arrays ``vertices`` and ``faces``).

    Returns
    -------
    vertices : ndarray of float64, shape (n, 3)
    faces : ndarray of int32, shape (m, 3)
        Equal, element for element, to ``hmira.marching_cubes(np.asarray(darr), iso, ...)``
        (with ``out``: the same mesh, vertices in another order).

    Raises
    ------
    ValueError
        A bad argument, or a failure in one chunk, naming that chunk's index and samples.

    Examples
    --------
    >>> import dask.array as da, numpy as np, hmira.dask
    >>> x = da.linspace(-1, 1, 40, chunks=16)
    >>> f = x[:, None, None] ** 2 + x[None, :, None] ** 2 + x[None, None, :] ** 2
    >>> v, t = hmira.dask.marching_cubes(f, 0.5)
    >>> ref_v, ref_t = hmira.marching_cubes(f.compute(), 0.5)
    >>> bool(np.array_equal(v, ref_v) and np.array_equal(t, ref_t))
    True
    """
    import dask

    if decimate is not None:
        from ._dask_decimate import marching_cubes_decimated

        return marching_cubes_decimated(darr, iso, decimate, block=block, spacing=spacing, origin=origin, inside=inside,
                                        out=out, zarr=zarr)
    if int(threads) < 0:
        raise ValueError(f"hmira.dask.marching_cubes: threads must be 0 (all cores) or more, got {threads}")
    if out is None and _in_process(darr):
        vertices, faces = _direct(darr, iso, spacing, origin, inside)
        if len(faces) == 0:
            _refuse_outside_range(darr, iso)
        return vertices, faces
    darr, tasks = _block_tasks(darr, iso, spacing, origin, inside)
    if out is None:
        blocks = dask.compute(*tasks)
        vertices, faces = _core._merge_blocks(list(blocks), whole=list(darr.shape), chunks=[list(c) for c in darr.chunks],
                                              threads=int(threads))
        if len(faces) == 0:
            _refuse_outside_range(darr, iso)
        return vertices, faces
    _stream_ply(os.fspath(out), darr.shape, darr.chunks, tasks, window or 2 * (os.cpu_count() or 1),
                empty=lambda: _refuse_outside_range(darr, iso))
    return None


def _in_process(darr):
    """Whether the scheduler runs the tasks in this process (threaded or synchronous), so that
    chunks can write straight into one result."""
    import dask
    import dask.array as da
    import dask.local
    import dask.threaded

    try:
        scheduler = dask.base.get_scheduler(collections=[da.asarray(darr)])
    except Exception:  # an unknown scheduler setting: take the path that works everywhere
        return False
    return scheduler in (dask.threaded.get, dask.local.get_sync)


def _direct(darr, iso, spacing, origin, inside):
    """The in-process path: every row of chunks along x (or every chunk) counts what it owns,
    the client lays out the whole result by prefix sums, then every row writes its vertices
    and triangles straight into it. No mesh is kept and nothing is merged; each chunk is read
    twice, and its samples' classification (one bit each) and row counts are kept from the
    first step to the second."""
    import dask

    darr, spacing, origin = _checked(darr, iso, spacing, origin, inside)
    mode = _DIRECT
    if mode == "rows" and _row_bytes(darr) > _ROW_BYTES:
        mode = "chunks"  # a row would take too much memory per thread if its chunks must be copied
    if mode == "rows":
        # A row of chunks along x is one block: rows of samples as long as the whole grid's,
        # read in place when the chunks are views of one array. Chunk by chunk, the rows are a
        # chunk wide, and reading them costs twice the whole-grid pass (perf: cache misses).
        buffers = _Buffers()
        counts = dask.compute(*_joined_row_tasks(darr, iso, spacing, origin, inside, _count_row, (buffers,), "hmira-mc-count-"))
        layout = _core._layout_blocks(list(counts), whole=list(darr.shape), x_chunks=[int(darr.shape[2])])
        into = _Into(layout, counts, darr.numblocks[:2])
        dask.compute(*_joined_row_tasks(darr, iso, spacing, origin, inside, _write_row, (buffers, into), "hmira-mc-write-"))
        return _core._layout_result(layout)
    darr, tasks = _block_tasks(darr, iso, spacing, origin, inside, func=_count_block, label="hmira-mc-count-")
    counts = dask.compute(*tasks)
    layout = _core._layout_blocks(list(counts), whole=list(darr.shape), x_chunks=list(darr.chunks[2]))
    into = _Into(layout, counts, darr.numblocks)
    if mode == "chunk_rows":
        # One task per row of chunks along x, writing its chunks row by row in turn: the result
        # is in the whole grid's order, where one chunk's share of a sample row is a few dozen
        # bytes, so chunk by chunk the writes scatter (perf: twice the in-memory writing pass).
        dask.compute(*_row_tasks(darr, iso, spacing, origin, inside, into))
    else:
        _, tasks = _block_tasks(darr, iso, spacing, origin, inside, func=_write_block, extra=(into,), label="hmira-mc-write-")
        dask.compute(*tasks)
    return _core._layout_result(layout)


# How the direct path splits the work: "rows" (a task per row of chunks along x, joined into
# one block), "chunk_rows" (a task per row of chunks, each chunk a block, written row by row in
# turn) or "chunks" (a task per chunk). The tests check all give the whole-volume mesh.
_DIRECT = "rows"
# "rows" takes a task per chunk instead when a row of chunks (with its overlap) is larger than
# this: a row whose chunks are not views of one array is copied into a buffer per thread.
_ROW_BYTES = 256 << 20


def _row_bytes(darr):
    """The largest row of chunks along x, with its overlap, in bytes."""
    return (max(darr.chunks[0]) + 1) * (max(darr.chunks[1]) + 1) * int(darr.shape[2]) * np.dtype(darr.dtype).itemsize


def _shared_mask(keys, shape, chunks):
    """Which keyed vertices lie on an inner chunk face, where two chunks share them."""
    # Keys are in grid axes (x = array axis 2): key = ((k * ny + j) * 4 + a) * nx + i.
    nz, ny, nx = shape
    i = keys % nx
    rest = keys // nx
    axis = rest % 4
    rest //= 4
    j = rest % ny
    k = rest // ny
    shared = np.zeros(len(keys), dtype=bool)
    for coord, a, c in ((i, 0, chunks[2]), (j, 1, chunks[1]), (k, 2, chunks[0])):
        inner = np.zeros(shape[2 - a] + 1, dtype=bool)
        inner[np.cumsum(c)[:-1]] = True
        # An edge along axis a is never shared across a face perpendicular to a; a centre
        # vertex (axis 3) belongs to one cube.
        shared |= inner[coord.astype(np.int64)] & (axis != a) & (axis != 3)
    return shared


def _results_in_order(tasks, window):
    """Yields the tasks' results in order, holding few of them at once.

    On a distributed Client, every task is submitted at once (so neighbouring chunks of a lazy
    field are made once) and each result is released as soon as it has been consumed; on the
    local schedulers, tasks run a window at a time.
    """
    import dask

    try:
        from distributed import default_client
        client = default_client()
    except (ImportError, ValueError):
        client = None
    if client is not None and dask.config.get("scheduler", None) in (None, "dask.distributed", "distributed"):
        futures = client.compute(tasks)
        try:
            for i in range(len(futures)):
                result = futures[i].result()
                futures[i].release()
                futures[i] = None
                yield result
        finally:
            client.cancel([f for f in futures if f is not None])
        return
    for w0 in range(0, len(tasks), window):
        yield from dask.compute(*tasks[w0:w0 + window])


def _stream_ply(path, shape, chunks, tasks, window, empty=None):

    directory = os.path.dirname(os.path.abspath(path))
    vfile = tempfile.NamedTemporaryFile(dir=directory, prefix=".hmira-vertices-", delete=False)
    ffile = tempfile.NamedTemporaryFile(dir=directory, prefix=".hmira-faces-", delete=False)
    final = None
    try:
        shared_ids = {}  # key -> global vertex id, only for vertices on inner chunk faces
        n_vertices = 0
        n_faces = 0
        face_dtype = np.dtype([("n", "u1"), ("v", "<i4", (3,))])
        for positions, keys, triangles, _cubes in _results_in_order(tasks, window):
            ids = np.empty(len(keys), dtype=np.int64)
            shared = _shared_mask(keys, shape, chunks)
            fresh = ~shared
            ids[fresh] = n_vertices + np.arange(int(fresh.sum()))
            n_vertices += int(fresh.sum())
            new_rows = [np.flatnonzero(fresh)]
            extra = []
            for row in np.flatnonzero(shared):
                k = int(keys[row])
                got = shared_ids.get(k)
                if got is None:
                    got = shared_ids[k] = n_vertices + len(extra)
                    extra.append(row)
                ids[row] = got
            n_vertices += len(extra)
            new_rows.append(np.asarray(extra, dtype=np.int64))
            order = np.concatenate(new_rows)
            # Rows in the order of their new ids: the fresh ones first, then new shared ones.
            vfile.write(np.ascontiguousarray(positions[order], dtype="<f8").tobytes())
            if n_vertices > np.iinfo(np.int32).max:
                raise ValueError("hmira.dask.marching_cubes: more than 2^31 - 1 vertices do not fit int32 PLY indices")
            f = np.empty(len(triangles), dtype=face_dtype)
            f["n"] = 3
            f["v"] = ids[triangles]
            ffile.write(f.tobytes())
            n_faces += len(triangles)
        vfile.close()
        ffile.close()
        if n_faces == 0 and empty is not None:
            empty()  # raises before anything is put in place when there is no surface to write
        header = ("ply\nformat binary_little_endian 1.0\ncomment hmira.dask.marching_cubes\n"
                  f"element vertex {n_vertices}\nproperty double x\nproperty double y\nproperty double z\n"
                  f"element face {n_faces}\nproperty list uchar int vertex_indices\nend_header\n").encode()
        fd, final = tempfile.mkstemp(dir=directory, prefix=".hmira-ply-")
        with os.fdopen(fd, "wb") as dst:
            dst.write(header)
            for part in (vfile.name, ffile.name):
                with open(part, "rb") as src:
                    while True:
                        buf = src.read(1 << 24)
                        if not buf:
                            break
                        dst.write(buf)
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(final, 0o666 & ~umask)  # mkstemp made it private
        os.replace(final, path)
        final = None
    finally:
        for f in (vfile, ffile):
            f.close()
            if os.path.exists(f.name):
                os.unlink(f.name)
        if final is not None and os.path.exists(final):
            os.unlink(final)


# Chunked voxelization lives in its own module; hmira.dask exposes it beside marching_cubes.
from ._dask_voxelize import voxelize  # noqa: E402,F401

# Out-of-core decimation (block-wise, exact seams) lives in its own module too.
from ._dask_decimate import decimate, decimation_quality, volume_decimation_quality  # noqa: E402,F401

# The chunked signed distance lives in its own module too.
from ._dask_sdf import signed_distance  # noqa: E402,F401

