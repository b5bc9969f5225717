#pragma once
// The [timing] section of the setup (docs/setup-format.md) as data: the machine's motion
// limits and the times of its auxiliary functions, named after the Fanuc parameters that hold
// them. The cycle-time model (src/timing) reads it; machine/timing_keys.hpp parses its keys.
// With dynamic = false (model = "simple", the default) ncvm keeps the plain length / feed time.
#include "canon/events.hpp"

namespace ncvm {

struct TimingSetup {
  bool dynamic = false;  // model = "dynamic": acceleration, jerk, look-ahead, aux times
  // Per axis (X Y Z A B C); the plain keys set every axis, timing.axes.X.* one axis.
  AxisArray rapidT1Ms{100, 100, 100, 100, 100, 100};    // 1620 rapid acc/dec time constant T1
  AxisArray rapidT2Ms{50, 50, 50, 50, 50, 50};          // 1621 bell-shaped rapid T2 (0: linear)
  AxisArray accel{1500, 1500, 1500, 1500, 1500, 1500};  // 1660 acc before interpolation, mm/s^2
  AxisArray cornerSpeedDiff{500, 500, 500,
                            500, 500, 500};  // 1783 permissible speed difference, mm/min
  double accelChangeMs = 40;  // 1772 acceleration change time (bell-shaped); 0: linear
  int lookaheadBlocks = 40;   // blocks read ahead for acc/dec before interpolation
  double arcClampFeed = 5000, arcClampRadius = 5;  // 1730 / 1731: a = V^2 / R on arcs
  double arcClampMinFeed = 100;                    // 1732 lower limit of the arc clamp
  double minBlockTimeMs = 1.0;  // block processing time: a block never takes less
  double inPositionS = 0.010;   // in-position check at rapid ends and exact stops
  double toolChangeS = 2.5;     // M06
  double tCodeS = 0.0;          // T selection (lathe: turret index)
  double mCodeS = 0.1;          // any M code with a FIN (M03/M04/M05 add the spindle ramp)
  double coolantS = 0.1;        // M07/M08/M09
  double spindleAccel = 5000;   // rpm/s, spindle ramps and G96 following
  bool spindleWait = true;      // M03/M04/M05/S wait for the speed arrival (SAR)
  double feedOverride = 100, rapidOverride = 100;  // percent
  // A comment alone on its line starts an operation of the time report (as a tool change
  // does) and names it; false: operations start at tool changes only.
  bool operationComments = true;
};

}  // namespace ncvm
