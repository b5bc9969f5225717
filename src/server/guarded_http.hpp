#pragma once
// cpp-httplib's server with connection handling that a slow or idle client cannot stall:
// each request must arrive whole (request line, headers and body) within a deadline, however
// slowly its bytes trickle in (slow loris); a connection waits a bounded time for its first
// and each next request; one client (remote address) holds at most a bounded number of
// connections; and a connection serves a bounded number of requests. What a request does
// once it has arrived (a run of up to the worker's timeout) is not limited here.
#include <httplib.h>

#include <map>
#include <mutex>
#include <string>

#include "server/connection_limits.hpp"

namespace ncvm::server {

class GuardedHttpServer : public httplib::Server {
 public:
  explicit GuardedHttpServer(ConnectionLimits limits) : limits_(limits) {}
  // cpp-httplib listens with a backlog of 5: a burst of connections (50 idle ones) then waits
  // for SYN retransmissions, seconds each. Call after binding.
  void widenBacklog(int backlog);

 private:
  bool process_and_close_socket(socket_t sock) override;
  bool admit(const std::string& client);
  void leave(const std::string& client);

  ConnectionLimits limits_;
  std::mutex mutex_;
  std::map<std::string, int> open_;  // connections per remote address
};

}  // namespace ncvm::server
