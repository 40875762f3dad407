#!/usr/bin/env python3
"""Reads frontpack's files back with the real programs and checks every disk, bit for bit.

    check_readers.py lammps|vtk|yade WRITER SHAPE.wkt WORKDIR

WRITER (tests/readers/write_formats.cpp) fills SHAPE and writes packing.csv, packing.data,
packing.vtp and packing.txt into WORKDIR. The CSV is the reference: it is parsed here with
Python's float(), which rounds correctly, independently of frontpack's readers. Then:

  lammps  `lmp` runs read_data on packing.data (units lj, dimension 2, atom_style sphere) and
          dumps id, type, radius, diameter, mass, x, y, z with 17 significant digits;
  vtk     vtkXMLPolyDataReader reads packing.vtp (points, vertex cells, radius and id arrays);
  yade    `yade -n -x yade_import.py` runs ymport.textExt(packing.txt, format='x_y_z_r') and
          pack.SpherePack().load(packing.txt).

Every disk must come back with exactly the written doubles: same count, same order, same x, y,
radius (LAMMPS: diameter = 2 r), z = 0.

Exit codes: 0 pass, 1 fail, 77 the reader program is not installed (a skip for CTest), unless
the environment has FRONTPACK_REQUIRE_READERS=1, where a missing reader is a failure.
"""
import os
import shutil
import sys

from reader_support import fail, missing, read_csv, run


def read_reference(path):
    return read_csv(path, at_least=100)






def compare(program, got, want):
    """got, want: lists of (x, y, z, r) in the reference order."""
    if len(got) != len(want):
        fail("%s read %d disks, frontpack wrote %d" % (program, len(got), len(want)))
    for i, (g, w) in enumerate(zip(got, want)):
        if g != (w[0], w[1], 0.0, w[2]):
            fail("%s: disk %d is (x, y, z, r) = %r, frontpack wrote %r" % (program, i, g, (w[0], w[1], 0.0, w[2])))
    print("%s: %d disks, every x, y, z and radius bit-identical" % (program, len(got)))


def check_lammps(work, want):
    lmp = shutil.which("lmp") or shutil.which("lmp_serial")
    if lmp is None:
        missing("LAMMPS (Debian package lammps, program lmp)")
    with open(os.path.join(work, "in.frontpack"), "w", encoding="ascii") as f:
        f.write(
            "units lj\n"
            "dimension 2\n"
            "atom_style sphere\n"
            "boundary f f p\n"
            "read_data packing.data\n"
            "variable n equal count(all)\n"
            'print "FRONTPACK_COUNT ${n}"\n'
            "write_dump all custom dump.frontpack id type radius diameter mass x y z"
            " modify sort id format float %.17g\n"
        )
    out = run([lmp, "-in", "in.frontpack", "-log", "none", "-nocite"], work)
    counts = [line.split()[1] for line in out.splitlines() if line.startswith("FRONTPACK_COUNT")]
    if counts != [str(len(want))]:
        fail("LAMMPS count(all) printed %r, frontpack wrote %d disks:\n%s" % (counts, len(want), out))
    with open(os.path.join(work, "dump.frontpack"), encoding="ascii") as f:
        lines = f.read().splitlines()
    start = lines.index("ITEM: ATOMS id type radius diameter mass x y z") + 1
    got = []
    conventions = set()
    for i, line in enumerate(lines[start:]):
        ident, kind, radius, diameter, mass, x, y, z = line.split()
        if int(ident) != i + 1 or kind != "1":
            fail("LAMMPS atom %d has id %s, type %s" % (i + 1, ident, kind))
        r = float(radius)
        if float(diameter) != 2 * r:
            fail("LAMMPS atom %s: diameter %s is not twice the radius %s" % (ident, diameter, radius))
        # density 1: mass = (4/3) pi r^3 (LAMMPS 2021, even in 2D) or pi r^2 (a disc convention).
        m = float(mass)
        sphere, disc = 4.0 / 3.0 * 3.141592653589793 * r**3, 3.141592653589793 * r**2
        if abs(m - sphere) <= 1e-12 * sphere:
            conventions.add("mass = density * 4/3 pi r^3")
        elif abs(m - disc) <= 1e-12 * disc:
            conventions.add("mass = density * pi r^2")
        else:
            fail("LAMMPS atom %s: mass %s is neither 4/3 pi r^3 nor pi r^2 for radius %s" % (ident, mass, radius))
        got.append((float(x), float(y), float(z), r))
    compare("LAMMPS read_data", got, want)
    print("LAMMPS: " + ", ".join(sorted(conventions)))


def check_vtk(work, want):
    try:
        import vtk  # Debian package python3-vtk9, for /usr/bin/python3
    except ImportError:
        missing("VTK for Python (Debian package python3-vtk9)")
    errors = []
    reader = vtk.vtkXMLPolyDataReader()
    reader.AddObserver("ErrorEvent", lambda obj, event: errors.append(event))
    reader.SetFileName(os.path.join(work, "packing.vtp"))
    reader.Update()
    if errors or reader.GetErrorCode() != 0:
        fail("vtkXMLPolyDataReader reported errors reading packing.vtp")
    data = reader.GetOutput()
    n = data.GetNumberOfPoints()
    if n != len(want) or data.GetNumberOfVerts() != n or data.GetNumberOfCells() != n:
        fail("VTK: %d points, %d vertex cells, %d cells; frontpack wrote %d disks"
             % (n, data.GetNumberOfVerts(), data.GetNumberOfCells(), len(want)))
    if data.GetPoints().GetDataType() != vtk.VTK_DOUBLE:
        fail("VTK: points are not Float64")
    point_data = data.GetPointData()
    radius = point_data.GetArray("radius")
    ids = point_data.GetArray("id")
    if radius is None or ids is None:
        fail("VTK: no 'radius' or no 'id' point data array")
    if radius.GetDataType() != vtk.VTK_DOUBLE or radius.GetNumberOfComponents() != 1:
        fail("VTK: 'radius' is not one Float64 component")
    if point_data.GetScalars() is None or point_data.GetScalars().GetName() != "radius":
        fail("VTK: 'radius' is not the active scalars")
    got = []
    for i in range(n):
        cell = data.GetCell(i)
        if cell.GetCellType() != vtk.VTK_VERTEX or cell.GetNumberOfPoints() != 1 or cell.GetPointId(0) != i:
            fail("VTK: cell %d is not the vertex of point %d" % (i, i))
        if ids.GetValue(i) != i:
            fail("VTK: id of point %d is %r" % (i, ids.GetValue(i)))
        x, y, z = data.GetPoint(i)
        got.append((x, y, z, radius.GetValue(i)))
    compare("VTK vtkXMLPolyDataReader", got, want)


def check_yade(work, want):
    yade = shutil.which("yade")
    if yade is None:
        missing("Yade (Debian package yade)")
    script = os.path.join(os.path.dirname(os.path.abspath(__file__)), "yade_import.py")
    out = run([yade, "-n", "-x", script, "packing.txt"], work)
    got = []
    for line in out.splitlines():
        if line.startswith("FRONTPACK_BODY "):
            got.append(tuple(float(v) for v in line.split()[1:]))
    counts = [line.split()[1] for line in out.splitlines() if line.startswith("FRONTPACK_COUNT ")]
    if counts != [str(len(want))]:
        fail("Yade holds %r bodies, frontpack wrote %d disks:\n%s" % (counts, len(want), out))
    compare("Yade ymport.textExt", got, want)
    packed = [tuple(float(v) for v in line.split()[1:]) for line in out.splitlines()
              if line.startswith("FRONTPACK_SPHEREPACK ")]
    compare("Yade SpherePack.load", packed, want)


def main():
    if len(sys.argv) != 5 or sys.argv[1] not in ("lammps", "vtk", "yade"):
        fail("usage: check_readers.py lammps|vtk|yade WRITER SHAPE.wkt WORKDIR")
    mode = sys.argv[1]
    writer, shape, work = (os.path.abspath(p) for p in sys.argv[2:])
    if os.path.isdir(work):
        shutil.rmtree(work)
    os.makedirs(work)
    run([writer, shape, work], work)
    want = read_reference(os.path.join(work, "packing.csv"))
    {"lammps": check_lammps, "vtk": check_vtk, "yade": check_yade}[mode](work, want)


if __name__ == "__main__":
    main()
