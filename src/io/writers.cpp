// Writers: SVG, CSV, Yade, LAMMPS, VTK PolyData; their formats by name and extension (the table
// of formats, frontpack/formats.hpp); write_file() through OutputFile.
#include "frontpack/io.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>

#include "common/format.hpp"
#include "common/stop.hpp"
#include "common/text.hpp"
#include "frontpack/output_file.hpp"
#include "frontpack/version.hpp"

namespace frontpack {

namespace {

std::string fixed(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f", v);
  return buf;
}

// Types, when given, must be one per disk and >= 1.
void check_types(const char* format, std::span<const Disk> disks, std::span<const std::uint32_t> types) {
  if (types.empty()) {
    return;
  }
  if (types.size() != disks.size()) {
    throw OptionError(std::string(format) + " writer: " + std::to_string(types.size()) + " types for " +
                      std::to_string(disks.size()) + " disks (expected one type per disk)");
  }
  for (std::size_t i = 0; i < types.size(); ++i) {
    if (types[i] < 1) {
      throw OptionError(std::string(format) + " writer: disk " + std::to_string(i) + " has type 0 (types are >= 1)");
    }
  }
}

// Every writer's disks: a centre of finite coordinates and a radius that is a finite number > 0,
// checked before a byte is written. The disk readers refuse anything else, so a file written
// without this check could not be read back (and a simulator would take it as it is).
void check_disks(const char* format, std::span<const Disk> disks) {
  for (std::size_t i = 0; i < disks.size(); ++i) {
    const Disk& d = disks[i];
    if (!(std::isfinite(d.centre.x) && std::isfinite(d.centre.y) && std::isfinite(d.radius) && d.radius > 0)) {
      throw OptionError(std::string(format) + " writer: disk " + std::to_string(i) + " (centre " +
                        detail::format_point(d.centre) + ", radius " + detail::format_double(d.radius) +
                        ") is not a disk: a disk has a finite centre and a finite radius > 0");
    }
  }
}

}  // namespace

const char* to_string(Format format) noexcept {
  const FileFormat* row = format_row(format);
  return row != nullptr ? row->name.data() : "unknown";  // the table's names are string literals
}

Format format_from_path(const std::filesystem::path& path) {
  if (const FileFormat* f = find_format_by_extension(path, FormatUse::library_writes)) {
    return *f->written_as;
  }
  std::string name(1, '\'');  // built by append: GCC 12 warns (-Wrestrict) on "'" + std::string
  name.append(path.string()).append(1, '\'');
  const std::string known = format_extensions(FormatUse::library_writes);
  if (const FileFormat* f = find_format_by_extension(path, FormatUse::tool_pictures)) {
    throw OptionError(name + ": " + detail::ascii_upper(f->name) +
                      " pictures are drawn by the frontpack tool (frontpack render), not by the library; " +
                      "the library writes " + known);
  }
  if (path.extension().empty()) {
    throw OptionError(name + ": no file extension to tell the format by; use " + known);
  }
  throw OptionError(name + ": unknown format '" + path.extension().string() + "'; use " + known);
}

Format format_from_name(std::string_view name) {
  if (const FileFormat* f = find_format_by_name(name, FormatUse::library_writes)) {
    return *f->written_as;
  }
  throw OptionError("unknown format '" + std::string(name) + "'; expected " + format_names(FormatUse::library_writes));
}

void write_svg(std::ostream& out, const Domain& domain, std::span<const Disk> disks, const SvgStyle& style,
               std::stop_token stop) {
  check_disks("SVG", disks);
  const Box b = domain.bbox();
  const double margin = 0.02 * std::max(b.width(), b.height());
  const double scale = style.width_px / (b.width() + 2 * margin);
  const double height = (b.height() + 2 * margin) * scale;
  const auto X = [&](double x) { return (x - b.xmin + margin) * scale; };
  const auto Y = [&](double y) { return (b.ymax + margin - y) * scale; };
  double rmin = 0;
  double rmax = 0;
  if (!disks.empty()) {
    rmin = rmax = disks[0].radius;
    for (const Disk& d : disks) {
      rmin = std::min(rmin, d.radius);
      rmax = std::max(rmax, d.radius);
    }
  }
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << fixed(style.width_px) << "\" height=\""
      << fixed(height) << "\" viewBox=\"0 0 " << fixed(style.width_px) << ' ' << fixed(height) << "\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n<path fill=\"#f4f4f0\" fill-rule=\"evenodd\" "
         "stroke=\"black\" stroke-width=\"1\" d=\"";
  for (const Polygon& p : domain.polygons()) {
    const auto ring = [&](const Ring& r) {
      for (std::size_t k = 0; k < r.size(); ++k) {
        out << (k == 0 ? 'M' : 'L') << fixed(X(r[k].x)) << ',' << fixed(Y(r[k].y)) << ' ';
      }
      out << "Z ";
    };
    ring(p.outer);
    for (const Ring& h : p.holes) {
      ring(h);
    }
  }
  out << "\"/>\n<g stroke=\"#1d3557\" stroke-width=\"0.4\">\n";
  for (std::size_t i = 0; i < disks.size(); ++i) {
    detail::throw_if_stopped(stop, i);
    const Disk& d = disks[i];
    const double t = rmax > rmin ? (d.radius - rmin) / (rmax - rmin) : 0.5;
    const int shade = style.colour_by_size ? static_cast<int>(200 - 120 * t) : 150;
    out << "<circle cx=\"" << fixed(X(d.centre.x)) << "\" cy=\"" << fixed(Y(d.centre.y)) << "\" r=\""
        << fixed(d.radius * scale) << "\" fill=\"rgb(" << shade / 2 << ',' << shade << ',' << std::min(255, shade + 40)
        << ")\"/>\n";
  }
  out << "</g>\n</svg>\n";
}

void write_csv(std::ostream& out, std::span<const Disk> disks, std::span<const std::uint32_t> types,
               std::stop_token stop) {
  check_disks("CSV", disks);
  check_types("CSV", disks, types);
  out << (types.empty() ? "x,y,r\n" : "x,y,r,type\n");
  for (std::size_t i = 0; i < disks.size(); ++i) {
    detail::throw_if_stopped(stop, i);
    const Disk& d = disks[i];
    out << detail::format_double(d.centre.x) << ',' << detail::format_double(d.centre.y) << ','
        << detail::format_double(d.radius);
    if (!types.empty()) {
      out << ',' << types[i];
    }
    out << '\n';
  }
}

void write_yade(std::ostream& out, std::span<const Disk> disks, std::span<const std::uint32_t> types,
                std::stop_token stop) {
  // ymport.textExt splits each line on whitespace, takes "#format F" as the format, skips other
  // lines starting with '#', and fails on a blank line: so no blank line, not even at the end.
  // SpherePack.load takes lines of 4 (x y z r) or 5 (x y z r clumpId) columns and refuses any
  // other line, '#' lines included: so no header unless the matId column needs one.
  check_disks("Yade", disks);
  check_types("Yade", disks, types);
  if (!types.empty()) {
    out << "#format x_y_z_r_matId\n";
  } else if (disks.empty()) {
    out << "#format x_y_z_r\n";
  }
  for (std::size_t i = 0; i < disks.size(); ++i) {
    detail::throw_if_stopped(stop, i);
    const Disk& d = disks[i];
    out << detail::format_double(d.centre.x) << ' ' << detail::format_double(d.centre.y) << " 0 "
        << detail::format_double(d.radius);
    if (!types.empty()) {
      out << ' ' << types[i] - 1;
    }
    out << '\n';
  }
}

namespace {

void check_lammps_options(const LammpsOptions& options, const Box& box) {
  if (!(std::isfinite(options.density) && options.density > 0)) {
    throw OptionError("LAMMPS density " + detail::format_double(options.density) + " must be a finite number > 0");
  }
  if (options.atom_type < 1) {
    throw OptionError("LAMMPS atom type " + std::to_string(options.atom_type) + " must be >= 1");
  }
  if (box.empty() || !std::isfinite(box.xmin) || !std::isfinite(box.xmax) || !std::isfinite(box.ymin) ||
      !std::isfinite(box.ymax)) {
    throw OptionError("LAMMPS box must be finite and non-empty");
  }
}

// The largest radius, once every disk is checked to lie in the box (on a periodic axis, its centre
// in the half-open box).
double lammps_rmax(std::span<const Disk> disks, const Box& box, Periodicity periodicity) {
  const bool wraps_x = periodicity != Periodicity::none;
  const bool wraps_y = periodicity == Periodicity::xy;
  double rmax = 0;
  for (std::size_t i = 0; i < disks.size(); ++i) {
    const Disk& d = disks[i];
    // Rounding is monotone and the bounds are doubles, so these floating-point tests give the
    // same answers as exact arithmetic. On a periodic axis the centre lies in the half-open box.
    const bool in_x = wraps_x ? (d.radius >= 0 && box.xmin <= d.centre.x && d.centre.x < box.xmax)
                              : (d.centre.x - d.radius >= box.xmin && d.centre.x + d.radius <= box.xmax);
    const bool in_y = wraps_y ? (d.radius >= 0 && box.ymin <= d.centre.y && d.centre.y < box.ymax)
                              : (d.centre.y - d.radius >= box.ymin && d.centre.y + d.radius <= box.ymax);
    if (!(in_x && in_y && std::isfinite(d.radius))) {
      throw OptionError(
          std::string("LAMMPS box [") + detail::format_double(box.xmin) + ", " + detail::format_double(box.xmax) +
          (wraps_x ? ")" : "]") + " x [" + detail::format_double(box.ymin) + ", " + detail::format_double(box.ymax) +
          (wraps_y ? ")" : "]") + (wraps_x ? " (periodic cell)" : "") + " does not contain disk " + std::to_string(i) +
          " (centre " + detail::format_point(d.centre) + ", radius " + detail::format_double(d.radius) + ")");
    }
    rmax = std::max(rmax, d.radius);
  }
  return rmax;
}

// With per-disk types: the number of atom types written (`type`) and each type's density.
std::vector<std::string> lammps_type_densities(const LammpsOptions& options, std::span<const std::uint32_t> types,
                                               std::string& type) {
  std::vector<std::string> densities;
  if (types.empty()) {
    return densities;
  }
  const std::uint32_t largest = *std::max_element(types.begin(), types.end());
  if (options.atom_types != 0 && options.atom_types < largest) {
    throw OptionError("LAMMPS atom types " + std::to_string(options.atom_types) + " is below the largest type " +
                      std::to_string(largest));
  }
  type = std::to_string(options.atom_types != 0 ? options.atom_types : std::int64_t{largest});
  if (!options.type_densities.empty() && options.type_densities.size() < largest) {
    throw OptionError("LAMMPS type densities: " + std::to_string(options.type_densities.size()) +
                      " given, but the largest type is " + std::to_string(largest));
  }
  for (std::uint32_t t = 1; t <= largest; ++t) {
    const double rho = options.type_densities.empty() ? options.density : options.type_densities[t - 1];
    if (!(std::isfinite(rho) && rho > 0)) {
      throw OptionError("LAMMPS density of type " + std::to_string(t) + ", " + detail::format_double(rho) +
                        ", must be a finite number > 0");
    }
    densities.push_back(detail::format_double(rho));
  }
  return densities;
}

}  // namespace

void write_lammps(std::ostream& out, std::span<const Disk> disks, std::span<const std::uint32_t> types, const Box& box,
                  const LammpsOptions& options, std::stop_token stop) {
  check_disks("LAMMPS", disks);
  check_types("LAMMPS", disks, types);
  check_lammps_options(options, box);
  const bool wraps_x = options.periodicity != Periodicity::none;
  const bool wraps_y = options.periodicity == Periodicity::xy;
  const double rmax = lammps_rmax(disks, box, options.periodicity);
  // Dimension 2 needs a z range that straddles 0 (and a periodic z boundary); one largest
  // diameter thick, the packing is also a valid monolayer for a 3D run.
  const std::string zhi = detail::format_double(rmax > 0 ? rmax : 0.5);
  const std::string density = detail::format_double(options.density);
  std::string type = std::to_string(options.atom_type);
  const std::vector<std::string> densities = lammps_type_densities(options, types, type);  // per type, with types
  out << "LAMMPS data file (atom_style sphere, 2D: z = 0"
      << (wraps_y   ? "; periodic cell: boundary p p p"
          : wraps_x ? "; periodic in x, walls in y: boundary p f p"
                    : "")
      << ") written by frontpack " << version_string << "\n\n"
      << disks.size() << " atoms\n"
      << type << " atom types\n\n"
      << detail::format_double(box.xmin) << ' ' << detail::format_double(box.xmax) << " xlo xhi\n"
      << detail::format_double(box.ymin) << ' ' << detail::format_double(box.ymax) << " ylo yhi\n"
      << '-' << zhi << ' ' << zhi << " zlo zhi\n\n"
      << "Atoms # sphere\n\n";
  for (std::size_t i = 0; i < disks.size(); ++i) {
    detail::throw_if_stopped(stop, i);
    const Disk& d = disks[i];
    if (types.empty()) {
      out << i + 1 << ' ' << type << ' ';
    } else {
      out << i + 1 << ' ' << types[i] << ' ';
    }
    out << detail::format_double(2 * d.radius) << ' ' << (types.empty() ? density : densities[types[i] - 1]) << ' '
        << detail::format_double(d.centre.x) << ' ' << detail::format_double(d.centre.y) << " 0\n";
  }
}

namespace {

// The VTP writer; a periodic `domain` adds the cell as field data.
void write_vtp_file(std::ostream& out, const Domain* domain, std::span<const Disk> disks,
                    std::span<const std::uint32_t> types, const std::stop_token& stop) {
  check_disks("VTP", disks);
  check_types("VTP", disks, types);
  // File format version 1.0: "offsets" holds each cell's end (version 2.0 would add a leading 0).
  const std::string n = std::to_string(disks.size());
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
      << "  <PolyData>\n";
  if (domain != nullptr && domain->periodicity() != Periodicity::none) {
    const Box cell = domain->bbox();
    out << "    <FieldData>\n"
        << "      <DataArray type=\"Float64\" Name=\"periodic_cell\" NumberOfTuples=\"1\" "
           "NumberOfComponents=\"4\" format=\"ascii\">\n"
        << "        " << detail::format_double(cell.xmin) << ' ' << detail::format_double(cell.ymin) << ' '
        << detail::format_double(cell.xmax) << ' ' << detail::format_double(cell.ymax) << "\n"
        << "      </DataArray>\n"
        << "      <DataArray type=\"Int32\" Name=\"periodic_axes\" NumberOfTuples=\"1\" format=\"ascii\">\n"
        << "        " << (domain->periodicity() == Periodicity::xy ? 2 : 1) << "\n"
        << "      </DataArray>\n"
        << "    </FieldData>\n";
  }
  out << "    <Piece NumberOfPoints=\"" << n << "\" NumberOfVerts=\"" << n
      << "\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n"
      << "      <PointData Scalars=\"radius\">\n"
      << "        <DataArray type=\"Float64\" Name=\"radius\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < disks.size(); ++i) {
    detail::throw_if_stopped(stop, i);
    out << detail::format_double(disks[i].radius) << '\n';
  }
  out << "        </DataArray>\n"
      << "        <DataArray type=\"Int64\" Name=\"id\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < disks.size(); ++i) {
    detail::throw_if_stopped(stop, i);
    out << i << '\n';
  }
  if (!types.empty()) {
    out << "        </DataArray>\n"
        << "        <DataArray type=\"Int32\" Name=\"type\" format=\"ascii\">\n";
    for (std::size_t i = 0; i < types.size(); ++i) {
      detail::throw_if_stopped(stop, i);
      out << types[i] << '\n';
    }
  }
  out << "        </DataArray>\n"
      << "      </PointData>\n"
      << "      <Points>\n"
      << "        <DataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < disks.size(); ++i) {
    detail::throw_if_stopped(stop, i);
    out << detail::format_double(disks[i].centre.x) << ' ' << detail::format_double(disks[i].centre.y) << " 0\n";
  }
  out << "        </DataArray>\n"
      << "      </Points>\n"
      << "      <Verts>\n"
      << "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < disks.size(); ++i) {
    detail::throw_if_stopped(stop, i);
    out << i << '\n';
  }
  out << "        </DataArray>\n"
      << "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < disks.size(); ++i) {
    detail::throw_if_stopped(stop, i);
    out << i + 1 << '\n';
  }
  out << "        </DataArray>\n"
      << "      </Verts>\n"
      << "    </Piece>\n"
      << "  </PolyData>\n"
      << "</VTKFile>\n";
}

}  // namespace

void write_vtp(std::ostream& out, std::span<const Disk> disks, std::span<const std::uint32_t> types,
               std::stop_token stop) {
  write_vtp_file(out, nullptr, disks, types, stop);
}

void write_vtp(std::ostream& out, const Domain& domain, std::span<const Disk> disks,
               std::span<const std::uint32_t> types, std::stop_token stop) {
  write_vtp_file(out, &domain, disks, types, stop);
}

void write(std::ostream& out, Format format, const Domain& domain, std::span<const Disk> disks,
           const WriteOptions& options) {
  switch (format) {
    case Format::csv: write_csv(out, disks, options.types, options.stop); break;
    case Format::yade: write_yade(out, disks, options.types, options.stop); break;
    case Format::lammps: {
      LammpsOptions lammps = options.lammps;
      lammps.periodicity = domain.periodicity();
      write_lammps(out, disks, options.types, domain.bbox(), lammps, options.stop);
      break;
    }
    case Format::vtp: write_vtp(out, domain, disks, options.types, options.stop); break;
    case Format::svg: write_svg(out, domain, disks, options.svg, options.stop); break;
  }
}

void write_file(const std::filesystem::path& path, Format format, const Domain& domain, std::span<const Disk> disks,
                const WriteOptions& options) {
  OutputFile file(path);
  write(file.stream(), format, domain, disks, options);
  file.commit();
}

}  // namespace frontpack
