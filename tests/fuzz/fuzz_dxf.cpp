#include <sys/mman.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

#include "check.hpp"
#include "frontpack/domain_file.hpp"
#include "frontpack/errors.hpp"
#include "fuzz_targets.hpp"

namespace frontpack::fuzz {

namespace {

// A memory file holding `text`, named by /proc/self/fd/N: dxflib reads by path.
class MemoryFile {
 public:
  explicit MemoryFile(const std::string& text) : fd_(::memfd_create("fuzz-dxf", MFD_CLOEXEC)) {
    check(fd_ >= 0, "memfd_create works");
    for (std::size_t done = 0; done < text.size();) {
      const ssize_t n = ::write(fd_, text.data() + done, text.size() - done);
      check(n > 0, "a memory file takes the input");
      done += static_cast<std::size_t>(n);
    }
  }
  ~MemoryFile() { ::close(fd_); }
  MemoryFile(const MemoryFile&) = delete;
  MemoryFile& operator=(const MemoryFile&) = delete;
  [[nodiscard]] std::string path() const { return "/proc/self/fd/" + std::to_string(fd_); }

 private:
  int fd_;
};

DomainFile read(const std::string& text) {
  const MemoryFile file(text);
  DomainReadOptions o;
  o.format = DomainFormat::dxf;
  return read_domain_file(file.path(), o);
}

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

// The domain's rings as closed LWPOLYLINEs, coordinates to 17 digits (they read back exactly):
// the nesting of the rings makes the same outer boundaries and holes again.
std::string as_dxf(const Domain& domain) {
  std::string out = "  0\nSECTION\n  2\nENTITIES\n";
  const auto ring = [&out](const Ring& r) {
    out += "  0\nLWPOLYLINE\n 90\n" + std::to_string(r.size()) + "\n 70\n1\n";
    for (const Point& p : r) {
      out += " 10\n" + number(p.x) + "\n 20\n" + number(p.y) + "\n";
    }
  };
  for (const Polygon& p : domain.polygons()) {
    ring(p.outer);
    for (const Ring& h : p.holes) {
      ring(h);
    }
  }
  return out + "  0\nENDSEC\n  0\nEOF\n";
}

bool same_area_and_box(const Domain& a, const Domain& b) {
  const Box x = a.bbox();
  const Box y = b.bbox();
  return a.num_polygons() == b.num_polygons() && a.num_holes() == b.num_holes() &&
         a.num_vertices() == b.num_vertices() && a.area() == b.area() && x.xmin == y.xmin && x.xmax == y.xmax &&
         x.ymin == y.ymin && x.ymax == y.ymax;
}

}  // namespace

void dxf(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::optional<DomainFile> parsed;
  try {
    parsed.emplace(read(text));
  } catch (const DomainFileError& e) {
    check_message(e.what());
    // The reader's own consistency check (dxf_reader.cpp): its detail starts so, where no user
    // text can stand (the user's text is quoted, after a line or an entity).
    check(!e.detail().starts_with("dxflib read "), "dxflib reads the groups as checked");
    return;
  } catch (const Error& e) {
    check_message(e.what());
    return;  // a clear, typed error: what bad input must get
  }
  const Domain& domain = parsed->domain;
  check_accepted_domain(domain);
  for (const CurveReport& c : parsed->curves) {
    check(std::isfinite(c.radius) && c.radius > 0 && c.segments > 0, "every curve has a finite circle and segments");
  }
  const DomainFile again = read(as_dxf(domain));
  check(same_area_and_box(again.domain, domain), "the domain written as DXF polylines reads back the same");
  check(again.curves.empty(), "straight polylines read back without curves");
}

}  // namespace frontpack::fuzz
