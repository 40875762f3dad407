#!/usr/bin/python3
"""Seams of a packing of a periodic cell [0, L) x [0, L): an independent look, with scipy.

    tools/periodic_seams.py PACKING.csv L [SAMPLES_PER_CELL]

Prints the overlapping pairs through the nearest image (floating point, a second opinion to
`frontpack check --periodic`, which decides exactly), the packing fraction, and the coverage of
the cells of side 8 rmax (estimated on a grid of SAMPLES_PER_CELL^2 points per cell, default 16):
its mean, 1st percentile, the cells along the sides x = 0 and y = 0 (column and row 0, and the last
ones, which touch them through the side) against the cells elsewhere. docs/periodic.md uses it.
"""
import sys

import numpy as np
from scipy.spatial import cKDTree


def main():
    path, side = sys.argv[1], float(sys.argv[2])
    per_cell = int(sys.argv[3]) if len(sys.argv) > 3 else 16
    disks = np.loadtxt(path, delimiter=",", skiprows=1, usecols=(0, 1, 2), ndmin=2)
    x, y, r = disks[:, 0], disks[:, 1], disks[:, 2]
    tree = cKDTree(np.c_[x, y], boxsize=[side, side])
    overlaps, worst = 0, 0.0
    for i, j in tree.query_pairs(2 * r.max()):
        dx = x[i] - x[j]
        dy = y[i] - y[j]
        dx -= side * np.round(dx / side)
        dy -= side * np.round(dy / side)
        depth = r[i] + r[j] - np.hypot(dx, dy)
        if depth > 0:
            overlaps += 1
            worst = max(worst, depth)
    print(f"disks {len(r)}, overlapping pairs {overlaps} (deepest {worst:.3g})")
    print(f"fraction {np.pi * np.sum(r * r) / side**2:.4f}")
    cell = 8 * r.max()
    cells = int(side // cell)
    n = per_cell * cells
    g = (np.arange(n) + 0.5) * (cells * cell) / n
    gx, gy = np.meshgrid(g, g)
    dist, idx = tree.query(np.c_[gx.ravel(), gy.ravel()], k=6)
    covered = (dist <= r[idx]).any(axis=1).reshape(n, n)
    cover = covered.reshape(cells, per_cell, cells, per_cell).mean(axis=(1, 3))  # [row, column]
    inner = cover[1:-1, 1:-1]
    print(f"cells of 8 rmax: {cells} x {cells}, mean {cover.mean():.4f}, 1st percentile {np.percentile(cover, 1):.4f}")
    print(f"along x = 0: column 0 {cover[:, 0].mean():.4f}, last column {cover[:, -1].mean():.4f}")
    print(f"along y = 0: row 0 {cover[0, :].mean():.4f}, last row {cover[-1, :].mean():.4f}")
    print(f"elsewhere: mean {inner.mean():.4f}, sd {inner.std():.4f}")


if __name__ == "__main__":
    main()
