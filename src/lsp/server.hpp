#pragma once
// The language server's state and its dispatch: one JSON-RPC message in, the messages to
// send out (the response, and diagnostics when they are due). Knows nothing of stdio, so
// the unit tests drive it directly; stdio_server.hpp moves the bytes.
#include <chrono>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "lsp/documents.hpp"
#include "lsp/workspace.hpp"
#include "machine/setup.hpp"

namespace ncvm::lsp {

class Server {
 public:
  Server(Setup setup, ServerOptions options);

  // One message (a request, a notification or a response to us); returns what to send.
  std::vector<nlohmann::json> handle(const nlohmann::json& message);
  // Documents whose diagnostics are due: after an open or a save at once; after a change
  // when the editor has paused (the caller's debounce: it calls publishDue after a quiet
  // spell, or at once when urgent()).
  bool hasPending() const { return !pending_.empty(); }
  bool urgent() const { return urgent_; }
  std::vector<nlohmann::json> publishDue();

  bool exited() const { return exited_; }
  // LSP: exit after shutdown is 0, exit without it is 1.
  int exitCode() const { return shutdown_ ? 0 : 1; }

 private:
  nlohmann::json dispatchRequest(const std::string& method, const nlohmann::json& params);
  void notify(const std::string& method, const nlohmann::json& params,
              std::vector<nlohmann::json>& out);
  Document* documentOf(const nlohmann::json& params);

  Setup setup_;
  ServerOptions options_;
  DocumentStore docs_;
  std::set<std::string> pending_;  // URIs whose diagnostics are due
  bool urgent_ = false;
  bool initialized_ = false, shutdown_ = false, exited_ = false;
};

// The answer to a message whose JSON does not parse (id null, as JSON-RPC says).
nlohmann::json parseErrorResponse(const std::string& what);

// A JSON-RPC error a request handler raises (code from the LSP specification).
struct RequestError {
  int code;
  std::string message;
};

}  // namespace ncvm::lsp
