"""The fill options are described once, in the library (frontpack/options.hpp, _core.fill_options()):
frontpack.fill's keywords and defaults, its docstring, the .pyi stub and the `frontpack fill` flags
must all agree with that description, and the library refuses what the tool refuses."""

import ast
import inspect
import os
import pathlib
import subprocess

import pytest

import frontpack
from frontpack import _core

OPTIONS = _core.fill_options()
STUB = ast.parse((pathlib.Path(__file__).resolve().parents[1] / "frontpack" / "__init__.pyi").read_text())
SQUARE = "POLYGON((0 0,1 0,1 1,0 1,0 0))"


def described():
    return {o["name"]: o["default"] for o in OPTIONS}


def test_the_description_has_every_fill_option():
    names = [o["name"] for o in OPTIONS]
    assert len(set(names)) == len(names) and "radius" in names and "stop" not in names
    for o in OPTIONS:
        assert o["help"] and o["kind"] and o["flag"].startswith("--") and o["expected"] and o["default_text"], o


def test_fill_takes_exactly_the_described_keywords_with_their_defaults():
    params = inspect.signature(frontpack.fill).parameters
    extra = {"domain", "progress", "stop"}
    assert set(params) - extra == set(described())
    for name, default in described().items():
        assert params[name].default == default, name
        assert type(params[name].default) is type(default), name
    assert list(params)[:2] == ["domain", "radius"]  # radius also by position
    with pytest.raises(TypeError):
        frontpack.fill(SQUARE, no_such_option=1)


def test_the_stub_agrees_with_the_description():
    node = next(n for n in STUB.body if isinstance(n, ast.FunctionDef) and n.name == "fill")
    positional = node.args.args[len(node.args.args) - len(node.args.defaults):]
    stub = {a.arg: ast.literal_eval(d) for a, d in zip(positional, node.args.defaults)}
    stub.update({a.arg: ast.literal_eval(d) for a, d in zip(node.args.kwonlyargs, node.args.kw_defaults)})
    for name in ("progress", "stop"):
        assert stub.pop(name) is None
    assert stub == described()
    assert {k: type(v) for k, v in stub.items()} == {k: type(v) for k, v in described().items()}


def test_the_docstring_names_every_option_and_its_default():
    for o in OPTIONS:
        assert "`%s` (default %r): %s" % (o["name"], o["default"], o["help"]) in frontpack.fill.__doc__


def test_the_tool_has_a_flag_for_every_option_with_its_default():
    tool = os.environ.get("FRONTPACK_TOOL")
    if not tool:
        pytest.skip("FRONTPACK_TOOL is not set (the build has no tool)")
    help_text = " ".join(subprocess.run([tool, "fill", "--help"], capture_output=True, text=True, check=True)
                         .stdout.split())
    for o in OPTIONS:
        assert o["flag"] in help_text, o["name"]
        assert " ".join(("%s (default %s)" % (o["help"], o["default_text"])).split()) in help_text, o["name"]


def test_start_with_another_form_or_several_polygons_is_refused_by_the_library():
    with pytest.raises(frontpack.OptionError, match=r"start \(--start\) is where the closed form"):
        frontpack.fill(SQUARE, "constant:0.1", method="open", start=(0.5, 0.5))
    with pytest.raises(frontpack.OptionError, match=r"the boundary form has no start point"):
        frontpack.fill(SQUARE, "constant:0.1", start=(0.5, 0.5))
    two = "MULTIPOLYGON(((0 0,1 0,1 1,0 1,0 0)),((2 0,3 0,3 1,2 1,2 0)))"
    with pytest.raises(frontpack.OptionError, match="the domain has 2 polygons"):
        frontpack.fill(two, "constant:0.1", method="closed", start=(0.5, 0.5))


def test_values_are_checked_as_the_tool_checks_them():
    with pytest.raises(frontpack.OptionError, match=r"^window 4294967297: expected a whole number from 0 to 4294967296$"):
        frontpack.fill(SQUARE, window=2**32 + 1)
    with pytest.raises(frontpack.OptionError, match=r"^window -1: expected a whole number"):
        frontpack.fill(SQUARE, window=-1)
    with pytest.raises(frontpack.OptionError, match=r"^clearance -1: expected a gap > 0"):
        frontpack.fill(SQUARE, clearance=-1.0)
    with pytest.raises(TypeError, match="seed must be"):
        frontpack.fill(SQUARE, seed="x")
