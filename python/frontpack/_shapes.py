"""Domains from what a Python script holds: WKT text, files, shapely geometries (any object with
``__geo_interface__`` or a ``.wkt`` attribute; shapely itself is never imported), GeoJSON-like
dicts, and coordinate arrays."""

import os

import numpy as np

from . import _core


def _ring(coordinates):
    ring = np.asarray(coordinates, dtype=np.float64)
    if ring.ndim != 2 or ring.shape[1] != 2:
        raise ValueError(
            "a ring's coordinates must be (x, y) pairs; got an array of shape %s "
            "(frontpack's domains are 2D: drop z first)" % (ring.shape,)
        )
    return ring


def _polygon(rings):
    rings = list(rings)
    if not rings:
        raise ValueError("a Polygon needs at least its outer ring")
    return (_ring(rings[0]), [_ring(h) for h in rings[1:]])


def from_geo(geo):
    """A Domain from a GeoJSON-like mapping: a Polygon, a MultiPolygon, or a Feature holding one."""
    kind = geo.get("type")
    if kind == "Feature":
        return from_geo(geo["geometry"])
    if kind == "Polygon":
        return _core.Domain.from_polygons([_polygon(geo["coordinates"])])
    if kind == "MultiPolygon":
        return _core.Domain.from_polygons([_polygon(p) for p in geo["coordinates"]])
    raise TypeError("a domain is a Polygon or a MultiPolygon, not a %r geometry" % (kind,))


def as_domain(shape):
    """A Domain from ``shape``: a Domain (returned as is), WKT text (str), a path (os.PathLike or
    pathlib.Path: Domain.from_file), an object with ``__geo_interface__`` (a shapely Polygon or
    MultiPolygon, a GeoPandas geometry), a GeoJSON-like dict, or an object with a ``.wkt`` str.
    Raises WktError, InvalidDomainError, TypeError for anything else."""
    if isinstance(shape, _core.Domain):
        return shape
    if isinstance(shape, str):
        return _core.Domain.from_wkt(shape)
    if isinstance(shape, os.PathLike):
        return _core.Domain.from_file(shape)
    geo = getattr(shape, "__geo_interface__", None)
    if geo is not None:
        return from_geo(geo)
    if isinstance(shape, dict):
        return from_geo(shape)
    wkt = getattr(shape, "wkt", None)
    if isinstance(wkt, str):
        return _core.Domain.from_wkt(wkt)
    raise TypeError(
        "cannot make a frontpack.Domain from %s: give WKT text, a path, a shapely Polygon or "
        "MultiPolygon (anything with __geo_interface__ or .wkt), or a GeoJSON-like dict"
        % type(shape).__name__
    )


def _closed(ring):
    points = [(float(x), float(y)) for x, y in ring]
    return tuple(points + points[:1])


def geo_interface(domain):
    """The domain as a GeoJSON-like mapping (rings closed), so that shapely.geometry.shape(domain)
    gives the same polygons."""
    parts = [
        (_closed(outer),) + tuple(_closed(h) for h in holes) for outer, holes in domain.polygons()
    ]
    if len(parts) == 1:
        return {"type": "Polygon", "coordinates": parts[0]}
    return {"type": "MultiPolygon", "coordinates": tuple(parts)}
