#include "report/clock_time.hpp"

#include <gtest/gtest.h>

using namespace ncvm;

TEST(ClockTime, RoundingCarriesIntoTheMinutesAndHours) {
  EXPECT_EQ(clockTime(59.996), "0:01:00.00");
  EXPECT_EQ(clockTime(3599.999), "1:00:00.00");
  EXPECT_EQ(clockTime(59.994), "0:00:59.99");
  EXPECT_EQ(clockTime(0), "0:00:00.00");
  EXPECT_EQ(clockTime(3725.5), "1:02:05.50");
}
