#!/usr/bin/env python3
"""Writes the table of parameters of the reference page PD_ParameterTable (parameter_table.txt)
from the library's parameter_table, as `hitops --list-parameters` prints it.

    parameter_table.py HITOPS           rewrites the table of the page
    parameter_table.py HITOPS --check   exits with status 1 if the page's table is not the one made

The table lies between two HTML comments of the page (MARK_BEGIN, MARK_END); nothing else changes.
The pytest suite runs the check, so that the page cannot drift from the library.
"""

import os
import subprocess
import sys

PAGE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "parameter_table.txt")
MARK_BEGIN = "<!-- parameter table: made by tools/parameter_table.py from parameter_table, do not edit -->"
MARK_END = "<!-- end of the parameter table -->"


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


def main(argv):
    if len(argv) not in (2, 3) or (len(argv) == 3 and argv[2] != "--check"):
        sys.exit(__doc__)
    with open(PAGE, encoding="utf-8") as f:
        manual = f.read()
    begin, end = manual.index(MARK_BEGIN) + len(MARK_BEGIN) + 1, manual.index(MARK_END)
    made = manual[:begin] + make_table(read_rows(argv[1])) + manual[end:]
    if len(argv) == 3:
        if made != manual:
            sys.exit("the parameter table of %s is not the one made from the library: run %s %s" %
                     (os.path.normpath(PAGE), sys.argv[0], argv[1]))
        return
    with open(PAGE, "w", encoding="utf-8") as f:
        f.write(made)


if __name__ == "__main__":
    main(sys.argv)
