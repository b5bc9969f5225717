#include "server/web_server.hpp"

#include <httplib.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstring>
#include <fstream>
#include <mutex>
#include <sstream>
#include <stdexcept>

#include "core/version.hpp"
#include "server/guarded_http.hpp"
#include "server/request_checks.hpp"
#include "server/safe_path.hpp"
#include "server/setup_layers.hpp"
#include "server/viewer_stream.hpp"

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

// Cuts a byte stream into the frames of viewer_stream.hpp.
class FrameSplitter {
 public:
  template <class OnFrame>
  void feed(std::string_view bytes, OnFrame onFrame) {
    pending_.append(bytes);
    size_t at = 0;
    while (pending_.size() - at >= 8) {
      uint32_t kind = 0, length = 0;
      std::memcpy(&kind, pending_.data() + at, 4);
      std::memcpy(&length, pending_.data() + at + 4, 4);
      size_t whole = 8 + length + (8 - length % 8) % 8;
      if (pending_.size() - at < whole) break;
      onFrame(std::string_view(pending_).substr(at, whole), kind);
      at += whole;
    }
    pending_.erase(0, at);
  }

 private:
  std::string pending_;
};

}  // namespace

// At most `limit` runs at once; a request waits for a free slot at most `wait`.
class RunSlots {
 public:
  explicit RunSlots(int limit) : free_(std::max(1, limit)) {}
  bool acquire(std::chrono::milliseconds wait) {
    std::unique_lock lock(mutex_);
    if (!freed_.wait_for(lock, wait, [this] { return free_ > 0; })) return false;
    --free_;
    return true;
  }
  void release() {
    {
      std::lock_guard lock(mutex_);
      ++free_;
    }
    freed_.notify_one();
  }

 private:
  std::mutex mutex_;
  std::condition_variable freed_;
  int free_;
};

struct WebServer::Impl {
  Impl(int runs, ConnectionLimits limits) : http(limits), slots(runs) {}
  GuardedHttpServer http;
  RunSlots slots;
};

WebServer::WebServer(ServerConfig config)
    : config_(std::move(config)),
      impl_(std::make_unique<Impl>(config_.threads, config_.connection)) {
  httplib::Server& s = impl_->http;
  const ServerConfig& c = config_;
  // Connection threads are cheap and many; the runs (worker processes) are bounded by
  // RunSlots. Before, one pool bounded both, so 8 slow connections held every thread.
  const int connections = std::max(c.connections, std::max(c.threads, 1));
  s.new_task_queue = [connections] {
    return new httplib::ThreadPool(static_cast<size_t>(connections));
  };
  s.set_payload_max_length(c.maxBodyBytes);
  // SO_REUSEADDR only: cpp-httplib's default adds SO_REUSEPORT, which lets a second server
  // listen on the same port and silently take half of the connections.
  s.set_socket_options([](socket_t sock) {
    int yes = 1;
    ::setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
  });
  // Read and idle timeouts, the request deadline and the bounds per connection and client
  // are GuardedHttpServer's (c.connection).

  const bool loopbackOnly = isLoopback(c.bind);
  s.set_pre_routing_handler(
      [this, loopbackOnly](const httplib::Request& req, httplib::Response& res) {
        if (loopbackOnly)
          if (auto refusal = foreignHostOrOrigin(req.get_header_value("Host"),
                                                 req.get_header_value("Origin"), config_.port)) {
            sendError(res, 403, *refusal);
            return httplib::Server::HandlerResponse::Handled;
          }
        // Compression: none on loopback, where it costs far more than it saves (brotli took
        // 48-61 s for an 18 MB answer); gzip at most elsewhere. cpp-httplib picks the encoding
        // from the request's Accept-Encoding when it writes the answer, so that header is what
        // is changed (the request object is the server's own, handed over as const).
        auto& headers = const_cast<httplib::Request&>(req).headers;
        auto accept = headers.find("Accept-Encoding");
        if (accept != headers.end()) {
          bool gzip = !loopbackOnly && accept->second.find("gzip") != std::string::npos;
          headers.erase("Accept-Encoding");
          if (gzip) headers.emplace("Accept-Encoding", "gzip");
        }
        res.set_header("X-Content-Type-Options", "nosniff");
        res.set_header("Cache-Control", "no-store");
        return httplib::Server::HandlerResponse::Unhandled;
      });

  // cpp-httplib refuses a body over its payload limit before any handler: say which limit.
  s.set_error_handler([this](const httplib::Request& req, httplib::Response& res) {
    if (res.status != 413 || !res.body.empty()) return;
    uint64_t length = 0;
    try {
      length = std::stoull(req.get_header_value("Content-Length"));
    } catch (const std::exception&) {
    }
    sendError(res, 413, tooLargeBody(length, config_));
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
         {"max_upload_bytes", cf.maxUploadBytes},
         {"setup", cf.setupText.empty() ? nlohmann::json(nullptr) : nlohmann::json(cf.setupText)},
         {"setup_name", cf.setupName},
         {"start", cf.startPath.empty()
                       ? nlohmann::json(nullptr)
                       : nlohmann::json{{"root", cf.startRoot}, {"path", cf.startPath}}}});
  });

  s.Get("/api/files", [this](const httplib::Request&, httplib::Response& res) {
    sendJson(res, 200, config_.catalog.list());
  });

  s.Get("/api/setups", [this](const httplib::Request&, httplib::Response& res) {
    sendJson(res, 200, setupFiles(config_));
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
    if (!impl_->slots.acquire(cf.worker.timeout))
      return sendError(res, 503,
                       "busy: " + std::to_string(cf.threads) + " runs in progress; try again");
    WorkerResult w;
    try {
      w = runWorker(cf.workerExe,
                    job.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace), cf.worker);
    } catch (...) {
      impl_->slots.release();
      throw;
    }
    impl_->slots.release();
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

  // The page's run: the binary frames of viewer_stream.hpp, passed on as the worker makes
  // them. Only whole frames are passed on, so that when the worker stops short (timeout,
  // crash, the answer cap) the server's own end frame says why.
  s.Post("/api/run.bin", [this](const httplib::Request& req, httplib::Response& res) {
    RunRequest run = runRequestFromBody(req.body, config_);
    if (run.status != 200) return sendError(res, run.status, run.error);
    run.job["format"] = "binary";
    auto job = std::make_shared<std::string>(
        run.job.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));
    // The same bound on runs at once as /api/run; the slot is given back when the answer
    // has been streamed (or the connection dropped).
    if (!impl_->slots.acquire(config_.worker.timeout))
      return sendError(res, 503,
                       "busy: " + std::to_string(config_.threads) + " runs in progress; try again");
    res.status = 200;
    res.set_chunked_content_provider(
        "application/octet-stream",
        [this, job](size_t, httplib::DataSink& sink) {
          FrameSplitter frames;
          bool ended = false, open = true;
          WorkerLimits limits = config_.worker;
          limits.maxOutputBytes = config_.maxAnswerBytes;
          WorkerResult w = runWorker(config_.workerExe, *job, limits, [&](std::string_view bytes) {
            frames.feed(bytes, [&](std::string_view f, uint32_t kind) {
              if (kind == static_cast<uint32_t>(FrameKind::End)) ended = true;
              open = open && sink.write(f.data(), f.size());
            });
            return open;
          });
          if (!ended && open) {
            std::string why = w.status == WorkerResult::Status::Timeout
                                  ? "timeout: " + w.detail + " (ncvm serve --timeout)"
                              : w.status == WorkerResult::Status::TooLarge
                                  ? w.detail + " (ncvm serve --max-answer-mb)"
                              : w.detail.empty() ? "the worker ended without an answer"
                                                 : w.detail;
            std::string f = frame(FrameKind::End,
                                  nlohmann::json{{"ok", false}, {"error", why}}.dump(
                                      -1, ' ', false, nlohmann::json::error_handler_t::replace));
            sink.write(f.data(), f.size());
          }
          sink.done();
          return true;
        },
        [this](bool) { impl_->slots.release(); });
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
  GuardedHttpServer& s = impl_->http;
  if (config_.port == 0) {
    int port = s.bind_to_any_port(config_.bind);
    if (port <= 0) throw std::runtime_error("cannot bind to " + config_.bind);
    config_.port = port;
  } else if (!s.bind_to_port(config_.bind, config_.port)) {
    throw std::runtime_error("cannot bind to " + config_.bind + ":" + std::to_string(config_.port));
  }
  s.widenBacklog(std::max(128, config_.connections));
  return config_.port;
}

void WebServer::listen() {
  impl_->http.listen_after_bind();
}

void WebServer::stop() {
  if (impl_) impl_->http.stop();
}

}  // namespace ncvm::server
