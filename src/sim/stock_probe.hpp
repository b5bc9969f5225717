#pragma once
// The simulated stock as the control's probe world (probe.use_stock). A stock model's own
// probe world takes the moves' coordinates (the work system in use, program units, X
// radial) and places them in its frame (sim/stock_frame.hpp) as it places the moves; this
// one takes machine millimetres, like every ProbeWorld, so `origin` (work zero on the
// machine now) is asked at every G31.
#include <functional>
#include <optional>

#include "sim/probe_world.hpp"

namespace ncvm {

class StockProbe final : public ProbeWorld {
 public:
  // stock: the model's probe world; unitsPerMm: 1 (mm) or 1 / 25.4 (inch stock);
  // origin: machine position (mm) of work zero now.
  StockProbe(const ProbeWorld& stock, double unitsPerMm, std::function<Vec3()> origin)
      : stock_(stock), scale_(unitsPerMm), origin_(std::move(origin)) {}

  std::optional<double> firstContact(const Vec3& a, const Vec3& b, double r) const override {
    const Vec3 o = origin_();
    auto place = [&](const Vec3& p) {
      return Vec3{(p[0] - o[0]) * scale_, (p[1] - o[1]) * scale_, (p[2] - o[2]) * scale_};
    };
    return stock_.firstContact(place(a), place(b), r * scale_);
  }

 private:
  const ProbeWorld& stock_;
  double scale_;
  std::function<Vec3()> origin_;
};

}  // namespace ncvm
