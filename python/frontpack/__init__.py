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


def fill(
    domain,
    radius=default_radius_spec,
    *,
    method="boundary",
    seed=0,
    window=5,
    start=None,
    clearance=0.0,
    fill_voids=True,
    max_disks=50_000_000,
    memory_limit=0,
    fraction=None,
    count=0,
    height=None,
    jam=False,
    progress=None,
    stop=None,
):
    """Fills `domain` with disks; returns a Packing whose `disks` are certified exactly.

    The defaults are the tool's (`frontpack fill DOMAIN`). `radius`: a Radii, a radius spec
    ("uniform:0.01,0.05", "curve:sand.csv", ...) or a number (every radius the same). `method`:
    "boundary" (against the domain's own edges), "closed" or "open" (the paper's forms). The same
    inputs and seed give bit-identical disks. `window`: front check window M (0: the whole
    front). `start`: the closed form's first disks, (x, y). `clearance`: 0 is automatic (a few
    ulps of the coordinates); a value given must be at least 16 * 2^-52 * (largest |coordinate| +
    5 rmax). `fill_voids=False`: the paper's forms as published (the boundary method refuses it).
    `max_disks`, `memory_limit` (bytes; 0: three quarters of the machine's memory): requests
    beyond them raise LimitError up front; a run reaching max_disks stops (Packing.truncated).

    Targets (Packing.target reports what was achieved): `fraction`, a packing fraction F in
    (0, 1) reached within 0.002 with the requested radii exactly (a looser fill shrunk back and
    thinned; no contacts; two or three fills; docs/fraction.md); `count`, exactly this many disks
    in a compact region (closed and open forms); `height`, only the part below y = height is
    filled (every disk has y + r <= height).

    `jam=True`: after the front, disks are inserted and the overlaps relaxed away until the
    packing jams (denser at narrow size ranges: bidisperse 1:1.4 about 0.837 instead of 0.815;
    little change at wide ones; not with fraction or count; docs/jam.md). Progress phase "jam".

    `progress`: a callable taking a Progress, called about every 16384 disks and at each phase
    (returning False stops generating: the packing of what was generated, certified, with
    Packing.cancelled), or True for a bar (tqdm when importable). The GIL is released while the
    library runs. Ctrl-C cancels the run within one progress interval and raises
    KeyboardInterrupt; an exception raised by the callback cancels it and is raised again.
    `stop`: a StopSource another thread may request (CancelledError).

    Raises OptionError, LimitError, NothingFitsError (no disk placed: the message says why), CancelledError.
    """
    d = _shapes.as_domain(domain)
    callback, close = _progress.callback(progress)
    try:
        return _core._fill(
            d, radius, method, seed, window, start, clearance, fill_voids, max_disks, memory_limit, fraction, count,
            height, jam, callback, stop,
        )
    finally:
        close()


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
