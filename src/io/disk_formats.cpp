// The disk readers' formats by name and extension (the table of formats, frontpack/formats.hpp),
// and read_disks() choosing the reader.
#include <fstream>
#include <string>

#include "common/read_file.hpp"
#include "frontpack/io.hpp"

namespace frontpack {

const char* to_string(DiskFormat format) noexcept {
  const FileFormat* row = format_row(format);
  return row != nullptr ? row->name.data() : "unknown";  // the table's names are string literals
}

DiskFormat disk_format_from_path(const std::filesystem::path& path) {
  if (const FileFormat* f = find_format_by_extension(path, FormatUse::disk_reader)) {
    return *f->read_as;
  }
  const std::string ext = path.extension().string();
  throw OptionError("'" + path.string() + "': " +
                    (ext.empty() ? std::string("no file extension to tell the format by")
                                 : "unknown disk file format '" + ext + "'") +
                    "; frontpack reads " + format_extensions(FormatUse::disk_reader));
}

DiskFormat disk_format_from_name(std::string_view name) {
  if (const FileFormat* f = find_format_by_name(name, FormatUse::disk_reader)) {
    return *f->read_as;
  }
  throw OptionError("unknown disk file format '" + std::string(name) + "'; expected " +
                    format_names(FormatUse::disk_reader));
}

std::vector<Disk> read_disks(const std::filesystem::path& path, DiskFormat format, const ReadOptions& options) {
  std::ifstream in = detail::open_for_reading(path);
  const std::string name = path.string();
  switch (format) {
    case DiskFormat::csv: return read_csv(in, name);
    case DiskFormat::yade: return read_yade(in, name);
    case DiskFormat::lammps: return read_lammps(in, name);
    case DiskFormat::lammps_dump: return read_lammps_dump(in, name, options.timestep);
    case DiskFormat::vtp: return read_vtp(in, name, options.radius_array);
  }
  return {};
}

}  // namespace frontpack
