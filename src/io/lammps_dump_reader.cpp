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

// The dump's snapshots, read item by item; the one asked for (the last one without a timestep)
// is kept.
class DumpReader {
 public:
  DumpReader(std::istream& in, std::string_view source_name, std::optional<std::int64_t> timestep)
      : lines_(in, source_name), timestep_(timestep) {}

  std::vector<Disk> read() {
    bool any = false;
    while (lines_.next()) {
      any = true;
      item();
    }
    if (!any) {
      lines_.fail(Kind::empty_file, "empty file (expected a LAMMPS dump: 'ITEM: TIMESTEP', ...)");
    }
    if (have_step_ || have_natoms_) {
      lines_.fail(Kind::missing_item, "the last snapshot has no 'ITEM: ATOMS' section (a truncated dump?)");
    }
    if (!chosen_) {
      fail_no_snapshot();
    }
    return std::move(*chosen_);
  }

 private:
  // An "ITEM: ..." line and the lines of its values.
  void item() {
    const std::vector<std::string_view> t = detail::tokens(lines_.text());
    if (t.empty()) {
      lines_.fail(Kind::blank_line, "blank line (LAMMPS dumps have none)");
    }
    if (t[0] != "ITEM:" || t.size() < 2) {
      lines_.fail(Kind::syntax, "expected an 'ITEM: ...' line, got " + detail::quote_text(lines_.text()));
    }
    const std::string item(lines_.text().substr(static_cast<std::size_t>(t[1].data() - lines_.text().data())));
    if (item == "TIMESTEP") {
      timestep_item(item);
    } else if (item == "NUMBER OF ATOMS") {
      value_line(lines_, item);
      const std::vector<std::string_view> v = detail::tokens(lines_.text());
      if (v.size() != 1) {
        lines_.fail(Kind::field_count, "expected the number of atoms, one whole number");
      }
      natoms_ = lines_.count_at(v[0], "the number of atoms", kMaxAtoms);
      have_natoms_ = true;
    } else if (item.starts_with("BOX BOUNDS")) {
      box_bounds_item(item);
    } else if (item == "UNITS" || item == "TIME") {
      value_line(lines_, item);
    } else if (t[1] == "ATOMS") {
      atoms_item(t);
    } else {
      lines_.fail(Kind::syntax, "unknown item " + detail::quote_text(lines_.text()) +
                                    " (expected TIMESTEP, NUMBER OF ATOMS, BOX BOUNDS, ATOMS, UNITS or TIME)");
    }
  }

  // A snapshot's timestep: two snapshots of one timestep are refused, whichever is asked for
  // (which of them is meant is not the reader's guess).
  void timestep_item(const std::string& item) {
    const std::size_t step_line = lines_.number();
    value_line(lines_, item);
    const std::vector<std::string_view> v = detail::tokens(lines_.text());
    if (v.size() != 1) {
      lines_.fail(Kind::field_count, "expected the timestep, one whole number");
    }
    step_ = lines_.integer_at(v[0], "the timestep");
    const auto [seen, first] = step_lines_.emplace(step_, step_line);
    if (!first) {
      lines_.fail(Kind::duplicate_id,
                  "timestep " + std::to_string(step_) + " given twice: the snapshots of lines " +
                      std::to_string(seen->second) + " and " + std::to_string(step_line) + " (keep one of them)",
                  lines_.column_of(v[0]));
    }
    have_step_ = true;
    have_natoms_ = false;
  }

  // The box's three lines of bounds: checked as numbers, not used.
  void box_bounds_item(const std::string& item) {
    for (int k = 0; k < 3; ++k) {
      value_line(lines_, item);
      const std::vector<std::string_view> v = detail::tokens(lines_.text());
      if (v.size() != 2 && v.size() != 3) {
        lines_.fail(Kind::field_count, "expected 2 box bounds (or 3, triclinic), got " + std::to_string(v.size()));
      }
      for (const std::string_view b : v) {
        (void)lines_.number_at(b, "box bound");
      }
    }
  }

  // The snapshot's atoms, as many as it said, after its timestep and atom count.
  void atoms_item(const std::vector<std::string_view>& t) {
    if (!have_step_ || !have_natoms_) {
      lines_.fail(Kind::missing_item, std::string("'ITEM: ATOMS' without a preceding 'ITEM: ") +
                                          (have_step_ ? "NUMBER OF ATOMS'" : "TIMESTEP'") + " in its snapshot");
    }
    const Columns c = columns(lines_, t);
    const std::size_t header = lines_.number();
    std::vector<detail::Atom> atoms;
    for (std::uint64_t k = 0; k < natoms_; ++k) {
      if (!lines_.next()) {
        lines_.fail(Kind::count_mismatch, "the snapshot of timestep " + std::to_string(step_) + " (ATOMS on line " +
                                              std::to_string(header) + ") ends after " + std::to_string(k) +
                                              " of its " + std::to_string(natoms_) + " atoms");
      }
      atoms.push_back(atom_line(lines_, c));
    }
    std::vector<Disk> disks = detail::disks_by_id(std::move(atoms), lines_.source());
    steps_.push_back(step_);
    if (!timestep_ || *timestep_ == step_) {
      chosen_ = std::move(disks);
    }
    have_step_ = have_natoms_ = false;
  }

  // No snapshot at all, or none of the timestep asked for: the first timesteps there are.
  [[noreturn]] void fail_no_snapshot() const {
    if (!timestep_) {
      lines_.fail(Kind::missing_item, "no snapshot (no 'ITEM: ATOMS' section)");
    }
    std::string list;
    for (std::size_t i = 0; i < steps_.size() && i < 10; ++i) {
      list += (i > 0 ? ", " : "") + std::to_string(steps_[i]);
    }
    lines_.fail(Kind::missing_item,
                "no snapshot of timestep " + std::to_string(*timestep_) + " (the dump has " +
                    std::to_string(steps_.size()) + (steps_.size() == 1 ? " snapshot" : " snapshots") +
                    (steps_.empty() ? "" : ": timesteps " + list + (steps_.size() > 10 ? ", ..." : "")) + ")");
  }

  LineReader lines_;
  std::optional<std::int64_t> timestep_;  // the one asked for
  // The snapshot being read: its timestep and atom count, once given (plain values and flags:
  // GCC's -Wmaybe-uninitialized misreads optionals here).
  std::int64_t step_ = 0;
  std::uint64_t natoms_ = 0;
  bool have_step_ = false;
  bool have_natoms_ = false;
  std::optional<std::vector<Disk>> chosen_;
  std::vector<std::int64_t> steps_;
  std::map<std::int64_t, std::size_t> step_lines_;  // each snapshot's timestep and its line
};

}  // namespace

std::vector<Disk> read_lammps_dump(std::istream& in, std::string_view source_name,
                                   std::optional<std::int64_t> timestep) {
  return DumpReader(in, source_name, timestep).read();
}

}  // namespace frontpack
