#include "lsp/stdio_server.hpp"

#include <poll.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>

#include "lsp/framing.hpp"
#include "lsp/server.hpp"

namespace ncvm::lsp {

namespace {
bool writeAll(int fd, const std::string& bytes) {
  size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<size_t>(n);
  }
  return true;
}

bool send(int fd, const std::vector<nlohmann::json>& messages) {
  for (const auto& m : messages)
    if (!writeAll(fd,
                  encodeFrame(m.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace))))
      return false;
  return true;
}
}  // namespace

int runStdioServer(int inFd, int outFd, Setup setup, ServerOptions options, int debounceMs) {
  Server server(std::move(setup), std::move(options));
  FrameDecoder decoder;
  char buf[1 << 16];
  while (!server.exited()) {
    // Whole messages already read go first; then, with nothing left to do, the diagnostics.
    std::optional<std::string> body;
    try {
      body = decoder.next();
    } catch (const FramingError& e) {
      std::fprintf(stderr, "ncvm lsp: %s\n", e.what());
      return 1;
    }
    if (body) {
      nlohmann::json message;
      try {
        message = nlohmann::json::parse(*body);
      } catch (const nlohmann::json::exception& e) {
        if (!send(outFd, {parseErrorResponse(e.what())})) return 1;
        continue;
      }
      if (!send(outFd, server.handle(message))) return 1;
      continue;
    }
    if (server.hasPending() && server.urgent()) {
      if (!send(outFd, server.publishDue())) return 1;
      continue;
    }
    pollfd p{inFd, POLLIN, 0};
    const int ready = ::poll(&p, 1, server.hasPending() ? debounceMs : -1);
    if (ready < 0 && errno == EINTR) continue;
    if (ready == 0) {  // quiet: the changed documents' diagnostics
      if (!send(outFd, server.publishDue())) return 1;
      continue;
    }
    const ssize_t n = ::read(inFd, buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return server.exitCode();  // the editor went away without exit
    decoder.feed(std::string_view(buf, static_cast<size_t>(n)));
  }
  return server.exitCode();
}

}  // namespace ncvm::lsp
