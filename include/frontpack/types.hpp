// frontpack: particle types, one per disk, assigned by a rule (by size class or by region).
//
//   const frontpack::TypeRule rule = frontpack::parse_type_rule("size:0.008,0.012");
//   const std::vector<std::uint32_t> types = frontpack::assign_types(rule, packing.disks);
//
// Types are 1-based, as LAMMPS atom types are: a rule with k classes or k regions gives types
// 1..k+1. The writers carry them (WriteOptions::types): a CSV "type" column, Yade's matId
// (type - 1, an index into O.materials), the LAMMPS type column, a VTP point-data array "type".
//
// Exactness: every decision is exact on the disks' doubles. A size class compares radii with the
// bin edges (doubles, so exact); a region decides with Domain::locate, exactly.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "frontpack/domain.hpp"
#include "frontpack/errors.hpp"
#include "frontpack/geometry.hpp"

namespace frontpack {

/// How disks get their types.
struct TypeRule {
  enum class Kind : std::uint8_t {
    none,    ///< every disk has type 1
    size,    ///< by radius: type 1 + the number of edges <= r (edges strictly increasing)
    region,  ///< by the centre: type k + 1 for the first region k (1-based) whose closure holds it, else 1
  };
  Kind kind = Kind::none;
  /// Kind::size: bin edges, finite, > 0, strictly increasing. A radius r gets type
  /// 1 + #{e in edges : e <= r}: with edges {a, b}, r < a is type 1, a <= r < b type 2, r >= b type 3.
  std::vector<double> edges{};
  /// Kind::region: the regions, in order. A centre "in" region k means Domain::locate(centre) is
  /// inside or boundary (the closed region, decided exactly); the first such region wins, so
  /// overlapping regions are allowed and the earlier one takes precedence.
  std::vector<Domain> regions{};
  /// Kind::region: the regions' names (files) for messages and summaries.
  std::vector<std::string> region_names{};

  /// The number of types the rule gives: edges.size() + 1, regions.size() + 1, or 1.
  [[nodiscard]] std::uint32_t count() const noexcept;
};

/// Parses a type rule: "size:E1,E2,..." (radius bin edges, finite, > 0, strictly increasing) or
/// "region:A.wkt,B.wkt,..." (WKT files, read with Domain::from_wkt_file). Throws OptionError naming
/// the rule and the offending part (a bad number, edges not increasing, an unknown kind); for a
/// region file, IoError, WktError or InvalidDomainError as from_wkt_file.
[[nodiscard]] TypeRule parse_type_rule(std::string_view spec);

/// A size rule from edges; throws OptionError as parse_type_rule.
[[nodiscard]] TypeRule size_types(std::vector<double> edges);

/// The type of each disk under `rule`: out[i] in [1, rule.count()].
[[nodiscard]] std::vector<std::uint32_t> assign_types(const TypeRule& rule, std::span<const Disk> disks);

}  // namespace frontpack
