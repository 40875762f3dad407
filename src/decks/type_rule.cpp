// Type rules: parsing "size:..." and "region:...", and assigning one type per disk.
#include <cmath>
#include <string>

#include "common/format.hpp"
#include "common/numbers.hpp"
#include "common/text.hpp"
#include "frontpack/types.hpp"

namespace frontpack {

namespace {

constexpr const char* kForms = "expected size:E1,E2,... (radius bin edges) or region:A.wkt,B.wkt,... (WKT files)";

std::string quoted(std::string_view s) {
  return detail::quote_text(s);
}

}  // namespace

std::uint32_t TypeRule::count() const noexcept {
  switch (kind) {
    case Kind::none: return 1;
    case Kind::size: return static_cast<std::uint32_t>(edges.size() + 1);
    case Kind::region: return static_cast<std::uint32_t>(regions.size() + 1);
  }
  return 1;
}

TypeRule size_types(std::vector<double> edges) {
  if (edges.empty()) {
    throw OptionError("type rule size: needs at least one radius bin edge, e.g. size:0.008,0.012");
  }
  for (std::size_t k = 0; k < edges.size(); ++k) {
    if (!(std::isfinite(edges[k]) && edges[k] > 0)) {
      throw OptionError("type rule size: edge " + std::to_string(k + 1) + " (" + detail::format_double(edges[k]) +
                        ") must be a finite radius > 0");
    }
    if (k > 0 && !(edges[k - 1] < edges[k])) {
      throw OptionError("type rule size: edges must increase strictly, but edge " + std::to_string(k + 1) + " (" +
                        detail::format_double(edges[k]) + ") follows " + detail::format_double(edges[k - 1]));
    }
  }
  TypeRule rule;
  rule.kind = TypeRule::Kind::size;
  rule.edges = std::move(edges);
  return rule;
}

TypeRule parse_type_rule(std::string_view spec) {
  const std::size_t colon = spec.find(':');
  const std::string_view kind = spec.substr(0, colon);
  if (colon == std::string_view::npos || (kind != "size" && kind != "region")) {
    throw OptionError("type rule " + quoted(spec) + ": " + kForms);
  }
  const std::string_view list = spec.substr(colon + 1);
  std::vector<std::string_view> items = detail::split(list, ',');
  for (std::size_t k = 0; k < items.size(); ++k) {
    if (items[k].empty()) {
      throw OptionError("type rule " + quoted(spec) + ": item " + std::to_string(k + 1) + " is empty; " + kForms);
    }
  }
  if (kind == "size") {
    std::vector<double> edges;
    for (const std::string_view item : items) {
      const detail::Decimal d = detail::parse_decimal(item);
      if (d.status == detail::DecimalStatus::overflow || d.status == detail::DecimalStatus::underflow) {
        throw OptionError("type rule " + quoted(spec) + ": edge " + detail::out_of_range(item, d.status));
      }
      if (d.status != detail::DecimalStatus::ok) {
        throw OptionError("type rule " + quoted(spec) + ": edge " + quoted(item) + " is not a number");
      }
      edges.push_back(d.value);
    }
    return size_types(std::move(edges));
  }
  TypeRule rule;
  rule.kind = TypeRule::Kind::region;
  for (const std::string_view item : items) {
    rule.regions.push_back(Domain::from_wkt_file(std::string(item)));
    rule.region_names.emplace_back(item);
  }
  return rule;
}

std::vector<std::uint32_t> assign_types(const TypeRule& rule, std::span<const Disk> disks) {
  std::vector<std::uint32_t> types(disks.size(), 1);
  for (std::size_t i = 0; i < disks.size(); ++i) {
    const Disk& d = disks[i];
    if (rule.kind == TypeRule::Kind::size) {
      std::uint32_t t = 1;
      for (const double e : rule.edges) {
        t += e <= d.radius ? 1 : 0;
      }
      types[i] = t;
    } else if (rule.kind == TypeRule::Kind::region) {
      for (std::size_t k = 0; k < rule.regions.size(); ++k) {
        if (rule.regions[k].locate(d.centre) != Location::outside) {
          types[i] = static_cast<std::uint32_t>(k + 2);
          break;
        }
      }
    }
  }
  return types;
}

}  // namespace frontpack
