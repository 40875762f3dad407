// Domains from CAD and GIS files (include/frontpack/domain_file.hpp): the fixtures of
// tests/data/cad/ (made by ezdxf and ogr2ogr, tests/data/cad/make_fixtures.py) read to the
// expected polygons, holes and areas; every arc's polyline lies on the domain's side of the true
// circle, checked exactly here with CGAL's exact kernel; and each kind of bad file gives its error.
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "frontpack/frontpack.hpp"

namespace {

using K = CGAL::Exact_predicates_exact_constructions_kernel;
using frontpack::DomainFile;
using frontpack::read_domain_file;

const std::string kDir = std::string(FRONTPACK_TEST_DATA_DIR) + "/cad/";

K::FT sq(double v) {
  return K::FT(v) * K::FT(v);
}

// Exact: every vertex of `ring` in the closed disk (chords of a wall the domain is inside).
[[maybe_unused]] bool vertices_in_disk(const frontpack::Ring& ring, frontpack::Point c, double r) {
  for (const auto& p : ring) {
    if (CGAL::squared_distance(K::Point_2(p.x, p.y), K::Point_2(c.x, c.y)) > sq(r)) {
      return false;
    }
  }
  return true;
}

// Exact: no edge of `ring` enters the open disk (tangents around a hole).
[[maybe_unused]] bool edges_off_disk(const frontpack::Ring& ring, frontpack::Point c, double r) {
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const auto& a = ring[i];
    const auto& b = ring[(i + 1) % ring.size()];
    const K::Segment_2 s(K::Point_2(a.x, a.y), K::Point_2(b.x, b.y));
    if (CGAL::squared_distance(K::Point_2(c.x, c.y), s) < sq(r)) {
      return false;
    }
  }
  return true;
}

// The polygonal domain lies inside the true one: its area is below the true area, and by at most
// the deviation times the curves' length.
[[maybe_unused]] void expect_area(const DomainFile& f, double true_area, double curve_length) {
  double deviation = 0;
  for (const auto& c : f.curves) {
    deviation = std::max(deviation, c.deviation);
  }
  EXPECT_LE(f.domain.area(), true_area * (1 + 1e-14));
  EXPECT_GE(f.domain.area(), true_area - curve_length * deviation * (1 + 1e-9));
}

template <typename E>
std::string error_of(const std::string& file, const frontpack::DomainReadOptions& o = {}) {
  try {
    (void)read_domain_file(kDir + file, o);
  } catch (const E& e) {
    return e.what();
  }
  ADD_FAILURE() << file << ": no error of the expected type";
  return {};
}

// Without a reader, its formats are refused with an OptionError; the reader tests below are
// compiled only where the build has the reader.
TEST(CadTest, BuildStatesItsReaders) {
  EXPECT_EQ(frontpack::has_dxf_reader(), FRONTPACK_TEST_DXF != 0);
  EXPECT_EQ(frontpack::has_gis_reader(), FRONTPACK_TEST_GIS != 0);
  if (!frontpack::has_dxf_reader()) {
    const std::string e = error_of<frontpack::OptionError>("drum.dxf");
    EXPECT_NE(e.find("built without dxflib"), std::string::npos) << e;
  }
  if (!frontpack::has_gis_reader()) {
    const std::string e = error_of<frontpack::OptionError>("plate.geojson");
    EXPECT_NE(e.find("built without GDAL"), std::string::npos) << e;
  }
  EXPECT_EQ(read_domain_file(std::string(FRONTPACK_SHAPES_DIR) + "/annulus.wkt").format, frontpack::DomainFormat::wkt);
}

#if FRONTPACK_TEST_DXF
class DxfTest : public ::testing::Test {};

TEST_F(DxfTest, DrumIsA64GonOfChordsAroundATangentPolygonHole) {
  // A deviation just above that of a 64-gon of chords of the unit outer wall.
  frontpack::DomainReadOptions o;
  o.max_deviation = (1 - std::cos(std::numbers::pi / 64)) * 1.0001;
  const DomainFile f = read_domain_file(kDir + "drum.dxf", o);
  EXPECT_EQ(f.format, frontpack::DomainFormat::dxf);
  ASSERT_EQ(f.domain.num_polygons(), 1u);
  ASSERT_EQ(f.domain.num_holes(), 1u);
  EXPECT_EQ(f.ignored_entities, 1u);  // the TEXT
  ASSERT_EQ(f.curves.size(), 2u);
  EXPECT_TRUE(f.curves[0].domain_inside);
  EXPECT_EQ(f.curves[0].segments, 64u);
  EXPECT_FALSE(f.curves[1].domain_inside);
  EXPECT_NE(f.curves[0].entity.find("CIRCLE (handle"), std::string::npos) << f.curves[0].entity;
  const auto& poly = f.domain.polygons()[0];
  EXPECT_EQ(poly.outer.size(), 64u);
  EXPECT_TRUE(vertices_in_disk(poly.outer, {10.1, 20.3}, 1.0));
  EXPECT_TRUE(edges_off_disk(poly.holes[0], {10.4, 20.4}, 0.25));
  const double pi = std::numbers::pi;
  expect_area(f, pi * (1 - 0.0625), 2 * pi * 1.25);
  for (const auto& c : f.curves) {
    EXPECT_LE(c.deviation, o.max_deviation);
  }
}

TEST_F(DxfTest, RoundedVerticesAreMovedToTheSafeSide) {
  // 41 circles about (1e5, -3e4): ulps of 1.5e-11 against radii of 1 to 50.
  const DomainFile f = read_domain_file(kDir + "many_pipes.dxf");
  ASSERT_EQ(f.domain.num_polygons(), 1u);
  ASSERT_EQ(f.domain.num_holes(), 40u);
  ASSERT_EQ(f.curves.size(), 41u);
  std::size_t nudged = 0;
  for (const auto& c : f.curves) {
    nudged += c.nudged;
  }
  EXPECT_GT(nudged, 0u) << "no vertex needed moving: the fixture no longer tests the rounding";
  const auto& poly = f.domain.polygons()[0];
  EXPECT_TRUE(vertices_in_disk(poly.outer, f.curves[0].centre, f.curves[0].radius));
  for (std::size_t h = 0; h < poly.holes.size(); ++h) {
    EXPECT_TRUE(edges_off_disk(poly.holes[h], f.curves[h + 1].centre, f.curves[h + 1].radius)) << "hole " << h;
  }
}

TEST_F(DxfTest, BulgesGiveConvexEndConcaveNotchAndHole) {
  const DomainFile f = read_domain_file(kDir + "bulge_plate.dxf");
  ASSERT_EQ(f.domain.num_polygons(), 1u);
  ASSERT_EQ(f.domain.num_holes(), 1u);
  ASSERT_EQ(f.curves.size(), 4u);
  EXPECT_FALSE(f.curves[0].domain_inside);  // the notch, bulge -1 on edge 1
  EXPECT_NE(f.curves[0].entity.find("LWPOLYLINE (handle 2F, line 2026), edge 1"), std::string::npos)
      << f.curves[0].entity;
  EXPECT_TRUE(f.curves[1].domain_inside);   // the half-disk end
  EXPECT_FALSE(f.curves[2].domain_inside);  // the hole's two halves
  EXPECT_FALSE(f.curves[3].domain_inside);
  EXPECT_NEAR(f.curves[1].radius, 0.5, 1e-15);
  EXPECT_NEAR(f.curves[2].radius, 0.2, 1e-15);
  const double pi = std::numbers::pi;
  expect_area(f, 2 + pi / 8 - pi / 32 - pi / 25, pi * (0.5 + 0.25 + 0.4));
  const auto& poly = f.domain.polygons()[0];
  EXPECT_TRUE(edges_off_disk(poly.holes[0], f.curves[2].centre, f.curves[2].radius));
  EXPECT_TRUE(edges_off_disk(poly.outer, f.curves[0].centre, f.curves[0].radius));  // the notch
}

TEST_F(DxfTest, NearlyFlatArcKeepsItsTangentVertexAccurate) {
  const DomainFile f = read_domain_file(kDir + "flat_bulge.dxf");
  ASSERT_EQ(f.curves.size(), 1u);
  const auto& c = f.curves[0];
  EXPECT_FALSE(c.domain_inside);
  EXPECT_GT(c.radius, 2e5);
  EXPECT_EQ(c.segments, 2u);  // one step: start tangent, end tangent
  const auto& ring = f.domain.polygons()[0].outer;
  ASSERT_EQ(ring.size(), 5u);
  // The tangent vertex is above the chord's midpoint by (L/2) tan(sweep/4 * 2) ~ the sagitta.
  bool found = false;
  for (const auto& p : ring) {
    if (std::abs(p.x - (1e4 + 0.5)) < 1e-9) {
      found = true;
      EXPECT_NEAR(p.y, 1e4 + 1 - 1e-6, 1e-9);
      // Exactly outside the open disk: no nearer the centre than the radius.
      EXPECT_GE(CGAL::squared_distance(K::Point_2(p.x, p.y), K::Point_2(c.centre.x, c.centre.y)), sq(c.radius));
    }
  }
  EXPECT_TRUE(found);
  expect_area(f, 1 - 2.0 / 3 * 1.0 * 5e-7, 1.0);
}

TEST_F(DxfTest, LinesAndArcsJoinIntoAStadium) {
  const DomainFile f = read_domain_file(kDir + "line_arc.dxf");
  ASSERT_EQ(f.domain.num_polygons(), 1u);
  EXPECT_EQ(f.domain.num_holes(), 0u);
  EXPECT_EQ(f.contours, 1u);
  ASSERT_EQ(f.curves.size(), 2u);
  EXPECT_TRUE(f.curves[0].domain_inside);
  EXPECT_TRUE(f.curves[1].domain_inside);  // the mirrored one (extrusion 0 0 -1) bulges right
  const frontpack::Box b = f.domain.bbox();
  EXPECT_NEAR(b.xmin, -0.5, 1e-3);
  EXPECT_NEAR(b.xmax, 2.5, 1e-3);
  expect_area(f, 2 + std::numbers::pi / 4, std::numbers::pi);
}

TEST_F(DxfTest, NestedContoursAlternateOuterAndHole) {
  const DomainFile f = read_domain_file(kDir + "nested.dxf");
  EXPECT_EQ(f.domain.num_polygons(), 2u);
  EXPECT_EQ(f.domain.num_holes(), 1u);
  ASSERT_EQ(f.curves.size(), 3u);
  EXPECT_TRUE(f.curves[0].domain_inside);
  EXPECT_FALSE(f.curves[1].domain_inside);
  EXPECT_TRUE(f.curves[2].domain_inside);
  expect_area(f, 6 * std::numbers::pi, 12 * std::numbers::pi);
}

TEST_F(DxfTest, ErrorsNameTheFileAndEntity) {
  using frontpack::DomainFileError;
  const std::string open = error_of<DomainFileError>("open_polyline.dxf");
  EXPECT_NE(open.find("open_polyline.dxf: LWPOLYLINE (handle 2F, line 2026)"), std::string::npos) << open;
  EXPECT_NE(open.find("open contour: its end (1 1)"), std::string::npos) << open;
  const std::string chain = error_of<DomainFileError>("open_chain.dxf");
  EXPECT_NE(chain.find("open contour"), std::string::npos) << chain;
  const std::string ellipse = error_of<DomainFileError>("ellipse.dxf");
  EXPECT_NE(ellipse.find("ELLIPSE (handle "), std::string::npos) << ellipse;
  EXPECT_NE(ellipse.find("convert it to a polyline"), std::string::npos) << ellipse;
  const std::string empty = error_of<DomainFileError>("empty.dxf");
  EXPECT_NE(empty.find("no closed contour"), std::string::npos) << empty;
  const std::string crossing = error_of<frontpack::InvalidDomainError>("crossing.dxf");
  EXPECT_NE(crossing.find("crossing.dxf"), std::string::npos) << crossing;
  EXPECT_NE(crossing.find("CIRCLE (handle"), std::string::npos) << crossing;
  frontpack::DomainReadOptions tiny;
  tiny.max_deviation = 1e-15;
  const std::string dev = error_of<frontpack::OptionError>("drum.dxf", tiny);
  EXPECT_NE(dev.find("too small"), std::string::npos) << dev;
  EXPECT_THROW((void)read_domain_file(kDir + "missing.dxf"), frontpack::IoError);
  // Any other extension is WKT.
  const std::string py = error_of<frontpack::WktError>("make_fixtures.py");
  EXPECT_NE(py.find("WKT error in '"), std::string::npos) << py;
}

#endif  // FRONTPACK_TEST_DXF

#if FRONTPACK_TEST_GIS
class GisTest : public ::testing::Test {};

TEST_F(GisTest, GeoJsonPolygonWithHole) {
  const DomainFile f = read_domain_file(kDir + "plate.geojson");
  EXPECT_EQ(f.format, frontpack::DomainFormat::geojson);
  EXPECT_EQ(f.domain.num_polygons(), 1u);
  EXPECT_EQ(f.domain.num_holes(), 1u);
  EXPECT_EQ(f.domain.area(), 3.0);
}

TEST_F(GisTest, ShapefileMultipolygon) {
  const DomainFile f = read_domain_file(kDir + "islands.shp");
  EXPECT_EQ(f.format, frontpack::DomainFormat::shapefile);
  EXPECT_EQ(f.domain.num_polygons(), 2u);
  EXPECT_EQ(f.domain.num_holes(), 1u);
  EXPECT_EQ(f.domain.area(), 4.75);
}

TEST_F(GisTest, OtherGeometriesAreRefused) {
  const std::string e = error_of<frontpack::DomainFileError>("points.geojson");
  EXPECT_NE(e.find("points.geojson: layer points, feature 0: geometry type Point"), std::string::npos) << e;
  frontpack::DomainReadOptions as_geojson;
  as_geojson.format = frontpack::DomainFormat::geojson;
  const std::string bad = error_of<frontpack::DomainFileError>("drum.dxf", as_geojson);
  EXPECT_NE(bad.find("could not read the file as GeoJSON"), std::string::npos) << bad;
}

#endif  // FRONTPACK_TEST_GIS

}  // namespace
