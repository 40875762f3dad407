#include "render.hpp"
#include "render_parts.hpp"

#include <cairo-pdf.h>
#include <cairo-svg.h>
#include <cairo.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <memory>
#include <numbers>
#include <ostream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "frontpack/fill.hpp"  // OptionError
#include "frontpack/stats.hpp"
#include "report.hpp"  // fmt, fmt4

namespace frontpack_tool {

namespace {

using render_parts::ColourScale;
using render_parts::font_px;
using render_parts::kLevels;
using render_parts::kMarginFraction;
using render_parts::Rgb;

// Where Cairo's output goes. For SVG, `insert` (a <title> element) is written right after the
// root element's start tag: Cairo writes text as glyph outlines, so without it the caption would
// not be in the file as text.
struct Sink {
  std::ostream* out = nullptr;
  std::string insert;
  std::size_t matched = 0;  // characters of "<svg" matched so far
  bool in_root_tag = false;
};

cairo_status_t write_to_file(void* closure, const unsigned char* data, unsigned int length) {
  Sink& sink = *static_cast<Sink*>(closure);
  const auto put = [&](const void* bytes, std::size_t n) {
    return static_cast<bool>(sink.out->write(static_cast<const char*>(bytes), static_cast<std::streamsize>(n)));
  };
  std::size_t from = 0;
  if (!sink.insert.empty()) {
    static constexpr std::string_view kRoot = "<svg";
    for (std::size_t i = 0; i < length; ++i) {
      const char c = static_cast<char>(data[i]);
      if (sink.in_root_tag) {
        if (c == '>') {
          if (!put(data, i + 1) || !put(sink.insert.data(), sink.insert.size())) {
            return CAIRO_STATUS_WRITE_ERROR;
          }
          sink.insert.clear();
          from = i + 1;
          break;
        }
      } else {
        sink.matched = c == kRoot[sink.matched] ? sink.matched + 1 : (c == '<' ? 1 : 0);
        sink.in_root_tag = sink.matched == kRoot.size();
      }
    }
  }
  return put(data + from, length - from) ? CAIRO_STATUS_SUCCESS : CAIRO_STATUS_WRITE_ERROR;
}

struct SurfaceDeleter {
  void operator()(cairo_surface_t* s) const { cairo_surface_destroy(s); }
};
struct ContextDeleter {
  void operator()(cairo_t* c) const { cairo_destroy(c); }
};
using Surface = std::unique_ptr<cairo_surface_t, SurfaceDeleter>;
using Context = std::unique_ptr<cairo_t, ContextDeleter>;

void check(cairo_status_t status, const std::filesystem::path& path) {
  if (status != CAIRO_STATUS_SUCCESS) {
    std::string message("cannot write '");
    message.append(path.string()).append("': ").append(cairo_status_to_string(status));
    throw frontpack::IoError(message, path.string());
  }
}

// Maps domain coordinates to the picture's (y up becomes y down), with a margin. Lengths are
// taken times k, a power of two (exact), then times scale: k is 1 but for a domain narrower than
// 2^-900, where pixels per unit of length would overflow (a subnormal domain, 4e-320 wide).
struct View {
  double scale = 1;
  double k = 1;
  double x0 = 0;
  double y0 = 0;
  double margin = 0;
  double height = 0;
  [[nodiscard]] double px(double length) const { return length * k * scale; }     // a length in pixels
  [[nodiscard]] double units(double pixels) const { return pixels / scale / k; }  // and back
  [[nodiscard]] double x(double v) const { return margin + px(v - x0); }
  [[nodiscard]] double y(double v) const { return height - margin - px(v - y0); }
};

// The picture's rectangle in domain coordinates, grown by `pad` pixels on every side.
struct Frame {
  double x0, x1, y0, y1;
};

Frame frame_of(const View& view, double width, double height, double pad) {
  return {view.x0 + view.units(-pad - view.margin), view.x0 + view.units(width + pad - view.margin),
          view.y0 + view.units(view.height - view.margin - height - pad),
          view.y0 + view.units(view.height - view.margin + pad)};
}

// How a disk meets the frame, decided in domain coordinates (where every disk read is finite;
// in pixels a disk of radius 1e308 is infinite). `big`: its radius is at least the frame's
// diagonal, so that a disk meeting the frame in part has its centre outside it.
enum class Reach { none, part, covers };
Reach reach(const frontpack::Disk& d, const Frame& f) {
  const double cx = d.centre.x;
  const double cy = d.centre.y;
  const double near = std::hypot(std::max({f.x0 - cx, 0.0, cx - f.x1}), std::max({f.y0 - cy, 0.0, cy - f.y1}));
  if (!(near <= d.radius)) {
    return Reach::none;
  }
  const double far = std::hypot(std::max(cx - f.x0, f.x1 - cx), std::max(cy - f.y0, f.y1 - cy));
  return far <= d.radius ? Reach::covers : Reach::part;
}

// The part in frame f of a disk of radius r (domain units) at least as large as the frame's
// diagonal, its centre c outside the frame: the annular sector between r and a radius short of
// the frame, over the angles the frame spans seen from c (less than half a turn), the arc in 128
// chords (each deviates from it by less than a thousandth of a pixel). Cairo's own arc of such a
// radius has millions of segments (a disk of radius 1e20 took 25 s). Where c and r are far
// larger than the frame the arc's position within it carries their rounding error (a domain
// unit in 2^52 of |c|), which no drawing could avoid; its points are kept within a few frames of
// the picture so that Cairo never sees a coordinate beyond its fixed-point range.
void huge_disk_path(cairo_t* cr, const View& view, frontpack::Point c, double r, const Frame& f, double extent_px) {
  const double base = std::atan2((f.y0 + f.y1) / 2 - c.y, (f.x0 + f.x1) / 2 - c.x);
  const double ux = std::cos(base);
  const double uy = std::sin(base);
  double lo = 0;
  double hi = 0;
  for (const auto& [x, y] :
       {std::pair{f.x0, f.y0}, std::pair{f.x1, f.y0}, std::pair{f.x1, f.y1}, std::pair{f.x0, f.y1}}) {
    const double px = x - c.x;
    const double py = y - c.y;
    const double a = std::atan2(ux * py - uy * px, ux * px + uy * py);
    lo = std::min(lo, a);
    hi = std::max(hi, a);
  }
  const double near = std::hypot(std::max({f.x0 - c.x, 0.0, c.x - f.x1}), std::max({f.y0 - c.y, 0.0, c.y - f.y1}));
  const double inner = std::max(0.0, near - std::hypot(f.x1 - f.x0, f.y1 - f.y0));
  const auto to = [&](double radius, double angle) {
    const double x = std::clamp(view.x(c.x + radius * std::cos(angle)), -2 * extent_px, 3 * extent_px);
    const double y = std::clamp(view.y(c.y + radius * std::sin(angle)), -2 * extent_px, 3 * extent_px);
    cairo_line_to(cr, std::isnan(x) ? 0 : x, std::isnan(y) ? 0 : y);
  };
  constexpr int kChords = 128;
  cairo_new_sub_path(cr);
  for (int i = 0; i <= kChords; ++i) {
    to(r, base + lo + (hi - lo) * i / kChords);
  }
  to(inner, base + hi);
  to(inner, base + lo);
  cairo_close_path(cr);
}

// The disks' indices grouped by colour level: order[start[k], start[k + 1]) have level k, in
// index order (a stable counting sort).
struct ByLevel {
  std::vector<std::uint32_t> start;
  std::vector<std::uint32_t> order;
};

ByLevel sort_by_level(std::span<const frontpack::Disk> disks, const ColourScale& colours) {
  ByLevel g;
  g.start.assign(kLevels + 1, 0);
  for (const frontpack::Disk& d : disks) {
    ++g.start[colours.level(d.radius) + 1];
  }
  for (std::size_t k = 0; k < kLevels; ++k) {
    g.start[k + 1] += g.start[k];
  }
  g.order.resize(disks.size());
  std::vector<std::uint32_t> next(g.start.begin(), g.start.end() - 1);
  for (std::size_t i = 0; i < disks.size(); ++i) {
    g.order[next[colours.level(disks[i].radius)]++] = static_cast<std::uint32_t>(i);
  }
  return g;
}

// Builds the path of a run of disks, in one of the two passes. Outlines are drawn as a dark disk
// under a slightly smaller coloured one: two fills, which Cairo rasterises several times faster
// than a stroke. Only what meets the picture is drawn (a disk far outside the domain is skipped),
// and a disk larger than the picture is drawn as the part of it inside (frame_of(), reach()).
struct DiskPaths {
  // The path of order[b, e): the outlined disks' full size in the outline pass, else every disk
  // (an outlined one shrunk by the outline's width); false when nothing meets the picture.
  bool path(std::size_t b, std::size_t e, bool outline_pass) const {
    cairo_new_path(cr);
    bool any = false;
    for (std::size_t m = b; m < e; ++m) {
      const frontpack::Disk& d = disks[order[m]];
      double r = view.px(d.radius);
      const bool outlined = r >= outline_from;
      if (outline_pass && !outlined) {
        continue;
      }
      if (!outline_pass && outlined) {
        r -= outline_width;
      }
      if (!(r <= extent)) {  // (in pixels, its radius or centre may be infinite: decided in domain units)
        any = huge(d, outline_pass || !outlined) || any;
        continue;
      }
      any = small(d, r) || any;
    }
    return any;
  }

  // A disk larger than the picture: what of it meets the frame, of its full radius or shrunk by
  // the outline's width.
  bool huge(const frontpack::Disk& d, bool full) const {
    const frontpack::Disk shown{d.centre, full ? d.radius : d.radius - view.units(outline_width)};
    const Reach where = reach(shown, frame);
    if (where == Reach::none) {
      return false;
    }
    if (where == Reach::covers) {
      cairo_rectangle(cr, -pad, -pad, width_px + 2 * pad, height_px + 2 * pad);
    } else {
      huge_disk_path(cr, view, d.centre, shown.radius, frame, extent);
    }
    return true;
  }

  // A disk of radius r pixels, unless its box misses the picture.
  bool small(const frontpack::Disk& d, double r) const {
    const double x = view.x(d.centre.x);
    const double y = view.y(d.centre.y);
    if (!(x + r >= -pad && x - r <= width_px + pad && y + r >= -pad && y - r <= height_px + pad)) {
      return false;  // its box misses the picture (also a centre beyond the doubles in pixels)
    }
    if (raster && r < 1) {
      // Below a pixel a square of the same area looks the same and is much cheaper.
      const double h = 0.5 * std::sqrt(std::numbers::pi) * r;
      cairo_rectangle(cr, x - h, y - h, 2 * h, 2 * h);
    } else {
      cairo_new_sub_path(cr);
      cairo_arc(cr, x, y, r, 0, 2 * std::numbers::pi);
    }
    return true;
  }

  cairo_t* cr;
  const View& view;
  std::span<const frontpack::Disk> disks;
  std::span<const std::uint32_t> order;
  int width_px, height_px;
  bool raster;
  double outline_width, outline_from;  // outline disks at least 8 outline widths across
  double pad;
  Frame frame;
  double extent;  // at least the frame's diagonal, in pixels
};

// The disks, coloured by radius on the scale `colours`.
void draw_disks(cairo_t* cr, const View& view, Picture format, std::span<const frontpack::Disk> disks,
                const ColourScale& colours, int width_px, int height_px) {
  // The disks, grouped by colour (64 levels of the colour map) so that each group is filled as
  // a few large paths rather than one fill per disk: fast for millions of disks, small SVGs.
  const ByLevel groups = sort_by_level(disks, colours);
  const double outline_width = std::max(0.4, width_px / 3000.0);
  const double pad = 2 * outline_width + 2;
  const DiskPaths paths{cr,
                        view,
                        disks,
                        groups.order,
                        width_px,
                        height_px,
                        format == Picture::png,
                        outline_width,
                        4 * outline_width,
                        pad,
                        frame_of(view, width_px, height_px, pad),
                        static_cast<double>(width_px + height_px)};
  constexpr std::size_t kChunk = 4096;
  for (std::size_t k = 0; k < kLevels; ++k) {
    const Rgb fill = ColourScale::colour(k);
    for (std::size_t b = groups.start[k]; b < groups.start[k + 1]; b += kChunk) {
      const std::size_t e = std::min<std::size_t>(groups.start[k + 1], b + kChunk);
      if (paths.path(b, e, true)) {
        cairo_set_source_rgb(cr, 0.25, 0.25, 0.25);
        cairo_fill(cr);
      }
      if (paths.path(b, e, false)) {
        cairo_set_source_rgb(cr, fill.r, fill.g, fill.b);
        cairo_fill(cr);
      }
    }
  }
}

// The images of the disks that cross a periodic side of a periodic cell: each disk shifted by a
// period (x, y or both on a torus) whose box meets the cell.
std::vector<frontpack::Disk> periodic_images(const frontpack::Domain& domain, std::span<const frontpack::Disk> disks) {
  std::vector<frontpack::Disk> images;
  if (domain.periodicity() == frontpack::Periodicity::none) {
    return images;
  }
  const frontpack::Box cell = domain.bbox();
  const double lx = cell.xmax - cell.xmin;
  const double ly = cell.ymax - cell.ymin;
  const int ky_max = domain.periodicity() == frontpack::Periodicity::xy ? 1 : 0;
  for (const frontpack::Disk& d : disks) {
    for (int kx = -1; kx <= 1; ++kx) {
      for (int ky = -ky_max; ky <= ky_max; ++ky) {
        const frontpack::Point c{d.centre.x + kx * lx, d.centre.y + ky * ly};
        if ((kx != 0 || ky != 0) && c.x - d.radius < cell.xmax && c.x + d.radius > cell.xmin &&
            c.y - d.radius < cell.ymax && c.y + d.radius > cell.ymin) {
          images.push_back({c, d.radius});
        }
      }
    }
  }
  return images;
}

// The least and the largest coverage of the map's interior cells (infinity, -infinity for none).
std::pair<double, double> coverage_range(const frontpack::CellCoverage& c) {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -lo;
  for (const double v : c.map) {
    if (!std::isnan(v)) {
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
  }
  return {lo, hi};
}

// The cells of the map, each a square filled by its coverage (the caller clips to the domain: in a
// periodic cell the last column or row of cells reaches past the period).
void draw_cells(cairo_t* cr, const View& view, const frontpack::CellCoverage& c,
                const std::optional<std::array<double, 2>>& range) {
  const auto [lo, hi] = range ? std::pair{(*range)[0], (*range)[1]} : coverage_range(c);
  for (std::size_t j = 0; j < c.ny; ++j) {
    for (std::size_t i = 0; i < c.nx; ++i) {
      const double v = c.map[j * c.nx + i];
      if (std::isnan(v)) {
        continue;
      }
      const render_parts::Rgb colour = render_parts::viridis(hi > lo ? (v - lo) / (hi - lo) : 0.5);
      const double x0 = c.origin.x + static_cast<double>(i) * c.cell_side;
      const double y1 = c.origin.y + static_cast<double>(j + 1) * c.cell_side;
      cairo_rectangle(cr, view.x(x0), view.y(y1), view.px(c.cell_side), view.px(c.cell_side));
      cairo_set_source_rgb(cr, colour.r, colour.g, colour.b);
      cairo_fill(cr);
    }
  }
}

void draw(cairo_t* cr, const View& view, Picture format, const frontpack::Domain& domain,
          std::span<const frontpack::Disk> disks, std::span<const frontpack::Disk> images, const RenderOptions& options,
          int width_px, int height_px) {
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);

  // The domain: every ring in one path, filled even-odd so that holes stay white.
  const auto ring_path = [&](const frontpack::Ring& ring) {
    for (std::size_t k = 0; k < ring.size(); ++k) {
      (k == 0 ? cairo_move_to : cairo_line_to)(cr, view.x(ring[k].x), view.y(ring[k].y));
    }
    cairo_close_path(cr);
  };
  const auto domain_path = [&] {
    cairo_new_path(cr);
    for (const frontpack::Polygon& polygon : domain.polygons()) {
      ring_path(polygon.outer);
      for (const frontpack::Ring& hole : polygon.holes) {
        ring_path(hole);
      }
    }
  };
  cairo_set_fill_rule(cr, CAIRO_FILL_RULE_EVEN_ODD);
  domain_path();
  cairo_set_source_rgb(cr, 0.9, 0.9, 0.9);
  cairo_fill(cr);
  cairo_set_fill_rule(cr, CAIRO_FILL_RULE_WINDING);

  if (options.cells) {
    cairo_save(cr);
    cairo_set_fill_rule(cr, CAIRO_FILL_RULE_EVEN_ODD);
    domain_path();
    cairo_clip(cr);
    cairo_set_antialias(cr, CAIRO_ANTIALIAS_NONE);  // no seam of blended pixels between two cells
    draw_cells(cr, view, *options.cells, options.cells_range);
    cairo_restore(cr);
  } else {
    const ColourScale colours(disks);
    if (!images.empty()) {
      // Lighter: the images drawn on a group painted at a third of their opacity.
      cairo_push_group(cr);
      draw_disks(cr, view, format, images, colours, width_px, height_px);
      cairo_pop_group_to_source(cr);
      cairo_paint_with_alpha(cr, 0.35);
    }
    draw_disks(cr, view, format, disks, colours, width_px, height_px);
  }

  cairo_set_source_rgb(cr, 0.15, 0.15, 0.15);
  const double line = std::max(1.0, width_px / 800.0);
  cairo_set_line_width(cr, line);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  if (domain.periodicity() == frontpack::Periodicity::none) {
    domain_path();
    cairo_stroke(cr);
    return;
  }
  // A periodic cell: its walls solid, its periodic sides dashed (the plane continues there).
  const frontpack::Box b = domain.bbox();
  const auto side = [&](double x0, double y0, double x1, double y1) {
    cairo_move_to(cr, view.x(x0), view.y(y0));
    cairo_line_to(cr, view.x(x1), view.y(y1));
  };
  cairo_new_path(cr);
  if (domain.periodicity() == frontpack::Periodicity::x) {
    side(b.xmin, b.ymin, b.xmax, b.ymin);
    side(b.xmin, b.ymax, b.xmax, b.ymax);
    cairo_stroke(cr);
  } else {
    side(b.xmin, b.ymin, b.xmax, b.ymin);
    side(b.xmin, b.ymax, b.xmax, b.ymax);
  }
  side(b.xmin, b.ymin, b.xmin, b.ymax);
  side(b.xmax, b.ymin, b.xmax, b.ymax);
  const double dash[] = {4 * line, 3 * line};
  cairo_set_dash(cr, dash, 2, 0);
  cairo_stroke(cr);
  cairo_set_dash(cr, nullptr, 0, 0);
}

View make_view(const frontpack::Domain& domain, int width_px) {
  const frontpack::Box b = domain.bbox();
  const double extent = std::max(b.width(), b.height());
  const double margin = kMarginFraction * width_px;
  View view;
  view.margin = margin;
  const double width = b.width() > 0 ? b.width() : extent;
  view.k = width < 0x1p-900 ? 0x1p1000 : 1.0;
  view.scale = (width_px - 2 * margin) / (width * view.k);
  view.x0 = b.xmin;
  view.y0 = b.ymin;
  return view;
}

int packing_height(const frontpack::Domain& domain, int width_px) {
  const View view = make_view(domain, width_px);
  return static_cast<int>(std::ceil(view.px(domain.bbox().height()) + 2 * view.margin));
}

std::string xml_escaped(std::string_view text) {
  std::string out;
  for (const char c : text) {
    if (c == '&') {
      out.append("&amp;");
    } else if (c == '<') {
      out.append("&lt;");
    } else if (c == '>') {
      out.append("&gt;");
    } else {
      out.push_back(c);
    }
  }
  return out;
}

}  // namespace

std::string cells_key(const frontpack::CellCoverage& cells, const std::optional<std::array<double, 2>>& range) {
  if (cells.cells == 0) {
    return "no interior cell";
  }
  const auto [lo, hi] = coverage_range(cells);
  const std::string head =
      std::to_string(cells.cells) + " interior cells of side " + fmt(cells.cell_side) + ", coverage ";
  if (range) {
    return head + fmt4((*range)[0]) + " (dark) to " + fmt4((*range)[1]) + " (light), the cells' " + fmt4(lo) + " to " +
           fmt4(hi);
  }
  return head + fmt4(lo) + " (dark) to " + fmt4(hi) + " (light)";
}

int histogram_height(int width_px) {
  return width_px / 4 + 6 * font_px(width_px);
}

int picture_height(const frontpack::Domain& domain, int width_px, bool histogram) {
  return packing_height(domain, width_px) + (histogram ? histogram_height(width_px) : 0);
}

void render(frontpack::OutputFile& out, Picture format, const frontpack::Domain& domain,
            std::span<const frontpack::Disk> disks, const RenderOptions& options) {
  const std::filesystem::path& path = out.path();
  const int width = options.width_px;
  if (width < 16 || width > 16384) {
    throw frontpack::OptionError(std::string("--width ") + std::to_string(width) + ": expected 16 to 16384 pixels");
  }
  const bool with_panel = options.histogram && !options.cells;
  const double panel = with_panel ? histogram_height(width) : 0;
  const double height_real = make_view(domain, width).px(domain.bbox().height()) + 2 * kMarginFraction * width + panel;
  if (!(height_real <= 32767)) {
    throw frontpack::OptionError(std::string("--width ") + std::to_string(width) +
                                 ": the picture would be taller than 32767 pixels (the domain is tall "
                                 "and narrow); use a smaller width");
  }
  const int height = picture_height(domain, width, with_panel);
  View view = make_view(domain, width);
  view.height = packing_height(domain, width);
  std::optional<render_parts::Panel> histogram;
  std::string caption;
  if (options.cells) {
    caption = "frontpack cell coverage: " + cells_key(*options.cells, options.cells_range);
  } else if (options.histogram) {
    histogram = render_parts::make_panel(disks, options);
    caption.append("frontpack packing. ").append(histogram->caption[0]);
    if (!histogram->caption[1].empty()) {
      caption.append(". ").append(histogram->caption[1]);
    }
  }

  Sink sink;
  sink.out = &out.stream();
  Surface surface;
  if (format == Picture::png) {
    surface.reset(cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height));
  } else if (format == Picture::svg) {
    if (!caption.empty()) {
      sink.insert.append("\n<title>").append(xml_escaped(caption)).append("</title>");
    }
    surface.reset(cairo_svg_surface_create_for_stream(write_to_file, &sink, width, height));
  } else {
    surface.reset(cairo_pdf_surface_create_for_stream(write_to_file, &sink, width, height));
    if (!caption.empty()) {
      cairo_pdf_surface_set_metadata(surface.get(), CAIRO_PDF_METADATA_SUBJECT, caption.c_str());
    }
  }
  check(cairo_surface_status(surface.get()), path);
  {
    const Context cr(cairo_create(surface.get()));
    const std::vector<frontpack::Disk> images =
        options.images && !options.cells ? periodic_images(domain, disks) : std::vector<frontpack::Disk>{};
    draw(cr.get(), view, format, domain, disks, images, options, width, height);
    if (options.stop.stop_requested()) {
      throw frontpack::CancelledError();
    }
    if (histogram) {
      render_parts::draw_panel(cr.get(), *histogram, ColourScale(disks), view.height, width);
    }
    check(cairo_status(cr.get()), path);
  }
  if (format == Picture::png) {
    check(cairo_surface_write_to_png_stream(surface.get(), write_to_file, &sink), path);
  }
  cairo_surface_finish(surface.get());
  check(cairo_surface_status(surface.get()), path);
  surface.reset();
}

}  // namespace frontpack_tool
