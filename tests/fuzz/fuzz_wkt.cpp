#include <cmath>
#include <optional>
#include <string_view>

#include "check.hpp"
#include "frontpack/domain.hpp"
#include "frontpack/errors.hpp"
#include "fuzz_targets.hpp"

namespace frontpack::fuzz {

namespace {

bool same_polygons(const std::vector<Polygon>& a, const std::vector<Polygon>& b) {
  if (a.size() != b.size()) {
    return false;
  }
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i].outer != b[i].outer || a[i].holes != b[i].holes) {
      return false;
    }
  }
  return true;
}

}  // namespace

void wkt(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  std::optional<Domain> parsed;
  try {
    parsed.emplace(Domain::from_wkt(text));
  } catch (const Error& e) {
    check_message(e.what());
    return;  // a clear, typed error: what bad input must get
  }
  const Domain& domain = *parsed;
  check_accepted_domain(domain);
  const Domain again = Domain::from_wkt(domain.to_wkt());
  check(same_polygons(again.polygons(), domain.polygons()), "to_wkt round-trips exactly");
  // The box's corners are never strictly inside (the domain touches its box from inside).
  const Box b = domain.bbox();
  check(domain.locate({b.xmin, b.ymin}) != Location::inside, "a box corner is not inside");
  (void)domain.locate({(b.xmin + b.xmax) / 2, (b.ymin + b.ymax) / 2});
}

}  // namespace frontpack::fuzz
