// The disks of the periodic plane near a cell, and points brought into the cell
// (periodic/disk_images.hpp).
#include "periodic/disk_images.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "common/budget.hpp"
#include "common/format.hpp"

namespace frontpack::detail {

namespace {

// More shifts per axis than this means disks hundreds of periods wide: refused rather than
// listing millions of images of each.
constexpr double kMaxShifts = 1000;

// The shifts k (in periods l) that bring coordinate c within `reach` of [lo, hi], as a range
// [first, last] (one more on each side than the quotients say: the test on the translated
// coordinate settles it).
void shift_range(double c, double lo, double hi, double l, double reach, long& first, long& last) {
  const double a = std::floor((lo - reach - c) / l) - 1;
  const double b = std::ceil((hi + reach - c) / l) + 1;
  if (!(a >= -kMaxShifts) || !(b <= kMaxShifts)) {
    throw std::invalid_argument("measure: a periodic cell " + format_double(l) +
                                " wide is too narrow for disks this large (reach " + format_double(reach) +
                                "): more than " + format_double(kMaxShifts) + " images per disk and axis");
  }
  first = static_cast<long>(a);
  last = static_cast<long>(b);
}

}  // namespace

Periods::Periods(const Domain& domain)
    : x(domain.periodicity() != Periodicity::none),
      y(domain.periodicity() == Periodicity::xy),
      cell(domain.bbox()),
      lx(cell.width()),
      ly(cell.height()) {}

Point wrap(const Periods& periods, Point p) noexcept {
  const auto into = [](double v, double lo, double hi, double l) {
    if (v >= lo && v < hi) {
      return v;
    }
    const double w = v - std::floor((v - lo) / l) * l;
    // Rounding may leave w on the wrong side of a bound by an ulp: the nearest point inside.
    return w < lo ? lo : w >= hi ? std::nextafter(hi, lo) : w;
  };
  if (periods.x && std::isfinite(p.x)) {
    p.x = into(p.x, periods.cell.xmin, periods.cell.xmax, periods.lx);
  }
  if (periods.y && std::isfinite(p.y)) {
    p.y = into(p.y, periods.cell.ymin, periods.cell.ymax, periods.ly);
  }
  return p;
}

Location locate_wrapped(const Domain& domain, const Periods& periods, Point p) noexcept {
  return domain.locate(periods.any() ? wrap(periods, p) : p);
}

DiskImages::DiskImages(const Periods& periods, std::span<const Disk> disks, double reach, const Budget& budget)
    : originals_(disks.size()), all_(disks) {
  if (!periods.any() || disks.empty()) {
    return;
  }
  const double per_disk = (1 + 2 * reach / periods.lx) * (periods.y ? 1 + 2 * reach / periods.ly : 1);
  check_count(budget, static_cast<double>(disks.size()) * per_disk, sizeof(Disk) + sizeof(Image), "periodic images",
              "use a larger periodic cell, or a smaller hole radius or cell side (--hole-radius, --cell-side)");
  const Box& c = periods.cell;
  storage_.assign(disks.begin(), disks.end());
  for (std::size_t k = 0; k < disks.size(); ++k) {
    const Point p = disks[k].centre;
    long i0 = 0;
    long i1 = 0;
    long j0 = 0;
    long j1 = 0;
    shift_range(p.x, c.xmin, c.xmax, periods.lx, reach, i0, i1);
    if (periods.y) {
      shift_range(p.y, c.ymin, c.ymax, periods.ly, reach, j0, j1);
    }
    for (long j = j0; j <= j1; ++j) {
      const double y = p.y + static_cast<double>(j) * periods.ly;
      if (!(y >= c.ymin - reach && y <= c.ymax + reach)) {
        continue;
      }
      for (long i = i0; i <= i1; ++i) {
        const double x = p.x + static_cast<double>(i) * periods.lx;
        if ((i == 0 && j == 0) || !(x >= c.xmin - reach && x <= c.xmax + reach)) {
          continue;
        }
        storage_.push_back({{x, y}, disks[k].radius});
        images_.push_back({static_cast<std::uint32_t>(k), static_cast<std::int32_t>(i), static_cast<std::int32_t>(j)});
      }
    }
  }
  all_ = storage_;
}

}  // namespace frontpack::detail
