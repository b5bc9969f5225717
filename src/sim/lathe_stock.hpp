#pragma once
// The lathe stock: an exact half-profile (r >= 0, z) of the solid of revolution, kept as
// integer polygons (Clipper, 1e-6 program units) split into tiles along Z so a move only
// clips the few tiles its swept area touches. Each move removes the area the tool outline
// sweeps (sim/lathe_insert.hpp); arcs are followed in chords whose sagitta stays below a
// fraction of the tolerance.
#include <map>
#include <polyclipping/clipper.hpp>
#include <string>
#include <vector>

#include "sim/deviation.hpp"
#include "sim/lathe_insert.hpp"
#include "sim/lathe_reachable.hpp"
#include "sim/model_probe.hpp"
#include "sim/stock_frame.hpp"
#include "sim/stock_model.hpp"

namespace ncvm {

class LatheStock final : public StockModel {
 public:
  // Throws SetupError when the stock is not a bar or tube.
  explicit LatheStock(const Setup& setup);

  void onMove(const MoveEvent& e) override;
  void onTool(const ToolEvent& e) override;
  void onWorkOrigin(const WorkOriginEvent& e) override { frame_.origin(e); }
  nlohmann::json finish(const std::string& outDir) override;
  nlohmann::json viewerStock(int maxGrid) override;
  ViewerStockData viewerSnapshot(int maxGrid) override;
  const ProbeWorld* probeWorld() const override { return &probe_; }

  // The pieces, for tests and benchmarks. Points are (radius, z) of the programmed point.
  void selectTool(const ToolSpec& tool);
  // Removes the area swept from a to b; returns the area removed (program units^2).
  // `reached` (if given) is set when the swept area reaches a tile's material bounds.
  double cutLine(lsim::Pt a, lsim::Pt b, bool* reached = nullptr);
  // The same for a feed move, deferred: consecutive moves with the same extreme tool
  // vertices are cut as one polygon (lsim::sweepPath) at flush(), or when the next move
  // cannot join them. Returns whether the move's own sweep reaches the material as it stood
  // before the pending moves (tile bounds and the sweep's lower envelope).
  bool queueLine(lsim::Pt a, lsim::Pt b);
  double flush();  // cuts the pending moves; returns the area removed
  double area();
  ClipperLib::Paths profile();           // the tiles merged: outer rings and holes
  static constexpr double kScale = 1e6;  // integer units per program unit

 private:
  struct Tile {
    ClipperLib::Paths paths;
    ClipperLib::cInt zmin = 0, zmax = 0, rmin = 0, rmax = 0;  // bounds of the material
    double area = 0;
    bool empty = false;
  };
  struct TargetSeg {
    lsim::Pt a, b;
    int n = -1;
  };
  struct Sample {
    lsim::Pt p;
    double d = 0;
    int n = -1;
  };

  // Removes the convex counter-clockwise polygon from the tiles; returns the area removed.
  double apply(const ClipperLib::Path& poly, bool& reached);
  bool touches(const ClipperLib::Path& poly) const;
  double overlap(const ClipperLib::Path& poly);  // area of the stock inside the polygon
  double applyWithMirror(const ClipperLib::Path& poly, bool* reached);
  void refreshBounds(Tile& t);
  void cutPath(const std::vector<lsim::Pt>& pts, const MoveEvent& e);
  void cutMove(const std::vector<lsim::Pt>& pts, const MoveEvent& e);
  void captureTarget(const MoveEvent& e, const std::vector<lsim::Pt>& pts);
  // A probe moved other than by G31 into the stock: a "probe" collision (it does not cut).
  void checkProbeMove(const MoveEvent& e, const std::vector<lsim::Pt>& pts);
  void loadTargetFile();
  // reach: filled for [target] reachable = "nose" (the samples then lie on its boundary).
  std::vector<Sample> measure(const ClipperLib::Paths& final, ReachablePart* reach) const;
  std::vector<Sample> measureReachable(const ClipperLib::Paths& final, ReachablePart& reach) const;
  double targetNoseRadius() const;
  nlohmann::json writeOutputs(const std::string& dir, const ClipperLib::Paths& final,
                              const std::vector<Sample>& samples, nlohmann::json& analysis) const;

  const Setup& setup_;
  StockFrame frame_;
  MoveEvent placed_;  // scratch: a move shifted into the stock frame
  double unit_ = 1;   // 1 mm in program units (1/25.4 in an inch setup)
  double tol_ = 0.01, chord_ = 0.0005;
  double rIn_ = 0, rOut_ = 0, zFront_ = 0, zBack_ = 0;
  double tileWidth_ = 1;
  ClipperLib::cInt tileZ0_ = 0, tileW_ = 1;
  std::vector<Tile> tiles_;
  ClipperLib::Clipper clipper_;
  // Scratch paths kept between moves so their storage is reused.
  std::vector<lsim::Pt> swept_;
  ClipperLib::Path poly_, mirror_, boxed_, scratch_;
  ClipperLib::Paths result_;
  static constexpr ClipperLib::cInt kMargin = 64;  // units (64 nm) around a tile's material
  // The pending feed moves: the path and the hull vertices its sides leave from. Separate
  // sweeps of consecutive moves overlap, and Clipper pays for every crossing between clip
  // polygons (16 of them per operation measured slower than one at a time); their union as
  // one polygon has no crossings. The cap bounds the polygon's size.
  std::vector<lsim::Pt> pending_;
  size_t pendLo_ = 0, pendHi_ = 0;
  static constexpr size_t kMaxPending = 16;
  std::vector<lsim::Pt> outline_;  // the tool's convex hull, counter-clockwise in (z, r)
  std::vector<lsim::Pt> holder_;   // the holder's rectangle (empty: no holder given)
  nlohmann::json tools_ = nlohmann::json::array();
  std::vector<std::string> notes_;
  bool toolKnown_ = false;
  bool cuts_ = true;        // false while a probe is in the turret
  double probeRadius_ = 0;  // the probe's ball radius while !cuts_ (0: a point)
  // Nose radii for reachable = "nose": the tool's as the target blocks ran (-1: not yet), and
  // the largest of the cutting tools (for a polyline target).
  double noseNow_ = 0, noseTarget_ = -1, noseMax_ = 0;
  // Statistics.
  uint64_t moves_ = 0, cuttingMoves_ = 0;
  double removed_ = 0;
  nlohmann::json collisions_ = nlohmann::json::array();
  // Target from blocks: the feed moves of the range, first pass only.
  std::vector<TargetSeg> target_;
  bool capturing_ = false, captured_ = false;
  const std::string* targetProgram_ = nullptr;
  lsim::Pt programmed_{};  // last programmed point (cutter compensation gives it apart)
  bool havePos_ = false;
  std::string targetSource_;

  // G31 against the profile as cut so far (sim/lathe_probe.hpp), stock coordinates (X
  // radial): applies the queue first.
  std::optional<double> probeContact(const Vec3& a, const Vec3& b, double r);
  friend class ModelProbe<LatheStock>;
  ModelProbe<LatheStock> probe_{*this, frame_};
};

}  // namespace ncvm
