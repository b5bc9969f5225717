// The compact move records of the time stage's worker (src/timing/move_codec.hpp): every
// field the stage reads comes back with the control's bits, whatever the record leaves out.
#include "timing/move_codec.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

using namespace ncvm;
namespace mc = ncvm::movecodec;

namespace {

uint64_t b(double d) {
  return std::bit_cast<uint64_t>(d);
}

// The fields the stage reads, bit for bit (N axes of the four arrays).
void expectSame(const MoveEvent& want, const MoveEvent& got, size_t axes, int move) {
  SCOPED_TRACE("move " + std::to_string(move));
  EXPECT_EQ(want.at.file, got.at.file);
  EXPECT_EQ(want.at.line, got.at.line);
  EXPECT_EQ(want.at.n, got.at.n);
  EXPECT_EQ(want.at.programName, got.at.programName);
  EXPECT_EQ(want.mode, got.mode);
  for (size_t k = 0; k < axes; ++k) {
    EXPECT_EQ(b(want.start[k]), b(got.start[k])) << "start " << k;
    EXPECT_EQ(b(want.end[k]), b(got.end[k])) << "end " << k;
    EXPECT_EQ(b(want.mstart[k]), b(got.mstart[k])) << "mstart " << k;
    EXPECT_EQ(b(want.mend[k]), b(got.mend[k])) << "mend " << k;
  }
  EXPECT_EQ(b(want.feed), b(got.feed));
  EXPECT_EQ(b(want.length), b(got.length));
  EXPECT_EQ(b(want.time), b(got.time));
  EXPECT_EQ(want.exactStop, got.exactStop);
  EXPECT_EQ(want.inch, got.inch);
  EXPECT_EQ(b(want.perRev), b(got.perRev));
  EXPECT_EQ(b(want.surfaceSpeed), b(got.surfaceSpeed));
  EXPECT_EQ(b(want.rpmLimit), b(got.rpmLimit));
  EXPECT_EQ(want.arc, got.arc);
  if (want.arc) {
    for (size_t k = 0; k < 3; ++k) EXPECT_EQ(b(want.center[k]), b(got.center[k]));
    EXPECT_EQ(want.plane, got.plane);
  }
  EXPECT_EQ(want.thread, got.thread);
  EXPECT_EQ(want.skip, got.skip);
}

// Encodes the moves one after the other into one stream, as the control does, and decodes
// them as the worker does; returns the words of each record.
template <size_t N>
std::vector<uint64_t> roundTrip(const std::vector<MoveEvent>& moves) {
  std::vector<uint64_t> stream(moves.size() * mc::kMaxWords + 8);
  mc::History h;
  std::vector<uint64_t> sizes;
  uint64_t at = 0;
  for (const MoveEvent& e : moves) {
    const uint64_t words = mc::encode<N>(e, &stream[at], h, 1);
    EXPECT_EQ(stream[at] & 0xff, 1u);
    EXPECT_EQ((stream[at] >> 8) & 0xff, words);
    EXPECT_LE(words, mc::kMaxWords);
    sizes.push_back(words);
    at += words;
  }
  // encodeAny alone (the control's path when the usual test failed or found no room) writes
  // the same records.
  std::vector<uint64_t> any(stream.size());
  mc::History h2;
  uint64_t at2 = 0;
  for (const MoveEvent& e : moves) at2 += mc::encodeAny<N>(e, &any[at2], h2, 1);
  EXPECT_EQ(at2, at);
  EXPECT_TRUE(
      std::equal(any.begin(), any.begin() + static_cast<std::ptrdiff_t>(at), stream.begin()));
  MoveEvent got;
  at = 0;
  for (size_t k = 0; k < moves.size(); ++k) {
    mc::decode<N>(&stream[at], got);
    expectSame(moves[k], got, N, static_cast<int>(k));
    at += sizes[k];
  }
  return sizes;
}

// A raster line on from the previous move: the usual move.
MoveEvent lineOn(const MoveEvent& prev, double dx, double dy, double dz, const double* off) {
  MoveEvent e = prev;
  e.arc = false;
  ++e.at.line;
  e.start = prev.end;
  e.mstart = prev.mend;
  for (size_t k = 0; k < 3; ++k) {
    e.end[k] = prev.end[k] + (k == 0 ? dx : k == 1 ? dy : dz);
    e.mend[k] = e.end[k] + off[k];
  }
  e.length = std::sqrt(dx * dx + dy * dy + dz * dz);
  e.time = e.length / e.feed * 60;
  return e;
}

}  // namespace

TEST(MoveCodec, UsualLineTakesNineWords) {
  const std::string prog = "O1";
  std::vector<MoveEvent> moves;
  MoveEvent e;
  e.at = EventOrigin{0, 7, -1, &prog};
  e.feed = 3000;
  e.end = {1, 2, -1, 0, 0, 0};
  const double off[3] = {-123.4567, -45.6789, -300.1234};
  e.mend = {1 + off[0], 2 + off[1], -1 + off[2], 0, 0, 0};
  e.length = 3, e.time = 0.06;
  moves.push_back(e);
  for (int k = 0; k < 50; ++k) moves.push_back(lineOn(moves.back(), 0.2, 0.0, 0.01 * (k % 3), off));
  std::vector<uint64_t> sizes = roundTrip<3>(moves);
  // The first record says everything; from the second on only N, length, time, end and
  // mend (a work offset that is not a round number: mend is sent, never derived).
  EXPECT_GT(sizes[0], 9u);
  for (size_t k = 1; k < sizes.size(); ++k) EXPECT_EQ(sizes[k], 9u) << k;
  std::vector<uint64_t> six = roundTrip<kMaxAxes>(moves);
  for (size_t k = 1; k < six.size(); ++k) EXPECT_EQ(six[k], 15u) << k;
}

// Each thing a record may leave out, changed on its own between usual moves, and mixed at
// random: the rebuilt fields are the control's, bit for bit (a field that a record drops
// wrongly fails here).
TEST(MoveCodec, EveryOmissionRebuildsTheControlsBits) {
  const std::string progA = "O1", progB = "O2";
  const double off[3] = {-100, -50.5, -200.25};
  std::vector<MoveEvent> moves;
  MoveEvent e;
  e.at = EventOrigin{0, 1, -1, &progA};
  e.feed = 1000;
  e.end = {0, 0, 5, 0, 0, 0};
  e.mend = {-100, -50.5, 5 - 200.25, 0, 0, 0};
  e.length = 5, e.time = 0.3;
  moves.push_back(e);
  auto usual = [&] { moves.push_back(lineOn(moves.back(), 0.2, 0.1, -0.01, off)); };
  auto changed = [&](auto change) {
    usual();
    MoveEvent m = lineOn(moves.back(), 0.3, -0.1, 0.02, off);
    change(m);
    moves.push_back(m);
    usual();
    usual();
  };
  usual();
  changed([](MoveEvent& m) { m.at.n = 120; });                       // N (always sent)
  changed([](MoveEvent& m) { m.at.line += 5; });                     // a jump (a loop, a call)
  changed([](MoveEvent& m) { m.at.line -= 1; });                     // the same line again
  changed([](MoveEvent& m) { m.at.file = 3; });                      // another file
  changed([&](MoveEvent& m) { m.at.programName = &progB; });         // another program
  changed([](MoveEvent& m) { m.feed = 2500; });                      // feed
  changed([](MoveEvent& m) { m.mode = MoveMode::Rapid; });           // mode
  changed([](MoveEvent& m) { m.exactStop = true; });                 // G09
  changed([](MoveEvent& m) { m.inch = true; });                      // G20
  changed([](MoveEvent& m) { m.thread = true; });                    // G32
  changed([](MoveEvent& m) { m.skip = true; });                      // G31
  changed([](MoveEvent& m) { m.start[1] += 1e-9; });                 // start is not the last end
  changed([](MoveEvent& m) { m.start[2] = -0.0, m.end[2] = 0; });    // -0.0 is not +0.0
  changed([](MoveEvent& m) { m.mstart[0] += 10; });                  // mstart is not the last mend
  changed([](MoveEvent& m) { m.mstart[1] = -0.0, m.mend[1] = 0; });  // -0.0 is not +0.0
  changed([](MoveEvent& m) { m.mend[2] += 0.5; });                   // the offset changes
  // An offset that does not round-trip: end + (mend - end) is not mend.
  changed([](MoveEvent& m) { m.end[0] = 1, m.mend[0] = 1e-20; });
  changed([](MoveEvent& m) {  // G96 with G95
    m.perRev = 0.2, m.surfaceSpeed = 180, m.rpmLimit = 3000;
  });
  changed([](MoveEvent& m) { m.rpmLimit = 2500; });
  changed([](MoveEvent& m) {  // an arc
    m.arc = true, m.mode = MoveMode::Cw, m.center = {1, 2, 3}, m.plane = 18;
  });
  changed([](MoveEvent& m) { m.time = std::numeric_limits<double>::quiet_NaN(); });
  roundTrip<3>(moves);
  roundTrip<kMaxAxes>(moves);

  // Rotary axes: A, B and C values are carried by six-axis records.
  std::vector<MoveEvent> five = moves;
  for (size_t k = 0; k < five.size(); ++k) {
    five[k].end[3] = 0.5 * static_cast<double>(k), five[k].mend[3] = five[k].end[3];
    five[k].end[5] = -1.0 * static_cast<double>(k % 7), five[k].mend[5] = five[k].end[5] + 90;
    if (k > 0) {
      five[k].start[3] = five[k - 1].end[3], five[k].mstart[3] = five[k - 1].mend[3];
      five[k].start[5] = five[k - 1].end[5], five[k].mstart[5] = five[k - 1].mend[5];
    }
  }
  roundTrip<kMaxAxes>(five);

  // At random: each field kept or changed on its own.
  std::mt19937_64 rng(9);
  std::vector<MoveEvent> mixed(1, moves.front());
  for (int k = 0; k < 3000; ++k) {
    MoveEvent m = lineOn(mixed.back(), 0.1, 0.2, 0.0, off);
    const uint64_t r = rng();
    if (r & 1) m.at.n = static_cast<int32_t>(r >> 40);
    if ((r & 0x6) == 0x6) m.at.line = static_cast<uint32_t>(r >> 20) & 0xffff;
    if ((r & 0x38) == 0x38) m.feed = static_cast<double>((r >> 12) & 0xfff);
    if ((r & 0x1c0) == 0x1c0) m.start[(r >> 30) % 3] += 0.001;
    if ((r & 0xe00) == 0xe00) m.mstart[(r >> 33) % 3] -= 0.002;
    if ((r & 0x7000) == 0x7000) m.mend[(r >> 35) % 3] += 0.25;
    if ((r & 0x38000) == 0x38000) m.perRev = 0.1;
    if ((r & 0x1c0000) == 0x1c0000) {
      m.arc = true;
      m.center = {static_cast<double>(r & 0xff), 1, 2};
      m.plane = 17 + static_cast<int>((r >> 50) % 3);
    }
    if ((r & 0xe00000) == 0xe00000) m.mode = static_cast<MoveMode>((r >> 52) & 3);
    if ((r & 0x7000000) == 0x7000000) m.exactStop = !m.exactStop;
    mixed.push_back(m);
  }
  roundTrip<3>(mixed);
  roundTrip<kMaxAxes>(mixed);
}
