"""Fill a shapely polygon with a hole, check it, plot it, write a LAMMPS data file.

    PYTHONPATH=build/release/python /usr/bin/python3 examples/python_fill.py [OUTPUT_DIR]

Needs the Python module (built by `tools/dev.sh build` when pybind11-dev, python3-dev and
python3-numpy are installed), python3-shapely; the picture needs python3-matplotlib (skipped
without it).
"""

import pathlib
import sys

import numpy as np
from shapely.geometry import Point, Polygon

import frontpack

out = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".")
out.mkdir(parents=True, exist_ok=True)

# A plate with a round hole: shapely builds it, frontpack takes it as it is (no import of shapely
# inside frontpack: any object with __geo_interface__ will do).
plate = Polygon([(0, 0), (0.2, 0), (0.2, 0.1), (0, 0.1)]).difference(Point(0.1, 0.05).buffer(0.025))

# Radii uniform in [1 mm, 2.5 mm], seed 1: the same disks on every run, bit for bit.
packing = frontpack.fill(plate, "uniform:0.001,0.0025", seed=1, progress=True)
disks = packing.disks  # (N, 3) float64: x, y, r; a view of the library's memory
print(f"{len(disks)} disks, certified: {packing.certificate}")

# Certify again independently of the run (any (N, 3) array works: after a simulation too).
report = frontpack.certify(plate, disks)
assert report.valid, report

stats = frontpack.measure(plate, disks, requested=frontpack.Radii("uniform:0.001,0.0025"), samples=200_000)
print(f"packing fraction {stats['packing_fraction']:.4f}, mean coordination {stats['mean_coordination']:.2f}, "
      f"rattlers {stats['rattlers']}")

# LAMMPS data file (atom_style sphere), two types by size, densities per type.
types = frontpack.assign_types([0.00175], disks)
frontpack.write(out / "plate.data", plate, disks, types=types, type_densities=[2500, 7800])
print(f"wrote {out / 'plate.data'}")

try:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.collections import EllipseCollection
except ImportError:
    print("matplotlib is not installed: no picture (Debian: python3-matplotlib)")
else:
    fig, ax = plt.subplots(figsize=(8, 4.4))
    ax.add_collection(EllipseCollection(2 * disks[:, 2], 2 * disks[:, 2], np.zeros(len(disks)), units="xy",
                                        offsets=disks[:, :2], offset_transform=ax.transData,
                                        array=disks[:, 2], cmap="viridis"))
    for ring in [plate.exterior, *plate.interiors]:
        ax.plot(*ring.xy, color="black", linewidth=0.8)
    ax.set_aspect("equal")
    ax.autoscale_view()
    ax.set_title(f"{len(disks)} disks, packing fraction {stats['packing_fraction']:.3f}")
    fig.savefig(out / "plate.png", dpi=120, bbox_inches="tight")
    print(f"wrote {out / 'plate.png'}")
