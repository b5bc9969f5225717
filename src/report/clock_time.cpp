#include "report/clock_time.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdint>

namespace ncvm {

std::string clockTime(double seconds) {
  // Times are bounded by limits.max_time_s; the guard keeps llround defined for any input.
  if (!std::isfinite(seconds) || seconds < 0 || seconds > 1e12)
    return fmt::format("{:.2f} s", seconds);
  const int64_t hundredths = std::llround(seconds * 100);
  return fmt::format("{}:{:02d}:{:02d}.{:02d}", hundredths / 360000, hundredths / 6000 % 60,
                     hundredths / 100 % 60, hundredths % 100);
}

}  // namespace ncvm
