// How `ncvm compare` pairs the two programs' operations and holes (src/app/compare.hpp).
#include "app/compare.hpp"

#include <gtest/gtest.h>

using namespace ncvm;

namespace {
OperationTime op(int tool) {
  OperationTime o;
  o.tool = tool;
  return o;
}
HoleTime hole(uint32_t operation, double x, double y) {
  HoleTime h;
  h.op = operation, h.x = x, h.y = y;
  return h;
}
std::vector<std::pair<int, int>> flat(const std::vector<OperationPair>& v) {
  std::vector<std::pair<int, int>> out;
  for (const auto& p : v) out.emplace_back(p.a, p.b);
  return out;
}
}  // namespace

// The k-th operation of a tool beside the k-th of the same tool; the others alone, where
// they come; every operation once.
TEST(ComparePairing, OperationsByToolAndOccurrence) {
  std::vector<OperationTime> a{op(1), op(2), op(2), op(3)};
  std::vector<OperationTime> b{op(1), op(4), op(2), op(3), op(3)};
  using P = std::pair<int, int>;
  EXPECT_EQ(flat(pairOperations(a, b)),
            (std::vector<P>{{0, 0}, {-1, 1}, {1, 2}, {2, -1}, {3, 3}, {-1, 4}}));
  EXPECT_EQ(flat(pairOperations(a, {})), (std::vector<P>{{0, -1}, {1, -1}, {2, -1}, {3, -1}}));
  EXPECT_EQ(flat(pairOperations({}, b)).size(), 5u);
}

// Holes by position within the paired operations, not by order.
TEST(ComparePairing, HolesByPosition) {
  std::vector<HoleTime> a{hole(0, 0, 0), hole(0, 10, 0), hole(1, 5, 5)};
  std::vector<HoleTime> b{hole(0, 10, 0.0004), hole(0, 20, 0), hole(0, 0, 0), hole(2, 5, 5)};
  using P = std::pair<int, int>;
  EXPECT_EQ(flat(pairHoles(a, 0, b, 0)), (std::vector<P>{{0, 2}, {1, 0}, {-1, 1}}));
  // Holes of other operations stay out; an operation without a partner lists its own.
  EXPECT_EQ(flat(pairHoles(a, 1, b, 2)), (std::vector<P>{{2, 3}}));
  EXPECT_EQ(flat(pairHoles(a, 1, b, -1)), (std::vector<P>{{2, -1}}));
}
