#!/usr/bin/env python3
"""Files written by the real programs, read back by frontpack's readers, bit for bit.

    from_programs.py lammps|vtk WRITER TO_CSV TOOL SHAPE.wkt WORKDIR

WRITER (write_formats.cpp) fills SHAPE and writes packing.csv (the reference, parsed here with
Python's float()), packing.data and packing.vtp into WORKDIR. TO_CSV (disks_to_csv.cpp) reads a
file with frontpack::read_disks and writes it as CSV; TOOL is the frontpack tool.

  lammps  `lmp` reads packing.data, runs 0 steps, and writes the state with write_data and as a
          dump (id type x y z radius, %.17g): both must read back as the reference, and
          `frontpack check` must certify the data file (exit 0). Then a few hundred steps of
          gravity settling with granular (Hooke) contacts press the disks into each other: check
          must exit 6 and name the overlapping pairs, for the data file and the dump alike.
  vtk     vtkXMLPolyDataReader reads packing.vtp and vtkXMLPolyDataWriter writes it again in
          ascii, binary (inline base64) and appended raw modes, uncompressed: each must read back
          as the reference and be certified by check (with --wkt). The writer's default, zlib
          compression, must be refused with exit 7 and a message that says how to write it.

Exit codes: 0 pass, 1 fail, 77 the program is not installed (a skip for CTest), unless
FRONTPACK_REQUIRE_READERS=1, where a missing program is a failure.
"""
import os
import re
import shutil
import sys

from reader_support import fail, missing, read_csv, run






def same_as_reference(to_csv, work, name, want):
    out = os.path.join(work, name + ".csv")
    run([to_csv, os.path.join(work, name), out], work)
    got = read_csv(out)
    if len(got) != len(want):
        fail("%s: frontpack read %d disks, the reference has %d" % (name, len(got), len(want)))
    for i, (g, w) in enumerate(zip(got, want)):
        if g != w:
            fail("%s: disk %d is %r, the reference %r" % (name, i, g, w))
    print("%s: %d disks, every x, y and radius bit-identical" % (name, len(got)))


LAMMPS_SETUP = """units lj
dimension 2
atom_style sphere
comm_modify vel yes
boundary f f p
read_data packing.data
pair_style gran/hooke 2000 NULL 50 NULL 0.5 0
pair_coeff * *
fix integrate all nve/sphere disc
fix plane all enforce2d
timestep 0.0001
"""


def check_lammps(work, to_csv, tool, shape, want):
    lmp = shutil.which("lmp") or shutil.which("lmp_serial")
    if lmp is None:
        missing("LAMMPS (Debian package lammps, program lmp)")
    with open(os.path.join(work, "in.still"), "w", encoding="ascii") as f:
        f.write(LAMMPS_SETUP + "dump d all custom 1 still.dump id type x y z radius\n"
                "dump_modify d format float %.17g\nrun 0\nwrite_data still.data\n")
    run([lmp, "-in", "in.still", "-log", "none", "-nocite", "-screen", "none"], work)
    same_as_reference(to_csv, work, "still.data", want)
    same_as_reference(to_csv, work, "still.dump", want)
    out = run([tool, "check", shape, "still.data"], work)
    if "certified: no two disks overlap" not in out:
        fail("check did not certify LAMMPS's write_data after 0 steps:\n" + out)
    print("check certifies LAMMPS's write_data after a 0-step run")

    with open(os.path.join(work, "in.settle"), "w", encoding="ascii") as f:
        f.write(LAMMPS_SETUP + "set group all density 1000\nfix down all gravity 100 vector 0 -1 0\n"
                "fix box all wall/reflect xlo EDGE xhi EDGE ylo EDGE\n"
                "dump d all custom 100 settled.dump id type x y z radius\n"
                "dump_modify d format float %.17g\nrun 500\nwrite_data settled.data\n")
    run([lmp, "-in", "in.settle", "-log", "none", "-nocite", "-screen", "none"], work)
    for name in ("settled.data", "settled.dump"):
        out = run([tool, "check", "--all", shape, name], work, expect=6)
        pairs = re.search(r"overlaps: +([0-9]+) pairs? of overlapping disks; worst: disks [0-9]+ and [0-9]+", out)
        listed = re.findall(r"^overlap [0-9]+ [0-9]+$", out, re.M)
        if not pairs or int(pairs.group(1)) == 0 or len(listed) != int(pairs.group(1)):
            fail("check on %s after settling did not name the overlapping pairs:\n%s" % (name, out))
        if "is not certified" not in out:
            fail("check on %s did not say NOT certified:\n%s" % (name, out))
        print("%s: check exits 6 and names %s overlapping pairs" % (name, pairs.group(1)))
    # The dump's first snapshot is the packing itself.
    out = run([tool, "check", "--timestep", "0", shape, "settled.dump"], work)
    if "certified: no two disks overlap" not in out:
        fail("check did not certify the dump's timestep 0:\n" + out)
    print("settled.dump --timestep 0: certified")


def check_vtk(work, to_csv, tool, shape, want):
    try:
        import vtk  # Debian package python3-vtk9, for /usr/bin/python3
    except ImportError:
        missing("VTK for Python (Debian package python3-vtk9)")
    reader = vtk.vtkXMLPolyDataReader()
    reader.SetFileName(os.path.join(work, "packing.vtp"))
    reader.Update()
    data = reader.GetOutput()
    if data.GetNumberOfPoints() != len(want):
        fail("VTK read %d points, frontpack wrote %d" % (data.GetNumberOfPoints(), len(want)))
    with open(shape, encoding="ascii") as f:
        wkt = f.read().strip()
    for mode in ("ascii", "binary", "appended", "zlib"):
        name = "vtk_%s.vtp" % mode
        writer = vtk.vtkXMLPolyDataWriter()
        writer.SetFileName(os.path.join(work, name))
        writer.SetInputData(data)
        if mode == "ascii":
            writer.SetDataModeToAscii()
        elif mode == "binary":
            writer.SetDataModeToBinary()
        else:
            writer.SetDataModeToAppended()
            writer.EncodeAppendedDataOff()
        if mode != "zlib":
            writer.SetCompressorTypeToNone()
        if writer.Write() != 1:
            fail("vtkXMLPolyDataWriter failed on " + name)
        if mode == "zlib":
            out = run([tool, "check", "--wkt", wkt, name], work, expect=7)
            if "compressed data (vtkZLibDataCompressor) is not read by frontpack" not in out:
                fail("check on a zlib-compressed file did not say why:\n" + out)
            print("%s: refused (exit 7) with the reason" % name)
            continue
        same_as_reference(to_csv, work, name, want)
        out = run([tool, "check", "--wkt", wkt, name], work)
        if "certified: no two disks overlap" not in out:
            fail("check did not certify %s:\n%s" % (name, out))


def main():
    if len(sys.argv) != 7 or sys.argv[1] not in ("lammps", "vtk"):
        fail("usage: from_programs.py lammps|vtk WRITER TO_CSV TOOL SHAPE.wkt WORKDIR")
    mode = sys.argv[1]
    writer, to_csv, tool, shape, work = (os.path.abspath(p) for p in sys.argv[2:])
    if os.path.isdir(work):
        shutil.rmtree(work)
    os.makedirs(work)
    run([writer, shape, work], work)
    want = read_csv(os.path.join(work, "packing.csv"))
    if len(want) < 100:
        fail("only %d disks; the test wants a real packing" % len(want))
    {"lammps": check_lammps, "vtk": check_vtk}[mode](work, to_csv, tool, shape, want)


if __name__ == "__main__":
    main()
