// frontpack.certify (certify.hpp): the exact check of any (N, 3) array of disks against a domain.
#include <pybind11/stl.h>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "bind.hpp"
#include "fields.hpp"

namespace frontpack::python {

namespace {

CertifyReport certify_array(const Domain& domain, const py::handle& disks) {
  const std::vector<Disk> ds = disks_from(disks);
  py::gil_scoped_release release;
  return certify(domain, ds);
}

py::array pairs_array(const std::vector<std::pair<std::size_t, std::size_t>>& pairs) {
  py::array_t<std::int64_t> out({static_cast<py::ssize_t>(pairs.size()), py::ssize_t{2}});
  auto p = out.mutable_unchecked<2>();
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const auto i = static_cast<py::ssize_t>(k);
    p(i, 0) = static_cast<std::int64_t>(pairs[k].first);
    p(i, 1) = static_cast<std::int64_t>(pairs[k].second);
  }
  return out;
}

bool valid(const CertifyReport& r) {
  return r.outside.empty() && r.overlapping.empty();
}

}  // namespace

void bind_certify(py::module_& m) {
  py::class_<Certificate> certificate(m, "Certificate", "The certifier's report on a packing.");
  bind_fields(certificate);
  certificate.def("__repr__", [](const Certificate& c) {
    return "<frontpack.Certificate " + std::to_string(c.generated) + " generated, " + std::to_string(c.culled) +
           " culled, " + std::to_string(c.dropped) + " dropped, " + std::to_string(c.candidate_pairs) +
           " candidate pairs>";
  });

  py::class_<CertifyReport> report(m, "CertifyReport", "What certify() found.");
  bind_fields(report);
  // The index lists as int64 arrays: `outside` (N,) and `overlapping` (K, 2).
  report
      .def_property_readonly(
          "outside", [](const CertifyReport& r) { return index_array(r.outside); },
          (field_doc<CertifyReport>("outside") + " An int64 array.").c_str())
      .def_property_readonly(
          "overlapping", [](const CertifyReport& r) { return pairs_array(r.overlapping); },
          (field_doc<CertifyReport>("overlapping") + " A (K, 2) int64 array.").c_str())
      .def_property_readonly("valid", &valid, "No disk outside and no pair overlapping.")
      .def("__bool__", &valid)
      .def("__repr__", [](const CertifyReport& r) {
        return "<frontpack.CertifyReport " + std::to_string(r.outside.size()) + " outside, " +
               std::to_string(r.overlapping.size()) + " overlapping pairs>";
      });

  m.def("certify", &certify_array, py::arg("domain"), py::arg("disks"),
        "Certifies any (N, 3) array of disks (x, y, r) against a domain, exactly on the given doubles: which "
        "disks are not inside the closed domain and which pairs overlap (interiors intersect; touching is fine). "
        "The report is true when the packing is valid. The GIL is released while it runs.");
}

}  // namespace frontpack::python
