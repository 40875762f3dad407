#include "domain/dxf_reader.hpp"

#include <dl_creationadapter.h>
#include <dl_dxf.h>

#include <cmath>
#include <numbers>
#include <optional>
#include <set>
#include <string>
#include <utility>

#include "common/format.hpp"
#include "common/read_file.hpp"
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

// One entity as dxflib's group stream shows it: its type, handle (group 5) and the line of its
// "0" group. dxflib reports an entity when the next one's "0" group arrives, so the callbacks
// see the entity just finished.
struct Record {
  std::string type;
  std::string handle;
  std::size_t line = 0;
  bool in_entities = false;
  [[nodiscard]] std::string name() const {
    return type + " (" + (handle.empty() ? std::string() : "handle " + handle + ", ") + "line " + std::to_string(line) +
           ")";
  }
};

class Reader : public DL_CreationAdapter {
 public:
  explicit Reader(std::string source) : source_(std::move(source)) {}

  DxfContents contents;
  std::optional<DomainFileError> error;

  void processCodeValuePair(unsigned int code, const std::string& value) override {
    const std::size_t line = 2 * pairs_ + 2;  // a group is two lines, code then value: the value's
    ++pairs_;
    if (code == 0) {
      finish(current_);
      finished_ = current_;
      current_ = {value, {}, line, section_ == "ENTITIES"};
      if (value == "ENDSEC") {
        section_.clear();
      }
    } else if (code == 2 && current_.type == "SECTION") {
      section_ = value;
    } else if (code == 5) {
      current_.handle = value;
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
    double sweep_deg = d.angle2 - d.angle1;
    while (sweep_deg <= 0 && std::isfinite(sweep_deg)) {
      sweep_deg += 360;
    }
    while (sweep_deg > 360) {
      sweep_deg -= 360;
    }
    constexpr double deg = std::numbers::pi / 180;
    Arc arc{
        .centre = point(d.cx, d.cy, mirrored_), .radius = d.radius, .start = d.angle1 * deg, .sweep = sweep_deg * deg};
    double end_angle = d.angle2 * deg;
    if (mirrored_) {  // OCS z = -1: x mirrored, so angles a -> pi - a and the sweep turns clockwise
      arc.start = std::numbers::pi - arc.start;
      end_angle = std::numbers::pi - end_angle;
      arc.sweep = -arc.sweep;
    }
    check_circle(arc);
    if (!std::isfinite(d.angle1) || !std::isfinite(d.angle2)) {
      fail(Kind::bad_curve, "non-finite start or end angle");
      return;
    }
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
    polyline_ = Polyline{finished_.name(), (d.flags & 1) != 0, mirrored_, {}, {}};
  }

  void addVertex(const DL_VertexData& d) override {
    if (polyline_) {
      polyline_->points.push_back(point(d.x, d.y, polyline_->mirrored));
      polyline_->bulges.push_back(polyline_->mirrored ? -d.bulge : d.bulge);
    }
  }

  void endEntity() override { finish_polyline(); }
  void endSequence() override { finish_polyline(); }

  void done() {
    finish(current_);
    finish_polyline();
  }

 private:
  struct Polyline {
    std::string name;
    bool closed = false;
    bool mirrored = false;
    std::vector<Point> points;
    std::vector<double> bulges;
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
      if (!std::isfinite(bulge)) {
        fail_named(Kind::bad_curve, "vertex " + std::to_string(i) + " has a non-finite bulge", pl.name);
        return;
      }
      if (bulge != 0) {
        e.curved = true;
        e.arc = arc_from_bulge(a, b, bulge);
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
  std::string section_;
  std::size_t pairs_ = 0;
  Record current_;
  Record finished_;
  bool mirrored_ = false;
  std::optional<Polyline> polyline_;
};

}  // namespace

DxfContents read_dxf(const std::filesystem::path& path) {
  const std::string source = path.string();
  (void)open_for_reading(path);  // IoError with the project's message when unreadable
  Reader reader(source);
  // dxflib's std::istream entry point reads nothing (dxflib 3.26): the file entry point it is.
  DL_Dxf dxf;
  if (!dxf.in(source, &reader)) {
    throw DomainFileError(Kind::unreadable, "dxflib could not read the file as DXF", source);
  }
  reader.done();
  if (reader.error) {
    throw *reader.error;
  }
  return std::move(reader.contents);
}

}  // namespace frontpack::detail
