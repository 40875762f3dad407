// The inputs of the commands that read a packing (check, stats, render): the domain, as a DOMAIN
// file, --wkt TEXT or a periodic cell (--periodic), and a disk file DISKS in any format the library reads.
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "cli.hpp"
#include "frontpack/frontpack.hpp"
#include "outputs.hpp"

namespace frontpack_tool::cli {

struct PackingInputs {
  DomainSource domain;
  std::string disks;
  std::string disks_format;  ///< --disks-format; empty: by DISKS's extension
  std::string timestep;      ///< --timestep (LAMMPS dump); empty: the last snapshot
  std::string radius_array;  ///< --radius-array (VTK PolyData); empty: the library's default names
};

/// DOMAIN and DISKS (positional), --wkt TEXT or --periodic CELL [--periodic-axes xy|x] (then the
/// one positional is DISKS), --disks-format, --timestep, --radius-array.
void add_packing_inputs(CLI::App& cmd, PackingInputs& in);

/// After parsing: with --wkt or --periodic, the one positional given is DISKS. Throws UsageError or
/// CLI::RequiredError when the files given do not fit, OptionError for a bad option value.
void resolve(PackingInputs& in);

/// DOMAIN and DISKS as inputs that no output may overwrite.
[[nodiscard]] std::vector<FileUse> input_uses(const PackingInputs& in);

/// The disks, read as the options say.
[[nodiscard]] std::vector<frontpack::Disk> read_disks(const PackingInputs& in);

/// "(numbered from 0 in file order)", or in atom id order for the LAMMPS formats.
[[nodiscard]] const char* disk_numbering(const PackingInputs& in);

}  // namespace frontpack_tool::cli
