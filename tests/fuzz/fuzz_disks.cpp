#include <cmath>
#include <cstring>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include "check.hpp"
#include "frontpack/errors.hpp"
#include "frontpack/io.hpp"
#include "fuzz_targets.hpp"

namespace frontpack::fuzz {

namespace {

bool same_bits(const std::vector<Disk>& a, const std::vector<Disk>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(Disk)) == 0);
}

// One reader on the text; what it accepts must be finite with positive radii, and must come
// back bit for bit through the matching writer (`write` returns false where the writer refuses
// the disks with an OptionError, e.g. a LAMMPS box beyond the doubles; nullptr: no writer).
template <class Read, class Write>
void one(const std::string& text, Read read, Write write) {
  std::vector<Disk> disks;
  try {
    std::istringstream in(text);
    disks = read(in, "fuzz");
  } catch (const Error& e) {
    check_message(e.what());
    return;  // DiskFileError (or another typed error): what bad input must get
  }
  for (const Disk& d : disks) {
    check(std::isfinite(d.centre.x) && std::isfinite(d.centre.y) && std::isfinite(d.radius) && d.radius > 0,
          "an accepted disk has finite coordinates and a positive radius");
  }
  if constexpr (!std::is_same_v<Write, std::nullptr_t>) {
    std::ostringstream out;
    if (write(out, disks)) {
      std::istringstream back(out.str());
      check(same_bits(read(back, "round trip"), disks), "what was read is written and read back bit for bit");
    }
  }
}

// The smallest box that holds every disk (x - r, x + r exact in that direction: write_lammps's
// own test), for a LAMMPS data file of what was read.
Box box_of(const std::vector<Disk>& disks) {
  Box b;
  for (const Disk& d : disks) {
    b.extend(Point{d.centre.x - d.radius, d.centre.y - d.radius});
    b.extend(Point{d.centre.x + d.radius, d.centre.y + d.radius});
  }
  return b.empty() ? Box{0, 0, 1, 1} : b;
}

}  // namespace

void disks(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  one(
      text, [](std::istream& in, const char* name) { return read_lammps(in, name); },
      [](std::ostream& out, const std::vector<Disk>& d) {
        try {
          write_lammps(out, d, box_of(d));
          return true;
        } catch (const OptionError&) {
          return false;
        }
      });
  one(
      text, [](std::istream& in, const char* name) { return read_vtp(in, name); },
      [](std::ostream& out, const std::vector<Disk>& d) {
        write_vtp(out, d);
        return true;
      });
  one(
      text, [](std::istream& in, const char* name) { return read_lammps_dump(in, name); }, nullptr);
  one(
      text, [](std::istream& in, const char* name) { return read_csv(in, name); },
      [](std::ostream& out, const std::vector<Disk>& d) {
        write_csv(out, d);
        return true;
      });
  one(
      text, [](std::istream& in, const char* name) { return read_yade(in, name); },
      [](std::ostream& out, const std::vector<Disk>& d) {
        write_yade(out, d);
        return true;
      });
}

}  // namespace frontpack::fuzz
