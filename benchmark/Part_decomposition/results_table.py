#!/usr/bin/env python3
"""Writes the current table of RESULTS.md from the benchmark_segmentation runs of results.sh.

usage: results_table.py RESULTS.md COMMIT LABEL=DIR[,DIR...] [LABEL=DIR[,DIR...] ...]

Each DIR is the --out folder of one run (results.tsv) with the methods sdf, ours and, for the sets
with human part counts, ours_k; the runs of one LABEL (two seeds of make_open.py) are averaged shape
by shape. Per set and method: mIoU with its halves (shapes in name order, alternately A and B), RI,
VoI, parts, median seconds, the median of the ours/SDF time ratio shape by shape, the median peak
memory, and for generated unions the share of true primitives found. The table replaces the text
between the two marks of RESULTS.md (MARK_BEGIN, MARK_END); nothing else changes. Standard library
only.
"""
import statistics
import sys

from open_meshes_table import mean_of, read_runs

MARK_BEGIN = "<!-- current table: written by results.sh (results_table.py), do not edit -->"
MARK_END = "<!-- end of the current table -->"
METHODS = (("sdf", "CGAL SDF"), ("ours", "Hi-TOPS"), ("ours_k", "Hi-TOPS told the count"))


def halves(values, shapes):
    """mean over the shapes, and over halves A and B"""
    a = [values[s] for i, s in enumerate(shapes) if i % 2 == 0]
    b = [values[s] for i, s in enumerate(shapes) if i % 2 == 1]
    return statistics.mean(values.values()), statistics.mean(a), statistics.mean(b) if b else float("nan")


def found(rows_of_shape):
    """the true primitives found and their number, summed over the runs"""
    hits = sum(int(r["found"]) for r in rows_of_shape if r["found"] not in ("", "n/a"))
    total = sum(int(r["true_primitives"]) for r in rows_of_shape if r["true_primitives"] not in ("", "n/a"))
    return hits, total


def rows_of_set(label, runs):
    """the table rows of one set"""
    shapes = sorted(set.intersection(*[set(runs[m].keys()) for m, _ in METHODS if m in runs]))
    out = []
    for method, name in METHODS:
        if method not in runs:
            continue
        g = runs[method]
        total, a, b = halves({s: mean_of(g[s], "mIoU") for s in shapes}, shapes)
        ratio = ""
        if method != "sdf" and "sdf" in runs:
            ratio = "%.2f" % statistics.median(
                mean_of(g[s], "t_method") / mean_of(runs["sdf"][s], "t_method") for s in shapes)
        hits = [found(g[s]) for s in shapes]
        share = "%.1f%%" % (100. * sum(h for h, _ in hits) / sum(t for _, t in hits)) \
            if method != "sdf" and sum(t for _, t in hits) > 0 else ""
        out.append("| %s (%d) | %s | %.3f (%.3f / %.3f) | %.3f | %.3f | %.1f | %.3f | %s | %.0f | %s |" % (
            label, len(shapes), name, total, a, b,
            statistics.mean(mean_of(g[s], "RI") for s in shapes),
            statistics.mean(mean_of(g[s], "VoI") for s in shapes),
            statistics.mean(mean_of(g[s], "parts") for s in shapes),
            statistics.median(mean_of(g[s], "t_method") for s in shapes), ratio,
            statistics.median(mean_of(g[s], "peak_mb") for s in shapes), share))
    return out


def make_table(commit, groups):
    lines = ["Commit %s; every set in one session, 2 threads, CGAL's SDF segmentation in the same run." % commit,
             "",
             "| Set | Method | mIoU (A / B) | RI | VoI | parts | median s | / SDF time | median MB | found |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for label, runs in groups:
        lines += rows_of_set(label, runs)
    return "\n".join(lines) + "\n"


def main(argv):
    if len(argv) < 3:
        sys.exit(__doc__)
    path, commit = argv[0], argv[1]
    groups = []
    for arg in argv[2:]:
        label, _, folders = arg.partition("=")
        if not folders:
            sys.exit(__doc__)
        groups.append((label, read_runs(folders.split(","))))
    with open(path, encoding="utf-8") as f:
        text = f.read()
    begin, end = text.index(MARK_BEGIN) + len(MARK_BEGIN) + 1, text.index(MARK_END)
    with open(path, "w", encoding="utf-8") as f:
        f.write(text[:begin] + make_table(commit, groups) + text[end:])


if __name__ == "__main__":
    main(sys.argv[1:])
