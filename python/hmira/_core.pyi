"""
hmira's compiled core: marching cubes, voxelization, Delaunay, mesh I/O and the Mesh class.
"""

from collections.abc import Sequence
from typing import Annotated

import numpy
from numpy.typing import NDArray


def marching_cubes(volume: Annotated[NDArray, dict(shape=(None, None, None), device='cpu', writable=False)], iso: float | None = None, *, spacing: Sequence[float] = [1.0, 1.0, 1.0], origin: Sequence[float] = [0.0, 0.0, 0.0], inside: str = 'below', threads: int = 0) -> tuple[NDArray[numpy.float64], NDArray[numpy.int32]]:
    """
    Extract the iso-surface of a 3-D volume as a welded, closed triangle mesh.

    Parameters
    ----------
    volume : ndarray, shape (n0, n1, n2)
        Samples of any float, integer or bool dtype (hmira.marching_cubes also takes
        nested lists); C- or Fortran-ordered or strided, read in place (never copied).
        A NaN or infinite sample raises ValueError naming it ("volume[3, 4, 5] is inf").
    iso : float, optional
        The iso value, within the samples' range [min, max]: outside it there is no
        surface, and ValueError names the range. Default: the midpoint of the range
        (as scikit-image), so a default never gives an empty mesh. A signed distance
        field wants ``iso=0.0``; scans (CT, MRI) want ``inside="above"``, e.g.
        ``hmira.marching_cubes(ct, 300.0, inside="above")``.
    spacing : sequence of 3 floats, keyword-only
        Distance between samples along array axes 0, 1, 2.
    origin : sequence of 3 floats, keyword-only
        Position of sample [0, 0, 0].
    inside : {"below", "above"}, keyword-only
        Which side of `iso` is the solid ("below" for signed distances, "above" for
        CT/MRI scans and label maps). Triangles wind counter-clockwise seen from outside
        the solid: a label map or scan left at "below" takes the background for the
        solid and comes out inside-out (``hmira.Mesh(v, f).volume()`` is negative).
    threads : int, keyword-only
        Worker threads (0: all cores). The output does not depend on it.

    Returns
    -------
    vertices : ndarray of float64, shape (n, 3)
        Column j is the coordinate along array axis j (as scikit-image).
    faces : ndarray of int32, shape (m, 3)

    Notes
    -----
    The GIL is released while the surface is extracted; Ctrl-C stops it between
    z-slices (KeyboardInterrupt).

    Examples
    --------
    >>> import numpy as np, hmira
    >>> x, y, z = np.mgrid[-1:1:32j, -1:1:32j, -1:1:32j]
    >>> v, f = hmira.marching_cubes(x**2 + y**2 + z**2 - 0.5, 0.0)  # the zero level of a distance
    >>> v.shape[1], f.dtype.name, len(f) == 2 * len(v) - 4
    (3, 'int32', True)
    """

def delaunay_triangulation(points: Annotated[NDArray[numpy.float64], dict(shape=(None, None), order='C', device='cpu', writable=False)], *, voronoi: bool = False) -> object:
    """
    Delaunay triangulation of points in the plane.

    Parameters
    ----------
    points : ndarray of float64, shape (n, 2) or (n, 3)
        The points; a third column is a height, kept but ignored by the
        triangulation (2.5-D), unlike scipy's 3-D tetrahedra.
    voronoi : bool, keyword-only
        Also return the Voronoi diagram.

    Returns
    -------
    triangles : ndarray of int32, shape (m, 3)
        Counter-clockwise triangles indexing `points` (duplicates use their first
        occurrence).
    voronoi_vertices : ndarray of float64, shape (m, 2)
        Only with ``voronoi=True``: the circumcentre of each triangle.
    voronoi_edges : ndarray of int32, shape (e, 2)
        Only with ``voronoi=True``: pairs of Voronoi vertex indices, -1 marking the
        infinite end of a ray.

    Examples
    --------
    >>> import numpy as np, hmira
    >>> hmira.delaunay_triangulation(np.array([[0., 0.], [1., 0.], [0., 1.], [1., 1.1]])).shape
    (2, 3)
    """

class OpenHole:
    """A hole fill_holes left open: its first vertex, length and why."""

    @property
    def vertex(self) -> int: ...

    @property
    def edges(self) -> int: ...

    @property
    def reason(self) -> str: ...

    def __getitem__(self, key: str) -> object:
        """The field `key`, as the dict results of earlier versions offered it."""

    def keys(self) -> list:
        """The field names, in order (with __getitem__, dict(result) works)."""

    def __eq__(self, other: object | None) -> bool: ...

    def __repr__(self) -> str: ...

    __hash__: None = None

class FillHolesResult:
    """
    What Mesh.fill_holes did: loops filled and skipped, faces and vertices added.
    """

    @property
    def filled(self) -> int: ...

    @property
    def skipped(self) -> int: ...

    @property
    def faces_added(self) -> int: ...

    @property
    def vertices_added(self) -> int: ...

    @property
    def unfaired(self) -> int: ...

    @property
    def open(self) -> list[OpenHole]: ...

    def __getitem__(self, key: str) -> object:
        """The field `key`, as the dict results of earlier versions offered it."""

    def keys(self) -> list:
        """The field names, in order (with __getitem__, dict(result) works)."""

    def __eq__(self, other: object | None) -> bool: ...

    def __repr__(self) -> str: ...

    __hash__: None = None

class DecimateResult:
    """
    What Mesh.decimate did: faces and vertices after, collapses, why it stopped ('target_faces', 'max_error' or 'constraints'), the largest error of a collapse made.
    """

    @property
    def faces(self) -> int: ...

    @property
    def vertices(self) -> int: ...

    @property
    def collapses(self) -> int: ...

    @property
    def triangulated(self) -> bool: ...

    @property
    def stopped_by(self) -> str: ...

    @property
    def error(self) -> float: ...

    @property
    def note(self) -> str: ...

    def __getitem__(self, key: str) -> object:
        """The field `key`, as the dict results of earlier versions offered it."""

    def keys(self) -> list:
        """The field names, in order (with __getitem__, dict(result) works)."""

    def __eq__(self, other: object | None) -> bool: ...

    def __repr__(self) -> str: ...

    __hash__: None = None

class TruncateResult:
    """What Mesh.truncate made: new faces and vertices (counts)."""

    @property
    def faces(self) -> int: ...

    @property
    def vertices(self) -> int: ...

    def __getitem__(self, key: str) -> object:
        """The field `key`, as the dict results of earlier versions offered it."""

    def keys(self) -> list:
        """The field names, in order (with __getitem__, dict(result) works)."""

    def __eq__(self, other: object | None) -> bool: ...

    def __repr__(self) -> str: ...

    __hash__: None = None

class BevelResult:
    """
    What Mesh.bevel made: strip faces, vertex faces, vertices (counts), and the smallest width used.
    """

    @property
    def strip_faces(self) -> int: ...

    @property
    def vertex_faces(self) -> int: ...

    @property
    def vertices(self) -> int: ...

    @property
    def width(self) -> float: ...

    def __getitem__(self, key: str) -> object:
        """The field `key`, as the dict results of earlier versions offered it."""

    def keys(self) -> list:
        """The field names, in order (with __getitem__, dict(result) works)."""

    def __eq__(self, other: object | None) -> bool: ...

    def __repr__(self) -> str: ...

    __hash__: None = None

class ExtrudeResult:
    """What Mesh.extrude made: top faces, side faces, vertices (counts)."""

    @property
    def top_faces(self) -> int: ...

    @property
    def side_faces(self) -> int: ...

    @property
    def vertices(self) -> int: ...

    def __getitem__(self, key: str) -> object:
        """The field `key`, as the dict results of earlier versions offered it."""

    def keys(self) -> list:
        """The field names, in order (with __getitem__, dict(result) works)."""

    def __eq__(self, other: object | None) -> bool: ...

    def __repr__(self) -> str: ...

    __hash__: None = None

class RemeshResult:
    """What Mesh.remesh did: splits, collapses, flips, feature edges kept."""

    @property
    def splits(self) -> int: ...

    @property
    def collapses(self) -> int: ...

    @property
    def flips(self) -> int: ...

    @property
    def feature_edges(self) -> int: ...

    def __getitem__(self, key: str) -> object:
        """The field `key`, as the dict results of earlier versions offered it."""

    def keys(self) -> list:
        """The field names, in order (with __getitem__, dict(result) works)."""

    def __eq__(self, other: object | None) -> bool: ...

    def __repr__(self) -> str: ...

    __hash__: None = None

class SubdivideResult:
    """Vertex, edge and face counts after Mesh.subdivide."""

    @property
    def vertices(self) -> int: ...

    @property
    def edges(self) -> int: ...

    @property
    def faces(self) -> int: ...

    def __getitem__(self, key: str) -> object:
        """The field `key`, as the dict results of earlier versions offered it."""

    def keys(self) -> list:
        """The field names, in order (with __getitem__, dict(result) works)."""

    def __eq__(self, other: object | None) -> bool: ...

    def __repr__(self) -> str: ...

    __hash__: None = None

class TriangulateResult:
    """What Mesh.triangulate_faces did: faces cut, triangles added."""

    @property
    def faces_cut(self) -> int: ...

    @property
    def triangles_added(self) -> int: ...

    def __getitem__(self, key: str) -> object:
        """The field `key`, as the dict results of earlier versions offered it."""

    def keys(self) -> list:
        """The field names, in order (with __getitem__, dict(result) works)."""

    def __eq__(self, other: object | None) -> bool: ...

    def __repr__(self) -> str: ...

    __hash__: None = None

class BooleanResult:
    """
    What mesh_boolean made: the new Mesh, per output face its origin (origin_mesh 0 for a, 1 for b; origin_face the face there), candidate pairs tested, input triangles cut, snapped vertices, degenerate faces and face pairs that rounding made intersect.
    """

    @property
    def mesh(self) -> object: ...

    @property
    def origin_mesh(self) -> object: ...

    @property
    def origin_face(self) -> object: ...

    @property
    def intersecting_pairs(self) -> int: ...

    @property
    def cut_triangles(self) -> int: ...

    @property
    def snapped_vertices(self) -> int: ...

    @property
    def degenerate_faces(self) -> int: ...

    @property
    def rounding_intersections(self) -> int: ...

    def __getitem__(self, key: str) -> object:
        """The field `key`, as the dict results of earlier versions offered it."""

    def keys(self) -> list:
        """The field names, in order (with __getitem__, dict(result) works)."""

    def __eq__(self, other: object | None) -> bool: ...

    def __repr__(self) -> str: ...

    __hash__: None = None

class Topology:
    """Counts of a mesh's elements and its topological invariants."""

    @property
    def vertices(self) -> int:
        """live vertices"""

    @property
    def edges(self) -> int:
        """edges"""

    @property
    def faces(self) -> int:
        """faces"""

    @property
    def genus(self) -> int:
        """total genus of the surface components"""

    @property
    def components(self) -> int:
        """connected components, isolated vertices included"""

    @property
    def boundary_loops(self) -> int:
        """closed chains of boundary edges"""

    @property
    def boundary_edges(self) -> int:
        """edges with one face"""

    @property
    def isolated_vertices(self) -> int:
        """vertices used by no face"""

    @property
    def non_manifold_edges(self) -> int:
        """edges with more than two faces"""

    @property
    def euler_characteristic(self) -> int:
        """V - E + F"""

    @property
    def closed(self) -> bool:
        """no boundary and no non-manifold edge"""

    def __repr__(self) -> str: ...

class MeshCore:
    """
    A polygon mesh backed by hmira's half-edge mesh (the compiled part of
    hmira.Mesh; use hmira.Mesh, which adds the checked `vertices` view).
    """

    def __init__(self) -> None:
        """An empty mesh."""

    def is_flip_ok(self, halfedge: int) -> bool:
        """
        Whether flip_edge(halfedge) is allowed: two triangles on either side, no edge between the two opposite vertices yet.
        """

    def flip_edge(self, halfedge: int) -> int:
        """
        Turns the edge between two triangles to join their opposite vertices; returns the flipped halfedge. Its own inverse.
        """

    def split_edge(self, halfedge: int, *, position: Sequence[float] | None = None, split_triangles: bool = True) -> tuple[int, int]:
        """
        A new vertex on the edge (at its midpoint by default), the triangles beside it split; returns (vertex, halfedge from the new vertex to the old target). collapse_edge(halfedge, placement='target') undoes it.
        """

    def split_face(self, face: int, *, position: Sequence[float] | None = None) -> tuple[int, int]:
        """
        Splits a triangle into three at a new vertex (its centroid by default); returns (vertex, halfedge).
        """

    def is_collapse_ok(self, halfedge: int, *, placement: str = 'midpoint', position: Sequence[float] | None = None, check_geometry: bool = False) -> bool:
        """
        Whether collapse_edge(halfedge) is allowed: the link condition and the boundary rules, and with check_geometry no face turned over.
        """

    def collapse_edge(self, halfedge: int, *, placement: str = 'midpoint', position: Sequence[float] | None = None, check_geometry: bool = False) -> int:
        """
        Merges the halfedge's source into its target, which survives at `placement` ('midpoint', 'target', 'source' or 'given' with position); returns the surviving vertex. Deleted slots stay until collect_garbage().
        """

    def triangulate_faces(self, *, delaunay: bool = False) -> TriangulateResult:
        """
        Triangulates every polygon (inner rings included, robust on concave faces); with delaunay=True each face's diagonals are its constrained Delaunay ones (largest smallest angle). Returns a TriangulateResult (faces_cut, triangles_added).
        """

    def fill_hole(self, boundary_halfedge: int, *, max_dynamic_programming_edges: int = 200, refine: bool = False, fair: str = 'none') -> list[int]:
        """
        Closes the boundary loop of a boundary halfedge with triangles (minimal area, maximal dihedral, Liepa 2003); with refine=True the patch is refined to the edge length around the hole, and fair='membrane' or 'thin-plate' (implies refine) smooths it. Returns the new faces.
        """

    def fill_holes(self, max_edges: int = 1000, *, max_dynamic_programming_edges: int = 200, refine: bool = False, fair: str = 'none') -> FillHolesResult:
        """
        Fills every hole of at most max_edges boundary edges (the CLI's --max-edges and default) (refine and fair as for fill_hole); returns a FillHolesResult (filled, skipped, faces_added, vertices_added, unfaired, open), 'open' listing each hole left open as an OpenHole (vertex, edges, reason). Ctrl-C stops it with the mesh unchanged.
        """

    def subdivide(self, *, scheme: str = 'loop', levels: int = 1) -> SubdivideResult:
        """
        Subdivides `levels` times with `scheme`: 'loop' or 'sqrt3' (triangle meshes) or 'catmull-clark' (any
        polygon mesh), boundaries included; returns the counts after the last level
        (a SubdivideResult). 'sqrt3' refines the
        boundary on every second level of a call, so give it an even `levels` for a smooth boundary.

        >>> m = hmira.Mesh([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], [[0, 1, 2, 3]])
        >>> m.subdivide(scheme='catmull-clark')
        SubdivideResult(vertices=9, edges=12, faces=4)
        """

    def laplacian_smooth(self, *, iterations: int = 1, lambda_: float = 0.5, weights: str = 'uniform', fix_boundary: bool = True, fixed_vertices: Sequence[int] | None = None, refresh_weights: bool = True, threads: int = 0) -> int:
        """
        Laplacian smoothing (uniform or cotangent weights, step lambda_ in (0, 1]); returns the number of vertices free to move. refresh_weights: recompute cotangent weights before every step (False: once). threads: worker threads (0: all); the result does not depend on it.
        """

    def taubin_smooth(self, *, iterations: int = 10, lambda_: float = 0.5, mu: float = -0.53, weights: str = 'uniform', fix_boundary: bool = True, fixed_vertices: Sequence[int] | None = None, refresh_weights: bool = True, threads: int = 0) -> int:
        """
        Taubin lambda/mu smoothing (keeps the volume); returns the number of vertices free to move.
        refresh_weights and threads as in laplacian_smooth.
        """

    def decimate(self, *, target_faces: int | None = None, target_ratio: float | None = None, max_error: float | None = None, fix_boundary: bool = True, max_normal_angle: float = 120.0, max_aspect_ratio: float = float('inf'), fixed_vertices: Sequence[int] | None = None, min_angle: float = 1.0, area_weighted: bool = True, feature_angle: float | None = None, feature_edges: Sequence[int] | None = None, keep_features: bool = False) -> DecimateResult:
        """
        Quadric error decimation (Garland-Heckbert) until the first target reached: target_faces, target_ratio
        (of the faces) or max_error (a distance). Polygons are triangulated first. Boundary vertices stay
        unless fix_boundary=False; fixed_vertices never move (the names smoothing uses; hmira.Mesh.decimate
        still takes keep_boundary and locked_vertices, deprecated). feature_angle (degrees) and feature_edges
        add planes through creases; keep_features keeps feature lines on their input vertices.
        Returns a DecimateResult (faces, vertices, collapses,
        triangulated, stopped_by, error, note); vertices are renumbered densely afterwards.

        >>> m = hmira.Mesh([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0.5, 0.5, 0]],
        ...                [[0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]])
        >>> m.decimate(target_faces=2).faces
        2
        """

    def remesh(self, *, target_edge_length: float | None = None, iterations: int = 5, feature_angle: float | None = None, feature_edges: Sequence[int] | None = None) -> RemeshResult:
        """
        Isotropic remeshing of a triangle mesh towards target_edge_length (default: the mean edge length):
        `iterations` rounds of split, collapse, flip and tangential relaxation with projection onto the input.
        The boundary is kept, and so are edges sharper than feature_angle degrees and the edges listed in
        feature_edges (edge indices). Returns a RemeshResult (splits, collapses, flips, feature_edges).

        >>> m = hmira.Mesh([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], [[0, 1, 2], [0, 2, 3]])
        >>> m.remesh(target_edge_length=0.25).feature_edges
        4
        """

    def write(self, path: str, *, ascii: bool = False, big_endian: bool = False, float32: bool = False, attributes: bool = True) -> None:
        """
        Write the mesh to a file (OBJ, OFF, PLY, STL, glTF .glb or .gltf by extension), atomically.

        Parameters
        ----------
        path : str
        ascii : bool, keyword-only
            PLY/STL: text instead of binary.
        big_endian : bool, keyword-only
            PLY: binary big endian.
        float32 : bool, keyword-only
            PLY: 32-bit coordinates (default 64-bit).
        attributes : bool, keyword-only
            Write per-vertex normals and colours read from a file.
        """

    @property
    def vertex_count(self) -> int:
        """Live vertices."""

    @property
    def edge_count(self) -> int:
        """Live edges."""

    @property
    def face_count(self) -> int:
        """Live faces."""

    @property
    def faces(self) -> Annotated[NDArray[numpy.int32], dict(shape=(None, None))]:
        """Faces as an (m, k) int32 array (ValueError when faces differ in size)."""

    @property
    def polygons(self) -> list:
        """Faces as a list of vertex-index lists."""

    def topology(self) -> Topology:
        """V, E, F, genus, components and boundary loops (a Topology)."""

    def validate(self, *, relaxed: bool = False) -> list[str]:
        """The mesh's problems, one message each; an empty list for a valid mesh."""

    def flip(self) -> int:
        """Reverse every face's winding; returns the faces flipped."""

    def vertex_normals(self, *, weighting: str = 'angle') -> Annotated[NDArray[numpy.float64], dict(shape=(None, None))]:
        """
        Unit vertex normals (n, 3), faces weighted by corner angle ('angle') or area ('area').
        """

    def collect_garbage(self) -> None:
        """Drop deleted elements and renumber densely (after kill operators)."""

    def find_halfedge(self, a: int, b: int) -> int:
        """The halfedge from vertex a to vertex b, or -1."""

    def make_vertex(self, position: Sequence[float]) -> int:
        """makeV: a new isolated vertex; returns its index."""

    def make_edge_vertex(self, corner: int, position: Sequence[float]) -> tuple[int, int]:
        """
        makeEV: a new vertex joined to target(corner); returns (vertex, halfedge from the old vertex to the new).
        """

    def kill_edge_vertex(self, halfedge: int) -> tuple[int, int, tuple[float, float, float]]:
        """
        killEV: removes the edge and its degree-1 target; returns (vertex, corner, position) for the redo.
        """

    def make_edge_face(self, h0: int, h1: int) -> tuple[int, int]:
        """
        makeEF: splits a face by an edge from target(h0) to target(h1); returns (halfedge, face).
        """

    def kill_edge_face(self, halfedge: int) -> tuple[int, int, int]:
        """
        killEF: removes the edge, merging its two faces; returns (face, h0, h1) for make_edge_face.
        """

    def self_intersections(self) -> NDArray[numpy.int64]:
        """
        The pairs of faces that intersect other than along a shared edge or vertex (touching, crossing, folded or overlapping in one plane), decided exactly: a (k, 2) int64 array of face indices, each row (f, g) with f < g, rows sorted. Polygon faces are tested by their triangles.

        Examples
        --------
        >>> import numpy as np, hmira
        >>> v = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [.2, .2, -1], [.3, .2, 1], [.2, .3, 1]], float)
        >>> hmira.Mesh(v, [[0, 1, 2], [3, 4, 5]]).self_intersections().tolist()
        [[0, 1]]
        """

    def closest_point(self, points: Annotated[NDArray, dict(shape=(None, None), device='cpu', writable=False)], *, max_distance: float = float('inf'), threads: int = 0, nan: str = 'raise') -> tuple:
        """
        The closest surface point to each query point.

        Parameters
        ----------
        points : ndarray, shape (n, 3), float64 or float32
        max_distance : float
            Look no farther; a point with nothing that close gets face -1 and distance inf.
        threads : int
            Worker threads (0: all). The answers do not depend on it.
        nan : {'raise', 'propagate'}
            A query with a NaN or infinite coordinate raises ValueError naming its index, or gets NaN
            point and distance and face -1.

        Returns
        -------
        points : ndarray (n, 3) float64
        faces : ndarray (n,) int64
            The face each point lies on (-1 if none).
        barycentrics : ndarray (n, 3) float64
            Weights on the corners of the triangle of that face's triangulation the point lies on.
        distances : ndarray (n,) float64

        Builds a BVH on every call: keep an hmira.BVH to query the same mesh again.

        Examples
        --------
        >>> import hmira, numpy as np
        >>> m = hmira.Mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]])
        >>> points, faces, bary, dist = m.closest_point(np.array([[0.2, 0.2, 1.0]]))
        >>> faces.tolist(), dist.tolist()
        ([0], [1.0])
        """

    def ray_intersect(self, origins: Annotated[NDArray, dict(shape=(None, None), device='cpu', writable=False)], directions: Annotated[NDArray, dict(shape=(None, None), device='cpu', writable=False)], *, mode: str = 'first', threads: int = 0, nan: str = 'raise') -> object:
        """
        Intersects rays origin + t * direction (t >= 0) with the surface.

        Parameters
        ----------
        origins, directions : ndarray, shape (n, 3), float64 or float32
        mode : {'first', 'any'}
            'first': the nearest hit of each ray; 'any': whether it hits at all (occlusion, faster).
        threads : int
            Worker threads (0: all).
        nan : {'raise', 'propagate'}
            A ray with a non-finite coordinate raises ValueError naming its index, or gets a NaN t.

        Returns
        -------
        mode 'first': (t, faces, barycentrics, points): t (n,) (inf for a miss), faces (n,) int64
        (-1 for a miss), barycentrics (n, 3), points (n, 3). mode 'any': a bool array (n,).
        Degenerate (zero-area) triangles are never hit.

        Builds a BVH on every call: keep an hmira.BVH to query the same mesh again.

        Examples
        --------
        >>> import hmira, numpy as np
        >>> m = hmira.Mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]])
        >>> t, faces, bary, points = m.ray_intersect(np.array([[0.2, 0.2, 1.0]]), np.array([[0.0, 0.0, -1.0]]))
        >>> t.tolist(), faces.tolist()
        ([1.0], [0])
        """

    def bounds(self) -> Annotated[NDArray[numpy.float64], dict(shape=(None, None))]:
        """
        The bounding box as a (2, 3) float64 array [min, max]; (0, 3) without vertices.
        """

    def area(self) -> float:
        """The total area of the faces."""

    def volume(self) -> float:
        """
        The signed enclosed volume (divergence theorem): positive for a closed mesh wound counter-clockwise seen from outside, negative when inside-out.
        """

    def face_normals(self) -> Annotated[NDArray[numpy.float64], dict(shape=(None, None))]:
        """Unit face normals (m, 3) in face order; zero for a face of zero area."""

    def face_areas(self) -> Annotated[NDArray[numpy.float64], dict(shape=(None,))]:
        """Face areas (m,) in face order."""

    def edges(self) -> Annotated[NDArray[numpy.int32], dict(shape=(None, None))]:
        """
        Each edge once as (k, 2) int32 vertex indices, the smaller index first.
        """

    def winding_number(self, points: Annotated[NDArray, dict(device='cpu', writable=False)], *, method: str = 'fast', beta: float = 2.0, nan: str = 'error', threads: int = 0) -> object:
        """
        Generalised winding numbers at points (k, 3) (see hmira.winding_number).
        """

    def contains(self, points: Annotated[NDArray, dict(device='cpu', writable=False)], *, beta: float = 2.0, nan: str = 'error', threads: int = 0) -> NDArray[numpy.bool_]:
        """
        Whether each point (k, 3) is inside: winding number at least 1/2 (a bool array).
        """

    def signed_distance(self, points: Annotated[NDArray, dict(device='cpu', writable=False)], *, sign: str = 'winding_number', beta: float = 2.0, nan: str = 'error', threads: int = 0) -> object:
        """
        Signed distances from points (k, 3), negative inside (see hmira.signed_distance).
        """

    def sample_surface(self, count: int, *, method: str = 'uniform', seed: int = 0) -> dict:
        """
        count points on the surface, 'uniform' by area or 'poisson_disk' (blue noise), the same for the same seed: {'points' (count, 3), 'faces' (count,), 'barycentrics' (count, 3), 'corners' (count, 3)}: point i is sum over k of barycentrics[i, k] * vertex corners[i, k].
        """

class BVH:
    """
    A bounding-volume hierarchy over a Mesh's faces (polygons triangulated in their plane), for
    repeated batched closest-point and ray queries.

    The tree copies the triangles; a query after the mesh's connectivity changed raises
    ValueError. Positions moved in place (through Mesh.vertices) are not detected: call refit().

    Parameters
    ----------
    mesh : Mesh
        A mesh with at least one face.

    Examples
    --------
    >>> import hmira, numpy as np
    >>> m = hmira.Mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]])
    >>> bvh = hmira.BVH(m)
    >>> bvh.closest_point(np.array([[0.2, 0.2, 1.0]]))[3].tolist()
    [1.0]
    """

    def __init__(self, mesh: object) -> None: ...

    @property
    def triangle_count(self) -> int:
        """Number of triangles in the tree."""

    def refit(self) -> None:
        """
        Recomputes the boxes from the mesh's current positions (after moving vertices), keeping the tree.
        """

    def closest_point(self, points: Annotated[NDArray, dict(shape=(None, None), device='cpu', writable=False)], *, max_distance: float = float('inf'), threads: int = 0, nan: str = 'raise') -> tuple:
        """
        The closest surface point to each query point.

        Parameters
        ----------
        points : ndarray, shape (n, 3), float64 or float32
        max_distance : float
            Look no farther; a point with nothing that close gets face -1 and distance inf.
        threads : int
            Worker threads (0: all). The answers do not depend on it.
        nan : {'raise', 'propagate'}
            A query with a NaN or infinite coordinate raises ValueError naming its index, or gets NaN
            point and distance and face -1.

        Returns
        -------
        points : ndarray (n, 3) float64
        faces : ndarray (n,) int64
            The face each point lies on (-1 if none).
        barycentrics : ndarray (n, 3) float64
            Weights on the corners of the triangle of that face's triangulation the point lies on.
        distances : ndarray (n,) float64
        """

    def ray_intersect(self, origins: Annotated[NDArray, dict(shape=(None, None), device='cpu', writable=False)], directions: Annotated[NDArray, dict(shape=(None, None), device='cpu', writable=False)], *, mode: str = 'first', threads: int = 0, nan: str = 'raise') -> object:
        """
        Intersects rays origin + t * direction (t >= 0) with the surface.

        Parameters
        ----------
        origins, directions : ndarray, shape (n, 3), float64 or float32
        mode : {'first', 'any'}
            'first': the nearest hit of each ray; 'any': whether it hits at all (occlusion, faster).
        threads : int
            Worker threads (0: all).
        nan : {'raise', 'propagate'}
            A ray with a non-finite coordinate raises ValueError naming its index, or gets a NaN t.

        Returns
        -------
        mode 'first': (t, faces, barycentrics, points): t (n,) (inf for a miss), faces (n,) int64
        (-1 for a miss), barycentrics (n, 3), points (n, 3). mode 'any': a bool array (n,).
        Degenerate (zero-area) triangles are never hit.
        """

def winding_number(vertices: Annotated[NDArray, dict(device='cpu', writable=False)], faces: Annotated[NDArray, dict(device='cpu', writable=False)], points: Annotated[NDArray, dict(device='cpu', writable=False)], *, method: str = 'fast', beta: float = 2.0, nan: str = 'error', threads: int = 0) -> object:
    """
    Generalised winding numbers of the triangles (vertices (n, 3), faces (m, 3)) at points (k, 3), float64 or float32: 1 inside a closed outward surface, 0 outside, robust on open and self-intersecting input. method 'fast' (Barill et al., accuracy beta > 1) or 'direct'. nan='error' raises ValueError naming a non-finite point; nan='propagate' gives NaN there.

    Example
    -------
    >>> import numpy as np, hmira
    >>> V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1.0]])
    >>> F = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
    >>> hmira.winding_number(V, F, np.array([[0.1, 0.1, 0.1], [2, 2, 2.0]])).round(3)
    array([1., 0.])
    """

def signed_distance(vertices: Annotated[NDArray, dict(device='cpu', writable=False)], faces: Annotated[NDArray, dict(device='cpu', writable=False)], points: Annotated[NDArray, dict(device='cpu', writable=False)], *, sign: str = 'winding_number', beta: float = 2.0, nan: str = 'error', threads: int = 0) -> object:
    """
    Signed distances from points (k, 3) to the triangles (vertices, faces), negative inside. sign 'winding_number' (robust on open, soup and flipped input), 'pseudo_normal' or 'parity'.
    """

def hausdorff_distance(a: object, b: object, *, per_triangle: int = 10, min_samples: int = 1000000, seed: int = 11400714819323198485, threads: int = 0) -> dict:
    """
    Sampled Hausdorff distance between two surfaces, each a Mesh or a (vertices, faces) pair: {'symmetric', 'a_to_b', 'b_to_a'}, each direction {'max', 'mean', 'rms', 'samples'}.
    """

def mesh_boolean(a: object, b: object, *, op: str = 'union') -> BooleanResult:
    """
    Union, intersection, difference (a minus b) or symmetric difference of two closed meshes, computed exactly (hmira::mesh_boolean).

    Parameters
    ----------
    a, b : Mesh or (vertices, faces)
        Closed (self-intersecting, nested or overlapping shells allowed: a point is inside where the winding number is positive); polygons are cut into triangles.
    op : str, keyword-only
        'union' (default), 'intersection', 'difference' or 'xor'.

    Returns
    -------
    BooleanResult
        mesh (a new Mesh of triangles; empty for an empty result; where the result touches itself along edges, as an xor of overlapping meshes does along the intersection curve, those edges' vertices are split as read_mesh repairs, and mesh.repairs says so), origin_mesh (uint8 per output face: 0 for a, 1 for b), origin_face (int64 per output face: the face of that input it lies in), and the counts intersecting_pairs, cut_triangles, snapped_vertices, degenerate_faces, rounding_intersections.

    Raises
    ------
    ValueError
        An unknown op, a non-finite coordinate, a self-intersecting input that is not closed or has triangles overlapping in one plane.
    KeyboardInterrupt
        Ctrl-C; nothing is returned.

    Examples
    --------
    >>> import hmira
    >>> V = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]
    >>> F = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]
    >>> r = hmira.mesh_boolean(hmira.Mesh(V, F), hmira.Mesh(V, F), op='difference')
    >>> r.mesh.face_count, len(r.origin_face)
    (0, 0)
    """

def repair(mesh: object, *, solid: bool = True) -> BooleanResult:
    """
    The clean surface of the solid a closed mesh bounds (hmira::make_solid): self-intersections are cut exactly and only the boundary of the points the surface winds around (winding number > 0) is kept, so overlapping parts merge, a shell inside another disappears and an inward-turned shell stays a cavity.

    Parameters
    ----------
    mesh : Mesh or (vertices, faces)
        Closed (every edge used as often in one direction as in the other); polygons are cut into triangles.
    solid : bool, keyword-only
        True (default): make_solid. False: the mesh as the readers' repair holds it (a copy).

    Returns
    -------
    BooleanResult
        mesh (a new Mesh of triangles, closed and consistently oriented; empty when nothing is inside), origin_mesh (all 0), origin_face (int64 per output face: the input face it lies in), and the counts intersecting_pairs, cut_triangles, snapped_vertices, degenerate_faces, rounding_intersections.

    Raises
    ------
    ValueError
        A non-finite coordinate, an input that is not closed, triangles overlapping in one plane.
    KeyboardInterrupt
        Ctrl-C; nothing is returned.

    Examples
    --------
    >>> import hmira
    >>> V = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]
    >>> F = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]
    >>> r = hmira.repair(hmira.Mesh(V, F))
    >>> r.mesh.face_count, r.cut_triangles
    (4, 0)
    """
