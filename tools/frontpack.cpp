// The frontpack command-line tool. It maps library errors to messages and exit codes; the
// library itself never prints.
//
// Exit codes (also in `frontpack --help` and the README):
//   0 success, 1 usage error (unknown option, missing argument, a file given for two uses),
//   2 unreadable input or unwritable output file, 3 WKT syntax or unsupported geometry, 4 invalid
//   domain, 5 invalid option (radius, method, format, width, seed, limit), 6 packing not certified
//   (check: overlaps or disks outside), 7 malformed disk file, 8 no disk fits (fill: nothing
//   written), 9 stopped at --max-disks (fill: the certified partial packing is written),
//   70 internal error, 128 + N stopped by signal N (130 SIGINT, 143 SIGTERM, 129 SIGHUP; nothing
//   written).
//
// Files (tools/outputs.hpp): outputs are written to temporary files and committed together at
// the end, so a failed or interrupted run leaves every file as it was; /dev/stdout, devices and
// FIFOs are written through; a file given for two uses is refused before any work.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <iostream>
#include <limits>
#include <numbers>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

#include "frontpack/frontpack.hpp"
#include "outputs.hpp"
#include "render.hpp"
#include "report.hpp"
#include "signals.hpp"

namespace {

using frontpack_tool::Clock;
using frontpack_tool::fmt;
using frontpack_tool::fmt4;
using frontpack_tool::Json;
using frontpack_tool::seconds_since;

enum Exit : int {
  ok = 0,
  usage = 1,
  io = 2,
  wkt = 3,
  invalid_domain = 4,
  bad_option = 5,
  not_certified = 6,
  bad_disk_file = 7,
  nothing_fits = 8,
  max_disks_reached = 9,
  internal = 70,
};

constexpr const char* kExitCodes =
    "Exit codes: 0 success, 1 usage error, 2 unreadable input or unwritable output, 3 WKT syntax or\n"
    "unsupported geometry, 4 invalid domain, 5 invalid option (radius, method, format, width, seed,\n"
    "limit), 6 packing not certified (check), 7 malformed disk file, 8 no disk fits (fill), 9 stopped\n"
    "at --max-disks (fill; the partial packing is written), 70 internal error, 130/143/129 stopped\n"
    "by SIGINT/SIGTERM/SIGHUP.\n"
    "Outputs are written to temporary files and renamed together at the end: a failed or interrupted\n"
    "run leaves every file as it was. /dev/stdout, devices and FIFOs are written through.";

// The one signal watcher of the process (made first in main, before any other thread).
frontpack_tool::SignalWatch* g_signals = nullptr;

std::stop_token stop_token() {
  return g_signals != nullptr ? g_signals->token() : std::stop_token{};
}

// A whole number for OPTION, in [0, max]: digits only (no sign, no exponent, no fraction), so
// that "-1" or "1e23" is refused rather than wrapped or truncated. Throws OptionError naming the
// option and the text given.
std::uint64_t parse_count(const char* option, const std::string& text, std::uint64_t max) {
  std::uint64_t value = 0;
  const char* first = text.data();
  const char* last = text.data() + text.size();
  const bool digits = !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
  const auto [end, ec] = digits ? std::from_chars(first, last, value) : std::from_chars_result{first, std::errc()};
  const std::string range = "a whole number from 0 to " + std::to_string(max);
  const std::string given = text.size() > 40 ? text.substr(0, 40) + "..." : text;
  if (!digits) {
    throw frontpack::OptionError(std::string(option) + " " + given + ": expected " + range +
                                 (text.empty() ? "" : " (digits only)"));
  }
  if (ec == std::errc::result_out_of_range || end != last || value > max) {
    throw frontpack::OptionError(std::string(option) + " " + given + ": too large; expected " + range);
  }
  return value;
}

// ---------------------------------------------------------------------------------------------
// Inputs.

struct DomainSource {
  std::string file;
  std::string wkt;
  CLI::Option* wkt_option = nullptr;
  [[nodiscard]] bool from_text() const { return wkt_option != nullptr && wkt_option->count() > 0; }
  [[nodiscard]] std::string name() const { return from_text() ? std::string("--wkt") : file; }
};

void add_domain_options(CLI::App& cmd, DomainSource& src) {
  auto* file = cmd.add_option("DOMAIN", src.file, "WKT file with a POLYGON or MULTIPOLYGON");
  src.wkt_option = cmd.add_option("--wkt", src.wkt, "the domain as WKT text instead of a file");
  file->excludes(src.wkt_option);
  src.wkt_option->excludes(file);
}

frontpack::Domain load(const DomainSource& src) {
  if (src.from_text()) {
    if (src.wkt.find_first_not_of(" \t\r\n") == std::string::npos) {
      throw frontpack::WktError(frontpack::WktError::Kind::empty_geometry,
                                "the WKT text given with --wkt is empty; expected a POLYGON or MULTIPOLYGON", 0, 1, 1,
                                "--wkt");
    }
    return frontpack::Domain::from_wkt(src.wkt);
  }
  if (src.file.empty()) {
    throw CLI::RequiredError("DOMAIN or --wkt");
  }
  return frontpack::Domain::from_wkt_file(src.file);
}

std::vector<frontpack_tool::FileUse> domain_inputs(const DomainSource& src) {
  if (src.from_text() || src.file.empty()) {
    return {};
  }
  return {{"DOMAIN", src.file}};
}

std::vector<frontpack_tool::FileUse> output_uses(const std::vector<frontpack_tool::Output>& outputs,
                                                 const std::string& json) {
  std::vector<frontpack_tool::FileUse> uses;
  for (const auto& o : outputs) {
    uses.push_back({"-o", o.path});
  }
  if (!json.empty()) {
    uses.push_back({"--json", json});
  }
  return uses;
}

// ---------------------------------------------------------------------------------------------
// info

int run_info(const DomainSource& src) {
  const frontpack::Domain domain = load(src);
  const frontpack::Box b = domain.bbox();
  std::cout << "domain:     " << src.name() << "\n"
            << "polygons:   " << domain.num_polygons() << "\n"
            << "holes:      " << domain.num_holes() << "\n"
            << "vertices:   " << domain.num_vertices() << "\n"
            << "area:       " << fmt(domain.area()) << "\n"
            << "perimeter:  " << fmt(domain.perimeter()) << "\n"
            << "bbox:       [" << fmt(b.xmin) << ", " << fmt(b.xmax) << "] x [" << fmt(b.ymin) << ", " << fmt(b.ymax)
            << "]\n"
            << "valid:      yes (OGC simple features, decided exactly)\n";
  return ok;
}

// ---------------------------------------------------------------------------------------------
// fill

constexpr const char* kDefaultRadius = frontpack::default_radius_spec;

// --memory-limit: bytes, with an optional suffix K, M, G or T (powers of 1024: 512M, 2G); 0 leaves
// the library's default (three quarters of the machine's memory).
std::size_t parse_bytes(const char* option, const std::string& text) {
  std::size_t digits = 0;
  while (digits < text.size() && text[digits] >= '0' && text[digits] <= '9') {
    ++digits;
  }
  int shift = -1;
  if (digits == text.size()) {
    shift = 0;
  } else if (digits + 1 == text.size()) {
    const std::string units = "KMGT";
    const std::size_t u = units.find(static_cast<char>(std::toupper(static_cast<unsigned char>(text.back()))));
    shift = u == std::string::npos ? -1 : 10 * static_cast<int>(u + 1);
  }
  const std::string given = text.size() > 40 ? text.substr(0, 40) + "..." : text;
  if (digits == 0 || shift < 0) {
    throw frontpack::OptionError(std::string(option) + " '" + given +
                                 "': expected a number of bytes, with an optional suffix K, M, G or T (powers of "
                                 "1024), e.g. 512M or 2G; 0 for three quarters of the machine's memory");
  }
  std::uint64_t value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + digits, value);
  (void)end;
  if (ec != std::errc{} || value > (std::numeric_limits<std::size_t>::max() >> shift)) {
    throw frontpack::OptionError(std::string(option) + " '" + given + "': too large");
  }
  return static_cast<std::size_t>(value) << shift;
}

struct FillArgs {
  DomainSource src;
  std::string method = frontpack::to_string(frontpack::FillOptions{}.method);
  std::string radius;  // empty: kDefaultRadius
  std::string seed = "0";
  std::string max_disks = std::to_string(frontpack::FillOptions{}.max_disks);
  std::string memory_limit = "0";
  std::vector<std::string> outputs;
  std::string format;
  std::string json;
  int width = 1200;
  bool no_histogram = false;
  bool quiet = false;
};

frontpack::Method parse_method(const std::string& name) {
  if (name == "closed") {
    return frontpack::Method::closed;
  }
  if (name == "open") {
    return frontpack::Method::open;
  }
  if (name == "boundary") {
    return frontpack::Method::boundary;
  }
  throw frontpack::OptionError(std::string("--method ") + name + ": expected closed, open or boundary");
}

// The file a `curve:FILE` radius spec reads, as an input that no output may overwrite.
void add_curve_input(const std::string& spec, std::vector<frontpack_tool::FileUse>& inputs) {
  constexpr std::string_view kCurve = "curve:";
  if (spec.compare(0, kCurve.size(), kCurve) == 0) {
    inputs.push_back({"--radius curve:FILE", spec.substr(kCurve.size())});
  }
}

Json fill_json(const FillArgs& a, const std::string& spec, const frontpack::FillOptions& options,
               const frontpack::Domain& domain, const frontpack::Packing& p, const frontpack::PackingStats& s,
               const std::vector<frontpack_tool::Output>& outputs, double seconds_stats, double seconds_total) {
  const frontpack::Certificate& c = p.certificate;
  Json outs = Json::array();
  for (const auto& o : outputs) {
    outs.push_back(Json{{"path", o.path.string()}, {"format", frontpack_tool::format_name(o.format)}});
  }
  Json j{{"frontpack_version", frontpack::version_string},
         {"command", "fill"},
         {"domain", frontpack_tool::domain_json(a.src.name(), domain)},
         {"method", frontpack::to_string(options.method)},
         {"radius_spec", spec},
         {"radius_spec_given", !a.radius.empty()},
         {"radius_distribution", options.radii.describe()},
         {"seed", options.seed},
         {"disks", p.disks.size()},
         {"truncated", p.truncated}};
  j.update(frontpack_tool::stats_json(s));
  j["certificate"] = Json{{"certified", true},
                          {"generated", c.generated},
                          {"culled", c.culled},
                          {"dropped", c.dropped},
                          {"candidate_pairs", c.candidate_pairs},
                          {"exact", c.exact}};
  j["seconds"] = Json{{"front", p.stats.seconds_front},
                      {"cull", p.stats.seconds_cull},
                      {"overlap_pass", p.stats.seconds_overlap},
                      {"statistics", seconds_stats},
                      {"total", seconds_total}};
  j["outputs"] = outs;
  return j;
}

// Why a fill placed no disk. A disk of radius r inside the domain lies in one polygon's bounding
// box and has area pi r^2 at most the domain's: r <= min(sqrt(area / pi), the largest polygon box's
// half-side), a cheap bound that is exact for rectangles and corridors.
std::string why_no_disk(const frontpack::Domain& domain, const frontpack::FillOptions& options, const std::string& spec,
                        std::size_t generated) {
  double half_side = 0;
  for (std::size_t k = 0; k < domain.num_polygons(); ++k) {
    const frontpack::Box b = domain.bbox(k);
    half_side = std::max(half_side, 0.5 * std::min(b.width(), b.height()));
  }
  const double bound = std::min(std::sqrt(domain.area() / std::numbers::pi), half_side);
  const double rmin = options.radii.min();
  if (rmin > bound) {
    return "no disk fits: the smallest radius of " + spec + " is " + fmt(rmin) + ", and no disk of radius above " +
           fmt(bound) + " fits in this domain; use smaller radii";
  }
  return std::string("no disk was placed: the ") + frontpack::to_string(options.method) + " form generated " +
         std::to_string(generated) + (generated == 1 ? " disk" : " disks") +
         " and none lay inside the domain; use smaller radii" +
         (options.method == frontpack::Method::boundary ? "" : " or --method boundary");
}

int run_fill(const FillArgs& a) {
  const auto t_start = Clock::now();
  const std::string spec = a.radius.empty() ? std::string(kDefaultRadius) : a.radius;
  frontpack::FillOptions options;
  options.method = parse_method(a.method);
  options.radii = frontpack::parse_radii(spec);
  options.seed = parse_count("--seed", a.seed, std::numeric_limits<std::uint64_t>::max());
  options.max_disks = parse_count("--max-disks", a.max_disks, std::numeric_limits<std::uint64_t>::max());
  options.memory_limit = parse_bytes("--memory-limit", a.memory_limit);
  options.stop = stop_token();
  const std::vector<frontpack_tool::Output> outputs = frontpack_tool::resolve_outputs(a.outputs, a.format, false);
  std::vector<frontpack_tool::FileUse> inputs = domain_inputs(a.src);
  add_curve_input(spec, inputs);
  frontpack_tool::check_files(inputs, output_uses(outputs, a.json));
  const frontpack::Domain domain = load(a.src);

  frontpack::Packing p;
  {
    frontpack_tool::ProgressBar bar(!a.quiet);
    frontpack::Generator generator(domain, options);
    generator.on_progress([&bar](const frontpack::Progress& progress) {
      bar.update(progress);
      return true;
    });
    p = generator.run();
  }
  if (p.disks.empty()) {
    std::cerr << "frontpack: " << why_no_disk(domain, options, spec, p.certificate.generated) << "; nothing written\n";
    return nothing_fits;
  }

  // Statistics only where they are shown or written.
  const auto t_stats = Clock::now();
  frontpack::PackingStats s;
  if (!a.quiet || !a.json.empty()) {
    s = frontpack::measure(domain, p.disks, {.requested = options.radii, .stop = options.stop});
  }
  const double seconds_stats = seconds_since(t_stats);

  frontpack_tool::PendingOutputs pending;
  const frontpack_tool::RenderOptions picture{.width_px = a.width,
                                              .histogram = !a.no_histogram,
                                              .requested = options.radii,
                                              .requested_spec = spec,
                                              .stop = options.stop};
  for (const auto& o : outputs) {
    pending.write(o, domain, p.disks, picture, options.stop);
  }
  if (!a.json.empty()) {
    const Json j = fill_json(a, spec, options, domain, p, s, outputs, seconds_stats, seconds_since(t_start));
    pending.write_text(a.json, j.dump(2) + "\n");
  }
  pending.commit_all(options.stop);

  if (!a.quiet) {
    const frontpack::Certificate& c = p.certificate;
    const double seconds_fill = p.stats.seconds_front + p.stats.seconds_cull + p.stats.seconds_overlap;
    std::cerr << "disks:       " << p.disks.size() << " (" << frontpack::to_string(options.method) << " form, seed "
              << options.seed << (p.truncated ? ", truncated at --max-disks" : "") << ")\n"
              << "radius:      " << spec << (a.radius.empty() ? " (the default; set with --radius)" : "") << "\n"
              << "fraction:    " << frontpack_tool::fraction_line(s) << "\n"
              << "radii:       " << frontpack_tool::radii_line(s.sizes) << "\n"
              << "certificate: " << (c.dropped == 0 ? "certified" : "certified after repair") << ": " << c.generated
              << " generated, " << c.culled << " culled (not inside), " << c.dropped
              << " dropped (overlap); every decision exact\n"
              << "time:        " << fmt(seconds_fill) << " s (front " << fmt(p.stats.seconds_front) << ", cull "
              << fmt(p.stats.seconds_cull) << ", overlap pass " << fmt(p.stats.seconds_overlap) << "), statistics "
              << fmt(seconds_stats) << " s\n";
    for (const auto& o : outputs) {
      std::cerr << "wrote:       " << o.path.string() << " (" << frontpack_tool::format_name(o.format) << ")\n";
    }
    if (!a.json.empty()) {
      std::cerr << "wrote:       " << a.json << " (summary)\n";
    }
  }
  if (p.truncated) {
    std::cerr << "frontpack: stopped at --max-disks " << options.max_disks << ": the packing written ("
              << p.disks.size() << (p.disks.size() == 1 ? " disk" : " disks")
              << ", certified) does not fill the domain\n";
    return max_disks_reached;
  }
  return ok;
}

// ---------------------------------------------------------------------------------------------
// check

struct CheckArgs {
  std::string domain;
  std::string disks;
  std::string json;
  bool all = false;
  bool quiet = false;
};

std::string disk_text(const frontpack::Disk& d) {
  return std::string("centre (") + fmt(d.centre.x) + ", " + fmt(d.centre.y) + "), radius " + fmt(d.radius);
}

int run_check(const CheckArgs& a) {
  frontpack_tool::check_files({{"DOMAIN", a.domain}, {"DISKS", a.disks}}, output_uses({}, a.json));
  const frontpack::Domain domain = frontpack::Domain::from_wkt_file(a.domain);
  const std::vector<frontpack::Disk> disks = frontpack::read_disks(a.disks);
  const frontpack::CertifyReport r = frontpack::certify(domain, disks, stop_token());
  const bool certified = r.outside.empty() && r.overlapping.empty();

  std::ostringstream out;
  out << "domain:      " << a.domain << " (area " << fmt(domain.area()) << ")\n"
      << "disks:       " << disks.size() << " in " << a.disks << " (numbered from 0 in file order)\n";
  out << "outside:     " << r.outside.size() << (r.outside.size() == 1 ? " disk" : " disks")
      << " not entirely inside the domain";
  if (r.farthest_outside) {
    const std::size_t i = *r.farthest_outside;
    out << "; worst: disk " << i << " (" << disk_text(disks[i]) << ") reaches about " << fmt(r.farthest_outside_by)
        << " out of the domain";
  }
  out << "\n";
  out << "overlaps:    " << r.overlapping.size() << (r.overlapping.size() == 1 ? " pair" : " pairs")
      << " of overlapping disks";
  if (r.deepest_overlap) {
    const auto [i, j] = *r.deepest_overlap;
    out << "; worst: disks " << i << " and " << j << " overlap by about " << fmt(r.deepest_overlap_depth)
        << " (r_i + r_j - distance)";
  }
  out << "\n";
  if (!certified) {
    out << "             (which disks are outside and which pairs overlap is decided exactly; the 'about' "
           "figures are floating point)\n";
  }
  if (a.all) {
    for (const std::size_t i : r.outside) {
      out << "outside " << i << ": " << disk_text(disks[i]) << "\n";
    }
    for (const auto& [i, j] : r.overlapping) {
      out << "overlap " << i << " " << j << "\n";
    }
  }
  out << "result:      "
      << (certified ? "certified: no two disks overlap and every disk lies in the domain" : "NOT certified") << " ("
      << r.certificate.candidate_pairs << " candidate pairs, every decision exact)\n";
  frontpack_tool::PendingOutputs pending;
  if (!a.json.empty()) {
    Json j{{"frontpack_version", frontpack::version_string},
           {"command", "check"},
           {"domain", a.domain},
           {"disk_file", a.disks},
           {"disks", disks.size()},
           {"certified", certified},
           {"outside", r.outside.size()},
           {"overlapping_pairs", r.overlapping.size()},
           {"candidate_pairs", r.certificate.candidate_pairs}};
    if (r.farthest_outside) {
      j["farthest_outside"] =
          Json{{"disk", *r.farthest_outside},
               {"by", std::isfinite(r.farthest_outside_by) ? Json(r.farthest_outside_by) : Json(nullptr)}};
    }
    if (r.deepest_overlap) {
      j["deepest_overlap"] =
          Json{{"disks", {r.deepest_overlap->first, r.deepest_overlap->second}}, {"depth", r.deepest_overlap_depth}};
    }
    pending.write_text(a.json, j.dump(2) + "\n");
  }
  pending.commit_all(stop_token());
  if (!a.quiet) {
    std::cout << out.str();
  }
  if (!certified) {
    std::cerr << "frontpack: " << a.disks << " is not certified: " << r.overlapping.size() << " overlapping "
              << (r.overlapping.size() == 1 ? "pair" : "pairs") << ", " << r.outside.size()
              << (r.outside.size() == 1 ? " disk" : " disks") << " outside the domain\n";
    return not_certified;
  }
  return ok;
}

// ---------------------------------------------------------------------------------------------
// render

struct RenderArgs {
  std::string domain;
  std::string disks;
  std::vector<std::string> outputs;
  std::string format;
  std::string radius;
  int width = 1200;
  bool no_histogram = false;
  bool quiet = false;
};

int run_render(const RenderArgs& a) {
  frontpack_tool::RenderOptions picture;
  picture.width_px = a.width;
  picture.histogram = !a.no_histogram;
  if (!a.radius.empty()) {
    picture.requested = frontpack::parse_radii(a.radius);
    picture.requested_spec = a.radius;
  }
  const std::vector<frontpack_tool::Output> outputs = frontpack_tool::resolve_outputs(a.outputs, a.format, true);
  frontpack_tool::check_files({{"DOMAIN", a.domain}, {"DISKS", a.disks}}, output_uses(outputs, {}));
  const frontpack::Domain domain = frontpack::Domain::from_wkt_file(a.domain);
  const std::vector<frontpack::Disk> disks = frontpack::read_disks(a.disks);
  frontpack_tool::PendingOutputs pending;
  for (const auto& o : outputs) {
    pending.write(o, domain, disks, picture, stop_token());
  }
  pending.commit_all(stop_token());
  if (!a.quiet) {
    for (const auto& o : outputs) {
      std::cerr << "wrote:       " << o.path.string() << " (" << frontpack_tool::format_name(o.format) << ", "
                << a.width << " x " << frontpack_tool::picture_height(domain, a.width, picture.histogram) << ", "
                << disks.size() << " disks)\n";
    }
  }
  return ok;
}

// ---------------------------------------------------------------------------------------------
// stats

struct StatsArgs {
  std::string domain;
  std::string disks;
  std::string radius;
  std::string json;
  std::string samples = "1000000";
  bool quiet = false;
};

int run_stats(const StatsArgs& a) {
  frontpack::StatsOptions options;
  std::vector<frontpack_tool::FileUse> inputs{{"DOMAIN", a.domain}, {"DISKS", a.disks}};
  if (!a.radius.empty()) {
    options.requested = frontpack::parse_radii(a.radius);
    add_curve_input(a.radius, inputs);
  }
  options.samples = parse_count("--samples", a.samples, std::uint64_t{1} << 40);
  options.stop = stop_token();
  frontpack_tool::check_files(inputs, output_uses({}, a.json));
  const frontpack::Domain domain = frontpack::Domain::from_wkt_file(a.domain);
  const std::vector<frontpack::Disk> disks = frontpack::read_disks(a.disks);
  const frontpack::PackingStats s = frontpack::measure(domain, disks, options);
  if (!a.json.empty()) {
    Json j{{"frontpack_version", frontpack::version_string},
           {"command", "stats"},
           {"domain", frontpack_tool::domain_json(a.domain, domain)},
           {"disk_file", a.disks},
           {"disks", s.disks}};
    j.update(frontpack_tool::stats_json(s));
    frontpack_tool::PendingOutputs pending;
    pending.write_text(a.json, j.dump(2) + "\n");
    pending.commit_all(options.stop);
  }
  if (a.quiet) {
    return ok;
  }
  std::cout << "disks:        " << s.disks << " in " << a.disks << "\n"
            << "fraction:     " << frontpack_tool::fraction_line(s) << "\n"
            << "void ratio:   " << fmt(s.void_ratio) << "\n"
            << "radii:        " << frontpack_tool::radii_line(s.sizes) << "\n";
  if (s.sizes.compared) {
    std::cout << "requested:    " << s.sizes.requested << "\n"
              << "KS distance:  " << fmt4(s.sizes.ks_number) << " by number, " << fmt4(s.sizes.ks_area) << " by area\n";
  }
  std::cout << "coordination: " << fmt4(s.mean_coordination) << " mean, " << fmt4(s.interior_coordination)
            << " in the interior (" << s.interior_disks << " disks); " << s.contacts << " contacts, " << s.wall_contacts
            << " wall contacts, " << s.rattlers << " rattlers (gap <= " << fmt(s.contact_gap)
            << " counts as contact)\n";
  if (s.band_disks > 0 && s.band_disks < s.disks) {
    std::cout << "segregation:  median radius by area " << fmt(s.band_median_area) << " in the band (" << s.band_disks
              << " disks), " << fmt(s.inside_median_area) << " inside; KS by area " << fmt4(s.segregation_ks_area)
              << "\n";
  }
  return ok;
}

// ---------------------------------------------------------------------------------------------

// One exit code per kind of error (see the top of this file).
int exit_code(const std::exception& e) {
  if (dynamic_cast<const frontpack_tool::UsageError*>(&e) != nullptr) {
    return usage;
  }
  if (dynamic_cast<const frontpack::IoError*>(&e) != nullptr ||
      dynamic_cast<const std::filesystem::filesystem_error*>(&e) != nullptr) {
    return io;
  }
  if (dynamic_cast<const frontpack::WktError*>(&e) != nullptr) {
    return wkt;
  }
  if (dynamic_cast<const frontpack::InvalidDomainError*>(&e) != nullptr) {
    return invalid_domain;
  }
  if (dynamic_cast<const frontpack::DiskFileError*>(&e) != nullptr) {
    return bad_disk_file;
  }
  if (dynamic_cast<const frontpack::OptionError*>(&e) != nullptr ||
      dynamic_cast<const frontpack::LimitError*>(&e) != nullptr) {
    return bad_option;
  }
  return internal;
}

constexpr const char* kRadiusHelp =
    "radius distribution: uniform:RMIN,RMAX | constant:R | normal:MEAN,SD[,LO,HI] | "
    "lognormal:MEDIAN,GSD[,LO,HI] | discrete:S1:F1,S2:F2,...[@area] | curve:FILE.csv (sizes.hpp)";

}  // namespace

int main(int argc, char** argv) {
  frontpack_tool::SignalWatch signals;  // first: every later thread inherits the blocked signals
  g_signals = &signals;
  CLI::App app{"frontpack: dense, exactly certified disk packings of polygonal domains", "frontpack"};
  app.set_version_flag("--version", std::string(frontpack::version_string));
  app.require_subcommand(1);
  app.footer(std::string("Run 'frontpack SUBCOMMAND --help' for a worked example of each.\n\n") + kExitCodes);

  DomainSource info_src;
  auto* info = app.add_subcommand("info", "Load and validate a domain, and print its summary");
  add_domain_options(*info, info_src);
  info->footer(
      "Example:\n"
      "  frontpack info shapes/concave_polygon.wkt\n"
      "  frontpack info --wkt 'POLYGON((0 0, 2 0, 2 1, 0 1, 0 0))'");

  FillArgs fill_args;
  auto* fill = app.add_subcommand("fill", "Fill a domain with disks (advancing front, certified exactly)");
  add_domain_options(*fill, fill_args.src);
  fill->add_option("--method", fill_args.method,
                   "closed (Sec. 2), open (Sec. 3) or boundary (the domain's edges as walls)")
      ->capture_default_str();
  fill->add_option("--radius", fill_args.radius, std::string(kRadiusHelp) + " (default " + kDefaultRadius + ")");
  fill->add_option("--seed", fill_args.seed, "64-bit seed, 0 to 18446744073709551615 (same seed, same packing)")
      ->capture_default_str();
  fill->add_option("--max-disks", fill_args.max_disks,
                   "refuse runs estimated beyond this many disks, and stop a run that reaches it (exit 9)")
      ->capture_default_str();
  fill->add_option("--memory-limit", fill_args.memory_limit,
                   "bytes a run may take, e.g. 512M or 2G (K, M, G, T: powers of 1024); refused up front or stopped "
                   "before it would take more (exit 5); 0: three quarters of the machine's memory")
      ->capture_default_str();
  fill->add_option("-o,--output", fill_args.outputs,
                   "output file, any number; format by extension: .csv, .txt/.yade (Yade), .data/.lmp (LAMMPS), "
                   ".vtp (ParaView), .png/.svg/.pdf (picture)");
  fill->add_option("--format", fill_args.format,
                   "format of every -o instead of the extension: csv, yade, lammps, "
                   "vtp, png, svg, pdf");
  fill->add_option("--json", fill_args.json, "write the summary as JSON to this file");
  fill->add_option("--width", fill_args.width, "picture width in pixels")->capture_default_str();
  fill->add_flag("--no-histogram", fill_args.no_histogram,
                 "pictures without the size-distribution panel (histogram by area, KS distance)");
  fill->add_flag("-q,--quiet", fill_args.quiet, "print nothing but errors (no summary, no progress bar)");
  fill->footer(
      "Example:\n"
      "  frontpack fill shapes/plate_with_holes.wkt --radius uniform:0.005,0.02 --seed 7 \\\n"
      "      -o packing.csv -o packing.data -o packing.png --json summary.json\n"
      "Prints a summary on stderr (disks, packing fraction overall and interior, radii, certificate, time);\n"
      "on a terminal, runs longer than half a second show a progress bar. Ctrl-C (or SIGTERM) stops the\n"
      "run within a second (exit 130 or 143) and leaves every output file as it was.");

  CheckArgs check_args;
  auto* check = app.add_subcommand("check", "Certify any packing exactly: no overlap, every disk inside");
  check->add_option("DOMAIN", check_args.domain, "WKT file")->required();
  check->add_option("DISKS", check_args.disks, "disk file: .csv (x,y,r) or .txt/.yade (Yade x y z r)")->required();
  check->add_flag("--all", check_args.all, "list every disk outside and every overlapping pair");
  check->add_option("--json", check_args.json, "write the report as JSON to this file");
  check->add_flag("-q,--quiet", check_args.quiet, "print nothing but errors; the exit code tells");
  check->footer(
      "Example:\n"
      "  frontpack check shapes/l_shape.wkt packing.csv\n"
      "Exit 0 if certified, 6 if some pair overlaps or some disk is not entirely inside (the worst of each\n"
      "is named), 7 if the disk file is malformed (the line is named).");

  RenderArgs render_args;
  auto* render = app.add_subcommand("render", "Draw a packing: PNG, SVG or PDF, disks coloured by radius");
  render->add_option("DOMAIN", render_args.domain, "WKT file")->required();
  render->add_option("DISKS", render_args.disks, "disk file: .csv or .txt/.yade")->required();
  render->add_option("-o,--output", render_args.outputs, "picture file(s): .png, .svg or .pdf")->required();
  render->add_option("--format", render_args.format, "png, svg or pdf instead of the extension");
  render->add_option("--width", render_args.width, "width in pixels (height: the domain's, plus the histogram)")
      ->capture_default_str();
  render->add_option("--radius", render_args.radius,
                     "the requested radius distribution (a --radius SPEC of fill): drawn over the histogram, "
                     "with the KS distance by area");
  render->add_flag("--no-histogram", render_args.no_histogram,
                   "the packing alone, without the size-distribution panel below it");
  render->add_flag("-q,--quiet", render_args.quiet, "print nothing but errors");
  render->footer(
      "Example:\n"
      "  frontpack fill shapes/plate_with_holes.wkt --radius uniform:0.005,0.02 -o packing.csv\n"
      "  frontpack render shapes/plate_with_holes.wkt packing.csv -o packing.png --width 800 \\\n"
      "      --radius uniform:0.005,0.02\n"
      "Below the packing, a histogram of the radii by area (bars coloured as the disks: the colour key), the\n"
      "requested distribution's area per bin as a line and the KS distance by area; --no-histogram omits it.");

  StatsArgs stats_args;
  auto* stats = app.add_subcommand("stats", "Packing statistics: fractions, coordination, radii");
  stats->add_option("DOMAIN", stats_args.domain, "WKT file")->required();
  stats->add_option("DISKS", stats_args.disks, "disk file: .csv or .txt/.yade")->required();
  stats->add_option("--radius", stats_args.radius, "compare the radii with this requested distribution");
  stats->add_option("--samples", stats_args.samples, "sample points for the interior and band fractions")
      ->capture_default_str();
  stats->add_option("--json", stats_args.json, "write the statistics as JSON to this file");
  stats->add_flag("-q,--quiet", stats_args.quiet, "print nothing but errors");
  stats->footer(
      "Example:\n"
      "  frontpack stats shapes/l_shape.wkt packing.csv --radius uniform:0.01,0.05 --json stats.json");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? ok : usage;
  }

  try {
    if (*info) {
      return run_info(info_src);
    }
    if (*fill) {
      return run_fill(fill_args);
    }
    if (*check) {
      return run_check(check_args);
    }
    if (*render) {
      return run_render(render_args);
    }
    if (*stats) {
      return run_stats(stats_args);
    }
    return usage;
  } catch (const CLI::ParseError& e) {
    std::cerr << "frontpack: " << e.what() << "\n";
    return usage;
  } catch (const frontpack::CancelledError&) {
    std::cerr << "\nfrontpack: interrupted by " << frontpack_tool::signal_name(signals.signal())
              << "; no output written\n";
    return signals.exit_code();
  } catch (const std::exception& e) {
    const int code = exit_code(e);
    std::cerr << "frontpack: " << (code == internal ? "internal error: " : "") << e.what() << "\n";
    return code;
  }
}
