// Closed contours (with arcs) to a validated domain: nesting by exact containment (even depth:
// an outer boundary, odd: a hole of the contour just around it), then each arc made a polyline on
// the domain's side (domain/safe_arcs.hpp), then Domain::from_polygons. Errors name the file and
// the contours' entities.
#pragma once

#include <string>
#include <vector>

#include "domain/contour.hpp"
#include "frontpack/domain.hpp"
#include "frontpack/domain_file.hpp"

namespace frontpack::detail {

/// The deviation an arc of `radius` gets under `options`.
[[nodiscard]] double curve_deviation(const DomainReadOptions& options, double radius);

/// Throws DomainFileError (no contour), InvalidDomainError (a contour that crosses itself,
/// contours that cross or touch), OptionError (a deviation too small for a curve). Appends one
/// report per arc to `curves`.
[[nodiscard]] Domain nest_contours(const std::vector<Contour>& contours, const DomainReadOptions& options,
                                   const std::string& source, std::vector<CurveReport>& curves);

/// Domain::from_polygons, with an InvalidDomainError's message prefixed by the file and by the
/// names of the rings it concerns (`ring_names[part][ring]`).
[[nodiscard]] Domain polygons_to_domain(std::vector<Polygon> polygons,
                                        const std::vector<std::vector<std::string>>& ring_names,
                                        const std::string& source);

}  // namespace frontpack::detail
