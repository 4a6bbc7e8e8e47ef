"""hmira: polygon-mesh algorithms for numpy users.

Marching cubes, voxelization, Delaunay triangulation, mesh I/O and editing, over the same
C++ headers as the hmira library. Arrays go in and come out without copies where the layout
allows; options are keyword-only; errors are ``ValueError`` (``OSError`` for files) carrying
the C++ message.

Examples
--------
>>> import numpy as np, hmira
>>> x, y, z = np.mgrid[-1:1:40j, -1:1:40j, -1:1:40j]
>>> vertices, faces = hmira.marching_cubes(x**2 + y**2 + z**2 - 0.5)
>>> mesh = hmira.Mesh(vertices, faces)
>>> mesh.topology().genus
0
"""
from __future__ import annotations

import weakref
from typing import Any, Optional, Sequence, Tuple

import numpy as np

from . import _core
from ._core import Topology, delaunay_triangulation, marching_cubes
from ._core import hausdorff_distance, signed_distance, winding_number

__all__ = [
    "Mesh",
    "Topology",
    "VertexView",
    "bevel",
    "delaunay_triangulation",
    "extrude",
    "flip_normals",
    "hausdorff_distance",
    "marching_cubes",
    "mesh_topology",
    "read_mesh",
    "render",
    "signed_distance",
    "truncate",
    "view",
    "voxelize",
    "winding_number",
    "write_mesh",
]

__version__ = "0.1.0"


class VertexView(np.ndarray):
    """The positions of a :class:`Mesh` as a writable (n, 3) float64 view, checked on use.

    Reading or writing it changes the mesh's own positions (no copy). After a topology
    change of the mesh (an edit, an Euler operator, ``collect_garbage``, reading a file) or
    once the mesh has been garbage collected, any use through the view (indexing, arithmetic,
    numpy functions, ``repr``) raises ``RuntimeError``; take ``mesh.vertices`` again. The
    memory stays valid even then (the view keeps the old storage alive), so a plain array
    derived from it with ``np.asarray`` reads stale but never freed data.
    """

    _mesh_ref: Optional[weakref.ReferenceType]
    _version: int

    def __array_finalize__(self, obj: Any) -> None:
        self._mesh_ref = getattr(obj, "_mesh_ref", None)
        self._version = getattr(obj, "_version", -1)

    def _check(self) -> None:
        ref = self._mesh_ref
        if ref is None:
            return
        mesh = ref()
        if mesh is None:
            raise RuntimeError("hmira: this vertices view belongs to a Mesh that no longer exists")
        if mesh._topology_version != self._version:
            raise RuntimeError(
                "hmira: this vertices view is stale: its Mesh's topology changed since it was taken "
                "(take mesh.vertices again)"
            )

    def _plain(self) -> np.ndarray:
        self._check()
        return self.view(np.ndarray)

    def __getitem__(self, key: Any) -> Any:
        result = self._plain()[key]
        if isinstance(result, np.ndarray) and result.base is not None and np.may_share_memory(result, self):
            result = result.view(VertexView)
            result._mesh_ref, result._version = self._mesh_ref, self._version
        return result

    def __setitem__(self, key: Any, value: Any) -> None:
        self._plain()[key] = value

    def __array_ufunc__(self, ufunc: Any, method: str, *inputs: Any, **kwargs: Any) -> Any:
        def unwrap(x: Any) -> Any:
            return x._plain() if isinstance(x, VertexView) else x

        inputs = tuple(unwrap(x) for x in inputs)
        outs = kwargs.get("out")
        if outs is not None:
            kwargs["out"] = tuple(unwrap(x) for x in outs)
        result = getattr(ufunc, method)(*inputs, **kwargs)
        if outs is not None and any(isinstance(x, VertexView) for x in outs):
            # In-place operations (v += 1) keep the checked view.
            return outs[0] if len(outs) == 1 else outs
        return result

    def __array_function__(self, func: Any, types: Any, args: Any, kwargs: Any) -> Any:
        def unwrap(x: Any) -> Any:
            if isinstance(x, VertexView):
                return x._plain()
            if isinstance(x, (list, tuple)):
                return type(x)(unwrap(y) for y in x)
            return x

        return func(*unwrap(args), **{k: unwrap(v) for k, v in kwargs.items()})

    def __array__(self, dtype: Any = None, copy: Any = None) -> np.ndarray:
        plain = self._plain()
        return plain if dtype is None else plain.astype(dtype)

    def __repr__(self) -> str:
        return "VertexView(" + repr(self._plain())[6:]

    def __str__(self) -> str:
        return str(self._plain())

    def __len__(self) -> int:
        return len(self._plain())

    def __iter__(self) -> Any:
        return iter(self._plain())

    def copy(self, order: str = "C") -> np.ndarray:  # type: ignore[override]
        return self._plain().copy(order=order)

    def tolist(self) -> Any:  # type: ignore[override]
        return self._plain().tolist()


def _vertex_array(vertices: Any) -> np.ndarray:
    return np.ascontiguousarray(vertices, dtype=np.float64)


def _faces_arg(faces: Any) -> Any:
    if isinstance(faces, np.ndarray):
        if faces.ndim != 2:
            raise ValueError(f"faces must be an (m, k) integer array or a list of polygons, got shape {faces.shape}")
        if faces.dtype.kind not in "iu":
            raise ValueError(f"faces must hold integers, got dtype {faces.dtype}")
        if faces.dtype == np.int32:
            return np.ascontiguousarray(faces)  # read in place (marching_cubes' output)
        return np.ascontiguousarray(faces, dtype=np.int64)
    return faces


class Mesh(_core.MeshCore):
    """A polygon mesh backed by hmira's half-edge mesh.

    Parameters
    ----------
    vertices : array_like, shape (n, 3), optional
        Positions (converted to float64).
    faces : array_like of int, shape (m, k), or sequence of sequences, optional
        Faces as rows of vertex indices, or polygons of any sizes. The mesh must be a
        consistently oriented 2-manifold (with or without boundary); construction goes
        through the same soup-to-mesh path as the file readers.

    Raises
    ------
    ValueError
        A vertex index out of range, a non-finite coordinate, a non-manifold or
        inconsistently oriented face (the message names the face).

    Examples
    --------
    >>> import hmira
    >>> m = hmira.Mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]],
    ...                [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
    >>> m.topology().genus, m.validate()
    (0, [])
    >>> m.truncate(all=True, fraction=0.3)["faces"]
    4
    >>> m.face_count
    8
    """

    def __init__(self, vertices: Any = None, faces: Any = None) -> None:
        super().__init__()
        if vertices is None and faces is None:
            return
        if vertices is None or faces is None:
            raise ValueError("Mesh: give both vertices and faces, or neither")
        self._set_polygons(_vertex_array(vertices), _faces_arg(faces))

    @property
    def vertices(self) -> VertexView:
        """The positions as a writable (n, 3) float64 :class:`VertexView` onto the mesh's own
        storage; it raises once the topology changes (see VertexView)."""
        view = self._positions().view(VertexView)
        view._mesh_ref = weakref.ref(self)
        view._version = self._topology_version
        return view

    @vertices.setter
    def vertices(self, value: Any) -> None:
        self.vertices[...] = value

    def copy(self) -> "Mesh":
        """An independent copy (edits on it leave this mesh alone)."""
        out = Mesh()
        out._assign(self)
        return out

    def __repr__(self) -> str:
        return f"hmira.Mesh(vertices={self.vertex_count}, faces={self.face_count})"

    def _repr_html_(self) -> str:
        """Jupyter shows the mesh in the viewer (see :func:`hmira.view`)."""
        from . import viewer

        return viewer.repr_html(self)

    def truncate(self, vertices: Optional[Sequence[int]] = None, *, all: bool = False,
                 fraction: Optional[float] = None, distance: Optional[float] = None) -> dict:
        """Cut chosen corners off, in place (as ``hmira truncate``).

        Parameters
        ----------
        vertices : sequence of int, optional
            The vertices to truncate.
        all : bool, keyword-only
            Truncate every vertex instead.
        fraction : float, keyword-only
            Cut each edge at this fraction of its length from the vertex, in (0, 1) (default 1/3).
        distance : float, keyword-only
            Cut at this distance instead (> 0).

        Returns
        -------
        dict
            ``faces``: new faces, ``vertices``: new vertices. Indices stay dense.

        Examples
        --------
        >>> import hmira
        >>> m = hmira.Mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]],
        ...                [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
        >>> m.truncate([0], fraction=0.5)
        {'faces': 1, 'vertices': 3}
        """
        return self._truncate(None if vertices is None else [int(v) for v in vertices], all=all, fraction=fraction, distance=distance)

    def bevel(self, edges: Optional[Sequence[Tuple[int, int]]] = None, *, all: bool = False, angle: Optional[float] = None,
              width: float = 0.1, segments: int = 1, no_clamp: bool = False, vertices: Optional[Sequence[int]] = None,
              vertices_all: bool = False) -> dict:
        """Bevel edges (by their end vertices, all, or sharper than ``angle`` degrees) or, in
        vertex-only mode, corners; in place (as ``hmira bevel``).

        Returns
        -------
        dict
            ``strip_faces``, ``vertex_faces``, ``vertices`` (counts made) and ``width`` (used).

        Examples
        --------
        >>> import hmira
        >>> m = hmira.Mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]],
        ...                [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
        >>> m.bevel([(0, 1)], width=0.05)["strip_faces"]
        1
        """
        e = None if edges is None else [(int(a), int(b)) for a, b in edges]
        v = None if vertices is None else [int(x) for x in vertices]
        return self._bevel(e, all=all, angle=angle, width=width, segments=segments, no_clamp=no_clamp,
                           vertices=v, vertices_all=vertices_all)

    def extrude(self, faces: Optional[Sequence[int]] = None, *, all: bool = False, distance: float = 1.0,
                direction: Optional[Sequence[float]] = None, mode: str = "region") -> dict:
        """Extrude faces, in place (as ``hmira extrude``); ``mode`` is "region" or "individual".

        Returns
        -------
        dict
            ``top_faces``, ``side_faces`` and ``vertices`` made.

        Examples
        --------
        >>> import hmira
        >>> m = hmira.Mesh([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], [[0, 1, 2, 3]])
        >>> m.extrude([0], distance=2.0)["side_faces"]
        4
        """
        d = None if direction is None else [float(x) for x in direction]
        return self._extrude(None if faces is None else [int(f) for f in faces], all=all, distance=distance,
                             direction=d, mode=mode)

    def smooth(self, method: str = "taubin", **options: Any) -> int:
        """Smooth the vertex positions in place, as ``hmira smooth``: ``method`` "taubin"
        (:meth:`taubin_smooth`, keeps the volume) or "laplacian" (:meth:`laplacian_smooth`);
        ``options`` are that method's keywords. Returns the number of vertices free to move.

        Examples
        --------
        >>> import hmira
        >>> m = hmira.Mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]],
        ...                [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
        >>> m.smooth("laplacian", iterations=2, fixed_vertices=[0])
        3
        """
        if method == "taubin":
            return self.taubin_smooth(**options)
        if method == "laplacian":
            return self.laplacian_smooth(**options)
        raise ValueError(f"smooth: method must be 'taubin' or 'laplacian', got {method!r}")

    @classmethod
    def from_trimesh(cls, tm: Any) -> "Mesh":
        """A Mesh from a ``trimesh.Trimesh`` (or anything with ``.vertices`` and ``.faces``)."""
        return cls(np.asarray(tm.vertices), np.asarray(tm.faces))

    def to_trimesh(self) -> Any:
        """A ``trimesh.Trimesh`` copy (needs trimesh; triangles only, as trimesh holds)."""
        import trimesh  # optional dependency

        return trimesh.Trimesh(vertices=np.array(self._positions()), faces=self.faces, process=False)


def as_mesh(mesh: Any) -> Mesh:
    """A :class:`Mesh` from a Mesh (returned as is), a ``(vertices, faces)`` pair, or any
    object with ``.vertices`` and ``.faces`` arrays (trimesh, meshio-like)."""
    if isinstance(mesh, Mesh):
        return mesh
    if isinstance(mesh, tuple) and len(mesh) == 2:
        return Mesh(mesh[0], mesh[1])
    if hasattr(mesh, "vertices") and hasattr(mesh, "faces"):
        return Mesh(np.asarray(mesh.vertices), np.asarray(mesh.faces))
    raise ValueError("expected a hmira.Mesh, a (vertices, faces) pair, or an object with .vertices and .faces")


def read_mesh(path: Any, *, weld_stl: bool = True) -> Mesh:
    """Read an OBJ, OFF, PLY or STL file (chosen by extension) into a :class:`Mesh`.

    Parameters
    ----------
    path : str or os.PathLike
    weld_stl : bool, keyword-only
        STL: weld corners with equal coordinates (default), else a triangle soup.

    Raises
    ------
    OSError
        Missing file, directory, permissions.
    ValueError
        Malformed content or a face the half-edge mesh cannot hold (the message names it).

    Examples
    --------
    >>> import hmira, os, tempfile
    >>> path = os.path.join(tempfile.mkdtemp(), "t.off")
    >>> hmira.write_mesh(path, ([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]]))
    >>> hmira.read_mesh(path).face_count
    1
    """
    m = Mesh()
    m._read(str(path), weld_stl=weld_stl)
    return m


def write_mesh(path: Any, mesh: Any, *, ascii: bool = False, big_endian: bool = False, float32: bool = False,
               attributes: bool = True) -> None:
    """Write a :class:`Mesh`, a ``(vertices, faces)`` pair or any object with ``.vertices`` and
    ``.faces`` to an OBJ, OFF, PLY or STL file, atomically (a failure never leaves a partial
    file). Options as ``hmira convert``: ``ascii`` (PLY/STL text), ``big_endian`` (PLY),
    ``float32`` (PLY coordinates), ``attributes`` (normals/colours read from a file).

    Examples
    --------
    >>> import hmira, os, tempfile
    >>> path = os.path.join(tempfile.mkdtemp(), "t.ply")
    >>> hmira.write_mesh(path, ([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]]), ascii=True)
    >>> open(path).readline().strip()
    'ply'
    """
    if isinstance(mesh, _core.MeshCore):
        mesh.write(str(path), ascii=ascii, big_endian=big_endian, float32=float32, attributes=attributes)
        return
    if isinstance(mesh, tuple) and len(mesh) == 2:
        vertices, faces = mesh
    elif hasattr(mesh, "vertices") and hasattr(mesh, "faces"):
        vertices, faces = mesh.vertices, mesh.faces
    else:
        raise ValueError("write_mesh: expected a hmira.Mesh, a (vertices, faces) pair, or an object with .vertices and .faces")
    _core._write_polygons(str(path), _vertex_array(vertices), _faces_arg(faces), ascii=ascii, big_endian=big_endian,
                          float32=float32)


def voxelize(vertices: Any, faces: Any = None, *, resolution: Optional[int] = None, pitch: Optional[float] = None,
             mode: str = "conservative", fill_open: bool = False, threads: int = 0) -> Tuple[np.ndarray, np.ndarray, float]:
    """Voxelize a triangle or polygon mesh on a cubic grid around its bounding box.

    Parameters
    ----------
    vertices : array_like, shape (n, 3), or a Mesh / object with .vertices and .faces
    faces : array_like of int (m, k) or sequence of polygons; omitted when `vertices` is a mesh
    resolution : int, keyword-only
        Voxels along the longest side of the bounding box (default 256, as the CLI).
    pitch : float, keyword-only
        Voxel size instead of `resolution`.
    mode : {"conservative", "centres", "surface"}, keyword-only
        The CLI's ``--mode``. "surface": the voxels the surface touches (touching at a
        single point counts; none is lost to rounding, and a voxel set beyond them misses the
        surface by less than about 1e-13 of a triangle's size); "conservative" (the default, a solid for collision): those plus every voxel
        whose centre lies inside a closed mesh; "centres": exactly the voxels whose centre lies
        inside (exact test; for volume, as VTK's stencil and scikit-image count it).
    fill_open : bool, keyword-only
        Conservative or centres mode on a mesh with holes: fill where the winding number is at least 1/2
        (default: surface voxels only, as the CLI).
    threads : int, keyword-only
        Worker threads (0: all cores).

    Returns
    -------
    voxels : ndarray of bool, shape (nx, ny, nz)
        ``voxels[i, j, k]`` is the voxel centred at ``origin + pitch * (i, j, k)`` along
        x, y, z; two empty layers pad every side. Fortran-ordered.
    origin : ndarray of float64, shape (3,)
        Centre of voxel [0, 0, 0].
    pitch : float
        Voxel size.

    Examples
    --------
    >>> import numpy as np, hmira
    >>> cube = hmira.Mesh([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]],
    ...                   [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]])
    >>> grid, origin, pitch = hmira.voxelize(cube, resolution=10)
    >>> grid.shape, pitch
    ((14, 14, 14), 0.1)
    """
    if faces is None:
        if isinstance(vertices, Mesh):
            v, f = np.array(vertices._positions()), vertices.polygons
        elif isinstance(vertices, tuple) and len(vertices) == 2:
            v, f = vertices
        elif hasattr(vertices, "vertices") and hasattr(vertices, "faces"):
            v, f = vertices.vertices, vertices.faces
        else:
            raise ValueError("voxelize: give (vertices, faces) or a mesh")
    else:
        v, f = vertices, faces
    grid, origin, step, _filled, _note = _core._voxelize(
        _vertex_array(v), _faces_arg(f), resolution=resolution, pitch=pitch, mode=mode, fill_open=fill_open, threads=threads
    )
    return grid, np.array(origin), step


def flip_normals(mesh: Mesh) -> int:
    """Reverse the winding of every face of `mesh` in place; returns the number of faces."""
    return mesh.flip()


def mesh_topology(mesh: Any) -> Topology:
    """V, E, F, genus, components and boundary loops of a mesh (any :func:`as_mesh` input)."""
    return as_mesh(mesh).topology()


def truncate(mesh: Mesh, vertices: Optional[Sequence[int]] = None, **options: Any) -> dict:
    """``mesh.truncate(vertices, **options)``: see :meth:`Mesh.truncate`."""
    return mesh.truncate(vertices, **options)


def bevel(mesh: Mesh, edges: Optional[Sequence[Tuple[int, int]]] = None, **options: Any) -> dict:
    """``mesh.bevel(edges, **options)``: see :meth:`Mesh.bevel`."""
    return mesh.bevel(edges, **options)


def extrude(mesh: Mesh, faces: Optional[Sequence[int]] = None, **options: Any) -> dict:
    """``mesh.extrude(faces, **options)``: see :meth:`Mesh.extrude`."""
    return mesh.extrude(faces, **options)


from .viewer import render, view  # noqa: E402  (viewer.py uses Mesh)
