// read_domain_file(): the format, then its reader (WKT here; DXF through dxflib, GeoJSON and
// Shapefile through GDAL, when the build has them).
#include "frontpack/domain_file.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "common/format.hpp"
#include "common/read_file.hpp"
#include "common/text.hpp"
#include "frontpack/errors.hpp"

#include "domain/contour_chain.hpp"
#include "domain/contour_nesting.hpp"
#if FRONTPACK_HAVE_DXFLIB
#include "domain/dxf_reader.hpp"
#endif
#if FRONTPACK_HAVE_GDAL
#include "domain/ogr_reader.hpp"
#endif

namespace frontpack {

namespace {

void check_options(const DomainReadOptions& o) {
  if (!std::isfinite(o.max_deviation) || o.max_deviation < 0) {
    throw OptionError("max_deviation (--max-deviation) " + detail::format_double(o.max_deviation) +
                      ": expected a finite number >= 0 (0: relative to each curve's radius)");
  }
  if (!std::isfinite(o.relative_deviation) || o.relative_deviation <= 0) {
    throw OptionError("relative_deviation " + detail::format_double(o.relative_deviation) +
                      ": expected a finite number > 0");
  }
  if (!std::isfinite(o.join_tolerance) || o.join_tolerance < 0) {
    throw OptionError("join_tolerance " + detail::format_double(o.join_tolerance) + ": expected a finite number >= 0");
  }
}

[[noreturn, maybe_unused]] void missing_reader(DomainFormat format, const std::filesystem::path& path,
                                               const char* library, const char* option) {
  throw OptionError("'" + path.string() + "': this frontpack was built without " + library + ", so it cannot read " +
                    to_string(format) + " files (configure with " + option + "=ON and " + library +
                    " installed); WKT is always read");
}

}  // namespace

const char* to_string(DomainFormat format) noexcept {
  if (format == DomainFormat::automatic) {
    return "auto";
  }
  const FileFormat* row = format_row(format);
  return row != nullptr ? row->name.data() : "unknown";  // the table's names are string literals
}

DomainFormat parse_domain_format(std::string_view name) {
  if (detail::ascii_lower(name) == "auto") {
    return DomainFormat::automatic;
  }
  if (const FileFormat* f = find_format_by_name(name, FormatUse::domain_reader)) {
    return *f->domain_as;
  }
  throw OptionError("domain format '" + std::string(name) + "': expected auto, " +
                    format_names(FormatUse::domain_reader));
}

DomainFormat domain_format_of(const std::filesystem::path& path) {
  const FileFormat* f = find_format_by_extension(path, FormatUse::domain_reader);
  return f != nullptr ? *f->domain_as : DomainFormat::wkt;  // any other name: WKT needs no extension
}

bool has_dxf_reader() noexcept {
  return FRONTPACK_HAVE_DXFLIB != 0;
}

bool has_gis_reader() noexcept {
  return FRONTPACK_HAVE_GDAL != 0;
}

DomainFile read_domain_file(const std::filesystem::path& path, const DomainReadOptions& options) {
  check_options(options);
  const DomainFormat format = options.format == DomainFormat::automatic ? domain_format_of(path) : options.format;
  const std::string source = path.string();
  switch (format) {
    case DomainFormat::automatic:
    case DomainFormat::wkt: {
      Domain d = Domain::from_wkt_file(path);
      const std::size_t rings = d.num_polygons() + d.num_holes();
      return {.domain = std::move(d),
              .format = DomainFormat::wkt,
              .contours = rings,
              .ignored_entities = 0,
              .curves = {},
              .units = {}};
    }
    case DomainFormat::dxf: {
#if FRONTPACK_HAVE_DXFLIB
      detail::DxfContents dxf = detail::read_dxf(path);
      const double extent = std::max(dxf.extent.width(), dxf.extent.height());
      std::vector<detail::Contour> contours = std::move(dxf.closed);
      std::vector<detail::Contour> chained =
          detail::chain_pieces(std::move(dxf.open), options.join_tolerance * extent, source);
      contours.insert(contours.end(), std::make_move_iterator(chained.begin()), std::make_move_iterator(chained.end()));
      std::vector<CurveReport> curves;
      Domain d = detail::nest_contours(contours, options, source, curves);
      return {.domain = std::move(d),
              .format = DomainFormat::dxf,
              .contours = contours.size(),
              .ignored_entities = dxf.ignored,
              .curves = std::move(curves),
              .units = std::move(dxf.units)};
#else
      missing_reader(format, path, "dxflib", "FRONTPACK_WITH_DXFLIB");
#endif
    }
    case DomainFormat::geojson:
    case DomainFormat::shapefile: {
#if FRONTPACK_HAVE_GDAL
      if (format == DomainFormat::shapefile) {
        (void)detail::open_for_reading(path);  // IoError with the project's message when unreadable
      }  // (GeoJSON is read once, as text, by read_ogr: opening a FIFO twice would wait forever)
      detail::GisPolygons gis = detail::read_ogr(path, format == DomainFormat::geojson ? "GeoJSON" : "ESRI Shapefile");
      std::size_t rings = 0;
      for (const auto& names : gis.ring_names) {
        rings += names.size();
      }
      Domain d = detail::polygons_to_domain(std::move(gis.polygons), gis.ring_names, source);
      return {.domain = std::move(d),
              .format = format,
              .contours = rings,
              .ignored_entities = 0,
              .curves = {},
              .units = {}};
#else
      missing_reader(format, path, "GDAL", "FRONTPACK_WITH_GDAL");
#endif
    }
  }
  throw OptionError("unknown domain format");
}

}  // namespace frontpack
