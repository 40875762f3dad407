// Reader of LAMMPS data files for atom_style sphere: as write_lammps writes them, and as LAMMPS's
// own write_data writes them after a run (header keywords in any order, a Velocities section,
// image flags after the coordinates, '#' comments).
#include <algorithm>
#include <cstdint>
#include <istream>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "common/numbers.hpp"
#include "frontpack/io.hpp"
#include "io/line_reader.hpp"

namespace frontpack {

namespace {

using Kind = DiskFileError::Kind;
using detail::LineReader;

// The largest atom count read: a header that declares more is refused before anything is
// allocated for it.
constexpr std::uint64_t kMaxAtoms = std::uint64_t{1} << 40;

bool is_section_name(std::string_view line) {
  return !line.empty() &&
         ((line.front() >= 'A' && line.front() <= 'Z') || (line.front() >= 'a' && line.front() <= 'z'));
}

// The header keywords of a LAMMPS data file (read_data): a count, or box bounds. Only "atoms"
// matters here; the others are checked for their shape and skipped.
bool is_count_keyword(std::string_view words) {
  for (const std::string_view k :
       {"atoms", "bonds", "angles", "dihedrals", "impropers", "atom types", "bond types", "angle types",
        "dihedral types", "improper types", "extra bond per atom", "extra angle per atom", "extra dihedral per atom",
        "extra improper per atom", "extra special per atom", "ellipsoids", "lines", "triangles", "bodies"}) {
    if (words == k) {
      return true;
    }
  }
  return false;
}

std::string join(const std::vector<std::string_view>& t, std::size_t from) {
  std::string out;
  for (std::size_t i = from; i < t.size(); ++i) {
    out.append(i > from ? " " : "").append(t[i]);
  }
  return out;
}

// One header line (comment stripped, not empty). Returns the atom count if it is "N atoms".
std::optional<std::uint64_t> header_line(const LineReader& lines, std::string_view text) {
  const std::vector<std::string_view> t = detail::tokens(text);
  const auto bounds = [&](std::size_t numbers) {
    for (std::size_t i = 0; i < numbers; ++i) {
      (void)lines.number_at(t[i], "box bound");
    }
  };
  if (t.size() == 4 && (join(t, 2) == "xlo xhi" || join(t, 2) == "ylo yhi" || join(t, 2) == "zlo zhi")) {
    bounds(2);
    return std::nullopt;
  }
  if (t.size() == 6 && join(t, 3) == "xy xz yz") {
    bounds(3);
    return std::nullopt;
  }
  if (t.size() >= 2 && is_count_keyword(join(t, 1))) {
    const std::uint64_t n = lines.count_at(t[0], ("the number of " + join(t, 1)).c_str(), kMaxAtoms);
    return join(t, 1) == "atoms" ? std::optional<std::uint64_t>(n) : std::nullopt;
  }
  lines.fail(Kind::syntax,
             "expected a header line ('N atoms', 'N atom types', 'LO HI xlo xhi', ...) or a section name, got " +
                 detail::quote_text(text));
}

// The "Atoms" line: "Atoms" and an optional "# sphere" style hint.
void atoms_header(const LineReader& lines) {
  const std::string_view raw = lines.text();
  const std::size_t hash = raw.find('#');
  if (hash == std::string_view::npos) {
    return;
  }
  const std::vector<std::string_view> hint = detail::tokens(raw.substr(hash + 1));
  if (hint.size() != 1 || hint[0] != "sphere") {
    lines.fail(Kind::unsupported_format,
               "atom style " + detail::quote_text(detail::strip_comment(raw.substr(hash + 1))) +
                   ": frontpack reads LAMMPS data files of atom_style sphere ('Atoms # sphere')",
               hash + 1);
  }
}

// One line of the Atoms section: id type diameter density x y z [ix iy iz].
detail::Atom atom_line(const LineReader& lines, std::string_view text) {
  const std::vector<std::string_view> t = detail::tokens(text);
  if (t.size() != 7 && t.size() != 10) {
    lines.fail(Kind::field_count,
               "expected 'id type diameter density x y z' (atom_style sphere), optionally followed by 3 image "
               "flags, got " +
                   std::to_string(t.size()) + " values");
  }
  const std::int64_t id = lines.integer_at(t[0], "the atom id");
  if (id < 1) {
    lines.fail(Kind::bad_number, "atom id must be >= 1, got " + detail::quote_text(t[0]), lines.column_of(t[0]));
  }
  if (lines.integer_at(t[1], "the atom type") < 1) {
    lines.fail(Kind::bad_number, "atom type must be >= 1, got " + detail::quote_text(t[1]), lines.column_of(t[1]));
  }
  const double diameter = lines.number_at(t[2], "diameter");
  (void)lines.number_at(t[3], "density");
  const double x = lines.number_at(t[4], "x");
  const double y = lines.number_at(t[5], "y");
  if (lines.number_at(t[6], "z") != 0) {
    lines.fail(Kind::nonzero_z, "z must be 0 (frontpack's disks are planar), got " + detail::quote_text(t[6]),
               lines.column_of(t[6]));
  }
  for (std::size_t i = 7; i < t.size(); ++i) {
    (void)lines.integer_at(t[i], "an image flag");
  }
  if (!(diameter > 0)) {
    lines.fail(Kind::bad_radius, "diameter must be > 0, got " + detail::quote_text(t[2]), lines.column_of(t[2]));
  }
  return {id, detail::make_disk(lines, x, y, diameter / 2, t[2]), lines.number()};
}

}  // namespace

std::vector<Disk> read_lammps(std::istream& in, std::string_view source_name) {
  LineReader lines(in, source_name);
  if (!lines.next()) {
    lines.fail(Kind::empty_file, "empty file (expected a LAMMPS data file: a title line, then 'N atoms', ...)");
  }
  std::optional<std::uint64_t> declared;
  std::vector<detail::Atom> atoms;
  bool in_header = true;
  bool in_atoms = false;
  bool atoms_seen = false;
  std::size_t atoms_line = 0;
  const auto end_atoms = [&] {
    if (in_atoms && atoms.size() != *declared) {
      lines.fail(Kind::count_mismatch, "the Atoms section (line " + std::to_string(atoms_line) + ") has " +
                                           std::to_string(atoms.size()) + " atoms; the header declares " +
                                           std::to_string(*declared));
    }
    in_atoms = false;
  };
  while (lines.next()) {
    const std::string_view text = detail::strip_comment(lines.text());
    if (text.empty()) {
      continue;
    }
    if (is_section_name(text)) {
      end_atoms();
      in_header = false;
      if (text == "Atoms") {
        if (atoms_seen) {
          lines.fail(Kind::syntax, "a second Atoms section (the first is on line " + std::to_string(atoms_line) + ")");
        }
        if (!declared) {
          lines.fail(Kind::missing_item, "the Atoms section comes before an 'N atoms' header line");
        }
        atoms_header(lines);
        atoms_seen = in_atoms = true;
        atoms_line = lines.number();
        atoms.reserve(static_cast<std::size_t>(std::min<std::uint64_t>(*declared, 1 << 20)));
      }
      continue;  // another section (Velocities, Masses, coefficients): not needed for the disks
    }
    if (in_header) {
      if (const auto n = header_line(lines, text)) {
        declared = n;
      }
    } else if (in_atoms) {
      if (atoms.size() == *declared) {
        lines.fail(Kind::count_mismatch, "more atoms than the " + std::to_string(*declared) +
                                             " the header declares (Atoms on line " + std::to_string(atoms_line) + ")");
      }
      atoms.push_back(atom_line(lines, text));
    }
  }
  end_atoms();
  if (!declared) {
    lines.fail(Kind::missing_item, "no 'N atoms' header line (is this a LAMMPS data file?)");
  }
  if (!atoms_seen && *declared > 0) {
    lines.fail(Kind::missing_item, "no Atoms section; the header declares " + std::to_string(*declared) + " atoms");
  }
  return detail::disks_by_id(std::move(atoms), lines.source());
}

}  // namespace frontpack
