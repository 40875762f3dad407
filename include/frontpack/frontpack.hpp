// frontpack: dense, exactly certified advancing-front disk packings of polygonal domains.
// Umbrella header (CGAL-free). For CGAL interoperability include "frontpack/cgal.hpp".
#pragma once

#include "frontpack/budget.hpp"
#include "frontpack/certify.hpp"
#include "frontpack/deck.hpp"
#include "frontpack/domain.hpp"
#include "frontpack/domain_file.hpp"
#include "frontpack/errors.hpp"
#include "frontpack/fill.hpp"
#include "frontpack/formats.hpp"
#include "frontpack/geometry.hpp"
#include "frontpack/io.hpp"
#include "frontpack/method.hpp"
#include "frontpack/options.hpp"
#include "frontpack/output_file.hpp"
#include "frontpack/sizes.hpp"
#include "frontpack/stats.hpp"
#include "frontpack/types.hpp"
#include "frontpack/version.hpp"
