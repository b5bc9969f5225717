#include "report/json_number.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
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
