// A generator that reaches CGAL through one of our headers: layout.catches_cgal_in_generate expects
// check_layout.cmake to print this include chain.
#include "exact/predicates.hpp"
