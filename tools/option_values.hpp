// The values of the tool's options read from their text: the library's readers
// (frontpack/options.hpp, namespace option_text), so that the fill options and the tool's own
// options are refused with one kind of message, "OPTION 'TEXT': expected ...".
#pragma once

#include "frontpack/options.hpp"

namespace frontpack_tool::cli {

using frontpack::option_text::finite_number;
using frontpack::option_text::finite_numbers;
using frontpack::option_text::given_value;
using frontpack::option_text::parse_bytes;
using frontpack::option_text::parse_count;
using frontpack::option_text::parse_double;
using frontpack::option_text::parse_positive;

}  // namespace frontpack_tool::cli
