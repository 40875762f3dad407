// A periodic cell as the statistics see it (Domain::periodic): the disks of the plane near the cell,
// and the points of the plane brought into it. The walls are the other half of the picture, kept
// by domain/edge_distance.hpp (none for Periodicity::xy, the bottom and top for Periodicity::x).
//
// Every measure works on the disks with their images: the disks translated by whole periods whose
// centre comes within a reach of the cell. A measure that looks at most `reach` away from the cell
// (from a point or a disk centre in it) then sees every disk of the periodic plane it can meet, as
// with the walled domain's disks, and needs no code of its own for the periodic sides. A polygonal
// domain has no images: the disks are passed through untouched (bit-identical results).
//
// Floating point (measurements): the periods are the cell's rounded width and height, and an image
// is its disk's centre plus a whole number of periods, rounded.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "frontpack/budget.hpp"
#include "frontpack/domain.hpp"
#include "frontpack/geometry.hpp"

namespace frontpack::detail {

/// The periodic axes of a domain and their periods (both axes false for a polygonal domain).
struct Periods {
  bool x = false;
  bool y = false;
  Box cell{};     ///< the cell (the domain's bounding box)
  double lx = 0;  ///< cell.width()
  double ly = 0;  ///< cell.height()
  explicit Periods(const Domain& domain);
  [[nodiscard]] bool any() const noexcept { return x; }  // (y is periodic only with x)
};

/// p with its periodic coordinates brought into the half-open cell (p itself on the others).
[[nodiscard]] Point wrap(const Periods& periods, Point p) noexcept;

/// Exact point location of wrap(p): in a periodic cell every point of the plane is classified as
/// its image in the cell (a periodic side is no boundary); domain.locate(p) for a polygonal domain.
[[nodiscard]] Location locate_wrapped(const Domain& domain, const Periods& periods, Point p) noexcept;

class DiskImages {
 public:
  /// The disks, then the images of those whose translate by (i lx, j ly), (i, j) != (0, 0), has
  /// its centre within `reach` of the cell on each axis (j = 0 unless y is periodic). As many
  /// periods as `reach` spans are tried, so a cell narrower than the reach gets every image it
  /// needs (at a cost growing as (reach / period)^2). Precondition: the centres lie in the cell.
  /// The disks and images, about n (1 + 2 reach / lx) (1 + 2 reach / ly) for centres spread over
  /// the cell (the second factor 1 unless y is periodic), are held to `budget` before any is made
  /// (detail::check_count: LimitError).
  DiskImages(const Periods& periods, std::span<const Disk> disks, double reach, const Budget& budget);
  DiskImages(const DiskImages&) = delete;  // all() may point into storage_
  DiskImages& operator=(const DiskImages&) = delete;

  /// The disks (indices 0 .. originals() - 1, as given) followed by the images.
  [[nodiscard]] std::span<const Disk> all() const noexcept { return all_; }
  [[nodiscard]] std::size_t originals() const noexcept { return originals_; }
  /// Disk k's original (k itself for k < originals()).
  [[nodiscard]] std::size_t source(std::size_t k) const noexcept {
    return k < originals_ ? k : images_[k - originals_].source;
  }
  /// Whether disk k (an image) is its original moved by a positive shift (j > 0, or j = 0 and
  /// i > 0): of a disk's contact with its own image, the one with the positive image is counted.
  [[nodiscard]] bool positive_shift(std::size_t k) const noexcept {
    const Image& m = images_[k - originals_];
    return m.j > 0 || (m.j == 0 && m.i > 0);
  }

 private:
  struct Image {
    std::uint32_t source = 0;
    std::int32_t i = 0;
    std::int32_t j = 0;
  };
  std::size_t originals_ = 0;
  std::vector<Disk> storage_;  // the disks and their images, when there are images
  std::vector<Image> images_;
  std::span<const Disk> all_;
};

}  // namespace frontpack::detail
