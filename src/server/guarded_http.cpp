#include "server/guarded_http.hpp"

#include <arpa/inet.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstring>

namespace ncvm::server {

namespace {

using Clock = std::chrono::steady_clock;

// Waits until `sock` is readable, the deadline passes or the server stops (polled in short
// slices, so that stop() never waits for a slow client).
bool readableBefore(socket_t sock, Clock::time_point deadline,
                    const std::atomic<socket_t>& server) {
  for (;;) {
    if (server == INVALID_SOCKET) return false;
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    if (left <= 0) return false;
    pollfd p{sock, POLLIN, 0};
    int r = ::poll(&p, 1, static_cast<int>(std::min<long long>(left, 100)));
    if (r > 0) return true;
    if (r < 0 && errno != EINTR) return false;
  }
}

std::string addressText(const sockaddr_storage& a, int& port) {
  char text[INET6_ADDRSTRLEN] = {};
  port = 0;
  if (a.ss_family == AF_INET) {
    const auto* v4 = reinterpret_cast<const sockaddr_in*>(&a);
    ::inet_ntop(AF_INET, &v4->sin_addr, text, sizeof text);
    port = ntohs(v4->sin_port);
  } else if (a.ss_family == AF_INET6) {
    const auto* v6 = reinterpret_cast<const sockaddr_in6*>(&a);
    ::inet_ntop(AF_INET6, &v6->sin6_addr, text, sizeof text);
    port = ntohs(v6->sin6_port);
  }
  return text;
}

// A socket whose reads must all come before one deadline (the request's), buffered: the
// request parser reads its lines a byte at a time.
class DeadlineStream final : public httplib::Stream {
 public:
  DeadlineStream(socket_t sock, const std::atomic<socket_t>& server)
      : sock_(sock), server_(server) {}
  void setDeadline(Clock::time_point d) { deadline_ = d; }
  bool buffered() const { return at_ < end_; }
  // A read failed: the deadline passed, the server stopped or the client went away.
  bool cutOff() const { return cut_; }

  bool is_readable() const override {
    return buffered() || readableBefore(sock_, deadline_, server_);
  }
  bool is_writable() const override {
    pollfd p{sock_, POLLOUT, 0};
    return ::poll(&p, 1, 30'000) > 0;  // the write timeout
  }
  ssize_t read(char* ptr, size_t size) override {
    if (!buffered()) {
      if (!waitForData()) return -1;
      ssize_t n = ::recv(sock_, buffer_, sizeof buffer_, 0);
      if (n <= 0) return n;
      at_ = 0;
      end_ = static_cast<size_t>(n);
    }
    const size_t n = std::min(size, end_ - at_);
    std::memcpy(ptr, buffer_ + at_, n);
    at_ += n;
    return static_cast<ssize_t>(n);
  }
  ssize_t write(const char* ptr, size_t size) override {
    if (!is_writable()) return -1;
    return ::send(sock_, ptr, size, MSG_NOSIGNAL);
  }
  void get_remote_ip_and_port(std::string& ip, int& port) const override {
    sockaddr_storage a{};
    socklen_t len = sizeof a;
    ::getpeername(sock_, reinterpret_cast<sockaddr*>(&a), &len);
    ip = addressText(a, port);
  }
  void get_local_ip_and_port(std::string& ip, int& port) const override {
    sockaddr_storage a{};
    socklen_t len = sizeof a;
    ::getsockname(sock_, reinterpret_cast<sockaddr*>(&a), &len);
    ip = addressText(a, port);
  }
  socket_t socket() const override { return sock_; }

 private:
  bool waitForData() const {
    if (readableBefore(sock_, deadline_, server_)) return true;
    cut_ = true;
    return false;
  }

  socket_t sock_;
  const std::atomic<socket_t>& server_;
  mutable bool cut_ = false;
  Clock::time_point deadline_ = Clock::now();
  char buffer_[4096];
  size_t at_ = 0, end_ = 0;
};

}  // namespace

void GuardedHttpServer::widenBacklog(int backlog) {
  // Linux takes a second listen() on a listening socket as a new backlog.
  if (svr_sock_ != INVALID_SOCKET) ::listen(svr_sock_, backlog);
}

bool GuardedHttpServer::admit(const std::string& client) {
  std::lock_guard lock(mutex_);
  int& n = open_[client];
  if (n >= limits_.connectionsPerClient) return false;
  ++n;
  return true;
}

void GuardedHttpServer::leave(const std::string& client) {
  std::lock_guard lock(mutex_);
  if (--open_[client] <= 0) open_.erase(client);
}

bool GuardedHttpServer::process_and_close_socket(socket_t sock) {
  DeadlineStream stream(sock, svr_sock_);
  std::string client;
  int port = 0;
  stream.get_remote_ip_and_port(client, port);
  bool ret = false;
  if (admit(client)) {
    auto wait = std::chrono::seconds(limits_.firstRequestSeconds);
    for (int n = 0; n < limits_.requestsPerConnection; ++n) {
      // The next request's first byte, then the whole request, each within its time.
      if (!stream.buffered() && !readableBefore(sock, Clock::now() + wait, svr_sock_)) break;
      stream.setDeadline(Clock::now() + std::chrono::seconds(limits_.requestSeconds));
      bool closed = false;
      ret = process_request(stream, n + 1 == limits_.requestsPerConnection, closed, nullptr);
      // A request cut off at its deadline was answered 400; the connection goes with it.
      if (!ret || closed || stream.cutOff()) break;
      wait = std::chrono::seconds(limits_.idleSeconds);
    }
    leave(client);
  }
  ::shutdown(sock, SHUT_RDWR);
  ::close(sock);
  return ret;
}

}  // namespace ncvm::server
