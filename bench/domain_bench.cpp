// Domain benchmarks: loading + validating large WKT polygons, and exact batch classification of
// many disks against a many-edge domain. Run:
//   build/release/bench/frontpack_bench_domain
// Figures are recorded in docs/performance.md.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "frontpack/frontpack.hpp"

namespace fp = frontpack;

namespace {

void append_point(std::string& out, fp::Point p) {
  char buf[64];
  const int n = std::snprintf(buf, sizeof buf, "%.17g %.17g", p.x, p.y);
  out.append(buf, static_cast<std::size_t>(n));
}

void append_ring(std::string& out, const std::vector<fp::Point>& ring) {
  out.push_back('(');
  for (std::size_t k = 0; k <= ring.size(); ++k) {
    if (k > 0) {
      out.push_back(',');
    }
    append_point(out, ring[k % ring.size()]);
  }
  out.push_back(')');
}

// A star-shaped ring with n vertices (strictly increasing angles, so it is simple) whose radius
// wiggles between 0.9 and 1.1, and `holes` small square holes on a circle of radius 0.5.
// Deterministic: the wiggle comes from a fixed-seed generator's integers.
std::string big_polygon_wkt(std::size_t n, std::size_t holes) {
  std::mt19937_64 rng(2003);
  std::vector<fp::Point> ring;
  for (std::size_t k = 0; k < n; ++k) {
    const double t = 2 * std::numbers::pi * static_cast<double>(k) / static_cast<double>(n);
    const double r = 1.0 + 0.1 * std::sin(37 * t) + 0.001 * (static_cast<double>(rng() >> 11) * 0x1p-53 - 0.5);
    ring.push_back({r * std::cos(t), r * std::sin(t)});
  }
  std::string wkt = "POLYGON(";
  append_ring(wkt, ring);
  for (std::size_t h = 0; h < holes; ++h) {
    const double t = 2 * std::numbers::pi * static_cast<double>(h) / static_cast<double>(holes);
    const double cx = 0.5 * std::cos(t);
    const double cy = 0.5 * std::sin(t);
    const double s = 0.02;
    wkt.push_back(',');
    append_ring(wkt, {{cx - s, cy - s}, {cx - s, cy + s}, {cx + s, cy + s}, {cx + s, cy - s}});
  }
  wkt.push_back(')');
  return wkt;
}

// Disks of radius 5e-4..5e-3 on a jittered lattice over the domain's box (about n of them).
std::vector<fp::Disk> disks_over(const fp::Box& box, std::size_t n) {
  std::mt19937_64 rng(77);
  const auto side = static_cast<std::size_t>(std::sqrt(static_cast<double>(n)));
  std::vector<fp::Disk> disks;
  disks.reserve(side * side);
  for (std::size_t i = 0; i < side; ++i) {
    for (std::size_t j = 0; j < side; ++j) {
      const double u = (static_cast<double>(i) + 0.5) / static_cast<double>(side);
      const double v = (static_cast<double>(j) + 0.5) / static_cast<double>(side);
      const double r = 5e-4 + 4.5e-3 * (static_cast<double>(rng() >> 11) * 0x1p-53);
      disks.push_back({{box.xmin + u * box.width(), box.ymin + v * box.height()}, r});
    }
  }
  return disks;
}

void BM_LoadWkt(benchmark::State& state) {
  const std::string wkt = big_polygon_wkt(static_cast<std::size_t>(state.range(0)), 16);
  for (auto _ : state) {
    fp::Domain d = fp::Domain::from_wkt(wkt);
    benchmark::DoNotOptimize(d);
  }
  state.counters["vertices"] = static_cast<double>(state.range(0) + 16 * 4);
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_LoadWkt)->Arg(10'000)->Arg(100'000)->Unit(benchmark::kMillisecond);

// A star of n spikes alternately at radius 1 and 2: its edges fan around the unit disk, so their
// boxes meet in about n^2 / 22 pairs though no two edges meet. Validation's worst case for the
// box pass; the sweep (src/domain/validate.cpp, edges_disjoint) decides it.
void BM_ValidateStar(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  std::vector<fp::Point> ring;
  for (std::size_t k = 0; k < n; ++k) {
    const double t = 2 * std::numbers::pi * static_cast<double>(k) / static_cast<double>(n);
    const double r = k % 2 == 0 ? 1.0 : 2.0;
    ring.push_back({r * std::cos(t), r * std::sin(t)});
  }
  for (auto _ : state) {
    fp::Domain d = fp::Domain::from_rings(ring);
    benchmark::DoNotOptimize(d);
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_ValidateStar)->Arg(50'000)->Arg(200'000)->Unit(benchmark::kMillisecond);

// The unit square with lower left corner (x, y).
fp::Ring unit_square(double x, double y) {
  return {{x, y}, {x + 1, y}, {x + 1, y + 1}, {x, y + 1}};
}

// A checkerboard of n x n / 2 unit squares as a multipolygon (n = 128: 8,192 parts, 32,768
// vertices): neighbouring parts touch at corners, so every vertex is a touch point. Ray parity
// per ring made this quadratic (174 s at n = 128); the nesting sweep (src/domain/ring_tree.cpp) decides it.
void BM_ValidateCheckerboard(benchmark::State& state) {
  const auto n = static_cast<int>(state.range(0));
  std::vector<fp::Polygon> parts;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      if ((i + j) % 2 == 0) {
        parts.push_back({unit_square(i, j), {}});
      }
    }
  }
  for (auto _ : state) {
    fp::Domain d = fp::Domain::from_polygons(parts);
    benchmark::DoNotOptimize(d);
  }
  state.counters["parts"] = static_cast<double>(parts.size());
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(4 * parts.size()));
}
BENCHMARK(BM_ValidateCheckerboard)->Arg(128)->Unit(benchmark::kMillisecond);

// One polygon: a frame around an n x n board whose squares are holes where keep(i, j) holds.
template <class Keep>
std::vector<fp::Polygon> board_of_holes(int n, Keep keep) {
  fp::Polygon p{{{-1, -1}, {n + 1.0, -1}, {n + 1.0, n + 1.0}, {-1, n + 1.0}}, {}};
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      if (keep(i, j)) {
        p.holes.push_back(unit_square(i, j));
      }
    }
  }
  return {p};
}

// Holes along every third diagonal of the board, touching their diagonal neighbours at corners:
// chains of touching holes, valid (n = 128: 5,462 holes).
void BM_ValidateTouchingHoles(benchmark::State& state) {
  const auto n = static_cast<int>(state.range(0));
  const std::vector<fp::Polygon> polygon = board_of_holes(n, [](int i, int j) { return ((j - i) % 3 + 3) % 3 == 0; });
  for (auto _ : state) {
    fp::Domain d = fp::Domain::from_polygons(polygon);
    benchmark::DoNotOptimize(d);
  }
  state.counters["holes"] = static_cast<double>(polygon[0].holes.size());
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(4 * polygon[0].holes.size()));
}
BENCHMARK(BM_ValidateTouchingHoles)->Arg(128)->Unit(benchmark::kMillisecond);

// Holes on one colour of the board (n = 128: 8,192 holes): every square of the other colour is
// cut off by the four holes around it, and validation must say so (disconnected_interior).
void BM_RejectCheckerboardOfHoles(benchmark::State& state) {
  const auto n = static_cast<int>(state.range(0));
  const std::vector<fp::Polygon> polygon = board_of_holes(n, [](int i, int j) { return (i + j) % 2 == 0; });
  for (auto _ : state) {
    try {
      fp::Domain d = fp::Domain::from_polygons(polygon);
      benchmark::DoNotOptimize(d);
      state.SkipWithError("the checkerboard of holes was accepted");
      break;
    } catch (const fp::InvalidDomainError& e) {
      benchmark::DoNotOptimize(e.kind());
    }
  }
  state.counters["holes"] = static_cast<double>(polygon[0].holes.size());
}
BENCHMARK(BM_RejectCheckerboardOfHoles)->Arg(128)->Unit(benchmark::kMillisecond);

// n thin triangles as a multipolygon, all with a vertex at the origin (n = 8,192: 24,576
// vertices): their edges there meet in n^2 pairs, and sorting them by angle about the point
// replaces classifying the pairs (src/domain/validate.cpp, find_hubs(); about 70 s before at n = 8,192).
void BM_ValidateFan(benchmark::State& state) {
  const auto n = static_cast<int>(state.range(0));
  std::vector<fp::Polygon> parts;
  for (int k = 0; k < n; ++k) {
    const double a = 2 * std::numbers::pi * k / n;
    const double b = 2 * std::numbers::pi * (k + 0.5) / n;
    parts.push_back({{{0, 0}, {std::cos(a), std::sin(a)}, {std::cos(b), std::sin(b)}}, {}});
  }
  for (auto _ : state) {
    fp::Domain d = fp::Domain::from_polygons(parts);
    benchmark::DoNotOptimize(d);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(3 * parts.size()));
}
BENCHMARK(BM_ValidateFan)->Arg(8192)->Unit(benchmark::kMillisecond);

void BM_ContainsBatch(benchmark::State& state) {
  const fp::Domain d = fp::Domain::from_wkt(big_polygon_wkt(static_cast<std::size_t>(state.range(0)), 16));
  const std::vector<fp::Disk> disks = disks_over(d.bbox(), static_cast<std::size_t>(state.range(1)));
  std::vector<std::uint8_t> out(disks.size());
  for (auto _ : state) {
    d.contains(disks, out);
    benchmark::DoNotOptimize(out.data());
  }
  std::size_t inside = 0;
  for (const auto o : out) {
    inside += o;
  }
  state.counters["edges"] = static_cast<double>(d.num_vertices());
  state.counters["disks"] = static_cast<double>(disks.size());
  state.counters["inside"] = static_cast<double>(inside);
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(disks.size()));
}
BENCHMARK(BM_ContainsBatch)->Args({100'000, 1'000'000})->Args({1'000, 1'000'000})->Unit(benchmark::kMillisecond);

void BM_Locate(benchmark::State& state) {
  const fp::Domain d = fp::Domain::from_wkt(big_polygon_wkt(static_cast<std::size_t>(state.range(0)), 16));
  const std::vector<fp::Disk> disks = disks_over(d.bbox(), 1'000'000);
  for (auto _ : state) {
    std::size_t inside = 0;
    for (const fp::Disk& disk : disks) {
      inside += d.locate(disk.centre) == fp::Location::inside ? 1U : 0U;
    }
    benchmark::DoNotOptimize(inside);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(disks.size()));
}
BENCHMARK(BM_Locate)->Arg(100'000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
