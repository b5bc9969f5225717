#pragma once
// Velocity profiles of one block, in the distance domain: how long a velocity change takes
// and how far it goes with a limited acceleration a and, for S-curve (bell-shaped) profiles,
// a limited jerk j. Every ramp starts and ends with zero acceleration, so blocks join
// without an acceleration step. j <= 0 means no jerk limit (a trapezoidal profile).
// Units are whatever the caller uses consistently (ncvm: mm, s).
namespace ncvm::timing {

struct Ramp {
  double a = 0;  // acceleration limit (> 0; 0 or less: unlimited)
  double j = 0;  // jerk limit (> 0), or <= 0 for a trapezoidal profile
};

// Time to change velocity by dv >= 0.
double rampTime(double dv, const Ramp& r);
// Distance covered while changing velocity from v0 to v1 (either direction).
double rampDistance(double v0, double v1, const Ramp& r);
// The highest velocity reachable from v0 within distance d (>= v0).
double reachable(double v0, double d, const Ramp& r);
// Time of a block of length len entered at v0 and left at v1, cruising at most at vmax.
// v0 and v1 must be reachable from each other within len (the planner makes them so); if
// they are not, the time of a constant-acceleration change is returned.
double blockTime(double v0, double v1, double vmax, double len, const Ramp& r);

// The whole profile of a stretch: up-ramp v0 -> vp, cruise at vp, down-ramp vp -> v1, and the
// time at which a given distance is passed (to split a stretch of several blocks).
struct Profile {
  double v0 = 0, vp = 0, v1 = 0, len = 0;
  Ramp r;
  double dUp = 0, tUp = 0, dDown = 0, tDown = 0, tCruise = 0;
  double total() const { return tUp + tCruise + tDown; }
  // Inline for the cruise, where most blocks of a long stretch end.
  double timeAt(double s) const {
    if (s > dUp && s <= len - dDown && vp > 0) return tUp + (s - dUp) / vp;
    return timeOutsideCruise(s);
  }
  double timeOutsideCruise(double s) const;
};
Profile makeProfile(double v0, double v1, double vmax, double len, const Ramp& r);

}  // namespace ncvm::timing
