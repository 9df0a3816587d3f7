// Numbers written for users and their tools (results.csv, summaries, flight
// and replay CSVs): the shortest decimal text that reads back to the same
// value (fmt's "{}": 0.85, not %.17g's 0.84999999999999998, so
// pd.read_csv(...)[kd == 0.85] selects the row; a float as a float, 0.1f as
// 0.1). Exact either way: the text parses to the very bits written, so files
// still compare byte for byte across backends and with resume. fmt from 7 on
// writes a whole number without ".0" (1), Ubuntu 20.04's fmt 6 with it (1.0):
// the same double. fmt header-only (libfmt-dev): nothing to link. Not for CUDA translation units (fmt's headers are host C++).
#pragma once

#include <cstdio>

// Header-only fmt in every includer: nothing to link, one mode everywhere.
#ifndef FMT_HEADER_ONLY
#define FMT_HEADER_ONLY
#endif
#include <fmt/format.h>

namespace aurora_common {

// Writes `separator` then the shortest text of v that reads back to v to f
// ("nan", "inf", "-inf" as fmt writes them).
inline void writeNumber(std::FILE* f, double v, const char* separator = ",") {
  fmt::print(f, "{}{}", separator, v);
}
inline void writeNumber(std::FILE* f, float v, const char* separator = ",") {
  fmt::print(f, "{}{}", separator, v);
}

}  // namespace aurora_common
