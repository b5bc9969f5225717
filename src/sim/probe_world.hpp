#pragma once
// What a G31 probe can touch. The control asks one question — where along this segment
// does a sphere of this radius first touch something — and never learns how the world is
// stored, so the stock simulation can answer it too.
#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "machine/setup.hpp"

namespace ncvm {

using Vec3 = std::array<double, 3>;

class ProbeWorld {
 public:
  virtual ~ProbeWorld() = default;
  // Fraction t in [0, 1] of the segment a->b (machine coordinates, mm) where a sphere of
  // radius r centred on the segment first touches material; nullopt if it never does.
  virtual std::optional<double> firstContact(const Vec3& a, const Vec3& b, double r) const = 0;
};

// Analytic solids from the setup: boxes, cylinders (bosses), bores and planes.
class SolidWorld final : public ProbeWorld {
 public:
  struct Solid {
    enum Kind { Box, Cylinder, Bore, Plane } kind;
    Vec3 a{}, b{};  // box min/max; cylinder/bore centre (x, y); plane point
    Vec3 n{};       // plane normal (material on the -n side)
    double radius = 0, outer = 0, top = 0, bottom = 0;
  };
  // Work-frame solids are placed with `workShift(frameIndex)` (mm per axis X Y Z), the
  // offsets at the start of the run. Throws SetupError for an incomplete solid.
  static std::unique_ptr<SolidWorld> fromSetup(const Setup& setup,
                                               const std::function<Vec3(int)>& workShift);
  void add(const Solid& s) { solids_.push_back(s); }
  bool empty() const { return solids_.empty(); }
  // Signed distance from p to the nearest material (negative inside).
  double distance(const Vec3& p) const;
  std::optional<double> firstContact(const Vec3& a, const Vec3& b, double r) const override;

 private:
  std::vector<Solid> solids_;
};

}  // namespace ncvm
