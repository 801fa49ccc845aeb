#!/usr/bin/env python3
"""Makes, from the library's parameter_table as `hitops --list-parameters` prints it, the table of
the reference page PD_ParameterTable (parameter_table.txt), the namespace `defaults` of
parameters.h and the list of settings of the tools (hitops, the benchmark, the Python module) in
decomposition_settings.h.

    parameter_table.py HITOPS           rewrites all three
    parameter_table.py HITOPS --check   exits with status 1 if one is not the one made

Each lies between two marks of its file; nothing else changes. The pytest suite runs the check, so
that none of them can drift from the table.
"""

import os
import re
import subprocess
import sys

PAGE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "parameter_table.txt")
MARK_BEGIN = "<!-- parameter table: made by tools/parameter_table.py from parameter_table, do not edit -->"
MARK_END = "<!-- end of the parameter table -->"
HEADER = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "include", "CGAL",
                      "Part_decomposition", "parameters.h")
HEADER_BEGIN = "// defaults: made by doc/Part_decomposition/tools/parameter_table.py from parameter_table, do not edit"
HEADER_END = "// end of the defaults"
ENUMS = ("Tsdf_sign_method", "Interior_weight_mode")
SETTINGS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "examples",
                        "Part_decomposition", "include", "decomposition_settings.h")
SETTINGS_BEGIN = "// settings: made by doc/Part_decomposition/tools/parameter_table.py from parameter_table, do not edit"
SETTINGS_END = "// end of the settings"
# CGAL's own named parameters, which the tools pass apart from the package's
CGAL_PARAMETERS = ("number_of_points_per_face", "verbose")


def read_rows(hitops):
    """The rows of `hitops --list-parameters`, as dicts keyed by its header."""
    text = subprocess.run([hitops, "--list-parameters"], check=True, stdout=subprocess.PIPE,
                          universal_newlines=True).stdout
    lines = text.rstrip("\n").split("\n")
    header = lines[0].split("\t")
    return [dict(zip(header, line.split("\t"))) for line in lines[1:]]


def cpp_default(row):
    """The default as a C++ user writes it: lists in braces, enumerators in upper case."""
    d = row["default"]
    if row["type"].startswith("std::vector") or row["type"].startswith("std::array"):
        return "`{%s}`" % ", ".join(d.split(","))
    if row["type"] in ("Tsdf_sign_method", "Interior_weight_mode"):
        return "`%s`" % d.upper()
    if d in ("true", "false", "nullptr"):
        return "`%s`" % d
    return d


def make_table(rows):
    out = ["| Named parameter | Type | Default | Range | Meaning |",
           "| :-------------- | :--- | :------ | :---- | :------ |"]
    stage = None
    for row in rows:
        if row["stage"] != stage:
            stage = row["stage"]
            out.append("| <b>%s</b> | | | | |" % (stage[0].upper() + stage[1:]))
        meaning = row["meaning"] + (" <em>(ablation)</em>" if row["ablation"] == "yes" else "")
        out.append("| `%s` | `%s` | %s | %s | %s |" % (row["name"], row["type"], cpp_default(row), row["range"],
                                                     meaning))
    return "\n".join(out) + "\n"


def cpp_number(row, text):
    """A literal of the row's type: doubles with a decimal point, as the rest of the code writes them."""
    if "double" in row["type"] and re.fullmatch(r"-?[0-9]+", text):
        return text + "."
    return text


def make_default(row):
    """The declaration of the default of one row: a function for a list, a constant otherwise."""
    name, cpp_type, text = row["name"], row["type"], row["table_default"]
    doc = "/// %s\n" % row["meaning"]
    if cpp_type.startswith("std::vector"):
        items = ", ".join(cpp_number(row, x) for x in text.split(","))
        return doc + "inline %s %s() { return {%s}; }\n" % (cpp_type, name, items)
    if cpp_type.startswith("std::array"):
        items = ", ".join(cpp_number(row, x) for x in text.split(","))
        return doc + "constexpr %s %s = {{%s}};\n" % (cpp_type, name, items)
    if cpp_type in ENUMS:
        return doc + "constexpr %s %s = %s::%s;\n" % (cpp_type, name, cpp_type, text.upper())
    return doc + "constexpr %s %s = %s;\n" % (cpp_type, name, cpp_number(row, text))


def make_defaults(rows):
    """The defaults of every value parameter that has one (not the outputs, nor `number_of_parts`)."""
    return "".join(make_default(row) for row in rows if has_default(row))


def has_default(row):
    """Whether the row is a value parameter with a default (not an output, nor `number_of_parts`)."""
    return bool(row["option"]) and row["table_default"] not in ("none", "nullptr")


def make_settings(rows):
    """The X-macro of the tools' settings: every value parameter of decompose() with a default,
    in table order, but CGAL's own and the reader's."""
    def setting_type(t):
        if t.startswith("std::array"):
            return "PD_cue_weights"  # a macro argument cannot hold the comma
        return "PD::" + t if t in ENUMS else t

    lines = ["#define PART_DECOMPOSITION_TOOLS_SETTINGS(X)"]
    for row in rows:
        if not has_default(row) or row["name"] in CGAL_PARAMETERS or row["stage"].startswith("reading"):
            continue
        default = "PD::defaults::" + row["name"] + ("()" if row["type"].startswith("std::vector") else "")
        lines.append("  X(%s, %s, %s)" % (setting_type(row["type"]), row["name"], default))
    width = max(len(line) for line in lines) + 1
    return "".join(line.ljust(width) + "\\\n" for line in lines[:-1]) + lines[-1] + "\n"


def remake(path, begin_mark, end_mark, made_text, check, hitops):
    """Puts `made_text` between the marks of `path`; with `check`, exits if that changes the file."""
    with open(path, encoding="utf-8") as f:
        text = f.read()
    begin, end = text.index(begin_mark) + len(begin_mark) + 1, text.index(end_mark)
    made = text[:begin] + made_text + text[end:]
    if check:
        if made != text:
            sys.exit("%s is not the one made from the library's parameter_table: run %s %s" %
                     (os.path.normpath(path), sys.argv[0], hitops))
        return
    with open(path, "w", encoding="utf-8") as f:
        f.write(made)


def main(argv):
    if len(argv) not in (2, 3) or (len(argv) == 3 and argv[2] != "--check"):
        sys.exit(__doc__)
    rows = read_rows(argv[1])
    check = len(argv) == 3
    remake(PAGE, MARK_BEGIN, MARK_END, make_table(rows), check, argv[1])
    remake(HEADER, HEADER_BEGIN, HEADER_END, make_defaults(rows), check, argv[1])
    remake(SETTINGS, SETTINGS_BEGIN, SETTINGS_END, make_settings(rows), check, argv[1])


if __name__ == "__main__":
    main(sys.argv)
