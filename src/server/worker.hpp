#pragma once
// Each run of the web viewer happens in a child process (`ncvm serve-worker`): a runaway
// program is killed at the wall-clock deadline, a crash or a memory blow-up ends only that
// request, and concurrent tabs never share a control.
#include <chrono>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>

namespace ncvm::server {

struct WorkerLimits {
  std::chrono::milliseconds timeout{10'000};  // wall clock, per request
  uint64_t maxOutputBytes = 256u << 20;       // the answer
  uint64_t memoryBytes = 2ull << 30;          // address space of the child (RLIMIT_AS)
};

struct WorkerResult {
  enum class Status { Ok, Timeout, Failed, TooLarge } status = Status::Failed;
  std::string output;  // the child's answer (JSON) when Ok
  std::string detail;  // why, otherwise
};

// Runs `exe serve-worker` with `input` on its stdin; returns what it wrote on stdout. With
// `onOutput`, the output goes there as it arrives instead (WorkerResult::output stays empty);
// onOutput returning false (the client went away) kills the worker.
WorkerResult runWorker(const std::string& exe, const std::string& input, const WorkerLimits& limits,
                       const std::function<bool(std::string_view)>& onOutput = {});

// The child's answer (JSON text) to one request (JSON text): runJob, with a malformed request
// or an exhausted memory cap answered as {"ok": false, "error"}.
std::string workerAnswer(const std::string& request);

// The child's side: reads the request from stdin, runs it (run_job.hpp), writes the answer:
// JSON, or with "format": "binary" in the request the frames of viewer_stream.hpp, each as
// soon as it is made.
// `memoryBytes` caps its own address space first (0: no cap).
int workerMain(uint64_t memoryBytes);

}  // namespace ncvm::server
