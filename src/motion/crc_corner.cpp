#include "motion/crc_corner.hpp"

#include <cmath>
#include <optional>

#include "motion/crc_geom.hpp"

namespace ncvm::crc::corner {

using namespace geom;

namespace {

// Everything the rules need to know about one corner, computed once.
struct Corner {
  const InSeg& a;
  const InSeg& b;
  double dA, dB, eps;
  P2 tA, tB;  // directions of travel at the corner
  P2 pA, pB;  // tool centre perpendicular to a at its end and to b at its start

  Corner(const InSeg& a_, double dA_, const InSeg& b_, double dB_, double eps_)
      : a(a_), b(b_), dA(dA_), dB(dB_), eps(eps_) {
    tA = tangentAt(a, a.end);
    tB = tangentAt(b, b.start);
    pA = offsetPoint(a, a.end, dA, eps);
    pB = offsetPoint(b, b.start, dB, eps);
  }

  // The two offset paths meet here (the one nearest the corner, when there are two).
  std::optional<P2> meet() const {
    return intersect(offsetCurve(a, a.end, dA, eps), offsetCurve(b, b.start, dB, eps),
                     0.5 * (pA + pB), eps);
  }

  P2 meetOrAlarm() const {
    if (auto x = meet()) return *x;
    throw CrcError(AlarmId::NoIntersectionCrc, "the offset paths do not meet", b.tag);
  }

  bool tangent() const { return std::abs(cross(tA, tB)) <= eps && dot(tA, tB) > 0; }
  // Inner: the path turns towards the tool, so the workpiece-side angle exceeds 180 degrees.
  // A reversal (cross 0, dot < 0) is an outer corner of 0 degrees.
  bool inner() const { return (dA > 0 ? 1 : -1) * cross(tA, tB) > eps; }
  // Outer corners of 90 degrees or more on the workpiece side are cut to the intersection;
  // the tolerance keeps an exact right angle out of the acute branch.
  bool acute() const { return dot(tA, tB) < -eps; }

  // Outer acute corner: extend a by r along its direction, cross to the point r before the
  // start of b's offset path, so the corner is cut with straight lines. An arc cannot be
  // extended, so the perpendicular points of arcs are visited as well.
  std::vector<P2> extraVectors() const {
    double r = std::abs(dA);
    std::vector<P2> pts;
    if (a.kind != Kind::Line) pts.push_back(pA);
    pts.push_back(pA + r * tA);
    pts.push_back(pB - r * tB);
    if (b.kind != Kind::Line) pts.push_back(pB);
    return pts;
  }
};

// G41 <-> G42 (or a sign change of D) between a and b: there is no inside or outside, only
// the intersection of the old-side path of a with the new-side path of b. Without one the
// control ends a perpendicular to itself and moves across to b's perpendicular start.
std::vector<P2> sideChange(const Corner& c) {
  if (auto x = c.meet()) return {*x};
  return {c.pA, c.pB};
}

// Type A start-up and cancel at an outer corner, and cancel at an inner one, use the
// perpendicular vector: at the end of the start-up block it is perpendicular to the NEXT
// block, before a cancel block it is perpendicular to the end of the previous block.
std::vector<P2> perpendicular(const Corner& c, Rule rule) {
  bool startup = rule == Rule::StartupA || rule == Rule::StartupB;
  return {startup ? c.pB : c.pA};
}

}  // namespace

std::vector<P2> place(const InSeg& a, double dA, const InSeg& b, double dB, Rule rule, double eps) {
  // The order follows the manual's tables: side changes have their own rule; a straight
  // continuation needs none; an inner corner goes to the intersection, start-up included
  // (seed 002: a 0i-MC running the paper's G42 face-milling program makes its passes at
  // Y 25, 25, -75, -75, ... only this way), except before a cancel block, which ends
  // perpendicular; type A start-up/cancel at outer corners is perpendicular; outer corners
  // split at 90 degrees.
  Corner c(a, dA, b, dB, eps);
  if ((dA > 0) != (dB > 0)) return sideChange(c);
  if (c.tangent()) return {c.pA};
  bool typeA = rule == Rule::StartupA || rule == Rule::CancelA;
  bool cancel = rule == Rule::CancelA || rule == Rule::CancelB;
  if (c.inner() && cancel) return perpendicular(c, rule);
  if (c.inner()) return {c.meetOrAlarm()};
  if (typeA) return perpendicular(c, rule);
  if (!c.acute()) return {c.meetOrAlarm()};
  return c.extraVectors();
}

std::vector<P2> placeToward(const InSeg& a, double dA, P2 dir, double eps) {
  InSeg virt;
  virt.start = a.end;
  virt.end = a.end + dir;
  virt.tag = a.tag;
  Corner c(a, dA, virt, dA, eps);
  if (auto x = c.meet()) return {*x};
  return {c.pA};
}

}  // namespace ncvm::crc::corner
