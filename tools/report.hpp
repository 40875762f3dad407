// What the tool prints and writes as JSON about domains, packings and statistics, and the
// progress bar of long runs.
#pragma once

#include <chrono>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "frontpack/domain.hpp"
#include "frontpack/fill.hpp"
#include "frontpack/stats.hpp"
#include "json_fields.hpp"

namespace frontpack_tool {

using Json = nlohmann::ordered_json;
using Clock = std::chrono::steady_clock;

[[nodiscard]] double seconds_since(Clock::time_point t0);
/// 10 significant digits.
[[nodiscard]] std::string fmt(double v);
/// 4 decimals.
[[nodiscard]] std::string fmt4(double v);

[[nodiscard]] Json domain_json(const std::string& source, const frontpack::Domain& domain);
/// The statistics, one key per PackingStats field (json_fields.hpp), with "largest_empty_circle"
/// only when computed, the request's comparison only with a request, and the band's figures null
/// without walls.
[[nodiscard]] Json stats_json(const frontpack::PackingStats& s);
/// The text report's lines for the same measures ("empty circle: ...", "holes: ...", ...).
[[nodiscard]] std::vector<std::string> void_lines(const frontpack::PackingStats& s);
/// "0.8123 overall, 0.8300 interior (+/- 0.0010, farther than 0.1 from the boundary), ..."
[[nodiscard]] std::string fraction_line(const frontpack::PackingStats& s);
/// "min 0.01, mean 0.03, max 0.05, sd ..., median by area ..."
[[nodiscard]] std::string radii_line(const frontpack::SizeStats& s);
/// The certificate with "certified": true.
[[nodiscard]] Json certificate_json(const frontpack::Certificate& c);
/// The fill's counters and timings: {"generation": {...}, "jam": {...} (only when jammed), "seconds": {...}}.
[[nodiscard]] Json fill_stats_json(const frontpack::FillStats& stats, bool jam);
/// certify()'s report, with "outside" and "overlapping_pairs" the counts.
[[nodiscard]] Json certify_json(const frontpack::CertifyReport& r);
/// A fill to a fraction, count or level (Packing::target): what was asked and what was reached.
[[nodiscard]] Json target_json(const frontpack::TargetReport& t);
/// "fraction 0.7000 asked, 0.6999 reached (dense 0.8305; radii filled 1.0801x then shrunk back, 51 disks
/// thinned; 3 fills)", ", below y = H (area A)" with a level.
[[nodiscard]] std::string target_line(const frontpack::TargetReport& t);

}  // namespace frontpack_tool
