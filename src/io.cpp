// Writers: SVG, CSV, Yade, LAMMPS, VTK PolyData; format names; atomic file output.
#include "frontpack/io.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ostream>
#include <streambuf>
#include <string>

#include "format.hpp"
#include "frontpack/version.hpp"

namespace frontpack {

namespace {

std::string fixed(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f", v);
  return buf;
}

constexpr const char* known_extensions = ".csv, .txt or .yade (Yade), .data or .lmp (LAMMPS), .vtp, .svg";

}  // namespace

const char* to_string(Format format) noexcept {
  switch (format) {
    case Format::csv: return "csv";
    case Format::yade: return "yade";
    case Format::lammps: return "lammps";
    case Format::vtp: return "vtp";
    case Format::svg: return "svg";
  }
  return "unknown";
}

Format format_from_path(const std::filesystem::path& path) {
  const std::string original = path.extension().string();
  std::string ext = original;
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; });
  if (ext == ".csv") {
    return Format::csv;
  }
  if (ext == ".txt" || ext == ".yade") {
    return Format::yade;
  }
  if (ext == ".data" || ext == ".lmp") {
    return Format::lammps;
  }
  if (ext == ".vtp") {
    return Format::vtp;
  }
  if (ext == ".svg") {
    return Format::svg;
  }
  std::string name(1, '\'');
  name.append(path.string()).append(1, '\'');
  if (ext == ".png") {
    throw OptionError(name + ": PNG pictures are drawn by the frontpack tool (frontpack render), not by the library; " +
                      "the library writes " + known_extensions);
  }
  if (ext.empty()) {
    throw OptionError(name + ": no file extension to tell the format by; use " + known_extensions);
  }
  throw OptionError(name + ": unknown format '" + original + "'; use " + known_extensions);
}

Format format_from_name(std::string_view name) {
  for (const Format f : {Format::csv, Format::yade, Format::lammps, Format::vtp, Format::svg}) {
    if (name == to_string(f)) {
      return f;
    }
  }
  throw OptionError("unknown format '" + std::string(name) + "'; expected csv, yade, lammps, vtp or svg");
}

void write_svg(std::ostream& out, const Domain& domain, std::span<const Disk> disks, const SvgStyle& style) {
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
  for (const Disk& d : disks) {
    const double t = rmax > rmin ? (d.radius - rmin) / (rmax - rmin) : 0.5;
    const int shade = style.colour_by_size ? static_cast<int>(200 - 120 * t) : 150;
    out << "<circle cx=\"" << fixed(X(d.centre.x)) << "\" cy=\"" << fixed(Y(d.centre.y)) << "\" r=\""
        << fixed(d.radius * scale) << "\" fill=\"rgb(" << shade / 2 << ',' << shade << ',' << std::min(255, shade + 40)
        << ")\"/>\n";
  }
  out << "</g>\n</svg>\n";
}

void write_csv(std::ostream& out, std::span<const Disk> disks) {
  out << "x,y,r\n";
  for (const Disk& d : disks) {
    out << detail::format_double(d.centre.x) << ',' << detail::format_double(d.centre.y) << ','
        << detail::format_double(d.radius) << '\n';
  }
}

void write_yade(std::ostream& out, std::span<const Disk> disks) {
  // ymport.textExt splits each line on whitespace, takes "#format F" as the format, skips other
  // lines starting with '#', and fails on a blank line: so no blank line, not even at the end.
  out << "#format x_y_z_r\n";
  for (const Disk& d : disks) {
    out << detail::format_double(d.centre.x) << ' ' << detail::format_double(d.centre.y) << " 0 "
        << detail::format_double(d.radius) << '\n';
  }
}

void write_lammps(std::ostream& out, std::span<const Disk> disks, const Box& box, const LammpsOptions& options) {
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
  double rmax = 0;
  for (std::size_t i = 0; i < disks.size(); ++i) {
    const Disk& d = disks[i];
    // Rounding is monotone and the bounds are doubles, so these floating-point tests give the
    // same answers as exact arithmetic.
    if (!(d.centre.x - d.radius >= box.xmin && d.centre.x + d.radius <= box.xmax && d.centre.y - d.radius >= box.ymin &&
          d.centre.y + d.radius <= box.ymax)) {
      throw OptionError("LAMMPS box [" + detail::format_double(box.xmin) + ", " + detail::format_double(box.xmax) +
                        "] x [" + detail::format_double(box.ymin) + ", " + detail::format_double(box.ymax) +
                        "] does not contain disk " + std::to_string(i) + " (centre " + detail::format_point(d.centre) +
                        ", radius " + detail::format_double(d.radius) + ")");
    }
    rmax = std::max(rmax, d.radius);
  }
  // Dimension 2 needs a z range that straddles 0 (and a periodic z boundary); one largest
  // diameter thick, the packing is also a valid monolayer for a 3D run.
  const std::string zhi = detail::format_double(rmax > 0 ? rmax : 0.5);
  const std::string density = detail::format_double(options.density);
  const std::string type = std::to_string(options.atom_type);
  out << "LAMMPS data file (atom_style sphere, 2D: z = 0) written by frontpack " << version_string << "\n\n"
      << disks.size() << " atoms\n"
      << type << " atom types\n\n"
      << detail::format_double(box.xmin) << ' ' << detail::format_double(box.xmax) << " xlo xhi\n"
      << detail::format_double(box.ymin) << ' ' << detail::format_double(box.ymax) << " ylo yhi\n"
      << '-' << zhi << ' ' << zhi << " zlo zhi\n\n"
      << "Atoms # sphere\n\n";
  for (std::size_t i = 0; i < disks.size(); ++i) {
    const Disk& d = disks[i];
    out << i + 1 << ' ' << type << ' ' << detail::format_double(2 * d.radius) << ' ' << density << ' '
        << detail::format_double(d.centre.x) << ' ' << detail::format_double(d.centre.y) << " 0\n";
  }
}

void write_vtp(std::ostream& out, std::span<const Disk> disks) {
  // File format version 1.0: "offsets" holds each cell's end (version 2.0 would add a leading 0).
  const std::string n = std::to_string(disks.size());
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
      << "  <PolyData>\n"
      << "    <Piece NumberOfPoints=\"" << n << "\" NumberOfVerts=\"" << n
      << "\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n"
      << "      <PointData Scalars=\"radius\">\n"
      << "        <DataArray type=\"Float64\" Name=\"radius\" format=\"ascii\">\n";
  for (const Disk& d : disks) {
    out << detail::format_double(d.radius) << '\n';
  }
  out << "        </DataArray>\n"
      << "        <DataArray type=\"Int64\" Name=\"id\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < disks.size(); ++i) {
    out << i << '\n';
  }
  out << "        </DataArray>\n"
      << "      </PointData>\n"
      << "      <Points>\n"
      << "        <DataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (const Disk& d : disks) {
    out << detail::format_double(d.centre.x) << ' ' << detail::format_double(d.centre.y) << " 0\n";
  }
  out << "        </DataArray>\n"
      << "      </Points>\n"
      << "      <Verts>\n"
      << "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < disks.size(); ++i) {
    out << i << '\n';
  }
  out << "        </DataArray>\n"
      << "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < disks.size(); ++i) {
    out << i + 1 << '\n';
  }
  out << "        </DataArray>\n"
      << "      </Verts>\n"
      << "    </Piece>\n"
      << "  </PolyData>\n"
      << "</VTKFile>\n";
}

namespace {

// An output stream buffer on a POSIX file descriptor that remembers the first write error's errno,
// so that the error message can give the OS's reason (std::ofstream loses it).
class FdBuf : public std::streambuf {
 public:
  explicit FdBuf(int fd) : fd_(fd) { setp(buffer_, buffer_ + sizeof buffer_); }
  FdBuf(const FdBuf&) = delete;
  FdBuf& operator=(const FdBuf&) = delete;
  ~FdBuf() override = default;

  [[nodiscard]] int error() const noexcept { return error_; }
  bool flush_all() { return drain() && error_ == 0; }

 protected:
  int_type overflow(int_type ch) override {
    if (!drain()) {
      return traits_type::eof();
    }
    if (!traits_type::eq_int_type(ch, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(ch);
      pbump(1);
    }
    return traits_type::not_eof(ch);
  }
  int sync() override { return drain() ? 0 : -1; }

 private:
  bool drain() {
    const char* p = pbase();
    while (p < pptr() && error_ == 0) {
      const ssize_t n = ::write(fd_, p, static_cast<std::size_t>(pptr() - p));
      if (n < 0) {
        if (errno != EINTR) {
          error_ = errno;
        }
      } else {
        p += n;
      }
    }
    setp(buffer_, buffer_ + sizeof buffer_);
    return error_ == 0;
  }

  int fd_;
  int error_ = 0;
  char buffer_[1 << 16];
};

// Removes the temporary file unless released (after the rename).
class TempFile {
 public:
  explicit TempFile(std::filesystem::path path) : path_(std::move(path)) {}
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;
  ~TempFile() {
    if (fd_ >= 0) {
      ::close(fd_);
    }
    if (!released_) {
      ::unlink(path_.c_str());
    }
  }
  void set_fd(int fd) noexcept { fd_ = fd; }
  int close() noexcept {
    const int rc = ::close(fd_);
    fd_ = -1;
    return rc;
  }
  void release() noexcept { released_ = true; }

 private:
  std::filesystem::path path_;
  int fd_ = -1;
  bool released_ = false;
};

[[noreturn]] void throw_io(const std::filesystem::path& path, int error) {
  throw IoError("cannot write '" + path.string() + "': " + std::strerror(error), path.string());
}

}  // namespace

void write_file(const std::filesystem::path& path, Format format, const Domain& domain, std::span<const Disk> disks,
                const WriteOptions& options) {
  if (path.filename().empty()) {
    throw IoError("cannot write '" + path.string() + "': not a file name", path.string());
  }
  // A new file beside the target (same file system, so the rename is atomic), created exclusively
  // with the permissions a plain new file gets (0666 less the umask).
  static std::atomic<unsigned> counter{0};
  std::filesystem::path tmp;
  int fd = -1;
  for (int attempt = 0; fd < 0; ++attempt) {
    tmp = path;
    std::string name(1, '.');
    name.append(path.filename().string())
        .append(".frontpack-")
        .append(std::to_string(::getpid()))
        .append(1, '-')
        .append(std::to_string(counter.fetch_add(1)))
        .append(".tmp");
    tmp.replace_filename(name);
    fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0 && (errno != EEXIST || attempt >= 100)) {
      throw_io(path, errno);
    }
  }
  TempFile guard(tmp);
  guard.set_fd(fd);
  {
    FdBuf buf(fd);
    std::ostream out(&buf);
    switch (format) {
      case Format::csv: write_csv(out, disks); break;
      case Format::yade: write_yade(out, disks); break;
      case Format::lammps: write_lammps(out, disks, domain.bbox(), options.lammps); break;
      case Format::vtp: write_vtp(out, disks); break;
      case Format::svg: write_svg(out, domain, disks, options.svg); break;
    }
    if (!buf.flush_all() || !out) {
      throw_io(path, buf.error() != 0 ? buf.error() : EIO);
    }
  }
  // Durable before it becomes visible: a crash after the rename must not leave an empty file.
  if (::fsync(fd) != 0) {
    throw_io(path, errno);
  }
  if (guard.close() != 0) {
    throw_io(path, errno);
  }
  if (::rename(tmp.c_str(), path.c_str()) != 0) {
    throw_io(path, errno);
  }
  guard.release();
}

}  // namespace frontpack
