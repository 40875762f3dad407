"""The Python module's overhead over the C++ fill (issue #32): the ~1M-disk fill of
bench/fill_bench.cpp (radii uniform in [5e-4, 5e-3] in a 6 x 6 square, seed 2003), timed as
frontpack.fill() from Python (argument conversion, the progress trampoline that checks for
Ctrl-C, the array made from the library's vector) against frontpack::fill() called from C++ in
the same process (frontpack._core._time_cpp_fill, timed in C++ with the GIL released). Runs
alternate; reported: the minimum of each (the least disturbed runs) and the median of the paired
differences (each Python run against the C++ run just before it), so that a busy machine's drift
cancels.

    PYTHONPATH=build/release/python /usr/bin/python3 bench/python_overhead.py [REPEATS] [METHOD]
"""

import statistics
import sys
import time

import frontpack
from frontpack import _core

repeats = int(sys.argv[1]) if len(sys.argv) > 1 else 5
method = sys.argv[2] if len(sys.argv) > 2 else "boundary"
domain = frontpack.Domain.from_wkt("POLYGON((0 0,6 0,6 6,0 6,0 0))")
radii = frontpack.Radii.uniform(5e-4, 5e-3)

cpp, python = [], []
for _ in range(repeats):
    seconds, disks = _core._time_cpp_fill(domain, radii, 2003, method)
    cpp.append(seconds)
    t0 = time.perf_counter()
    packing = frontpack.fill(domain, radii, seed=2003, method=method, max_disks=200_000_000)
    python.append(time.perf_counter() - t0)
    assert len(packing) == disks, (len(packing), disks)
    del packing

print(f"{method}, {disks} disks, {repeats} runs each")
print(f"C++ fill:    min {min(cpp):.3f} s, median {statistics.median(cpp):.3f} s")
print(f"Python fill: min {min(python):.3f} s, median {statistics.median(python):.3f} s")
print(f"overhead:    {100 * (min(python) - min(cpp)) / min(cpp):+.2f}% (min), "
      f"{100 * statistics.median((p - c) / c for p, c in zip(python, cpp)):+.2f}% (median of the paired runs)")
