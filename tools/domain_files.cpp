#include "domain_files.hpp"

#include <algorithm>
#include <numbers>
#include <optional>
#include <sstream>

#include "option_values.hpp"
#include "report.hpp"

namespace frontpack_tool {

namespace {

double parse_deviation(const std::string& text) {
  const std::optional<double> value = cli::finite_number(text);
  if (!value || *value < 0) {
    throw frontpack::OptionError(cli::given_value("--max-deviation", text) +
                                 ": expected a finite number >= 0 (the largest distance between a curve and its "
                                 "polyline, in the domain's units; 0: 1e-3 of each curve's radius)");
  }
  return *value;
}

}  // namespace

frontpack::DomainFile read_domain(const std::string& file, const std::string& format, const std::string& max_deviation,
                                  double default_deviation, const frontpack::Budget& budget) {
  frontpack::DomainReadOptions options;
  options.budget = budget;
  options.format = format.empty() ? frontpack::DomainFormat::automatic : frontpack::parse_domain_format(format);
  options.max_deviation = max_deviation.empty() ? default_deviation : parse_deviation(max_deviation);
  return frontpack::read_domain_file(file, options);
}

std::string units_line(const frontpack::DomainFile& file) {
  if (file.format != frontpack::DomainFormat::dxf) {
    return {};
  }
  return "units:      " +
         (file.units.empty() ? std::string("not stated (no $INSUNITS in the HEADER)") : file.units + " ($INSUNITS)") +
         "; coordinates used as written\n";
}

std::string curve_lines(const frontpack::DomainFile& file, std::size_t max_lines) {
  if (file.curves.empty()) {
    return {};
  }
  std::ostringstream out;
  std::size_t segments = 0;
  std::size_t nudged = 0;
  double deviation = 0;
  for (const auto& c : file.curves) {
    segments += c.segments;
    nudged += c.nudged;
    deviation = std::max(deviation, c.deviation);
  }
  out << "curves:     " << file.curves.size() << (file.curves.size() == 1 ? " arc" : " arcs") << " -> " << segments
      << " segments, on the domain's side of each arc, deviation <= " << fmt(deviation) << " (" << nudged
      << " rounded vertices moved to the safe side)\n";
  for (std::size_t i = 0; i < file.curves.size() && i < max_lines; ++i) {
    const auto& c = file.curves[i];
    out << "  " << c.entity << ": radius " << fmt(c.radius) << ", " << fmt(c.sweep * 180 / std::numbers::pi)
        << " deg -> " << c.segments << (c.domain_inside ? " chords" : " tangent segments") << ", deviation "
        << fmt(c.deviation) << "\n";
  }
  if (file.curves.size() > max_lines) {
    out << "  ... and " << file.curves.size() - max_lines << " more\n";
  }
  return out.str();
}

Json curves_json(const frontpack::DomainFile& file) {
  Json out = Json::array();
  for (const auto& c : file.curves) {
    out.push_back(Json{{"entity", c.entity},
                       {"centre", Json::array({c.centre.x, c.centre.y})},
                       {"radius", c.radius},
                       {"sweep_degrees", c.sweep * 180 / std::numbers::pi},
                       {"domain_inside", c.domain_inside},
                       {"deviation", c.deviation},
                       {"segments", c.segments},
                       {"nudged", c.nudged}});
  }
  return out;
}

}  // namespace frontpack_tool
