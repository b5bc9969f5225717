#pragma once
// What the command line does differently on a terminal: colour (never into a pipe or a file,
// never with NO_COLOR set or TERM=dumb: https://no-color.org) and a progress line on standard
// error for runs longer than a second.
#include <fmt/format.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <string>
#include <string_view>
#include <thread>

#include "canon/events.hpp"

namespace ncvm::cli {

inline bool isTerminal(std::FILE* f) {
  return ::isatty(::fileno(f)) == 1;
}

inline bool colourWanted(std::FILE* f) {
  const char* noColour = std::getenv("NO_COLOR");
  const char* term = std::getenv("TERM");
  if (noColour && *noColour) return false;
  if (term && std::strcmp(term, "dumb") == 0) return false;
  return isTerminal(f);
}

enum class Paint { Red, Yellow, Green };

inline std::string painted(std::string_view text, Paint p, bool on) {
  if (!on) return std::string(text);
  const char* code = p == Paint::Red ? "31" : p == Paint::Yellow ? "33" : "32";
  return fmt::format("\033[{}m{}\033[0m", code, text);
}

// Counts the moves the control sends (on the control's thread) for the progress line.
class MoveCounter final : public EventSink {
 public:
  void onMove(const MoveEvent&) override { moves_.fetch_add(1, std::memory_order_relaxed); }
  uint64_t moves() const { return moves_.load(std::memory_order_relaxed); }

 private:
  std::atomic<uint64_t> moves_{0};
};

// "ncvm: NAME: 1234567 moves, 3 s" on standard error, rewritten twice a second from the first
// second of the run on, and erased when the run ends (the summary follows on a clean line).
class ProgressLine {
 public:
  ProgressLine(std::string name, const MoveCounter& counter)
      : name_(std::move(name)), counter_(counter), thread_([this] { loop(); }) {}
  ~ProgressLine() {
    {
      std::lock_guard<std::mutex> lock(m_);
      done_ = true;
    }
    cv_.notify_one();
    thread_.join();
    if (shown_) std::fputs("\r\033[K", stderr);
  }
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

 private:
  void loop() {
    const auto start = std::chrono::steady_clock::now();
    std::unique_lock<std::mutex> lock(m_);
    if (cv_.wait_for(lock, std::chrono::seconds(1), [this] { return done_; })) return;
    do {
      const double s =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      fmt::print(stderr, "\r\033[Kncvm: {}: {} moves, {:.0f} s", name_, counter_.moves(), s);
      std::fflush(stderr);
      shown_ = true;
    } while (!cv_.wait_for(lock, std::chrono::milliseconds(500), [this] { return done_; }));
  }

  std::string name_;
  const MoveCounter& counter_;
  std::mutex m_;
  std::condition_variable cv_;
  bool done_ = false;
  bool shown_ = false;
  std::thread thread_;  // last: starts once the rest is built
};

}  // namespace ncvm::cli
