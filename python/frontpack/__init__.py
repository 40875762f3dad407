"""frontpack: dense, exactly certified disk packings of polygonal domains.

    import frontpack
    packing = frontpack.fill(shapely_polygon, radius="uniform:0.01,0.05", seed=1)
    packing.disks          # (N, 3) float64 array of x, y, r, certified exactly
    frontpack.write("packing.data", domain, packing.disks)   # LAMMPS, by the extension

Every function that takes a domain takes anything frontpack.as_domain() accepts: a Domain, WKT
text, a path, a shapely geometry (or any object with __geo_interface__ or .wkt), a GeoJSON-like
dict. Disks are numpy (N, 3) float64 arrays; every decision (inside, overlapping) is exact on
their doubles, and every writer writes them in shortest round-trip form.
"""

import functools as _functools
import inspect as _inspect

from . import _core, _progress, _shapes
from ._core import (  # noqa: F401  (the public names)
    CancelledError,
    Certificate,
    CertifyReport,
    DiskFileError,
    Domain,
    DomainFileError,
    Error,
    FillStats,
    InvalidDomainError,
    IoError,
    LimitError,
    Location,
    NothingFitsError,
    OptionError,
    Packing,
    Progress,
    Radii,
    StopSource,
    WktError,
    __version__,
    default_radius_spec,
    has_dxf_reader,
    has_gis_reader,
    read_disks,
    read_domain_file,
)

as_domain = _shapes.as_domain
Domain.from_shape = staticmethod(_shapes.as_domain)
Domain.__geo_interface__ = property(_shapes.geo_interface)


# The fill options, described once in the library (frontpack/options.hpp): fill's keywords, their
# defaults and the docstring's option paragraph are made from this list.
_FILL_OPTIONS = _core.fill_options()
# `radius`, the one option also given by position (after the domain).
_POSITIONAL_OPTION = "radius"


def _fill_signature():
    p = _inspect.Parameter
    by_position = [o for o in _FILL_OPTIONS if o["name"] == _POSITIONAL_OPTION]
    by_keyword = [o for o in _FILL_OPTIONS if o["name"] != _POSITIONAL_OPTION]
    return _inspect.Signature(
        [p("domain", p.POSITIONAL_OR_KEYWORD)]
        + [p(o["name"], p.POSITIONAL_OR_KEYWORD, default=o["default"]) for o in by_position]
        + [p(o["name"], p.KEYWORD_ONLY, default=o["default"]) for o in by_keyword]
        + [p("progress", p.KEYWORD_ONLY, default=None), p("stop", p.KEYWORD_ONLY, default=None)]
    )


_FILL_DOC_HEAD = """Fills `domain` with disks; returns a Packing whose `disks` are certified exactly.

    The defaults are the tool's (`frontpack fill DOMAIN`); the same inputs and seed give
    bit-identical disks. `radius` may also be a Radii or a number (every radius the same).

    Options (keyword, default: what it does; the `frontpack fill` flag):
"""

_FILL_DOC_TAIL = """
    `progress`: a callable taking a Progress, called about every 16384 disks and at each phase
    (returning False stops generating: the packing of what was generated, certified, with
    Packing.cancelled), or True for a bar (tqdm when importable). The GIL is released while the
    library runs. Ctrl-C cancels the run within one progress interval and raises
    KeyboardInterrupt; an exception raised by the callback cancels it and is raised again.
    `stop`: a StopSource another thread may request (CancelledError).

    Raises OptionError (every option checked as the tool checks it: check_options), LimitError,
    NothingFitsError (no disk placed: the message says why), CancelledError.
    """


def _fill_doc():
    lines = [
        "    `%s` (default %r): %s (%s)." % (o["name"], o["default"], o["help"], o["flag"]) for o in _FILL_OPTIONS
    ]
    return _FILL_DOC_HEAD + "\n".join(lines) + "\n" + _FILL_DOC_TAIL


def fill(*args, **kwargs):
    bound = _FILL_SIGNATURE.bind(*args, **kwargs)
    bound.apply_defaults()
    options = dict(bound.arguments)
    d = _shapes.as_domain(options.pop("domain"))
    radius = options.pop(_POSITIONAL_OPTION)
    callback, close = _progress.callback(options.pop("progress"))
    stop = options.pop("stop")
    try:
        return _core._fill(d, radius, callback, stop, **options)
    finally:
        close()


_FILL_SIGNATURE = _fill_signature()
fill.__signature__ = _FILL_SIGNATURE
fill.__doc__ = _fill_doc()


def _takes_domain(function):
    """`function` with its `domain` argument (second for write/render, else first) run through as_domain."""
    position = 1 if function.__name__ in ("write", "render") else 0

    @_functools.wraps(function)
    def wrapper(*args, **kwargs):
        if "domain" in kwargs:
            kwargs["domain"] = _shapes.as_domain(kwargs["domain"])
        elif len(args) > position:
            args = args[:position] + (_shapes.as_domain(args[position]),) + args[position + 1 :]
        return function(*args, **kwargs)

    return wrapper


certify = _takes_domain(_core.certify)
measure = _takes_domain(_core.measure)
write = _takes_domain(_core.write)
dumps = _takes_domain(_core.dumps)
render = _takes_domain(_core.render)
wall_disks = _takes_domain(_core.wall_disks)
make_deck = _takes_domain(_core.make_deck)
assign_types = _core.assign_types

__all__ = [
    "CancelledError", "Certificate", "CertifyReport", "DiskFileError", "Domain", "DomainFileError", "Error",
    "FillStats", "InvalidDomainError", "IoError", "LimitError", "Location", "NothingFitsError", "OptionError", "Packing", "Progress",
    "Radii", "StopSource", "WktError", "as_domain", "assign_types", "certify", "default_radius_spec", "dumps",
    "fill", "has_dxf_reader", "has_gis_reader", "make_deck", "measure", "read_disks", "read_domain_file",
    "render", "wall_disks", "write",
]
