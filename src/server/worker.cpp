#include "server/worker.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <iostream>
#include <iterator>
#include <mutex>
#include <vector>

#include "server/run_job.hpp"
#include "server/viewer_stream.hpp"

extern char** environ;

// GCC says __SANITIZE_ADDRESS__ under -fsanitize=address; clang 14 only answers __has_feature.
#if defined(__SANITIZE_ADDRESS__)
#define NCVM_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define NCVM_UNDER_ASAN 1
#endif
#endif

namespace ncvm::server {

namespace {

struct Fd {
  int fd = -1;
  ~Fd() { reset(); }
  void reset() {
    if (fd >= 0) ::close(fd);
    fd = -1;
  }
};

// Kills and reaps the child on every way out of runWorker.
struct Child {
  pid_t pid = -1;
  ~Child() {
    if (pid <= 0) return;
    ::kill(pid, SIGKILL);
    int st = 0;
    while (::waitpid(pid, &st, 0) < 0 && errno == EINTR) {
    }
  }
};

}  // namespace

WorkerResult runWorker(const std::string& exe, const std::string& input, const WorkerLimits& limits,
                       const std::function<bool(std::string_view)>& onOutput) {
  // A worker that dies before reading its request must give EPIPE here, not kill the server.
  static std::once_flag ignorePipe;
  std::call_once(ignorePipe, [] { std::signal(SIGPIPE, SIG_IGN); });
  WorkerResult res;
  int in[2], out[2];
  // O_CLOEXEC: a pipe end must not leak into a worker spawned at the same time by another
  // thread, or that worker would keep this one's stdin open.
  if (::pipe2(in, O_CLOEXEC) != 0) return {WorkerResult::Status::Failed, "", "pipe failed"};
  Fd inRead{in[0]}, inWrite{in[1]};
  if (::pipe2(out, O_CLOEXEC) != 0) return {WorkerResult::Status::Failed, "", "pipe failed"};
  Fd outRead{out[0]}, outWrite{out[1]};

  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_adddup2(&fa, inRead.fd, 0);
  posix_spawn_file_actions_adddup2(&fa, outWrite.fd, 1);
  std::string mem = std::to_string(limits.memoryBytes);
  std::vector<char*> argv{const_cast<char*>(exe.c_str()), const_cast<char*>("serve-worker"),
                          const_cast<char*>("--memory"), mem.data(), nullptr};
  Child child;
  int rc = ::posix_spawn(&child.pid, exe.c_str(), &fa, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&fa);
  if (rc != 0) {
    child.pid = -1;
    return {WorkerResult::Status::Failed, "", "cannot start " + exe};
  }
  inRead.reset();
  outWrite.reset();
  ::fcntl(inWrite.fd, F_SETFL, O_NONBLOCK);
  ::fcntl(outRead.fd, F_SETFL, O_NONBLOCK);

  auto deadline = std::chrono::steady_clock::now() + limits.timeout;
  size_t sent = 0;
  uint64_t received = 0;
  std::vector<char> buffer(1u << 20);
  char* buf = buffer.data();
  if (input.empty()) inWrite.reset();
  while (outRead.fd >= 0) {
    auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) {
      res.status = WorkerResult::Status::Timeout;
      res.detail = "the run took longer than " + std::to_string(limits.timeout.count()) + " ms";
      return res;  // ~Child kills it
    }
    pollfd fds[2] = {{outRead.fd, POLLIN, 0}, {inWrite.fd, POLLOUT, 0}};
    int n = ::poll(fds, inWrite.fd >= 0 ? 2 : 1,
                   static_cast<int>(std::min<int64_t>(left.count(), 1000)));
    if (n < 0 && errno != EINTR) break;
    if (inWrite.fd >= 0 && (fds[1].revents & (POLLOUT | POLLERR | POLLHUP))) {
      ssize_t w = ::write(inWrite.fd, input.data() + sent, input.size() - sent);
      if (w > 0) sent += static_cast<size_t>(w);
      if (w < 0 && errno != EAGAIN && errno != EINTR) inWrite.reset();  // the child stopped reading
      if (sent == input.size()) inWrite.reset();  // EOF: the request is complete
    }
    if (fds[0].revents & (POLLIN | POLLERR | POLLHUP)) {
      ssize_t r = ::read(outRead.fd, buf, buffer.size());
      if (r > 0) {
        received += static_cast<uint64_t>(r);
        if (onOutput) {
          if (!onOutput(std::string_view(buf, static_cast<size_t>(r)))) {
            res.detail = "the client went away";
            return res;  // ~Child kills it
          }
        } else {
          res.output.append(buf, static_cast<size_t>(r));
        }
        if (received > limits.maxOutputBytes) {
          res.status = WorkerResult::Status::TooLarge;
          res.detail =
              "the answer is larger than " + std::to_string(limits.maxOutputBytes) + " bytes";
          res.output.clear();
          return res;
        }
      } else if (r == 0 || (errno != EAGAIN && errno != EINTR)) {
        outRead.reset();
      }
    }
  }
  int st = 0;
  pid_t pid = child.pid;
  child.pid = -1;
  while (::waitpid(pid, &st, 0) < 0 && errno == EINTR) {
  }
  if (WIFEXITED(st) && WEXITSTATUS(st) == 0) {
    res.status = WorkerResult::Status::Ok;
  } else {
    res.status = WorkerResult::Status::Failed;
    res.detail = WIFSIGNALED(st)
                     ? "the worker died (signal " + std::to_string(WTERMSIG(st)) + ")"
                     : "the worker failed (status " + std::to_string(WEXITSTATUS(st)) + ")";
    res.output.clear();
  }
  return res;
}

std::string workerAnswer(const std::string& input) {
  nlohmann::json answer;
  try {
    answer = runJob(nlohmann::json::parse(input));
  } catch (const nlohmann::json::exception& e) {
    answer = {{"ok", false}, {"error", std::string("bad request: ") + e.what()}};
  } catch (const std::bad_alloc&) {
    answer = {{"ok", false}, {"error", "the run needed more memory than the server allows"}};
  }
  return answer.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

int workerMain(uint64_t memoryBytes) {
#if !defined(NCVM_UNDER_ASAN)
  // (AddressSanitizer reserves terabytes of address space: no cap under it.)
  if (memoryBytes > 0) {
    rlimit r{memoryBytes, memoryBytes};
    ::setrlimit(RLIMIT_AS, &r);
  }
#else
  (void)memoryBytes;
#endif
  std::string input((std::istreambuf_iterator<char>(std::cin)), std::istreambuf_iterator<char>());
  nlohmann::json request = nlohmann::json::parse(input, nullptr, false);
  if (request.is_object() && request.value("format", "") == "binary") {
    input.clear();
    input.shrink_to_fit();
    bool written = true;
    try {
      runViewerJob(request, [&](std::string_view frame) {
        written = written && std::fwrite(frame.data(), 1, frame.size(), stdout) == frame.size() &&
                  std::fflush(stdout) == 0;
      });
    } catch (const std::bad_alloc&) {
      std::string f = frame(
          FrameKind::End,
          R"j({"ok":false,"error":"the run needed more memory than the server allows (ncvm serve --max-memory-mb)"})j");
      std::fwrite(f.data(), 1, f.size(), stdout);
    }
    return written && std::fflush(stdout) == 0 ? 0 : 1;
  }
  std::string text = workerAnswer(input);
  std::fwrite(text.data(), 1, text.size(), stdout);
  return std::fflush(stdout) == 0 ? 0 : 1;
}

}  // namespace ncvm::server
