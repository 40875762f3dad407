// The certifier: Sec. 2.4.5's exact cull against the domain and Sec. 2.4.3's global overlap pass,
// the same functions for fill()'s own output and for certify() on any set of disks.
#include "certify/certify.hpp"

#include <chrono>
#include <cstdint>
#include <utility>

#include "certify/cull.hpp"
#include "certify/overlap_pass.hpp"
#include "certify/report.hpp"
#include "frontpack/certify.hpp"
#include "periodic/overlap_pass.hpp"

namespace frontpack {

namespace detail {

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// The overlap pass the domain needs: across the images in a periodic cell.
void pairs_for(const Domain& domain, std::span<const Disk> disks, std::vector<std::pair<std::size_t, std::size_t>>& out,
               std::size_t& candidates, const std::stop_token& stop) {
  if (domain.periodicity() != Periodicity::none) {
    periodic_overlapping_pairs(domain, disks, out, candidates, stop);
  } else {
    overlapping_pairs(disks, out, candidates, stop);
  }
}

}  // namespace

CertifyResult certify_fill(const Domain& domain, std::vector<Disk>& disks, std::span<const std::size_t> part_end,
                           const std::stop_token& stop) {
  auto t0 = std::chrono::steady_clock::now();
  CertifyResult result;
  Certificate& certificate = result.certificate;
  certificate.generated = disks.size();
  {
    std::vector<std::uint8_t> inside(disks.size());
    contains_in_own_polygon(domain, disks, part_end, inside, stop);
    keep_where(disks, inside, 1);
  }
  certificate.culled = certificate.generated - disks.size();
  result.seconds_cull = seconds_since(t0);
  t0 = std::chrono::steady_clock::now();

  // Drop the later disk of every overlapping pair, in the order of the sorted pairs: deterministic.
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  pairs_for(domain, disks, pairs, certificate.candidate_pairs, stop);
  certificate.dropped = drop_one_of_each_pair(disks, pairs);
  // The capacity reserved beyond the disks generated was never touched and, in a block of its
  // own mapping (above malloc's mmap threshold, at most 32 MiB), costs no memory; a smaller block
  // that malloc recycled may hold touched pages there, at most a fifth of the disks' worth. The
  // culled and dropped disks' places were touched. Give them back only when they are worth a
  // copy (a copy of every disk into memory never touched: 0.2 s of the 10M-disk pipeline's 7 s).
  if (certificate.generated - disks.size() > disks.size() / 8) {
    disks.shrink_to_fit();
  }
  certificate.exact = true;
  result.seconds_overlap = seconds_since(t0);
  return result;
}

}  // namespace detail

CertifyReport certify(const Domain& domain, std::span<const Disk> disks, std::stop_token stop) {
  CertifyReport report;
  std::vector<std::uint8_t> inside(disks.size());
  detail::contains(domain, disks, inside, stop);
  for (std::size_t i = 0; i < disks.size(); ++i) {
    if (inside[i] == 0) {
      report.outside.push_back(i);
    }
  }
  detail::pairs_for(domain, disks, report.overlapping, report.certificate.candidate_pairs, stop);
  report.certificate.generated = disks.size();
  report.certificate.culled = report.outside.size();
  report.certificate.exact = true;
  detail::measure_worst(domain, disks, report);
  return report;
}

}  // namespace frontpack
