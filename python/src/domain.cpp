// frontpack.Domain (domain.hpp, domain_file.hpp): validated polygonal domains and exact queries.
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <string>

#include "bind.hpp"

namespace frontpack::python {

namespace {

std::vector<Ring> holes_from(const py::handle& holes) {
  std::vector<Ring> rings;
  if (!holes.is_none()) {
    for (const py::handle h : holes) {
      rings.push_back(ring_from(h));
    }
  }
  return rings;
}

Periodicity periodicity_from(const std::string& name) {
  for (const Periodicity p : {Periodicity::none, Periodicity::x, Periodicity::xy}) {
    if (name == to_string(p)) {
      return p;
    }
  }
  throw OptionError("periodicity '" + name + "': expected 'x' or 'xy'");
}

// A periodic cell's bounds as the tool's --periodic takes them: (LX, LY), the cell [0, LX) x [0, LY),
// or (xmin, ymin, xmax, ymax).
Box cell_from(const py::handle& bounds) {
  const auto v = bounds.cast<std::vector<double>>();
  if (v.size() == 2) {
    return Box{0, 0, v[0], v[1]};
  }
  if (v.size() != 4) {
    throw py::value_error("a periodic cell is (LX, LY) or (xmin, ymin, xmax, ymax): 2 or 4 numbers, not " +
                          std::to_string(v.size()));
  }
  return box_from(bounds);
}

// locate() of one point (shape (2,)) or of many ((N, 2)): a Location, or a uint8 array of them.
py::object locate(const Domain& d, const py::handle& points) {
  using Doubles = py::array_t<double, py::array::c_style | py::array::forcecast>;
  const Doubles a = Doubles::ensure(points);
  if (a && a.ndim() == 1 && a.shape(0) == 2) {
    return py::cast(d.locate(Point{a.at(0), a.at(1)}));
  }
  const Ring ps = ring_from(points);
  py::array_t<std::uint8_t> out(static_cast<py::ssize_t>(ps.size()));
  std::uint8_t* o = out.mutable_data();
  {
    py::gil_scoped_release release;
    for (std::size_t i = 0; i < ps.size(); ++i) {
      o[i] = static_cast<std::uint8_t>(d.locate(ps[i]));
    }
  }
  return out;
}

// contains() of one disk (shape (3,)) or of many ((N, 3)): a bool, or a bool array.
py::object contains(const Domain& d, const py::handle& disks) {
  using Doubles = py::array_t<double, py::array::c_style | py::array::forcecast>;
  const Doubles a = Doubles::ensure(disks);
  if (a && a.ndim() == 1 && a.shape(0) == 3) {
    return py::bool_(d.contains(Disk{{a.at(0), a.at(1)}, a.at(2)}));
  }
  const std::vector<Disk> ds = disks_from(disks);
  py::array_t<bool> out(static_cast<py::ssize_t>(ds.size()));
  // numpy's bool is one byte holding 0 or 1, which is what contains() writes.
  std::span<std::uint8_t> o(reinterpret_cast<std::uint8_t*>(out.mutable_data()), ds.size());
  {
    py::gil_scoped_release release;
    d.contains(ds, o);
  }
  return out;
}

py::list polygons(const Domain& d) {
  py::list out;
  for (const Polygon& p : d.polygons()) {
    py::list holes;
    for (const Ring& h : p.holes) {
      holes.append(ring_array(h));
    }
    out.append(py::make_tuple(ring_array(p.outer), holes));
  }
  return out;
}

py::dict curve_dict(const CurveReport& c) {
  py::dict d;
  d["entity"] = c.entity;
  d["centre"] = py::make_tuple(c.centre.x, c.centre.y);
  d["radius"] = c.radius;
  d["sweep"] = c.sweep;
  d["domain_inside"] = c.domain_inside;
  d["deviation"] = c.deviation;
  d["segments"] = c.segments;
  d["nudged"] = c.nudged;
  return d;
}

}  // namespace

void bind_domain(py::module_& m) {
  py::enum_<Location>(m, "Location", "Where a point lies relative to a domain; boundary: exactly on an edge or vertex.")
      .value("outside", Location::outside)
      .value("boundary", Location::boundary)
      .value("inside", Location::inside);

  py::class_<Domain>(m, "Domain",
                     "One or more polygons with holes, validated (OGC Simple Features rules) and normalised: "
                     "outer rings anticlockwise, holes clockwise, rings open. Every query is decided exactly on "
                     "the input doubles (no tolerance). Immutable; cheap to copy; safe to query from several "
                     "threads.")
      .def_static("from_wkt", &Domain::from_wkt, py::arg("wkt"),
                  "A POLYGON or MULTIPOLYGON from WKT text. Raises WktError for text that is not such a geometry "
                  "(numbers out of the double range included: never rounded quietly) and InvalidDomainError for "
                  "an invalid geometry.")
      .def_static(
          "from_file",
          [](const std::filesystem::path& path, const std::string& format, double max_deviation,
             double relative_deviation, double join_tolerance) {
            return read_domain_file(path, DomainReadOptions{parse_domain_format(format), max_deviation,
                                                            relative_deviation, join_tolerance})
                .domain;
          },
          py::arg("path"), py::arg("format") = "auto", py::arg("max_deviation") = 0.0,
          py::arg("relative_deviation") = default_relative_deviation, py::arg("join_tolerance") = 1e-9,
          "A domain from a WKT, DXF, GeoJSON or Shapefile file (format 'auto': by the extension). DXF arcs become "
          "polylines on the domain's side of the true curve, at most max_deviation from it (0: relative_deviation "
          "times the curve's radius). Raises IoError, OptionError (a reader this build lacks), DomainFileError, "
          "WktError, InvalidDomainError, each naming the file.")
      .def_static(
          "from_rings",
          [](const py::handle& outer, const py::handle& holes) {
            return Domain::from_rings(ring_from(outer), holes_from(holes));
          },
          py::arg("outer"), py::arg("holes") = py::none(),
          "A polygon from an (N, 2) outer ring and a sequence of (M, 2) holes, each open or closed (a last "
          "vertex equal to the first is dropped), in either orientation. Raises InvalidDomainError.")
      .def_static(
          "from_polygons",
          [](const py::iterable& parts) {
            std::vector<Polygon> polygons;
            for (const py::handle part : parts) {
              const auto t = part.cast<py::sequence>();
              if (t.size() < 1 || t.size() > 2) {
                throw py::value_error("each polygon is (outer, holes) or (outer,)");
              }
              polygons.push_back(Polygon{ring_from(t[0]), t.size() == 2 ? holes_from(t[1]) : std::vector<Ring>{}});
            }
            return Domain::from_polygons(std::move(polygons));
          },
          py::arg("polygons"),
          "A multipolygon from a sequence of (outer, holes) pairs, rings as in from_rings. Raises "
          "InvalidDomainError (overlapping parts included).")
      .def_static(
          "periodic",
          [](const py::handle& bounds, const std::string& axes) {
            return Domain::periodic(cell_from(bounds), periodicity_from(axes));
          },
          py::arg("bounds"), py::arg("axes") = "xy",
          "A periodic cell [xmin, xmax) x [ymin, ymax) from bounds (xmin, ymin, xmax, ymax), or [0, LX) x [0, LY) "
          "from (LX, LY) as the tool's --periodic; axes 'xy' (a flat "
          "torus) or 'x' (walls at the bottom and top). Periods are taken exactly. Raises InvalidDomainError for "
          "an empty, non-finite or too large box, OptionError for another axes value.")
      .def_property_readonly(
          "periodicity", [](const Domain& d) { return to_string(d.periodicity()); },
          "'none' for a polygonal domain, 'x' or 'xy' for a periodic cell.")
      .def_property_readonly("area", &Domain::area, "The exact area rounded to the nearest double.")
      .def_property_readonly("perimeter", &Domain::perimeter, "Perimeter of all rings (floating point).")
      .def_property_readonly(
          "bbox", [](const Domain& d) { return box_tuple(d.bbox()); }, "(xmin, ymin, xmax, ymax), as shapely's bounds.")
      .def_property_readonly("num_polygons", &Domain::num_polygons)
      .def_property_readonly("num_holes", &Domain::num_holes)
      .def_property_readonly("num_vertices", &Domain::num_vertices)
      .def_property_readonly("max_abs_coordinate", &Domain::max_abs_coordinate,
                             "Largest |coordinate| of any vertex: the scale of constructions' rounding error.")
      .def("polygons", &polygons,
           "The normalised polygons, in input order: a list of (outer, holes), each ring an (N, 2) float64 array "
           "(open: the closing vertex is not repeated).")
      .def("locate", &locate, py::arg("points"),
           "Exact point location: for one point (x, y) a Location; for an (N, 2) array a uint8 array of "
           "Location values (0 outside, 1 boundary, 2 inside).")
      .def("contains", &contains, py::arg("disks"),
           "Exact: whether the closed disk (x, y, r) lies in the closed domain (touching the boundary counts as "
           "inside; a negative or NaN radius never does). For an (N, 3) array, a bool array (the batch form, "
           "about constant cost per disk).")
      .def("to_wkt", &Domain::to_wkt,
           "WKT with shortest round-trip numbers: Domain.from_wkt(d.to_wkt()) gives an identical domain.")
      .def_property_readonly("wkt", &Domain::to_wkt, "to_wkt(), as shapely names it.")
      .def(py::pickle(  // by WKT (exact: shortest round-trip numbers) and the periodicity
          [](const Domain& d) { return py::make_tuple(d.to_wkt(), to_string(d.periodicity())); },
          [](const py::tuple& state) {
            const Domain d = Domain::from_wkt(state[0].cast<std::string>());
            const auto axes = state[1].cast<std::string>();
            return axes == to_string(Periodicity::none) ? d : Domain::periodic(d.bbox(), periodicity_from(axes));
          }))
      .def("__repr__", [](const Domain& d) {
        return "<frontpack.Domain " + std::to_string(d.num_polygons()) + " polygon(s), " +
               std::to_string(d.num_holes()) + " hole(s), area " + py::repr(py::float_(d.area())).cast<std::string>() +
               (d.periodicity() == Periodicity::none ? std::string()
                                                     : std::string(", periodic ") + to_string(d.periodicity())) +
               ">";
      });

  m.def(
      "read_domain_file",
      [](const std::filesystem::path& path, const std::string& format, double max_deviation, double relative_deviation,
         double join_tolerance) {
        DomainFile f = read_domain_file(
            path, DomainReadOptions{parse_domain_format(format), max_deviation, relative_deviation, join_tolerance});
        py::dict out;
        out["domain"] = f.domain;
        out["format"] = to_string(f.format);
        out["contours"] = f.contours;
        out["ignored_entities"] = f.ignored_entities;
        py::list curves;
        for (const CurveReport& c : f.curves) {
          curves.append(curve_dict(c));
        }
        out["curves"] = curves;
        out["units"] = f.units;
        return out;
      },
      py::arg("path"), py::arg("format") = "auto", py::arg("max_deviation") = 0.0,
      py::arg("relative_deviation") = default_relative_deviation, py::arg("join_tolerance") = 1e-9,
      "Domain.from_file with the reader's report: a dict of domain, format, contours, ignored_entities, curves "
      "(one dict per arc: entity, centre, radius, sweep, domain_inside, deviation, segments, nudged) and units "
      "(DXF: the units $INSUNITS names, e.g. 'millimeters'; '' when the file names none).");
  m.def("has_dxf_reader", &has_dxf_reader, "Whether this build reads DXF domains.");
  m.def("has_gis_reader", &has_gis_reader, "Whether this build reads GeoJSON and Shapefile domains.");
}

}  // namespace frontpack::python
