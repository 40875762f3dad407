// frontpack._core.fill (fill.hpp): the run with the GIL released, progress and cancellation.
//
// The run holds no Python object and does not hold the GIL: other Python threads run meanwhile.
// The progress callback (Generator::on_progress, about every 2^14 disks and at each phase) takes
// the GIL back for the user's callback and for PyErr_CheckSignals(), so that Ctrl-C in the
// interpreter is seen within one callback interval. An exception there (KeyboardInterrupt from
// Ctrl-C, or one the user's callback raised) requests the run's stop; the run then throws
// CancelledError, which is replaced by that exception: fill() raises KeyboardInterrupt on Ctrl-C.
#include <pybind11/stl.h>

#include <chrono>
#include <optional>
#include <stop_token>
#include <string>

#include "bind.hpp"
#include "fields.hpp"

namespace frontpack::python {

namespace {

struct PyPacking {
  py::array disks;
  Certificate certificate;
  FillStats stats;
  bool truncated = false;
  bool cancelled = false;
  py::object target = py::none();  // a dict of TargetReport, or None
};

py::object target_dict(const std::optional<TargetReport>& t) {
  return t ? py::object(fields_dict(*t)) : py::object(py::none());
}

// A std::stop_source Python can hold and request from another thread.
struct StopSource {
  std::stop_source source;
};

Method method_from(const std::string& name) {
  for (const Method method : {Method::closed, Method::open, Method::boundary}) {
    if (name == to_string(method)) {
      return method;
    }
  }
  throw OptionError("method '" + name + "': expected 'boundary', 'closed' or 'open'");
}

Radii radii_from(const py::handle& radius) {
  if (py::isinstance<Radii>(radius)) {
    return radius.cast<Radii>();
  }
  if (py::isinstance<py::str>(radius)) {
    return parse_radii(radius.cast<std::string>());
  }
  if (py::isinstance<py::float_>(radius) || py::isinstance<py::int_>(radius)) {
    return Radii::constant(radius.cast<double>());
  }
  throw py::type_error("radius must be a Radii, a radius spec string or a number (a constant radius)");
}

// Adds a note (Python 3.11+) to the exception that cancelled a run, for the traceback and for tests
// that tell a cancelled run from one that had finished.
py::error_already_set cancelled_by(const py::error_already_set& e, std::size_t disks) {
  if (py::hasattr(e.value(), "add_note")) {
    e.value().attr("add_note")("frontpack.fill was cancelled after " + std::to_string(disks) + " disks");
  }
  return e;
}

PyPacking run(const Domain& domain, FillOptions options, const py::object& progress, const py::object& stop) {
  std::stop_source cancel;
  options.stop = cancel.get_token();
  std::optional<std::stop_callback<std::function<void()>>> link;
  if (!stop.is_none()) {
    link.emplace(stop.cast<StopSource&>().source.get_token(), [&cancel] { cancel.request_stop(); });
  }
  std::optional<py::error_already_set> pending;
  std::size_t disks = 0;
  Generator generator(domain, std::move(options));
  generator.on_progress([&](const Progress& p) {
    py::gil_scoped_acquire gil;
    disks = p.disks;
    if (pending) {
      return true;
    }
    try {
      if (PyErr_CheckSignals() != 0) {
        throw py::error_already_set();
      }
      if (!progress.is_none()) {
        const py::object answer = progress(p);
        if (!answer.is_none() && !py::bool_(answer)) {
          return false;  // stop generating; the run certifies and returns what it has
        }
      }
    } catch (py::error_already_set& e) {
      pending.emplace(std::move(e));
      cancel.request_stop();
    }
    return true;
  });
  Packing packing;
  try {
    py::gil_scoped_release release;
    packing = generator.run();
  } catch (const CancelledError&) {
    if (pending) {
      throw cancelled_by(*pending, disks);
    }
    throw;
  }
  if (pending) {
    throw *pending;  // Ctrl-C (or the callback's exception) after the last cancellable point
  }
  return PyPacking{disks_array(std::move(packing.disks)),
                   packing.certificate,
                   packing.stats,
                   packing.truncated,
                   packing.cancelled,
                   target_dict(packing.target)};
}

// Progress, FillStats and Packing: the classes a fill hands back.
void bind_results(py::module_& m) {
  py::class_<Progress> progress_class(m, "Progress", "A run's progress, passed to fill's progress callback.");
  bind_fields(progress_class);
  progress_class.def("__repr__", [](const Progress& p) {
    return "<frontpack.Progress " + std::string(to_string(p.phase)) + " " + std::to_string(p.disks) + " disks, " +
           py::repr(py::float_(p.fraction)).cast<std::string>() + ">";
  });

  py::class_<FillStats> stats_class(
      m, "FillStats",
      "Counters of the advancing front and the jam stage (diagnostics), and the stages' wall "
      "times.");
  bind_fields(stats_class);

  py::class_<PyPacking>(m, "Packing", "The result of fill().")
      .def_readonly("disks", &PyPacking::disks,
                    "(N, 3) float64 array of x, y, r: certified pairwise non-overlapping and inside the domain, "
                    "exactly. It views the library's own memory (no copy).")
      .def_readonly("certificate", &PyPacking::certificate)
      .def_readonly("stats", &PyPacking::stats)
      .def_readonly("truncated", &PyPacking::truncated, "max_disks was reached.")
      .def_readonly("cancelled", &PyPacking::cancelled, "The progress callback returned False.")
      .def_readonly("target", &PyPacking::target,
                    "With fraction, count or height: what was achieved, a dict of the TargetReport fields "
                    "(frontpack._core._result_fields['TargetReport']); else None.")
      .def("__len__", [](const PyPacking& p) { return p.disks.shape(0); })
      .def("__repr__", [](const PyPacking& p) {
        return "<frontpack.Packing " + std::to_string(p.disks.shape(0)) + " disks, certified (" +
               std::to_string(p.certificate.generated) + " generated, " + std::to_string(p.certificate.culled) +
               " culled, " + std::to_string(p.certificate.dropped) + " dropped)>";
      });
}

}  // namespace

void bind_fill(py::module_& m) {
  py::class_<StopSource>(m, "StopSource",
                         "Cancels a fill from another thread: pass it as fill(..., stop=s) and call "
                         "s.request_stop(); the fill raises CancelledError within milliseconds.")
      .def(py::init<>())
      .def(
          "request_stop", [](StopSource& s) { return s.source.request_stop(); },
          "Requests the stop; True if this call made the request.")
      .def_property_readonly("stop_requested", [](const StopSource& s) { return s.source.stop_requested(); });

  bind_results(m);

  m.def(
      "_fill",
      [](const Domain& domain, const py::handle& radius, const std::string& method, std::uint64_t seed,
         std::size_t window, const std::optional<std::pair<double, double>>& start, double clearance, bool fill_voids,
         std::size_t max_disks, std::size_t memory_limit, std::optional<double> fraction, std::size_t count,
         std::optional<double> height, bool jam, const py::object& progress, const py::object& stop) {
        FillOptions o;
        o.method = method_from(method);
        o.radii = radii_from(radius);
        o.seed = seed;
        o.window = window;
        if (start) {
          o.start = Point{start->first, start->second};
        }
        o.clearance = clearance;
        o.fill_voids = fill_voids;
        o.max_disks = max_disks;
        o.memory_limit = memory_limit;
        o.fraction = fraction;
        o.count = count;
        o.height = height;
        o.jam = jam;
        return run(domain, std::move(o), progress, stop);
      },
      py::arg("domain"), py::arg("radius"), py::arg("method"), py::arg("seed"), py::arg("window"), py::arg("start"),
      py::arg("clearance"), py::arg("fill_voids"), py::arg("max_disks"), py::arg("memory_limit"), py::arg("fraction"),
      py::arg("count"), py::arg("height"), py::arg("jam"), py::arg("progress"), py::arg("stop"),
      "fill() without the shape conversion and the progress bar.");

  // For bench/python_overhead.py: frontpack::fill alone (no callback), timed in C++.
  m.def(
      "_time_cpp_fill",
      [](const Domain& domain, const Radii& radii, std::uint64_t seed, const std::string& method) {
        FillOptions o;
        o.method = method_from(method);
        o.radii = radii;
        o.seed = seed;
        o.max_disks = 200'000'000;
        py::gil_scoped_release release;
        const auto t0 = std::chrono::steady_clock::now();
        const Packing p = frontpack::fill(domain, o);
        const std::chrono::duration<double> s = std::chrono::steady_clock::now() - t0;
        return std::make_pair(s.count(), p.disks.size());
      },
      py::arg("domain"), py::arg("radii"), py::arg("seed"), py::arg("method"));
}

}  // namespace frontpack::python
