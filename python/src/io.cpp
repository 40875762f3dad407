// frontpack's writers and readers (io.hpp), pictures (write_svg), types (types.hpp) and simulator
// decks (deck.hpp). Files are written through the library's write_file: whole or not at all.
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <optional>
#include <sstream>
#include <string>

#include "bind.hpp"

namespace frontpack::python {

namespace {

// The keyword options of write() and dumps(), with the types they point to.
struct Writing {
  std::vector<std::uint32_t> types;
  WriteOptions options;
};

Writing writing(const py::handle& types, double width, bool colour_by_size, double density, std::int64_t atom_type,
                const std::vector<double>& type_densities, std::int64_t atom_types) {
  Writing w;
  w.types = types_from(types);
  w.options.types = w.types;
  w.options.svg = SvgStyle{width, colour_by_size};
  w.options.lammps = LammpsOptions{density, atom_type, type_densities, atom_types};
  return w;
}

#define FRONTPACK_WRITE_KEYWORDS                                                                            \
  py::kw_only(), py::arg("types") = py::none(), py::arg("width") = 800.0, py::arg("colour_by_size") = true, \
                 py::arg("density") = 1.0, py::arg("atom_type") = std::int64_t{1},                          \
                 py::arg("type_densities") = std::vector<double>{}, py::arg("atom_types") = std::int64_t {  \
    0                                                                                                       \
  }

DiskFormat disk_format(const std::filesystem::path& path, const std::optional<std::string>& format) {
  return format ? disk_format_from_name(*format) : disk_format_from_path(path);
}

// The names of the formats serving `use`, as Python strings for a docstring: "'csv', 'yade' or 'svg'".
std::string quoted_names(FormatUse use) {
  std::vector<std::string> names;
  for (const FileFormat& f : file_formats()) {
    if (serves(f, use)) {
      std::string name(1, '\'');  // built by append: GCC 12 warns (-Wrestrict) on "'" + std::string
      names.push_back(name.append(f.name).append(1, '\''));
    }
  }
  std::string out;
  for (std::size_t k = 0; k < names.size(); ++k) {
    out.append(k == 0 ? "" : k + 1 == names.size() ? " or " : ", ").append(names[k]);
  }
  return out;
}

// One row of the table of formats as a dict.
py::dict format_dict(const FileFormat& f) {
  static constexpr const char* kHolds[] = {"disks", "domain", "picture"};
  py::dict d;
  d["name"] = std::string(f.name);
  d["extensions"] = std::vector<std::string>(f.extensions.begin(), f.extensions.end());
  d["aliases"] = std::vector<std::string>(f.aliases.begin(), f.aliases.end());
  d["holds"] = kHolds[static_cast<int>(f.holds)];
  d["library_writes"] = f.written_as.has_value();
  d["library_reads_disks"] = f.read_as.has_value();
  d["library_reads_domain"] = f.domain_as.has_value();
  d["tool_writes"] = f.tool_writes;
  return d;
}

TypeRule type_rule(const py::handle& rule) {
  if (py::isinstance<py::str>(rule)) {
    return parse_type_rule(rule.cast<std::string>());
  }
  return size_types(rule.cast<std::vector<double>>());
}

}  // namespace

void bind_io(py::module_& m) {
  m.def(
      "write",
      [](const std::filesystem::path& path, const Domain& domain, const py::handle& disks,
         const std::optional<std::string>& format, const py::handle& types, double width, bool colour_by_size,
         double density, std::int64_t atom_type, const std::vector<double>& type_densities, std::int64_t atom_types) {
        const Format f = format ? format_from_name(*format) : format_from_path(path);
        const std::vector<Disk> ds = disks_from(disks);
        const Writing w = writing(types, width, colour_by_size, density, atom_type, type_densities, atom_types);
        py::gil_scoped_release release;
        write_file(path, f, domain, ds, w.options);
      },
      py::arg("path"), py::arg("domain"), py::arg("disks"), py::arg("format") = py::none(), FRONTPACK_WRITE_KEYWORDS,
      ("Writes disks to `path` in `format` (" + quoted_names(FormatUse::library_writes) + "; None: by the extension, " +
       format_extensions(FormatUse::library_writes) +
       "). Numbers are written in their shortest round-trip form, so what was "
       "certified in memory is certified in the file. The file appears whole or not at all (a temporary file "
       "renamed over the target). LAMMPS: the domain's bounding box is the box; `density`, `atom_type`, "
       "`type_densities`, `atom_types` as LammpsOptions. SVG: `width` in pixels, `colour_by_size`. `types`: one "
       "whole number >= 1 per disk (a CSV column, Yade's matId, the LAMMPS type, a VTP array). Raises "
       "OptionError, IoError.")
          .c_str());
  m.def(
      "dumps",
      [](const Domain& domain, const py::handle& disks, const std::string& format, const py::handle& types,
         double width, bool colour_by_size, double density, std::int64_t atom_type,
         const std::vector<double>& type_densities, std::int64_t atom_types) {
        const Format f = format_from_name(format);
        const std::vector<Disk> ds = disks_from(disks);
        const Writing w = writing(types, width, colour_by_size, density, atom_type, type_densities, atom_types);
        std::ostringstream out;
        {
          py::gil_scoped_release release;
          write(out, f, domain, ds, w.options);
        }
        return out.str();
      },
      py::arg("domain"), py::arg("disks"), py::arg("format"), FRONTPACK_WRITE_KEYWORDS,
      ("The text write() would put in a file of `format` (" + quoted_names(FormatUse::library_writes) + "), as a str.")
          .c_str());
  m.def(
      "render",
      [](const std::filesystem::path& path, const Domain& domain, const py::handle& disks, double width,
         bool colour_by_size) {
        const std::vector<Disk> ds = disks_from(disks);
        WriteOptions o;
        o.svg = SvgStyle{width, colour_by_size};
        py::gil_scoped_release release;
        write_file(path, Format::svg, domain, ds, o);
      },
      py::arg("path"), py::arg("domain"), py::arg("disks"), py::arg("width") = 800.0, py::arg("colour_by_size") = true,
      "An SVG picture of the domain's outline and the disks (the library's write_svg: coordinates rounded to "
      "0.001 px, a picture, not a data file). PNG pictures with histograms are the frontpack tool's (render).");
  m.def(
      "read_disks",
      [](const std::filesystem::path& path, const std::optional<std::string>& format,
         std::optional<std::int64_t> timestep, const std::string& radius_array) {
        const DiskFormat f = disk_format(path, format);
        std::vector<Disk> disks;
        {
          py::gil_scoped_release release;
          disks = read_disks(path, f, ReadOptions{timestep, radius_array});
        }
        return disks_array(std::move(disks));
      },
      py::arg("path"), py::arg("format") = py::none(), py::kw_only(), py::arg("timestep") = py::none(),
      py::arg("radius_array") = "",
      ("Reads disks as an (N, 3) float64 array, bit for bit as written: format " +
       quoted_names(FormatUse::disk_reader) +
       " ('lammps' a data file; 'lammps-dump' the last snapshot, or `timestep`; 'vtp' the radius from "
       "`radius_array`, or the first of radius, Radius, diameter, Diameter); None: by the extension (" +
       format_extensions(FormatUse::disk_reader) + "). Raises IoError, DiskFileError (naming the line), OptionError.")
          .c_str());
  m.def(
      "file_formats",
      [] {
        py::list out;
        for (const FileFormat& f : file_formats()) {
          out.append(format_dict(f));
        }
        return out;
      },
      "The table of file formats (frontpack/formats.hpp), one dict per format: name, extensions, aliases, holds "
      "('disks', 'domain', 'picture'), library_writes, library_reads_disks, library_reads_domain, tool_writes. "
      "Every format name and extension the package and the tool accept comes from it.");
  m.def(
      "assign_types",
      [](const py::handle& rule, const py::handle& disks) {
        const TypeRule r = type_rule(rule);
        return types_array(assign_types(r, disks_from(disks)));
      },
      py::arg("rule"), py::arg("disks"),
      "Per-disk types (a uint32 array, 1-based as LAMMPS atom types): `rule` a spec 'size:E1,E2,...' or "
      "'region:A.wkt,B.wkt,...', or a sequence of radius bin edges (type 1 + the number of edges <= r). Raises "
      "OptionError.");
  m.def(
      "wall_disks",
      [](const Domain& domain, double wall_radius, double rmin) {
        std::vector<Disk> walls;
        {
          py::gil_scoped_release release;
          walls = wall_disks(domain, wall_radius, rmin);
        }
        return disks_array(std::move(walls));
      },
      py::arg("domain"), py::arg("wall_radius"), py::arg("rmin"),
      "Frozen wall disks outside the domain (exactly, in the closure of its complement), close enough along every "
      "ring that no disk of radius >= rmin passes between them. Raises OptionError where a ring cannot be closed.");
  m.def(
      "make_deck",
      [](const Domain& domain, const py::handle& disks, const std::string& simulator, const py::handle& types,
         const std::vector<double>& densities, double thickness, double gravity, double wall_radius,
         std::uint64_t steps) {
        const std::vector<Disk> ds = disks_from(disks);
        const std::vector<std::uint32_t> ts = types_from(types);
        DeckOptions o;
        o.simulator = simulator_from_name(simulator);
        o.densities = densities;
        o.thickness = thickness;
        o.gravity = gravity;
        o.wall_radius = wall_radius;
        o.steps = steps;
        std::vector<DeckFile> files;
        {
          py::gil_scoped_release release;
          files = make_deck(domain, ds, ts, o);
        }
        py::dict out;
        for (const DeckFile& f : files) {
          out[py::str(f.name)] = py::str(f.text);
        }
        return out;
      },
      py::arg("domain"), py::arg("disks"), py::arg("simulator") = "lammps", py::kw_only(),
      py::arg("types") = py::none(), py::arg("densities") = std::vector<double>{2500.0}, py::arg("thickness") = 0.0,
      py::arg("gravity") = 9.81, py::arg("wall_radius") = 0.0, py::arg("steps") = std::uint64_t{5000},
      "A simulator deck ('lammps', 'liggghts', 'yade') as {file name: text}, to write into one directory "
      "(docs/simulators.md): densities per type (or one for all), mass per area when thickness is 0. Raises "
      "OptionError.");
}

}  // namespace frontpack::python
