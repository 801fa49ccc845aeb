"""Hi-TOPS part decomposition of triangle meshes (the CGAL package Part_decomposition)."""

import os
from typing import IO, Any, Dict, List, Optional, Protocol, Tuple, Union, overload

import numpy as np
from numpy.typing import ArrayLike, NDArray

__version__: str
"""The version of the package, that of the CMake project Part_decomposition."""

DEFAULTS: Dict[str, Any]
"""Every keyword of decompose(), decompose_file() and decompose_bytes() with its default value
(None for number_of_parts and threads: the default granularity, all cores)."""

FORMATS: Tuple[str, ...]
"""The formats decompose_bytes() accepts: "glb", "obj", "off", "ply", "stl"."""

class InvalidInput(ValueError):
    """An input or parameter the library refuses (CGAL::Part_decomposition::Invalid_input); its
    message names the check."""

class Primitive:
    """The superquadric of one part, in the input's coordinates."""

    @property
    def center(self) -> NDArray[np.float64]:
        """(3,) the centre."""
    @property
    def rotation(self) -> NDArray[np.float64]:
        """(3, 3) the rotation, local to world: column j is the local axis j."""
    @property
    def scales(self) -> NDArray[np.float64]:
        """(3,) the semi-axes along the local axes."""
    @property
    def exponents(self) -> NDArray[np.float64]:
        """(2,) epsilon1 (along the local z axis) and epsilon2 (in the local xy plane)."""

class Decomposition:
    """The parts of a mesh: a label per input face, a primitive per part, and the part hierarchy."""

    @property
    def labels(self) -> NDArray[np.int64]:
        """(m,) the part of each input face, in [0, number_of_parts)."""
    @property
    def number_of_parts(self) -> int:
        """The number of parts."""
    @property
    def primitives(self) -> List[Primitive]:
        """One Primitive per part: part k is explained by primitives[k]."""
    @property
    def timings(self) -> Dict[str, float]:
        """Wall-clock seconds: read (the mesh from the file or arrays) and each stage of decompose()."""
    def parts(self) -> List[NDArray[np.int64]]:
        """One array per part: the input faces of part k, increasing (those where labels == k)."""
    def part_faces(self, k: int) -> NDArray[np.int64]:
        """The input faces of part k, increasing. Raises IndexError unless 0 <= k < number_of_parts."""
    @property
    def levels(self) -> range:
        """The numbers of parts labels_at() accepts, range(1, L + 1) for a hierarchy of L leaves
        (the finest parts). number_of_parts is one of them."""
    def labels_at(self, k: int) -> NDArray[np.int64]:
        """(m,) the part of each input face at level k of the part hierarchy: k parts, those of
        decompose(..., number_of_parts=k), numbered alike. A level is the union of parts of every
        finer level; labels_at(number_of_parts) is labels. Raises ValueError unless k is in levels."""

class _MeshWithFaces(Protocol):
    """A mesh as trimesh.Trimesh gives it."""

    vertices: ArrayLike
    faces: ArrayLike

class _MeshWithTriangles(Protocol):
    """A mesh as open3d.geometry.TriangleMesh gives it."""

    vertices: ArrayLike
    triangles: ArrayLike

@overload
def decompose(vertices: ArrayLike, faces: ArrayLike, **parameters: Any) -> Decomposition:
    """Decomposes the triangle mesh of vertices, an (n, 3) float array, and faces, an (m, 3) integer
    array of vertex indices: labels has one part per row of faces. Keywords: those of DEFAULTS.
    Raises ValueError (InvalidInput for the library's checks) for a bad array or parameter,
    TypeError for an unknown keyword."""

@overload
def decompose(vertices: Union[_MeshWithFaces, _MeshWithTriangles], faces: None = None,
              **parameters: Any) -> Decomposition:
    """Decomposes a mesh object: its .vertices and .faces (trimesh; load with process=False to
    keep the faces of the file) or .vertices and .triangles (Open3D), converted with
    numpy.asarray. Raises TypeError for an object without them."""

def decompose_file(path: Union[str, os.PathLike[str]], **parameters: Any) -> Decomposition:
    """Reads the mesh file (OFF, OBJ, PLY, STL, glTF .gltf/.glb) with the package's reader and
    decomposes it: the labels are in the file's face order, as written by hitops --labels. Same
    keywords as decompose(); ValueError for a file that cannot be opened or parsed."""

def decompose_bytes(data: Union[bytes, bytearray, memoryview, IO[bytes]], format: str,
                    **parameters: Any) -> Decomposition:
    """Decomposes the mesh file held in memory: data is its contents, format one of FORMATS (case
    and a leading dot do not matter). The labels are those of decompose_file() on the same file.
    Raises ValueError for an unknown format or contents that cannot be parsed, TypeError for text."""

def write_labels_glb(output: Union[str, os.PathLike[str]], input: Union[str, os.PathLike[str]],
                     labels: ArrayLike, number_of_labels: Optional[int] = None) -> None:
    """Writes the mesh file input (any format of decompose_file()) as a binary glTF file output,
    with the label of every face as an EXT_mesh_features feature ID (vertex attribute
    _FEATURE_ID_0); a glTF input keeps its scene, materials and textures. labels has one entry
    per face in the file's order, as decompose_file() gives them; number_of_labels (the
    featureCount) defaults to max(labels) + 1. Raises ValueError for labels that do not fit."""

def render_parts(mesh_or_path: Union[str, os.PathLike[str], Tuple[ArrayLike, ArrayLike], _MeshWithFaces,
                                     _MeshWithTriangles],
                 labels: Union[ArrayLike, Decomposition], path: Union[str, os.PathLike[str]],
                 size: Tuple[int, int] = (640, 320)) -> None:
    """Writes a PNG picture of the mesh in grey beside its parts in their colours (those of hitops
    --colored), drawn by the package's own renderer (the thumbnails of hitops --report).
    mesh_or_path: a mesh file (labels in its face order, as decompose_file() gives them), a
    (vertices, faces) pair or a mesh object (labels: one per row of faces); labels may be a
    Decomposition. size: (width, height) in pixels, each from 2 to 4096. Raises ValueError for
    labels that do not fit the mesh, OSError if path cannot be written."""
