#pragma once
// `ncvm compare A B`: two runs side by side (total and modelled time, the breakdown by
// block type and by tool, path lengths, moves, and peck drilling), as text and JSON.
#include <nlohmann/json.hpp>
#include <string>

#include "app/session.hpp"

namespace ncvm {

struct ComparedRun {
  std::string name;  // the program file as given
  Session::Result result;
};

// Plain-text table: one row per quantity, columns A, B, B - A, and B / A in percent.
std::string compareText(const ComparedRun& a, const ComparedRun& b, bool dynamic);
nlohmann::json compareJson(const ComparedRun& a, const ComparedRun& b, bool dynamic);

}  // namespace ncvm
