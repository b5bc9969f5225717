#pragma once
// A macro variable's value: a double that may be vacant (null). Only EQ/NE tell vacant from
// zero; arithmetic reads vacant as 0 (fanuc-reference B.2).
#include <cstdint>

namespace ncvm {

struct Value {
  double v = 0.0;
  bool null = true;

  static Value num(double d) { return Value{d, false}; }
  static Value vacant() { return Value{}; }
  double asNumber() const { return null ? 0.0 : v; }
};

}  // namespace ncvm
