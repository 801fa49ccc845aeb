#!/usr/bin/env python3
"""Makes, from the library's parameter_table as `hitops --list-parameters` prints it, the two tables
of the reference page PD_ParameterTable (parameter_table.txt): the named parameters and the
switches of Method_variant. Nothing else is made from it: the library, the programs and the Python
module expand the lists of parameters.h themselves.

    parameter_table.py HITOPS           rewrites both
    parameter_table.py HITOPS --check   exits with status 1 if one is not the one made

Each lies between two marks of the page; nothing else changes. The pytest suite runs the check, so
that none of them can drift from the table.
"""

import os
import subprocess
import sys

PAGE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "parameter_table.txt")
MARK_BEGIN = "<!-- parameter table: made by tools/parameter_table.py from parameter_table, do not edit -->"
MARK_END = "<!-- end of the parameter table -->"
SWITCHES_BEGIN = "<!-- switches: made by tools/parameter_table.py from parameter_table, do not edit -->"
SWITCHES_END = "<!-- end of the switches -->"
ENUMS = ("Tsdf_sign_method", "Interior_weight_mode")


def read_rows(hitops):
    """The rows of `hitops --list-parameters`, as dicts keyed by its header."""
    text = subprocess.run([hitops, "--list-parameters"], check=True, stdout=subprocess.PIPE,
                          universal_newlines=True).stdout
    lines = text.rstrip("\n").split("\n")
    header = lines[0].split("\t")
    return [dict(zip(header, line.split("\t"))) for line in lines[1:]]


def cpp_default(row, text):
    """A default as a C++ user writes it: lists in braces, enumerators in upper case."""
    if row["type"].startswith("std::vector"):
        return "`{%s}`" % ", ".join(text.split(","))
    if row["type"] in ENUMS:
        return "`%s`" % text.upper()
    if text in ("true", "false", "nullptr"):
        return "`%s`" % text
    return text


def cell(text):
    """Text in a cell of a Markdown table: a bar would end the cell."""
    return text.replace("|", "\\|")


def stage_heading(stage):
    return "| <b>%s</b> | | | | |" % (stage[0].upper() + stage[1:])


def make_table(rows):
    """The named parameters, values and objects, grouped by stage in the order of the stages."""
    rows = [row for row in rows if row["kind"] != "switch"]
    rank = {}
    for row in rows:
        rank.setdefault(row["stage"], len(rank))
    out = ["| Named parameter | Type | Default | Range | Meaning |",
           "| :-------------- | :--- | :------ | :---- | :------ |"]
    stage = None
    for row in sorted(rows, key=lambda r: rank[r["stage"]]):
        if row["stage"] != stage:
            stage = row["stage"]
            out.append(stage_heading(stage))
        out.append("| `%s` | `%s` | %s | %s | %s |" % (row["name"], row["type"], cpp_default(row, row["default"]),
                                                     row["range"], cell(row["meaning"])))
    return "\n".join(out) + "\n"


def make_switches(rows):
    """The fields of Method_variant, with the package's value and the paper's."""
    out = ["| Switch | Type | Default | Paper | Meaning |",
           "| :----- | :--- | :------ | :---- | :------ |"]
    for row in rows:
        if row["kind"] == "switch":
            out.append("| `%s` | `%s` | %s | %s | %s |" % (row["name"], row["type"], cpp_default(row, row["default"]),
                                                         cpp_default(row, row["paper"]), cell(row["meaning"])))
    return "\n".join(out) + "\n"


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
    remake(PAGE, SWITCHES_BEGIN, SWITCHES_END, make_switches(rows), check, argv[1])


if __name__ == "__main__":
    main(sys.argv)
