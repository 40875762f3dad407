// The boundary front's pockets (src/generate/boundary/pocket.hpp), the largest circle touching
// three elements from outside, against closed forms: two disks resting on a wall's line and
// touching each other leave a cusp of radius rho with 1 / sqrt(rho) = 1 / sqrt(r1) + 1 / sqrt(r2)
// (r / 4 for equal disks); three disks touching pairwise one of curvature k1 + k2 + k3 +
// 2 sqrt(k1 k2 + k2 k3 + k3 k1) (Descartes); a disk inscribed in a corner of angle 2 phi leaves,
// between itself and the corner's vertex, one of r (1 - sin phi) / (1 + sin phi) (both circles'
// centres on the bisector, at their radius over sin phi from the vertex); and a circle touching a
// wall at its end's vertex is found from a disk placed tangent to it. Equal disks on a wall make
// the quadratic's leading coefficient 0 up to rounding, where a solver that cancels loses the
// root: the walls here turn through many angles so that rounding leaves it a few ulps either side
// of 0.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstddef>

#include "generate/boundary/pocket.hpp"
#include "generate/scale.hpp"

namespace {

using frontpack::detail::LengthScale;
using frontpack::detail::pocket_at_line;
using frontpack::detail::pocket_at_two_walls;
using frontpack::detail::pocket_at_wall_end;
using frontpack::detail::pocket_of_nodes;
using frontpack::detail::V2;
using frontpack::detail::Wall;

struct Node {
  double x, y, r;
};

// The wall from a in direction theta, the domain on its left.
Wall wall_at(double ax, double ay, double theta, double len) {
  const double tx = std::cos(theta);
  const double ty = std::sin(theta);
  return Wall{ax, ay, ax + len * tx, ay + len * ty, tx, ty, -ty, tx, len, -ty * ax + tx * ay};
}

// A disk of radius r resting on the wall at distance s along it.
Node on_wall(const Wall& w, double s, double r) {
  return Node{w.ax + s * w.tx + r * w.nx, w.ay + s * w.ty + r * w.ny, r};
}

constexpr double kPi = 3.141592653589793;

double cusp(double r1, double r2) {
  const double k = 1 / std::sqrt(r1) + 1 / std::sqrt(r2);
  return 1 / (k * k);
}

TEST(Pocket, CuspOfTwoDisksOnAWall) {
  for (const double scale : {1e-3, 1.0, 1e4}) {
    for (const std::array<double, 2> radii : {std::array<double, 2>{1, 1}, {1, 1.4}, {0.3, 1}, {1, 10}}) {
      for (int step = 0; step < 360; ++step) {
        const double theta = step * (2 * kPi / 360) + 0.001;
        const double r1 = radii[0] * scale;
        const double r2 = radii[1] * scale;
        const Wall w = wall_at(3.7 * scale, -1.3 * scale, theta, 100 * scale);
        const Node a = on_wall(w, 10 * scale, r1);
        const Node b = on_wall(w, 10 * scale + 2 * std::sqrt(r1 * r2), r2);  // touching a
        SCOPED_TRACE(testing::Message() << "scale " << scale << " radii " << r1 << ", " << r2 << " theta " << theta);
        const double expected = cusp(r1, r2);
        EXPECT_NEAR(pocket_at_line(w, a, b), expected, 1e-9 * expected);
        EXPECT_NEAR(pocket_at_line(w, b, a), expected, 1e-9 * expected);
      }
    }
  }
}

TEST(Pocket, ThreeTouchingDisksLanesAndScalarAlike) {
  const LengthScale unit(2.0);
  for (const std::array<double, 3> r : {std::array<double, 3>{1, 1, 1}, {1, 1.4, 1}, {1, 2, 5}, {0.1, 1, 1}}) {
    for (int step = 0; step < 36; ++step) {
      const double theta = step * (2 * kPi / 36) + 0.01;
      // b touching a, and d touching both on the left of a -> b: the pocket lies between the
      // three, on the left of a -> b.
      const Node a{0.25, -0.5, r[0]};
      const Node b{a.x + (r[0] + r[1]) * std::cos(theta), a.y + (r[0] + r[1]) * std::sin(theta), r[1]};
      const double ab = r[0] + r[1];
      const double ad = r[0] + r[2];
      const double bd = r[1] + r[2];
      const double along = (ab * ab + ad * ad - bd * bd) / (2 * ab);
      const double off = std::sqrt(ad * ad - along * along);
      const double ux = (b.x - a.x) / ab;
      const double uy = (b.y - a.y) / ab;
      const Node d{a.x + along * ux - off * uy, a.y + along * uy + off * ux, r[2]};
      const double k1 = 1 / r[0];
      const double k2 = 1 / r[1];
      const double k3 = 1 / r[2];
      const double expected = 1 / (k1 + k2 + k3 + 2 * std::sqrt(k1 * k2 + k2 * k3 + k3 * k1));
      SCOPED_TRACE(testing::Message() << "radii " << r[0] << ", " << r[1] << ", " << r[2] << " theta " << theta);
      const double scalar = pocket_of_nodes<double>(a.x, a.y, a.r, b.x, b.y, b.r, d.x, d.y, d.r, unit);
      EXPECT_NEAR(scalar, expected, 1e-9 * expected);
      const V2 lanes = pocket_of_nodes<V2>(V2{a.x, b.x}, V2{a.y, b.y}, V2{a.r, b.r}, V2{b.x, a.x}, V2{b.y, a.y},
                                           V2{b.r, a.r}, V2{d.x, d.x}, V2{d.y, d.y}, V2{d.r, d.r}, unit);
      // The same bits in a lane as in a double, b -> a too (where the pocket lies on the right).
      EXPECT_EQ(lanes[0], scalar);
      EXPECT_EQ(lanes[1], pocket_of_nodes<double>(b.x, b.y, b.r, a.x, a.y, a.r, d.x, d.y, d.r, unit));
    }
  }
}

TEST(Pocket, DiskInscribedInACorner) {
  for (const double scale : {1e-3, 1.0, 1e4}) {
    // Corners of 20 to 170 degrees (2 phi), their bisectors turned through the whole circle.
    for (int opening = 20; opening <= 170; opening += 10) {
      const double phi = opening * kPi / 360;
      for (int step = 0; step < 72; ++step) {
        const double beta = step * (2 * kPi / 72) + 0.003;
        const double len = 50 * scale;
        const double vx = -2.1 * scale;
        const double vy = 0.7 * scale;
        // The domain is the wedge between the walls, on the left of each: one wall runs from the
        // vertex at angle beta - phi, the other back into the vertex from angle beta + phi.
        const Wall out = wall_at(vx, vy, beta - phi, len);
        const Wall in =
            wall_at(vx + len * std::cos(beta + phi), vy + len * std::sin(beta + phi), beta + phi + kPi, len);
        const double r = 1.3 * scale;
        const double d = r / std::sin(phi);
        const Node disk{vx + d * std::cos(beta), vy + d * std::sin(beta), r};
        const double expected = r * (1 - std::sin(phi)) / (1 + std::sin(phi));
        SCOPED_TRACE(testing::Message() << "scale " << scale << " opening " << opening << " beta " << beta);
        EXPECT_NEAR(pocket_at_two_walls(out, in, disk), expected, 1e-9 * expected);
        EXPECT_NEAR(pocket_at_two_walls(in, out, disk), expected, 1e-9 * expected);
      }
    }
  }
}

TEST(Pocket, CircleTouchingAWallAtItsEnd) {
  for (const double scale : {1e-3, 1.0, 1e4}) {
    for (int step = 0; step < 72; ++step) {
      const double theta = step * (2 * kPi / 72) + 0.007;
      const Wall w = wall_at(1.1 * scale, 2.9 * scale, theta, 20 * scale);
      const Node end{w.bx, w.by, 0};  // the reflex vertex at the wall's end
      // A circle of radius rho touching the wall's line at its end (its centre rho along the
      // normal), and a disk touching it from outside on either side, above the line.
      for (const double rho : {0.2, 1.0, 3.0}) {
        for (const double alpha : {0.3, 1.2, 2.0, 2.8}) {
          const double rj = 0.7 * scale;
          const double cx = end.x + rho * scale * w.nx;
          const double cy = end.y + rho * scale * w.ny;
          const double dir_x = std::cos(alpha) * w.tx + std::sin(alpha) * w.nx;
          const double dir_y = std::cos(alpha) * w.ty + std::sin(alpha) * w.ny;
          const Node disk{cx + (rho * scale + rj) * dir_x, cy + (rho * scale + rj) * dir_y, rj};
          SCOPED_TRACE(testing::Message()
                       << "scale " << scale << " theta " << theta << " rho " << rho << " alpha " << alpha);
          EXPECT_NEAR(pocket_at_wall_end(w, end, disk), rho * scale, 1e-9 * rho * scale);
        }
      }
    }
  }
}

}  // namespace
