#pragma once
// Fast number formatting for the trace, written into a caller's buffer: positions exactly
// (the same text as fmt's "{}", the shortest decimal that reads back as the same double),
// derived quantities (feed, length, time) rounded to a fixed number of decimals.
#include <cstdint>

namespace ncvm {

// Room for any double or int64 this writes ("-2.2250738585072014e-308" is 24 characters).
// The writers may store bytes past the end they return, never past out + kNumberChars.
constexpr int kNumberChars = 32;

// Writes v as fmt::format("{}", v) would and returns the end. Positions are whole
// nanometres in program units, so most values are n / 10^6 for an integer n: those are
// written from n directly (see json_number.cpp for why that is the shortest form).
char* formatDouble(char* out, double v);
char* formatInt(char* out, int64_t v);

// The decimals formatFixed keeps (docs/trace-format.md: why that is enough).
constexpr int kFixedDecimals = 9;

// Writes v rounded to kFixedDecimals decimals in fixed notation, trailing zeros and a bare
// point dropped ("0.089442719", "10", "0.00001", "0"). A value whose shortest form has at
// most that many decimals comes out exactly as formatDouble writes it when it is not below
// 10^-4 (fmt writes smaller ones in exponent form). |v| >= 10^6, NaN, infinities and -0 are
// written by formatDouble.
char* formatFixed(char* out, double v);

}  // namespace ncvm
