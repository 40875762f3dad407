// A folder the map has no row for, and a file that includes a public header: the check names both.
#include "frontpack/api.hpp"
