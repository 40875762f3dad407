// The library's errors as Python exceptions: frontpack.Error and one subclass per error type, with
// the same context as attributes (errors.hpp). Where Python has an idiom for the failure, the
// class derives from it too: OptionError, WktError, InvalidDomainError, DiskFileError and
// DomainFileError are ValueErrors, IoError is an OSError (with `path`; its errno and filename stay None: the message
// names both). CancelledError is a frontpack.Error only: a fill that Ctrl-C cancels raises KeyboardInterrupt itself
// (fill.cpp), so `except frontpack.Error` never swallows an interrupt.
#include <Python.h>

#include <exception>

#include "bind.hpp"

namespace frontpack::python {

namespace {

// The exception classes, created once at import and kept for the process's life (never
// decref'ed: the translator may run until the interpreter shuts down).
struct Classes {
  PyObject* error = nullptr;
  PyObject* cancelled = nullptr;
  PyObject* option = nullptr;
  PyObject* limit = nullptr;
  PyObject* nothing_fits = nullptr;
  PyObject* io = nullptr;
  PyObject* wkt = nullptr;
  PyObject* invalid_domain = nullptr;
  PyObject* disk_file = nullptr;
  PyObject* domain_file = nullptr;
};
Classes classes;

PyObject* make_class(py::module_& m, const char* name, py::handle bases, const char* doc) {
  const std::string qualified = std::string("frontpack.") + name;
  PyObject* cls = PyErr_NewExceptionWithDoc(qualified.c_str(), doc, bases.ptr(), nullptr);
  if (cls == nullptr) {
    throw py::error_already_set();
  }
  m.add_object(name, py::handle(cls));  // the module holds a reference; `classes` keeps its own
  Py_INCREF(cls);
  return cls;
}

py::object site(const InvalidDomainError::Site& s) {
  return py::make_tuple(s.part, s.ring, s.vertex ? py::cast(*s.vertex) : py::object(py::none()));
}

// Raises `cls(message)` with the attributes set by `fill`.
template <class Fill>
void raise(PyObject* cls, const char* message, Fill&& fill) {
  py::object exc = py::reinterpret_borrow<py::object>(cls)(message);
  fill(exc);
  PyErr_SetObject(cls, exc.ptr());
}

void translate(std::exception_ptr p) {
  try {
    std::rethrow_exception(p);
  } catch (const WktError& e) {
    raise(classes.wkt, e.what(), [&](py::object& x) {
      x.attr("kind") = to_string(e.kind());
      x.attr("detail") = e.detail();
      x.attr("source") = e.source();
      x.attr("offset") = e.offset();
      x.attr("line") = e.line();
      x.attr("column") = e.column();
    });
  } catch (const InvalidDomainError& e) {
    raise(classes.invalid_domain, e.what(), [&](py::object& x) {
      x.attr("kind") = to_string(e.kind());
      x.attr("site") = site(e.site());
      x.attr("other_site") = e.other_site() ? site(*e.other_site()) : py::object(py::none());
      x.attr("where") = e.where() ? py::object(py::make_tuple(e.where()->x, e.where()->y)) : py::object(py::none());
    });
  } catch (const DiskFileError& e) {
    raise(classes.disk_file, e.what(), [&](py::object& x) {
      x.attr("kind") = to_string(e.kind());
      x.attr("detail") = e.detail();
      x.attr("source") = e.source();
      x.attr("line") = e.line();
      x.attr("column") = e.column();
    });
  } catch (const DomainFileError& e) {
    raise(classes.domain_file, e.what(), [&](py::object& x) {
      x.attr("kind") = to_string(e.kind());
      x.attr("detail") = e.detail();
      x.attr("source") = e.source();
      x.attr("entity") = e.entity();
    });
  } catch (const IoError& e) {
    raise(classes.io, e.what(), [&](py::object& x) { x.attr("path") = e.path(); });
  } catch (const LimitError& e) {
    raise(classes.limit, e.what(), [&](py::object& x) { x.attr("estimate") = e.estimate(); });
  } catch (const NothingFitsError& e) {
    raise(classes.nothing_fits, e.what(), [](py::object&) {});
  } catch (const OptionError& e) {
    raise(classes.option, e.what(), [](py::object&) {});
  } catch (const CancelledError& e) {
    raise(classes.cancelled, e.what(), [](py::object&) {});
  } catch (const Error& e) {
    raise(classes.error, e.what(), [](py::object&) {});
  }
}

}  // namespace

void bind_errors(py::module_& m) {
  const py::handle base = PyExc_Exception;
  const py::handle value = PyExc_ValueError;
  classes.error = make_class(m, "Error", base,
                             "Base of every error frontpack raises; str() is a complete sentence naming the "
                             "problem and where it is.");
  const py::handle error = classes.error;
  classes.cancelled = make_class(m, "CancelledError", error,
                                 "A run stopped because its StopSource was requested (fill's `stop`); it returns "
                                 "nothing and leaves no output file. Ctrl-C raises KeyboardInterrupt instead.");
  classes.option = make_class(m, "OptionError", py::make_tuple(error, value),
                              "Invalid options: a radius spec, a window, a limit, a format name.");
  classes.limit = make_class(m, "LimitError", error,
                             "A fill whose estimated disks exceed max_disks or memory_limit, refused up front, "
                             "or a run stopped at memory_limit. `estimate`: the estimated disk count.");
  classes.nothing_fits = make_class(m, "NothingFitsError", error,
                                    "A fill that placed no disk (fill never returns an empty packing); str() says "
                                    "why: the radii, a fraction or level that keeps none, the start point, the "
                                    "clearance, the precision at the domain's coordinates.");
  classes.io = make_class(m, "IoError", py::make_tuple(error, py::handle(PyExc_OSError)),
                          "A file could not be opened, read or written. `path`: the file; str() has the reason.");
  classes.wkt = make_class(m, "WktError", py::make_tuple(error, value),
                           "WKT that is not a 2D POLYGON or MULTIPOLYGON. Attributes: kind (syntax, "
                           "unsupported_geometry, empty_geometry, dimension, bad_number), detail, source, "
                           "offset (0-based), line and column (1-based).");
  classes.invalid_domain =
      make_class(m, "InvalidDomainError", py::make_tuple(error, value),
                 "A geometry that is not a valid domain (OGC Simple Features validity). Attributes: kind (e.g. "
                 "self_intersection), site and other_site ((part, ring, vertex or None); ring 0 is the outer ring, "
                 "k >= 1 the k-th hole; other_site may be None), where ((x, y) of the offending point, or None).");
  classes.disk_file = make_class(m, "DiskFileError", py::make_tuple(error, value),
                                 "A disk file that does not follow its format. Attributes: kind, detail, "
                                 "source, line (1-based), column (1-based, 0 for the whole line).");
  classes.domain_file = make_class(m, "DomainFileError", py::make_tuple(error, value),
                                   "A CAD or GIS file that does not describe a domain. Attributes: kind, "
                                   "detail, source, entity (e.g. 'ARC (handle 3A, line 210)', or '').");
  py::register_exception_translator(&translate);
}

}  // namespace frontpack::python
