// Metamorphic properties: transforming the domain by an exact map transforms every answer the
// same way. Translations by an exactly representable offset, scaling by 2, reversing the ring
// orientation, and reordering holes or polygons must change nothing but the coordinates.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <random>
#include <vector>

#include "frontpack/frontpack.hpp"
#include "test_support.hpp"

namespace fp = frontpack;

namespace {

using Map = std::function<fp::Point(fp::Point)>;

fp::Ring map_ring(const fp::Ring& ring, const Map& f) {
  fp::Ring out;
  for (const fp::Point& p : ring) {
    out.push_back(f(p));
  }
  return out;
}

std::vector<fp::Polygon> map_polygons(const fp::Domain& d, const Map& f) {
  std::vector<fp::Polygon> out;
  for (const fp::Polygon& p : d.polygons()) {
    fp::Polygon q;
    q.outer = map_ring(p.outer, f);
    for (const fp::Ring& h : p.holes) {
      q.holes.push_back(map_ring(h, f));
    }
    out.push_back(std::move(q));
  }
  return out;
}

// Deterministic query points: vertices, edge midpoints (exact when the map is), and a lattice
// over the bounding box. Doubles made from integers, never from <random> distributions.
std::vector<fp::Point> queries(const fp::Domain& d) {
  std::vector<fp::Point> q;
  for (const fp::Polygon& p : d.polygons()) {
    for (std::size_t k = 0; k < p.outer.size(); k += 1 + p.outer.size() / 64) {
      const fp::Point a = p.outer[k];
      const fp::Point b = p.outer[(k + 1) % p.outer.size()];
      q.push_back(a);
      q.push_back({(a.x + b.x) / 2, (a.y + b.y) / 2});
    }
  }
  const fp::Box b = d.bbox();
  std::mt19937_64 rng(42);
  for (int i = 0; i < 2000; ++i) {
    const double u = static_cast<double>(rng() >> 11) * 0x1p-53;
    const double v = static_cast<double>(rng() >> 11) * 0x1p-53;
    q.push_back({b.xmin + u * (b.xmax - b.xmin), b.ymin + v * (b.ymax - b.ymin)});
  }
  return q;
}

struct Answers {
  std::vector<fp::Location> locations;
  std::vector<std::uint8_t> contains;
};

Answers answer(const fp::Domain& d, const std::vector<fp::Point>& points, double radius, const Map& f,
               double radius_scale) {
  Answers a;
  std::vector<fp::Disk> disks;
  for (const fp::Point& p : points) {
    a.locations.push_back(d.locate(f(p)));
    disks.push_back({f(p), radius * radius_scale});
  }
  a.contains.resize(disks.size());
  d.contains(disks, a.contains);
  return a;
}

void expect_same(const Answers& x, const Answers& y) {
  ASSERT_EQ(x.locations.size(), y.locations.size());
  for (std::size_t i = 0; i < x.locations.size(); ++i) {
    EXPECT_EQ(x.locations[i], y.locations[i]) << "query " << i;
    EXPECT_EQ(x.contains[i], y.contains[i]) << "query " << i;
  }
}

// `snap` moves each query point to a nearby point on which f is exact.
void check_transform(const fp::Domain& d, const Map& f, double radius_scale, double area_scale, const Map& snap) {
  const fp::Domain t = fp::Domain::from_polygons(map_polygons(d, f));
  EXPECT_EQ(t.area(), d.area() * area_scale);
  auto pts = queries(d);
  for (fp::Point& p : pts) {
    p = snap(p);
  }
  const double r = std::min(d.bbox().width(), d.bbox().height()) / 50;
  const Map id = [](fp::Point p) { return p; };
  expect_same(answer(d, pts, r, id, 1.0), answer(t, pts, r, f, radius_scale));
}

}  // namespace

class Metamorphic : public ::testing::TestWithParam<std::string> {};

TEST_P(Metamorphic, TranslationByAnExactOffset) {
  const fp::Domain original = fp::Domain::from_wkt_file(fp::test::shapes_dir() / GetParam());
  // Snap the shape to a dyadic grid 2^-30 of its size so that a translation by a power of two
  // above its coordinates is exact (decimal inputs such as 0.1 use all 53 bits otherwise).
  const int e = std::ilogb(original.max_abs_coordinate());
  const double grid = std::ldexp(1.0, e - 30);
  const fp::Domain d = fp::Domain::from_polygons(map_polygons(original, [grid](fp::Point p) {
    return fp::Point{std::round(p.x / grid) * grid, std::round(p.y / grid) * grid};
  }));
  const double offset = std::ldexp(1.0, e + 3);
  for (const fp::Polygon& p : d.polygons()) {
    for (const fp::Point& v : p.outer) {
      ASSERT_EQ((v.x + offset) - offset, v.x);
      ASSERT_EQ((v.y - offset) + offset, v.y);
    }
  }
  // (p + o) - o is exact for |p| <= o / 4 (Sterbenz), and so is adding o to the result.
  check_transform(
      d,
      [offset](fp::Point p) {
        return fp::Point{p.x + offset, p.y - offset};
      },
      1.0, 1.0,
      [offset](fp::Point p) {
        return fp::Point{(p.x + offset) - offset, (p.y - offset) + offset};
      });
}

TEST_P(Metamorphic, ScalingByTwo) {
  const fp::Domain d = fp::Domain::from_wkt_file(fp::test::shapes_dir() / GetParam());
  check_transform(
      d,
      [](fp::Point p) {
        return fp::Point{2 * p.x, 2 * p.y};
      },
      2.0, 4.0, [](fp::Point p) { return p; });
}

TEST_P(Metamorphic, MirrorSwapsOrientationButNotAnswers) {
  const fp::Domain d = fp::Domain::from_wkt_file(fp::test::shapes_dir() / GetParam());
  check_transform(
      d,
      [](fp::Point p) {
        return fp::Point{-p.x, p.y};
      },
      1.0, 1.0, [](fp::Point p) { return p; });
}

TEST_P(Metamorphic, ReversedRingsAndReorderedHolesAndPolygons) {
  const fp::Domain d = fp::Domain::from_wkt_file(fp::test::shapes_dir() / GetParam());
  std::vector<fp::Polygon> polys = d.polygons();
  for (fp::Polygon& p : polys) {
    std::reverse(p.outer.begin(), p.outer.end());
    std::rotate(p.outer.begin(), p.outer.begin() + 1, p.outer.end());
    for (fp::Ring& h : p.holes) {
      std::reverse(h.begin(), h.end());
    }
    std::reverse(p.holes.begin(), p.holes.end());
  }
  std::reverse(polys.begin(), polys.end());
  const fp::Domain t = fp::Domain::from_polygons(polys);
  EXPECT_EQ(t.area(), d.area());
  EXPECT_EQ(t.bbox(), d.bbox());
  const auto pts = queries(d);
  const Map id = [](fp::Point p) { return p; };
  const double r = std::min(d.bbox().width(), d.bbox().height()) / 50;
  expect_same(answer(d, pts, r, id, 1.0), answer(t, pts, r, id, 1.0));
}

INSTANTIATE_TEST_SUITE_P(Shapes, Metamorphic,
                         ::testing::Values("unit_square.wkt", "concave_polygon.wkt", "l_shape.wkt",
                                           "plate_with_holes.wkt", "annulus.wkt", "islands.wkt", "gear.wkt", "comb.wkt",
                                           "hole_touching.wkt", "offset_1e6.wkt", "millimetre.wkt",
                                           "narrow_channel.wkt"),
                         [](const auto& param_info) {
                           std::string name = param_info.param;
                           name = name.substr(0, name.find('.'));
                           return name;
                         });
