#pragma once
// What the server decides from a request's bytes alone, before a file is read or a worker
// started: whether its Host and Origin are loopback names, and the worker job a /api/run
// body becomes. Kept apart from the HTTP plumbing so that tests and the fuzz target
// (tests/fuzz/fuzz_server.cpp) call them without a socket.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "server/web_server.hpp"

namespace ncvm::server {

// "localhost", "::1" or an IPv4 literal 127.a.b.c: names that can only mean this machine.
// "127.evil.example" is none of them: a DNS name can point anywhere.
bool isLoopback(const std::string& host);

// "localhost:8765", "127.0.0.1", "[::1]:8765" -> the host part.
std::string hostPart(const std::string& hostHeader);
// -> the port: 8765, 80 without one, -1 when it is not a port number.
int portPart(const std::string& hostHeader);

// Why a request with these Host and Origin headers is refused (the 403 text), or nullopt.
// Empty headers pass (a client that sends none is not a browser driven from elsewhere).
// The only trusted origin is the server's own: http://, a loopback name and the server's
// port (`ownPort`). Another local port (a development server on :3000, any page served on
// this machine) is another origin, and a page there must not drive the server.
std::optional<std::string> foreignHostOrOrigin(const std::string& host, const std::string& origin,
                                               int ownPort);

// The file name a client gave, reduced to its last component (it names the program in
// alarms and the trace; it never opens a file).
std::string baseName(const std::string& name);

// "request too large: N bytes (..), the server accepts ... (--max-upload-mb ...)".
std::string tooLargeBody(uint64_t bytes, const ServerConfig& config);

// A /api/run body turned into the worker's request (run_job.hpp), or the HTTP status and
// message it is refused with. The body names the program by its text ("program") or, without
// one, by "root" and "path" (a file of the server's folders, at any size the caps allow).
struct RunRequest {
  int status = 200;    // 200: `job` is ready for runWorker
  std::string error;   // otherwise: why
  nlohmann::json job;  // program or program_path, name, caps, libs, setup, setup_name
};
RunRequest runRequestFromBody(const std::string& body, const ServerConfig& config);

}  // namespace ncvm::server
