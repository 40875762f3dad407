// Fill benchmarks (issue #3): radii uniform in [5e-4, 5e-3] in a 6 x 6 square (~1M disks),
// one thread. Run each alone so that the peak-memory counter means something:
//   build/release/bench/frontpack_bench_fill --benchmark_filter=Core
//   build/release/bench/frontpack_bench_fill --benchmark_filter=Pipeline/1/
//   build/release/bench/frontpack_bench_fill --benchmark_filter=Pipeline/10/1/   (open, ~10M disks)
//   build/release/bench/frontpack_bench_fill --benchmark_filter=Pipeline/10/2/   (boundary)
//   build/release/bench/frontpack_bench_fill --benchmark_filter=Pipeline/100/   (100M disks, 5.4 GB)
//   build/release/bench/frontpack_bench_fill --benchmark_filter=CostRatio/      (issue #5's cost ratio)
//   build/release/bench/frontpack_bench_fill --benchmark_filter=Sliver/         (a 1:1e6 rectangle)
// "Core" times the advancing front alone (FillStats::seconds_front, manual time); "Pipeline"
// times fill() end to end: generation + exact cull + CGAL overlap pass. The last argument is
// FillOptions::fill_voids: issue #3's figures are the paper's forms (0); issue #5's compare the
// boundary method with the open form (Core/2/1 against Core/1/0).
#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <numbers>
#include <string>
#include <vector>

#include "frontpack/frontpack.hpp"

namespace fp = frontpack;

namespace {

// A square of side 6 * sqrt(scale): scale = 10 gives ten times the area (~10M disks).
fp::Domain square(double scale) {
  const double s = 6 * std::sqrt(scale);
  const std::string side = std::to_string(s);
  return fp::Domain::from_wkt("POLYGON((0 0," + side + " 0," + side + " " + side + ",0 " + side + ",0 0))");
}

fp::FillOptions options(fp::Method m, bool voids) {
  fp::FillOptions o;
  o.method = m;
  o.fill_voids = voids;
  o.radii = fp::Radii::uniform(5e-4, 5e-3);
  o.seed = 2003;
  o.max_disks = 200'000'000;  // the 100M-disk run
  return o;
}

double fraction(const fp::Packing& p, const fp::Domain& d) {
  double a = 0;
  for (const fp::Disk& k : p.disks) {
    a += std::numbers::pi * k.radius * k.radius;
  }
  return a / d.area();
}

void report(benchmark::State& state, const fp::Packing& p, const fp::Domain& d) {
  rusage ru{};
  getrusage(RUSAGE_SELF, &ru);
  state.counters["disks"] = static_cast<double>(p.disks.size());
  state.counters["fraction"] = fraction(p, d);
  state.counters["dropped"] = static_cast<double>(p.certificate.dropped);
  state.counters["front_s"] = p.stats.seconds_front;
  state.counters["cull_s"] = p.stats.seconds_cull;
  state.counters["overlap_s"] = p.stats.seconds_overlap;
  state.counters["peak_bytes_per_disk"] =
      static_cast<double>(ru.ru_maxrss) * 1024.0 / static_cast<double>(p.disks.size());
}

void BM_Core(benchmark::State& state) {
  const auto method = static_cast<fp::Method>(state.range(0));
  const fp::Domain d = square(1);
  fp::Packing p;
  for (auto _ : state) {
    p = fp::fill(d, options(method, state.range(1) != 0));
    state.SetIterationTime(p.stats.seconds_front);
  }
  report(state, p, d);
  state.SetLabel(std::string(fp::to_string(method)) + (state.range(1) != 0 ? ", voids" : ""));
}
BENCHMARK(BM_Core)
    ->Args({static_cast<int>(fp::Method::open), 0})
    ->Args({static_cast<int>(fp::Method::closed), 0})
    ->Args({static_cast<int>(fp::Method::open), 1})
    ->Args({static_cast<int>(fp::Method::closed), 1})
    ->Args({static_cast<int>(fp::Method::boundary), 1})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);

void BM_Pipeline(benchmark::State& state) {
  const fp::Domain d = square(static_cast<double>(state.range(0)));
  const auto method = static_cast<fp::Method>(state.range(1));
  fp::Packing p;
  for (auto _ : state) {
    p = fp::fill(d, options(method, state.range(2) != 0));
  }
  report(state, p, d);
  state.SetLabel(std::string(fp::to_string(method)) + (state.range(2) != 0 ? ", voids" : ""));
}
BENCHMARK(BM_Pipeline)
    ->Args({1, static_cast<int>(fp::Method::open), 0})
    ->Args({1, static_cast<int>(fp::Method::closed), 0})
    ->Args({1, static_cast<int>(fp::Method::boundary), 1})
    ->Args({10, static_cast<int>(fp::Method::open), 0})
    ->Args({10, static_cast<int>(fp::Method::boundary), 1})  // the tool's default method at 10M
    ->Args({100, static_cast<int>(fp::Method::open), 0})     // ~100M disks, ~5.4 GB, ~100 s: run alone
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

// One fill per run, for counting instructions rather than timing them (this shared machine's
// times drift by 15-20% in a day; its instruction counts do not). Callgrind then counts the
// advancing front alone, the exact cull and the overlap pass running uncounted; divide by the
// `generated` counter:
//   valgrind --tool=callgrind --toggle-collect='frontpack::detail::advance_*'
//       build/release/bench/frontpack_bench_fill --benchmark_filter=Once/1/0/2/
// (one command line).
// Arguments: method, fill_voids, side of the square (2: ~112k disks, about a minute under
// callgrind; 6: issue #3's square, ~1M disks).
void BM_Once(benchmark::State& state) {
  const auto method = static_cast<fp::Method>(state.range(0));
  const std::string side = std::to_string(state.range(2));
  const fp::Domain d =
      fp::Domain::from_wkt("POLYGON((0 0," + side + " 0," + side + " " + side + ",0 " + side + ",0 0))");
  fp::Packing p;
  for (auto _ : state) {
    p = fp::fill(d, options(method, state.range(1) != 0));
  }
  report(state, p, d);
  state.counters["generated"] = static_cast<double>(p.certificate.generated);
  state.SetLabel(std::string(fp::to_string(method)) + (state.range(1) != 0 ? ", voids" : ""));
}
BENCHMARK(BM_Once)
    ->Args({static_cast<int>(fp::Method::open), 0, 2})
    ->Args({static_cast<int>(fp::Method::closed), 0, 2})
    ->Args({static_cast<int>(fp::Method::boundary), 1, 2})
    ->Args({static_cast<int>(fp::Method::open), 0, 6})
    ->Args({static_cast<int>(fp::Method::closed), 0, 6})
    ->Args({static_cast<int>(fp::Method::boundary), 1, 6})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

// Issue #5's targets are measured "on the shapes/ domains with holes and reflex corners": each of
// those shapes at about 1,000,000 disks, radii uniform in [R, 10 R] with R from the shape's area
// (as tools/density_table.py chooses it for its 40,000, without its rounding to two digits).
// Manual time is the advancing front alone; per_disk_us divides it by the disks kept
// (certified), per_generated_us by those generated (the paper's forms fill each polygon's
// bounding box and cull what is not inside).
// Arguments: shape (index into kShapes), method, fill_voids.
//   build/release/bench/frontpack_bench_fill --benchmark_filter=Shape/
constexpr const char* kShapes[] = {"annulus",    "big_polygon",    "comb",       "concave_polygon",
                                   "gear",       "hole_touching",  "islands",    "l_shape",
                                   "millimetre", "narrow_channel", "offset_1e6", "plate_with_holes"};

fp::Domain shape(std::int64_t index) {
  return fp::Domain::from_wkt_file(std::string(FRONTPACK_SHAPES_DIR) + "/" + kShapes[index] + ".wkt");
}

// Uniform radii in [R, 10 R] for about a million disks in d: E[r^2] = 37 R^2; about 0.8 of the
// area covered.
fp::Radii shape_radii(const fp::Domain& d) {
  const double r = std::sqrt(0.8 * d.area() / (1e6 * std::numbers::pi * 37.0));
  return fp::Radii::uniform(r, 10 * r);
}

void BM_Shape(benchmark::State& state) {
  const std::string name = kShapes[state.range(0)];
  const fp::Domain d = shape(state.range(0));
  const auto method = static_cast<fp::Method>(state.range(1));
  fp::FillOptions o = options(method, state.range(2) != 0);
  o.radii = shape_radii(d);
  fp::Packing p;
  for (auto _ : state) {
    p = fp::fill(d, o);
    state.SetIterationTime(p.stats.seconds_front);
  }
  report(state, p, d);
  state.counters["generated"] = static_cast<double>(p.certificate.generated);
  state.counters["per_disk_us"] = 1e6 * p.stats.seconds_front / static_cast<double>(p.disks.size());
  state.counters["per_generated_us"] = 1e6 * p.stats.seconds_front / static_cast<double>(p.certificate.generated);
  state.SetLabel(name + ", " + fp::to_string(method) + (state.range(2) != 0 ? ", voids" : ""));
}
void shape_args(benchmark::internal::Benchmark* b) {
  for (int s = 0; s < static_cast<int>(std::size(kShapes)); ++s) {
    b->Args({s, static_cast<int>(fp::Method::open), 0});
    b->Args({s, static_cast<int>(fp::Method::open), 1});
    b->Args({s, static_cast<int>(fp::Method::boundary), 1});
  }
}
// Three repetitions, medians reported: the first fill of a process runs on memory fresh to it,
// slower on this VM (a whole benchmark program's first fill, whichever it is, ran 1.5 x slower).
BENCHMARK(BM_Shape)
    ->Apply(shape_args)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->Repetitions(3)
    ->ComputeStatistics("min", [](const std::vector<double>& v) { return *std::min_element(v.begin(), v.end()); })
    ->ReportAggregatesOnly(true);

// Issue #5's cost target as one figure per shape: the boundary method's front time per disk kept
// over the paper's open form's (fill_voids off), the two filled in turn in one process: a warm-up
// fill, then kPairs pairs, open first in one pair and boundary first in the next, so that the
// machine's drift (about 10% within an hour on this VM, as much as the margin measured) falls on
// both sides of the ratio. Separate BM_Shape runs an hour apart gave the same shape ratios 0.33
// apart. Counters: ratio (the median of the pairs' ratios), ratio_min, ratio_max, and the median
// times per disk kept. Manual time: the fronts' total.
//   build/release/bench/frontpack_bench_fill --benchmark_filter=CostRatio/
void BM_CostRatio(benchmark::State& state) {
  constexpr int kPairs = 5;
  const std::string name = kShapes[state.range(0)];
  const fp::Domain d = shape(state.range(0));
  fp::FillOptions open = options(fp::Method::open, false);
  fp::FillOptions boundary = options(fp::Method::boundary, true);
  open.radii = boundary.radii = shape_radii(d);
  auto per_kept_disk = [&](const fp::FillOptions& o, double& seconds) {
    const fp::Packing p = fp::fill(d, o);
    seconds += p.stats.seconds_front;
    return p.stats.seconds_front / static_cast<double>(p.disks.size());
  };
  auto median = [](std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
  };
  std::vector<double> ratios;
  std::vector<double> open_us;
  std::vector<double> boundary_us;
  for (auto _ : state) {
    double seconds = 0;
    double warm_up = 0;
    per_kept_disk(open, warm_up);
    for (int i = 0; i < kPairs; ++i) {
      const bool open_first = i % 2 == 0;
      const double t1 = per_kept_disk(open_first ? open : boundary, seconds);
      const double t2 = per_kept_disk(open_first ? boundary : open, seconds);
      const double o = open_first ? t1 : t2;
      const double b = open_first ? t2 : t1;
      ratios.push_back(b / o);
      open_us.push_back(1e6 * o);
      boundary_us.push_back(1e6 * b);
    }
    state.SetIterationTime(seconds);
  }
  state.counters["ratio"] = median(ratios);
  state.counters["ratio_min"] = *std::min_element(ratios.begin(), ratios.end());
  state.counters["ratio_max"] = *std::max_element(ratios.begin(), ratios.end());
  state.counters["open_us"] = median(open_us);
  state.counters["boundary_us"] = median(boundary_us);
  state.SetLabel(name + ", boundary / open (paper), per disk kept");
}
BENCHMARK(BM_CostRatio)
    ->DenseRange(0, static_cast<int>(std::size(kShapes)) - 1)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

// A sliver: the rectangle L x 1e-6 (L = 1: 1:1e6), radii uniform in [2e-7, 4.5e-7], so that one
// to two disks fit across it. The closed form's box is thin: its front becomes two long inactive
// strands outside the box joined by two short active ends, and looking up the list of active
// segments walked a strand whenever an end lost its last listed segment (src/generate/front_list.hpp, relist()):
// 182 s for L = 1, now about 2 s; the time must grow linearly with L. Manual time: the front.
// Arguments: method, L in thousandths.
//   build/release/bench/frontpack_bench_fill --benchmark_filter=Sliver/
void BM_Sliver(benchmark::State& state) {
  const auto method = static_cast<fp::Method>(state.range(0));
  char text[32];
  std::snprintf(text, sizeof text, "%g", static_cast<double>(state.range(1)) / 1000);
  const std::string length = text;
  const fp::Domain d = fp::Domain::from_wkt("POLYGON((0 0," + length + " 0," + length + " 1e-6,0 1e-6,0 0))");
  fp::FillOptions o = options(method, method == fp::Method::boundary);
  o.radii = fp::Radii::uniform(2e-7, 4.5e-7);
  o.seed = 1;
  fp::Packing p;
  for (auto _ : state) {
    p = fp::fill(d, o);
    state.SetIterationTime(p.stats.seconds_front);
  }
  report(state, p, d);
  state.counters["generated"] = static_cast<double>(p.certificate.generated);
  state.counters["per_generated_us"] = 1e6 * p.stats.seconds_front / static_cast<double>(p.certificate.generated);
  state.SetLabel(std::string(fp::to_string(method)) + ", " + length + " x 1e-6");
}
BENCHMARK(BM_Sliver)
    ->Args({static_cast<int>(fp::Method::closed), 200})
    ->Args({static_cast<int>(fp::Method::closed), 1000})
    ->Args({static_cast<int>(fp::Method::open), 1000})
    ->Args({static_cast<int>(fp::Method::boundary), 1000})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
