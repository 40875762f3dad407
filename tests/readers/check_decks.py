#!/usr/bin/env python3
"""Runs a simulator deck written by `frontpack fill --deck` in the real program and checks it.

    check_decks.py lammps|liggghts|yade TOOL SHAPE.wkt RADIUS WORKDIR

TOOL fills SHAPE with RADIUS, two size types, and writes WORKDIR/packing.csv (the reference,
with its type column) and the deck into WORKDIR/deck. Then the simulator runs the deck as it is:

  lammps, liggghts  `lmp` / `liggghts -in in.frontpack`, 5000 steps under gravity. At step 0
                    every free atom is where the CSV puts it, with its type, and feels its weight
                    and nothing else (fx = 0, fy = -m g: no contact force, so no overlap with
                    another disk or a wall); at the end no atom is lost and every disk is inside
                    the domain (its centre inside, at least r - 5% rmin from the boundary);
  yade              `yade -n -x run.py 500`: every sphere (with its material = type) is inside at
                    the end.

"Inside" allows 5% of rmin past the boundary: the LAMMPS wall chain's bumps (at most 1.6% of the
wall radius, docs/simulators.md) and the contacts' elastic overlap.

Then the same deck without its walls (LAMMPS: wall atoms deleted; LIGGGHTS: no wall fix; Yade: no
facets; 4000 steps, since 500 move a disk too little to leave) must FAIL the inside check: the
check sees a leak. Exit 0 pass, 1 fail, 77 the simulator is
not installed (a skip), unless FRONTPACK_REQUIRE_READERS=1.
"""
import math
import os
import shutil
import subprocess
import sys

from reader_support import fail, missing, run
from reader_support import read_csv as read_any_csv


def read_csv(path):
    return read_any_csv(path, header="x,y,r,type", at_least=1000)






def read_dump(path):
    """{timestep: [dict per atom]} from a LAMMPS/LIGGGHTS custom dump."""
    frames = {}
    with open(path, encoding="ascii") as f:
        lines = f.read().splitlines()
    i = 0
    while i < len(lines):
        step = int(lines[i + 1])
        n = int(lines[i + 3])
        columns = lines[i + 8].split()[2:]
        frames[step] = [dict(zip(columns, (float(v) for v in line.split()))) for line in lines[i + 9:i + 9 + n]]
        i += 9 + n
    return frames


def outside(domain, disks, tolerance):
    """The disks (x, y, r) not inside: centre outside, or nearer the boundary than r - tolerance."""
    from shapely.geometry import Point

    bad = []
    boundary = domain.boundary
    for x, y, r in disks:
        p = Point(x, y)
        if not domain.contains(p) or boundary.distance(p) < r - tolerance:
            bad.append((x, y, r))
    return bad


def simulate(simulator, deck, steps):
    if simulator == "lammps":
        run([shutil.which("lmp"), "-in", "in.frontpack", "-log", "none", "-nocite"], deck)
    elif simulator == "liggghts":
        run([shutil.which("liggghts"), "-in", "in.frontpack", "-log", "none"], deck)
    else:
        out = run([shutil.which("yade"), "-n", "-x", "run.py", str(steps)], deck)
        if "FRONTPACK_DONE %d steps" % steps not in out:
            fail("yade did not finish %d steps:\n%s" % (steps, out[-3000:]))


def final_disks(simulator, deck, want):
    """The free disks at the end, as (x, y, r); checks that none was lost."""
    if simulator == "yade":
        with open(os.path.join(deck, "final.txt"), encoding="ascii") as f:
            rows = [line.split() for line in f.read().splitlines()]
        if len(rows) != len(want):
            fail("yade: %d spheres at the end, frontpack wrote %d" % (len(rows), len(want)))
        for row, w in zip(rows, want):
            if float(row[2]) != w[2] or int(row[3]) != w[3]:
                fail("yade: sphere radius/type %s %s, frontpack wrote %r" % (row[2], row[3], w))
        return [(float(r[0]), float(r[1]), float(r[2])) for r in rows]
    frames = read_dump(os.path.join(deck, "free.lammpstrj"))
    last = frames[max(frames)]
    if max(frames) != 5000 or len(last) != len(want):
        fail("%s: %d free atoms at step %d, frontpack wrote %d" % (simulator, len(last), max(frames), len(want)))
    return [(a["x"], a["y"], a["radius"]) for a in last]


def check_start(simulator, deck, want, gravity):
    frames = read_dump(os.path.join(deck, "free.lammpstrj"))
    start = frames[0]
    if len(start) != len(want):
        fail("%s: %d free atoms at step 0, frontpack wrote %d" % (simulator, len(start), len(want)))
    # Both dump 17 digits (dump_modify format): the start is the CSV's doubles up to the
    # simulators' own arithmetic (mass = density pi r^2 rounded).
    rel = 1e-12
    for a, (x, y, r, t) in zip(start, want):
        if int(a["type"]) != t or abs(a["x"] - x) > rel * 4 or abs(a["y"] - y) > rel * 4 or abs(a["radius"] - r) > rel * r:
            fail("%s: atom %d is %r at step 0, frontpack wrote %r" % (simulator, int(a["id"]), a, (x, y, r, t)))
        weight = a["mass"] * gravity
        if a["fx"] != 0 or abs(a["fy"] + weight) > rel * weight:
            fail("%s: atom %d feels force (%r, %r) at step 0, its weight is %r: a contact at the start"
                 % (simulator, int(a["id"]), a["fx"], a["fy"], weight))
    print("%s: step 0: %d free atoms where frontpack put them, each feeling only its weight" % (simulator, len(start)))


def recheck(tool, deck, steps):
    """`frontpack check` on the dump: the first snapshot (the packing as written) certifies; the
    last, after the dynamics, is either certified or has its overlaps reported (exit 6, naming a
    pair): settling under gravity with soft contacts overlaps some, by design of DEM."""
    run([tool, "check", "domain.wkt", "free.lammpstrj", "--timestep", "0"], deck)
    result = subprocess.run([tool, "check", "domain.wkt", "free.lammpstrj"], cwd=deck, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True)
    if result.returncode == 6 and "overlap" in result.stdout:
        print("check: step 0 certified; step %d: the overlaps the dynamics made are reported" % steps)
    elif result.returncode == 0:
        print("check: steps 0 and %d both certified" % steps)
    else:
        fail("check on the final snapshot exited %d:\n%s" % (result.returncode, result.stdout))


def sabotage(simulator, deck):
    """The deck without its walls."""
    if simulator == "lammps":
        path, old, new = "in.frontpack", "group wall type", "delete_atoms group wall\ngroup wall type"
    elif simulator == "liggghts":
        path, old, new = "in.frontpack", "fix wall all wall/gran", "# fix wall all wall/gran"
    else:
        path, old, new = "run.py", "for ring in RINGS:", "for ring in []:"
    with open(os.path.join(deck, path), encoding="ascii") as f:
        text = f.read()
    if old not in text:
        fail("cannot remove the walls from %s: no %r" % (path, old))
    # LAMMPS: deleting the wall atoms must happen after both groups exist.
    if simulator == "lammps":
        text = text.replace("fix walls wall freeze\n", "delete_atoms group wall\nfix walls wall freeze\n")
    else:
        text = text.replace(old, new)
    with open(os.path.join(deck, path), "w", encoding="ascii") as f:
        f.write(text)


def main():
    simulator, tool, shape, radius, work = sys.argv[1:6]
    program = {"lammps": "lmp", "liggghts": "liggghts", "yade": "yade"}[simulator]
    if shutil.which(program) is None:
        missing(program)
    import shapely.wkt

    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    deck = os.path.join(work, "deck")
    lo, hi = (float(v) for v in radius.split(":")[1].split(","))
    edge = (lo + hi) / 2
    run([tool, "fill", shape, "--radius", radius, "--seed", "3", "--types", "size:%r" % edge, "-q",
         "-o", os.path.join(work, "packing.csv"), "--deck", simulator, deck, "--density", "1:2500,2:7800"], work)
    # The domain the deck was made for (a DXF's arcs as the polylines certified against): the disks
    # must stay in it, which is stricter than staying in the true curves.
    with open(os.path.join(deck, "domain.wkt"), encoding="ascii") as f:
        domain = shapely.wkt.loads(f.read())
    want = read_csv(os.path.join(work, "packing.csv"))
    if {d[3] for d in want} != {1, 2}:
        fail("expected disks of types 1 and 2")
    rmin = min(d[2] for d in want)
    steps = 500 if simulator == "yade" else 5000
    pristine = os.path.join(work, "pristine")
    shutil.copytree(deck, pristine)

    simulate(simulator, deck, steps)
    if simulator != "yade":
        check_start(simulator, deck, want, 9.81)
    end = final_disks(simulator, deck, want)
    bad = outside(domain, end, 0.05 * rmin)
    if bad:
        fail("%s: %d disks outside the domain after %d steps, e.g. %r" % (simulator, len(bad), steps, bad[:3]))
    if simulator != "yade":
        recheck(tool, deck, steps)
    moved = max(math.hypot(e[0] - w[0], e[1] - w[1]) for e, w in zip(end, want))
    print("%s: %d steps, no disk lost, every disk inside (largest displacement %.3g = %.3g rmin)"
          % (simulator, steps, moved, moved / rmin))

    sabotage(simulator, pristine)
    # Yade's 500 steps move a disk 0.002 rmin: too little to see a leak; 4000 move it about 0.13 rmin.
    simulate(simulator, pristine, 4000 if simulator == "yade" else steps)
    leaked = outside(domain, final_disks(simulator, pristine, want), 0.05 * rmin)
    if not leaked:
        fail("%s: the deck without walls kept every disk inside: the check cannot see a leak" % simulator)
    print("%s: without its walls, %d disks leave the domain: the check sees leaks" % (simulator, len(leaked)))


if __name__ == "__main__":
    main()
