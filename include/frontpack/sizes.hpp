// frontpack: particle size distributions (the radii a fill draws).
//
//   options.radii = frontpack::Radii::uniform(0.01, 0.05);                 // the paper's
//   options.radii = frontpack::Radii::normal(0.02, 0.004, 0.01, 0.03);     // truncated normal
//   options.radii = frontpack::parse_radii("curve:sand.csv");              // a sieve curve, by area
//
// Sizes. Every distribution is a distribution of disk RADII. Discrete classes and grading curves
// may be given in diameters (SizeKind::diameter, as sieve curves are): they are halved (exactly)
// on input, and every result (min(), quantile(), statistics) is in radii again.
//
// Basis. Fractions (class fractions, cumulative "passing" fractions) are by number (a fraction of
// the disks) or by area (a fraction of the disks' total area, the 2D analogue of the mass fraction
// of a sieve analysis). A by-area distribution with area density g(r) is drawn by number with
// density proportional to g(r) / r^2, so that the drawn disks, weighted by their area, follow the
// curve as given (docs/distributions.md).
//
// Reproducibility. Radii are drawn by inverse transform, r = quantile(u), from the 53-bit uniform
// variates of frontpack's own generator; no std:: distribution (whose algorithms are
// implementation-defined) is used. uniform, constant, discrete and grading curves by number use
// only +, -, *, / and comparisons besides std::exp/std::log (curves) and std::sqrt (by-area
// curves), normal and lognormal use std::erfc, std::exp, std::log and std::sqrt. So: the same seed
// gives bit-identical radii for every build (any compiler, optimisation level or sanitizer) that
// uses the same C math library; libms that round exp/log/erfc differently may differ in the last
// bits of a few radii, never in the distribution.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "frontpack/errors.hpp"

namespace frontpack {

/// What the fractions of a size table count.
enum class Basis : std::uint8_t {
  number,  ///< fractions of the number of disks
  area,    ///< fractions of the total disk area (2D analogue of mass; sieve curves)
};

/// What the sizes of a size table are.
enum class SizeKind : std::uint8_t { radius, diameter };

[[nodiscard]] const char* to_string(Basis basis) noexcept;
[[nodiscard]] const char* to_string(SizeKind kind) noexcept;

/// One row of a size table: a discrete class (size, fraction of the class) or a point of a
/// grading curve (sieve size, cumulative fraction passing, i.e. of sizes <= size).
struct SizeFraction {
  double size = 0.0;
  double fraction = 0.0;
  friend constexpr bool operator==(const SizeFraction&, const SizeFraction&) = default;
};

/// A radius distribution. Radii are drawn by inverse transform from a 53-bit uniform variate of
/// frontpack's own generator, so a seed gives the same radii on every compiler and platform
/// (see the header comment). This is the seam through which further distributions plug in.
class RadiusDistribution {
 public:
  virtual ~RadiusDistribution() = default;
  /// The radius at cumulative probability u in [0, 1). Must be monotone in u and within
  /// [min(), max()].
  [[nodiscard]] virtual double quantile(double u) const = 0;
  [[nodiscard]] virtual double min() const = 0;
  [[nodiscard]] virtual double max() const = 0;
  /// E[r^2], for estimating disk counts.
  [[nodiscard]] virtual double mean_square() const = 0;
  /// P(radius <= r), by number. Default: bisection on quantile() (to 2^-52 in u).
  [[nodiscard]] virtual double cdf(double r) const;
  /// The fraction of the total disk area in disks of radius <= r: E[R^2 1{R <= r}] / E[R^2].
  /// Default: a 4096-point midpoint rule in u on quantile() (error about 1e-4 for smooth
  /// distributions).
  [[nodiscard]] virtual double area_cdf(double r) const;
  /// The class radii (discrete distributions) or sieve radii (grading curves), increasing: the
  /// rows of the per-class table of statistics. Empty for continuous distributions (default).
  [[nodiscard]] virtual std::vector<double> class_radii() const;
  /// One line, e.g. "normal: mean 0.02, sd 0.004, truncated to [0.01, 0.03] (radius)".
  [[nodiscard]] virtual std::string describe() const;
};

/// A radius specification (a value type sharing an immutable distribution). Every factory
/// validates its parameters and throws OptionError naming the bad one; NaN and infinities are
/// refused everywhere.
class Radii {
 public:
  /// Radii uniform in [rmin, rmax] (the paper's); 0 < rmin <= rmax, finite.
  [[nodiscard]] static Radii uniform(double rmin, double rmax);
  /// Every radius equal to r > 0.
  [[nodiscard]] static Radii constant(double r);
  /// Normal with the given mean and standard deviation (of the radius), truncated to [lo, hi]:
  /// sd > 0, 0 < lo < hi, and [lo, hi] must keep a probability of at least 1e-300 (windows far in a tail are fine:
  /// their probabilities are computed in the tail).
  [[nodiscard]] static Radii normal(double mean, double sd, double lo, double hi);
  /// Lognormal: log(r) is normal with mean log(median) and standard deviation log(gsd); that is,
  /// median radius `median` and geometric standard deviation `gsd` > 1 (mu = log(median),
  /// sigma = log(gsd) in the other common parametrisation). Truncated to [lo, hi], 0 < lo < hi,
  /// keeping a probability of at least 1e-300.
  [[nodiscard]] static Radii lognormal(double median, double gsd, double lo, double hi);
  /// Discrete classes (size, fraction): sizes > 0 and distinct (any order), fractions in [0, 1]
  /// summing to 1 within 1e-6 (they are then normalised), at least one fraction > 0.
  [[nodiscard]] static Radii discrete(std::vector<SizeFraction> classes, Basis basis = Basis::number,
                                      SizeKind kind = SizeKind::radius);
  /// A grading curve: points (size, cumulative fraction passing), sizes > 0 strictly increasing,
  /// passing non-decreasing in [0, 1], starting at 0 and ending at 1 (the smallest and largest
  /// sizes bound the distribution); at least 2 points. Between points the cumulative fraction is
  /// linear in log(size), as sieve curves are drawn.
  [[nodiscard]] static Radii grading_curve(std::vector<SizeFraction> points, Basis basis = Basis::area,
                                           SizeKind kind = SizeKind::diameter);
  /// Any distribution (must satisfy RadiusDistribution's contract; its bounds are checked).
  [[nodiscard]] static Radii custom(std::shared_ptr<const RadiusDistribution> distribution);

  [[nodiscard]] const RadiusDistribution& distribution() const;
  [[nodiscard]] double min() const { return distribution().min(); }
  [[nodiscard]] double max() const { return distribution().max(); }
  [[nodiscard]] std::string describe() const { return distribution().describe(); }

 private:
  std::shared_ptr<const RadiusDistribution> d_;
};

/// The first n radii that frontpack::fill with this seed draws (one generator stream, in
/// order; a fill of a single polygon places them in this order, minus the disks it culls).
[[nodiscard]] std::vector<double> sample_radii(const Radii& radii, std::size_t n, std::uint64_t seed);

/// Parses a radius spec, as the tool's --radius takes it. Sizes are radii unless @diameter says
/// otherwise; numbers are decimal (C locale) and must be finite; one out of the range of doubles,
/// overflowing or underflowing to 0, is refused as by every reader ("'1e-400' is out of the range
/// of a double (underflows to 0)"; README, "Numbers").
///
///   uniform:RMIN,RMAX                   uniform in [RMIN, RMAX] (the paper's)
///   constant:R                          every radius R
///   normal:MEAN,SD[,LO,HI]              truncated normal; default bounds MEAN -/+ 3 SD (which
///                                       must stay > 0)
///   lognormal:MEDIAN,GSD[,LO,HI]        truncated lognormal, median and geometric sd (> 1);
///                                       default bounds MEDIAN / GSD^3 and MEDIAN * GSD^3
///   discrete:S1:F1,S2:F2,...[@MOD...]   classes (size S, fraction F); by number unless @area
///   discrete:FILE.csv[@area|@number]    classes from a CSV file (read_size_table)
///   curve:S1:P1,S2:P2,...[@MOD...]      grading curve (size S, fraction passing P); by area
///                                       unless @number; sizes are DIAMETERS unless @radius
///   curve:FILE.csv[@area|@number]       grading curve from a CSV file (read_size_table)
///
/// MOD is one of area, number, radius, diameter (each at most once; @radius/@diameter only for
/// inline lists, a file's header says which). An argument ending in ".csv" is a file, read
/// relative to the working directory. Throws OptionError ("radius 'SPEC': ..." naming the bad
/// part); a file that cannot be read gives IoError.
[[nodiscard]] Radii parse_radii(std::string_view spec);

/// A size table from a CSV file: discrete classes or a grading curve.
struct SizeTable {
  SizeKind kind = SizeKind::radius;
  bool cumulative = false;  ///< "passing" column (a grading curve) rather than "fraction" (classes)
  std::vector<SizeFraction> rows;
};

/// Reads a size table. Format: a header line "radius,fraction", "diameter,fraction" (discrete
/// classes) or "radius,passing", "diameter,passing" (a grading curve: cumulative fraction
/// passing), then one "size,fraction" line per row. Fractions are in [0, 1] (not percent).
/// Blank lines and lines starting with '#' are skipped; fields may be padded with spaces;
/// CRLF line ends are accepted; numbers as for parse_radii. Only the syntax is checked here: the
/// factories check the values. Throws IoError if unreadable, OptionError "FILE:LINE: ..." naming
/// the bad line.
[[nodiscard]] SizeTable read_size_table(const std::filesystem::path& path);
/// The same, from text; `source` names it in messages.
[[nodiscard]] SizeTable parse_size_table(std::string_view text, std::string_view source);

/// Radii from a size table: discrete(...) or grading_curve(...) with the table's kind.
[[nodiscard]] Radii radii_from_table(const SizeTable& table, Basis basis);

}  // namespace frontpack
