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

// A Python value as the option's value, by its kind; range checks are check_options()'s (fill
// calls it). None gives none (refused by set_option for an option that is not optional).
OptionValue option_value(const OptionInfo& info, const py::handle& value) {
  if (value.is_none()) {
    return std::monostate{};
  }
  const std::string name(info.name);
  try {
    switch (info.kind) {
      case OptionKind::method: return parse_method(value.cast<std::string>(), name);
      case OptionKind::radii: return radii_from(value);
      case OptionKind::count:
      case OptionKind::bytes:
        if (py::isinstance<py::int_>(value) &&
            (value.attr("__lt__")(0).cast<bool>() || value.attr("__gt__")(py::int_(UINT64_MAX)).cast<bool>())) {
          throw OptionError(name + " " + py::repr(value).cast<std::string>() + ": expected " + expected_text(info));
        }
        return value.cast<std::uint64_t>();
      case OptionKind::real: return value.cast<double>();
      case OptionKind::point: {
        const auto xy = value.cast<std::pair<double, double>>();
        return Point{xy.first, xy.second};
      }
      case OptionKind::flag: return value.cast<bool>();
    }
  } catch (const py::cast_error&) {
    throw py::type_error(name + " must be " + expected_text(info) + ", not " +
                         py::str(py::type::of(value).attr("__name__")).cast<std::string>());
  }
  return std::monostate{};
}

// The default of an option as a Python value: None for none, the radius spec for the radii.
py::object default_object(const OptionInfo& info) {
  const OptionValue value = default_value(info);
  if (std::holds_alternative<std::monostate>(value)) {
    return py::none();
  }
  switch (info.kind) {
    case OptionKind::method:
    case OptionKind::radii: return py::str(default_text(info));
    case OptionKind::count:
    case OptionKind::bytes: return py::int_(std::get<std::uint64_t>(value));
    case OptionKind::real: return py::float_(std::get<double>(value));
    case OptionKind::point: return py::make_tuple(std::get<Point>(value).x, std::get<Point>(value).y);
    case OptionKind::flag: return py::bool_(std::get<bool>(value));
  }
  return py::none();
}

py::list fill_options_list() {
  py::list out;
  for (const OptionInfo& info : fill_option_list()) {
    py::dict d;
    d["name"] = std::string(info.name);
    d["kind"] = to_string(info.kind);
    d["default"] = default_object(info);
    d["default_text"] = default_text(info);
    d["flag"] = flag_name(info);
    d["expected"] = expected_text(info);
    d["help"] = std::string(info.help);
    out.append(d);
  }
  return out;
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

// fill_options() and _fill(): the options by the names of their description.
void bind_fill_call(py::module_& m) {
  m.def("fill_options", &fill_options_list,
        "The fill options' one description (frontpack/options.hpp), in FillOptions' order: a list of dicts "
        "with name (the keyword of fill), kind, default, default_text (as the tool shows it), flag (the frontpack fill "
        "flag), expected and help.");

  m.def(
      "_fill",
      [](const Domain& domain, const py::handle& radius, const py::object& progress, const py::object& stop,
         const py::kwargs& options) {
        FillOptions o;
        o.radii = radii_from(radius);
        for (const auto& [key, value] : options) {
          const OptionInfo& info = fill_option(key.cast<std::string>());
          set_option(o, info, option_value(info, value));
        }
        return run(domain, std::move(o), progress, stop);
      },
      py::arg("domain"), py::arg("radius"), py::arg("progress"), py::arg("stop"),
      "fill() without the shape conversion and the progress bar; the options by their names (fill_options()).");
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

  bind_fill_call(m);

  // For bench/python_overhead.py: frontpack::fill alone (no callback), timed in C++.
  m.def(
      "_time_cpp_fill",
      [](const Domain& domain, const Radii& radii, std::uint64_t seed, const std::string& method) {
        FillOptions o;
        o.method = parse_method(method);
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
