#pragma once
// The compact record a move crosses the cores in (timing_thread.*): only the fields of a
// MoveEvent the time stage reads, and of those only what the moves before do not already
// say. What crosses between the cores is what the control pays for (every cache line it
// writes is read on the other core), so a plain line of a CAM program, which starts where
// the previous move ended, whose feed and modes did not change and whose line follows the
// previous one, takes 9 words (header, length, time, end and mend X Y Z) instead of 19.
//
// What a record leaves out is a copy of what the worker already has (the previous move's
// end, mend, feed, modes), tested bit for bit (a -0.0 is not a +0.0), so the rebuilt event
// has the control's bits in every field the stage reads. mend is always sent: it cannot be
// derived from end exactly (the executor rounds each from its own nanometre integers, and a
// real work offset makes end + (mend - end) differ from mend in the last bits).
//
// Record: header (kind | words << 8 | flags << 16 | the N number << 32), then what the
// flags say, in this order:
//   mode, exactStop, inch, thread, skip (1 word)  fMode; else the previous move's
//   file | line << 32, programName (2 words)      fOrigin; else the previous with line + 1
//   feed                                          fFeed; else the previous feed
//   length, time                                  always
//   start (N words)                               fStart; else the previous end
//   end (N words)                                 always
//   mstart (N words)                              fMstart; else the previous mend
//   mend (N words)                                always
//   perRev, surfaceSpeed, rpmLimit                fSpin; else 0
//   centre (3 words), plane                       fArc; else {} and 17
// N is 3 on a machine without A, B and C (the stage reads their values only to see whether
// they move, and there they never do) and 6 otherwise. Before the first record the worker's
// "previous" values are a default MoveEvent's, and so are the control's.
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "canon/events.hpp"

namespace ncvm::movecodec {

constexpr uint64_t fMode = 1, fOrigin = 2, fFeed = 4, fStart = 8, fMstart = 16, fSpin = 32,
                   fArc = 64;
// The longest record: header, modes, origin, feed, length, time, four arrays of six, spin,
// arc.
constexpr uint64_t kMaxWords = 1 + 1 + 2 + 1 + 2 + 4 * kMaxAxes + 3 + 4;

static_assert(offsetof(EventOrigin, line) == 4 && offsetof(MoveEvent, at) == 0);
static_assert(offsetof(MoveEvent, time) == offsetof(MoveEvent, length) + sizeof(double));
static_assert(offsetof(MoveEvent, inch) == offsetof(MoveEvent, exactStop) + 1 &&
              offsetof(MoveEvent, skip) == offsetof(MoveEvent, thread) + 1);

inline uint64_t bitsOf(double d) {
  return std::bit_cast<uint64_t>(d);
}
// The lanes the usual move's test compares: N rounded up to an even number, as two-lane
// SIMD does it (on a machine without A, B and C the A lane is tested too: its values are
// 0 there, and a test stricter than needed only sends more).
template <size_t N>
constexpr size_t kLanes = (N + 1) & ~size_t{1};
static_assert(kLanes<3> <= kMaxAxes && kLanes<kMaxAxes> <= kMaxAxes);

inline uint64_t fileLineOf(const EventOrigin& at) {
  return uint64_t{at.file} | uint64_t{at.line} << 32;
}
inline uint64_t modeBitsOf(const MoveEvent& e) {
  uint16_t stopInch, threadSkip;
  std::memcpy(&stopInch, &e.exactStop, 2);
  std::memcpy(&threadSkip, &e.thread, 2);
  return uint64_t{static_cast<uint8_t>(e.mode)} | uint64_t{stopInch} << 8 |
         uint64_t{threadSkip} << 24;
}

// What the control remembers of the moves it sent (the worker has the same in the event it
// rebuilds).
struct History {
  uint64_t fileLine = uint64_t{1} << 32;  // file | line << 32 the next move would have
  const std::string* programName = nullptr;
  uint64_t feed = 0;                      // bits
  uint64_t modeBits = ~uint64_t{0};       // none yet: no move has them, the first record sends them
  uint64_t header = 0;                    // a record with no flags (set by the first record)
  alignas(16) double end[kMaxAxes] = {};  // the previous move's end
  alignas(16) double mend[kMaxAxes] = {};  // and mend
};

// Any record: what differs from the moves before is sent (for the usual move the same
// record as encodeUsual's).
template <size_t N>
[[gnu::noinline]] uint64_t encodeAny(const MoveEvent& e, uint64_t* w, History& h, uint64_t kind) {
  uint64_t* p = w + 1;
  uint64_t f = 0;
  const uint64_t modeBits = modeBitsOf(e);
  if (modeBits != h.modeBits) {
    f |= fMode;
    *p++ = modeBits;
    h.modeBits = modeBits;
  }
  const uint64_t fileLine = fileLineOf(e.at);
  if (fileLine != h.fileLine || e.at.programName != h.programName) {
    f |= fOrigin;
    p[0] = fileLine;
    p[1] = std::bit_cast<uintptr_t>(e.at.programName);
    p += 2;
    h.programName = e.at.programName;
  }
  h.fileLine = fileLine + (uint64_t{1} << 32);
  const uint64_t feed = bitsOf(e.feed);
  if (feed != h.feed) {
    f |= fFeed;
    *p++ = feed;
    h.feed = feed;
  }
  std::memcpy(p, &e.length, 2 * sizeof(double));
  p += 2;
  uint64_t diff = 0;
  for (size_t k = 0; k < N; ++k) diff |= bitsOf(e.start[k]) ^ bitsOf(h.end[k]);
  if (diff) {
    f |= fStart;
    std::memcpy(p, e.start.data(), N * sizeof(double));
    p += N;
  }
  std::memcpy(p, e.end.data(), N * sizeof(double));
  std::memcpy(h.end, e.end.data(), kLanes<N> * sizeof(double));
  p += N;
  diff = 0;
  for (size_t k = 0; k < N; ++k) diff |= bitsOf(e.mstart[k]) ^ bitsOf(h.mend[k]);
  if (diff) {
    f |= fMstart;
    std::memcpy(p, e.mstart.data(), N * sizeof(double));
    p += N;
  }
  std::memcpy(p, e.mend.data(), N * sizeof(double));
  std::memcpy(h.mend, e.mend.data(), kLanes<N> * sizeof(double));
  p += N;
  if ((bitsOf(e.perRev) | bitsOf(e.surfaceSpeed) | bitsOf(e.rpmLimit)) != 0) {
    f |= fSpin;
    p[0] = bitsOf(e.perRev), p[1] = bitsOf(e.surfaceSpeed), p[2] = bitsOf(e.rpmLimit);
    p += 3;
  }
  if (e.arc) {
    f |= fArc;
    std::memcpy(p, e.center.data(), 3 * sizeof(double));
    p[3] = static_cast<uint32_t>(e.plane);
    p += 4;
  }
  h.header = kind | (3 + 2 * N) << 8;
  const auto words = static_cast<uint64_t>(p - w);
  w[0] = kind | words << 8 | f << 16 | uint64_t{static_cast<uint32_t>(e.at.n)} << 32;
  return words;
}

// The usual move (a line on from the previous one: nothing but N, length, time, end and mend
// to say), found with one test: writes its record at w and returns its length in words, or
// 0 when e is not one (then encode() writes it).
template <size_t N>
inline uint64_t encodeUsual(const MoveEvent& e, uint64_t* w, History& h) {
  constexpr size_t L = kLanes<N>;
  const uint64_t fileLine = fileLineOf(e.at);
  uint64_t diff =
      (fileLine ^ h.fileLine) |
      (std::bit_cast<uintptr_t>(e.at.programName) ^ std::bit_cast<uintptr_t>(h.programName)) |
      (bitsOf(e.feed) ^ h.feed) | bitsOf(e.perRev) | bitsOf(e.surfaceSpeed) | bitsOf(e.rpmLimit) |
      (modeBitsOf(e) ^ h.modeBits) | uint64_t{e.arc};
  for (size_t k = 0; k < L; ++k)
    diff |= (bitsOf(e.start[k]) ^ bitsOf(h.end[k])) | (bitsOf(e.mstart[k]) ^ bitsOf(h.mend[k]));
  if (diff != 0) [[unlikely]]  // also the first move: no modes are remembered yet
    return 0;
  w[0] = h.header | uint64_t{static_cast<uint32_t>(e.at.n)} << 32;
  std::memcpy(w + 1, &e.length, 2 * sizeof(double));
  std::memcpy(w + 3, e.end.data(), N * sizeof(double));
  std::memcpy(w + 3 + N, e.mend.data(), N * sizeof(double));
  std::memcpy(h.end, e.end.data(), L * sizeof(double));
  std::memcpy(h.mend, e.mend.data(), L * sizeof(double));
  h.fileLine = fileLine + (uint64_t{1} << 32);
  return 3 + 2 * N;
}

// Writes the record of e at w (room for kMaxWords) with the given kind byte (the same for
// every record of h); returns the number of words written.
template <size_t N>
inline uint64_t encode(const MoveEvent& e, uint64_t* w, History& h, uint64_t kind) {
  if (uint64_t words = encodeUsual<N>(e, w, h)) [[likely]]
    return words;
  return encodeAny<N>(e, w, h, kind);
}

// Rebuilds into e (the previous record's event: what a record leaves out comes from it)
// the fields the stage reads; the others keep what they had.
template <size_t N>
inline void decode(const uint64_t* w, MoveEvent& e) {
  const uint64_t header = w[0];
  const uint64_t f = (header >> 16) & 0xffff;
  const uint64_t* p = w + 1;
  e.at.n = static_cast<int32_t>(static_cast<uint32_t>(header >> 32));
  if (f & fMode) [[unlikely]] {
    const uint64_t m = *p++;
    e.mode = static_cast<MoveMode>(m & 0xff);
    const auto stopInch = static_cast<uint16_t>(m >> 8),
               threadSkip = static_cast<uint16_t>(m >> 24);
    std::memcpy(&e.exactStop, &stopInch, 2);
    std::memcpy(&e.thread, &threadSkip, 2);
  }
  if (f & fOrigin) [[unlikely]] {
    e.at.file = static_cast<uint32_t>(p[0]);
    e.at.line = static_cast<uint32_t>(p[0] >> 32);
    e.at.programName = std::bit_cast<const std::string*>(static_cast<uintptr_t>(p[1]));
    p += 2;
  } else {
    ++e.at.line;
  }
  if (f & fFeed) [[unlikely]]
    std::memcpy(&e.feed, p++, sizeof(double));
  std::memcpy(&e.length, p, 2 * sizeof(double));
  p += 2;
  if (f & fStart) [[unlikely]] {
    std::memcpy(e.start.data(), p, N * sizeof(double));
    p += N;
  } else {
    std::memcpy(e.start.data(), e.end.data(), N * sizeof(double));
  }
  std::memcpy(e.end.data(), p, N * sizeof(double));
  p += N;
  if (f & fMstart) [[unlikely]] {
    std::memcpy(e.mstart.data(), p, N * sizeof(double));
    p += N;
  } else {
    std::memcpy(e.mstart.data(), e.mend.data(), N * sizeof(double));
  }
  std::memcpy(e.mend.data(), p, N * sizeof(double));
  p += N;
  if (f & fSpin) [[unlikely]] {
    std::memcpy(&e.perRev, p, sizeof(double));
    std::memcpy(&e.surfaceSpeed, p + 1, sizeof(double));
    std::memcpy(&e.rpmLimit, p + 2, sizeof(double));
    p += 3;
  } else {
    e.perRev = e.surfaceSpeed = e.rpmLimit = 0;
  }
  e.arc = (f & fArc) != 0;
  if (e.arc) [[unlikely]] {
    std::memcpy(e.center.data(), p, 3 * sizeof(double));
    e.plane = static_cast<int>(static_cast<uint32_t>(p[3]));
  } else {
    e.center = {};
    e.plane = 17;
  }
}

}  // namespace ncvm::movecodec
