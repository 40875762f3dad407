#!/usr/bin/env python3
"""Runs the deck of a periodic cell in the real LAMMPS, LIGGGHTS or Yade and checks it.

    check_periodic_deck.py lammps|liggghts|yade xy|x HELPER TOOL WORKDIR

HELPER (frontpack_periodic_deck) writes a dense periodic packing (fill's closed form in the cell,
bidisperse 1:1.4, certified exactly) and its deck: boundary p p p (xy) or
p f p with wall planes (x). `lmp` (or `liggghts`) runs it, 1000 steps, under gravity in the shear
cell (x) and without in the torus (xy: no wall would hold the packing, which would fall as one).
At step 0 every atom is where the CSV puts it and feels its weight and nothing else (fx = 0,
fy = -m g; in the torus fx = fy = 0: no contact, across the seams included), and the script has
gravity exactly in the shear cell; at step 1000 no atom is lost; `frontpack check --periodic` certifies the dump's
first snapshot. Then the same with one disk moved across the seam into its neighbour's image by 1%
of a radius: LAMMPS must see that contact at step 0 and the check must name the pair (exit 6), so
the test can fail.

Yade (`yade -n -x run.py 500`, O.periodic): the script counts the real interactions after its first
step (0 for the packing, across the periodic sides too; some for the planted overlap), every
sphere is there at the end and, in a shear cell, between the walls (up to 5% of rmin);
`frontpack check --periodic` certifies the deck's packing.txt (and names the planted pair).

Exit 0 pass, 1 fail, 77 the simulator is not installed (a skip), unless FRONTPACK_REQUIRE_READERS=1.
"""
import os
import shutil
import subprocess
import sys

from check_decks import read_dump
from reader_support import fail, missing, run
from reader_support import read_csv as read_any_csv

STEPS = 1000


def make_yade(helper, axes, kind, work):
    out = os.path.join(work, kind)
    shutil.rmtree(out, ignore_errors=True)
    lines = run([helper, "yade", axes, kind, out], work).splitlines()
    cell, planted = lines[0], (lines[1] if len(lines) > 1 else "")
    deck = os.path.join(out, "deck")
    log = run([shutil.which("yade"), "-n", "-x", "run.py", "500"], deck)
    if "FRONTPACK_DONE 500 steps" not in log:
        fail("yade did not finish 500 steps:\n" + log[-3000:])
    contacts = int(log.split("FRONTPACK_START_CONTACTS ")[1].split()[0])
    want = read_any_csv(os.path.join(out, "packing.csv"), header="x,y,r,type", at_least=400)
    with open(os.path.join(deck, "final.txt"), encoding="ascii") as f:
        end = [tuple(float(v) for v in line.split()) for line in f.read().splitlines()]
    if len(end) != len(want):
        fail("yade: %d spheres at the end, frontpack wrote %d" % (len(end), len(want)))
    return deck, cell, planted, want, contacts, end


def main_yade(axes, helper, tool, work):
    deck, cell, _, want, contacts, end = make_yade(helper, axes, "clean", work)
    if contacts != 0:
        fail("yade: %d contacts after the first step: an overlap Yade sees" % contacts)
    if axes == "x":
        ymin, ymax = (float(v) for v in cell.split(",")[1::2])
        rmin = min(w[2] for w in want)
        out = [e for e in end if e[1] - e[2] < ymin - 0.05 * rmin or e[1] + e[2] > ymax + 0.05 * rmin]
        if out:
            fail("yade: %d spheres through the shear cell's walls, e.g. %r" % (len(out), out[:3]))
    with open(os.path.join(deck, "run.py"), encoding="ascii") as f:
        if ("gravity=(0, 0, 0)" in f.read()) != (axes == "xy"):
            fail("yade: run.py should apply gravity in the shear cell only")
    check = [tool, "check", "--periodic", cell, "--periodic-axes", axes, "packing.txt"]
    run(check, deck)
    print("yade O.periodic (%s): %d spheres, no contact after the first step, none lost in 500 steps%s; "
          "packing.txt certified by frontpack check --periodic"
          % (axes, len(want), ", all between the walls" if axes == "x" else ""))
    deck, cell, planted, want, contacts, end = make_yade(helper, axes, "overlap", work)
    if contacts == 0:
        fail("yade: the planted overlap across the seam made no contact after the first step")
    result = run(check + ["--all"], deck, expect=6)
    if "overlap %s\n" % planted not in result:
        fail("check did not name the planted pair %s:\n%s" % (planted, result[-2000:]))
    print("yade O.periodic (%s): the planted overlap across the seam makes %d contacts and is named by check"
          % (axes, contacts))


def make(simulator, helper, axes, kind, work):
    out = os.path.join(work, kind)
    shutil.rmtree(out, ignore_errors=True)
    lines = run([helper, simulator, axes, kind, out], work).splitlines()
    cell, planted = lines[0], (lines[1] if len(lines) > 1 else "")
    if simulator == "lammps":
        run([shutil.which("lmp"), "-in", "in.frontpack", "-log", "none", "-nocite"], os.path.join(out, "deck"))
    else:
        run([shutil.which("liggghts"), "-in", "in.frontpack", "-log", "none"], os.path.join(out, "deck"))
    want = read_any_csv(os.path.join(out, "packing.csv"), header="x,y,r,type", at_least=400)
    frames = read_dump(os.path.join(out, "deck", "free.lammpstrj"))
    return out, cell, planted, want, frames


def contacts_at_start(start, want, gravity):
    """The atoms that feel more than their weight (gravity 0: any force) at step 0; fails if an
    atom is not where the CSV puts it."""
    rel = 1e-12
    touched = []
    for a, (x, y, r, t) in zip(start, want):
        if int(a["type"]) != t or abs(a["x"] - x) > 1e-15 or abs(a["y"] - y) > 1e-15 or abs(a["radius"] - r) > rel * r:
            fail("atom %d is %r at step 0, frontpack wrote %r" % (int(a["id"]), a, (x, y, r, t)))
        weight = a["mass"] * gravity
        if a["fx"] != 0 or (a["fy"] != 0 if gravity == 0 else abs(a["fy"] + weight) > rel * weight):
            touched.append(int(a["id"]))
    return touched


def main():
    simulator, axes, helper, tool, work = sys.argv[1:6]
    program = {"lammps": "lmp", "liggghts": "liggghts", "yade": "yade"}[simulator]
    if shutil.which(program) is None:
        missing(program)
    os.makedirs(work, exist_ok=True)
    if simulator == "yade":
        main_yade(axes, helper, tool, work)
        return

    out, cell, _, want, frames = make(simulator, helper, axes, "clean", work)
    if sorted(frames) != list(range(0, STEPS + 1, STEPS // 10)):
        fail("dump timesteps %r, expected 0 to %d every %d" % (sorted(frames), STEPS, STEPS // 10))
    gravity = 9.81 if axes == "x" else 0.0
    touched = contacts_at_start(frames[0], want, gravity)
    if touched:
        fail("atoms %r feel a contact at step 0: an overlap LAMMPS sees" % touched[:10])
    for step, atoms in frames.items():
        if len(atoms) != len(want):
            fail("%d atoms at step %d, frontpack wrote %d: atoms lost" % (len(atoms), step, len(want)))
    deck = os.path.join(out, "deck")
    with open(os.path.join(deck, "in.frontpack"), encoding="ascii") as f:
        script = f.read()
    boundary = "boundary p p p" if axes == "xy" else "boundary p f p"
    if boundary not in script:
        fail("in.frontpack has no %r" % boundary)
    if ("fix gravity" in script) != (axes == "x"):
        fail("in.frontpack %s gravity: expected it in the shear cell only" % ("has" if axes == "xy" else "lacks"))
    check = [tool, "check", "--periodic", cell, "--periodic-axes", axes, "free.lammpstrj", "--timestep", "0"]
    run(check, deck)
    print("%s %s: %d atoms, step 0 contact-free (each feels %s), none lost in %d steps, "
          "step 0 certified by frontpack check --periodic"
          % (simulator, boundary, len(want), "only its weight" if gravity else "no force", STEPS))

    out, cell, planted, want, frames = make(simulator, helper, axes, "overlap", work)
    i, j = (int(v) for v in planted.split())
    touched = contacts_at_start(frames[0], want, gravity)
    if i + 1 not in touched or j + 1 not in touched:
        fail("the planted overlap across the seam (atoms %d and %d) is not seen by LAMMPS at step 0: %r"
             % (i + 1, j + 1, touched[:10]))
    result = run(check + ["--all"], os.path.join(out, "deck"), expect=6)
    if "overlap %d %d\n" % (i, j) not in result:
        fail("check did not name the planted pair %d %d:\n%s" % (i, j, result[-2000:]))
    print("%s %s: the planted overlap across the seam is seen by the simulator (atoms %r) and by check" %
          (simulator, boundary, touched))


if __name__ == "__main__":
    main()
