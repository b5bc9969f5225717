#include "server/web_server.hpp"

#include <httplib.h>

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "core/version.hpp"
#include "server/request_checks.hpp"
#include "server/safe_path.hpp"

namespace ncvm::server {

namespace fs = std::filesystem;

namespace {

void sendJson(httplib::Response& res, int status, const nlohmann::json& j) {
  res.status = status;
  res.set_content(j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace),
                  "application/json");
}

void sendError(httplib::Response& res, int status, const std::string& message) {
  sendJson(res, status, {{"ok", false}, {"error", message}});
}

const char* contentType(const fs::path& p) {
  std::string e = p.extension().string();
  if (e == ".html") return "text/html; charset=utf-8";
  if (e == ".js" || e == ".mjs") return "text/javascript; charset=utf-8";
  if (e == ".css") return "text/css; charset=utf-8";
  if (e == ".svg") return "image/svg+xml";
  if (e == ".png") return "image/png";
  if (e == ".json") return "application/json";
  if (e == ".ico") return "image/x-icon";
  if (e == ".woff2") return "font/woff2";
  return "application/octet-stream";
}

}  // namespace

struct WebServer::Impl {
  httplib::Server http;
};

WebServer::WebServer(ServerConfig config)
    : config_(std::move(config)), impl_(std::make_unique<Impl>()) {
  httplib::Server& s = impl_->http;
  const ServerConfig& c = config_;
  int threads = c.threads > 0 ? c.threads : 1;
  s.new_task_queue = [threads] { return new httplib::ThreadPool(static_cast<size_t>(threads)); };
  s.set_payload_max_length(c.maxBodyBytes);
  // SO_REUSEADDR only: cpp-httplib's default adds SO_REUSEPORT, which lets a second server
  // listen on the same port and silently take half of the connections.
  s.set_socket_options([](socket_t sock) {
    int yes = 1;
    ::setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
  });
  s.set_read_timeout(10, 0);
  s.set_write_timeout(30, 0);

  const bool loopbackOnly = isLoopback(c.bind);
  s.set_pre_routing_handler([loopbackOnly](const httplib::Request& req, httplib::Response& res) {
    if (loopbackOnly)
      if (auto refusal =
              foreignHostOrOrigin(req.get_header_value("Host"), req.get_header_value("Origin"))) {
        sendError(res, 403, *refusal);
        return httplib::Server::HandlerResponse::Handled;
      }
    res.set_header("X-Content-Type-Options", "nosniff");
    res.set_header("Cache-Control", "no-store");
    return httplib::Server::HandlerResponse::Unhandled;
  });

  s.Get("/api/info", [this](const httplib::Request&, httplib::Response& res) {
    const ServerConfig& cf = config_;
    nlohmann::json roots = nlohmann::json::array();
    for (const auto& r : cf.catalog.roots()) roots.push_back(r.name);
    sendJson(
        res, 200,
        {{"name", "ncvm"},
         {"version", versionText()},
         {"roots", roots},
         {"caps", capsJson(cf.caps)},
         {"timeout_ms", cf.worker.timeout.count()},
         {"max_body_bytes", cf.maxBodyBytes},
         {"setup", cf.setupText.empty() ? nlohmann::json(nullptr) : nlohmann::json(cf.setupText)},
         {"setup_name", cf.setupName},
         {"start", cf.startPath.empty()
                       ? nlohmann::json(nullptr)
                       : nlohmann::json{{"root", cf.startRoot}, {"path", cf.startPath}}}});
  });

  s.Get("/api/files", [this](const httplib::Request&, httplib::Response& res) {
    sendJson(res, 200, config_.catalog.list());
  });

  s.Get("/api/file", [this](const httplib::Request& req, httplib::Response& res) {
    std::string root = req.get_param_value("root"), path = req.get_param_value("path");
    if (!isPlainRelative(path))
      return sendError(res, 400, "bad path: it must be relative, without '..'");
    auto f = config_.catalog.read(root, path, config_.caps.maxProgramBytes);
    if (!f) return sendError(res, 404, "no such program in the server's folders");
    (*f)["ok"] = true;
    sendJson(res, 200, *f);
  });

  s.Post("/api/run", [this](const httplib::Request& req, httplib::Response& res) {
    const ServerConfig& cf = config_;
    RunRequest run = runRequestFromBody(req.body, cf);
    if (run.status != 200) return sendError(res, run.status, run.error);
    const nlohmann::json& job = run.job;
    WorkerResult w =
        runWorker(cf.workerExe, job.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace),
                  cf.worker);
    switch (w.status) {
      case WorkerResult::Status::Ok:
        break;
      case WorkerResult::Status::Timeout:
        return sendError(res, 503, "timeout: " + w.detail);
      case WorkerResult::Status::TooLarge:
        return sendError(res, 507, w.detail);
      case WorkerResult::Status::Failed:
        return sendError(res, 500, w.detail);
    }
    // The answer is already JSON: passed through, with 400 when it reports a setup or load error.
    bool ok = w.output.find("\"ok\":true") != std::string::npos;
    res.status = ok ? 200 : 400;
    res.set_content(std::move(w.output), "application/json");
  });

  s.Get("/api/.*", [](const httplib::Request&, httplib::Response& res) {
    sendError(res, 404, "no such API");
  });

  // The front end: only files under webDir.
  s.Get("/(.*)", [this](const httplib::Request& req, httplib::Response& res) {
    std::string rel = req.matches[1];
    if (rel.empty()) rel = "index.html";
    if (config_.webDir.empty()) {
      res.status = 404;
      res.set_content("ncvm serve: the front end was not built (see web/README.md)", "text/plain");
      return;
    }
    auto full = resolveInside(config_.webDir, rel);
    std::error_code ec;
    if (!full || !fs::is_regular_file(*full, ec)) return sendError(res, 404, "not found");
    std::ifstream f(*full, std::ios::binary);
    std::ostringstream body;
    body << f.rdbuf();
    res.status = 200;
    res.set_content(body.str(), contentType(*full));
  });

  s.set_exception_handler(
      [](const httplib::Request&, httplib::Response& res, std::exception_ptr ep) {
        std::string what = "internal error";
        try {
          std::rethrow_exception(ep);
        } catch (const std::exception& e) {
          what = e.what();
        } catch (...) {
        }
        sendError(res, 500, what);
      });
}

WebServer::~WebServer() {
  stop();
}

int WebServer::bind() {
  httplib::Server& s = impl_->http;
  if (config_.port == 0) {
    int port = s.bind_to_any_port(config_.bind);
    if (port <= 0) throw std::runtime_error("cannot bind to " + config_.bind);
    config_.port = port;
    return port;
  }
  if (!s.bind_to_port(config_.bind, config_.port))
    throw std::runtime_error("cannot bind to " + config_.bind + ":" + std::to_string(config_.port));
  return config_.port;
}

void WebServer::listen() {
  impl_->http.listen_after_bind();
}

void WebServer::stop() {
  if (impl_) impl_->http.stop();
}

}  // namespace ncvm::server
