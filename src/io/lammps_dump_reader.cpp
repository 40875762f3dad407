// Reader of LAMMPS dump files (`dump custom ... id type x y z radius`): snapshots of "ITEM:"
// blocks; the columns are found by their names on the "ITEM: ATOMS" line.
#include <cstdint>
#include <istream>
#include <map>
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

constexpr std::uint64_t kMaxAtoms = std::uint64_t{1} << 40;
constexpr std::size_t kNone = static_cast<std::size_t>(-1);

// Where the needed values are on an atom line.
struct Columns {
  std::size_t count = 0;
  std::size_t id = kNone;
  std::size_t x = kNone;
  std::size_t y = kNone;
  std::size_t z = kNone;
  std::size_t size = kNone;  // radius or diameter
  bool diameter = false;
};

std::size_t find(const std::vector<std::string_view>& names, std::initializer_list<std::string_view> wanted) {
  for (const std::string_view w : wanted) {
    for (std::size_t i = 0; i < names.size(); ++i) {
      if (names[i] == w) {
        return i;
      }
    }
  }
  return kNone;
}

// The "ITEM: ATOMS name..." line: the columns by name.
Columns columns(const LineReader& lines, const std::vector<std::string_view>& t) {
  const std::vector<std::string_view> names(t.begin() + 2, t.end());
  Columns c;
  c.count = names.size();
  c.id = find(names, {"id"});
  c.x = find(names, {"x", "xu"});
  c.y = find(names, {"y", "yu"});
  c.z = find(names, {"z", "zu"});
  c.size = find(names, {"radius"});
  if (c.size == kNone) {
    c.size = find(names, {"diameter"});
    c.diameter = c.size != kNone;
  }
  if (c.x == kNone && find(names, {"xs", "xsu"}) != kNone) {
    lines.fail(Kind::unsupported_format,
               "scaled coordinates (xs, ys): frontpack reads dumps of x y (or xu yu); dump 'id type x y z radius'");
  }
  const char* missing = c.id == kNone ? "id" : c.x == kNone ? "x (or xu)" : c.y == kNone ? "y (or yu)" : nullptr;
  if (missing == nullptr && c.size == kNone) {
    missing = "radius (or diameter)";
  }
  if (missing != nullptr) {
    lines.fail(Kind::missing_item, std::string("no ") + missing +
                                       " column in the ATOMS line; frontpack needs id, x, y and radius "
                                       "(dump custom ... id type x y z radius)");
  }
  return c;
}

detail::Atom atom_line(const LineReader& lines, const Columns& c) {
  const std::vector<std::string_view> t = detail::tokens(lines.text());
  if (t.size() != c.count) {
    lines.fail(Kind::field_count, "expected " + std::to_string(c.count) + " values as the ATOMS line names, got " +
                                      std::to_string(t.size()));
  }
  const std::int64_t id = lines.integer_at(t[c.id], "the atom id");
  const double x = lines.number_at(t[c.x], "x");
  const double y = lines.number_at(t[c.y], "y");
  if (c.z != kNone && lines.number_at(t[c.z], "z") != 0) {
    lines.fail(Kind::nonzero_z, "z must be 0 (frontpack's disks are planar), got " + detail::quote_text(t[c.z]),
               lines.column_of(t[c.z]));
  }
  const double size = lines.number_at(t[c.size], c.diameter ? "diameter" : "radius");
  return {id, detail::make_disk(lines, x, y, c.diameter ? size / 2 : size, t[c.size]), lines.number()};
}

// The line after an "ITEM:" line, which must exist.
void value_line(LineReader& lines, std::string_view item) {
  if (!lines.next()) {
    lines.fail(Kind::missing_item, "the file ends after " + detail::quote_text("ITEM: " + std::string(item)));
  }
}

}  // namespace

std::vector<Disk> read_lammps_dump(std::istream& in, std::string_view source_name,
                                   std::optional<std::int64_t> timestep) {
  LineReader lines(in, source_name);
  // The snapshot being read: its timestep and atom count, once given (plain values and flags:
  // GCC's -Wmaybe-uninitialized misreads optionals here).
  std::int64_t step = 0;
  std::uint64_t natoms = 0;
  bool have_step = false;
  bool have_natoms = false;
  std::optional<std::vector<Disk>> chosen;
  std::vector<std::int64_t> steps;
  // Each snapshot's timestep and the line of its 'ITEM: TIMESTEP': two of one timestep are refused,
  // whichever is asked for (which of them is meant is not the reader's guess).
  std::map<std::int64_t, std::size_t> step_lines;
  std::size_t step_line = 0;
  bool any = false;
  while (lines.next()) {
    any = true;
    const std::vector<std::string_view> t = detail::tokens(lines.text());
    if (t.empty()) {
      lines.fail(Kind::blank_line, "blank line (LAMMPS dumps have none)");
    }
    if (t[0] != "ITEM:" || t.size() < 2) {
      lines.fail(Kind::syntax, "expected an 'ITEM: ...' line, got " + detail::quote_text(lines.text()));
    }
    const std::string item(lines.text().substr(static_cast<std::size_t>(t[1].data() - lines.text().data())));
    if (item == "TIMESTEP") {
      step_line = lines.number();
      value_line(lines, item);
      const std::vector<std::string_view> v = detail::tokens(lines.text());
      if (v.size() != 1) {
        lines.fail(Kind::field_count, "expected the timestep, one whole number");
      }
      step = lines.integer_at(v[0], "the timestep");
      const auto [seen, first] = step_lines.emplace(step, step_line);
      if (!first) {
        lines.fail(Kind::duplicate_id,
                   "timestep " + std::to_string(step) + " given twice: the snapshots of lines " +
                       std::to_string(seen->second) + " and " + std::to_string(step_line) + " (keep one of them)",
                   lines.column_of(v[0]));
      }
      have_step = true;
      have_natoms = false;
    } else if (item == "NUMBER OF ATOMS") {
      value_line(lines, item);
      const std::vector<std::string_view> v = detail::tokens(lines.text());
      if (v.size() != 1) {
        lines.fail(Kind::field_count, "expected the number of atoms, one whole number");
      }
      natoms = lines.count_at(v[0], "the number of atoms", kMaxAtoms);
      have_natoms = true;
    } else if (item.starts_with("BOX BOUNDS")) {
      for (int k = 0; k < 3; ++k) {
        value_line(lines, item);
        const std::vector<std::string_view> v = detail::tokens(lines.text());
        if (v.size() != 2 && v.size() != 3) {
          lines.fail(Kind::field_count, "expected 2 box bounds (or 3, triclinic), got " + std::to_string(v.size()));
        }
        for (const std::string_view b : v) {
          (void)lines.number_at(b, "box bound");
        }
      }
    } else if (item == "UNITS" || item == "TIME") {
      value_line(lines, item);
    } else if (t[1] == "ATOMS") {
      if (!have_step || !have_natoms) {
        lines.fail(Kind::missing_item, std::string("'ITEM: ATOMS' without a preceding 'ITEM: ") +
                                           (have_step ? "NUMBER OF ATOMS'" : "TIMESTEP'") + " in its snapshot");
      }
      const Columns c = columns(lines, t);
      const std::size_t header = lines.number();
      std::vector<detail::Atom> atoms;
      for (std::uint64_t k = 0; k < natoms; ++k) {
        if (!lines.next()) {
          lines.fail(Kind::count_mismatch, "the snapshot of timestep " + std::to_string(step) + " (ATOMS on line " +
                                               std::to_string(header) + ") ends after " + std::to_string(k) +
                                               " of its " + std::to_string(natoms) + " atoms");
        }
        atoms.push_back(atom_line(lines, c));
      }
      std::vector<Disk> disks = detail::disks_by_id(std::move(atoms), lines.source());
      steps.push_back(step);
      if (!timestep || *timestep == step) {
        chosen = std::move(disks);
      }
      have_step = have_natoms = false;
    } else {
      lines.fail(Kind::syntax, "unknown item " + detail::quote_text(lines.text()) +
                                   " (expected TIMESTEP, NUMBER OF ATOMS, BOX BOUNDS, ATOMS, UNITS or TIME)");
    }
  }
  if (!any) {
    lines.fail(Kind::empty_file, "empty file (expected a LAMMPS dump: 'ITEM: TIMESTEP', ...)");
  }
  if (have_step || have_natoms) {
    lines.fail(Kind::missing_item, "the last snapshot has no 'ITEM: ATOMS' section (a truncated dump?)");
  }
  if (!chosen) {
    if (!timestep) {
      lines.fail(Kind::missing_item, "no snapshot (no 'ITEM: ATOMS' section)");
    }
    std::string list;
    for (std::size_t i = 0; i < steps.size() && i < 10; ++i) {
      list += (i > 0 ? ", " : "") + std::to_string(steps[i]);
    }
    lines.fail(Kind::missing_item,
               "no snapshot of timestep " + std::to_string(*timestep) + " (the dump has " +
                   std::to_string(steps.size()) + (steps.size() == 1 ? " snapshot" : " snapshots") +
                   (steps.empty() ? "" : ": timesteps " + list + (steps.size() > 10 ? ", ..." : "")) + ")");
  }
  return std::move(*chosen);
}

}  // namespace frontpack
