// The compiled core of the Python package frontpack (frontpack/_core): each part binds one header's
// worth of the library; python/frontpack/__init__.py adds shapes and the progress bar on top.
#include "bind.hpp"

PYBIND11_MODULE(_core, m) {
  namespace fp = frontpack::python;
  m.doc() = "frontpack's compiled core; use the package frontpack.";
  m.attr("__version__") = frontpack::version_string;
  fp::bind_errors(m);
  fp::bind_domain(m);
  fp::bind_radii(m);
  fp::bind_certify(m);
  fp::bind_fill(m);
  fp::bind_stats(m);
  fp::bind_io(m);
}
