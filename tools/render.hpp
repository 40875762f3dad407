// Pictures of packings (PNG, SVG, PDF) drawn with Cairo. The tool's, not the library's: the
// library stays free of Cairo.
#pragma once

#include <filesystem>
#include <optional>
#include <span>

#include "frontpack/domain.hpp"
#include "frontpack/geometry.hpp"

namespace frontpack_tool {

enum class Picture { png, svg, pdf };

/// The picture format of a file name's extension (.png, .svg, .pdf; any case), if it is one.
[[nodiscard]] std::optional<Picture> picture_from_path(const std::filesystem::path& path);
/// "png", "svg" or "pdf".
[[nodiscard]] std::optional<Picture> picture_from_name(std::string_view name);

struct RenderOptions {
  int width_px = 1200;  ///< picture width in pixels (points for SVG/PDF); the height follows the domain
};

/// Height of the picture for a domain and a width (the domain's aspect ratio plus a margin).
[[nodiscard]] int picture_height(const frontpack::Domain& domain, int width_px);

/// Draws the domain (light grey, holes even-odd, dark outline) and the disks (coloured by radius,
/// viridis: small dark blue, large yellow; thin outlines when they are at least 3 px across) on
/// white, and writes it to `path` atomically. Throws frontpack::OptionError for a width out of
/// [16, 16384] or a picture taller than 32767 px, frontpack::IoError if it cannot be written.
void render(const std::filesystem::path& path, Picture format, const frontpack::Domain& domain,
            std::span<const frontpack::Disk> disks, const RenderOptions& options = {});

}  // namespace frontpack_tool
