// The disk readers' formats: names, extensions, and read_disks() choosing the reader.
#include <fstream>
#include <string>

#include "common/read_file.hpp"
#include "common/text.hpp"
#include "frontpack/io.hpp"

namespace frontpack {

namespace {

constexpr const char* kExtensions =
    ".csv, .txt or .yade (Yade), .data or .lmp (LAMMPS data), .dump or .lammpstrj (LAMMPS dump), .vtp";
constexpr DiskFormat kFormats[] = {DiskFormat::csv, DiskFormat::yade, DiskFormat::lammps, DiskFormat::lammps_dump,
                                   DiskFormat::vtp};

}  // namespace

const char* to_string(DiskFormat format) noexcept {
  switch (format) {
    case DiskFormat::csv: return "csv";
    case DiskFormat::yade: return "yade";
    case DiskFormat::lammps: return "lammps";
    case DiskFormat::lammps_dump: return "lammps-dump";
    case DiskFormat::vtp: return "vtp";
  }
  return "unknown";
}

DiskFormat disk_format_from_path(const std::filesystem::path& path) {
  const std::string original = path.extension().string();
  const std::string ext = detail::ascii_lower(original);
  if (ext == ".csv") {
    return DiskFormat::csv;
  }
  if (ext == ".txt" || ext == ".yade") {
    return DiskFormat::yade;
  }
  if (ext == ".data" || ext == ".lmp") {
    return DiskFormat::lammps;
  }
  if (ext == ".dump" || ext == ".lammpstrj") {
    return DiskFormat::lammps_dump;
  }
  if (ext == ".vtp") {
    return DiskFormat::vtp;
  }
  throw OptionError("'" + path.string() + "': " +
                    (ext.empty() ? std::string("no file extension to tell the format by")
                                 : "unknown disk file format '" + original + "'") +
                    "; frontpack reads " + kExtensions);
}

DiskFormat disk_format_from_name(std::string_view name) {
  for (const DiskFormat f : kFormats) {
    if (name == to_string(f)) {
      return f;
    }
  }
  throw OptionError("unknown disk file format '" + std::string(name) +
                    "'; expected csv, yade, lammps, lammps-dump or vtp");
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
