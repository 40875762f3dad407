// frontpack: writing and reading packings (CSV, Yade, LAMMPS, VTK PolyData, SVG).
//
// Round-trip guarantee: every writer except SVG prints each double in its shortest decimal form
// that reads back as exactly the same double (std::to_chars), so a packing certified in memory is
// certified in the file too: read_csv, read_yade, read_lammps and read_vtp (and LAMMPS, ParaView,
// Yade, Python's float()) get back the very bits that were written. Units are those of the domain's coordinates;
// frontpack never scales.
//
// Errors: OptionError (declared in frontpack/fill.hpp) for an unknown format or a bad writer
// option, IoError (with the OS's reason) for a file that cannot be read or written, DiskFileError
// (with file, line and column) for a malformed disk file, CancelledError once WriteOptions::stop
// (or a writer's `stop`) is requested.
#pragma once

#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <optional>
#include <span>
#include <stop_token>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "frontpack/domain.hpp"
#include "frontpack/errors.hpp"
#include "frontpack/fill.hpp"  // OptionError
#include "frontpack/formats.hpp"
#include "frontpack/geometry.hpp"

namespace frontpack {

/// The format's name in the table of formats (frontpack/formats.hpp): "csv", "yade", "lammps",
/// "vtp" or "svg".
[[nodiscard]] const char* to_string(Format format) noexcept;

/// The format for a file name's extension, compared case-insensitively, by the table of formats:
/// .csv -> csv; .txt and .yade -> yade (Yade's own examples name these files .txt); .data and .lmp
/// -> lammps; .vtp; .svg. Throws OptionError naming the extension and listing the known ones (for
/// a picture only the tool draws, .png or .pdf, saying so).
[[nodiscard]] Format format_from_path(const std::filesystem::path& path);

/// The format named `name` (as to_string gives it, compared case-insensitively, for a --format
/// option). Throws OptionError listing the known names.
[[nodiscard]] Format format_from_name(std::string_view name);

struct SvgStyle {
  double width_px = 800;       ///< picture width; the height follows the domain's aspect ratio
  bool colour_by_size = true;  ///< small disks light, large disks dark
};

/// Options of write_lammps.
struct LammpsOptions {
  /// Per-atom density column; finite, > 0. LAMMPS (29 Sep 2021, Debian bookworm) sets
  /// mass = density * (4/3) pi r^3 even with `dimension 2`; for a mass per area, set the masses
  /// after read_data (or use `set ... density/disc` where your LAMMPS has it).
  double density = 1.0;
  std::int64_t atom_type = 1;  ///< type of every atom without per-disk types, >= 1; the header declares this many
  /// With per-disk types: the density of type t is type_densities[t - 1] (when not empty; it must
  /// cover every type), else `density`.
  std::vector<double> type_densities{};
  /// With per-disk types: the "N atom types" of the header, >= the largest type (0: the largest type).
  std::int64_t atom_types = 0;
  /// Periodicity::x or xy: the box is a periodic cell (Domain::periodic). On a periodic axis a
  /// disk's centre must lie in the half-open box (xmin <= x < xmax) and the disk may reach across
  /// the side; on a walled axis it lies in the closed box as without periodicity. The title line
  /// names the `boundary` command the cell needs (p p p, or p f p for Periodicity::x): a data file
  /// cannot carry it.
  Periodicity periodicity = Periodicity::none;
};

/// Options of write() and write_file(), per format.
struct WriteOptions {
  SvgStyle svg;
  LammpsOptions lammps;
  /// Per-disk types (frontpack/types.hpp), empty or one >= 1 per disk; the writers carry them:
  /// CSV column "type", Yade matId = type - 1, LAMMPS type column, VTP Int32 array "type".
  std::span<const std::uint32_t> types{};
  /// Once a stop is requested, the writer throws CancelledError (within a few thousand disks);
  /// write_file() then leaves the target as it was.
  std::stop_token stop{};
};

/// A minimal SVG picture: the domain's outline (holes included) and the disks. Coordinates are
/// rounded to 0.001 px: a picture, not a data file.
void write_svg(std::ostream& out, const Domain& domain, std::span<const Disk> disks, const SvgStyle& style = {},
               std::stop_token stop = {});

/// CSV: a header line "x,y,r", then one line "x,y,r" per disk (centre and radius), in order. With
/// types (one per disk, else OptionError): "x,y,r,type" and a fourth column.
void write_csv(std::ostream& out, std::span<const Disk> disks, std::span<const std::uint32_t> types,
               std::stop_token stop = {});
inline void write_csv(std::ostream& out, std::span<const Disk> disks, std::stop_token stop = {}) {
  write_csv(out, disks, std::span<const std::uint32_t>{}, std::move(stop));
}

/// Yade text: one line "x y 0 r" per disk, in order (centre, z = 0, radius), separated by single
/// spaces, no header and no blank lines, so that both `ymport.textExt(file)` (format x_y_z_r, its
/// default) and `pack.SpherePack().load(file)` read it (SpherePack refuses any '#' line; textExt
/// fails on a blank line). An empty packing is the single line "#format x_y_z_r".
/// With types (one per disk, else OptionError): a first line "#format x_y_z_r_matId" and lines
/// "x y 0 r m" with m = type - 1, Yade's material index (O.materials[m]: append one material per
/// type, in type order, before textExt). SpherePack.load refuses such a file, rightly: its fifth
/// column would be a clump id.
void write_yade(std::ostream& out, std::span<const Disk> disks, std::span<const std::uint32_t> types,
                std::stop_token stop = {});
inline void write_yade(std::ostream& out, std::span<const Disk> disks, std::stop_token stop = {}) {
  write_yade(out, disks, std::span<const std::uint32_t>{}, std::move(stop));
}

/// LAMMPS data file for `atom_style sphere` (read with `read_data`; with `dimension 2` use
/// `boundary f f p` or `p p p`):
///
///     <title line>
///     N atoms
///     T atom types
///     xlo xhi xlo xhi          (the box)
///     ylo yhi ylo yhi
///     -R R zlo zhi             (R = largest radius, or 0.5 with no disks: straddles 0 as 2D requires)
///     Atoms # sphere
///     id type diameter density x y z     (one line per disk: id = index + 1, diameter = 2 r, z = 0)
///
/// 2 r is exact in binary, so r = diameter / 2 reads back exactly. Throws OptionError if the box
/// does not contain every disk fully (a periodic cell: LammpsOptions::periodicity) (decided exactly: x - r >= xmin and
/// x + r <= xmax in floating point are exact tests, because rounding is monotone and the bounds are doubles), or if an
/// option is out of range. With types (one per disk, else OptionError), each atom's type and its type's density.
void write_lammps(std::ostream& out, std::span<const Disk> disks, std::span<const std::uint32_t> types, const Box& box,
                  const LammpsOptions& options = {}, std::stop_token stop = {});
inline void write_lammps(std::ostream& out, std::span<const Disk> disks, const Box& box,
                         const LammpsOptions& options = {}, std::stop_token stop = {}) {
  write_lammps(out, disks, std::span<const std::uint32_t>{}, box, options, std::move(stop));
}

/// VTK XML PolyData (ASCII, version 1.0), for ParaView: one point per disk centre (Float64, z = 0),
/// one vertex cell per point, and point data `radius` (Float64, the active scalars: use it as the
/// scale array of the Point Gaussian representation or of a Glyph filter for true sizes) and `id`
/// (Int64, the disk's 0-based index in `disks`); with types (one per disk, else OptionError), also
/// `type` (Int32).
void write_vtp(std::ostream& out, std::span<const Disk> disks, std::span<const std::uint32_t> types,
               std::stop_token stop = {});
inline void write_vtp(std::ostream& out, std::span<const Disk> disks, std::stop_token stop = {}) {
  write_vtp(out, disks, std::span<const std::uint32_t>{}, std::move(stop));
}
/// As write_vtp() above; for a periodic domain (Domain::periodic) the PolyData also carries field
/// data `periodic_cell` (Float64, 4 components: xmin ymin xmax ymax) and `periodic_axes` (Int32:
/// 1 for Periodicity::x, 2 for xy), shown by ParaView's Information panel and spreadsheet view.
void write_vtp(std::ostream& out, const Domain& domain, std::span<const Disk> disks,
               std::span<const std::uint32_t> types, std::stop_token stop = {});

/// Writes `disks` (and, for SVG, the domain; for LAMMPS, the domain's bounding box as the box, a
/// periodic domain's cell with its periodicity; for VTP, a periodic domain's cell) to `out` in
/// `format`, with the writer of that format.
void write(std::ostream& out, Format format, const Domain& domain, std::span<const Disk> disks,
           const WriteOptions& options = {});

/// write() to `path` through an OutputFile (frontpack/output_file.hpp): a regular file (or a new
/// one, or the target of a symlink) is replaced in one step, so readers see the old file or the
/// complete new one, never a partial file; /dev/stdout, devices and FIFOs are written through.
/// On failure or cancellation the temporary file is removed and the target is left as it was;
/// IoError names the path and the OS's reason; OptionError as the writers; CancelledError.
void write_file(const std::filesystem::path& path, Format format, const Domain& domain, std::span<const Disk> disks,
                const WriteOptions& options = {});

/// Reads a CSV written by write_csv. Strict: the first line must be the header "x,y,r"; then
/// exactly three comma-separated numbers per line (spaces or tabs around a number are allowed;
/// CRLF line ends are accepted; no blank lines); every number finite; every radius > 0. Numbers
/// are parsed exactly and independently of the locale (std::from_chars: "1.5", "-2e-3", no "+").
/// A number out of the range of doubles is refused, whether it overflows ("1e400") or underflows
/// to 0 ("1e-400"); subnormal values ("5e-324") are read (README, "Numbers"). `source_name` (a
/// file name; "<input>" if empty) goes into the messages, and the offending text, escaped (a NUL
/// byte shows as \0) and cut to 40 characters. Throws DiskFileError naming the line.
/// The header may also be "x,y,r,type", with a fourth column of whole numbers >= 1 (types).
[[nodiscard]] std::vector<Disk> read_csv(std::istream& in, std::string_view source_name);
/// As read_csv, and the types into `types` (empty when the file has no type column).
[[nodiscard]] std::vector<Disk> read_csv(std::istream& in, std::string_view source_name,
                                         std::vector<std::uint32_t>& types);

/// Reads Yade text as written by write_yade: lines of four numbers "x y z r" separated by spaces
/// or tabs, where z must be 0 (frontpack's disks are planar); lines starting with '#' are
/// comments, except "#format F", where F must be x_y_z_r (the default of textExt) or x_y_z_r_matId
/// (a fifth column, a whole number m >= 0: type m + 1). Numbers and the other rules as read_csv
/// (no header required). Throws DiskFileError naming the line.
[[nodiscard]] std::vector<Disk> read_yade(std::istream& in, std::string_view source_name);
/// As read_yade, and the types into `types` (empty without "#format x_y_z_r_matId").
[[nodiscard]] std::vector<Disk> read_yade(std::istream& in, std::string_view source_name,
                                          std::vector<std::uint32_t>& types);

/// Reads a LAMMPS data file of atom_style sphere: as write_lammps writes it, and as LAMMPS's
/// `write_data` writes it after a run. The first line is the title. Header lines, in any order:
/// "N atoms" (required), the other counts of read_data ("N atom types", "N bonds", ...) and the box
/// ("LO HI xlo xhi", ..., "XY XZ YZ xy xz yz"), which are checked for their form and not used.
/// Then sections, each a name line (Atoms, Velocities, Masses, Pair Coeffs, ...) and its lines;
/// only "Atoms" is read (the others are skipped), with an optional "# sphere" style hint (another
/// style is refused): exactly N lines "id type diameter density x y z", optionally followed by three
/// image flags (write_data writes them). Ids >= 1 and unique, types >= 1, z = 0, diameter > 0;
/// radius = diameter / 2 (exact). '#' starts a comment anywhere; blank lines are skipped. Numbers
/// as read_csv. The disks come in ascending atom id order (LAMMPS writes atoms in the order its
/// processors hold them): with ids 1..N, disk k is atom k + 1. Throws DiskFileError naming the line.
[[nodiscard]] std::vector<Disk> read_lammps(std::istream& in, std::string_view source_name);

/// Reads a LAMMPS dump file (`dump custom ... id type x y z radius`): snapshots of "ITEM:" blocks
/// (TIMESTEP, NUMBER OF ATOMS, BOX BOUNDS, ATOMS, and UNITS or TIME), each checked in full. The
/// columns are found by the names on the "ITEM: ATOMS" line: id; x and y (or xu and yu); radius (or
/// diameter, halved); z (or zu), if present, must be 0; other columns are skipped. Scaled
/// coordinates (xs ys) are refused. The disks of the last snapshot, or of the one at `timestep`,
/// in ascending atom id order. LAMMPS's default dump format for floats is "%g" (6 significant
/// digits): for coordinates that certify what the run holds, use
/// `dump_modify ID format float %.17g`. Throws DiskFileError naming the line; missing_item if no
/// snapshot has `timestep` (the message lists the timesteps found).
[[nodiscard]] std::vector<Disk> read_lammps_dump(std::istream& in, std::string_view source_name,
                                                 std::optional<std::int64_t> timestep = std::nullopt);

/// Reads VTK XML PolyData (.vtp): as write_vtp writes it, and as VTK's vtkXMLPolyDataWriter and
/// ParaView write it: DataArrays in ascii, binary (inline base64) or appended (raw or base64)
/// format, either byte order, UInt32 or UInt64 headers, any VTK number type, several Pieces (read
/// in order). Compressed binary data (a VTKFile `compressor`) is refused (unsupported_format): write
/// the file uncompressed or in ascii mode. One disk per point, in order: the centre from Points
/// (z must be 0), the radius from the point data array named `radius_array`, or, if that is empty,
/// the first of "radius", "Radius", "diameter", "Diameter" (a diameter is halved); cells are not
/// read. Throws DiskFileError naming the line of the offending XML element.
[[nodiscard]] std::vector<Disk> read_vtp(std::istream& in, std::string_view source_name,
                                         std::string_view radius_array = {});

/// The format's name in the table of formats: "csv", "yade", "lammps", "lammps-dump" or "vtp".
[[nodiscard]] const char* to_string(DiskFormat format) noexcept;

/// The reader for a file name's extension, compared case-insensitively, by the table of formats:
/// .csv; .txt and .yade; .data and .lmp (LAMMPS data); .dump and .lammpstrj (LAMMPS dump); .vtp.
/// Throws OptionError naming the extension and listing the known ones.
[[nodiscard]] DiskFormat disk_format_from_path(const std::filesystem::path& path);

/// The reader named `name` (as to_string gives it, compared case-insensitively, for a
/// --disks-format option). Throws OptionError listing the known names.
[[nodiscard]] DiskFormat disk_format_from_name(std::string_view name);

/// Options of read_disks for the formats that have a choice.
struct ReadOptions {
  std::optional<std::int64_t> timestep;  ///< LAMMPS dump: this snapshot (default: the last)
  std::string radius_array;              ///< VTK PolyData: the radius array (default: as read_vtp)
};

/// Reads the disk file `path` with the reader of `format`. Throws IoError (with the OS's reason)
/// if the file cannot be read, DiskFileError if it is malformed.
[[nodiscard]] std::vector<Disk> read_disks(const std::filesystem::path& path, DiskFormat format,
                                           const ReadOptions& options = {});

/// read_disks() with the format chosen by disk_format_from_path (OptionError for an unknown
/// extension).
[[nodiscard]] std::vector<Disk> read_disks(const std::filesystem::path& path);

}  // namespace frontpack
