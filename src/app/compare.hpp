#pragma once
// `ncvm compare A B`: two runs side by side (total and modelled time, the breakdown by
// block type, by tool and by operation with its holes, path lengths, moves, and peck
// drilling), as text and JSON.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "app/session.hpp"
#include "timing/time_report.hpp"

namespace ncvm {

struct ComparedRun {
  std::string name;  // the program file as given
  Session::Result result;
};

// Which operation of A goes with which of B (-1: none), in the order the rows show them:
// the k-th operation of a tool in A beside the k-th of the same tool in B, in A's order, and
// B's without a partner where they come in B. Every operation of each program has one row,
// so the rows add up to the cycle times.
struct OperationPair {
  int a = -1, b = -1;
};
std::vector<OperationPair> pairOperations(const std::vector<OperationTime>& a,
                                          const std::vector<OperationTime>& b);
// The holes of operation `opA` of A and `opB` of B (-1: none) side by side, paired by
// position (within 0.001): indexes into the two hole lists, -1 for no partner.
std::vector<OperationPair> pairHoles(const std::vector<HoleTime>& a, int opA,
                                     const std::vector<HoleTime>& b, int opB);

// Plain-text table: one row per quantity, columns A, B, B - A, and B / A in percent.
std::string compareText(const ComparedRun& a, const ComparedRun& b, bool dynamic);
nlohmann::json compareJson(const ComparedRun& a, const ComparedRun& b, bool dynamic);

}  // namespace ncvm
