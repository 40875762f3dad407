// frontpack.certify (certify.hpp): the exact check of any (N, 3) array of disks against a domain.
#include <pybind11/stl.h>

#include <string>

#include "bind.hpp"

namespace frontpack::python {

namespace {

struct PyCertifyReport {
  Certificate certificate;
  py::array outside;
  py::array overlapping;
  py::object deepest_overlap = py::none();
  double deepest_overlap_depth = 0;
  py::object farthest_outside = py::none();
  double farthest_outside_by = 0;
};

PyCertifyReport certify_array(const Domain& domain, const py::handle& disks) {
  const std::vector<Disk> ds = disks_from(disks);
  CertifyReport r;
  {
    py::gil_scoped_release release;
    r = certify(domain, ds);
  }
  PyCertifyReport out;
  out.certificate = r.certificate;
  out.outside = index_array(r.outside);
  py::array_t<std::int64_t> pairs({static_cast<py::ssize_t>(r.overlapping.size()), py::ssize_t{2}});
  auto p = pairs.mutable_unchecked<2>();
  for (std::size_t k = 0; k < r.overlapping.size(); ++k) {
    const auto i = static_cast<py::ssize_t>(k);
    p(i, 0) = static_cast<std::int64_t>(r.overlapping[k].first);
    p(i, 1) = static_cast<std::int64_t>(r.overlapping[k].second);
  }
  out.overlapping = std::move(pairs);
  if (r.deepest_overlap) {
    out.deepest_overlap = py::make_tuple(r.deepest_overlap->first, r.deepest_overlap->second);
  }
  out.deepest_overlap_depth = r.deepest_overlap_depth;
  if (r.farthest_outside) {
    out.farthest_outside = py::cast(*r.farthest_outside);
  }
  out.farthest_outside_by = r.farthest_outside_by;
  return out;
}

}  // namespace

void bind_certify(py::module_& m) {
  py::class_<Certificate>(m, "Certificate", "The certifier's report on a packing.")
      .def_readonly("generated", &Certificate::generated, "Disks produced by the generator.")
      .def_readonly("culled", &Certificate::culled, "Removed because not entirely inside the domain (exact).")
      .def_readonly("dropped", &Certificate::dropped,
                    "Removed by the global overlap pass (0 for frontpack's generator).")
      .def_readonly("candidate_pairs", &Certificate::candidate_pairs, "Pairs whose boxes met, each decided exactly.")
      .def_readonly("exact", &Certificate::exact, "Every containment and every pair was decided exactly.")
      .def("__repr__", [](const Certificate& c) {
        return "<frontpack.Certificate " + std::to_string(c.generated) + " generated, " + std::to_string(c.culled) +
               " culled, " + std::to_string(c.dropped) + " dropped, " + std::to_string(c.candidate_pairs) +
               " candidate pairs>";
      });

  py::class_<PyCertifyReport>(m, "CertifyReport", "What certify() found.")
      .def_readonly("certificate", &PyCertifyReport::certificate)
      .def_readonly("outside", &PyCertifyReport::outside,
                    "int64 array: indices of the disks not inside the closed domain (non-finite or negative disks "
                    "included).")
      .def_readonly("overlapping", &PyCertifyReport::overlapping,
                    "(K, 2) int64 array: index pairs (i < j) whose interiors intersect, sorted. Touching is fine.")
      .def_readonly("deepest_overlap", &PyCertifyReport::deepest_overlap,
                    "The pair with the deepest overlap r_i + r_j - |c_i - c_j| (floating point), or None.")
      .def_readonly("deepest_overlap_depth", &PyCertifyReport::deepest_overlap_depth)
      .def_readonly("farthest_outside", &PyCertifyReport::farthest_outside,
                    "The outside disk reaching farthest out, or None.")
      .def_readonly("farthest_outside_by", &PyCertifyReport::farthest_outside_by,
                    "How far it reaches out: r - d, d the signed distance of its centre to the boundary "
                    "(infinity for a non-finite or negative disk).")
      .def_property_readonly(
          "valid", [](const PyCertifyReport& r) { return r.outside.size() == 0 && r.overlapping.size() == 0; },
          "No disk outside and no pair overlapping.")
      .def("__bool__", [](const PyCertifyReport& r) { return r.outside.size() == 0 && r.overlapping.size() == 0; })
      .def("__repr__", [](const PyCertifyReport& r) {
        return "<frontpack.CertifyReport " + std::to_string(r.outside.size()) + " outside, " +
               std::to_string(r.overlapping.shape(0)) + " overlapping pairs>";
      });

  m.def("certify", &certify_array, py::arg("domain"), py::arg("disks"),
        "Certifies any (N, 3) array of disks (x, y, r) against a domain, exactly on the given doubles: which "
        "disks are not inside the closed domain and which pairs overlap (interiors intersect; touching is fine). "
        "The report is true when the packing is valid. The GIL is released while it runs.");
}

}  // namespace frontpack::python
