"""hmira.dask.signed_distance: the signed distance sampled on a grid larger than memory, one
dask chunk at a time.

Every chunk asks the same C++ engine (hmira/algorithms/spatial/signed_distance.hpp: the
closest-point tree and the fast winding-number tree, built once per process) for the signed
distance at its samples, so each chunk holds exactly the values the in-memory query gives
there, and no chunk needs another.
"""
from __future__ import annotations

import threading
from typing import Any, Tuple, Union

import numpy as np

from . import _core

__all__ = ["signed_distance"]


def _triangles(vertices: Any, faces: Any) -> Tuple[np.ndarray, np.ndarray]:
    if faces is None and hasattr(vertices, "vertices") and hasattr(vertices, "faces"):
        vertices, faces = vertices.vertices, vertices.faces
    v = np.ascontiguousarray(vertices, dtype=np.float64)
    f = np.asarray(faces)
    if v.ndim != 2 or v.shape[1] != 3:
        raise ValueError(f"hmira.dask.signed_distance: vertices must have shape (n, 3), got {v.shape}")
    if f.dtype.kind not in "iu" or f.ndim != 2 or f.shape[1] != 3:
        raise ValueError(f"hmira.dask.signed_distance: faces must be an (m, 3) integer array, got {f.dtype} {f.shape}")
    return v, np.ascontiguousarray(f, dtype=np.int64)


class _Block:
    """The task of one chunk: picklable (for distributed workers), holding the mesh once and
    building the engine once per process, on the first chunk it computes there."""

    def __init__(self, vertices, faces, origin, pitch, sign, beta, threads):
        self.vertices, self.faces = vertices, faces
        self.origin, self.pitch = origin, pitch
        self.sign, self.beta, self.threads = sign, beta, threads
        self._engine = None
        self._lock = threading.Lock()

    def __getstate__(self):
        state = dict(self.__dict__)
        state["_engine"], state["_lock"] = None, None
        return state

    def __setstate__(self, state):
        self.__dict__.update(state)
        self._lock = threading.Lock()

    def engine(self):
        with self._lock:
            if self._engine is None:
                self._engine = _core._SignedDistanceEngine(self.vertices, self.faces, sign=self.sign, beta=self.beta)
            return self._engine

    def __call__(self, block_info=None):
        info = block_info[None]
        where = info["array-location"]
        lo = tuple(int(a) for a, _ in where)
        shape = tuple(int(b - a) for a, b in where)
        try:
            return self.engine().block(origin=self.origin, pitch=self.pitch, lo=lo, shape=shape, threads=self.threads)
        except Exception as e:
            span = ", ".join(f"{a}:{b}" for a, b in where)
            raise type(e)(f"hmira.dask.signed_distance: block {tuple(info['chunk-location'])} "
                          f"(samples [{span}]): {e}") from e


def signed_distance(vertices: Any, faces: Any = None, *, pitch: float, chunks: Union[int, Tuple, str] = 256,
                    sign: str = "winding_number", beta: float = 2.0, threads: int = 1):
    """The signed distance to a triangle mesh sampled lazily on a grid, as a ``dask.array``.

    The grid is the one ``hmira.dask.voxelize(vertices, faces, pitch=pitch)`` uses: sample
    ``[i, j, k]`` lies at ``origin + pitch * (i, j, k)``. Each chunk queries the same engine
    (built once per process) and equals ``hmira.signed_distance(vertices, faces, points)`` at
    its samples; no process holds the whole grid, so it can be larger than memory.

    Parameters
    ----------
    vertices : array_like, shape (n, 3), or a Mesh / object with .vertices and .faces
    faces : (m, 3) integer array; omitted when `vertices` is a mesh
    pitch : float, keyword-only
        Sample spacing.
    chunks : dask chunks, keyword-only
        Chunk shape (e.g. 256 or (256, 256, 128)), as ``dask.array`` takes it.
    sign : {"winding_number", "pseudo_normal", "parity"}, keyword-only
        How the inside is decided, as in :func:`hmira.signed_distance`.
    beta : float, keyword-only
        The fast winding number's accuracy (above 1).
    threads : int, keyword-only
        Threads per chunk (1: dask's workers give the parallelism; 0: all cores).

    Returns
    -------
    distances : dask.array.Array of float64, shape (nx, ny, nz)
        Negative inside.
    origin : ndarray of float64, shape (3,)
        The position of sample [0, 0, 0].
    pitch : float

    Errors in a chunk are raised (when computed) as one exception naming the chunk's index and
    sample range, with the C++ message.

    Examples
    --------
    >>> import numpy as np, hmira, hmira.dask
    >>> v = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], float)
    >>> f = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
    >>> sdf, origin, pitch = hmira.dask.signed_distance(v, f, pitch=0.25, chunks=4)
    >>> sdf.shape, bool(sdf.min().compute() < 0 < sdf.max().compute())
    ((5, 5, 5), True)
    """
    import dask.array as da

    v, f = _triangles(vertices, faces)
    if sign not in ("winding_number", "pseudo_normal", "parity"):
        raise ValueError(f"signed_distance: sign must be 'winding_number', 'pseudo_normal' or 'parity', got '{sign}'")
    if not beta > 1:
        raise ValueError(f"signed_distance: beta must be above 1, got {beta}")
    if len(f) == 0:
        raise ValueError("signed_distance: the mesh has no faces")
    dims, origin, pitch = _core._voxel_grid(v, pitch=pitch)
    normalized = da.core.normalize_chunks(chunks, shape=dims, dtype=np.float64)
    task = _Block(v, f, tuple(float(o) for o in origin), float(pitch), sign, float(beta), int(threads))
    grid = da.map_blocks(task, chunks=normalized, dtype=np.float64, meta=np.empty((0, 0, 0), dtype=np.float64),
                         name="hmira-signed-distance-" + da.core.tokenize(v, f, dims, origin, pitch, sign, beta))
    return grid, np.asarray(origin, dtype=np.float64), float(pitch)
