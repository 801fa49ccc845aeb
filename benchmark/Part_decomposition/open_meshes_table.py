#!/usr/bin/env python3
"""The "open meshes" tables of RESULTS.md from benchmark_segmentation runs (results.tsv).

usage: open_meshes_table.py closed=DIR open=DIR[,DIR...] hard=DIR[,DIR...] [LABEL=DIR[,DIR...] ...]

Each DIR is the --out folder of one benchmark_segmentation run with --methods sdf,ours. A group of
several runs (two seeds of make_open.py, say) is averaged shape by shape. Prints, per group and
method: mIoU (halves A / B: shapes in name order, alternately), RI, parts, median seconds and the
median of the ours/SDF time ratio shape by shape, the mIoU of ours as a share of the closed set's;
then the mIoU per category. Standard library only.
"""
import csv
import statistics
import sys
from collections import defaultdict


def read_runs(folders):
    """per method, per shape: the rows of every run of the group"""
    rows = defaultdict(lambda: defaultdict(list))
    for folder in folders:
        with open(folder + "/results.tsv") as f:
            for r in csv.DictReader(f, delimiter="\t"):
                if r["status"] == "ok":
                    rows[r["method"]][r["shape"]].append(r)
    return rows


def mean_of(rows, key):
    return statistics.mean(float(r[key]) for r in rows)


def main(argv):
    groups = []
    for arg in argv:
        label, _, folders = arg.partition("=")
        if not folders:
            sys.exit(__doc__)
        groups.append((label, read_runs(folders.split(","))))
    if not groups or groups[0][0] != "closed":
        sys.exit("the first group must be closed=DIR\n" + __doc__)
    shapes = sorted(set.intersection(*[set(g["ours"].keys()) for _, g in groups]))
    half = {s: "AB"[i % 2] for i, s in enumerate(shapes)}
    category = {s: groups[0][1]["ours"][s][0]["category"] for s in shapes}
    closed_miou = statistics.mean(mean_of(groups[0][1]["ours"][s], "mIoU") for s in shapes)

    print("| Set | Method | mIoU (A / B) | of closed | RI | parts | median s | ours/SDF time |")
    print("|---|---|---|---|---|---|---|---|")
    for label, g in groups:
        for method, name in (("sdf", "CGAL SDF"), ("ours", "Hi-TOPS")):
            if method not in g:
                continue
            m = {s: mean_of(g[method][s], "mIoU") for s in shapes}
            a = statistics.mean(m[s] for s in shapes if half[s] == "A")
            b = statistics.mean(m[s] for s in shapes if half[s] == "B")
            total = statistics.mean(m.values())
            share = "%.1f%%" % (100 * total / closed_miou) if method == "ours" else ""
            seconds = statistics.median(mean_of(g[method][s], "t_method") for s in shapes)
            ratio = ""
            if method == "ours" and "sdf" in g:
                ratio = "%.2f" % statistics.median(
                    mean_of(g["ours"][s], "t_method") / mean_of(g["sdf"][s], "t_method") for s in shapes)
            print("| %s (%d) | %s | %.3f (%.3f / %.3f) | %s | %.3f | %.1f | %.3f | %s |" % (
                label, len(shapes), name, total, a, b, share,
                statistics.mean(mean_of(g[method][s], "RI") for s in shapes),
                statistics.mean(mean_of(g[method][s], "parts") for s in shapes), seconds, ratio))
    print()
    labels = [label for label, _ in groups]
    print("| Category | " + " | ".join("%s ours / SDF" % label for label in labels) + " |")
    print("|---|" + "---|" * len(labels))
    for c in sorted(set(category.values())):
        members = [s for s in shapes if category[s] == c]
        cells = []
        for _, g in groups:
            ours = statistics.mean(mean_of(g["ours"][s], "mIoU") for s in members)
            sdf = statistics.mean(mean_of(g["sdf"][s], "mIoU") for s in members) if "sdf" in g else float("nan")
            cells.append("%.3f / %.3f" % (ours, sdf))
        print("| %s | %s |" % (c, " | ".join(cells)))


if __name__ == "__main__":
    main(sys.argv[1:])
