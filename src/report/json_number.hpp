#pragma once
// Fast, exact number formatting for the trace: the same text as fmt's "{}" (the shortest
// decimal that reads back as the same double), written into a caller's buffer.
#include <cstdint>

namespace ncvm {

// Room for any double or int64 this writes ("-2.2250738585072014e-308" is 24 characters).
constexpr int kNumberChars = 32;

// Writes v as fmt::format("{}", v) would and returns the end. Positions are whole
// nanometres in program units, so most values are n / 10^6 for an integer n: those are
// written from n directly (see json_number.cpp for why that is the shortest form).
char* formatDouble(char* out, double v);
char* formatInt(char* out, int64_t v);

}  // namespace ncvm
