#include "lsp/server.hpp"

#include <fmt/format.h>

#include "core/version.hpp"
#include "lsp/completion.hpp"
#include "lsp/definition.hpp"
#include "lsp/diagnostics.hpp"
#include "lsp/hover.hpp"
#include "lsp/symbols.hpp"
#include "machine/setup.hpp"

namespace ncvm::lsp {

namespace {
constexpr int kParseError = -32700, kInvalidRequest = -32600, kMethodNotFound = -32601,
              kInvalidParams = -32602, kInternalError = -32603, kServerNotInitialized = -32002;
constexpr int kSyncFull = 1;

nlohmann::json capabilities() {
  return {
      {"textDocumentSync",
       {{"openClose", true}, {"change", kSyncFull}, {"save", {{"includeText", false}}}}},
      {"hoverProvider", true},
      {"definitionProvider", true},
      {"documentSymbolProvider", true},
      {"completionProvider", {{"triggerCharacters", {"#", "G", "M", "g", "m"}}}},
  };
}

nlohmann::json errorResponse(const nlohmann::json& id, int code, const std::string& message) {
  return {{"jsonrpc", "2.0"}, {"id", id}, {"error", {{"code", code}, {"message", message}}}};
}

// A setup error names its file, line and key, as `ncvm run` prints it.
std::string errorText(const std::exception& e) {
  if (const auto* s = dynamic_cast<const SetupError*>(&e))
    return "setup error: " + setupErrorText(*s);
  return e.what();
}

int intParam(const nlohmann::json& j, const char* key) {
  if (!j.contains(key) || !j[key].is_number_integer())
    throw RequestError{kInvalidParams, std::string("missing ") + key};
  return j[key].get<int>();
}
}  // namespace

Server::Server(Setup setup, ServerOptions options)
    : setup_(std::move(setup)), options_(std::move(options)) {}

Document* Server::documentOf(const nlohmann::json& params) {
  if (!params.contains("textDocument") || !params["textDocument"].contains("uri"))
    throw RequestError{kInvalidParams, "missing textDocument.uri"};
  Document* d = docs_.find(params["textDocument"]["uri"].get<std::string>());
  if (!d) throw RequestError{kInvalidParams, "the document is not open"};
  return d;
}

nlohmann::json Server::dispatchRequest(const std::string& method, const nlohmann::json& params) {
  if (method == "initialize") {
    initialized_ = true;
    return {{"capabilities", capabilities()},
            {"serverInfo", {{"name", "ncvm"}, {"version", versionText()}}}};
  }
  if (!initialized_) throw RequestError{kServerNotInitialized, "initialize first"};
  if (method == "shutdown") {
    shutdown_ = true;
    return nullptr;
  }
  // Each feature sees the document's own setup (a lathe's G codes and offset variables).
  const auto where = [&](auto f) {
    const Document* d = documentOf(params);
    const auto& pos = params.at("position");
    return f(setupForDocument(setup_, options_, *d), *d, intParam(pos, "line"),
             intParam(pos, "character"));
  };
  if (method == "textDocument/hover")
    return where([&](const Setup& s, const Document& d, int l, int c) {
      nlohmann::json h = hover(s, d, l, c);
      // A call or a GOTO also says where it leads (what go to definition opens).
      if (h.is_null()) return h;
      const nlohmann::json to = definition(s, options_, docs_, d, l, c);
      if (to.is_null()) return h;
      const std::string uri = to["uri"];
      const std::string path = uriToPath(uri);
      h["contents"]["value"] = h["contents"]["value"].get<std::string>() +
                               fmt::format("\n→ {}:{}", path.empty() ? uri : path,
                                           to["range"]["start"]["line"].get<int>() + 1);
      return h;
    });
  if (method == "textDocument/completion")
    return where(
        [&](const Setup& s, const Document& d, int l, int c) { return complete(s, d, l, c); });
  if (method == "textDocument/definition")
    return where([&](const Setup& s, const Document& d, int l, int c) {
      return definition(s, options_, docs_, d, l, c);
    });
  if (method == "textDocument/documentSymbol") {
    const Document* d = documentOf(params);
    return documentSymbols(setupForDocument(setup_, options_, *d), options_, docs_, *d);
  }
  throw RequestError{kMethodNotFound, "no such method: " + method};
}

void Server::notify(const std::string& method, const nlohmann::json& params,
                    std::vector<nlohmann::json>& out) {
  if (method == "exit") {
    exited_ = true;
    return;
  }
  if (!initialized_) return;  // notifications before initialize are dropped (LSP)
  if (method == "textDocument/didOpen") {
    const auto& td = params.at("textDocument");
    docs_.open(td.at("uri"), td.at("text"), td.value("version", 0));
    pending_.insert(td.at("uri").get<std::string>());
    urgent_ = true;
  } else if (method == "textDocument/didChange") {
    const auto& td = params.at("textDocument");
    const auto& changes = params.at("contentChanges");
    if (changes.empty()) return;
    // Full sync: the last change holds the whole text.
    if (docs_.change(td.at("uri"), changes.back().at("text"), td.value("version", 0)))
      pending_.insert(td.at("uri").get<std::string>());
  } else if (method == "textDocument/didSave") {
    pending_.insert(params.at("textDocument").at("uri").get<std::string>());
    urgent_ = true;
  } else if (method == "textDocument/didClose") {
    const std::string uri = params.at("textDocument").at("uri");
    docs_.close(uri);
    pending_.erase(uri);
    out.push_back({{"jsonrpc", "2.0"},
                   {"method", "textDocument/publishDiagnostics"},
                   {"params", {{"uri", uri}, {"diagnostics", nlohmann::json::array()}}}});
  }
}

std::vector<nlohmann::json> Server::handle(const nlohmann::json& message) {
  std::vector<nlohmann::json> out;
  if (!message.is_object() || !message.contains("method")) {
    // A response to a request of ours (we send none) or garbage.
    if (message.is_object() && message.contains("id") && !message.contains("result") &&
        !message.contains("error"))
      out.push_back(errorResponse(message["id"], kInvalidRequest, "no method"));
    return out;
  }
  const std::string method = message["method"].is_string() ? message["method"] : "";
  const nlohmann::json params = message.value("params", nlohmann::json::object());
  if (!message.contains("id")) {
    try {
      notify(method, params, out);
    } catch (const std::exception&) {
      // A malformed notification has no one to answer: it is dropped.
    }
    return out;
  }
  const nlohmann::json& id = message["id"];
  try {
    if (shutdown_ && method != "shutdown")
      throw RequestError{kInvalidRequest, "the server is shut down"};
    out.push_back({{"jsonrpc", "2.0"}, {"id", id}, {"result", dispatchRequest(method, params)}});
  } catch (const RequestError& e) {
    out.push_back(errorResponse(id, e.code, e.message));
  } catch (const std::exception& e) {
    out.push_back(errorResponse(id, kInternalError, errorText(e)));
  }
  return out;
}

std::vector<nlohmann::json> Server::publishDue() {
  std::vector<nlohmann::json> out;
  for (const auto& uri : pending_) {
    const Document* d = docs_.find(uri);
    if (!d) continue;
    nlohmann::json diags;
    try {
      diags = diagnose(setupForDocument(setup_, options_, *d), options_, docs_, *d);
    } catch (const std::exception& e) {
      diags = nlohmann::json::array(
          {{{"range",
             {{"start", {{"line", 0}, {"character", 0}}},
              {"end", {{"line", 0}, {"character", 0}}}}},
            {"severity", 1},
            {"source", "ncvm"},
            {"message", std::string("ncvm could not check this document: ") + errorText(e)}}});
    }
    out.push_back({{"jsonrpc", "2.0"},
                   {"method", "textDocument/publishDiagnostics"},
                   {"params", {{"uri", uri}, {"version", d->version}, {"diagnostics", diags}}}});
  }
  pending_.clear();
  urgent_ = false;
  return out;
}

// JSON that does not parse: the caller answers with this (id null, as JSON-RPC says).
nlohmann::json parseErrorResponse(const std::string& what) {
  return errorResponse(nullptr, kParseError, what);
}

}  // namespace ncvm::lsp
