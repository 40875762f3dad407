#include "domain/dxf_reader.hpp"

#include <dl_creationadapter.h>
#include <dl_dxf.h>

#include <cmath>
#include <numbers>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "common/format.hpp"
#include "common/memory_file.hpp"
#include "common/numbers.hpp"
#include "common/read_file.hpp"
#include "domain/dxf_groups.hpp"
#include "frontpack/errors.hpp"

namespace frontpack::detail {

namespace {

using Kind = DomainFileError::Kind;

// Entities that carry no boundary: skipped and counted.
const std::set<std::string, std::less<>> kAnnotations = {"TEXT",    "MTEXT",    "DIMENSION", "LEADER",    "MULTILEADER",
                                                         "MLEADER", "POINT",    "ATTDEF",    "ATTRIB",    "HATCH",
                                                         "IMAGE",   "VIEWPORT", "WIPEOUT",   "TOLERANCE", "ACAD_TABLE"};
// Entities read (VERTEX and SEQEND belong to POLYLINE).
const std::set<std::string, std::less<>> kRead = {"LINE",     "ARC",    "CIRCLE", "LWPOLYLINE",
                                                  "POLYLINE", "VERTEX", "SEQEND"};

// A bulge as written, and the line of its value ("" when the vertex has none: 0).
struct BulgeText {
  std::string text;
  std::size_t line = 0;
};

// A bulge is tan(angle / 4) of its arc; b and 1 / b give the two arcs of one circle between the
// same endpoints. Nonzero bulges below 1e-12 in magnitude (an arc whose sagitta is below 1e-12 of
// its chord: a radius over 1e11 chords, a centre whose place a double cannot hold to the
// sagitta's scale) and their inverses above 1e12 are refused (docs/cad-gis.md).
constexpr double kMinBulge = 1e-12;
constexpr double kMaxBulge = 1e12;

// One entity as dxflib's group stream shows it: its type, handle (group 5) and the line of its
// "0" group. dxflib reports an entity when the next one's "0" group arrives, so the callbacks
// see the entity just finished.
struct Record {
  std::string type;
  std::string handle;
  std::size_t line = 0;
  bool in_entities = false;
  std::vector<BulgeText> vertices;  ///< LWPOLYLINE: one per group 10; VERTEX: its own
  [[nodiscard]] std::string name() const { return dxf_entity_name(type, handle, line); }
};

class Reader : public DL_CreationAdapter {
 public:
  Reader(std::string source, const std::vector<DxfGroup>& groups) : source_(std::move(source)), groups_(groups) {}

  DxfContents contents;
  std::optional<DomainFileError> error;

  // dxflib reads the groups checked by read_dxf_groups(), one value per line: the same groups, in
  // the same order, which this check confirms before any is used.
  void processCodeValuePair(unsigned int code, const std::string& value) override {
    if (pairs_ >= groups_.size() || static_cast<unsigned int>(groups_[pairs_].code) != code ||
        groups_[pairs_].value != value) {
      if (!error) {
        error = DomainFileError(Kind::bad_structure,
                                "dxflib read group " + std::to_string(pairs_ + 1) + " as code " + std::to_string(code) +
                                    " " + quote_text(value) + ", not as checked",
                                source_);
      }
      return;
    }
    const DxfGroup& g = groups_[pairs_++];
    if (code == 0) {
      finish(current_);
      finished_ = current_;
      current_ = {value, {}, g.line, section_ == "ENTITIES", {}};
      if (value == "ENDSEC") {
        section_.clear();
      }
      if (value == "VERTEX") {
        current_.vertices.emplace_back();
      }
      return;
    }
    if (code == 2 && current_.type == "SECTION") {
      section_ = value;
    } else if (code == 5) {
      current_.handle = value;
    }
    if (!current_.in_entities || kRead.count(current_.type) == 0 || code >= 1000 || error) {
      return;  // the numbers of entities read, extended data (1000 and above) aside
    }
    try {
      check_dxf_number(g, source_, current_.name());
    } catch (const DomainFileError& e) {
      error = e;
      return;
    }
    if (code == 10 && current_.type == "LWPOLYLINE") {
      current_.vertices.emplace_back();
    } else if (code == 42 && !current_.vertices.empty()) {
      current_.vertices.back() = {value, g.line};
    }
  }

  void addLine(const DL_LineData& d) override {
    if (!wanted()) {
      return;
    }
    const Point a = point(d.x1, d.y1, false);
    const Point b = point(d.x2, d.y2, false);
    Piece p;
    p.name = finished_.name();
    ContourEdge e;
    e.from = a;
    p.edges.push_back(e);
    p.end = b;
    contents.open.push_back(std::move(p));
  }

  void addCircle(const DL_CircleData& d) override {
    if (!wanted() || !plane_ok()) {
      return;
    }
    Contour c;
    c.full_circle = true;
    c.circle = {.centre = point(d.cx, d.cy, mirrored_), .radius = d.radius, .start = 0, .sweep = 2 * std::numbers::pi};
    c.names.push_back(finished_.name());
    check_circle(c.circle);
    contents.closed.push_back(std::move(c));
  }

  void addArc(const DL_ArcData& d) override {
    if (!wanted() || !plane_ok()) {
      return;
    }
    if (!std::isfinite(d.angle1) || !std::isfinite(d.angle2)) {
      fail(Kind::bad_curve, "non-finite start or end angle");
      return;
    }
    // An angle beyond one turn is reduced modulo 360 (fmod is exact), so that any finite angle
    // names its direction and the sweep is in (0, 360] in one step (subtracting 360 from 2e300
    // never ended); angles within a turn are used as written.
    const auto turn = [](double a) { return std::abs(a) <= 360 ? a : std::fmod(a, 360.0); };
    const double angle1 = turn(d.angle1);
    const double angle2 = turn(d.angle2);
    double sweep_deg = std::fmod(angle2 - angle1, 360.0);
    if (sweep_deg <= 0) {
      sweep_deg += 360;
    }
    constexpr double deg = std::numbers::pi / 180;
    Arc arc{
        .centre = point(d.cx, d.cy, mirrored_), .radius = d.radius, .start = angle1 * deg, .sweep = sweep_deg * deg};
    double end_angle = angle2 * deg;
    if (mirrored_) {  // OCS z = -1: x mirrored, so angles a -> pi - a and the sweep turns clockwise
      arc.start = std::numbers::pi - arc.start;
      end_angle = std::numbers::pi - end_angle;
      arc.sweep = -arc.sweep;
    }
    check_circle(arc);
    Piece p;
    p.name = finished_.name();
    const Point a{arc.centre.x + arc.radius * std::cos(arc.start), arc.centre.y + arc.radius * std::sin(arc.start)};
    p.edges.push_back({.from = a, .curved = true, .arc = arc});
    p.end = {arc.centre.x + arc.radius * std::cos(end_angle), arc.centre.y + arc.radius * std::sin(end_angle)};
    contents.open.push_back(std::move(p));
  }

  void addPolyline(const DL_PolylineData& d) override {
    finish_polyline();
    if (!wanted() || !plane_ok()) {
      return;
    }
    if ((d.flags & (8 | 16 | 64)) != 0) {
      fail(Kind::unsupported_entity, "a 3D polyline or mesh; frontpack reads 2D polylines");
      return;
    }
    polyline_ = Polyline{finished_.name(), (d.flags & 1) != 0, mirrored_, {}, {}, {}};
  }

  void addVertex(const DL_VertexData& d) override {
    if (polyline_) {
      // An LWPOLYLINE's vertices are its own groups; a POLYLINE's, each VERTEX entity's.
      const std::size_t k = finished_.type == "LWPOLYLINE" ? polyline_->points.size() : 0;
      polyline_->bulge_texts.push_back(k < finished_.vertices.size() ? finished_.vertices[k] : BulgeText{});
      polyline_->points.push_back(point(d.x, d.y, polyline_->mirrored));
      polyline_->bulges.push_back(polyline_->mirrored ? -d.bulge : d.bulge);
    }
  }

  void endEntity() override { finish_polyline(); }
  void endSequence() override { finish_polyline(); }

  void done() {
    finish(current_);
    finish_polyline();
    if (!error && pairs_ != groups_.size()) {
      error = DomainFileError(
          Kind::bad_structure,
          "dxflib read " + std::to_string(pairs_) + " groups of " + std::to_string(groups_.size()) + ", not as checked",
          source_);
    }
  }

 private:
  struct Polyline {
    std::string name;
    bool closed = false;
    bool mirrored = false;
    std::vector<Point> points;
    std::vector<double> bulges;
    std::vector<BulgeText> bulge_texts;
  };

  void fail(Kind kind, const std::string& detail) { fail_named(kind, detail, finished_.name()); }
  void fail_named(Kind kind, const std::string& detail, const std::string& entity) {
    if (!error) {
      error = DomainFileError(kind, detail, source_, entity);
    }
  }

  // Called for each entity once its groups are all read: the types frontpack cannot read.
  void finish(const Record& r) {
    if (!r.in_entities || r.type.empty() || r.type == "ENDSEC" || kRead.count(r.type) != 0) {
      return;
    }
    if (kAnnotations.count(r.type) != 0) {
      ++contents.ignored;
      return;
    }
    if (!error) {
      error = DomainFileError(
          Kind::unsupported_entity,
          "frontpack reads CIRCLE, ARC, LINE, LWPOLYLINE and 2D POLYLINE (with bulges)" +
              std::string(r.type == "INSERT"                          ? "; explode the block reference first"
                          : r.type == "SPLINE" || r.type == "ELLIPSE" ? "; convert it to a polyline or arcs first"
                                                                      : ""),
          source_, r.name());
    }
  }

  [[nodiscard]] bool wanted() const { return finished_.in_entities && !error; }

  // Only entities in the XY plane: extrusion (0, 0, 1), or (0, 0, -1), which mirrors x (the
  // arbitrary axis algorithm gives the OCS x axis (-1, 0, 0) for it).
  bool plane_ok() {
    const double* n = getExtrusion()->getDirection();
    mirrored_ = n[0] == 0 && n[1] == 0 && n[2] == -1;
    if (!mirrored_ && !(n[0] == 0 && n[1] == 0 && n[2] == 1)) {
      fail(Kind::unsupported_entity, "not in the XY plane (extrusion direction " + format_double(n[0]) + " " +
                                         format_double(n[1]) + " " + format_double(n[2]) + ")");
      return false;
    }
    return true;
  }

  Point point(double x, double y, bool mirror) {
    const Point p{mirror ? -x : x, y};
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
      fail(Kind::bad_curve, "a non-finite coordinate");
    }
    contents.extent.extend(p);
    return p;
  }

  void check_circle(const Arc& arc) {
    if (!(std::isfinite(arc.radius) && arc.radius > 0)) {
      fail(Kind::bad_curve, "radius " + format_double(arc.radius) + "; expected a finite number > 0");
      return;
    }
    contents.extent.extend(Point{arc.centre.x - arc.radius, arc.centre.y - arc.radius});
    contents.extent.extend(Point{arc.centre.x + arc.radius, arc.centre.y + arc.radius});
  }

  void finish_polyline() {
    if (!polyline_) {
      return;
    }
    Polyline pl = std::move(*polyline_);
    polyline_.reset();
    // Edges from vertex i to i + 1 (and back to 0 when closed), zero-length ones dropped.
    const std::size_t n = pl.points.size();
    const std::size_t edges = pl.closed ? n : (n > 0 ? n - 1 : 0);
    std::vector<ContourEdge> out;
    for (std::size_t i = 0; i < edges; ++i) {
      const Point a = pl.points[i];
      const Point b = pl.points[(i + 1) % n];
      if (a == b) {
        continue;
      }
      ContourEdge e;
      e.from = a;
      e.index = static_cast<std::uint32_t>(i);
      const double bulge = pl.bulges[i];
      const BulgeText& text = pl.bulge_texts[i];
      const auto bad_bulge = [&](const std::string& why) {
        fail_named(Kind::bad_curve,
                   "vertex " + std::to_string(i) + ": bulge " + quote_text(text.text) + " (line " +
                       std::to_string(text.line) + ") " + why,
                   pl.name);
      };
      if (bulge != 0 && !(std::abs(bulge) >= kMinBulge && std::abs(bulge) <= kMaxBulge)) {
        bad_bulge(
            "is outside 1e-12 <= |bulge| <= 1e12, where its arc's circle can be placed in doubles (0 is a "
            "straight edge)");
        return;
      }
      if (bulge != 0) {
        e.curved = true;
        e.arc = arc_from_bulge(a, b, bulge);
        if (!(std::isfinite(e.arc.centre.x) && std::isfinite(e.arc.centre.y) && std::isfinite(e.arc.radius) &&
              e.arc.radius > 0)) {
          bad_bulge("between (" + format_double(a.x) + " " + format_double(a.y) + ") and (" + format_double(b.x) + " " +
                    format_double(b.y) + ") makes a circle beyond the range of doubles");
          return;
        }
        check_circle(e.arc);
      }
      out.push_back(e);
    }
    if (out.empty()) {
      fail_named(Kind::open_contour, "a polyline with fewer than two distinct vertices", pl.name);
      return;
    }
    if (pl.closed) {
      Contour c;
      c.edges = std::move(out);
      c.names.push_back(pl.name);
      contents.closed.push_back(std::move(c));
    } else {
      Piece p;
      p.name = pl.name;
      p.end = pl.points.back();
      p.edges = std::move(out);
      contents.open.push_back(std::move(p));
    }
  }

  std::string source_;
  const std::vector<DxfGroup>& groups_;
  std::string section_;
  std::size_t pairs_ = 0;
  Record current_;
  Record finished_;
  bool mirrored_ = false;
  std::optional<Polyline> polyline_;
};

}  // namespace

namespace {

// The HEADER's $INSUNITS (group 9, then its value in group 70), checked: "" when absent.
std::string units_of(const std::vector<DxfGroup>& groups, const std::string& source) {
  std::string section;
  for (std::size_t i = 0; i + 1 < groups.size(); ++i) {
    if (groups[i].code == 0 && groups[i].value == "SECTION") {
      section = groups[i + 1].value;
    } else if (section == "HEADER" && groups[i].code == 9 && groups[i].value == "$INSUNITS" &&
               groups[i + 1].code == 70) {
      const DxfGroup& g = groups[i + 1];
      return dxf_units_name(dxf_integer(g, 0, kDxfUnitsMax, source,
                                        "HEADER variable $INSUNITS (line " + std::to_string(groups[i].line) + ")"));
    }
  }
  return {};
}

}  // namespace

DxfContents read_dxf(const std::filesystem::path& path) {
  const std::string source = path.string();
  const std::string text = read_text_file(path);  // IoError with the project's message when unreadable
  std::vector<DxfGroup> groups = read_dxf_groups(text, source);
  check_dxf_counts(groups, source);
  std::string units = units_of(groups, source);
  // Comments (999) are not handed over: dxflib reads one that starts with "dxflib" as its own
  // version stamp, and one of exactly "dxflib" made it throw std::out_of_range.
  std::erase_if(groups, [](const DxfGroup& g) { return g.code == 999; });
  // dxflib reads by path (its std::istream entry point reads nothing in 3.26): it reads the checked
  // groups, one value per line, from a memory file, so it sees what was checked and nothing else.
  std::string checked;
  checked.reserve(text.size());
  for (const DxfGroup& g : groups) {
    checked.append(std::to_string(g.code)).append("\n").append(g.value).append("\n");
  }
  const MemoryFile memory(checked, source, "dxflib");
  Reader reader(source, groups);
  DL_Dxf dxf;
  if (!dxf.in(memory.path(), &reader)) {
    throw DomainFileError(Kind::unreadable, "dxflib could not read the file as DXF", source);
  }
  reader.done();
  if (reader.error) {
    throw *reader.error;
  }
  DxfContents contents = std::move(reader.contents);
  contents.units = std::move(units);
  return contents;
}

}  // namespace frontpack::detail
