// A public header that includes CGAL.
#pragma once
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
