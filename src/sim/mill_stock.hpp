#pragma once
// The mill stock model: the setup's [stock] block as a height field (sim/heightfield.hpp),
// cut by every move with the physical tool of [tools.T] (sim/mill_sim.hpp), measured against
// [target] (sim/mill_analysis.hpp) and drawn (report/mill_pictures.hpp, report/stl_writer.hpp).
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sim/mill_analysis.hpp"
#include "sim/mill_sim.hpp"
#include "sim/model_probe.hpp"
#include "sim/stock_frame.hpp"
#include "sim/stock_model.hpp"

namespace ncvm {

class MillStock final : public StockModel {
 public:
  // Throws SetupError for an incomplete [stock], a bad [tools] entry or target file.
  explicit MillStock(const Setup& setup);

  void onMove(const MoveEvent& e) override;
  void onTool(const ToolEvent& e) override;
  void onWorkOrigin(const WorkOriginEvent& e) override { frame_.origin(e); }
  nlohmann::json finish(const std::string& outDir) override;
  nlohmann::json viewerStock(int maxGrid) override;
  ViewerStockData viewerSnapshot(int maxGrid) override;
  const ProbeWorld* probeWorld() const override { return &probe_; }

  MillSim& sim() { return *sim_; }
  double cell() const { return cell_; }

 private:
  void select(int t);
  uint32_t tag(const MoveEvent& e);
  void arc(const MoveEvent& e, uint32_t tag);
  nlohmann::json analysis(const std::string& outDir);

  // G31 against the field as cut so far (sim/heightfield_probe.hpp), stock coordinates:
  // applies the queued moves first.
  std::optional<double> probeContact(const Vec3& a, const Vec3& b, double r);
  friend class ModelProbe<MillStock>;
  ModelProbe<MillStock> probe_{*this, frame_};

  const Setup& setup_;
  StockFrame frame_;
  MoveEvent placed_;  // scratch: a move shifted into the stock frame
  double unit_ = 1, cell_ = 0.05, tol_ = 0.01;
  std::unique_ptr<MillSim> sim_;
  std::map<int, MillTool> tools_;  // cutting tools of [tools], by T
  std::optional<HeightField> targetField_;
  std::optional<MillTarget> target_;
  int selected_ = -1;       // last T word
  int current_ = -1;        // tool in the spindle
  double probeRadius_ = 0;  // > 0 while a probe is in the spindle (its ball radius)
  struct ProbeHit {
    uint32_t tag;
    double amount;  // how far the move went on past the first contact
  };
  std::vector<ProbeHit> probeHits_;  // probe moves other than G31 that ran into the stock
  void checkProbeMove(const MoveEvent& e);
  bool changed_ = false;
  nlohmann::json toolsUsed_ = nlohmann::json::array();
  std::vector<std::string> notes_;
  std::vector<EventOrigin> origins_;  // by tag
  uint64_t moves_ = 0;
};

}  // namespace ncvm
