// Statistics benchmarks: measure() as the domain's edges grow and as the disks grow large against
// the edges' length, and the circles finely drawn against their disks (30,000 and 300,000
// vertices filled at uniform:0.1,0.5), whose statistics are quadratic in the edges if the distance
// to the walls scans every edge of a grid cell of side 2 rmax. Run:
//   build/release/bench/frontpack_bench_stats
// Figures are recorded in docs/performance.md.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <vector>

#include "frontpack/frontpack.hpp"

namespace fp = frontpack;

namespace {

// A circle of radius r drawn with n edges.
fp::Domain circle(std::size_t n, double r) {
  fp::Ring ring;
  ring.reserve(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double t = 2 * std::numbers::pi * static_cast<double>(k) / static_cast<double>(n);
    ring.push_back({r * std::cos(t), r * std::sin(t)});
  }
  return fp::Domain::from_polygons({fp::Polygon{std::move(ring), {}}});
}

// measure() on a circle of E edges of length about 1 (radius E / 2 pi) and about E / 4 disks of
// radius `ratio` (the ratio of rmax to the edges' length) on a square lattice inside it, at E
// sample points, and coverage cells of side twice the lattice's spacing (about N / 4 of them; the
// default 8 rmax would make (R / rmax)^2 cells on a sparse lattice): the work is
// (N + E) log (N + E) for any ratio. Holes are left out: their cost goes with the disks and the
// radius asked (docs/robustness.md), not with the edges.
void BM_MeasureEdges(benchmark::State& state) {
  const auto edges = static_cast<std::size_t>(state.range(0));
  const auto ratio = static_cast<double>(state.range(1));
  const double radius = static_cast<double>(edges) / (2 * std::numbers::pi);
  const fp::Domain domain = circle(edges, radius);
  const double spacing =
      std::max(2.5 * ratio, std::sqrt(std::numbers::pi * radius * radius / (static_cast<double>(edges) / 4)));
  std::vector<fp::Disk> disks;
  const double reach = radius - ratio;
  for (double y = -reach; y <= reach; y += spacing) {
    for (double x = -reach; x <= reach; x += spacing) {
      if (std::hypot(x, y) <= reach * (1 - 1e-9)) {
        disks.push_back({{x, y}, ratio});
      }
    }
  }
  fp::StatsOptions options;
  options.samples = edges;
  options.holes = false;
  options.cell_side = 2 * spacing;
  for (auto _ : state) {
    benchmark::DoNotOptimize(fp::measure(domain, disks, options));
  }
  state.counters["edges"] = static_cast<double>(edges);
  state.counters["disks"] = static_cast<double>(disks.size());
  state.counters["ns_per_item"] =
      benchmark::Counter(static_cast<double>(edges + disks.size()),
                         benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

// Edge counts 1k..1M at ratios 1..1000, where the disks (radius `ratio`) fit in a quarter of the
// circle's radius.
void edge_args(benchmark::internal::Benchmark* b) {
  for (const std::int64_t e : {1'000, 10'000, 100'000, 1'000'000}) {
    for (const std::int64_t ratio : {1, 10, 100, 1'000}) {
      if (static_cast<double>(ratio) <= static_cast<double>(e) / (8 * std::numbers::pi)) {
        b->Args({e, ratio});
      }
    }
  }
}
BENCHMARK(BM_MeasureEdges)->Apply(edge_args)->Unit(benchmark::kMillisecond)->Iterations(1);

// The cases: a circle of radius 1 with E vertices filled at uniform:0.1,0.5 (about 10
// disks, rmax / edge length 2,400 and 24,000), measured with every default (a million samples,
// the holes at the median and largest radii).
void BM_MeasureFilledCircle(benchmark::State& state) {
  const auto edges = static_cast<std::size_t>(state.range(0));
  const fp::Domain domain = circle(edges, 1.0);
  fp::FillOptions fill;
  fill.radii = fp::Radii::uniform(0.1, 0.5);
  const fp::Packing packing = fp::fill(domain, fill);
  for (auto _ : state) {
    benchmark::DoNotOptimize(fp::measure(domain, packing.disks, {}));
  }
  state.counters["edges"] = static_cast<double>(edges);
  state.counters["disks"] = static_cast<double>(packing.disks.size());
}
BENCHMARK(BM_MeasureFilledCircle)->Arg(30'000)->Arg(300'000)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
