// The size-distribution panel below a packing picture: a histogram of the radii by area, the
// request's share per bin as a line, and a caption with the KS distance by area.
#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "frontpack/sizes.hpp"
#include "frontpack/stats.hpp"
#include "render_parts.hpp"

namespace frontpack_tool::render_parts {

namespace {

std::string format_g(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// Text for Cairo's toy API must be valid UTF-8: user text (a --radius spec) is reduced to
// printable ASCII.
std::string printable(std::string_view text) {
  std::string out(text);
  for (char& c : out) {
    if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f) {
      c = '?';
    }
  }
  return out;
}

// 1, 2 or 5 times a power of ten, at least `raw` (> 0).
double nice_step(double raw) {
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  for (const double m : {1.0, 2.0, 5.0, 10.0}) {
    if (m * p >= raw) {
      return m * p;
    }
  }
  return 10 * p;
}

double text_width(cairo_t* cr, const std::string& text) {
  cairo_text_extents_t e;
  cairo_text_extents(cr, text.c_str(), &e);
  return e.x_advance;
}

void show_text(cairo_t* cr, double x, double y, const std::string& text) {
  cairo_move_to(cr, x, y);
  cairo_show_text(cr, text.c_str());
}

}  // namespace

Panel make_panel(std::span<const frontpack::Disk> disks, const RenderOptions& options) {
  Panel panel;
  std::vector<double> radii;
  radii.reserve(disks.size());
  for (const frontpack::Disk& d : disks) {
    radii.push_back(d.radius);
  }
  const frontpack::RadiusDistribution* request = options.requested ? &options.requested->distribution() : nullptr;
  const frontpack::SizeStats s = frontpack::measure_sizes(radii, request, 0);
  const std::string spec =
      printable(options.requested_spec.empty() && request != nullptr ? request->describe() : options.requested_spec);

  double lo = radii.empty() ? INFINITY : s.rmin;
  double hi = radii.empty() ? -INFINITY : s.rmax;
  if (request != nullptr) {
    lo = std::min(lo, request->min());
    hi = std::max(hi, request->max());
  }
  if (!(lo <= hi)) {
    panel.caption[0] = "no disks";
    return panel;
  }
  // About sqrt(n) bins, 5 to 40, and at least 8 px wide; an odd number around a single radius,
  // so that it sits in the middle of the axis.
  const double root_n = std::sqrt(static_cast<double>(radii.size()));
  std::size_t bins = static_cast<std::size_t>(std::clamp(std::round(root_n), 5.0, 40.0));
  bins = std::min(bins, static_cast<std::size_t>(std::max(1, options.width_px / 8)));
  if (!(hi > lo)) {
    lo *= 0.9;
    hi = hi < std::numeric_limits<double>::max() / 1.1 ? hi * 1.1 : std::numeric_limits<double>::max();
    bins |= 1;
  }
  const frontpack::RadiusBins binning(lo, hi, bins, frontpack::BinSpacing::linear);
  panel.edges = binning.edges();
  panel.achieved.assign(bins, 0.0);
  // Areas r^2 at a scale k (a power of two) where they neither overflow nor underflow: 1 but for
  // radii beyond 2^400 (a disk of radius 1e308 made the total infinite and its share a NaN) or
  // below 2^-400.
  const double k = hi > 0x1p400 || hi < 0x1p-400 ? std::ldexp(1.0, -std::clamp(std::ilogb(hi), -1000, 1000)) : 1.0;
  const auto area = [k](double r) { return (r * k) * (r * k); };
  double total = 0;
  for (const double r : radii) {
    total += area(r);
  }
  for (const double r : radii) {
    panel.achieved[binning.bin_of(r)] += area(r) / total;
  }
  if (request != nullptr) {
    // Mass at an edge belongs to the bin above it, as for the disks.
    const auto below = [&](std::size_t b) {
      return b == 0 ? 0.0 : b == bins ? 1.0 : request->area_cdf(std::nextafter(panel.edges[b], 0.0));
    };
    for (std::size_t b = 0; b < bins; ++b) {
      panel.requested.push_back(std::max(0.0, below(b + 1) - below(b)));
    }
  }

  char buf[160];
  std::snprintf(buf, sizeof buf, "Disk area per radius bin (%zu disks, bins of %.3g)%s", s.count,
                (hi - lo) / static_cast<double>(bins), request != nullptr ? "; line: requested" : "");
  panel.caption[0] = buf;
  if (request != nullptr && s.count > 0) {
    std::snprintf(buf, sizeof buf, "KS by area %.4f (requested: ", s.ks_area);
    panel.caption[1] = buf;
    panel.caption[1].append(spec).append(")");
  } else if (request != nullptr) {
    panel.caption[1] = "no disks (requested: ";
    panel.caption[1].append(spec).append(")");
  } else {
    std::snprintf(buf, sizeof buf, "radius min %g, median by area %g, max %g", s.rmin, s.median_area, s.rmax);
    panel.caption[1] = buf;
  }
  return panel;
}

namespace {

// The panel's captions, each shrunk to fit the width if need be; leaves the font size at f.
void draw_captions(cairo_t* cr, const Panel& panel, double bottom, int width_px) {
  const double w = width_px;
  const double f = font_px(width_px);
  const double margin = kMarginFraction * w;
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  const auto caption_line = [&](int k, double baseline) {
    // Shrunk to fit the width if need be (a few rounds: hinted advances do not scale exactly).
    const double available = w - 2 * margin;
    double size = f;
    cairo_set_font_size(cr, size);
    for (int round = 0; round < 4; ++round) {
      const double tw = text_width(cr, panel.caption[k]);
      if (tw <= available || size <= 1) {
        break;
      }
      size = std::max(1.0, size * 0.98 * available / tw);
      cairo_set_font_size(cr, size);
    }
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    show_text(cr, margin, baseline, panel.caption[k]);
    cairo_set_font_size(cr, f);
  };
  caption_line(0, bottom - 1.8 * f);
  caption_line(1, bottom - 0.5 * f);
}

// The plot's frame in the picture: the y axis's nice ticks from 0 to at least the tallest bar or
// step, the plot's corners (room left for the tick labels), and the maps from radius and share
// to pixels.
struct PlotFrame {
  cairo_t* cr = nullptr;
  const Panel* panel = nullptr;
  double w = 0;       // picture width
  double f = 0;       // font size
  double margin = 0;  // picture margin
  double ystep = 0;
  double ytop = 0;
  int yticks = 0;
  double left = 0;
  double right = 0;
  double plot_top = 0;
  double axis_y = 0;
  double lo = 0;  // the radius axis's range
  double hi = 0;
  std::string hi_label;

  [[nodiscard]] double px(double r) const { return left + (r - lo) / (hi - lo) * (right - left); }
  [[nodiscard]] double py(double v) const { return axis_y - v / ytop * (axis_y - plot_top); }
};

// The frame of a panel with bins; false when the picture is too narrow for a plot.
bool plan_frame(PlotFrame& p, double top, double bottom) {
  cairo_t* cr = p.cr;
  const Panel& panel = *p.panel;
  const double f = p.f;
  double ymax = 0;
  for (std::size_t b = 0; b < panel.achieved.size(); ++b) {
    ymax = std::max({ymax, panel.achieved[b], panel.requested.empty() ? 0.0 : panel.requested[b]});
  }
  p.ystep = nice_step(ymax > 0 ? ymax / 4 : 0.25);
  p.ytop = std::max(1.0, std::ceil(ymax / p.ystep - 1e-9)) * p.ystep;
  p.yticks = static_cast<int>(std::lround(p.ytop / p.ystep));
  double ylabel_width = 0;
  for (int k = 0; k <= p.yticks; ++k) {
    ylabel_width = std::max(ylabel_width, text_width(cr, format_g(k * p.ystep)));
  }
  p.hi_label = format_g(panel.edges.back());
  p.left = p.margin + 1.5 * f + ylabel_width + 0.5 * f;
  p.right = p.w - p.margin - std::max(0.5 * text_width(cr, p.hi_label), 0.2 * f);
  p.plot_top = top + 0.6 * f;
  p.axis_y = bottom - 5.8 * f;
  if (!(p.right - p.left >= 4 && p.axis_y - p.plot_top >= 4)) {
    return false;
  }
  p.lo = panel.edges.front();
  p.hi = panel.edges.back();
  return true;
}

// Grid lines, y tick labels and the y axis's title.
void draw_y_axis(const PlotFrame& p) {
  cairo_t* cr = p.cr;
  cairo_set_line_width(cr, 1);
  for (int k = 0; k <= p.yticks; ++k) {
    const double v = k * p.ystep;
    const std::string label = format_g(v);
    cairo_set_source_rgb(cr, 0.88, 0.88, 0.88);
    cairo_move_to(cr, p.left, std::round(p.py(v)) + 0.5);
    cairo_line_to(cr, p.right, std::round(p.py(v)) + 0.5);
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    show_text(cr, p.left - 0.4 * p.f - text_width(cr, label), p.py(v) + 0.35 * p.f, label);
  }
  cairo_save(cr);
  cairo_move_to(cr, p.margin + 1.1 * p.f, 0.5 * (p.plot_top + p.axis_y) + 0.5 * text_width(cr, "area fraction"));
  cairo_rotate(cr, -std::numbers::pi / 2);
  cairo_show_text(cr, "area fraction");
  cairo_restore(cr);
}

// Bars, coloured as the disks of the bin's middle radius are; a hairline gap when they are wide.
void draw_bars(const PlotFrame& p, const ColourScale& colours) {
  cairo_t* cr = p.cr;
  const Panel& panel = *p.panel;
  for (std::size_t b = 0; b < panel.achieved.size(); ++b) {
    if (!(panel.achieved[b] > 0)) {
      continue;
    }
    double x0 = p.px(panel.edges[b]);
    double x1 = p.px(panel.edges[b + 1]);
    if (x1 - x0 >= 4) {
      x0 += 0.5;
      x1 -= 0.5;
    }
    const Rgb c = ColourScale::colour(colours.level(0.5 * (panel.edges[b] + panel.edges[b + 1])));
    cairo_set_source_rgb(cr, c.r, c.g, c.b);
    cairo_rectangle(cr, x0, p.py(panel.achieved[b]), x1 - x0, p.axis_y - p.py(panel.achieved[b]));
    cairo_fill(cr);
  }
}

// The request, as a step line over the same bins.
void draw_request(const PlotFrame& p) {
  cairo_t* cr = p.cr;
  const Panel& panel = *p.panel;
  if (panel.requested.empty()) {
    return;
  }
  cairo_new_path(cr);
  cairo_move_to(cr, p.px(p.lo), p.py(0));
  for (std::size_t b = 0; b < panel.achieved.size(); ++b) {
    cairo_line_to(cr, p.px(panel.edges[b]), p.py(panel.requested[b]));
    cairo_line_to(cr, p.px(panel.edges[b + 1]), p.py(panel.requested[b]));
  }
  cairo_line_to(cr, p.px(p.hi), p.py(0));
  cairo_set_source_rgb(cr, 0.8, 0.15, 0.1);
  cairo_set_line_width(cr, std::max(1.5, p.w / 600));
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_MITER);
  cairo_stroke(cr);
}

// The x ticks: the range's ends and nice values between.
std::vector<double> x_ticks(double lo, double hi) {
  std::vector<double> ticks{lo};
  const double xstep = nice_step((hi - lo) / 5);
  // Counted, not accumulated: a step below the spacing of doubles near lo cannot loop forever.
  const double first = std::ceil(lo / xstep);
  for (int k = 0; k <= 10; ++k) {
    const double t = (first + k) * xstep;
    if (t > lo && t < hi) {
      ticks.push_back(t);
    }
  }
  ticks.push_back(hi);
  return ticks;
}

// Axes, x ticks and their labels (without overlapping labels: the ends are always shown), and
// the x axis's title.
void draw_x_axis(const PlotFrame& p) {
  cairo_t* cr = p.cr;
  const double f = p.f;
  cairo_set_source_rgb(cr, 0.15, 0.15, 0.15);
  cairo_set_line_width(cr, 1);
  cairo_move_to(cr, p.left, p.plot_top);
  cairo_line_to(cr, p.left, p.axis_y);
  cairo_line_to(cr, p.right, p.axis_y);
  cairo_stroke(cr);
  const std::vector<double> ticks = x_ticks(p.lo, p.hi);
  const double label_y = p.axis_y + 0.3 * f + 1.0 * f;
  const double gap = 0.8 * f;
  const double hi_left = p.px(p.hi) - 0.5 * text_width(cr, p.hi_label);
  double last_right = -INFINITY;
  for (std::size_t k = 0; k < ticks.size(); ++k) {
    const bool end = k == 0 || k + 1 == ticks.size();
    const std::string label = format_g(ticks[k]);
    const double x = p.px(ticks[k]);
    const double lw = text_width(cr, label);
    const double x0 = k == 0 ? std::max(x - 0.5 * lw, p.margin) : x - 0.5 * lw;
    if (!end && (x0 < last_right + gap || x0 + lw > hi_left - gap)) {
      continue;
    }
    cairo_move_to(cr, x, p.axis_y);
    cairo_line_to(cr, x, p.axis_y + 0.3 * f);
    cairo_stroke(cr);
    show_text(cr, x0, label_y, label);
    last_right = x0 + lw;
  }
  const std::string xlabel = "radius";
  show_text(cr, 0.5 * (p.left + p.right) - 0.5 * text_width(cr, xlabel), label_y + 1.4 * f, xlabel);
}

}  // namespace

// Draws the panel in the band [top, top + histogram_height(width_px)) of the picture.
void draw_panel(cairo_t* cr, const Panel& panel, const ColourScale& colours, double top, int width_px) {
  const double bottom = top + histogram_height(width_px);
  draw_captions(cr, panel, bottom, width_px);
  if (panel.achieved.empty()) {
    return;
  }
  PlotFrame frame;
  frame.cr = cr;
  frame.panel = &panel;
  frame.w = width_px;
  frame.f = font_px(width_px);
  frame.margin = kMarginFraction * frame.w;
  if (!plan_frame(frame, top, bottom)) {
    return;  // too narrow a picture for a plot: the caption only
  }
  draw_y_axis(frame);
  draw_bars(frame, colours);
  draw_request(frame);
  draw_x_axis(frame);
}

}  // namespace frontpack_tool::render_parts
