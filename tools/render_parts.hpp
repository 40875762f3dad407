// The renderer's parts shared by the packing picture (render.cpp) and the size-distribution
// panel below it (render_panel.cpp): the colour scale, the margins and the font size.
#pragma once

#include <cairo.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <span>
#include <string>

#include "frontpack/geometry.hpp"
#include "render.hpp"

namespace frontpack_tool::render_parts {

struct Rgb {
  double r, g, b;
};

// viridis (matplotlib's perceptually uniform map) at 9 evenly spaced anchors, interpolated
// linearly in between.
inline Rgb viridis(double t) {
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

constexpr double kMarginFraction = 0.02;

// Disk colours: 64 levels of viridis, linear in radius from the smallest disk to the largest.
constexpr std::size_t kLevels = 64;

struct ColourScale {
  double rmin = INFINITY;
  double rmax = -INFINITY;
  explicit ColourScale(std::span<const frontpack::Disk> disks) {
    for (const frontpack::Disk& d : disks) {
      rmin = std::min(rmin, d.radius);
      rmax = std::max(rmax, d.radius);
    }
  }
  [[nodiscard]] std::size_t level(double r) const {
    if (!(rmax > rmin)) {
      return kLevels / 2;
    }
    // Beyond [0, 1] for a panel edge outside the disks' range, infinite far beyond it (radii near
    // the largest double): decided before the conversion, which is undefined out of range.
    const double t = (r - rmin) / (rmax - rmin);
    if (!(t > 0)) {
      return 0;
    }
    return t >= 1 ? kLevels - 1 : static_cast<std::size_t>(t * kLevels);  // (t * 64 < 64 exactly)
  }
  [[nodiscard]] static Rgb colour(std::size_t level) { return viridis((static_cast<double>(level) + 0.5) / kLevels); }
};

inline int font_px(int width_px) {
  return std::clamp(width_px / 80, 10, 18);
}

// The size-distribution panel's content: bins of equal width in radius over the achieved and
// requested ranges, the share of the total disk area in each (achieved and requested), and the
// caption.
struct Panel {
  std::vector<double> edges;      // bins + 1 edges; bin b is [edges[b], edges[b + 1]), the last one closed
  std::vector<double> achieved;   // share of the disks' total area per bin
  std::vector<double> requested;  // the requested distribution's, per bin (empty if none)
  std::string caption[2];
};

/// The panel's content for these disks and options (bins of RadiusBins over the achieved and
/// requested ranges).
[[nodiscard]] Panel make_panel(std::span<const frontpack::Disk> disks, const RenderOptions& options);

/// Draws the panel in the band [top, top + histogram_height(width_px)) of the picture.
void draw_panel(cairo_t* cr, const Panel& panel, const ColourScale& colours, double top, int width_px);

}  // namespace frontpack_tool::render_parts
