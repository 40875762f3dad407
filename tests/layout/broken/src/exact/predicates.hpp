#pragma once
#include <CGAL/Interval_nt.h>
