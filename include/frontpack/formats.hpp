// frontpack: the file formats, in one table. One row per format: its name, its extensions, what
// a file of it holds (disks, a domain, a picture), whether the library reads or writes it and
// whether the frontpack tool writes it. Every format name (to_string), every lookup by name or by
// extension (format_from_path, disk_format_from_name, domain_format_of, ...), every list of names
// or extensions in a message, and the tool's --format help come from this table.
//
// Names, aliases and extensions are compared case-insensitively (ASCII).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace frontpack {

/// The file formats of the library's writers (io.hpp: write, write_file).
enum class Format : std::uint8_t {
  csv,     ///< "x,y,r" with a header line (write_csv, read_csv)
  yade,    ///< Yade text for ymport.textExt(file, format='x_y_z_r') (write_yade, read_yade)
  lammps,  ///< LAMMPS data file for atom_style sphere (write_lammps)
  vtp,     ///< VTK XML PolyData for ParaView (write_vtp)
  svg,     ///< a picture (write_svg)
};

/// The formats of the disk readers (io.hpp: read_disks).
enum class DiskFormat : std::uint8_t {
  csv,          ///< read_csv
  yade,         ///< read_yade
  lammps,       ///< read_lammps (data file)
  lammps_dump,  ///< read_lammps_dump
  vtp,          ///< read_vtp
};

/// The formats of the domain readers (domain_file.hpp: read_domain_file).
enum class DomainFormat : std::uint8_t {
  automatic = 0,  ///< by the file's extension (domain_format_of)
  wkt = 1,        ///< .wkt, .txt, any other extension: POLYGON or MULTIPOLYGON text
  dxf = 2,        ///< .dxf: ASCII DXF (dxflib)
  geojson = 3,    ///< .geojson, .json (GDAL/OGR)
  shapefile = 4,  ///< .shp (GDAL/OGR)
};

/// What a file of a format holds.
enum class FileKind : std::uint8_t { disks, domain, picture };

/// One row of the table.
struct FileFormat {
  std::string_view name;                         ///< "csv", "lammps-dump", "geojson", "png"
  std::span<const std::string_view> extensions;  ///< lower case, with the dot; the usual one first
  std::span<const std::string_view> aliases;     ///< other names accepted for it ("json", "shp")
  std::string_view label;                        ///< said after the extensions in lists ("Yade"), or empty
  FileKind holds = FileKind::disks;
  std::optional<Format> written_as{};       ///< the library writes it: write(), write_file()
  std::optional<DiskFormat> read_as{};      ///< the library reads its disks: read_disks()
  std::optional<DomainFormat> domain_as{};  ///< the library reads a domain from it: read_domain_file()
  bool tool_writes = false;                 ///< the frontpack tool writes it with -o (pictures by Cairo)
};

/// Every format, in the order of every list: the disk formats, the pictures, the domain formats.
[[nodiscard]] std::span<const FileFormat> file_formats() noexcept;

/// The row the library writes, reads disks or reads a domain as `format`; nullptr for a value
/// outside the enum (and for DomainFormat::automatic, which is no format).
[[nodiscard]] const FileFormat* format_row(Format format) noexcept;
[[nodiscard]] const FileFormat* format_row(DiskFormat format) noexcept;
[[nodiscard]] const FileFormat* format_row(DomainFormat format) noexcept;

/// What a lookup or a list is for: the rows a use takes.
enum class FormatUse : std::uint8_t {
  library_writes,  ///< written_as
  disk_reader,     ///< read_as
  domain_reader,   ///< domain_as
  tool_writes,     ///< tool_writes
  tool_pictures,   ///< tool_writes and holds a picture
};

/// Whether `format` serves `use`.
[[nodiscard]] bool serves(const FileFormat& format, FormatUse use) noexcept;

/// The first row serving `use` whose name or alias is `name`; nullptr if none.
[[nodiscard]] const FileFormat* find_format_by_name(std::string_view name, FormatUse use) noexcept;

/// The first row serving `use` that lists `path`'s extension; nullptr if none (or no extension).
[[nodiscard]] const FileFormat* find_format_by_extension(const std::filesystem::path& path, FormatUse use);

/// The names of the rows serving `use`, for messages and help: "csv, yade, lammps, vtp or svg".
[[nodiscard]] std::string format_names(FormatUse use);

/// The extensions of the rows serving `use`, for messages and help, each row's extensions joined
/// by " or " and followed by its label: ".csv, .txt or .yade (Yade), .data or .lmp (LAMMPS data)".
[[nodiscard]] std::string format_extensions(FormatUse use);

}  // namespace frontpack
