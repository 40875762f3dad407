// frontpack.Radii (sizes.hpp): radius distributions, from the tool's spec strings or by keyword.
#include <pybind11/stl.h>

#include <string>

#include "bind.hpp"

namespace frontpack::python {

namespace {

Basis basis_from(const std::string& name) {
  for (const Basis b : {Basis::number, Basis::area}) {
    if (name == to_string(b)) {
      return b;
    }
  }
  throw OptionError("basis '" + name + "': expected 'number' or 'area'");
}

SizeKind kind_from(const std::string& name) {
  for (const SizeKind k : {SizeKind::radius, SizeKind::diameter}) {
    if (name == to_string(k)) {
      return k;
    }
  }
  throw OptionError("kind '" + name + "': expected 'radius' or 'diameter'");
}

std::vector<SizeFraction> rows_from(const py::iterable& rows) {
  std::vector<SizeFraction> out;
  for (const py::handle row : rows) {
    const auto pair = row.cast<std::pair<double, double>>();
    out.push_back(SizeFraction{pair.first, pair.second});
  }
  return out;
}

}  // namespace

void bind_radii(py::module_& m) {
  py::class_<Radii>(m, "Radii",
                    "A distribution of disk radii. Radii are drawn by inverse transform from frontpack's own "
                    "generator, so a seed gives the same radii on every platform (with the same libm). Every "
                    "constructor validates its parameters and raises OptionError naming the bad one; NaN and "
                    "infinities are refused.")
      .def(py::init(&parse_radii), py::arg("spec"),
           "A radius spec as the tool's --radius takes it: 'uniform:RMIN,RMAX', 'constant:R', "
           "'normal:MEAN,SD[,LO,HI]', 'lognormal:MEDIAN,GSD[,LO,HI]', 'discrete:S1:F1,S2:F2,...[@MOD]', "
           "'discrete:FILE.csv', 'curve:S1:P1,...[@MOD]', 'curve:FILE.csv' (MOD: area, number, radius, "
           "diameter). Raises OptionError naming the bad part, IoError for an unreadable file.")
      .def_static("uniform", &Radii::uniform, py::arg("rmin"), py::arg("rmax"),
                  "Uniform in [rmin, rmax] (the paper's); 0 < rmin <= rmax.")
      .def_static("constant", &Radii::constant, py::arg("r"), "Every radius r > 0.")
      .def_static("normal", &Radii::normal, py::arg("mean"), py::arg("sd"), py::arg("lo"), py::arg("hi"),
                  "Normal (of the radius) truncated to [lo, hi]: sd > 0, 0 < lo < hi.")
      .def_static("lognormal", &Radii::lognormal, py::arg("median"), py::arg("gsd"), py::arg("lo"), py::arg("hi"),
                  "Lognormal with this median and geometric standard deviation gsd > 1, truncated to [lo, hi].")
      .def_static(
          "discrete",
          [](const py::iterable& classes, const std::string& basis, const std::string& kind) {
            return Radii::discrete(rows_from(classes), basis_from(basis), kind_from(kind));
          },
          py::arg("classes"), py::arg("basis") = "number", py::arg("kind") = "radius",
          "Discrete classes [(size, fraction), ...]: sizes > 0 and distinct, fractions in [0, 1] summing to 1 "
          "(within 1e-6), by 'number' or 'area'; sizes are radii or ('diameter') diameters, halved exactly.")
      .def_static(
          "grading_curve",
          [](const py::iterable& points, const std::string& basis, const std::string& kind) {
            return Radii::grading_curve(rows_from(points), basis_from(basis), kind_from(kind));
          },
          py::arg("points"), py::arg("basis") = "area", py::arg("kind") = "diameter",
          "A sieve curve [(size, passing), ...]: sizes increasing, passing non-decreasing from 0 to 1, linear in "
          "log(size) between points; by area and in diameters unless told otherwise.")
      .def_property_readonly("min", &Radii::min)
      .def_property_readonly("max", &Radii::max)
      .def("describe", &Radii::describe, "One line, e.g. 'uniform in [0.01, 0.05] (radius)'.")
      .def(
          "quantile", [](const Radii& r, double u) { return r.distribution().quantile(u); }, py::arg("u"),
          "The radius at cumulative probability u in [0, 1).")
      .def(
          "cdf", [](const Radii& r, double x) { return r.distribution().cdf(x); }, py::arg("r"),
          "P(radius <= r), by number.")
      .def(
          "sample",
          [](const Radii& r, std::size_t n, std::uint64_t seed) {
            std::vector<double> v = sample_radii(r, n, seed);
            auto* owned = new std::vector<double>(std::move(v));
            py::capsule base(owned, [](void* p) { delete static_cast<std::vector<double>*>(p); });
            return py::array_t<double>(static_cast<py::ssize_t>(owned->size()), owned->data(), base);
          },
          py::arg("n"), py::arg("seed") = 0,
          "The first n radii a fill with this seed draws, in order (a float64 array).")
      .def("__repr__", [](const Radii& r) { return "<frontpack.Radii " + r.describe() + ">"; });
  py::implicitly_convertible<py::str, Radii>();
  m.attr("default_radius_spec") = default_radius_spec;
}

}  // namespace frontpack::python
