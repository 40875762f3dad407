#include <cmath>
#include <cstring>
#include <sstream>
#include <string>
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
// back bit for bit through the matching writer.
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
  std::ostringstream out;
  write(out, disks);
  std::istringstream back(out.str());
  check(same_bits(read(back, "round trip"), disks), "what was read is written and read back bit for bit");
}

}  // namespace

void disks(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  one(
      text, [](std::istream& in, const char* name) { return read_csv(in, name); },
      [](std::ostream& out, const std::vector<Disk>& d) { write_csv(out, d); });
  one(
      text, [](std::istream& in, const char* name) { return read_yade(in, name); },
      [](std::ostream& out, const std::vector<Disk>& d) { write_yade(out, d); });
}

}  // namespace frontpack::fuzz
