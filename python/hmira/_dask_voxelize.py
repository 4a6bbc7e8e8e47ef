"""hmira.dask.voxelize: voxelization of a grid larger than memory, one dask chunk at a time.

Each chunk is one call of the C++ block voxelizer (hmira/algorithms/conversion/
voxelize_blocks.hpp): the triangles near the chunk give its surface voxels, and the parity of
the inside fill is carried into the chunk from the crossings before it along x, so every
chunk holds exactly the voxels hmira.voxelize sets there, and no chunk needs another.
"""
from __future__ import annotations

from typing import Any, Tuple, Union

import numpy as np

from . import _core

__all__ = ["voxelize"]


def _arrays(vertices: Any, faces: Any) -> Tuple[np.ndarray, np.ndarray]:
    if faces is None and hasattr(vertices, "vertices") and hasattr(vertices, "faces"):
        vertices, faces = vertices.vertices, vertices.faces
    v = np.ascontiguousarray(vertices, dtype=np.float64)
    f = np.asarray(faces)
    if f.dtype.kind not in "iu":
        raise ValueError("hmira.dask.voxelize: faces must be an (m, k) integer array")
    f = np.ascontiguousarray(f, dtype=np.int64 if f.dtype.itemsize > 4 or f.dtype == np.uint32 else np.int32)
    if v.ndim != 2 or v.shape[1] != 3:
        raise ValueError(f"hmira.dask.voxelize: vertices must have shape (n, 3), got {v.shape}")
    if f.ndim != 2 or f.shape[1] < 3:
        raise ValueError(f"hmira.dask.voxelize: faces must have shape (m, k) with k >= 3, got {f.shape}")
    return v, f


class _Block:
    """The task of one chunk: picklable (for distributed workers), holding the mesh once."""

    def __init__(self, vertices, faces, dims, origin, pitch, mode, fill_open, threads):
        self.vertices, self.faces = vertices, faces
        self.dims, self.origin, self.pitch = dims, origin, pitch
        self.mode, self.fill_open, self.threads = mode, fill_open, threads

    def __call__(self, block_info=None):
        info = block_info[None]
        where = info["array-location"]
        lo = tuple(int(a) for a, _ in where)
        shape = tuple(int(b - a) for a, b in where)
        try:
            return _core._voxelize_block(self.vertices, self.faces, dims=self.dims, origin=self.origin, pitch=self.pitch,
                                         lo=lo, shape=shape, mode=self.mode, fill_open=self.fill_open, threads=self.threads)
        except Exception as e:
            span = ", ".join(f"{a}:{b}" for a, b in where)
            raise type(e)(f"hmira.dask.voxelize: block {tuple(info['chunk-location'])} (voxels [{span}]): {e}") from e


def voxelize(vertices: Any, faces: Any = None, *, pitch: float, chunks: Union[int, Tuple, str] = 256,
             mode: str = "conservative", fill_open: bool = False, threads: int = 1):
    """Voxelize a mesh lazily into a boolean ``dask.array``, chunk by chunk.

    The grid is the one ``hmira.voxelize(vertices, faces, pitch=pitch)`` uses, and every chunk
    equals that grid's voxels there, for every mode (``mode`` as in :func:`hmira.voxelize`);
    no process holds the whole grid, so it can be larger than memory and written to zarr.

    Parameters
    ----------
    vertices : array_like, shape (n, 3), or a Mesh / object with .vertices and .faces
    faces : (m, k) integer array; omitted when `vertices` is a mesh
    pitch : float, keyword-only
        Voxel size.
    chunks : dask chunks, keyword-only
        Chunk shape (e.g. 256 or (256, 256, 128)), as ``dask.array`` takes it.
    mode : {"conservative", "centres", "surface"}, keyword-only
    fill_open : bool, keyword-only
        As in :func:`hmira.voxelize`. (With a mesh that has holes, each run of empty voxels is
        decided at its first voxel inside the chunk, which can differ from the whole grid
        where the winding number changes along the run.)
    threads : int, keyword-only
        Threads per chunk (1: dask's workers give the parallelism; 0: all cores).

    Returns
    -------
    voxels : dask.array.Array of bool, shape (nx, ny, nz)
        ``voxels[i, j, k]`` is the voxel centred at ``origin + pitch * (i, j, k)``.
    origin : ndarray of float64, shape (3,)
        Centre of voxel [0, 0, 0].
    pitch : float

    Errors in a chunk are raised (when computed) as one exception naming the chunk's index
    and voxel range, with the C++ message.

    Examples
    --------
    >>> import numpy as np, hmira, hmira.dask
    >>> v = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], float)
    >>> f = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
    >>> grid, origin, pitch = hmira.dask.voxelize(v, f, pitch=0.1, chunks=8, mode="centres")
    >>> bool((grid.compute() == hmira.voxelize(v, f, pitch=0.1, mode="centres")[0]).all())
    True
    """
    import dask.array as da

    v, f = _arrays(vertices, faces)
    if mode not in ("conservative", "centres", "surface"):
        raise ValueError(f"voxelize: mode must be 'conservative', 'centres' or 'surface', got '{mode}'")
    dims, origin, pitch = _core._voxel_grid(v, pitch=pitch)
    normalized = da.core.normalize_chunks(chunks, shape=dims, dtype=bool)
    task = _Block(v, f, tuple(int(d) for d in dims), tuple(origin), float(pitch), mode, bool(fill_open), int(threads))
    grid = da.map_blocks(task, chunks=normalized, dtype=bool, meta=np.empty((0, 0, 0), dtype=bool),
                         name="hmira-voxelize-" + da.core.tokenize(v, f, dims, origin, pitch, mode, fill_open))
    return grid, np.asarray(origin, dtype=np.float64), float(pitch)
