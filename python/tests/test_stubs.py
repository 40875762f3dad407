"""python/frontpack/__init__.pyi describes the package as it is: every public name, every public
attribute and method of the classes, and the same parameters for the functions."""

import ast
import inspect
import pathlib

import frontpack

STUBS = ast.parse((pathlib.Path(__file__).resolve().parents[1] / "frontpack" / "__init__.pyi").read_text())
# TypedDicts describe the dicts the functions return, not names of the module
# (test_result_fields.py checks them).
TOP = {
    n.name: n
    for n in STUBS.body
    if isinstance(n, ast.FunctionDef)
    or (isinstance(n, ast.ClassDef) and not any(getattr(b, "id", "") == "TypedDict" for b in n.bases))
}
TOP.update({n.target.id: n for n in STUBS.body if isinstance(n, ast.AnnAssign)})


def test_every_public_name_has_a_stub():
    assert sorted(set(frontpack.__all__) - set(TOP)) == []
    assert sorted(n for n in TOP if not hasattr(frontpack, n)) == []


def test_classes_match():
    for name, node in TOP.items():
        cls = getattr(frontpack, name)
        if not isinstance(node, ast.ClassDef) or issubclass(cls, BaseException) or hasattr(cls, "__members__"):
            continue  # exceptions have their own test; enums list their values
        stub = {m.name for m in node.body if isinstance(m, ast.FunctionDef)}
        stub |= {m.target.id for m in node.body if isinstance(m, ast.AnnAssign)}
        real = {a for a in dir(getattr(frontpack, name)) if not a.startswith("_")}
        assert (name, sorted(real - stub)) == (name, [])
        assert (name, sorted(s for s in stub - real if not s.startswith("__"))) == (name, [])


def test_python_functions_have_the_stubs_parameters():
    for name in ("fill", "as_domain"):
        stub = [a.arg for a in TOP[name].args.args + TOP[name].args.kwonlyargs]
        assert list(inspect.signature(getattr(frontpack, name)).parameters) == stub


def test_exception_fields_are_in_the_stubs():
    wkt = {m.target.id for m in TOP["WktError"].body if isinstance(m, ast.AnnAssign)}
    try:
        frontpack.Domain.from_wkt("POLYGON((")
    except frontpack.WktError as e:
        assert wkt <= set(vars(e)) and set(vars(e)) <= wkt


def _literal(node):
    """The strings of a Literal[...] annotation (inside Optional[...] too)."""
    while isinstance(node, ast.Subscript) and node.value.id != "Literal":
        node = node.slice
    return [e.value for e in node.slice.elts]


def test_format_literals_are_the_table_of_formats():
    # The names a function accepts come from the library's one table of formats.
    table = frontpack._core.file_formats()
    written = [f["name"] for f in table if f["library_writes"]]
    read = [f["name"] for f in table if f["library_reads_disks"]]
    write_format = next(n for n in STUBS.body if isinstance(n, ast.Assign) and n.targets[0].id == "WriteFormat")
    assert _literal(write_format.value) == written
    read_disks = next(a for a in TOP["read_disks"].args.args if a.arg == "format")
    assert _literal(read_disks.annotation) == read
    for name in written:
        assert f"'{name}'" in frontpack.write.__doc__ and f"'{name}'" in frontpack.dumps.__doc__
    for f in table:
        if f["library_reads_disks"]:
            assert f"'{f['name']}'" in frontpack.read_disks.__doc__
            assert all(ext in frontpack.read_disks.__doc__ for ext in f["extensions"])
