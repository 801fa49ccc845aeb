"""The parameters cannot drift apart: every entry of the library's parameter_table (as
`hitops --list-parameters` prints it) has a hitops option of its name in `hitops --help` and a
Python keyword with the same default, decompose()'s reference documents it, and the manual's
table is the one doc/Part_decomposition/tools/parameter_table.py makes. Needs PD_HITOPS."""

import os
import re
import subprocess
import sys
import tempfile

import numpy as np
import pytest

import part_decomposition as pd

HITOPS = os.environ.get("PD_HITOPS")
ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
DATA = os.environ.get("PD_EXAMPLE_DATA_DIR", os.path.join(ROOT, "examples", "Part_decomposition", "data"))

pytestmark = pytest.mark.skipif(not HITOPS, reason="PD_HITOPS (the hitops tool) not given")


def run(*arguments):
    return subprocess.run([HITOPS] + list(arguments), check=True, stdout=subprocess.PIPE,
                          universal_newlines=True).stdout


@pytest.fixture(scope="module")
def table():
    lines = run("--list-parameters").rstrip("\n").split("\n")
    header = lines[0].split("\t")
    rows = [dict(zip(header, line.split("\t"))) for line in lines[1:]]
    assert len(rows) >= 50
    return rows


@pytest.fixture(scope="module")
def help_options():
    """option -> the default that `hitops --help` shows for it, from the lines '  --option DEFAULT  meaning'."""
    options = {}
    for line in run("--help").split("\n"):
        m = re.match(r"^  (--[a-z0-9-]+) (\S+)\s{2,}\S", line)
        if m:
            assert m.group(1) not in options, "%s is listed twice" % m.group(1)
            options[m.group(1)] = m.group(2)
    return options


def python_value(row, text):
    """The Python keyword value of the text of a hitops option."""
    if text == "none":
        return None
    if row["type"] == "bool":
        return {"true": True, "false": False}[text]
    if row["type"] in ("Tsdf_sign_method", "Method_variant"):
        return text
    if row["type"].startswith("std::vector") or row["type"].startswith("std::array"):
        return [float(x) for x in text.split(",")]
    return float(text)


def test_every_parameter_has_an_option_named_as_it_with_its_default(table, help_options):
    values = [row for row in table if row["option"]]
    for row in values:
        assert row["option"] == "--" + row["name"].replace("_", "-")
        assert row["option"] in help_options, "hitops --help does not list " + row["option"]
        assert help_options[row["option"]] == row["default"], row["name"]
    # the objects (outputs, a normalization) and the switches of the method have no option of their own
    assert {row["name"] for row in table if not row["option"] and row["kind"] != "switch"} == {
        "normalization", "part_hierarchy", "primitive_output_iterator", "stage_timings"}


def test_every_parameter_is_a_python_keyword_with_the_same_default(table, help_options):
    values = [row for row in table if row["option"]]
    for row in values:
        assert row["name"] in pd.DEFAULTS, "no Python keyword " + row["name"]
        default = pd.DEFAULTS[row["name"]]
        expected = python_value(row, help_options[row["option"]])
        if isinstance(default, (list, tuple)):
            default = [float(x) for x in default]
        assert default == expected, row["name"]
    # the module's own keyword is the only one outside the table
    assert set(pd.DEFAULTS) - {row["name"] for row in values} == {"threads"}


HEADERS = os.path.join(ROOT, "include", "CGAL", "Part_decomposition")
MESH_PARAMETERS = ("vertex_point_map", "vertex_index_map", "face_index_map", "geom_traits")


def read(*path):
    with open(os.path.join(*path), encoding="utf-8") as f:
        return f.read()


def headers():
    """path -> text of every public header of the package (internal/ excluded)."""
    out = {}
    for directory, subdirectories, files in os.walk(HEADERS):
        subdirectories[:] = [d for d in subdirectories if d != "internal"]
        for name in files:
            if name.endswith(".h"):
                out[os.path.join(directory, name)] = read(directory, name)
    return out


def documented_functions():
    """function name -> the doc comments (/*! */) of the functions and members of that name."""
    docs = {}
    for text in headers().values():
        for m in re.finditer(r"/\*!((?:(?!\*/).)*)\*/\s*(?:template\s*<[^{;]*?>\s*)?[^;{(]*?\b(\w+)\s*\(", text, re.S):
            docs.setdefault(m.group(2), []).append(m.group(1))
    return docs


def readers_of_the_table(table):
    """parameter -> the stage function that reads it, named in its stage's title ("prior
    (compute_flow_freeze_prior())"); a switch of the method is read through `method_variant`."""
    readers = {}
    for row in table:
        m = re.search(r"\((\w+)\(\)\)", row["stage"])
        if m and row["kind"] != "object":
            readers[row["name"]] = (m.group(1), "method_variant" if row["kind"] == "switch" else row["name"])
    assert len(readers) >= 40
    return readers


def test_each_parameter_is_documented_once():
    """One doc block per parameter at most in the headers: the table page and its section on the mesh
    parameters document them; a function keeps a block only for a meaning of its own."""
    blocks = [name for text in headers().values() for name in re.findall(r"\\cgalParamNBegin\{(\w+)\}", text)]
    repeated = sorted({name for name in blocks if blocks.count(name) > 1})
    assert not repeated, "documented more than once in the headers: %s" % ", ".join(repeated)
    page = read(ROOT, "doc", "Part_decomposition", "parameter_table.txt")
    mesh_section = page[page.index("\\section PD_MeshParameters"):]
    for name in MESH_PARAMETERS:
        assert "\\cgalParamNBegin{%s}" % name in mesh_section, name
    # decompose() documents the parameters that mean something of their own there, and refers to the table
    reference = read(HEADERS, "decompose.h")
    assert "\\ref PD_ParameterTable" in reference and "\\ref PD_MeshParameters" in reference
    for name in ("normalization", "primitive_output_iterator", "number_of_parts", "maximum_merge_cost",
                 "part_hierarchy", "stage_timings"):
        assert "\\cgalParamNBegin{%s}" % name in reference, name


def test_each_function_names_the_parameters_it_reads(table):
    """The doc of the stage function of every parameter names it (a switch: `method_variant`;
    decompose() accepts them all and refers to the table), and refers to the page that documents it."""
    docs = documented_functions()
    checked = 0
    for name, (function, named) in readers_of_the_table(table).items():
        if function == "decompose":
            continue
        assert function in docs, "no documented function %s() (the stage of %s)" % (function, name)
        assert any("`%s`" % named in doc or "`%s(" % named in doc or "\\cgalParamNBegin{%s}" % named in doc
                   for doc in docs[function]), "the doc of %s() does not name %s" % (function, named)
        assert any("\\ref PD_ParameterTable" in doc or "\\ref PD_MeshParameters" in doc for doc in docs[function]), function
        checked += 1
    assert checked >= 40


def violating_value(row):
    """A value outside the row's range that the option parser accepts, or None for rules not of this form."""
    rule, integer = row["range"], row["type"] in ("int", "unsigned int", "std::size_t")
    m = re.fullmatch(r"in ([\[(])(-?[0-9.]+), ([0-9.]+)([\])])", rule)
    if m:
        low, high = float(m.group(2)), float(m.group(3))
        value = low if m.group(1) == "(" else (high * 2 + 1 if m.group(4) == "]" else high)
    elif rule.startswith("positive"):
        value = 0
    elif rule.startswith("non-negative") and not integer:
        value = -1
    else:
        return None
    return str(int(value)) if integer else repr(float(value))


def test_the_range_checks_state_the_ranges_of_the_table(table):
    """The library's range checks take their rule from the table: "NAME must be RANGE"."""
    checked = 0
    for row in table:
        value = violating_value(row) if row["option"] else None
        if value is None:
            continue
        r = subprocess.run([HITOPS, os.path.join(DATA, "dumbbell.off"), row["option"], value],
                           stdout=subprocess.PIPE, stderr=subprocess.PIPE, universal_newlines=True)
        message = "%s must be %s" % (row["name"], row["range"])
        assert r.returncode == 1 and message in r.stderr, (row["name"], value, r.stderr)
        checked += 1
    assert checked >= 20


def test_the_switches_of_the_method_are_one_named_parameter(table, help_options):
    """Each switch is a field of Method_variant: no option or keyword of its own, a value in the paper."""
    switches = [row for row in table if row["kind"] == "switch"]
    assert len(switches) >= 10
    for row in switches:
        assert not row["option"] and "--" + row["name"].replace("_", "-") not in help_options, row["name"]
        assert row["name"] not in pd.DEFAULTS, row["name"]
        assert row["default"] and row["paper"], row["name"]
    assert help_options["--method-variant"] == "default" and pd.DEFAULTS["method_variant"] == "default"
    # the paper differs from the package's method in at least one switch, and says what it is
    assert any(row["default"] != row["paper"] for row in switches)


def test_the_reference_page_has_the_generated_table(table):
    script = os.path.join(ROOT, "doc", "Part_decomposition", "tools", "parameter_table.py")
    subprocess.run([sys.executable, script, HITOPS, "--check"], check=True)
    with open(os.path.join(ROOT, "doc", "Part_decomposition", "parameter_table.txt"), encoding="utf-8") as f:
        manual = f.read()
    for row in table:
        assert "| `%s` |" % row["name"] in manual, row["name"]


def test_former_spellings_give_the_same_labels():
    path = os.path.join(DATA, "dumbbell.off")
    labels = []
    with tempfile.TemporaryDirectory() as d:
        for k, options in enumerate([
                ["--no-pieces", "--max-merge-cost", "0.01", "--resolutions", "16,32", "--sign-method", "flood"],
                ["--method-variant", "use_pieces=false", "--maximum-merge-cost", "0.01", "--voxel-resolutions", "16,32",
                 "--tsdf-sign-method", "flood_fill"]]):
            seg = os.path.join(d, "%d.seg" % k)
            run(path, "--labels", seg, "--threads", "2", *options)
            labels.append(np.loadtxt(seg, dtype=np.int64))
    assert (labels[0] == labels[1]).all()


def test_bad_option_values_name_the_option():
    for options, message in [(["--method-variant", "use_pieces=no"], "--method-variant expects true or false"),
                             (["--method-variant", "use_piece=false"], "--method-variant expects default, paper_literal"),
                             (["--tsdf-sign-method", "ray"], "--tsdf-sign-method expects one of automatic"),
                             (["--cue-weights", "1,1"], "cue_weights must be 4 finite numbers"),
                             (["--parts", "0"], "--parts expects at least 1")]:
        r = subprocess.run([HITOPS, os.path.join(DATA, "dumbbell.off")] + options, stdout=subprocess.PIPE,
                           stderr=subprocess.PIPE, universal_newlines=True)
        assert r.returncode == 1 and message in r.stderr, (options, r.stderr)
