// Every bundled shape loads; areas are exact; orientation is normalised.
//
// The reference reads each file with Boost.Geometry's WKT reader (independent of ours) and sums
// the shoelace formula in exact rationals.
#include <gtest/gtest.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Polygon_2.h>

#include <boost/geometry.hpp>
#include <boost/geometry/geometries/multi_polygon.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/geometries/polygon.hpp>
#include <cmath>
#include <fstream>
#include <sstream>

#include "frontpack/frontpack.hpp"
#include "test_support.hpp"

namespace fp = frontpack;
namespace bg = boost::geometry;

namespace {

using BgPoint = bg::model::d2::point_xy<double>;
using BgPolygon = bg::model::polygon<BgPoint, false /* anticlockwise */>;
using BgMulti = bg::model::multi_polygon<BgPolygon>;

// The file's text without trailing white space (Boost.Geometry's reader rejects a final newline).
std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  std::string text = s.str();
  text.erase(text.find_last_not_of(" \t\r\n") + 1);
  return text;
}

template <class RingT>
CGAL::Gmpq twice_signed_area(const RingT& ring) {
  CGAL::Gmpq sum(0);
  for (std::size_t k = 0; k + 1 < ring.size(); ++k) {  // bg rings are closed
    sum +=
        CGAL::Gmpq(ring[k].x()) * CGAL::Gmpq(ring[k + 1].y()) - CGAL::Gmpq(ring[k].y()) * CGAL::Gmpq(ring[k + 1].x());
  }
  return sum;
}

CGAL::Gmpq abs(const CGAL::Gmpq& q) {
  return q < 0 ? -q : q;
}

// The exact area of a WKT geometry, read by Boost.Geometry.
CGAL::Gmpq reference_area(const std::string& wkt) {
  BgMulti multi;
  if (wkt.find("MULTIPOLYGON") != std::string::npos) {
    bg::read_wkt(wkt, multi);
  } else {
    BgPolygon p;
    bg::read_wkt(wkt, p);
    multi.push_back(p);
  }
  CGAL::Gmpq area(0);
  for (const BgPolygon& p : multi) {
    area += abs(twice_signed_area(p.outer()));
    for (const auto& hole : p.inners()) {
      area -= abs(twice_signed_area(hole));
    }
  }
  return area / 2;
}

// d is the double nearest to q: no neighbour of d is closer.
void expect_nearest(double d, const CGAL::Gmpq& q) {
  const CGAL::Gmpq err = abs(CGAL::Gmpq(d) - q);
  EXPECT_LE(err, abs(CGAL::Gmpq(std::nextafter(d, INFINITY)) - q)) << d;
  EXPECT_LE(err, abs(CGAL::Gmpq(std::nextafter(d, -INFINITY)) - q)) << d;
}

int orientation(const fp::Ring& ring) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  CGAL::Polygon_2<K> poly;
  for (const fp::Point& p : ring) {
    poly.push_back(K::Point_2(p.x, p.y));
  }
  return static_cast<int>(poly.orientation());
}

}  // namespace

TEST(Shapes, CorpusIsNotEmpty) {
  ASSERT_GE(fp::test::shape_files().size(), 12U);
}

TEST(Shapes, EveryShapeLoadsWithExactAreaAndNormalisedOrientation) {
  const auto files = fp::test::shape_files();
  ASSERT_FALSE(files.empty());
  for (const auto& file : files) {
    SCOPED_TRACE(file.string());
    const fp::Domain d = fp::Domain::from_wkt_file(file);
    expect_nearest(d.area(), reference_area(slurp(file)));
    EXPECT_GT(d.area(), 0.0);
    for (const fp::Polygon& p : d.polygons()) {
      EXPECT_EQ(orientation(p.outer), CGAL::COUNTERCLOCKWISE);
      for (const fp::Ring& h : p.holes) {
        EXPECT_EQ(orientation(h), CGAL::CLOCKWISE);
      }
    }
    // The bounding box is that of the vertices, and every vertex is on the boundary.
    fp::Box box;
    for (const fp::Polygon& p : d.polygons()) {
      for (const fp::Point& v : p.outer) {
        box.extend(v);
        EXPECT_EQ(d.locate(v), fp::Location::boundary);
      }
      for (const fp::Ring& h : p.holes) {
        for (const fp::Point& v : h) {
          box.extend(v);
          EXPECT_EQ(d.locate(v), fp::Location::boundary);
        }
      }
    }
    EXPECT_EQ(d.bbox(), box);
  }
}

TEST(Shapes, LShapeIsGivenClockwiseAndComesOutAnticlockwise) {
  const std::string text = slurp(fp::test::shapes_dir() / "l_shape.wkt");
  BgPolygon raw;
  bg::read_wkt(text, raw);
  ASSERT_LT(twice_signed_area(raw.outer()), 0) << "l_shape.wkt is meant to be written clockwise";
  const fp::Domain d = fp::Domain::from_wkt(text);
  EXPECT_EQ(orientation(d.polygons()[0].outer), CGAL::COUNTERCLOCKWISE);
  // The first vertex stays first.
  EXPECT_EQ(d.polygons()[0].outer[0].x, raw.outer()[0].x());
  EXPECT_EQ(d.polygons()[0].outer[0].y, raw.outer()[0].y());
}

TEST(Shapes, BigPolygonHasAtLeastTenThousandVertices) {
  const fp::Domain d = fp::Domain::from_wkt_file(fp::test::shapes_dir() / "big_polygon.wkt");
  EXPECT_GE(d.num_vertices(), 10000U);
}

TEST(Domain, RingsMayBeGivenOpenOrClosed) {
  const fp::Domain open = fp::Domain::from_rings({{0, 0}, {3, 0}, {3, 2}, {0, 2}});
  const fp::Domain closed = fp::Domain::from_rings({{0, 0}, {3, 0}, {3, 2}, {0, 2}, {0, 0}});
  EXPECT_EQ(open.polygons()[0].outer, closed.polygons()[0].outer);
  EXPECT_EQ(open.area(), 6.0);
}

TEST(Domain, HoleTouchingTheOuterRingAtOnePointIsValid) {
  // OGC (GEOS, Boost.Geometry): a hole may touch its shell at a single point.
  const fp::Domain d = fp::Domain::from_wkt_file(fp::test::shapes_dir() / "hole_touching.wkt");
  EXPECT_EQ(d.num_holes(), 1U);
  EXPECT_EQ(d.locate({2, 0}), fp::Location::boundary);
  EXPECT_EQ(d.locate({2, 1}), fp::Location::outside);  // inside the hole
}

TEST(Domain, ValidTouchesAreAccepted) {
  const char* valid[] = {
      // hole touching the shell at a shell vertex
      "POLYGON((0 0,4 0,4 4,0 4,0 0),(0 0,2 1,1 2,0 0))",
      // two holes touching each other at one point
      "POLYGON((0 0,4 0,4 4,0 4,0 0),(1 1,2 1,2 2,1 1),(2 1,3 1,3 2,2 1))",
      // three holes meeting at one common point (no loop)
      "POLYGON((0 0,6 0,6 6,0 6,0 0),(3 3,4 1,5 2,3 3),(3 3,2 5,1 4,3 3),(3 3,5 4,4 5,3 3))",
      // parts touching at a point
      "MULTIPOLYGON(((0 0,1 0,1 1,0 1,0 0)),((1 1,2 1,2 2,1 2,1 1)))",
      // an island inside the hole of another polygon
      "MULTIPOLYGON(((0 0,9 0,9 9,0 9,0 0),(2 2,2 7,7 7,7 2,2 2)),((3 3,6 3,6 6,3 6,3 3)))",
      // collinear consecutive edges (a redundant vertex) are fine
      "POLYGON((0 0,1 0,2 0,2 2,0 2,0 0))",
  };
  for (const char* text : valid) {
    SCOPED_TRACE(text);
    EXPECT_NO_THROW((void)fp::Domain::from_wkt(text));
  }
}

TEST(Domain, ErrorsCarryTheSite) {
  try {
    (void)fp::Domain::from_wkt("POLYGON((0 0,4 0,4 4,0 4,0 0),(1 1,3 1,3 3,1 3,1 1),(1 1.5,0.5 3,1.5 2.5,1 1.5))");
    FAIL() << "accepted a hole crossing another hole";
  } catch (const fp::InvalidDomainError& e) {
    EXPECT_EQ(e.kind(), fp::InvalidDomainError::Kind::rings_cross) << e.what();
    EXPECT_EQ(e.site().part, 0U);
    ASSERT_TRUE(e.other_site().has_value());
    EXPECT_NE(e.site().ring, e.other_site()->ring);
    EXPECT_TRUE(e.where().has_value());
  }
  try {
    (void)fp::Domain::from_rings({{0, 0}, {1, 0}, {NAN, 1}});
    FAIL() << "accepted NaN";
  } catch (const fp::InvalidDomainError& e) {
    EXPECT_EQ(e.kind(), fp::InvalidDomainError::Kind::non_finite_coordinate);
    EXPECT_EQ(e.site().vertex, 2U);
  }
  try {
    (void)fp::Domain::from_polygons({});
    FAIL() << "accepted no polygon";
  } catch (const fp::InvalidDomainError& e) {
    EXPECT_EQ(e.kind(), fp::InvalidDomainError::Kind::empty);
  }
}

TEST(Domain, IsCheapToCopyAndSharesTheGeometry) {
  const fp::Domain a = fp::Domain::from_rings({{0, 0}, {1, 0}, {1, 1}});
  const fp::Domain b = a;  // NOLINT(performance-unnecessary-copy-initialization)
  EXPECT_EQ(&a.polygons(), &b.polygons());
}
