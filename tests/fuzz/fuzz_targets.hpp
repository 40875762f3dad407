// Fuzz targets (issue #7). Each function takes one input, must return normally for every input,
// and aborts (through check()) when a guarantee is broken. They are linked both into the
// libFuzzer programs (tests/fuzz/main.cpp, Clang builds) and into the unit tests, which replay
// the committed seed corpora and every regression file on every build.
#pragma once

#include <cstddef>
#include <cstdint>

namespace frontpack::fuzz {

/// Domain::from_wkt on arbitrary text: it accepts or throws frontpack::Error (never anything
/// else); an accepted domain is valid (positive finite area, finite box), survives a WKT round
/// trip unchanged, and answers point queries.
void wkt(const std::uint8_t* data, std::size_t size);

/// fill() on a small domain and radius request decoded from the bytes (random rings and holes, or
/// shapes aimed at the boundary method: jagged rings, short edges, spikes, near-touching holes,
/// slivers, combs; scales from 1e-9 to 1e9, offsets up to 1e9, radius ratios up to 1000; the
/// closed, open and boundary methods, any window, voids on or off): it returns or throws
/// frontpack::Error; a returned packing certifies exactly (0 overlapping pairs, 0 disks outside,
/// checked by an independent certify() call), is reproducible, and with the boundary method has
/// nothing culled.
void fill(const std::uint8_t* data, std::size_t size);

/// read_domain_file on arbitrary text as DXF (written to a memory file: dxflib reads by path): it
/// accepts or throws frontpack::Error with a printable, bounded message; an accepted domain has a
/// positive finite area, a finite box and finite curves, and its rings written back as DXF
/// polylines (17 significant digits) read as the same domain.
void dxf(const std::uint8_t* data, std::size_t size);

/// read_csv and read_yade on arbitrary text: each accepts or throws frontpack::Error; accepted
/// disks are finite with positive radii and survive write + read bit for bit.
void disks(const std::uint8_t* data, std::size_t size);

}  // namespace frontpack::fuzz
