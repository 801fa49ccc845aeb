"""Tests of the Python package part_decomposition: arrays and mesh objects in, labels out, parts and
the hierarchy, parameters, errors, and the same labels as the hitops tool. Run by ctest (test
python_pytest), which sets PYTHONPATH to the package in the build tree, PD_EXAMPLE_DATA_DIR to the
shipped meshes and PD_HITOPS to the hitops tool, and by install_and_test.sh on the installed package."""

import json
import os
import struct
import subprocess
import tempfile
import threading
import time

import numpy as np
import pytest

import part_decomposition as pd

DATA = os.environ.get(
    "PD_EXAMPLE_DATA_DIR",
    os.path.join(os.path.dirname(__file__), "..", "..", "examples", "Part_decomposition", "data"))
HITOPS = os.environ.get("PD_HITOPS")

# Coarse grids keep each call well under a second; the code paths are those of the defaults.
FAST = {"voxel_resolutions": [16, 32], "number_of_points_per_face": 9}


def read_off(path):
    """The vertices and triangles of a plain OFF file, as numpy arrays."""
    with open(path) as f:
        tokens = f.read().split()
    assert tokens[0] == "OFF"
    nv, nf = int(tokens[1]), int(tokens[2])
    values = tokens[4:]
    vertices = np.array(values[:3 * nv], dtype=np.float64).reshape(nv, 3)
    faces = np.array(values[3 * nv:3 * nv + 4 * nf], dtype=np.int64).reshape(nf, 4)
    assert (faces[:, 0] == 3).all()
    return vertices, faces[:, 1:]


def box(lo, hi):
    """A closed box as 8 vertices and 12 outward triangles."""
    x = np.array([[lo[0], lo[1], lo[2]], [hi[0], lo[1], lo[2]], [hi[0], hi[1], lo[2]], [lo[0], hi[1], lo[2]],
                  [lo[0], lo[1], hi[2]], [hi[0], lo[1], hi[2]], [hi[0], hi[1], hi[2]], [lo[0], hi[1], hi[2]]], dtype=np.float64)
    f = np.array([[0, 2, 1], [0, 3, 2], [4, 5, 6], [4, 6, 7], [0, 1, 5], [0, 5, 4],
                  [1, 2, 6], [1, 6, 5], [2, 3, 7], [2, 7, 6], [3, 0, 4], [3, 4, 7]])
    return x, f


@pytest.fixture(scope="module")
def dumbbell():
    return read_off(os.path.join(DATA, "dumbbell.off"))


def test_every_named_parameter_is_a_keyword_with_its_default():
    # the value parameters of the library's list (test_parameter_table checks the whole list), the
    # switches of the method as one keyword, and the module's own `threads`
    names = set(pd.DEFAULTS)
    assert len(names) >= 35 and {"threads", "verbose", "weld_tolerance", "method_variant"} <= names
    assert not {"use_density", "adaptive_grid", "use_pieces"} & names
    d = pd.DEFAULTS
    assert d["voxel_resolutions"] == [16, 32, 64]
    assert d["number_of_points_per_face"] == 36
    assert d["freeze_ratio"] == 0.15
    assert d["tsdf_sign_method"] == "automatic" and d["method_variant"] == "default"
    assert d["grid_resolution"] == 128
    assert d["number_of_parts"] is None and d["threads"] is None
    for name in names:
        assert name in pd.decompose.__doc__


def test_arrays_in_labels_out(dumbbell):
    vertices, faces = dumbbell
    r = pd.decompose(vertices, faces, **FAST)
    assert isinstance(r.labels, np.ndarray) and r.labels.dtype == np.int64
    assert r.labels.shape == (len(faces),)
    assert r.number_of_parts >= 2  # two balls and a bar
    assert r.labels.min() == 0 and r.labels.max() == r.number_of_parts - 1
    assert len(np.unique(r.labels)) == r.number_of_parts
    assert len(r.primitives) == r.number_of_parts
    lo, hi = vertices.min(axis=0), vertices.max(axis=0)
    for q in r.primitives:
        assert q.center.shape == (3,) and q.scales.shape == (3,) and q.exponents.shape == (2,)
        assert q.rotation.shape == (3, 3)
        assert np.allclose(q.rotation.T @ q.rotation, np.eye(3), atol=1e-9)
        assert (q.scales > 0).all()
        # in the input's coordinates: the centres lie in (a margin around) the bounding box
        assert (q.center > lo - 0.1 * (hi - lo)).all() and (q.center < hi + 0.1 * (hi - lo)).all()
    for stage in ("read", "prior", "tsdf", "fitting", "over_segmentation", "assignment", "total"):
        assert r.timings[stage] >= 0.0
    assert r.timings["total"] > 0.0


def test_arrays_of_any_numeric_type_and_lists(dumbbell):
    vertices, faces = dumbbell
    ref = pd.decompose(vertices, faces, **FAST).labels
    assert (pd.decompose(vertices.tolist(), faces.tolist(), **FAST).labels == ref).all()
    assert (pd.decompose(vertices, faces.astype(np.uint32), **FAST).labels == ref).all()
    assert (pd.decompose(np.asfortranarray(vertices), np.asfortranarray(faces), **FAST).labels == ref).all()


def test_arrays_and_file_give_the_same_labels(dumbbell):
    vertices, faces = dumbbell
    a = pd.decompose(vertices, faces, **FAST)
    b = pd.decompose_file(os.path.join(DATA, "dumbbell.off"), **FAST)
    assert (a.labels == b.labels).all()
    assert a.number_of_parts == b.number_of_parts


def test_a_face_with_a_repeated_vertex_takes_a_neighbours_label():
    x, f = box((0, 0, 0), (1, 1, 1))
    y, g = box((1.5, 0, 0), (2.5, 1, 1))
    vertices = np.vstack([x, y])
    faces = np.vstack([f, g + 8, [[0, 0, 1]]])
    r = pd.decompose(vertices, faces, **FAST)
    assert r.labels.shape == (25,)
    assert r.number_of_parts == 2
    assert len(set(r.labels[:12])) == 1 and len(set(r.labels[12:24])) == 1
    assert r.labels[24] == r.labels[0]


def test_threads_do_not_change_the_labels(dumbbell):
    vertices, faces = dumbbell
    labels = [pd.decompose(vertices, faces, threads=t, **FAST).labels for t in (1, 2, 3)]
    assert (labels[0] == labels[1]).all() and (labels[0] == labels[2]).all()


def test_explicit_defaults_are_the_defaults(dumbbell):
    vertices, faces = dumbbell
    ref = pd.decompose(vertices, faces, **FAST).labels
    explicit = {k: v for k, v in pd.DEFAULTS.items() if k not in FAST}
    assert (pd.decompose(vertices, faces, **FAST, **explicit).labels == ref).all()


def test_parameters_reach_the_library(dumbbell):
    vertices, faces = dumbbell
    # an out-of-range value is refused by the library, with its message
    with pytest.raises(ValueError, match="freeze_ratio"):
        pd.decompose(vertices, faces, freeze_ratio=2.0)
    with pytest.raises(pd.InvalidInput, match="voxel_resolutions"):
        pd.decompose(vertices, faces, voxel_resolutions=[16, 48])
    # a parameter that changes the result
    one = pd.decompose(vertices, faces, **FAST)
    coarse = pd.decompose(vertices, faces, voxel_resolutions=[16, 32], number_of_points_per_face=9,
                          minimum_part_area=0.4)
    assert coarse.number_of_parts < one.number_of_parts
    with pytest.raises(pd.InvalidInput, match="weld_tolerance"):
        pd.decompose(vertices, faces, weld_tolerance=0.5)
    for method in ("inside", "winding_number", "flood_fill", "ray_votes", "automatic"):
        r = pd.decompose(vertices, faces, tsdf_sign_method=method, **FAST)
        assert r.labels.shape == (len(faces),)
    pd.decompose(vertices, faces, method_variant="interior_weight_mode=mps", cue_weights=(1, 1, 0.5, 1), **FAST)
    # number_of_parts cuts the part hierarchy at exactly that many parts, each with its primitive
    for k in (1, 2, 3):
        r = pd.decompose(vertices, faces, number_of_parts=k, method_variant="keep_residual_patches=true", residual_tolerance=3.0, **FAST)
        assert r.labels.shape == (len(faces),)
        assert r.number_of_parts == k and len(np.unique(r.labels)) == k and len(r.primitives) == k


def test_keyword_errors(dumbbell):
    vertices, faces = dumbbell
    with pytest.raises(TypeError, match="freeze_ration"):
        pd.decompose(vertices, faces, freeze_ration=0.2)
    with pytest.raises(TypeError, match="freeze_ratio"):
        pd.decompose(vertices, faces, freeze_ratio="high")
    with pytest.raises(TypeError, match="cue_weights"):
        pd.decompose(vertices, faces, cue_weights="high")
    with pytest.raises(pd.InvalidInput, match="cue_weights must be 4 finite numbers"):
        pd.decompose(vertices, faces, cue_weights=[1, 1, 1])
    with pytest.raises(ValueError, match="method_variant"):
        pd.decompose(vertices, faces, method_variant="use_density=maybe")
    with pytest.raises(TypeError, match="number_of_neighbors"):
        pd.decompose(vertices, faces, number_of_neighbors=-3)
    with pytest.raises(ValueError, match="tsdf_sign_method"):
        pd.decompose(vertices, faces, tsdf_sign_method="guess")
    with pytest.raises(ValueError, match="number_of_parts"):
        pd.decompose(vertices, faces, number_of_parts=0)
    with pytest.raises(ValueError, match="threads"):
        pd.decompose(vertices, faces, threads=-1)
    with pytest.raises(TypeError):
        pd.decompose(vertices)


def test_bad_arrays_raise_value_error():
    x, f = box((0, 0, 0), (1, 1, 1))
    nan = x.copy()
    nan[3, 1] = np.nan
    with pytest.raises(ValueError, match=r"vertices\[3\]"):
        pd.decompose(nan, f)
    inf = x.copy()
    inf[0, 0] = np.inf
    with pytest.raises(ValueError, match="non-finite"):
        pd.decompose(inf, f)
    with pytest.raises(ValueError, match=r"\(n, 3\)"):
        pd.decompose(x[:, :2], f)
    with pytest.raises(ValueError, match=r"\(n, 3\)"):
        pd.decompose(x.ravel(), f)
    with pytest.raises(ValueError, match=r"\(m, 3\)"):
        pd.decompose(x, np.hstack([f, f[:, :1]]))
    with pytest.raises(ValueError, match="dtype"):
        pd.decompose(x, f.astype(np.float64))
    with pytest.raises(ValueError, match="vertices"):
        pd.decompose("not an array", f)
    bad = f.copy()
    bad[5, 2] = 8
    with pytest.raises(ValueError, match=r"faces\[5, 2\] = 8"):
        pd.decompose(x, bad)
    bad[5, 2] = -1
    with pytest.raises(ValueError, match=r"faces\[5, 2\] = -1"):
        pd.decompose(x, bad)
    with pytest.raises(ValueError, match="is not a vertex index"):
        pd.decompose(x, np.full((1, 3), 2**63 + 5, dtype=np.uint64))
    with pytest.raises(pd.InvalidInput, match="no face"):
        pd.decompose(x, np.zeros((0, 3), dtype=np.int64))
    with pytest.raises(pd.InvalidInput, match="three distinct"):
        pd.decompose(x, np.array([[0, 0, 1], [2, 2, 2]]))
    with pytest.raises(pd.InvalidInput, match="out of range"):
        pd.decompose(x * 1e31, f)


def test_bad_files_raise_value_error():
    with tempfile.TemporaryDirectory() as d:
        with pytest.raises(ValueError, match="cannot open"):
            pd.decompose_file(os.path.join(d, "missing.off"))
        for name, content in (("garbage.off", b"OFF\nthis is not a mesh\n"), ("lying.off", b"OFF\n3 1000000000 0\n"),
                              ("truncated.glb", b"glTF\x02\x00\x00\x00\xff\x00\x00\x00"), ("mesh.xyz", b"0 0 0\n")):
            path = os.path.join(d, name)
            with open(path, "wb") as f:
                f.write(content)
            with pytest.raises(ValueError, match="cannot parse"):
                pd.decompose_file(path)


def test_the_gil_is_released_while_decomposing(dumbbell):
    vertices, faces = dumbbell
    done = threading.Event()
    result = {}

    def work():
        result["r"] = pd.decompose(vertices, faces, voxel_resolutions=[16, 32, 64], threads=1)
        done.set()

    t = threading.Thread(target=work)
    start = time.perf_counter()
    t.start()
    ticks = 0
    while not done.is_set():
        ticks += 1
        time.sleep(0.001)
    t.join()
    elapsed = time.perf_counter() - start
    assert result["r"].labels.shape == (len(faces),)
    # with the GIL held by the worker this thread would not run until the end
    assert ticks >= min(20, 0.2 * elapsed / 0.001)


@pytest.mark.skipif(not HITOPS, reason="PD_HITOPS (the hitops tool) not given")
@pytest.mark.parametrize("name,options,keywords", [
    ("animal.off", [], {}),
    ("table.off", ["--freeze-ratio", "0.2", "--resolutions", "16,32"], {"freeze_ratio": 0.2, "voxel_resolutions": [16, 32]}),
])
def test_decompose_file_gives_the_labels_of_hitops(name, options, keywords):
    path = os.path.join(DATA, name)
    with tempfile.TemporaryDirectory() as d:
        seg = os.path.join(d, "out.seg")
        subprocess.run([HITOPS, path, "--labels", seg, "--threads", "2"] + options, check=True,
                       stdout=subprocess.DEVNULL)
        expected = np.loadtxt(seg, dtype=np.int64)
    r = pd.decompose_file(path, threads=2, **keywords)
    assert r.labels.shape == expected.shape
    assert (r.labels == expected).all()


def write_glb(path, meshes, nodes, scene_nodes):
    """A GLB file: meshes is a list of (positions float32 (n, 3), indices (m, 3) of some integer dtype)."""
    binary = b""
    views, accessors, gltf_meshes = [], [], []

    def add(array, component_type, kind, count):
        nonlocal binary
        binary += b"\0" * (-len(binary) % 4)
        views.append({"buffer": 0, "byteOffset": len(binary), "byteLength": array.nbytes})
        binary += array.tobytes()
        accessors.append({"bufferView": len(views) - 1, "componentType": component_type, "type": kind, "count": count})
        return len(accessors) - 1

    types = {np.dtype(np.uint8): 5121, np.dtype(np.uint16): 5123, np.dtype(np.uint32): 5125}
    for positions, indices in meshes:
        p = add(np.ascontiguousarray(positions, dtype="<f4"), 5126, "VEC3", len(positions))
        i = add(np.ascontiguousarray(indices.ravel()), types[indices.dtype], "SCALAR", indices.size)
        gltf_meshes.append({"primitives": [{"attributes": {"POSITION": p}, "indices": i}]})
    doc = {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": scene_nodes}], "nodes": nodes,
           "meshes": gltf_meshes, "accessors": accessors, "bufferViews": views,
           "buffers": [{"byteLength": len(binary)}]}
    text = json.dumps(doc).encode()
    text += b" " * (-len(text) % 4)
    binary += b"\0" * (-len(binary) % 4)
    with open(path, "wb") as f:
        f.write(struct.pack("<4sII", b"glTF", 2, 12 + 8 + len(text) + 8 + len(binary)))
        f.write(struct.pack("<I4s", len(text), b"JSON") + text)
        f.write(struct.pack("<I4s", len(binary), b"BIN\0") + binary)


def write_off(path, vertices, faces):
    with open(path, "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(vertices), len(faces)))
        for v in vertices:
            f.write("%r %r %r\n" % tuple(float(x) for x in v))
        for t in faces:
            f.write("3 %d %d %d\n" % tuple(t))


def test_glb_of_several_meshes_with_node_transforms_gives_the_parts_of_the_same_off():
    dumbbell = read_off(os.path.join(DATA, "dumbbell.off"))
    table = read_off(os.path.join(DATA, "table.off"))
    a = (dumbbell[0].astype(np.float32), dumbbell[1].astype(np.uint16))
    b = (table[0].astype(np.float32), table[1].astype(np.uint32))
    # parent: T * R * S with half a turn about z; child: a matrix (x, y, z) -> (z, x, y) + (0, 5, 0)
    nodes = [{"mesh": 0, "children": [1], "translation": [3.0, 0.0, 0.0], "rotation": [0.0, 0.0, 1.0, 0.0],
              "scale": [2.0, 2.0, 2.0]},
             {"mesh": 1, "matrix": [0, 1, 0, 0, 0, 0, 1, 0, 1, 0, 0, 0, 0, 5, 0, 1]}]

    def parent(p):
        return np.column_stack([3.0 - 2.0 * p[:, 0], -2.0 * p[:, 1], 2.0 * p[:, 2]])

    pa = parent(a[0].astype(np.float64))
    pb64 = b[0].astype(np.float64)
    pb = parent(np.column_stack([pb64[:, 2], pb64[:, 0] + 5.0, pb64[:, 1]]))
    vertices = np.vstack([pa, pb])
    faces = np.vstack([a[1].astype(np.int64), b[1].astype(np.int64) + len(pa)])
    with tempfile.TemporaryDirectory() as d:
        write_glb(os.path.join(d, "scene.glb"), [a, b], nodes, [0])
        write_off(os.path.join(d, "scene.off"), vertices, faces)
        from_glb = pd.decompose_file(os.path.join(d, "scene.glb"), **FAST)
        from_off = pd.decompose_file(os.path.join(d, "scene.off"), **FAST)
    assert from_glb.labels.shape == (len(a[1]) + len(b[1]),)
    assert (from_glb.labels == from_off.labels).all()
    # the two objects are apart: no part holds triangles of both
    assert not set(from_glb.labels[:len(a[1])]) & set(from_glb.labels[len(a[1]):])
    assert from_glb.number_of_parts >= 3


def read_glb(path):
    """The JSON and the binary chunk of a GLB file, checking its container."""
    with open(path, "rb") as f:
        data = f.read()
    magic, version, length = struct.unpack_from("<4sII", data, 0)
    assert magic == b"glTF" and version == 2 and length == len(data)
    json_length, json_type = struct.unpack_from("<I4s", data, 12)
    assert json_type == b"JSON" and json_length % 4 == 0
    doc = json.loads(data[20:20 + json_length])
    bin_length, bin_type = struct.unpack_from("<I4s", data, 20 + json_length)
    assert bin_type == b"BIN\0" and 28 + json_length + bin_length == len(data)
    return doc, data[28 + json_length:]


def accessor_array(doc, binary, index):
    a = doc["accessors"][index]
    view = doc["bufferViews"][a["bufferView"]]
    dtype = {5126: "<f4", 5125: "<u4"}[a["componentType"]]
    width = {"VEC3": 3, "SCALAR": 1}[a["type"]]
    flat = np.frombuffer(binary, dtype=dtype, count=a["count"] * width, offset=view["byteOffset"])
    assert view["byteOffset"] % 4 == 0 and flat.nbytes == view["byteLength"]
    return flat.reshape(-1, width) if width > 1 else flat


@pytest.mark.skipif(not HITOPS, reason="PD_HITOPS (the hitops tool) not given")
def test_hitops_parts_glb_has_one_mesh_per_part_and_the_primitives():
    path = os.path.join(DATA, "animal.off")
    vertices, faces = read_off(path)
    with tempfile.TemporaryDirectory() as d:
        glb, seg = os.path.join(d, "parts.glb"), os.path.join(d, "parts.seg")
        subprocess.run([HITOPS, path, "--labels", seg, "--parts-glb", glb, "--parts-glb-primitives", "--threads", "2"],
                       check=True, stdout=subprocess.DEVNULL)
        labels = np.loadtxt(seg, dtype=np.int64)
        doc, binary = read_glb(glb)
        # the package's own reader takes the file back: every part and primitive triangle
        back = pd.decompose_file(glb, **FAST)
    k = labels.max() + 1
    names = [m["name"] for m in doc["meshes"]]
    assert names == ["part_%d" % i for i in range(k)] + ["primitive_%d" % i for i in range(k)]
    scene = [doc["nodes"][n]["name"] for n in doc["scenes"][doc["scene"]]["nodes"]]
    assert scene == ["parts", "primitives"]
    colours = set()
    total = 0
    for i, mesh in enumerate(doc["meshes"]):
        (primitive,) = mesh["primitives"]
        positions = accessor_array(doc, binary, primitive["attributes"]["POSITION"])
        indices = accessor_array(doc, binary, primitive["indices"])
        accessor = doc["accessors"][primitive["attributes"]["POSITION"]]
        assert np.allclose(accessor["min"], positions.min(axis=0)) and np.allclose(accessor["max"], positions.max(axis=0))
        assert indices.max() < len(positions) and len(indices) % 3 == 0
        material = doc["materials"][primitive["material"]]
        if i < k:
            # part i: its triangles and nothing else, at the input's positions
            assert len(indices) // 3 == (labels == i).sum()
            part_corners = np.sort(positions[indices].reshape(-1, 3, 3).reshape(-1, 9), axis=0)
            input_corners = np.sort(vertices[faces[labels == i]].astype(np.float32).reshape(-1, 9), axis=0)
            assert np.array_equal(np.unique(part_corners.reshape(-1, 3), axis=0),
                                  np.unique(input_corners.reshape(-1, 3), axis=0))
            colours.add(tuple(material["pbrMetallicRoughness"]["baseColorFactor"]))
            total += len(indices) // 3
        else:
            assert material["pbrMetallicRoughness"]["baseColorFactor"][3] == 0.5 and material["alphaMode"] == "BLEND"
    assert total == len(faces)
    assert len(colours) == k
    assert len(back.labels) > total


def _png_decoder():
    """The tests' PNG decoder (zlib of the standard library), shared with the hitops report tests."""
    import importlib.util
    path = os.path.join(os.path.dirname(__file__), "..", "..", "test", "Part_decomposition", "hitops_report",
                        "png_decode.py")
    spec = importlib.util.spec_from_file_location("png_decode", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def _check_picture(path, size, parts):
    png = _png_decoder()
    width, height, pixels = png.read_png(path)
    assert (width, height) == size
    left = {p for row in pixels for p in row[:width // 2]}
    right = {p for row in pixels for p in row[width // 2:]}
    assert max(png.saturation(p) for p in left) < 10  # the input in grey
    assert len(right) >= parts
    # a hue per part: saturated pixels binned by their normalized colour
    hues = {tuple(round(6 * c / max(p)) for c in p) for p in right if png.saturation(p) > 60}
    assert len(hues) >= parts


def test_render_parts_draws_the_input_beside_its_parts(dumbbell, tmp_path):
    path = os.path.join(DATA, "dumbbell.off")
    r = pd.decompose_file(path, **FAST)
    assert r.number_of_parts >= 2
    out = tmp_path / "file.png"
    pd.render_parts(path, r.labels, out, size=(300, 120))
    _check_picture(str(out), (300, 120), r.number_of_parts)
    # arrays, a mesh object and a Decomposition for the labels: the same kind of picture
    vertices, faces = dumbbell
    pd.render_parts((vertices, faces), r, str(tmp_path / "arrays.png"), size=(64, 40))
    _check_picture(str(tmp_path / "arrays.png"), (64, 40), r.number_of_parts)

    class Mesh:
        pass

    mesh = Mesh()
    mesh.vertices, mesh.faces = vertices, faces
    pd.render_parts(mesh, r.labels, str(tmp_path / "object.png"))
    _check_picture(str(tmp_path / "object.png"), (640, 320), r.number_of_parts)


def test_render_parts_refuses_what_does_not_fit(dumbbell, tmp_path):
    vertices, faces = dumbbell
    out = str(tmp_path / "x.png")
    with pytest.raises(ValueError, match="labels"):
        pd.render_parts((vertices, faces), np.zeros(len(faces) - 1, dtype=np.int64), out)
    with pytest.raises(ValueError, match="labels"):
        pd.render_parts(os.path.join(DATA, "dumbbell.off"), [0, 1], out)
    with pytest.raises(ValueError, match="negative"):
        pd.render_parts((vertices, faces), -np.ones(len(faces), dtype=np.int64), out)
    with pytest.raises(ValueError, match="size"):
        pd.render_parts((vertices, faces), np.zeros(len(faces), dtype=np.int64), out, size=(1, 100))
    with pytest.raises(OSError):
        pd.render_parts((vertices, faces), np.zeros(len(faces), dtype=np.int64), str(tmp_path / "no" / "x.png"))
    assert not os.path.exists(out)
