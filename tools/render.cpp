#include "render.hpp"

#include <cairo-pdf.h>
#include <cairo-svg.h>
#include <cairo.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "atomic_file.hpp"
#include "frontpack/fill.hpp"  // OptionError

namespace frontpack_tool {

namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

struct Rgb {
  double r, g, b;
};

// viridis (matplotlib's perceptually uniform map) at 9 evenly spaced anchors, interpolated
// linearly in between.
Rgb viridis(double t) {
  static constexpr std::array<std::array<int, 3>, 9> kAnchors = {{{68, 1, 84},
                                                                  {72, 40, 120},
                                                                  {62, 73, 137},
                                                                  {49, 104, 142},
                                                                  {38, 130, 142},
                                                                  {31, 158, 137},
                                                                  {53, 183, 121},
                                                                  {110, 206, 88},
                                                                  {253, 231, 37}}};
  t = std::clamp(t, 0.0, 1.0) * static_cast<double>(kAnchors.size() - 1);
  const auto k = std::min(static_cast<std::size_t>(t), kAnchors.size() - 2);
  const double f = t - static_cast<double>(k);
  const auto mix = [&](std::size_t c) { return ((1 - f) * kAnchors[k][c] + f * kAnchors[k + 1][c]) / 255.0; };
  return {mix(0), mix(1), mix(2)};
}

cairo_status_t write_to_file(void* closure, const unsigned char* data, unsigned int length) {
  return std::fwrite(data, 1, length, static_cast<std::FILE*>(closure)) == length ? CAIRO_STATUS_SUCCESS
                                                                                  : CAIRO_STATUS_WRITE_ERROR;
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

// Maps domain coordinates to the picture's (y up becomes y down), with a margin.
struct View {
  double scale = 1;
  double x0 = 0;
  double y0 = 0;
  double margin = 0;
  double height = 0;
  [[nodiscard]] double x(double v) const { return margin + (v - x0) * scale; }
  [[nodiscard]] double y(double v) const { return height - margin - (v - y0) * scale; }
};

constexpr double kMarginFraction = 0.02;

void draw(cairo_t* cr, const View& view, Picture format, const frontpack::Domain& domain,
          std::span<const frontpack::Disk> disks, int width_px) {
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

  // The disks, grouped by colour (64 levels of the colour map) so that each group is filled as
  // a few large paths rather than one fill per disk: fast for millions of disks, small SVGs.
  double rmin = INFINITY;
  double rmax = -INFINITY;
  for (const frontpack::Disk& d : disks) {
    rmin = std::min(rmin, d.radius);
    rmax = std::max(rmax, d.radius);
  }
  constexpr std::size_t kLevels = 64;
  const auto level_of = [&](double r) -> std::size_t {
    if (!(rmax > rmin)) {
      return kLevels / 2;
    }
    const double t = (r - rmin) / (rmax - rmin);
    return std::min(kLevels - 1, static_cast<std::size_t>(std::max(0.0, t) * kLevels));
  };
  std::vector<std::uint32_t> start(kLevels + 1, 0);
  for (const frontpack::Disk& d : disks) {
    ++start[level_of(d.radius) + 1];
  }
  for (std::size_t k = 0; k < kLevels; ++k) {
    start[k + 1] += start[k];
  }
  std::vector<std::uint32_t> order(disks.size());
  {
    std::vector<std::uint32_t> next(start.begin(), start.end() - 1);
    for (std::size_t i = 0; i < disks.size(); ++i) {
      order[next[level_of(disks[i].radius)]++] = static_cast<std::uint32_t>(i);
    }
  }
  const bool raster = format == Picture::png;
  const double outline_width = std::max(0.4, width_px / 3000.0);
  const double outline_from = 4 * outline_width;  // outline disks at least 8 outline widths across
  // Outlines are drawn as a dark disk under a slightly smaller coloured one: two fills, which
  // Cairo rasterises several times faster than a stroke.
  const auto disk_path = [&](std::size_t b, std::size_t e, bool outline_pass) {
    cairo_new_path(cr);
    bool any = false;
    for (std::size_t m = b; m < e; ++m) {
      const frontpack::Disk& d = disks[order[m]];
      double r = d.radius * view.scale;
      const bool outlined = r >= outline_from;
      if (outline_pass && !outlined) {
        continue;
      }
      if (!outline_pass && outlined) {
        r -= outline_width;
      }
      any = true;
      if (raster && r < 1) {
        // Below a pixel a square of the same area looks the same and is much cheaper.
        const double h = 0.5 * std::sqrt(std::numbers::pi) * r;
        cairo_rectangle(cr, view.x(d.centre.x) - h, view.y(d.centre.y) - h, 2 * h, 2 * h);
      } else {
        cairo_new_sub_path(cr);
        cairo_arc(cr, view.x(d.centre.x), view.y(d.centre.y), r, 0, 2 * std::numbers::pi);
      }
    }
    return any;
  };
  constexpr std::size_t kChunk = 4096;
  for (std::size_t k = 0; k < kLevels; ++k) {
    const Rgb fill = viridis((static_cast<double>(k) + 0.5) / kLevels);
    for (std::size_t b = start[k]; b < start[k + 1]; b += kChunk) {
      const std::size_t e = std::min<std::size_t>(start[k + 1], b + kChunk);
      if (disk_path(b, e, true)) {
        cairo_set_source_rgb(cr, 0.25, 0.25, 0.25);
        cairo_fill(cr);
      }
      if (disk_path(b, e, false)) {
        cairo_set_source_rgb(cr, fill.r, fill.g, fill.b);
        cairo_fill(cr);
      }
    }
  }

  domain_path();
  cairo_set_source_rgb(cr, 0.15, 0.15, 0.15);
  cairo_set_line_width(cr, std::max(1.0, width_px / 800.0));
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_stroke(cr);
}

View make_view(const frontpack::Domain& domain, int width_px) {
  const frontpack::Box b = domain.bbox();
  const double extent = std::max(b.width(), b.height());
  const double margin = kMarginFraction * width_px;
  View view;
  view.margin = margin;
  view.scale = (width_px - 2 * margin) / (b.width() > 0 ? b.width() : extent);
  view.x0 = b.xmin;
  view.y0 = b.ymin;
  return view;
}

}  // namespace

std::optional<Picture> picture_from_name(std::string_view name) {
  const std::string n = lower(std::string(name));
  if (n == "png") {
    return Picture::png;
  }
  if (n == "svg") {
    return Picture::svg;
  }
  if (n == "pdf") {
    return Picture::pdf;
  }
  return std::nullopt;
}

std::optional<Picture> picture_from_path(const std::filesystem::path& path) {
  const std::string ext = path.extension().string();
  return ext.size() > 1 ? picture_from_name(std::string_view(ext).substr(1)) : std::nullopt;
}

int picture_height(const frontpack::Domain& domain, int width_px) {
  const View view = make_view(domain, width_px);
  return static_cast<int>(std::ceil(domain.bbox().height() * view.scale + 2 * view.margin));
}

void render(const std::filesystem::path& path, Picture format, const frontpack::Domain& domain,
            std::span<const frontpack::Disk> disks, const RenderOptions& options) {
  const int width = options.width_px;
  if (width < 16 || width > 16384) {
    throw frontpack::OptionError(std::string("--width ") + std::to_string(width) + ": expected 16 to 16384 pixels");
  }
  const double height_real = domain.bbox().height() * make_view(domain, width).scale + 2 * kMarginFraction * width;
  if (!(height_real <= 32767)) {
    throw frontpack::OptionError(std::string("--width ") + std::to_string(width) +
                                 ": the picture would be taller than 32767 pixels (the domain is tall "
                                 "and narrow); use a smaller width");
  }
  const int height = picture_height(domain, width);
  View view = make_view(domain, width);
  view.height = height;

  AtomicFile out(path);
  Surface surface;
  if (format == Picture::png) {
    surface.reset(cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height));
  } else if (format == Picture::svg) {
    surface.reset(cairo_svg_surface_create_for_stream(write_to_file, out.file(), width, height));
  } else {
    surface.reset(cairo_pdf_surface_create_for_stream(write_to_file, out.file(), width, height));
  }
  check(cairo_surface_status(surface.get()), path);
  {
    const Context cr(cairo_create(surface.get()));
    draw(cr.get(), view, format, domain, disks, width);
    check(cairo_status(cr.get()), path);
  }
  if (format == Picture::png) {
    check(cairo_surface_write_to_png_stream(surface.get(), write_to_file, out.file()), path);
  }
  cairo_surface_finish(surface.get());
  check(cairo_surface_status(surface.get()), path);
  surface.reset();
  out.commit();
}

}  // namespace frontpack_tool
