#include "report/json_number.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <string>

using namespace ncvm;

namespace {
std::string fast(double v) {
  char buf[kNumberChars];
  return std::string(buf, formatDouble(buf, v));
}
}  // namespace

// The trace's numbers must be the text fmt's "{}" writes, byte for byte, on both paths.
TEST(JsonNumber, SameTextAsFmt) {
  const double edge[] = {0.0,
                         -0.0,
                         1e-6,
                         -1e-6,
                         0.0001,
                         0.000099,
                         0.0001001,
                         1.0,
                         -1.0,
                         0.1,
                         0.3,
                         123456.789,
                         999999999.999999,
                         1e9,
                         -1e9,
                         1e15,
                         1e16,
                         1e300,
                         5e-324,
                         std::numeric_limits<double>::max(),
                         1.0 / 3.0,
                         2.0 / 3.0,
                         0.1 + 0.2,
                         std::numeric_limits<double>::infinity(),
                         1234.5 / 25.4};
  for (double v : edge) EXPECT_EQ(fast(v), fmt::format("{}", v)) << v;
  uint64_t k = 987654321;
  for (int i = 0; i < 200000; ++i) {
    k = k * 6364136223846793005ULL + 1442695040888963407ULL;
    // Whole nanometres in mm (the fast path), up to +-10^9 mm.
    auto nm = static_cast<int64_t>(k >> 14) % 1000000000000000LL * ((k & 1) ? -1 : 1);
    double v = static_cast<double>(nm) / 1e6;
    ASSERT_EQ(fast(v), fmt::format("{}", v)) << nm;
    // Small ones, where fmt switches to exponent form below 10^-4.
    double small = static_cast<double>(nm % 1000) / 1e6;
    ASSERT_EQ(fast(small), fmt::format("{}", small)) << nm;
    // Any double (inch values, times, feeds): the slow path.
    double any = std::bit_cast<double>(k & 0x7fefffffffffffffULL) * ((k & 2) ? -1 : 1);
    ASSERT_EQ(fast(any), fmt::format("{}", any));
    double inch = static_cast<double>(nm % 100000000) / 25.4e6;
    ASSERT_EQ(fast(inch), fmt::format("{}", inch));
  }
}

TEST(JsonNumber, Integers) {
  for (int64_t v : {int64_t{0}, int64_t{7}, int64_t{-7}, int64_t{10}, int64_t{99}, int64_t{100},
                    int64_t{123456789}, std::numeric_limits<int64_t>::min(),
                    std::numeric_limits<int64_t>::max()}) {
    char buf[kNumberChars];
    EXPECT_EQ(std::string(buf, formatInt(buf, v)), fmt::format("{}", v));
  }
}

namespace {
std::string fixed(double v) {
  char buf[kNumberChars];
  return std::string(buf, formatFixed(buf, v));
}
}  // namespace

// A decimal of at most nine decimals (n / 10^m) comes out as the shortest form, byte for
// byte, from 10^-4 up to 10^6: the trace keeps its text for every whole number, programmed
// feed and round time.
TEST(JsonNumber, FixedKeepsDecimalsOfUpToNineDigits) {
  uint64_t k = 123456789;
  int checked = 0;
  for (int i = 0; i < 300000; ++i) {
    k = k * 6364136223846793005ULL + 1442695040888963407ULL;
    const int m = static_cast<int>((k >> 60) % 10);
    auto n = static_cast<int64_t>((k >> 8) % 1000000000000000ULL) * ((k & 1) ? -1 : 1);
    n /= static_cast<int64_t>(
        std::pow(10.0, static_cast<double>((k >> 4) % 12)));  // shorter ones too
    const double v = static_cast<double>(n) / std::pow(10.0, m);
    if (!(std::fabs(v) >= 1e-4 && std::fabs(v) < 1e6)) continue;
    ASSERT_EQ(fixed(v), fmt::format("{}", v)) << n << " / 10^" << m;
    ++checked;
  }
  EXPECT_GT(checked, 100000);
}

// Any other value: the nearest nine-decimal number (to within the double's own rounding),
// in fixed notation without trailing zeros, that a JSON reader reads back.
TEST(JsonNumber, FixedRoundsToNineDecimals) {
  uint64_t k = 42;
  for (int i = 0; i < 300000; ++i) {
    k = k * 6364136223846793005ULL + 1442695040888963407ULL;
    // Log-uniform from 10^-12 to 10^6, both signs: times, lengths, feeds, inch values.
    const double unit = static_cast<double>(k >> 11) / 9007199254740992.0;
    double v = std::pow(10.0, -12.0 + 18.0 * unit) * ((k & 1) ? -1 : 1);
    if (i % 3 == 0) v = static_cast<double>(k % 100000000) / 25.4e6;  // inch from whole nm
    const std::string s = fixed(v);
    ASSERT_EQ(s.find_first_of("eE"), std::string::npos) << s;
    const size_t point = s.find('.');
    if (point != std::string::npos) {
      ASSERT_LE(s.size() - point - 1, 9u) << s;
      ASSERT_NE(s.back(), '0') << s;
    }
    const double back = std::strtod(s.c_str(), nullptr);
    // Half a unit of the ninth decimal, plus the spacing of doubles at v.
    ASSERT_LE(std::fabs(back - v), 5e-10 + 4e-16 * std::fabs(v)) << s << " for " << v;
    // Correctly rounded: fmt's fixed precision rounds the exact binary value too (an exact
    // tie, where the two might differ, needs |v| * 10^9 to end in .5 exactly).
    std::string exact = fmt::format("{:.9f}", v);
    while (exact.back() == '0') exact.pop_back();
    if (exact.back() == '.') exact.pop_back();
    if (exact == "-0") exact = "0";
    ASSERT_EQ(s, exact) << v;
  }
}

TEST(JsonNumber, FixedEdges) {
  EXPECT_EQ(fixed(0.0), "0");
  EXPECT_EQ(fixed(-0.0), "-0");  // as formatDouble writes it
  EXPECT_EQ(fixed(4e-10), "0");
  EXPECT_EQ(fixed(-4e-10), "0");  // rounds to zero: no sign
  EXPECT_EQ(fixed(6e-10), "0.000000001");
  EXPECT_EQ(fixed(-6e-10), "-0.000000001");
  EXPECT_EQ(fixed(0.00001), "0.00001");  // fmt: "1e-05"
  EXPECT_EQ(fixed(0.0894427190999916), "0.089442719");
  EXPECT_EQ(fixed(0.9999999996), "1");
  EXPECT_EQ(fixed(99.9999999996), "100");
  EXPECT_EQ(fixed(14999.999999999998), "15000");
  EXPECT_EQ(fixed(1.0 / 3.0), "0.333333333");
  EXPECT_EQ(fixed(2.0 / 3.0), "0.666666667");
  EXPECT_EQ(fixed(999999.9999999), "999999.9999999");  // just below 10^6
  EXPECT_EQ(fixed(1e6), "1000000");
  EXPECT_EQ(fixed(1234567.123456789), fmt::format("{}", 1234567.123456789));
  EXPECT_EQ(fixed(1e300), fmt::format("{}", 1e300));
  EXPECT_EQ(fixed(std::numeric_limits<double>::infinity()),
            fmt::format("{}", std::numeric_limits<double>::infinity()));
  EXPECT_EQ(fixed(std::nan("")), fmt::format("{}", std::nan("")));
}

// Every six-digit fraction (the word of three pairs and its trailing zeros found at once),
// with integer parts of one, three (inline) and more digits, both signs; every integer
// part up to 10^5 (the digit counts and the inline hundreds).
TEST(JsonNumber, EveryMicrometreFractionAndIntegerPart) {
  for (int64_t whole : {int64_t{0}, int64_t{7}, int64_t{-123}, int64_t{999}, int64_t{45678}}) {
    for (int64_t frac = 0; frac < 1000000; ++frac) {
      const int64_t nm = whole < 0 ? whole * 1000000 - frac : whole * 1000000 + frac;
      const double v = static_cast<double>(nm) / 1e6;
      char buf[kNumberChars];
      const std::string got(buf, formatDouble(buf, v));
      if (got != fmt::format("{}", v)) {
        ADD_FAILURE() << got << " for " << nm << " nm";
        return;
      }
    }
  }
  for (int64_t v = -1000; v <= 100000; ++v) {
    char buf[kNumberChars];
    ASSERT_EQ(std::string(buf, formatInt(buf, v)), fmt::format("{}", v));
    const double d = static_cast<double>(v) + 0.5;
    ASSERT_EQ(std::string(buf, formatDouble(buf, d)), fmt::format("{}", d));
    ASSERT_EQ(std::string(buf, formatFixed(buf, d)), fmt::format("{}", d));
  }
}
