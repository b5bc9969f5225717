// The stock along the viewer's timeline (server/stock_snapshots.hpp): each snapshot the binary
// run answer carries is the stock of a fresh simulation of the first k moves, byte for byte;
// taking them changes neither the final stock nor the snapshots after them; a long run keeps
// at most 64, spread over the whole run.
#include "server/stock_snapshots.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "app/session.hpp"
#include "server/run_job.hpp"
#include "server/viewer_stream.hpp"
#include "sim/stock_model.hpp"

using namespace ncvm;
using namespace ncvm::server;
using nlohmann::json;

namespace {

struct Shot {
  uint64_t moves;
  std::string payload;
};

struct Answer {
  std::vector<Shot> shots;
  json tail;
  uint64_t streamedMoves = 0;  // moves of the events frames (kind 0-3), as the page counts
};

Answer binaryRun(const json& request) {
  std::string bytes;
  runViewerJob(request, [&](std::string_view f) { bytes.append(f); });
  Answer a;
  for (size_t at = 0; at + 8 <= bytes.size();) {
    uint32_t kind = 0, length = 0;
    std::memcpy(&kind, bytes.data() + at, 4);
    std::memcpy(&length, bytes.data() + at + 4, 4);
    const std::string payload = bytes.substr(at + 8, length);
    if (kind == static_cast<uint32_t>(FrameKind::Stock)) {
      uint32_t lo = 0, hi = 0;
      std::memcpy(&lo, payload.data(), 4);
      std::memcpy(&hi, payload.data() + 4, 4);
      a.shots.push_back({(uint64_t{hi} << 32) | lo, payload});
    } else if (kind == static_cast<uint32_t>(FrameKind::Events)) {
      uint32_t head[kBatchHeader];
      std::memcpy(head, payload.data(), sizeof head);
      a.streamedMoves += head[1];
    } else if (kind == static_cast<uint32_t>(FrameKind::End)) {
      a.tail = json::parse(payload);
    }
    at += 8 + length + (8 - length % 8) % 8;
  }
  return a;
}

// Every event of the run up to (not with) move k + 1, into a model of its own.
class FirstMoves final : public EventSink {
 public:
  FirstMoves(StockModel& model, uint64_t k) : model_(model), k_(k) {}
  void onMove(const MoveEvent& e) override {
    if (++seen_ <= k_) model_.onMove(e);
  }
  void onTool(const ToolEvent& e) override {
    if (seen_ <= k_) model_.onTool(e);
  }
  void onWorkOrigin(const WorkOriginEvent& e) override {
    if (seen_ <= k_) model_.onWorkOrigin(e);
  }

 private:
  StockModel& model_;
  uint64_t k_, seen_ = 0;
};

// The payload of a fresh simulation of the program's first k moves.
std::string freshSimulation(const std::string& program, const std::string& setupText, uint64_t k) {
  Session s(parseSetup(setupText, "setup.toml"));
  s.addProgramText(program, "p.nc");
  s.setTiming(false);  // the events straight from the control, as the stock model takes them
  std::unique_ptr<StockModel> model = makeStockModel(s.setup());
  FirstMoves sink(*model, k);
  s.run(&sink);
  return StockSnapshots::payload(model->viewerSnapshot(256), k);
}

const char* kMillSetup =
    "[machine]\nkind = \"mill\"\nunits = \"mm\"\n[axes.Z]\ninitial = 50.0\n"
    "[tools.1]\ntype = \"flat\"\ndiameter = 10.0\n[tools.2]\ntype = \"ball\"\ndiameter = 6.0\n"
    "[stock]\nmin = [0.0, 0.0, -20.0]\nmax = [100.0, 60.0, 0.0]\ncell = 0.5\n";
// Three slots with an end mill, then a ball-nose pass across them.
const char* kMillProgram =
    "O0002\nT1 M06\nG90 G00 X-10. Y10.\nZ-3.\nG01 X110. F500.\nY30.\nX-10. Z-5.\nG00 Z5.\n"
    "Y50.\nG01 Z-2.\nX110.\nG00 Z50.\nT2 M06\nG00 X50. Y-10.\nG01 Z-8. F300.\nY70.\n"
    "G02 X60. Y60. R10.\nG00 Z50.\nM30\n";

const char* kLatheSetup =
    "[machine]\nkind = \"lathe\"\nunits = \"mm\"\n[axes.X]\ninitial = 100.0\n[axes.Z]\ninitial = "
    "20.0\n[tools.1]\ntype = \"insert\"\nnose_radius = 0.4\ntip = 3\n"
    "[stock]\ndiameter = 50.0\nlength = 60.0\nfront_z = 0.0\n";
// Roughing passes of consecutive feed moves (the lathe joins them into one sweep), an arc.
const char* kLatheProgram =
    "O0001\nG99 T0101\nG00 X52. Z2.\nX46.\nG01 Z-30. F0.2\nX48. Z-31.\nG00 Z2.\nX42.\n"
    "G01 Z-20. F0.2\nX44. Z-21.\nZ-30.\nG00 X52.\nZ2.\nX30.\nG01 Z0.\nG03 X40. Z-5. R5.\n"
    "G01 Z-12.\nX52.\nG00 X100. Z20.\nM30\n";

void expectEveryMoveExact(const char* program, const char* setup) {
  Answer a = binaryRun({{"program", program}, {"setup", setup}, {"stock_every", 1}});
  ASSERT_TRUE(a.tail["ok"].get<bool>()) << a.tail.dump();
  // A snapshot before every move: 0 .. moves - 1; the stock after the last is answer.stock.
  ASSERT_EQ(a.shots.size(), a.streamedMoves);
  EXPECT_EQ(a.tail["stock_snapshots"]["every"], 1);
  for (size_t k = 0; k < a.shots.size(); ++k) {
    ASSERT_EQ(a.shots[k].moves, k);
    EXPECT_EQ(a.shots[k].payload, freshSimulation(program, setup, k)) << "move " << k;
  }
  // The snapshots do not change the final stock.
  json plain = runJob({{"program", program}, {"setup", setup}});
  EXPECT_EQ(a.tail["stock"], plain["stock"]);
  // The first is the stock before any cut, the last differs from it.
  EXPECT_NE(a.shots.front().payload, a.shots.back().payload);
}

}  // namespace

TEST(StockSnapshots, MillSnapshotAtMoveKIsAFreshSimulationOfKMoves) {
  expectEveryMoveExact(kMillProgram, kMillSetup);
}

TEST(StockSnapshots, LatheSnapshotAtMoveKIsAFreshSimulationOfKMoves) {
  expectEveryMoveExact(kLatheProgram, kLatheSetup);
}

TEST(StockSnapshots, ALongRunKeepsAtMost64SpreadOverIt) {
  // 1,000 short feed moves across the block, in a macro loop.
  const std::string program =
      "O0003\nT1 M06\nG90 G00 X0 Y1.\nZ-1.\n#1 = 0\nWHILE [#1 LT 500] DO1\nG01 X100. Y[1 + "
      "#1 * 0.1] F2000.\nX0\n#1 = #1 + 1\nEND1\nG00 Z50.\nM30\n";
  Answer a = binaryRun({{"program", program}, {"setup", kMillSetup}, {"stock_every", 4}});
  ASSERT_TRUE(a.tail["ok"].get<bool>()) << a.tail.dump();
  ASSERT_GE(a.streamedMoves, 1000u);
  const uint64_t every = a.tail["stock_snapshots"]["every"].get<uint64_t>();
  // 4 doubled until the run fits in 64: 1,004 moves need 16 (63 snapshots) or more.
  EXPECT_GE(every, 16u);
  EXPECT_LE(a.shots.size(), 64u);
  EXPECT_GE(a.shots.size(), 32u);
  EXPECT_EQ(a.tail["stock_snapshots"]["count"].get<size_t>(), a.shots.size());
  for (size_t k = 0; k < a.shots.size(); ++k) EXPECT_EQ(a.shots[k].moves, k * every);
  // Exact after the thinning too: the middle one against a fresh run.
  const Shot& mid = a.shots[a.shots.size() / 2];
  EXPECT_EQ(mid.payload, freshSimulation(program, kMillSetup, mid.moves));
}

TEST(StockSnapshots, NoneUnlessAskedOrWithoutAStock) {
  EXPECT_TRUE(binaryRun({{"program", kMillProgram}, {"setup", kMillSetup}}).shots.empty());
  Answer none = binaryRun({{"program", "O1\nG00 X1.\nM30\n"}, {"stock_every", 1}});
  EXPECT_TRUE(none.shots.empty());
  EXPECT_FALSE(none.tail.contains("stock_snapshots"));
}
