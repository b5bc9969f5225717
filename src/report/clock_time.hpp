#pragma once
// A cycle time as the summary and the report print it, H:MM:SS.ss. The time is rounded to
// hundredths first, so 59.996 s is 0:01:00.00: the carry goes into the minutes, never
// into a seconds field of 60.
#include <string>

namespace ncvm {

std::string clockTime(double seconds);

}  // namespace ncvm
