#include "frontpack/io.hpp"

#include <algorithm>
#include <cstdio>
#include <ostream>
#include <string>

#include "format.hpp"

namespace frontpack {

namespace {

std::string fixed(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f", v);
  return buf;
}

}  // namespace

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

}  // namespace frontpack
