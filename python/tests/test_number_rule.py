"""The one number rule from Python (tests/number_rule_test.cpp has the C++ table): every reader
refuses a value that is not a finite number in range, naming the file, the line and the text."""

import re

import pytest

import frontpack

BAD = ["nan", "inf", "-inf", "abc", "0x10", "", "1e400", "1e-400", "1.5.5", "+-1", "1abc"]

VTP = ('<?xml version="1.0"?>\n<VTKFile type="PolyData" version="1.0" byte_order="LittleEndian">\n'
       '<PolyData>\n<Piece NumberOfPoints="1" NumberOfVerts="1">\n<PointData Scalars="radius">\n'
       '<DataArray type="Float64" Name="radius" format="ascii">\n{}\n</DataArray>\n</PointData>\n<Points>\n'
       '<DataArray type="Float64" NumberOfComponents="3" format="ascii">\n0.5 0.5 0\n</DataArray>\n</Points>\n'
       '</Piece>\n</PolyData>\n</VTKFile>\n')

# name: (file name, text with the value, its line, the reader, the line an empty value is reported at)
READERS = {
    "wkt": ("d.wkt", "POLYGON((0 0,1 0,\n1 {},0 1,0 0))\n", 2, frontpack.Domain.from_file, 2),
    "csv": ("d.csv", "x,y,r\n0.5,{},0.1\n", 2, frontpack.read_disks, 2),
    "yade": ("d.txt", "0.5 0.5 0 0.1\n0.5 0.5 0 {}\n", 2, frontpack.read_disks, 2),
    "lammps": ("d.data", "title\n\n1 atoms\n1 atom types\n\n0 1 xlo xhi\n0 1 ylo yhi\n-0.5 0.5 zlo zhi\n\n"
               "Atoms # sphere\n\n1 1 0.2 1 0.5 {} 0\n", 12, frontpack.read_disks, 12),
    "dump": ("d.lammpstrj", "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n1\nITEM: BOX BOUNDS ff ff pp\n0 1\n0 1\n"
             "-0.5 0.5\nITEM: ATOMS id type x y z radius\n1 1 0.5 {} 0 0.1\n", 10, frontpack.read_disks, 10),
    "vtp": ("d.vtp", VTP, 7, frontpack.read_disks, 6),
    "curve": ("curve.csv", "diameter,passing\n0.1,0\n0.2,{}\n", 3, lambda p: frontpack.Radii("curve:" + str(p)), 3),
}


@pytest.mark.parametrize("bad", BAD)
@pytest.mark.parametrize("reader", sorted(READERS))
def test_every_reader_refuses_a_bad_number_naming_file_line_and_text(tmp_path, reader, bad):
    name, text, line, read, empty_line = READERS[reader]
    path = tmp_path / name
    path.write_text(text.format(bad))
    with pytest.raises(frontpack.Error) as e:
        read(path)
    message = str(e.value)
    n = empty_line if bad == "" else line
    assert str(path) in message
    assert re.search(r"(:%d[:\s]|line %d\b)" % (n, n), message), message
    if bad:
        assert "'%s'" % bad in message
