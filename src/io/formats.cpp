// The table of file formats (frontpack/formats.hpp) and the lookups and lists made from it.
#include "frontpack/formats.hpp"

#include <algorithm>
#include <array>
#include <optional>
#include <vector>

namespace frontpack {

namespace {

using Names = std::string_view[];

constexpr Names kCsv = {".csv"};
constexpr Names kYade = {".txt", ".yade"};  // Yade's own examples name these files .txt
constexpr Names kLammps = {".data", ".lmp"};
constexpr Names kDump = {".dump", ".lammpstrj"};
constexpr Names kVtp = {".vtp"};
constexpr Names kPng = {".png"};
constexpr Names kSvg = {".svg"};
constexpr Names kPdf = {".pdf"};
constexpr Names kWkt = {".wkt", ".txt"};  // and any extension no other domain format claims
constexpr Names kDxf = {".dxf"};
constexpr Names kGeojson = {".geojson", ".json"};
constexpr Names kGeojsonAliases = {"json"};
constexpr Names kShp = {".shp"};
constexpr Names kShpAliases = {"shp"};

constexpr std::span<const std::string_view> none{};

using K = FileKind;
const std::array kTable = {
    FileFormat{"csv", kCsv, none, "", K::disks, Format::csv, DiskFormat::csv, {}, true},
    FileFormat{"yade", kYade, none, "Yade", K::disks, Format::yade, DiskFormat::yade, {}, true},
    FileFormat{"lammps", kLammps, none, "LAMMPS data", K::disks, Format::lammps, DiskFormat::lammps, {}, true},
    FileFormat{"lammps-dump", kDump, none, "LAMMPS dump", K::disks, {}, DiskFormat::lammps_dump, {}, false},
    FileFormat{"vtp", kVtp, none, "ParaView", K::disks, Format::vtp, DiskFormat::vtp, {}, true},
    FileFormat{"png", kPng, none, "", K::picture, {}, {}, {}, true},
    FileFormat{"svg", kSvg, none, "", K::picture, Format::svg, {}, {}, true},
    FileFormat{"pdf", kPdf, none, "", K::picture, {}, {}, {}, true},
    FileFormat{"wkt", kWkt, none, "", K::domain, {}, {}, DomainFormat::wkt, false},
    FileFormat{"dxf", kDxf, none, "", K::domain, {}, {}, DomainFormat::dxf, false},
    FileFormat{"geojson", kGeojson, kGeojsonAliases, "", K::domain, {}, {}, DomainFormat::geojson, false},
    FileFormat{"shapefile", kShp, kShpAliases, "", K::domain, {}, {}, DomainFormat::shapefile, false},
};

bool same_name(std::string_view a, std::string_view b) noexcept {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           const auto lower = [](char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; };
           return lower(x) == lower(y);
         });
}

bool lists(std::span<const std::string_view> names, std::string_view name) noexcept {
  return std::any_of(names.begin(), names.end(), [name](std::string_view n) { return same_name(n, name); });
}

// "a", "a or b", "a, b or c".
std::string joined(const std::vector<std::string>& items) {
  std::string out;
  for (std::size_t k = 0; k < items.size(); ++k) {
    if (k > 0) {
      out.append(k + 1 == items.size() ? " or " : ", ");
    }
    out.append(items[k]);
  }
  return out;
}

// The row whose `member` is `value`.
template <class Enum>
const FileFormat* row_where(std::optional<Enum> FileFormat::*member, Enum value) noexcept {
  const auto rows = file_formats();
  const auto it = std::find_if(rows.begin(), rows.end(), [&](const FileFormat& f) { return f.*member == value; });
  return it == rows.end() ? nullptr : &*it;
}

}  // namespace

const FileFormat* format_row(Format format) noexcept {
  return row_where(&FileFormat::written_as, format);
}

const FileFormat* format_row(DiskFormat format) noexcept {
  return row_where(&FileFormat::read_as, format);
}

const FileFormat* format_row(DomainFormat format) noexcept {
  return row_where(&FileFormat::domain_as, format);
}

std::span<const FileFormat> file_formats() noexcept {
  return kTable;
}

bool serves(const FileFormat& format, FormatUse use) noexcept {
  switch (use) {
    case FormatUse::library_writes: return format.written_as.has_value();
    case FormatUse::disk_reader: return format.read_as.has_value();
    case FormatUse::domain_reader: return format.domain_as.has_value();
    case FormatUse::tool_writes: return format.tool_writes;
    case FormatUse::tool_pictures: return format.tool_writes && format.holds == FileKind::picture;
  }
  return false;
}

const FileFormat* find_format_by_name(std::string_view name, FormatUse use) noexcept {
  for (const FileFormat& f : kTable) {
    if (serves(f, use) && (same_name(f.name, name) || lists(f.aliases, name))) {
      return &f;
    }
  }
  return nullptr;
}

const FileFormat* find_format_by_extension(const std::filesystem::path& path, FormatUse use) {
  const std::string ext = path.extension().string();
  if (ext.empty()) {
    return nullptr;
  }
  for (const FileFormat& f : kTable) {
    if (serves(f, use) && lists(f.extensions, ext)) {
      return &f;
    }
  }
  return nullptr;
}

std::string format_names(FormatUse use) {
  std::vector<std::string> items;
  for (const FileFormat& f : kTable) {
    if (serves(f, use)) {
      items.emplace_back(f.name);
    }
  }
  return joined(items);
}

std::string format_extensions(FormatUse use) {
  std::vector<std::string> items;
  for (const FileFormat& f : kTable) {
    if (serves(f, use)) {
      std::vector<std::string> exts(f.extensions.begin(), f.extensions.end());
      std::string item = joined(exts);
      if (!f.label.empty()) {
        item.append(" (").append(f.label).append(")");
      }
      items.push_back(std::move(item));
    }
  }
  return joined(items);
}

}  // namespace frontpack
