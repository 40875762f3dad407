// The frontpack command-line tool. It maps library errors to messages and exit codes; the
// library itself never prints.
//
// Exit codes (also in `frontpack --help` and the README):
//   0 success, 1 usage error (unknown option, missing argument), 2 unreadable input or unwritable
//   output file, 3 WKT syntax or unsupported geometry, 4 invalid domain, 5 invalid option (radius,
//   method, format, width, limit), 6 packing not certified (check: overlaps or disks outside),
//   7 malformed disk file, 70 internal error, 130 interrupted (Ctrl-C; nothing written).
//
// Every output file (-o, --json) is written to a temporary file beside it and renamed: a failed
// or interrupted run never leaves a partial file.
#include <unistd.h>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <iostream>
#include <limits>
#include <nlohmann/json.hpp>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <system_error>
#include <variant>
#include <vector>

#include "atomic_file.hpp"
#include "frontpack/frontpack.hpp"
#include "render.hpp"

namespace {

using Json = nlohmann::ordered_json;
using Clock = std::chrono::steady_clock;

enum Exit : int {
  ok = 0,
  usage = 1,
  io = 2,
  wkt = 3,
  invalid_domain = 4,
  bad_option = 5,
  not_certified = 6,
  bad_disk_file = 7,
  internal = 70,
  interrupted = 130,
};

constexpr const char* kExitCodes =
    "Exit codes: 0 success, 1 usage error, 2 unreadable input or unwritable output, 3 WKT syntax or\n"
    "unsupported geometry, 4 invalid domain, 5 invalid option (radius, method, format, width, limit),\n"
    "6 packing not certified (check), 7 malformed disk file, 70 internal error, 130 interrupted.\n"
    "Output files are written to a temporary file and renamed: never a partial file.";

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

std::string fmt(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

std::string fmt4(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.4f", v);
  return buf;
}

// ---------------------------------------------------------------------------------------------
// Inputs.

struct DomainSource {
  std::string file;
  std::string wkt;
  [[nodiscard]] std::string name() const { return wkt.empty() ? file : std::string("--wkt"); }
};

void add_domain_options(CLI::App& cmd, DomainSource& src) {
  auto* file = cmd.add_option("DOMAIN", src.file, "WKT file with a POLYGON or MULTIPOLYGON");
  auto* text = cmd.add_option("--wkt", src.wkt, "the domain as WKT text instead of a file");
  file->excludes(text);
  text->excludes(file);
}

frontpack::Domain load(const DomainSource& src) {
  if (!src.wkt.empty()) {
    return frontpack::Domain::from_wkt(src.wkt);
  }
  if (src.file.empty()) {
    throw CLI::RequiredError("DOMAIN or --wkt");
  }
  return frontpack::Domain::from_wkt_file(src.file);
}

// ---------------------------------------------------------------------------------------------
// Outputs: data formats through the library's write_file, pictures through the Cairo renderer.

using OutputFormat = std::variant<frontpack::Format, frontpack_tool::Picture>;

struct Output {
  std::filesystem::path path;
  OutputFormat format;
};

std::string format_name(const OutputFormat& f) {
  if (const auto* picture = std::get_if<frontpack_tool::Picture>(&f)) {
    return *picture == frontpack_tool::Picture::png ? "png" : *picture == frontpack_tool::Picture::svg ? "svg" : "pdf";
  }
  return frontpack::to_string(std::get<frontpack::Format>(f));
}

// --format NAME (for every output) or the extension. Pictures (png, svg, pdf) are drawn by the
// tool's renderer, so that fill and render draw the same picture.
OutputFormat resolve_format(const std::filesystem::path& path, const std::string& name, bool pictures_only) {
  const std::string known = pictures_only ? "png, svg or pdf" : "csv, yade, lammps, vtp, png, svg or pdf";
  if (!name.empty()) {
    if (const auto picture = frontpack_tool::picture_from_name(name)) {
      return *picture;
    }
    if (!pictures_only) {
      try {
        return frontpack::format_from_name(name);
      } catch (const frontpack::OptionError&) {
      }
    }
    throw frontpack::OptionError(std::string("--format ") + name + ": unknown format; expected " + known);
  }
  if (const auto picture = frontpack_tool::picture_from_path(path)) {
    return *picture;
  }
  if (pictures_only) {
    throw frontpack::OptionError(std::string("-o ") + path.string() + ": unknown picture format '" +
                                 path.extension().string() + "'; use .png, .svg or .pdf (or --format)");
  }
  try {
    return frontpack::format_from_path(path);
  } catch (const frontpack::OptionError&) {
    // The library's message lists only its own formats; name the tool's pictures too.
    const std::string ext = path.extension().string();
    std::string message("-o ");
    message.append(path.string());
    message.append(ext.empty() ? std::string(": no file extension to tell the format by")
                               : std::string(": unknown format '") + ext + "'");
    message.append(
        "; use .csv, .txt or .yade (Yade), .data or .lmp (LAMMPS), .vtp (ParaView), .png, .svg or .pdf, "
        "or --format NAME");
    throw frontpack::OptionError(message);
  }
}

// Fails early (before a long run) when an output's directory does not exist or is not writable.
void check_writable(const std::filesystem::path& path) {
  std::filesystem::path dir = path.parent_path();
  if (dir.empty()) {
    dir = ".";
  }
  if (::access(dir.c_str(), W_OK) != 0) {
    const int err = errno;
    throw frontpack::IoError(std::string("cannot write '") + path.string() + "': " + std::strerror(err), path.string());
  }
  if (std::filesystem::is_directory(path)) {
    throw frontpack::IoError(std::string("cannot write '") + path.string() + "': it is a directory", path.string());
  }
}

std::vector<Output> resolve_outputs(const std::vector<std::string>& paths, const std::string& format,
                                    bool pictures_only) {
  std::vector<Output> out;
  for (const std::string& p : paths) {
    out.push_back({p, resolve_format(p, format, pictures_only)});
  }
  for (const Output& o : out) {
    check_writable(o.path);
  }
  return out;
}

void write_output(const Output& o, const frontpack::Domain& domain, std::span<const frontpack::Disk> disks,
                  const frontpack_tool::RenderOptions& picture_options) {
  if (const auto* picture = std::get_if<frontpack_tool::Picture>(&o.format)) {
    frontpack_tool::render(o.path, *picture, domain, disks, picture_options);
  } else {
    frontpack::WriteOptions options;
    options.svg.width_px = picture_options.width_px;
    frontpack::write_file(o.path, std::get<frontpack::Format>(o.format), domain, disks, options);
  }
}

void write_json(const std::string& path, const Json& json) {
  frontpack_tool::AtomicFile out(path);
  const std::string text = json.dump(2) + "\n";
  std::fwrite(text.data(), 1, text.size(), out.file());
  out.commit();
}

// ---------------------------------------------------------------------------------------------
// Progress bar and Ctrl-C.

volatile std::sig_atomic_t g_interrupted = 0;

extern "C" void on_sigint(int /*signal*/) {
  g_interrupted = 1;
}

// Installs the SIGINT handler for its lifetime (only around the run: Ctrl-C during loading or
// writing keeps its default effect, which cannot leave a partial output file either).
class InterruptScope {
 public:
  InterruptScope() {
    previous_ = std::signal(SIGINT, on_sigint);
    if (previous_ == SIG_IGN) {
      std::signal(SIGINT, SIG_IGN);  // started with Ctrl-C ignored (nohup, a background job): keep it so
    }
  }
  ~InterruptScope() { std::signal(SIGINT, previous_ == SIG_ERR ? SIG_DFL : previous_); }
  InterruptScope(const InterruptScope&) = delete;
  InterruptScope& operator=(const InterruptScope&) = delete;

 private:
  void (*previous_)(int) = SIG_DFL;
};

// On a terminal only, after half a second: "[#####.....]  42% of area  123456 disks  1.2e+06 disks/s  ETA 3 s".
class ProgressBar {
 public:
  explicit ProgressBar(bool enabled) : enabled_(enabled && ::isatty(STDERR_FILENO) == 1) {}
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;
  ~ProgressBar() { clear(); }

  void update(const frontpack::Progress& p) {
    if (!enabled_) {
      return;
    }
    const double t = seconds_since(start_);
    if (t < 0.5 || (shown_ && t - last_ < 0.1 && p.fraction < 1.0)) {
      return;
    }
    last_ = t;
    shown_ = true;
    constexpr int kWidth = 30;
    const double f = std::clamp(p.fraction, 0.0, 1.0);
    const int filled = static_cast<int>(f * kWidth);
    std::string line("\r[");
    line.append(static_cast<std::size_t>(filled), '#').append(static_cast<std::size_t>(kWidth - filled), '.');
    char tail[160];
    const double rate = static_cast<double>(p.disks) / t;
    const double eta = f > 0.01 ? t * (1 - f) / f : NAN;
    if (std::isfinite(eta)) {
      std::snprintf(tail, sizeof tail, "] %3.0f%% of area  %zu disks  %.3g disks/s  ETA %.0f s", 100 * f, p.disks, rate,
                    eta);
    } else {
      std::snprintf(tail, sizeof tail, "] %3.0f%% of area  %zu disks  %.3g disks/s", 100 * f, p.disks, rate);
    }
    line.append(tail).append("\033[K");
    std::fputs(line.c_str(), stderr);
    std::fflush(stderr);
  }

  void clear() {
    if (shown_) {
      std::fputs("\r\033[K", stderr);
      std::fflush(stderr);
      shown_ = false;
    }
  }

 private:
  bool enabled_;
  bool shown_ = false;
  double last_ = 0;
  Clock::time_point start_ = Clock::now();
};

// ---------------------------------------------------------------------------------------------
// JSON pieces shared by fill and stats.

Json domain_json(const DomainSource& src, const frontpack::Domain& domain) {
  return Json{{"source", src.name()},
              {"area", domain.area()},
              {"polygons", domain.num_polygons()},
              {"holes", domain.num_holes()},
              {"vertices", domain.num_vertices()}};
}

Json sizes_json(const frontpack::SizeStats& s) {
  Json j{{"count", s.count},
         {"min", s.rmin},
         {"max", s.rmax},
         {"mean", s.mean},
         {"sd", s.sd},
         {"median_by_number", s.median_number},
         {"median_by_area", s.median_area}};
  if (s.compared) {
    j["requested"] = s.requested;
    j["ks_by_number"] = s.ks_number;
    j["ks_by_area"] = s.ks_area;
  }
  return j;
}

Json stats_json(const frontpack::PackingStats& s) {
  return Json{{"packing_fraction", s.packing_fraction},
              {"interior_fraction", s.interior_fraction},
              {"interior_fraction_error", s.interior_error},
              {"band_fraction", s.band_fraction},
              {"band_fraction_error", s.band_error},
              {"band_width", s.band_width},
              {"void_ratio", std::isfinite(s.void_ratio) ? Json(s.void_ratio) : Json(nullptr)},
              {"mean_coordination", s.mean_coordination},
              {"interior_coordination", s.interior_coordination},
              {"contacts", s.contacts},
              {"wall_contacts", s.wall_contacts},
              {"rattlers", s.rattlers},
              {"contact_gap", s.contact_gap},
              {"band_disks", s.band_disks},
              {"band_median_by_area", s.band_median_area},
              {"inside_median_by_area", s.inside_median_area},
              {"segregation_ks_by_area", s.segregation_ks_area},
              {"radius", sizes_json(s.sizes)}};
}

std::string fraction_line(const frontpack::PackingStats& s) {
  std::string line = fmt4(s.packing_fraction);
  line.append(" overall");
  if (s.interior_samples > 0) {
    line.append(", ").append(fmt4(s.interior_fraction)).append(" interior (+/- ").append(fmt4(s.interior_error));
    line.append(", farther than ").append(fmt(s.band_width)).append(" from the boundary)");
  }
  if (s.band_samples > 0) {
    line.append(", ").append(fmt4(s.band_fraction)).append(" in the band");
  }
  return line;
}

std::string radii_line(const frontpack::SizeStats& s) {
  if (s.count == 0) {
    return "none";
  }
  return std::string("min ") + fmt(s.rmin) + ", mean " + fmt(s.mean) + ", max " + fmt(s.rmax) + ", sd " + fmt(s.sd) +
         ", median by area " + fmt(s.median_area);
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
  std::string method = "boundary";
  std::string radius = "uniform:0.01,0.05";
  std::uint64_t seed = 0;
  std::size_t max_disks = frontpack::FillOptions{}.max_disks;
  std::string memory_limit = "0";
  std::vector<std::string> outputs;
  std::string format;
  std::string json;
  int width = 1200;
  bool no_histogram = false;
  bool quiet = false;
};

int run_fill(const FillArgs& a) {
  const auto t_start = Clock::now();
  const frontpack::Domain domain = load(a.src);
  frontpack::FillOptions options;
  if (a.method == "closed") {
    options.method = frontpack::Method::closed;
  } else if (a.method == "open") {
    options.method = frontpack::Method::open;
  } else if (a.method == "boundary") {
    options.method = frontpack::Method::boundary;
  } else {
    throw frontpack::OptionError(std::string("--method ") + a.method + ": expected closed, open or boundary");
  }
  options.radii = frontpack::parse_radii(a.radius);
  options.seed = a.seed;
  options.max_disks = a.max_disks;
  options.memory_limit = parse_bytes("--memory-limit", a.memory_limit);
  const std::vector<Output> outputs = resolve_outputs(a.outputs, a.format, false);
  if (!a.json.empty()) {
    check_writable(a.json);
  }

  frontpack::Packing p;
  {
    ProgressBar bar(!a.quiet);
    const InterruptScope interrupt_scope;
    g_interrupted = 0;
    frontpack::Generator generator(domain, options);
    generator.on_progress([&bar](const frontpack::Progress& progress) {
      bar.update(progress);
      return g_interrupted == 0;
    });
    p = generator.run();
    bar.clear();
    if (p.cancelled || g_interrupted != 0) {
      std::cerr << "frontpack: interrupted; nothing written\n";
      return interrupted;
    }
  }

  const auto t_stats = Clock::now();
  const frontpack::PackingStats s = frontpack::measure(domain, p.disks, {.requested = options.radii});
  const double seconds_stats = seconds_since(t_stats);

  const frontpack_tool::RenderOptions picture{
      .width_px = a.width, .histogram = !a.no_histogram, .requested = options.radii, .requested_spec = a.radius};
  for (const Output& o : outputs) {
    write_output(o, domain, p.disks, picture);
  }
  const frontpack::Certificate& c = p.certificate;
  const double seconds_fill = p.stats.seconds_front + p.stats.seconds_cull + p.stats.seconds_overlap;
  if (!a.json.empty()) {
    Json outs = Json::array();
    for (const Output& o : outputs) {
      outs.push_back(Json{{"path", o.path.string()}, {"format", format_name(o.format)}});
    }
    Json j{{"frontpack_version", frontpack::version_string},
           {"command", "fill"},
           {"domain", domain_json(a.src, domain)},
           {"method", frontpack::to_string(options.method)},
           {"radius_spec", a.radius},
           {"radius_distribution", options.radii.describe()},
           {"seed", a.seed},
           {"disks", p.disks.size()},
           {"truncated", p.truncated}};
    j.update(stats_json(s));
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
                        {"total", seconds_since(t_start)}};
    j["outputs"] = outs;
    write_json(a.json, j);
  }
  if (a.quiet) {
    return ok;
  }
  std::cerr << "disks:       " << p.disks.size() << " (" << frontpack::to_string(options.method) << " form, seed "
            << a.seed << (p.truncated ? ", truncated at --max-disks" : "") << ")\n"
            << "fraction:    " << fraction_line(s) << "\n"
            << "radii:       " << radii_line(s.sizes) << "\n"
            << "certificate: " << (c.dropped == 0 ? "certified" : "certified after repair") << ": " << c.generated
            << " generated, " << c.culled << " culled (not inside), " << c.dropped
            << " dropped (overlap); every decision exact\n"
            << "time:        " << fmt(seconds_fill) << " s (front " << fmt(p.stats.seconds_front) << ", cull "
            << fmt(p.stats.seconds_cull) << ", overlap pass " << fmt(p.stats.seconds_overlap) << "), statistics "
            << fmt(seconds_stats) << " s\n";
  for (const Output& o : outputs) {
    std::cerr << "wrote:       " << o.path.string() << " (" << format_name(o.format) << ")\n";
  }
  if (!a.json.empty()) {
    std::cerr << "wrote:       " << a.json << " (summary)\n";
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
  const frontpack::Domain domain = frontpack::Domain::from_wkt_file(a.domain);
  const std::vector<frontpack::Disk> disks = frontpack::read_disks(a.disks);
  if (!a.json.empty()) {
    check_writable(a.json);
  }
  const frontpack::CertifyReport r = frontpack::certify(domain, disks);
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
  if (!a.quiet) {
    std::cout << out.str();
  }
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
    write_json(a.json, j);
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
  const frontpack::Domain domain = frontpack::Domain::from_wkt_file(a.domain);
  const std::vector<frontpack::Disk> disks = frontpack::read_disks(a.disks);
  const std::vector<Output> outputs = resolve_outputs(a.outputs, a.format, true);
  for (const Output& o : outputs) {
    write_output(o, domain, disks, picture);
    if (!a.quiet) {
      std::cerr << "wrote:       " << o.path.string() << " (" << format_name(o.format) << ", " << a.width << " x "
                << frontpack_tool::picture_height(domain, a.width, picture.histogram) << ", " << disks.size()
                << " disks)\n";
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
  std::size_t samples = 1'000'000;
  bool quiet = false;
};

int run_stats(const StatsArgs& a) {
  const frontpack::Domain domain = frontpack::Domain::from_wkt_file(a.domain);
  const std::vector<frontpack::Disk> disks = frontpack::read_disks(a.disks);
  frontpack::StatsOptions options;
  if (!a.radius.empty()) {
    options.requested = frontpack::parse_radii(a.radius);
  }
  options.samples = a.samples;
  if (!a.json.empty()) {
    check_writable(a.json);
  }
  const frontpack::PackingStats s = frontpack::measure(domain, disks, options);
  if (!a.json.empty()) {
    Json j{{"frontpack_version", frontpack::version_string},
           {"command", "stats"},
           {"domain", domain_json(DomainSource{a.domain, {}}, domain)},
           {"disk_file", a.disks},
           {"disks", s.disks}};
    j.update(stats_json(s));
    write_json(a.json, j);
  }
  if (a.quiet) {
    return ok;
  }
  std::cout << "disks:        " << s.disks << " in " << a.disks << "\n"
            << "fraction:     " << fraction_line(s) << "\n"
            << "void ratio:   " << fmt(s.void_ratio) << "\n"
            << "radii:        " << radii_line(s.sizes) << "\n";
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
  fill->add_option("--radius", fill_args.radius, kRadiusHelp)->capture_default_str();
  fill->add_option("--seed", fill_args.seed, "64-bit seed (same seed, same packing)")->capture_default_str();
  fill->add_option("--max-disks", fill_args.max_disks, "refuse or stop runs beyond this many disks")
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
      "on a terminal, runs longer than half a second show a progress bar. Ctrl-C stops the run (exit 130,\n"
      "nothing written).");

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
  } catch (const std::exception& e) {
    const int code = exit_code(e);
    std::cerr << "frontpack: " << (code == internal ? "internal error: " : "") << e.what() << "\n";
    return code;
  }
}
