// Pictures of packings (PNG, SVG, PDF) drawn with Cairo. The tool's, not the library's: the
// library stays free of Cairo.
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <span>
#include <stop_token>
#include <string>

#include "frontpack/domain.hpp"
#include "frontpack/geometry.hpp"
#include "frontpack/output_file.hpp"
#include "frontpack/sizes.hpp"
#include "frontpack/stats.hpp"

namespace frontpack_tool {

enum class Picture { png, svg, pdf };

/// The names and extensions of the pictures: the table of formats (frontpack/formats.hpp), read
/// by outputs.hpp.

struct RenderOptions {
  int width_px = 1200;  ///< picture width in pixels (points for SVG/PDF); the height follows the domain
  /// Draw the size-distribution panel below the packing (false: the bare packing picture).
  bool histogram = true;
  /// The requested radius distribution, if known: the panel overlays it and gives the KS distance
  /// by area (frontpack::measure_sizes).
  std::optional<frontpack::Radii> requested;
  /// How the request was written (the --radius spec), for the panel's caption.
  std::string requested_spec;
  /// A periodic cell: also draw, lighter, the images of the disks that cross a periodic side (each
  /// disk shifted by a period whose copy reaches into the cell), so that a seam can be inspected.
  bool images = false;
  /// Draw this map of the cell coverage (PackingStats::cell_coverage) instead of the disks: each
  /// interior cell filled with viridis from the map's least coverage (dark) to its largest
  /// (light), or over cells_range, clipped to the domain; seams and sparse patches show as dark
  /// cells. The panel below, which keys the disks' colours, is left out (histogram is taken as
  /// false).
  std::optional<frontpack::CellCoverage> cells{};
  /// With cells: the coverage drawn darkest and lightest, [0] < [1] (a cell beyond them is drawn as
  /// the nearer one), so that maps of different packings compare colour for colour; unset, the
  /// map's own least and largest coverage.
  std::optional<std::array<double, 2>> cells_range{};
  /// Once a stop is requested, render() throws frontpack::CancelledError.
  std::stop_token stop{};
};

/// What the colours of a map drawn by render() (options.cells) stand for: "N interior cells of
/// side S, coverage LO (dark) to HI (light)", or "no interior cell". With a `range`, LO and HI are
/// its ends, followed by ", the cells' A to B" (the map's own least and largest).
[[nodiscard]] std::string cells_key(const frontpack::CellCoverage& cells,
                                    const std::optional<std::array<double, 2>>& range = std::nullopt);

/// Height of the size-distribution panel for a picture width: width / 4 + 6 font sizes, the font
/// size being width / 80 clamped to [10, 18] px; integer arithmetic (tests/tool_tests.cmake
/// computes the same).
[[nodiscard]] int histogram_height(int width_px);

/// Height of the picture for a domain and a width: the packing (the domain's aspect ratio plus a
/// margin), plus histogram_height(width_px) if `histogram`.
[[nodiscard]] int picture_height(const frontpack::Domain& domain, int width_px, bool histogram = true);

/// Draws the domain (light grey, holes even-odd, dark outline; a periodic cell's periodic sides
/// dashed, its walls solid) and the disks, or the cells of options.cells (coloured by radius,
/// viridis: small dark blue, large yellow; thin outlines when they are at least 3 px across) on
/// white and, unless options.histogram is false, below it the size-distribution panel: a
/// histogram of the radii by area (each bar the share of the total disk area in a bin of equal
/// width in radius, coloured as the disks of that radius are: the colour key), the requested
/// distribution's share of the area per bin as a line, and a caption with the KS distance by area.
/// Text is drawn with Cairo's toy font API (fontconfig's "sans-serif"; without fonts, boxes).
/// SVG files get the caption as the root's <title> (Cairo writes text as glyph outlines), PDF
/// files as their subject. Writes to `out` (its commit() is the caller's). Throws
/// frontpack::OptionError for a width out of [16, 16384] or a picture taller than 32767 px,
/// frontpack::IoError if it cannot be written.
void render(frontpack::OutputFile& out, Picture format, const frontpack::Domain& domain,
            std::span<const frontpack::Disk> disks, const RenderOptions& options = {});

}  // namespace frontpack_tool
