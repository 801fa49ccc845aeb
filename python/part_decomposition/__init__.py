"""Hi-TOPS part decomposition of triangle meshes (the CGAL package Part_decomposition).

    import part_decomposition as pd
    r = pd.decompose_file("animal.off")          # or pd.decompose(vertices, faces), pd.decompose(mesh)
    r.labels, r.number_of_parts, r.parts(), r.labels_at(3)
    pd.render_parts("animal.off", r.labels, "animal.png")   # the input beside its parts, as PNG

decompose() takes (n, 3) vertices and (m, 3) faces, or a mesh object with both (trimesh, Open3D);
decompose_file() a mesh file; decompose_bytes() the contents of one. Every keyword and its default
is in DEFAULTS; the type stubs (__init__.pyi) document the whole API.
"""

import io
import os
import tempfile

import numpy as np

from . import _core
from ._core import DEFAULTS, Decomposition, InvalidInput, Primitive, __version__, decompose_file, write_labels_glb

__all__ = ["DEFAULTS", "FORMATS", "Decomposition", "InvalidInput", "Primitive", "__version__", "decompose",
           "decompose_bytes", "decompose_file", "render_parts", "write_labels_glb"]

# the classes show, and pickle, under the package's name rather than its private core's
for _c in (Decomposition, InvalidInput, Primitive):
    _c.__module__ = __name__
del _c

#: The formats of decompose_bytes(): those of decompose_file() that fit in one buffer (a .gltf may
#: refer to other files).
FORMATS = ("glb", "obj", "off", "ply", "stl")


def _arrays_of(mesh):
    """The vertices and faces of a mesh object, as arrays; TypeError if it has not both."""
    vertices = getattr(mesh, "vertices", None)
    # trimesh's faces before .triangles, which trimesh uses for the corner coordinates
    faces = getattr(mesh, "faces", None)
    if faces is None:
        faces = getattr(mesh, "triangles", None)  # Open3D
    if vertices is None or faces is None:
        raise TypeError("decompose() takes vertices and faces, or a mesh with .vertices and .faces (trimesh) or "
                        ".triangles (Open3D); got one %s" % type(mesh).__name__)
    return np.asarray(vertices), np.asarray(faces)


def decompose(vertices, faces=None, **parameters):
    if faces is None:
        vertices, faces = _arrays_of(vertices)
    return _core.decompose(vertices, faces, **parameters)


decompose.__doc__ = """decompose(vertices, faces, **parameters) -> Decomposition
decompose(mesh, **parameters) -> Decomposition

Decomposes the triangle mesh given by vertices, an (n, 3) float array, and faces, an (m, 3)
integer array of vertex indices, or by a mesh object with the two: .vertices and .faces
(trimesh.Trimesh) or .vertices and .triangles (open3d.geometry.TriangleMesh), each convertible
with numpy.asarray. labels has one part per row of faces. Load a file with trimesh.load(path,
process=False) to keep its faces and their order (process=True merges and drops faces), or give
the file to decompose_file().

The mesh is built as the package's reader builds it from a file (equal vertices merged, border
vertices within weld_tolerance of the bounding box diagonal welded, the soup oriented, closed
pieces outward). Runs with the GIL released, on `threads` threads (default: all cores; the labels
do not depend on it). Raises ValueError (InvalidInput for the library's checks) for a bad array or
a parameter out of its range, TypeError for an unknown keyword or an object without a mesh.

Keywords (the named parameters of CGAL::Part_decomposition::decompose(), and of the reader for
weld_tolerance), with defaults:
""" + _core._keyword_documentation


def decompose_bytes(data, format, **parameters):
    """decompose_bytes(data, format, **parameters) -> Decomposition

    Decomposes the mesh file held in memory: data is its contents (bytes, bytearray, memoryview or
    a binary file object such as io.BytesIO), format its type, one of FORMATS ("glb", "obj", "off",
    "ply", "stl"; case and a leading dot do not matter). The labels are those of decompose_file()
    on the same file. Same keywords as decompose(). Raises ValueError for an unknown format or
    contents that cannot be parsed, TypeError for text (encode it first).
    """
    kind = str(format).lower().lstrip(".")
    if kind not in FORMATS:
        raise ValueError("format must be one of %s, got %r" % (", ".join(repr(f) for f in FORMATS), format))
    if isinstance(data, io.TextIOBase) or isinstance(data, str):
        raise TypeError("data must be bytes (or a binary file object), got text: encode it first")
    if hasattr(data, "read"):
        data = data.read()
    contents = memoryview(data)  # TypeError for what is not bytes-like
    # the reader reads files and chooses by extension: a private file with that extension
    with tempfile.TemporaryDirectory(prefix="part_decomposition_") as directory:
        path = os.path.join(directory, "mesh." + kind)
        with open(path, "wb") as f:
            f.write(contents)
        try:
            return decompose_file(path, **parameters)
        except ValueError as e:
            # the messages name the file, quoted or not: name the data instead
            message = str(e).replace("'%s'" % path, path).replace(path, "<%s data>" % kind)
            if message == str(e):
                raise
            raise type(e)(message) from None


def render_parts(mesh_or_path, labels, path, size=(640, 320)):
    """render_parts(mesh_or_path, labels, path, size=(640, 320)) -> None

    Draws the mesh in grey beside its parts in their colours (those of hitops --colored and
    --parts-glb) and writes the picture as a PNG file: the thumbnails of hitops --report, drawn by
    the package's own renderer, to look at a result without a 3D viewer. mesh_or_path is a mesh
    file (labels: one per face of the file, in its order, as decompose_file() gives them), a
    (vertices, faces) pair or a mesh object as decompose() takes them (labels: one per row of
    faces). labels may also be a Decomposition. size is (width, height) in pixels, each from 2 to
    4096. Raises ValueError for labels that do not fit the mesh, OSError if path cannot be written.
    """
    labels = np.asarray(getattr(labels, "labels", labels))
    size = tuple(int(x) for x in size)
    if len(size) != 2:
        raise ValueError("size must be (width, height), got %r" % (size,))
    if isinstance(mesh_or_path, (str, os.PathLike)):
        png = _core._render_file_png(mesh_or_path, labels, size)
    else:
        if isinstance(mesh_or_path, (tuple, list)) and len(mesh_or_path) == 2:
            vertices, faces = (np.asarray(a) for a in mesh_or_path)
        else:
            vertices, faces = _arrays_of(mesh_or_path)
        png = _core._render_arrays_png(vertices, faces, labels, size)
    with open(path, "wb") as f:
        f.write(png)
