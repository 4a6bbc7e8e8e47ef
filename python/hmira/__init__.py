"""hmira: polygon-mesh algorithms for numpy users.

Marching cubes, voxelization, Delaunay triangulation, mesh I/O and editing, over the same
C++ headers as the hmira library. Arrays go in and come out without copies where the layout
allows; options are keyword-only; errors are ``ValueError`` (``OSError`` for files) carrying
the C++ message.

Examples
--------
>>> import numpy as np, hmira
>>> x, y, z = np.mgrid[-1:1:40j, -1:1:40j, -1:1:40j]
>>> vertices, faces = hmira.marching_cubes(x**2 + y**2 + z**2 - 0.5, 0.0)
>>> mesh = hmira.Mesh(vertices, faces)
>>> mesh.topology().genus
0
"""
from __future__ import annotations

import os
import warnings
import weakref
from typing import Any, List, Optional, Sequence, Tuple

import numpy as np

from . import _core
from ._core import BVH, Topology, delaunay_triangulation
from ._core import hausdorff_distance, mesh_boolean, repair, signed_distance, winding_number
from ._core import (BevelResult, BooleanResult, DecimateResult, ExtrudeResult, FillHolesResult, OpenHole, RemeshResult,
                    SubdivideResult, TriangulateResult, TruncateResult)

__all__ = [
    "BVH",
    "BevelResult",
    "BooleanResult",
    "DecimateResult",
    "ExtrudeResult",
    "FillHolesResult",
    "Mesh",
    "OpenHole",
    "RemeshResult",
    "RepairWarning",
    "SubdivideResult",
    "Topology",
    "TriangulateResult",
    "TruncateResult",
    "VertexView",
    "bevel",
    "delaunay_triangulation",
    "extrude",
    "flip_normals",
    "hausdorff_distance",
    "marching_cubes",
    "mesh_boolean",
    "mesh_topology",
    "read_mesh",
    "read_volume",
    "render",
    "repair",
    "signed_distance",
    "truncate",
    "view",
    "voxelize",
    "winding_number",
    "write_mesh",
]

__version__ = "0.1.0"


class RepairWarning(UserWarning):
    """Issued when :func:`read_mesh`, ``Mesh(vertices, faces, repair=True)`` or
    :meth:`Mesh.from_trimesh` repaired faces to hold them in a half-edge mesh (the CLI's editing
    commands print the same one-line summary); ``Mesh.repairs`` keeps the summary."""


def marching_cubes(volume: Any, iso: Optional[float] = None, **options: Any) -> Tuple[np.ndarray, np.ndarray]:
    if not isinstance(volume, np.ndarray):
        volume = np.asarray(volume)  # nested lists, and other array-likes
        if volume.dtype == object:
            raise ValueError("marching_cubes: volume must be a 3-D array of numbers (ragged nested lists?)")
    return _core.marching_cubes(volume, iso, **options)


marching_cubes.__doc__ = _core.marching_cubes.__doc__


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
        consistently oriented 2-manifold (with or without boundary).
    repair : bool, keyword-only
        Repair faces a half-edge mesh cannot hold as given (non-manifold edges or vertices,
        faces wound against each other, degenerate faces) with the file readers' repair, which
        :func:`read_mesh` uses: a :class:`RepairWarning` carries its one-line summary and
        ``repairs`` keeps it. Default: refuse them.

    Raises
    ------
    ValueError
        A vertex index out of range, a non-finite coordinate, a non-manifold or
        inconsistently oriented face (the message names the face, edge or vertex), unless
        ``repair=True``.

    Examples
    --------
    >>> import hmira
    >>> m = hmira.Mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]],
    ...                [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
    >>> m.topology().genus, m.validate()
    (0, [])
    >>> m.truncate(all=True, fraction=0.3).faces
    4
    >>> m.face_count
    8
    """

    #: What :func:`read_mesh` repaired, as the CLI's one-line summary ("" when nothing was).
    repairs: str = ""

    def __init__(self, vertices: Any = None, faces: Any = None, *, repair: bool = False) -> None:
        super().__init__()
        if vertices is None and faces is None:
            return
        if vertices is None or faces is None:
            raise ValueError("Mesh: give both vertices and faces, or neither")
        summary = self._set_polygons_checked(_vertex_array(vertices), _faces_arg(faces), repair=repair)
        if summary:
            self.repairs = summary
            warnings.warn(f"Mesh: repaired for editing: {summary}", RepairWarning, stacklevel=2)

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
                 fraction: Optional[float] = None, distance: Optional[float] = None) -> TruncateResult:
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
        TruncateResult
            ``faces``: new faces, ``vertices``: new vertices (counts). Indices stay dense.

        Examples
        --------
        >>> import hmira
        >>> m = hmira.Mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]],
        ...                [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
        >>> m.truncate([0], fraction=0.5)
        TruncateResult(faces=1, vertices=3)
        """
        return self._truncate(None if vertices is None else [int(v) for v in vertices], all=all, fraction=fraction, distance=distance)

    def bevel(self, edges: Optional[Sequence[Tuple[int, int]]] = None, *, all: bool = False, angle: Optional[float] = None,
              width: float = 0.1, segments: int = 1, no_clamp: bool = False, vertices: Optional[Sequence[int]] = None,
              vertices_all: bool = False) -> BevelResult:
        """Bevel edges (by their end vertices, all, or sharper than ``angle`` degrees) or, in
        vertex-only mode, corners; in place (as ``hmira bevel``).

        Returns
        -------
        BevelResult
            ``strip_faces``, ``vertex_faces``, ``vertices`` (counts made) and ``width`` (used).

        Examples
        --------
        >>> import hmira
        >>> m = hmira.Mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]],
        ...                [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
        >>> m.bevel([(0, 1)], width=0.05).strip_faces
        1
        """
        e = None if edges is None else [(int(a), int(b)) for a, b in edges]
        v = None if vertices is None else [int(x) for x in vertices]
        return self._bevel(e, all=all, angle=angle, width=width, segments=segments, no_clamp=no_clamp,
                           vertices=v, vertices_all=vertices_all)

    def extrude(self, faces: Optional[Sequence[int]] = None, *, all: bool = False, distance: float = 1.0,
                direction: Optional[Sequence[float]] = None, mode: str = "region") -> ExtrudeResult:
        """Extrude faces, in place (as ``hmira extrude``); ``mode`` is "region" or "individual".

        Returns
        -------
        ExtrudeResult
            ``top_faces``, ``side_faces`` and ``vertices`` made (counts).

        Examples
        --------
        >>> import hmira
        >>> m = hmira.Mesh([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], [[0, 1, 2, 3]])
        >>> m.extrude([0], distance=2.0).side_faces
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
    def from_trimesh(cls, tm: Any, *, repair: bool = False) -> "Mesh":
        """A Mesh from a ``trimesh.Trimesh`` (or anything with ``.vertices`` and ``.faces``).

        The faces must be a consistently oriented 2-manifold, as the class says: a non-manifold
        edge or vertex, or faces wound against each other, raise ValueError naming the element,
        unless ``repair=True``: then the faces go through the readers' repair, whose one-line summary
        the mesh's ``repairs`` keeps (as :func:`read_mesh`).
        """
        out = cls()
        vertices, faces = _vertex_array(np.asarray(tm.vertices)), _faces_arg(np.asarray(tm.faces))
        out.repairs = out._set_polygons_checked(vertices, faces, repair=repair)
        if out.repairs:
            warnings.warn(f"Mesh: repaired for editing: {out.repairs}", RepairWarning, stacklevel=2)
        return out

    # Geometry basics (mesh_geometry.cpp: bounds, area, volume, face_normals, face_areas, edges).

    def __len__(self) -> int:
        """The number of faces (as trimesh)."""
        return self.face_count

    def split(self) -> List["Mesh"]:
        """The connected components that have faces, each a new Mesh, in order of their lowest
        vertex index (vertices used by no face are left out; vertex colours follow).

        Examples
        --------
        >>> import hmira
        >>> two = hmira.Mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0], [5, 0, 0], [6, 0, 0], [5, 1, 0]],
        ...                  [[0, 1, 2], [3, 4, 5]])
        >>> [len(part) for part in two.split()]
        [1, 1]
        """
        labels, count = self._face_components()
        parts = []
        for c in range(count):
            part = Mesh()
            part._assign_faces(self, np.flatnonzero(labels == c).tolist())
            parts.append(part)
        return parts

    def apply_transform(self, matrix: Any) -> "Mesh":
        """A transformed copy: positions mapped by a 4x4 affine matrix (last row 0, 0, 0, 1).
        A matrix that mirrors (negative determinant) also reverses every face, so the copy
        stays wound counter-clockwise seen from outside (as trimesh does).

        Examples
        --------
        >>> import numpy as np, hmira
        >>> m = hmira.Mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]])
        >>> m.apply_transform(np.diag([2.0, 2.0, 2.0, 1.0])).area()
        2.0
        """
        t = np.asarray(matrix, dtype=np.float64)
        if t.shape != (4, 4):
            raise ValueError(f"apply_transform: expected a 4x4 matrix, got shape {t.shape}")
        if not np.all(np.isfinite(t)):
            raise ValueError("apply_transform: the matrix must be finite")
        if not np.array_equal(t[3], [0.0, 0.0, 0.0, 1.0]):
            raise ValueError(f"apply_transform: the last row must be [0, 0, 0, 1] (an affine map), got {t[3].tolist()}")
        out = self.copy()
        v = out._positions()
        v[...] = v @ t[:3, :3].T + t[:3, 3]
        if np.linalg.det(t[:3, :3]) < 0:
            out.flip()
        return out

    def translate(self, offset: Sequence[float]) -> "Mesh":
        """A copy moved by `offset` (3 numbers)."""
        t = np.eye(4)
        t[:3, 3] = np.asarray(offset, dtype=np.float64).reshape(3)
        return self.apply_transform(t)

    def scale(self, factor: Any, center: Optional[Sequence[float]] = None) -> "Mesh":
        """A copy scaled by `factor` (a number, or 3 per axis) about `center` (default the origin)."""
        f = np.broadcast_to(np.asarray(factor, dtype=np.float64), (3,))
        c = np.zeros(3) if center is None else np.asarray(center, dtype=np.float64).reshape(3)
        t = np.eye(4)
        t[:3, :3] = np.diag(f)
        t[:3, 3] = c - f * c
        return self.apply_transform(t)

    @property
    def vertex_colors(self) -> Optional[np.ndarray]:
        """Per-vertex RGBA colours as an (n, 4) uint8 array (a copy), or None when the mesh has
        none; read from PLY/OFF/OBJ files and written back by :meth:`write`. Assign an (n, 3) or
        (n, 4) uint8 array to set them, None to drop them."""
        return self._vertex_colors

    @vertex_colors.setter
    def vertex_colors(self, value: Any) -> None:
        if value is None:
            self._set_vertex_colors(None)
            return
        c = np.asarray(value)
        if c.dtype != np.uint8:
            if c.dtype.kind == "f" and c.size and c.min() >= 0 and c.max() <= 1:
                c = np.round(c * 255)
            c = c.astype(np.uint8)
        self._set_vertex_colors(np.ascontiguousarray(c))

    def __getstate__(self) -> dict:
        state = {"vertices": np.array(self._positions()), "polygons": self.polygons}
        colors = self._vertex_colors
        if colors is not None:
            state["vertex_colors"] = colors
        return state

    def __setstate__(self, state: dict) -> None:
        # Called on a fresh Mesh() (see __reduce__). A pickled mesh was valid: rebuild it exactly, refusing (never repairing) anything else.
        self._set_polygons_checked(_vertex_array(state["vertices"]), state["polygons"], repair=False)
        if state.get("vertex_colors") is not None:
            self._set_vertex_colors(np.ascontiguousarray(state["vertex_colors"], dtype=np.uint8))

    def __reduce__(self) -> Any:
        return (Mesh, (), self.__getstate__())

    # The one vocabulary (as smoothing and the CLI): fix_boundary, fixed_vertices, max_edges.

    def decimate(self, *, keep_boundary: Optional[bool] = None, locked_vertices: Optional[Sequence[int]] = None,
                 **options: Any) -> DecimateResult:
        """Quadric error decimation: see :meth:`MeshCore.decimate`. ``keep_boundary`` and
        ``locked_vertices`` are the deprecated names of ``fix_boundary`` and ``fixed_vertices``."""
        if keep_boundary is not None:
            warnings.warn("decimate: keep_boundary is deprecated; use fix_boundary", DeprecationWarning, stacklevel=2)
            options.setdefault("fix_boundary", keep_boundary)
        if locked_vertices is not None:
            warnings.warn("decimate: locked_vertices is deprecated; use fixed_vertices", DeprecationWarning,
                          stacklevel=2)
            options.setdefault("fixed_vertices", locked_vertices)
        return super().decimate(**options)

    def fill_holes(self, max_edges: Optional[int] = None, *, max_size: Optional[int] = None, **options: Any) -> FillHolesResult:
        """Fill every hole of at most `max_edges` boundary edges (default: the CLI's, from the
        library): see :meth:`MeshCore.fill_holes`. ``max_size`` is its deprecated name."""
        if max_size is not None:
            warnings.warn("fill_holes: max_size is deprecated; use max_edges", DeprecationWarning, stacklevel=2)
            if max_edges is None:
                max_edges = max_size
        if max_edges is None:
            return super().fill_holes(**options)
        return super().fill_holes(max_edges, **options)

    def to_trimesh(self) -> Any:
        """A ``trimesh.Trimesh`` copy (needs trimesh; triangles only, as trimesh holds)."""
        import trimesh  # optional dependency

        return trimesh.Trimesh(vertices=np.array(self._positions()), faces=self.faces, process=False)

    # Bridges to Open3D, PyVista and meshio: duck-typed on the way in (no import needed), the
    # package imported only on the way out. Construction checks as Mesh(V, F, repair=...) does.

    def _triangles(self) -> np.ndarray:
        """(m, 3) int32 triangles: the faces, or a triangulated copy's when some are polygons."""
        if self.face_count == 0:
            return np.zeros((0, 3), dtype=np.int32)
        try:
            faces = self.faces
            if faces.shape[1] == 3:
                return faces
        except ValueError:
            pass
        copy = self.copy()
        copy.triangulate_faces()
        return copy.faces

    @classmethod
    def _from_arrays(cls, vertices: Any, faces: Any, colors: Any, repair: bool) -> "Mesh":
        out = cls()
        out.repairs = out._set_polygons_checked(_vertex_array(vertices), _faces_arg(faces), repair=repair)
        if out.repairs:
            warnings.warn(f"Mesh: repaired for editing: {out.repairs}", RepairWarning, stacklevel=3)
        if colors is not None and len(colors) == out.vertex_count and not out.repairs:
            out.vertex_colors = colors
        return out

    @classmethod
    def from_open3d(cls, mesh: Any, *, repair: bool = False) -> "Mesh":
        """A Mesh from an ``open3d.geometry.TriangleMesh`` (its vertices, triangles and vertex
        colours); checked as ``Mesh(vertices, faces, repair=repair)``."""
        if not hasattr(mesh, "vertices") or not hasattr(mesh, "triangles"):
            raise ValueError("from_open3d: expected an open3d.geometry.TriangleMesh (.vertices and .triangles)")
        colors = None
        if getattr(mesh, "has_vertex_colors", lambda: False)():
            colors = np.asarray(mesh.vertex_colors, dtype=np.float64)
        return cls._from_arrays(np.asarray(mesh.vertices), np.asarray(mesh.triangles, dtype=np.int64), colors, repair)

    def to_open3d(self) -> Any:
        """An ``open3d.geometry.TriangleMesh`` copy (needs open3d): polygons are triangulated in
        the copy; vertex colours go along (as floats in [0, 1])."""
        import open3d  # optional dependency

        out = open3d.geometry.TriangleMesh(open3d.utility.Vector3dVector(np.array(self._positions())),
                                           open3d.utility.Vector3iVector(np.asarray(self._triangles(), np.int32)))
        colors = self._vertex_colors
        if colors is not None:
            out.vertex_colors = open3d.utility.Vector3dVector(colors[:, :3].astype(np.float64) / 255.0)
        return out

    @classmethod
    def from_pyvista(cls, mesh: Any, *, repair: bool = False) -> "Mesh":
        """A Mesh from a ``pyvista.PolyData`` (points and polygon faces; lines and vertices are
        left out; other datasets: call ``.extract_surface()`` first); checked as
        ``Mesh(vertices, faces, repair=repair)``. An "RGB" or "RGBA" uint8 point array becomes
        the vertex colours."""
        if not hasattr(mesh, "points") or not hasattr(mesh, "faces"):
            raise ValueError("from_pyvista: expected a pyvista.PolyData (.points and .faces); "
                             "call .extract_surface() on other datasets")
        cells = np.asarray(mesh.faces, dtype=np.int64).ravel()
        polygons = []
        i = 0
        while i < len(cells):
            k = int(cells[i])
            if k < 1 or i + 1 + k > len(cells):
                raise ValueError(f"from_pyvista: the face array is malformed at offset {i} (size {k})")
            polygons.append(cells[i + 1:i + 1 + k])
            i += 1 + k
        sizes = {len(p) for p in polygons}
        faces: Any = np.array(polygons, dtype=np.int64) if len(sizes) == 1 else [p.tolist() for p in polygons]
        if not polygons:
            faces = np.zeros((0, 3), dtype=np.int64)
        colors = None
        data = getattr(mesh, "point_data", {})
        for name in ("RGBA", "RGB"):
            if name in data and np.asarray(data[name]).dtype == np.uint8:
                colors = np.asarray(data[name])
                break
        return cls._from_arrays(np.asarray(mesh.points), faces, colors, repair)

    def to_pyvista(self) -> Any:
        """A ``pyvista.PolyData`` copy (needs pyvista), polygons kept; vertex colours go along as
        the "RGBA" point array."""
        import pyvista  # optional dependency

        polygons = self.polygons
        cells = np.fromiter((x for p in polygons for x in (len(p), *p)), dtype=np.int64,
                            count=sum(len(p) + 1 for p in polygons))
        out = pyvista.PolyData(np.array(self._positions()), cells)
        colors = self._vertex_colors
        if colors is not None:
            out.point_data["RGBA"] = colors
        return out

    @classmethod
    def from_meshio(cls, mesh: Any, *, repair: bool = False) -> "Mesh":
        """A Mesh from a ``meshio.Mesh``: its triangle, quad and polygon cell blocks (other cells,
        such as lines or tetrahedra, are left out; none at all is a ValueError); checked as
        ``Mesh(vertices, faces, repair=repair)``."""
        if not hasattr(mesh, "points") or not hasattr(mesh, "cells"):
            raise ValueError("from_meshio: expected a meshio.Mesh (.points and .cells)")
        blocks = [np.asarray(c.data, dtype=np.int64) for c in mesh.cells
                  if c.type in ("triangle", "quad") or c.type.startswith("polygon")]
        if not blocks:
            kinds = sorted({c.type for c in mesh.cells})
            raise ValueError(f"from_meshio: no triangle, quad or polygon cells (the mesh has {kinds or 'none'})")
        sizes = {b.shape[1] for b in blocks}
        faces: Any = np.concatenate(blocks) if len(sizes) == 1 else [row.tolist() for b in blocks for row in b]
        return cls._from_arrays(np.asarray(mesh.points), faces, None, repair)

    def to_meshio(self) -> Any:
        """A ``meshio.Mesh`` copy (needs meshio): one cell block per face size ("triangle",
        "quad", "polygon"), in order of size, each keeping the faces' relative order."""
        import meshio  # optional dependency

        polygons = self.polygons
        by_size: dict = {}
        for p in polygons:
            by_size.setdefault(len(p), []).append(p)
        names = {3: "triangle", 4: "quad"}
        cells = [(names.get(k, "polygon"), np.array(by_size[k], dtype=np.int64)) for k in sorted(by_size)]
        return meshio.Mesh(np.array(self._positions()), cells)


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


def read_mesh(path: Any, *, weld_stl: bool = True, repair: bool = True) -> Mesh:
    """Read an OBJ, OFF, PLY, STL, glTF (.glb, .gltf), VTK (.vtp, .vtk) or 3MF file (chosen by extension)
    into a :class:`Mesh`.

    A file a half-edge mesh cannot hold as it is (non-manifold edges or vertices, faces wound
    against each other, degenerate faces) is repaired, as the CLI's editing commands do, and
    never silently: a :class:`RepairWarning` carries the one-line summary the CLI prints, and
    the mesh's ``repairs`` attribute keeps it ("" when nothing was repaired). ``hmira validate``
    describes the file as it is.

    Parameters
    ----------
    path : str or os.PathLike
    weld_stl : bool, keyword-only
        STL: weld corners with equal coordinates (default), else a triangle soup.
    repair : bool, keyword-only
        False: refuse such a file (ValueError naming the first face at fault) instead.

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
    summary = m._read_reported(os.fspath(path), weld_stl=weld_stl, repair=repair)
    m.repairs = summary
    if summary:
        warnings.warn(f"{os.fspath(path)}: repaired for editing: {summary}", RepairWarning, stacklevel=2)
    return m


def _read_sidecar(path: str) -> dict:
    """The grid of a .raw volume from the "key: value" sidecar ``hmira voxelize`` writes next to it."""
    fields = {}
    with open(path, encoding="utf-8") as f:
        for line in f:
            line = line.split("#", 1)[0].strip()
            if ":" in line:
                key, value = line.split(":", 1)
                fields[key.strip()] = value.strip()
    return fields


def read_volume(path: Any, *, dims: Optional[Sequence[int]] = None, dtype: Optional[str] = None,
                spacing: Optional[Sequence[float]] = None, origin: Optional[Sequence[float]] = None,
                big_endian: bool = False) -> Tuple[np.ndarray, Tuple[float, float, float], Tuple[float, float, float]]:
    """Read a volume that ``hmira mc`` reads: .inr, .inr.gz, or .raw (x fastest, no header).

    A .raw volume's grid comes from its sidecar (``<path>.txt``, as ``hmira voxelize`` writes
    it) or from `dims`, `dtype`, `spacing` and `origin`, which override it (the CLI's
    ``--dims``, ``--type``, ``--spacing``, ``--origin``).

    Returns
    -------
    volume : ndarray, shape (nx, ny, nz)
        ``volume[i, j, k]`` is the sample at ``origin + spacing * (i, j, k)`` (Fortran-ordered,
        no copy); .inr samples as float32, .raw samples in their stored type.
    spacing, origin : tuple of 3 floats
        Pass them on: ``hmira.marching_cubes(volume, iso, spacing=spacing, origin=origin)``.

    Examples
    --------
    >>> import numpy as np, hmira, os, tempfile
    >>> path = os.path.join(tempfile.mkdtemp(), "v.raw")
    >>> np.arange(24, dtype=np.uint8).tofile(path)
    >>> volume, spacing, origin = hmira.read_volume(path, dims=(2, 3, 4), dtype="uint8")
    >>> volume.shape, int(volume[1, 0, 0]), int(volume[0, 1, 0])
    ((2, 3, 4), 1, 2)
    """
    p = os.fspath(path)
    lower = p.lower()
    if lower.endswith(".inr") or lower.endswith(".inr.gz"):
        if dims is not None or dtype is not None or spacing is not None or origin is not None:
            raise ValueError("read_volume: dims, dtype, spacing and origin describe .raw volumes only")
        volume, sp, org = _core._read_inr(p)
        return volume, tuple(sp), tuple(org)
    if not lower.endswith(".raw"):
        raise ValueError(f"read_volume: {p}: not a .inr, .inr.gz or .raw volume")
    side = _read_sidecar(p + ".txt") if os.path.exists(p + ".txt") else {}

    def numbers(given: Any, key: str, default: Any, kind: Any) -> list:
        if given is None:
            if key not in side:
                if default is None:
                    raise ValueError(f"read_volume: {p} needs {key} (no sidecar {p}.txt says it)")
                return list(default)
            given = side[key].split(",")
        values = [kind(x) for x in np.atleast_1d(given)]
        return values * 3 if len(values) == 1 and key == "spacing" else values

    grid_dims = numbers(dims, "dims", None, int)
    sample = dtype if dtype is not None else side.get("type", "float32")
    volume, sp, org = _core._read_raw(p, dims=grid_dims, type=np.dtype(sample).name,
                                      spacing=numbers(spacing, "spacing", (1.0, 1.0, 1.0), float),
                                      origin=numbers(origin, "origin", (0.0, 0.0, 0.0), float), big_endian=big_endian)
    return volume, tuple(sp), tuple(org)


def write_mesh(path: Any, mesh: Any, *, ascii: bool = False, big_endian: bool = False, float32: bool = False,
               attributes: bool = True) -> None:
    """Write a :class:`Mesh`, a ``(vertices, faces)`` pair or any object with ``.vertices`` and
    ``.faces`` to an OBJ, OFF, PLY, STL, glTF (.glb, .gltf), VTK (.vtp, .vtk) or 3MF file, atomically
    (a failure never leaves a partial file). Options as ``hmira convert``: ``ascii`` (PLY/STL text), ``big_endian`` (PLY),
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
            # The mesh's own positions (no copy) and its faces as one (m, k) array, which the
            # extension reads in place with the GIL released; a list only for mixed face sizes.
            v = vertices._positions()
            try:
                f = vertices.faces
            except ValueError:
                f = vertices.polygons
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


def truncate(mesh: Mesh, vertices: Optional[Sequence[int]] = None, **options: Any) -> TruncateResult:
    """``mesh.truncate(vertices, **options)``: see :meth:`Mesh.truncate`."""
    return mesh.truncate(vertices, **options)


def bevel(mesh: Mesh, edges: Optional[Sequence[Tuple[int, int]]] = None, **options: Any) -> BevelResult:
    """``mesh.bevel(edges, **options)``: see :meth:`Mesh.bevel`."""
    return mesh.bevel(edges, **options)


def extrude(mesh: Mesh, faces: Optional[Sequence[int]] = None, **options: Any) -> ExtrudeResult:
    """``mesh.extrude(faces, **options)``: see :meth:`Mesh.extrude`."""
    return mesh.extrude(faces, **options)


from .viewer import render, view  # noqa: E402  (viewer.py uses Mesh)
