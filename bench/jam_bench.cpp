// The jam stage's cost (docs/jam.md): bidisperse 1:1.4 (50/50 by number) in a square, the front
// then the jam stage, one thread. The time is the stage's alone (FillStats::seconds_jam, manual
// time); ns_per_disk_step divides it by the relaxation steps and the disks, the figure the
// relaxation's hot loop sets. The argument is about how many disks, in thousands:
//   build/release/bench/frontpack_bench_jam --benchmark_filter=Jam/10
//   build/release/bench/frontpack_bench_jam --benchmark_filter=Jam/40
// The same seed gives the same packing, so two builds' figures compare like for like (their
// steps and disks match unless the relaxation's arithmetic changed).
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>
#include <string>

#include "frontpack/frontpack.hpp"

namespace fp = frontpack;

namespace {

void BM_Jam(benchmark::State& state) {
  // Radii R and 1.4 R covering about 0.84 of a unit square with `disks` of them.
  const auto disks = static_cast<double>(state.range(0)) * 1000;
  const double r = std::sqrt(0.84 / (std::numbers::pi * disks * (1 + 1.4 * 1.4) / 2));
  const fp::Domain d = fp::Domain::from_wkt("POLYGON((0 0,1 0,1 1,0 1,0 0))");
  fp::FillOptions o;
  o.radii = fp::Radii::discrete({{r, 0.5}, {1.4 * r, 0.5}});
  o.seed = 1;
  o.jam = true;
  fp::Packing p;
  for (auto _ : state) {
    p = fp::fill(d, o);
    state.SetIterationTime(p.stats.seconds_jam);
  }
  double area = 0;
  for (const fp::Disk& k : p.disks) {
    area += std::numbers::pi * k.radius * k.radius;
  }
  const auto n = static_cast<double>(p.disks.size());
  state.counters["disks"] = n;
  state.counters["fraction"] = area;
  state.counters["inserted"] = static_cast<double>(p.stats.jam_inserted);
  state.counters["rounds"] = static_cast<double>(p.stats.jam_rounds);
  state.counters["steps"] = static_cast<double>(p.stats.jam_steps);
  state.counters["ns_per_disk_step"] = 1e9 * p.stats.seconds_jam / (static_cast<double>(p.stats.jam_steps) * n);
}
BENCHMARK(BM_Jam)->Arg(10)->Arg(40)->UseManualTime()->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
