"""Tests of what the package adds around decompose(): the parts and the hierarchy of a
Decomposition, mesh objects as input, decompose_bytes(), and the type stubs."""

import ast
import io
import os
import re
import struct
import tempfile

import numpy as np
import pytest

import part_decomposition as pd
from test_part_decomposition import DATA, FAST, read_off, write_glb, write_off


@pytest.fixture(scope="module")
def dumbbell():
    return read_off(os.path.join(DATA, "dumbbell.off"))


@pytest.fixture(scope="module")
def animal():
    return pd.decompose_file(os.path.join(DATA, "animal.off"), **FAST)


def test_parts_and_part_faces_follow_the_labels(animal):
    r = animal
    parts = r.parts()
    assert len(parts) == r.number_of_parts
    for k, faces in enumerate(parts):
        assert faces.dtype == np.int64 and len(faces) > 0
        assert (np.diff(faces) > 0).all()
        assert (r.labels[faces] == k).all()
        assert np.array_equal(r.part_faces(k), faces)
    # together, every face once
    assert np.array_equal(np.sort(np.concatenate(parts)), np.arange(len(r.labels)))
    for k in (-1, r.number_of_parts):
        with pytest.raises(IndexError, match="out of range"):
            r.part_faces(k)


def coarser_part_of(fine, coarse):
    """The part of `coarse` holding each part of `fine`; AssertionError if one straddles two."""
    base = coarse.max() + 1
    pairs = np.unique(fine * base + coarse)  # one per (fine, coarse) pair, by fine part
    assert len(pairs) == fine.max() + 1, "a finer part lies in several coarser parts"
    return pairs % base


def test_the_levels_nest_down_to_the_leaves(animal):
    r = animal
    levels = r.levels
    assert isinstance(levels, range) and levels.start == 1 and levels.step == 1
    assert r.number_of_parts in levels and len(levels) > r.number_of_parts  # finer levels exist
    previous = None
    for k in levels:
        labels = r.labels_at(k)
        assert labels.dtype == np.int64 and labels.shape == r.labels.shape
        assert np.array_equal(np.unique(labels), np.arange(k))
        if previous is not None:
            # one merge from level k to level k - 1: one part is made of two, the others stay
            counts = np.bincount(coarser_part_of(labels, previous), minlength=k - 1)
            assert sorted(counts) == [1] * (k - 2) + [2]
        previous = labels
    for k in (0, len(levels) + 1):
        with pytest.raises(ValueError, match="levels are 1 to"):
            r.labels_at(k)


def test_the_default_parts_are_a_level(animal):
    r = animal
    # the same parts, numbered alike (by their first face)
    assert np.array_equal(r.labels_at(r.number_of_parts), r.labels)
    # coarser levels merge default parts, finer levels split them
    coarse = r.labels_at(max(1, r.number_of_parts - 2))
    coarser_part_of(r.labels, coarse)
    coarser_part_of(r.labels_at(len(r.levels)), r.labels)


def test_labels_at_is_decompose_with_that_number_of_parts(dumbbell):
    vertices, faces = dumbbell
    r = pd.decompose(vertices, faces, **FAST)
    for k in sorted({1, 2, r.number_of_parts, r.number_of_parts + 1, len(r.levels)}):
        fixed = pd.decompose(vertices, faces, number_of_parts=k, **FAST)
        assert fixed.number_of_parts == k
        assert np.array_equal(fixed.labels_at(k), fixed.labels)
        # one pass, one tree: a level of the default tree, below the default number of parts and beyond
        assert np.array_equal(r.labels_at(k), fixed.labels)
        assert fixed.levels == r.levels


def test_the_grid_keywords_reach_the_library(dumbbell):
    vertices, faces = dumbbell
    # the paper's dense grid, and an adaptive grid whose finest leaves are coarser: parts and hierarchy
    for keywords in ({"method_variant": "adaptive_grid=false"}, {"grid_resolution": 64}):
        r = pd.decompose(vertices, faces, **keywords, **FAST)
        assert r.labels.shape == (len(faces),) and r.number_of_parts in r.levels
        assert np.array_equal(r.labels_at(r.number_of_parts), r.labels)
    # a power of two up to 256 (raised to the finest voxel resolution when below it)
    coarse = pd.decompose(vertices, faces, grid_resolution=16, **FAST)
    assert np.array_equal(coarse.labels, pd.decompose(vertices, faces, grid_resolution=32, **FAST).labels)
    for bad in (0, 96, 512):
        with pytest.raises(pd.InvalidInput, match="grid_resolution"):
            pd.decompose(vertices, faces, grid_resolution=bad, **FAST)
    with pytest.raises(ValueError, match="method_variant"):
        pd.decompose(vertices, faces, method_variant="adaptive_grid=no", **FAST)
    with pytest.raises(TypeError, match="grid_resolution"):
        pd.decompose(vertices, faces, grid_resolution="no", **FAST)


class TrackedArray(np.ndarray):
    """Stands for trimesh's ndarray subclass."""


class TrimeshLike:
    """The attributes of trimesh.Trimesh that matter: .triangles are corner coordinates there."""

    def __init__(self, vertices, faces):
        self.vertices = vertices.view(TrackedArray)
        self.faces = faces.view(TrackedArray)
        self.triangles = vertices[faces]


class Vector:
    """Stands for Open3D's Vector3dVector and Vector3iVector: no ndarray, but numpy.asarray works."""

    def __init__(self, values):
        self._values = [tuple(v) for v in values.tolist()]
        self._dtype = values.dtype

    def __len__(self):
        return len(self._values)

    def __array__(self, dtype=None):
        return np.array(self._values, dtype=dtype or self._dtype)


class Open3DLike:
    def __init__(self, vertices, faces):
        self.vertices = Vector(vertices)
        self.triangles = Vector(faces.astype(np.int32))


def test_mesh_objects_give_the_labels_of_their_arrays(dumbbell):
    vertices, faces = dumbbell
    expected = pd.decompose(vertices, faces, **FAST).labels
    assert np.array_equal(pd.decompose(TrimeshLike(vertices, faces), **FAST).labels, expected)
    assert np.array_equal(pd.decompose(Open3DLike(vertices, faces), **FAST).labels, expected)
    with pytest.raises(TypeError, match="triangles"):
        pd.decompose(object())
    half = TrimeshLike(vertices, faces)
    del half.faces, half.triangles
    with pytest.raises(TypeError, match="TrimeshLike"):
        pd.decompose(half)


def write_obj(path, vertices, faces):
    with open(path, "w") as f:
        f.writelines("v %r %r %r\n" % tuple(v) for v in vertices.tolist())
        f.writelines("f %d %d %d\n" % tuple(t) for t in (faces + 1).tolist())


def write_ply(path, vertices, faces):
    with open(path, "w") as f:
        f.write("ply\nformat ascii 1.0\nelement vertex %d\nproperty double x\nproperty double y\n"
                "property double z\nelement face %d\nproperty list uchar int vertex_indices\nend_header\n"
                % (len(vertices), len(faces)))
        f.writelines("%r %r %r\n" % tuple(v) for v in vertices.tolist())
        f.writelines("3 %d %d %d\n" % tuple(t) for t in faces.tolist())


def write_stl(path, vertices, faces):
    """Binary STL: float32 corners, no shared vertices."""
    with open(path, "wb") as f:
        f.write(b"\0" * 80 + struct.pack("<I", len(faces)))
        for t in faces:
            f.write(struct.pack("<12fH", 0, 0, 0, *vertices[t].ravel(), 0))


def test_decompose_bytes_gives_the_labels_of_decompose_file(dumbbell):
    vertices, faces = dumbbell
    expected = pd.decompose(vertices, faces, **FAST).labels
    writers = {"off": write_off, "obj": write_obj, "ply": write_ply, "stl": write_stl,
               "glb": lambda p, v, f: write_glb(p, [(v.astype(np.float32), f.astype(np.uint32))], [{"mesh": 0}], [0])}
    assert set(writers) == set(pd.FORMATS)
    with tempfile.TemporaryDirectory() as d:
        for kind, write in writers.items():
            path = os.path.join(d, "dumbbell." + kind)
            write(path, vertices, faces)
            with open(path, "rb") as f:
                data = f.read()
            from_bytes = pd.decompose_bytes(data, kind, **FAST)
            assert np.array_equal(from_bytes.labels, pd.decompose_file(path, **FAST).labels), kind
            if kind in ("off", "obj", "ply"):  # the same doubles as the arrays
                assert np.array_equal(from_bytes.labels, expected), kind
    # any bytes-like object or binary file, any spelling of the format
    data = open(os.path.join(DATA, "dumbbell.off"), "rb").read()
    for contents, kind in ((bytearray(data), "OFF"), (memoryview(data), ".off"), (io.BytesIO(data), "off")):
        assert np.array_equal(pd.decompose_bytes(contents, kind, **FAST).labels, expected)


def test_decompose_bytes_refuses_what_it_cannot_read():
    data = open(os.path.join(DATA, "dumbbell.off"), "rb").read()
    for kind in ("gltf", "xyz", ""):
        with pytest.raises(ValueError, match="format must be one of 'glb', 'obj', 'off', 'ply', 'stl'"):
            pd.decompose_bytes(data, kind)
    with pytest.raises(TypeError, match="encode"):
        pd.decompose_bytes(data.decode(), "off")
    with pytest.raises(TypeError):
        pd.decompose_bytes(12, "off")
    with pytest.raises(ValueError, match="cannot parse <off data>") as e:
        pd.decompose_bytes(b"OFF\nthis is not a mesh\n", "off")
    assert tempfile.gettempdir() not in str(e.value)
    with pytest.raises(TypeError, match="freeze_ration"):
        pd.decompose_bytes(data, "off", freeze_ration=0.2)


def stub_definitions(tree):
    """The names a stub body defines, each with its node and whether a docstring follows it."""
    body = tree.body
    found = {}
    for i, node in enumerate(body):
        if isinstance(node, (ast.ClassDef, ast.FunctionDef)):
            found[node.name] = ast.get_docstring(node) is not None
        elif isinstance(node, ast.AnnAssign):
            nxt = body[i + 1] if i + 1 < len(body) else None
            found[node.target.id] = (isinstance(nxt, ast.Expr) and isinstance(nxt.value, ast.Constant)
                                     and isinstance(nxt.value.value, str))
    return found


def test_the_stubs_document_the_public_api():
    package = os.path.dirname(pd.__file__)
    assert os.path.isfile(os.path.join(package, "py.typed"))
    with open(os.path.join(package, "__init__.pyi")) as f:
        tree = ast.parse(f.read())
    top = stub_definitions(tree)
    public = {name for name in top if not name.startswith("_") or name == "__version__"}
    assert public == set(pd.__all__)
    assert all(hasattr(pd, name) for name in pd.__all__)
    assert all(top[name] for name in public), [name for name in public if not top[name]]
    classes = {node.name: node for node in tree.body if isinstance(node, ast.ClassDef)}
    for cls in (pd.Decomposition, pd.Primitive):
        members = stub_definitions(classes[cls.__name__])
        assert set(members) == {n for n in dir(cls) if not n.startswith("_")}, cls.__name__
        assert all(members.values()), cls.__name__
    assert pd.Decomposition.__module__ == "part_decomposition"


def test_the_version_is_the_projects():
    cmake = os.path.join(os.path.dirname(__file__), "..", "..", "CMakeLists.txt")
    with open(cmake) as f:
        version = re.search(r"project\(Part_decomposition\s+VERSION\s+([0-9.]+)", f.read()).group(1)
    assert pd.__version__ == version


def _glb_feature_ids_per_triangle(path):
    """The _FEATURE_ID_0 of the three corners of every triangle of a GLB, primitive by primitive,
    and the featureCount of each primitive."""
    data = open(path, "rb").read()
    assert data[:4] == b"glTF"
    json_length = struct.unpack_from("<I", data, 12)[0]
    import json
    doc = json.loads(data[20:20 + json_length])
    binary = data[20 + json_length + 8:]

    def read(accessor_index):
        a = doc["accessors"][accessor_index]
        view = doc["bufferViews"][a["bufferView"]]
        dtype = {5121: np.uint8, 5123: np.uint16, 5125: np.uint32, 5126: np.float32}[a["componentType"]]
        start = view.get("byteOffset", 0) + a.get("byteOffset", 0)
        stride = view.get("byteStride", np.dtype(dtype).itemsize)  # vertex attributes are 4-byte aligned
        rows = np.frombuffer(binary, dtype=np.uint8, count=stride * a["count"], offset=start).reshape(-1, stride)
        return rows[:, :np.dtype(dtype).itemsize].copy().view(dtype).ravel()

    corners, counts = [], []
    for mesh in doc["meshes"]:
        for p in mesh["primitives"]:
            ext = p["extensions"]["EXT_mesh_features"]["featureIds"][0]
            counts.append(ext["featureCount"])
            ids = read(p["attributes"]["_FEATURE_ID_%d" % ext["attribute"]])
            corners.append(ids[read(p["indices"]).astype(np.int64)].reshape(-1, 3))
    assert "EXT_mesh_features" in doc["extensionsUsed"]
    return np.concatenate(corners), counts


def test_write_labels_glb_puts_the_labels_on_the_triangles(animal):
    path = os.path.join(DATA, "animal.off")
    with tempfile.TemporaryDirectory() as d:
        out = os.path.join(d, "animal_labels.glb")
        pd.write_labels_glb(out, path, animal.labels)
        corners, counts = _glb_feature_ids_per_triangle(out)
        # each triangle carries its face's label at its three corners (the OFF has only triangles)
        assert counts == [animal.number_of_parts]
        assert np.array_equal(corners, np.repeat(animal.labels[:, None], 3, axis=1))
        with pytest.raises(ValueError):
            pd.write_labels_glb(out, path, animal.labels[:-1])
        with pytest.raises(ValueError):
            pd.write_labels_glb(out, path, animal.labels, number_of_labels=1)
