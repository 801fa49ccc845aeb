#!/usr/bin/env python3
"""Makes, from the library's parameter_table as `hitops --list-parameters` prints it, the table of
the reference page PD_ParameterTable (parameter_table.txt) and the namespace `defaults` of
parameters.h.

    parameter_table.py HITOPS           rewrites both
    parameter_table.py HITOPS --check   exits with status 1 if either is not the one made

Each lies between two marks of its file; nothing else changes. The pytest suite runs the check, so
that neither the page nor the defaults can drift from the table.
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
    return "".join(make_default(row) for row in rows
                   if row["option"] and row["table_default"] not in ("none", "nullptr"))


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


if __name__ == "__main__":
    main(sys.argv)
