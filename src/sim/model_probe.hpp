#pragma once
// A stock model as a ProbeWorld (StockModel::probeWorld): one adapter for the lathe and the
// mill. It takes the moves' coordinates (the work system in use, program units, X radial),
// shifts them into the stock's frame as the moves are (sim/stock_frame.hpp) and asks the
// model, whose contact test may first cut the moves it still holds (hence not const).
#include <optional>

#include "sim/probe_world.hpp"
#include "sim/stock_frame.hpp"

namespace ncvm {

template <class Model>
class ModelProbe final : public ProbeWorld {
 public:
  ModelProbe(Model& model, const StockFrame& frame) : model_(model), frame_(frame) {}

  std::optional<double> firstContact(const Vec3& a, const Vec3& b, double r) const override {
    const auto& d = frame_.shift();
    return model_.probeContact({a[0] + d[0], a[1] + d[1], a[2] + d[2]},
                               {b[0] + d[0], b[1] + d[1], b[2] + d[2]}, r);
  }

 private:
  Model& model_;
  const StockFrame& frame_;
};

}  // namespace ncvm
