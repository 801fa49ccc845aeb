#!/usr/bin/env python3
"""The two measurements behind the default weld_tolerance of the reader, relative to the diagonal
of the bounding box.

usage: weld_tolerance.py roundoff MESH.off [...]   the gap float32 round-off leaves on a seam
       weld_tolerance.py gaps MESH.off|.obj [...]  the smallest gap between distinct border vertices

roundoff: each mesh is cut in two by a random plane; the second half is stored as a glTF exporter
stores it, in float32 in the frame of a node transform (random rotation, scale 0.1 to 10,
translation up to 3 sizes), and brought back in double, the first half in float32; the object
lies up to 2 sizes from the origin. Prints, per mesh, the largest distance between the two copies
of a seam vertex over 4 trials, then the largest over all meshes.
gaps: after merging equal vertices, the smallest distance between two distinct vertices on border
edges (edges of one triangle), and between any two distinct vertices. numpy only, seeded.
"""
import os
import sys
from collections import defaultdict

import numpy as np


def load(path):
    vertices, faces = [], []
    if path.endswith(".obj"):
        for line in open(path, errors="ignore"):
            t = line.split()
            if not t:
                continue
            if t[0] == "v":
                vertices.append([float(x) for x in t[1:4]])
            elif t[0] == "f":
                ids = [int(x.split("/")[0]) for x in t[1:]]
                ids = [i - 1 if i > 0 else len(vertices) + i for i in ids]
                faces += [(ids[0], ids[k], ids[k + 1]) for k in range(1, len(ids) - 1)]
    else:
        lines = [l for l in open(path) if l.strip() and not l.lstrip().startswith("#")]
        n, m = map(int, lines[1].split()[:2])
        vertices = [[float(x) for x in l.split()[:3]] for l in lines[2:2 + n]]
        for l in lines[2 + n:2 + n + m]:
            t = list(map(int, l.split()))
            faces += [(t[1], t[1 + k], t[2 + k]) for k in range(1, t[0] - 1)]
    return np.array(vertices, float), np.array(faces, int)


def rotation(rng):
    w, x, y, z = (q := rng.normal(size=4)) / np.linalg.norm(q)
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                     [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                     [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])


def roundoff(paths):
    rng = np.random.default_rng(1)
    f32 = lambda a: np.asarray(a).astype(np.float32).astype(np.float64)
    worst = []
    for path in paths:
        V, F = load(path)
        diagonal = np.linalg.norm(V.max(0) - V.min(0))
        cut = V[F].mean(1) @ rng.normal(size=3)
        half = cut > np.median(cut)
        seam = np.intersect1d(np.unique(F[half]), np.unique(F[~half]))
        gaps = []
        for trial in range(4):
            W = V + rng.uniform(-2, 2, 3) * diagonal * trial / 3
            R = rotation(rng)
            A = 10 ** rng.uniform(-1, 1) * R
            t = rng.uniform(-3, 3, 3) * diagonal
            local = f32(np.linalg.solve(A, (W[seam] - t).T).T)
            back = (f32(A) @ local.T).T + f32(t)
            gaps.append(np.linalg.norm(f32(W[seam]) - back, axis=1).max() / diagonal)
        worst.append(max(gaps))
        print("%-28s seam %5d  largest gap %.3g" % (os.path.basename(path), len(seam), worst[-1]), flush=True)
    print("over %d meshes: largest %.3g, median %.3g" % (len(worst), max(worst), np.median(worst)))


def smallest_gap(P):
    """the smallest distance between two of the distinct points P, by cells of growing size"""
    if len(P) < 2:
        return np.inf
    lo, extent = P.min(0), (P.max(0) - P.min(0)).max()
    for fraction in (1e-4, 1e-3, 1e-2, 1e-1):
        cell = extent * fraction
        bins = defaultdict(list)
        for i, k in enumerate(map(tuple, np.floor((P - lo) / cell).astype(np.int64))):
            bins[k].append(i)
        best = np.inf
        for k, ids in bins.items():
            for d in np.ndindex(3, 3, 3):
                other = bins.get((k[0] + d[0] - 1, k[1] + d[1] - 1, k[2] + d[2] - 1))
                if other:
                    D = np.linalg.norm(P[ids][:, None, :] - P[other][None, :, :], axis=-1)
                    D[D == 0] = np.inf
                    best = min(best, D.min())
        if best < np.inf:
            return best
    return np.inf


def gaps(paths):
    smallest = np.inf
    for path in paths:
        V, F = load(path)
        U, inverse = np.unique(V, axis=0, return_inverse=True)
        F = inverse.reshape(-1)[F]
        F = F[(F[:, 0] != F[:, 1]) & (F[:, 1] != F[:, 2]) & (F[:, 0] != F[:, 2])]
        used = np.unique(F)
        diagonal = np.linalg.norm(U[used].max(0) - U[used].min(0))
        E = np.sort(np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]]), axis=1)
        edges, count = np.unique(E, axis=0, return_counts=True)
        border = np.unique(edges[count == 1])
        b = smallest_gap(U[border]) / diagonal
        smallest = min(smallest, b)
        print("%-28s border vertices %6d  smallest border gap %.3g  smallest gap %.3g" % (
            os.path.basename(path), len(border), b, smallest_gap(U[used]) / diagonal), flush=True)
    print("over %d meshes: smallest border gap %.3g" % (len(paths), smallest))


if __name__ == "__main__":
    if len(sys.argv) < 3 or sys.argv[1] not in ("roundoff", "gaps"):
        sys.exit(__doc__)
    (roundoff if sys.argv[1] == "roundoff" else gaps)(sys.argv[2:])
