// Domains from and to CGAL polygons with holes (include/frontpack/cgal.hpp).
#include <gtest/gtest.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <CGAL/Gmpq.h>

#include <cmath>

#include "frontpack/cgal.hpp"
#include "frontpack/frontpack.hpp"
#include "test_support.hpp"

namespace fp = frontpack;

TEST(CgalInterop, RoundTripThroughPolygonWithHoles) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  for (const char* shape : {"plate_with_holes.wkt", "islands.wkt", "l_shape.wkt"}) {
    SCOPED_TRACE(shape);
    const fp::Domain d = fp::Domain::from_wkt_file(fp::test::shapes_dir() / shape);
    const auto cgal = fp::to_cgal<K>(d);
    ASSERT_EQ(cgal.size(), d.num_polygons());
    for (const auto& pwh : cgal) {
      EXPECT_EQ(pwh.outer_boundary().orientation(), CGAL::COUNTERCLOCKWISE);
      for (auto h = pwh.holes_begin(); h != pwh.holes_end(); ++h) {
        EXPECT_EQ(h->orientation(), CGAL::CLOCKWISE);
      }
    }
    const fp::Domain back = fp::from_cgal(cgal);
    ASSERT_EQ(back.num_polygons(), d.num_polygons());
    for (std::size_t p = 0; p < d.num_polygons(); ++p) {
      EXPECT_EQ(back.polygons()[p].outer, d.polygons()[p].outer);
      EXPECT_EQ(back.polygons()[p].holes, d.polygons()[p].holes);
    }
    EXPECT_EQ(back.area(), d.area());
  }
}

TEST(CgalInterop, ExactKernelInputIsRoundedThenValidated) {
  using K = CGAL::Exact_predicates_exact_constructions_kernel;
  CGAL::Polygon_2<K> outer;
  outer.push_back(K::Point_2(0, 0));
  outer.push_back(K::Point_2(K::FT(1) / 3, 0));  // not a double: rounded by CGAL::to_double
  outer.push_back(K::Point_2(1, 1));
  const fp::Domain d = fp::from_cgal(CGAL::Polygon_with_holes_2<K>(outer));
  const double third = d.polygons()[0].outer[1].x;
  // One of the two doubles around 1/3 (CGAL::to_double is within an ulp, not always nearest).
  const CGAL::Gmpq exact(1, 3);
  EXPECT_TRUE((CGAL::Gmpq(third) <= exact && exact <= CGAL::Gmpq(std::nextafter(third, 1.0))) ||
              (CGAL::Gmpq(std::nextafter(third, 0.0)) <= exact && exact <= CGAL::Gmpq(third)))
      << third;

  CGAL::Polygon_2<K> bowtie;
  for (const auto& [x, y] : {std::pair{0, 0}, {1, 1}, {1, 0}, {0, 1}}) {
    bowtie.push_back(K::Point_2(x, y));
  }
  EXPECT_THROW((void)fp::from_cgal(CGAL::Polygon_with_holes_2<K>(bowtie)), fp::InvalidDomainError);
}
