#include "packing_inputs.hpp"

#include <cstdint>
#include <limits>

#include "option_values.hpp"

namespace frontpack_tool::cli {

namespace {

frontpack::DiskFormat format_of(const PackingInputs& in) {
  return in.disks_format.empty() ? frontpack::disk_format_from_path(in.disks)
                                 : frontpack::disk_format_from_name(in.disks_format);
}

}  // namespace

void add_packing_inputs(CLI::App& cmd, PackingInputs& in) {
  cmd.add_option("DOMAIN", in.domain.file, std::string(kDomainFileHelp) + " (omit it with --wkt or --periodic)");
  cmd.add_option("DISKS", in.disks,
                 "disk file: .csv (x,y,r), .txt/.yade (Yade x y z r), .data/.lmp (LAMMPS data, atom_style sphere), "
                 ".dump/.lammpstrj (LAMMPS dump with id x y radius), .vtp (VTK PolyData)");
  add_domain_source_options(cmd, in.domain);
  add_periodic_options(cmd, in.domain);
  cmd.add_option("--disks-format", in.disks_format,
                 "read DISKS as csv, yade, lammps, lammps-dump or vtp instead of by its extension");
  cmd.add_option("--timestep", in.timestep, "LAMMPS dump: the snapshot of this timestep (default: the last)");
  cmd.add_option("--radius-array", in.radius_array,
                 "VTK PolyData: the point data array of radii (default: radius, Radius, or diameter/Diameter halved)");
}

void resolve(PackingInputs& in) {
  if (in.domain.from_option()) {
    if (!in.disks.empty()) {
      throw UsageError(std::string("with ") + (in.domain.from_text() ? "--wkt" : "--periodic") +
                       ", give only DISKS (got '" + in.domain.file + "' and '" + in.disks + "')");
    }
    in.disks = in.domain.file;
    in.domain.file.clear();
  }
  if (in.disks.empty()) {
    throw CLI::RequiredError(
        in.domain.from_option() || !in.domain.file.empty() ? "DISKS" : "DOMAIN (or --wkt, --periodic) and DISKS");
  }
  (void)format_of(in);
  if (!in.timestep.empty()) {
    (void)parse_count("--timestep", in.timestep, std::numeric_limits<std::int64_t>::max());
  }
}

std::vector<FileUse> input_uses(const PackingInputs& in) {
  std::vector<FileUse> uses = domain_inputs(in.domain);
  uses.push_back({"DISKS", in.disks});
  return uses;
}

std::vector<frontpack::Disk> read_disks(const PackingInputs& in) {
  frontpack::ReadOptions options;
  if (!in.timestep.empty()) {
    options.timestep =
        static_cast<std::int64_t>(parse_count("--timestep", in.timestep, std::numeric_limits<std::int64_t>::max()));
  }
  options.radius_array = in.radius_array;
  return frontpack::read_disks(in.disks, format_of(in), options);
}

const char* disk_numbering(const PackingInputs& in) {
  const frontpack::DiskFormat f = format_of(in);
  return f == frontpack::DiskFormat::lammps || f == frontpack::DiskFormat::lammps_dump
             ? "numbered from 0 in atom id order"
             : "numbered from 0 in file order";
}

}  // namespace frontpack_tool::cli
