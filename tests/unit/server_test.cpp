// The web viewer's server (src/server): safe paths, one run as JSON, and the HTTP server on
// loopback with concurrent clients, malformed and oversized requests, path traversal and a
// runaway program.
#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <httplib.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "app/session.hpp"
#include "server/request_checks.hpp"
#include "server/run_job.hpp"
#include "server/safe_path.hpp"
#include "server/viewer_stream.hpp"
#include "server/web_server.hpp"
#include "sim/heightfield_io.hpp"

namespace fs = std::filesystem;
using namespace ncvm::server;
using nlohmann::json;

namespace {

struct TempDir {
  fs::path path;
  TempDir() {
    std::string t = (fs::temp_directory_path() / "ncvm-server-XXXXXX").string();
    path = ::mkdtemp(t.data());
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

void write(const fs::path& p, const std::string& text) {
  fs::create_directories(p.parent_path());
  std::ofstream(p) << text;
}

size_t countLines(const std::string& s) {
  return static_cast<size_t>(std::count(s.begin(), s.end(), '\n'));
}

}  // namespace

TEST(SafePath, RefusesEverythingOutsideTheRoot) {
  TempDir root, outside;
  write(root.path / "a" / "prog.nc", "O1\n");
  write(outside.path / "secret.nc", "O2\n");
  fs::create_symlink(outside.path / "secret.nc", root.path / "a" / "link.nc");
  fs::create_symlink(outside.path, root.path / "dirlink");
  fs::create_symlink(root.path / "a" / "prog.nc", root.path / "inner.nc");

  EXPECT_TRUE(resolveInside(root.path, "a/prog.nc"));
  EXPECT_TRUE(resolveInside(root.path, "inner.nc"));  // a symlink that stays inside
  EXPECT_TRUE(resolveInside(root.path, ""));
  EXPECT_FALSE(resolveInside(root.path, "../" + outside.path.filename().string() + "/secret.nc"));
  EXPECT_FALSE(resolveInside(root.path, "a/../../x"));
  EXPECT_FALSE(resolveInside(root.path, ".."));
  EXPECT_FALSE(resolveInside(root.path, (outside.path / "secret.nc").string()));  // absolute
  EXPECT_FALSE(resolveInside(root.path, "/etc/passwd"));
  EXPECT_FALSE(resolveInside(root.path, "a/link.nc"));          // symlink out
  EXPECT_FALSE(resolveInside(root.path, "dirlink/secret.nc"));  // through a folder symlink
  EXPECT_FALSE(resolveInside(root.path, std::string("a/prog.nc\0x", 11)));
  EXPECT_FALSE(resolveInside(root.path, "a\\prog.nc"));
  EXPECT_FALSE(resolveInside(root.path, "a/missing.nc"));
}

// Found by fuzz_server: any name starting "127." passed as loopback, so a DNS name such as
// 127.0.0.1.evil.example (which can point anywhere) could drive the server from a web page.
TEST(RequestChecks, LoopbackNamesOnly) {
  for (const char* host : {"localhost", "localhost:8765", "127.0.0.1", "127.0.0.1:8765",
                           "127.1.2.3:80", "[::1]:8765", "[::1]"})
    EXPECT_FALSE(foreignHostOrOrigin(host, "", 8765)) << host;
  for (const char* host : {"127.evil.example", "127.0.0.1.evil.example:8765", "127.0.0.1.",
                           "127.0.0.256", "127.0.0", "127..0.1", "1127.0.0.1", "128.0.0.1",
                           "evil.example", "localhost.evil.example", "[::2]", "0127.0.0.1:1"})
    EXPECT_TRUE(foreignHostOrOrigin(host, "", 8765)) << host;
  EXPECT_FALSE(foreignHostOrOrigin("127.0.0.1:8765", "http://localhost:8765", 8765));
  EXPECT_TRUE(foreignHostOrOrigin("127.0.0.1:8765", "http://127.0.0.1.evil.example:8765", 8765));
  EXPECT_TRUE(foreignHostOrOrigin("127.0.0.1:8765", "http://127.evil.example", 8765));
}

// Issue 26 item 9: any local port passed as an origin, so a page of another local server (a
// development server on :3000) could drive this one. Only the server's own origin passes.
TEST(RequestChecks, OnlyTheServersOwnOrigin) {
  EXPECT_FALSE(foreignHostOrOrigin("localhost:8765", "http://localhost:8765", 8765));
  EXPECT_FALSE(foreignHostOrOrigin("[::1]:8765", "http://[::1]:8765", 8765));
  EXPECT_FALSE(foreignHostOrOrigin("localhost", "http://localhost", 80));
  for (const char* origin : {"http://localhost:3000", "http://127.0.0.1:8766", "http://localhost",
                             "https://localhost:8765", "http://localhost:8765x",
                             "http://localhost:", "null", "file://", "http://[::1]:3000"})
    EXPECT_TRUE(foreignHostOrOrigin("localhost:8765", origin, 8765)) << origin;
}

// Found while writing fuzz_server: a request's setup could name any file of the machine as
// its target (target.polyline = "/etc/passwd"), and the worker opened it.
TEST(RunJob, SetupFilesOnlyInsideTheProgramsFolder) {
  TempDir dir, outside;
  write(dir.path / "profile.csv", "# X Z\n40, 0\n40, -30\n");
  write(outside.path / "secret.csv", "40, 0\n40, -30\n");
  const std::string latheTarget =
      "[machine]\nkind = \"lathe\"\n[tools.1]\ntype = \"insert\"\nnose_radius = 0.4\ntip = 3\n"
      "[stock]\ndiameter = 50.0\nlength = 60.0\n[target]\npolyline = ";
  const std::string prog = "O1\nT0101\nG00 X52. Z2.\nM30\n";
  for (const std::string& bad : {(outside.path / "secret.csv").string(), std::string("/etc/passwd"),
                                 "../" + outside.path.filename().string() + "/secret.csv"}) {
    json r = runJob({{"program", prog},
                     {"setup", latheTarget + "\"" + bad + "\"\n"},
                     {"libs", {dir.path.string()}}});
    ASSERT_FALSE(r["ok"].get<bool>()) << bad << ": " << r.dump();
    EXPECT_NE(r["error"].get<std::string>().find("not a file of the program's folder"),
              std::string::npos)
        << r["error"];
  }
  // No folder at all (a program typed in the page): no file either.
  json none = runJob({{"program", prog}, {"setup", latheTarget + "\"profile.csv\"\n"}});
  EXPECT_FALSE(none["ok"].get<bool>()) << none.dump();
  // A file of the program's folder, named relative to it, is read.
  json good = runJob({{"program", prog},
                      {"setup", latheTarget + "\"profile.csv\"\n"},
                      {"libs", {dir.path.string()}}});
  ASSERT_TRUE(good["ok"].get<bool>()) << good.dump();
  EXPECT_EQ(good["state"]["stock"]["target"]["source"],
            "polyline " + fs::canonical(dir.path / "profile.csv").string());
}

TEST(RunJob, TraceAndStepsLineForLine) {
  json r = runJob({{"program", "O0001\nG90 G00 X10. Y5.\n#1=5\n#100=3\nG01 X#1 F100.\nM30\n"},
                   {"name", "t.nc"}});
  ASSERT_TRUE(r["ok"].get<bool>()) << r.dump();
  EXPECT_EQ(countLines(r["trace"].get<std::string>()), r["steps"].size());
  ASSERT_EQ(r["steps"].size(), 2u);
  // The second move runs after #1 = 5 and #100 = 3: its step says so, the first does not.
  EXPECT_FALSE(r["steps"][0].contains("l"));
  EXPECT_EQ(r["steps"][1]["l"]["#1"], 5.0);
  EXPECT_EQ(r["steps"][1]["c"]["#100"], 3.0);
  EXPECT_EQ(r["steps"][0]["m"]["1"], 0.0);   // G00
  EXPECT_EQ(r["steps"][1]["m"]["1"], 1.0);   // G01
  EXPECT_TRUE(r["steps"][0].contains("o"));  // offsets given once at the start
  EXPECT_EQ(r["state"]["end"], "M30");
  EXPECT_EQ(r["machine"]["kind"], "mill");
}

// The deltas the viewer folds (state_diff.cpp): a change of move kind alone gives only its G
// code group, a change of feed with it gives both, a variable written again with the same
// value gives nothing, and a variable changed after events that changed none is seen.
TEST(RunJob, StepsHoldWhatChangedAndNothingElse) {
  json r = runJob({{"program",
                    "O0001\nG90 G01 X1. F100.\nG02 X2. R0.5\nG01 X3. F200.\n#100=7\n#100=7\n"
                    "G01 X4.\nX5.\n#501=2\nX6.\nM30\n"},
                   {"name", "t.nc"}});
  ASSERT_TRUE(r["ok"].get<bool>()) << r.dump();
  const json& st = r["steps"];
  ASSERT_EQ(st.size(), 6u) << st.dump();
  EXPECT_EQ(st[1]["m"], (json{{"1", 2.0}})) << st[1];                // G02 only
  EXPECT_EQ(st[2]["m"], (json{{"1", 1.0}, {"F", 200.0}})) << st[2];  // G01 and F200.
  EXPECT_EQ(st[3]["c"], (json{{"#100", 7.0}})) << st[3];             // #100 once
  EXPECT_TRUE(st[4].is_null() || !st[4].contains("c")) << st[4];
  EXPECT_EQ(st[5]["c"], (json{{"#501", 2.0}})) << st[5];
}

// The page sends the editor's text with the name and folder of the file it came from: that
// file is the text, not a second copy of its programs ("O0202 is also in ..."), while the
// folder's other files still give the subprograms.
TEST(RunJob, TheProgramsOwnFileIsNotLoadedTwice) {
  TempDir dir;
  const std::string main = "O0202\nG00 X1.\nM98 P9001\nM30\n";
  write(dir.path / "main.nc", main);
  write(dir.path / "sub.nc", "O9001\nG00 X2.\nM99\n");
  json r = runJob({{"program", main}, {"name", "main.nc"}, {"libs", {dir.path.string()}}});
  ASSERT_TRUE(r["ok"].get<bool>()) << r.dump();
  EXPECT_EQ(r["load_warnings"], json::array()) << r["load_warnings"];
  EXPECT_EQ(r["state"]["end"], "M30");
  EXPECT_EQ(countLines(r["trace"].get<std::string>()), 2u);  // both moves, the sub's too
  // Another name: the folder's main.nc is a second copy, and said so.
  json other = runJob({{"program", main}, {"name", "copy.nc"}, {"libs", {dir.path.string()}}});
  ASSERT_EQ(other["load_warnings"].size(), 1u) << other.dump();
}

TEST(RunJob, AlarmHasItsLineAndColumn) {
  json r = runJob({{"program", "O0001\nG00 X1.\n#1=0\n#2=1/#1\nM30\n"}, {"name", "a.nc"}});
  ASSERT_TRUE(r["ok"].get<bool>());
  EXPECT_EQ(r["state"]["alarm"]["code"], "PS0112");
  EXPECT_EQ(r["state"]["alarm"]["line"], 4);
  EXPECT_EQ(r["state"]["alarm"]["file"], "a.nc");
  EXPECT_EQ(countLines(r["trace"].get<std::string>()), r["steps"].size());
}

TEST(RunJob, CapsBoundTheSetup) {
  // The setup asks for more blocks than the server allows: the server's cap wins.
  json r = runJob({{"program", "O0001\nWHILE[1EQ1]DO1\n#1=#1+1\nEND1\nM30\n"},
                   {"setup", "[limits]\nmax_blocks = 100000000\n"},
                   {"caps", {{"max_blocks", 500}}}});
  ASSERT_TRUE(r["ok"].get<bool>()) << r.dump();
  EXPECT_EQ(r["state"]["end"], "limit");
  EXPECT_EQ(r["state"]["blocks"], 500);
  json big = runJob({{"program", std::string(2000, ' ')}, {"caps", {{"max_program_bytes", 1000}}}});
  EXPECT_FALSE(big["ok"].get<bool>());
  json bad = runJob({{"program", "O1\nM30\n"}, {"setup", "[machine\nkind = 3\n"}});
  EXPECT_FALSE(bad["ok"].get<bool>());
  EXPECT_NE(bad["error"].get<std::string>().find("setup error"), std::string::npos);
  EXPECT_FALSE(runJob(json::array())["ok"].get<bool>());
}

class ServerTest : public ::testing::Test {
 protected:
  TempDir web, root, outside;
  std::unique_ptr<WebServer> server;
  std::thread thread;
  int port = 0;

  void SetUp() override {
    write(web.path / "index.html", "<title>ncvm test page</title>");
    write(outside.path / "secret.nc", "O9999 (SECRET)\n");
    write(root.path / "parts" / "p1.nc", "O0001\nG00 X1.\nM98 P2000\nM30\n");
    write(root.path / "parts" / "p1.toml", "[machine]\nkind = \"mill\"\n");
    write(root.path / "parts" / "O2000.nc", "O2000\nG00 Y2.\nM99\n");
    fs::create_symlink(outside.path / "secret.nc", root.path / "parts" / "link.nc");
    fs::create_symlink(outside.path / "secret.nc", web.path / "leak.html");
    ServerConfig c;
    c.port = 0;
    c.webDir = web.path.string();
    c.catalog.add("root", root.path);
    c.workerExe = NCVM_BINARY;
    c.maxBodyBytes = 64 * 1024;
    c.caps.maxProgramBytes = 16 * 1024;
    c.caps.maxBlocks = 1'000'000'000;  // so that only the wall clock stops the runaway
    c.worker.timeout = std::chrono::milliseconds(1500);
    c.threads = 8;
    // Shorter than the defaults (10 s, 5 s) so that the tests see them act.
    c.connection.requestSeconds = 3;
    c.connection.firstRequestSeconds = 2;
    server = std::make_unique<WebServer>(std::move(c));
    port = server->bind();
    thread = std::thread([this] { server->listen(); });
  }
  void TearDown() override {
    server->stop();
    thread.join();
  }
  httplib::Client client() {
    httplib::Client c("127.0.0.1", port);
    c.set_read_timeout(30, 0);
    return c;
  }
  httplib::Result post(const std::string& body) {
    return client().Post("/api/run", body, "application/json");
  }
  // What the server answers to raw bytes, or "" when it just closes.
  // A connected socket to the server, or -1.
  int connectRaw() {
    int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_port = htons(static_cast<uint16_t>(port));
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (::connect(fd, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0) {
      ::close(fd);
      return -1;
    }
    return fd;
  }
  std::string raw(const std::string& bytes) {
    int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_port = htons(static_cast<uint16_t>(port));
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (::connect(fd, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0) {
      ::close(fd);
      return "connect failed";
    }
    timeval tv{5, 0};
    ::setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &tv, sizeof tv);
    (void)::send(fd, bytes.data(), bytes.size(), MSG_NOSIGNAL);
    ::shutdown(fd, SHUT_WR);
    std::string out;
    char buf[4096];
    ssize_t n;
    while ((n = ::recv(fd, buf, sizeof buf, 0)) > 0) out.append(buf, static_cast<size_t>(n));
    ::close(fd);
    return out;
  }
};

TEST_F(ServerTest, ServesThePageAndListsPrograms) {
  auto r = client().Get("/");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);
  EXPECT_NE(r->body.find("ncvm test page"), std::string::npos);
  auto files = client().Get("/api/files");
  ASSERT_TRUE(files);
  json j = json::parse(files->body);
  ASSERT_EQ(j["roots"].size(), 1u);
  std::vector<std::string> paths;
  for (const auto& f : j["roots"][0]["files"]) paths.push_back(f["path"]);
  // The symlink out of the root is not listed.
  EXPECT_EQ(paths, (std::vector<std::string>{"parts/O2000.nc", "parts/p1.nc"}));
  auto f = client().Get("/api/file?root=root&path=parts/p1.nc");
  ASSERT_TRUE(f);
  EXPECT_EQ(f->status, 200);
  json pj = json::parse(f->body);
  EXPECT_EQ(pj["setup_path"], "parts/p1.toml");
  EXPECT_EQ(pj["dir"], "parts");
}

TEST_F(ServerTest, RefusesPathsOutsideItsFolders) {
  for (const char* bad :
       {"/api/file?root=root&path=../../etc/passwd", "/api/file?root=root&path=/etc/passwd",
        "/api/file?root=root&path=parts/link.nc", "/api/file?root=nope&path=parts/p1.nc",
        "/api/file?root=root&path=parts/%2e%2e/%2e%2e/x"}) {
    auto r = client().Get(bad);
    ASSERT_TRUE(r) << bad;
    EXPECT_TRUE(r->status == 400 || r->status == 404) << bad << " -> " << r->status;
    EXPECT_EQ(r->body.find("SECRET"), std::string::npos) << bad;
  }
  for (const char* bad : {"/leak.html", "/../../etc/passwd", "/%2e%2e/%2e%2e/etc/passwd",
                          "/..%2f..%2fetc%2fpasswd"}) {
    std::string answer = raw(std::string("GET ") + bad +
                             " HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n");
    EXPECT_EQ(answer.find("SECRET"), std::string::npos) << bad;
    EXPECT_EQ(answer.find("root:"), std::string::npos) << bad;
    EXPECT_EQ(answer.find("HTTP/1.1 200"), std::string::npos)
        << bad << ": " << answer.substr(0, 40);
  }
  // A library folder for M98 must be inside a root too.
  auto r = post(json{{"program", "O1\nM30\n"}, {"root", "root"}, {"dir", "../"}}.dump());
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 400);
}

TEST_F(ServerTest, RunsWithTheProgramsFolderAsLibrary) {
  auto f = client().Get("/api/file?root=root&path=parts/p1.nc");
  json pj = json::parse(f->body);
  auto r = post(json{
      {"program", pj["text"]},
      {"name", "p1.nc"},
      {"setup", pj["setup"]},
      {"root", "root"},
      {"dir",
       "parts"}}.dump());
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;
  json j = json::parse(r->body);
  EXPECT_EQ(j["state"]["end"], "M30");
  EXPECT_EQ(j["state"]["moves"], 2);  // O2000 was found in the folder
}

// A program of the server's folders sent without a setup runs with its own setup, by the rule
// of `ncvm list` (a variant NAME-VARIANT.nc with NAME.toml), by path and as edited text; a
// setup sent wins, and an empty one is the default machine.
TEST_F(ServerTest, AProgramWithoutASetupRunsWithItsOwn) {
  write(root.path / "parts" / "cut-x150.nc", "O0003\nG90 G54 G00 X1.\nM30\n");
  write(root.path / "parts" / "cut.toml", "[work_offsets]\nG54 = [10.0, 0.0, 0.0]\n");
  auto machineX = [&](const json& body) {
    auto r = post(body.dump());
    EXPECT_TRUE(r);
    if (!r) return -1.0;
    EXPECT_EQ(r->status, 200) << r->body;
    json j = json::parse(r->body);
    return j["state"]["position"]["machine"][0].get<double>();
  };
  EXPECT_DOUBLE_EQ(machineX({{"root", "root"}, {"path", "parts/cut-x150.nc"}}), 11.0);
  EXPECT_DOUBLE_EQ(machineX({{"program", "O0003\nG90 G54 G00 X1.\nM30\n"},
                             {"name", "cut-x150.nc"},
                             {"root", "root"},
                             {"dir", "parts"}}),
                   11.0);
  EXPECT_DOUBLE_EQ(
      machineX({{"root", "root"}, {"path", "parts/cut-x150.nc"}, {"setup", "[machine]\n"}}), 1.0);
  // Not a program of a folder: the default machine.
  EXPECT_DOUBLE_EQ(
      machineX({{"program", "O0003\nG90 G54 G00 X1.\nM30\n"}, {"name", "cut-x150.nc"}}), 1.0);
}

// Issue 26 item 7: parts/link.nc, a symlink to a file outside the roots, was loaded as a
// library program, so M98 P9999 ran it (its text showed in the answer) while /api/file
// refused it; and answers named files by the server's absolute paths.
TEST_F(ServerTest, LibraryLookupsStayInsideTheRootsAndAreNamedByThem) {
  auto r =
      post(json{{"program", "O1\nM98 P9999\nM30\n"}, {"root", "root"}, {"dir", "parts"}}.dump());
  ASSERT_TRUE(r);
  EXPECT_EQ(r->body.find("SECRET"), std::string::npos) << r->body.substr(0, 400);
  json j = json::parse(r->body);
  EXPECT_EQ(j["state"]["end"], "alarm") << r->body.substr(0, 400);
  EXPECT_EQ(j["state"]["alarm"]["code"], "PS0076");  // program not found

  auto f = client().Get("/api/file?root=root&path=parts/p1.nc");
  r = post(json{{"program", json::parse(f->body)["text"]},
                {"name", "p1.nc"},
                {"root", "root"},
                {"dir", "parts"}}
               .dump());
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;
  const std::string rootPath = fs::canonical(root.path).string(),
                    outsidePath = fs::canonical(outside.path).string();
  EXPECT_EQ(r->body.find(rootPath), std::string::npos) << "an absolute server path in the answer";
  EXPECT_EQ(r->body.find(outsidePath), std::string::npos);
  EXPECT_NE(r->body.find("root/parts/O2000.nc"), std::string::npos)
      << "O2000's lines named by their root";
  // A load error names the folder by its root too.
  r = post(json{{"program", "O1\nM98 P2000\nM30\n"},
                {"root", "root"},
                {"dir", "parts"},
                {"setup", "[target]\npolyline = \"nope.csv\"\n"}}
               .dump());
  ASSERT_TRUE(r);
  EXPECT_EQ(r->body.find(rootPath), std::string::npos) << r->body;
}

// Issue 26 item 8: 8 connections sending a byte at a time (as many as the server had
// threads) blocked every request, and 50 idle connections delayed one by 28 s. Idle and slow
// connections now hold connection threads only, are closed when idle, and the runs have
// slots of their own.
TEST_F(ServerTest, AnswersWithinASecondDuringSlowAndIdleConnections) {
  using Clock = std::chrono::steady_clock;
  std::vector<int> idle;
  for (int k = 0; k < 50; ++k) idle.push_back(connectRaw());
  const auto idleSince = Clock::now();
  std::vector<std::thread> slow;
  std::vector<long long> slowLasted(8, 0);  // ms until the server cut the connection
  for (int client = 0; client < 8; ++client)
    slow.emplace_back([&, client] {
      const auto start = Clock::now();
      int fd = connectRaw();
      const std::string head = "GET /api/info HTTP/1.1\r\nHost: 127.0.0.1\r\nX-Slow: ";
      // One byte every 100 ms, never finishing the header; at most 15 s.
      for (size_t k = 0; k < 150; ++k) {
        char c = k < head.size() ? head[k] : 'a';
        if (::send(fd, &c, 1, MSG_NOSIGNAL) != 1) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
      }
      slowLasted[static_cast<size_t>(client)] =
          std::chrono::duration_cast<std::chrono::milliseconds>(Clock::now() - start).count();
      ::close(fd);
    });
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  for (int attempt = 0; attempt < 3; ++attempt) {
    const auto start = Clock::now();
    auto r = client().Get("/api/info");
    const auto ms =
        std::chrono::duration_cast<std::chrono::milliseconds>(Clock::now() - start).count();
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 200);
    EXPECT_LT(ms, 1000) << "request " << attempt << " during the attack";
  }
  auto run = post(json{{"program", "O1\nG0X1.\nM30\n"}}.dump());
  ASSERT_TRUE(run);
  EXPECT_EQ(run->status, 200);
  // The idle connections are closed by the server (2 s without a request here).
  for (int fd : idle) {
    timeval tv{5, 0};
    ::setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &tv, sizeof tv);
  }
  char byte;
  EXPECT_EQ(::recv(idle.front(), &byte, 1, 0), 0) << "an idle connection stayed open";
  EXPECT_LT(std::chrono::duration_cast<std::chrono::milliseconds>(Clock::now() - idleSince).count(),
            4000);
  // A request that does not arrive whole within its deadline (3 s here) is cut off.
  for (auto& t : slow) t.join();
  for (long long ms : slowLasted) EXPECT_LT(ms, 6000) << "a slow request was not cut off";
  for (int fd : idle) ::close(fd);
}

// One client (one remote address) holds at most 64 connections: the others are closed at
// once instead of taking threads.
TEST_F(ServerTest, OneClientsConnectionsAreBounded) {
  std::vector<int> fds;
  for (int k = 0; k < 80; ++k) fds.push_back(connectRaw());
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  int closed = 0;
  for (int fd : fds) {
    pollfd p{fd, POLLIN, 0};
    char byte;
    if (::poll(&p, 1, 0) > 0 && ::recv(fd, &byte, 1, MSG_DONTWAIT) == 0) ++closed;
  }
  EXPECT_EQ(closed, 80 - 64);
  for (int fd : fds) ::close(fd);
  // Once they are gone, the client is served again.
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  auto r = client().Get("/api/info");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);
}

TEST_F(ServerTest, MalformedAndOversizedRequests) {
  auto r = post("{not json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 400);
  r = post("[1,2,3]");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 400);
  r = post(json{{"programme", "O1"}}.dump());
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 400);
  r = post(
      json{{"program", "O1\nM30\n"}, {"name", 42}, {"dir", false}}.dump());  // wrong types: ignored
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);
  r = post(json{{"program", 42}}.dump());
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 400);
  r = post(json{{"program", "O1\nM30\n"}, {"setup", "[[[bad toml"}}.dump());
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 400);
  EXPECT_NE(r->body.find("setup error"), std::string::npos);
  r = post(json{{"program", std::string(20 * 1024, 'G')}}.dump());  // program cap 16 KiB
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 413);
  r = post(std::string(100 * 1024, ' '));  // body cap 64 KiB
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 413);
  // Garbage on the socket gets an error or a closed connection, and the server lives on.
  for (const char* junk :
       {"GARBAGE\r\n\r\n", "GET\r\n\r\n", "\x01\x02\x03\xff\r\n\r\n",
        "POST /api/run HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Length: 99999999999\r\n\r\n"}) {
    std::string answer = raw(junk);
    EXPECT_EQ(answer.find("HTTP/1.1 200"), std::string::npos) << junk;
  }
  auto alive = client().Get("/api/info");
  ASSERT_TRUE(alive);
  EXPECT_EQ(alive->status, 200);
}

TEST_F(ServerTest, RefusesForeignHostAndOrigin) {
  httplib::Client c = client();
  auto r = c.Get("/api/info", {{"Host", "evil.example:80"}});
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 403);
  r = c.Get("/api/info", {{"Host", "127.0.0.1.evil.example:80"}});
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 403);
  r = c.Post("/api/run", {{"Origin", "http://evil.example"}}, json{{"program", "O1\nM30\n"}}.dump(),
             "application/json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 403);
  // Another local port is another origin; the server's own passes.
  r = c.Post("/api/run", {{"Origin", "http://localhost:3000"}},
             json{{"program", "O1\nM30\n"}}.dump(), "application/json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 403);
  r = c.Get("/api/info", {{"Origin", "http://127.0.0.1:" + std::to_string(port)}});
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);
}

TEST_F(ServerTest, ConcurrentClientsAreIsolated) {
  constexpr int kClients = 8, kEach = 3;
  std::vector<std::thread> threads;
  std::vector<int> good(kClients, 0);
  for (int id = 0; id < kClients; ++id)
    threads.emplace_back([&, id] {
      for (int k = 0; k < kEach; ++k) {
        // Each run writes its own id into #100 and #500: another run must never see it.
        std::string prog = "O0001\nIF[#100NE#0]GOTO9\n#100=" + std::to_string(id) +
                           "\n#500=#500+1\nG01 X#100 F1000.\nN9 M30\n";
        auto r = post(json{{"program", prog}}.dump());
        if (!r || r->status != 200) continue;
        json j = json::parse(r->body);
        if (j["state"]["vars"]["#100"] == static_cast<double>(id) &&
            j["state"]["vars"]["#500"] == 1.0)
          ++good[id];
      }
    });
  for (auto& t : threads) t.join();
  for (int id = 0; id < kClients; ++id) EXPECT_EQ(good[id], kEach) << "client " << id;
}

TEST_F(ServerTest, RunawayProgramTimesOut) {
  auto start = std::chrono::steady_clock::now();
  // The setup's own block limit (10^8 by default) is raised to the server's cap: 10^8 of these
  // blocks take about a second on a fast machine, less than the 1.5 s timeout.
  auto r = post(json{{"program", "O0001\nWHILE[1EQ1]DO1\n#1=#1+1\nEND1\nM30\n"},
                     {"setup", "[limits]\nmax_blocks = 1000000000\n"}}
                    .dump());
  auto took = std::chrono::steady_clock::now() - start;
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 503);
  EXPECT_NE(r->body.find("timeout"), std::string::npos);
  EXPECT_LT(took, std::chrono::seconds(10));
  // The server still runs the next program.
  auto ok = post(json{{"program", "O1\nG00 X1.\nM30\n"}}.dump());
  ASSERT_TRUE(ok);
  EXPECT_EQ(ok->status, 200);
}

namespace {

// The stock of a run, simulated by the CLI's path (Session with --stock-out) into `dir`.
void simulateToFiles(const std::string& program, const std::string& setupText,
                     const fs::path& dir) {
  ncvm::Session s(ncvm::parseSetup(setupText, "setup.toml"));
  s.addProgramText(program, "p.nc");
  s.simulateStock(dir.string());
  s.run(nullptr);
}

const char* kLatheSetup =
    "[machine]\nkind = \"lathe\"\nunits = \"mm\"\n[axes.X]\ninitial = 100.0\n[axes.Z]\ninitial = "
    "20.0\n"
    "[tools.1]\ntype = \"insert\"\nnose_radius = 0.4\ntip = 3\n"
    "[stock]\ndiameter = 50.0\nlength = 60.0\nfront_z = 0.0\n";
const char* kLatheProgram =
    "O0001\nG99 T0101\nG00 X52. Z2.\nG01 Z-30. F0.2\nX40.\nZ-30.\nG00 X52.\nZ2.\nX40.\n"
    "G01 Z-30.\nG00 X100. Z20.\nM30\n";

const char* kMillSetup =
    "[machine]\nkind = \"mill\"\nunits = \"mm\"\n[axes.Z]\ninitial = 50.0\n"
    "[tools.1]\ntype = \"flat\"\ndiameter = 10.0\n"
    "[stock]\nmin = [0.0, 0.0, -20.0]\nmax = [400.0, 100.0, 0.0]\ncell = 0.5\n";
const char* kMillProgram =
    "O0002\nT1 M06\nG90 G00 X-10. Y50.\nZ-5.\nG01 X410. F500.\nG00 Z50.\nM30\n";

}  // namespace

TEST(RunJob, LatheStockIsTheSimulatedProfile) {
  json r = runJob({{"program", kLatheProgram}, {"setup", kLatheSetup}});
  ASSERT_TRUE(r["ok"].get<bool>()) << r.dump();
  ASSERT_TRUE(r.contains("stock"));
  const json& st = r["stock"];
  EXPECT_EQ(st["type"], "profile");
  EXPECT_TRUE(r["state"]["stock"].is_object());  // the analysis for the panels

  // The same run through the CLI's path: profile.csv holds ring,hole,x,z.
  TempDir dir;
  simulateToFiles(kLatheProgram, kLatheSetup, dir.path);
  std::ifstream csv(dir.path / "profile.csv");
  std::string line;
  std::getline(csv, line);
  std::vector<std::vector<std::pair<double, double>>> rings;
  while (std::getline(csv, line)) {
    size_t ring = 0;
    int hole = 0;
    double x = 0, z = 0;
    ASSERT_EQ(std::sscanf(line.c_str(), "%zu,%d,%lf,%lf", &ring, &hole, &x, &z), 4) << line;
    if (rings.size() <= ring) rings.resize(ring + 1);
    rings[ring].push_back({z, x});
    EXPECT_EQ(st["rings"][ring]["hole"].get<bool>(), hole == 1);
  }
  ASSERT_EQ(st["rings"].size(), rings.size());
  double minX = 1e9, maxX = 0;
  for (size_t k = 0; k < rings.size(); ++k) {
    const json& pts = st["rings"][k]["points"];
    ASSERT_EQ(pts.size(), rings[k].size());
    for (size_t i = 0; i < pts.size(); ++i) {
      EXPECT_NEAR(pts[i][0].get<double>(), rings[k][i].first, 1e-4);
      EXPECT_NEAR(pts[i][1].get<double>(), rings[k][i].second, 1e-4);
      minX = std::min(minX, pts[i][1].get<double>());
      maxX = std::max(maxX, pts[i][1].get<double>());
    }
  }
  // The bar of D50 turned to D40 over Z0..-30 (the axis is the profile's other edge).
  EXPECT_NEAR(maxX, 50.0, 1e-6);
  EXPECT_NEAR(minX, 0.0, 1e-6);
  bool turned = false;
  for (const auto& p : st["rings"][0]["points"])
    if (std::abs(p[1].get<double>() - 40.0) < 1e-3 && p[0].get<double>() < -10) turned = true;
  EXPECT_TRUE(turned) << st.dump();
}

TEST(RunJob, MillStockIsTheHeightFieldDownsampled) {
  json r = runJob({{"program", kMillProgram}, {"setup", kMillSetup}});
  ASSERT_TRUE(r["ok"].get<bool>()) << r.dump();
  ASSERT_TRUE(r.contains("stock"));
  const json& st = r["stock"];
  EXPECT_EQ(st["type"], "grid");
  // 800 x 200 cells of 0.5 mm shrink by 4 to 200 x 50 cells of 2 mm.
  ASSERT_EQ(st["nx"].get<int>(), 200);
  ASSERT_EQ(st["ny"].get<int>(), 50);
  EXPECT_EQ(st["step"].get<int>(), 4);
  EXPECT_DOUBLE_EQ(st["cell"].get<double>(), 2.0);
  ASSERT_EQ(st["z"].size(), 200u * 50u);
  EXPECT_DOUBLE_EQ(st["bottom"].get<double>(), -20.0);

  // Every grid height is the lowest of its 4 x 4 block of stock.hmap.
  TempDir dir;
  simulateToFiles(kMillProgram, kMillSetup, dir.path);
  ncvm::HeightField f = ncvm::loadHeightMap((dir.path / "stock.hmap").string());
  ASSERT_EQ(f.nx(), 800);
  ASSERT_EQ(f.ny(), 200);
  EXPECT_DOUBLE_EQ(st["x0"].get<double>(), f.x0());
  EXPECT_DOUBLE_EQ(st["y0"].get<double>(), f.y0());
  int slot = 0;
  for (int gj = 0; gj < 50; ++gj)
    for (int gi = 0; gi < 200; ++gi) {
      float lo = f.top();
      for (int j = gj * 4; j < gj * 4 + 4; ++j)
        for (int i = gi * 4; i < gi * 4 + 4; ++i) lo = std::min(lo, f.at(i, j));
      double z = st["z"][static_cast<size_t>(gj * 200 + gi)].get<double>();
      ASSERT_NEAR(z, lo, 1e-4) << gi << "," << gj;
      if (std::abs(z + 5.0) < 1e-4) ++slot;
    }
  // The slot (Y45..55 at Z-5, 10 mm wide) covers 5 or 6 rows of 2 mm along the whole block.
  EXPECT_GE(slot, 5 * 200);
  EXPECT_LE(slot, 6 * 200);
}

TEST(RunJob, NoStockWithoutAStockSection) {
  json r = runJob({{"program", "O1\nG00 X1.\nM30\n"}});
  ASSERT_TRUE(r["ok"].get<bool>());
  EXPECT_FALSE(r.contains("stock"));
}

// ---- The binary run answer (viewer_stream.hpp, POST /api/run.bin) ----

namespace {

struct Frame {
  uint32_t kind;
  std::string payload;
};

// The frames of a binary answer; a cut frame fails the test.
std::vector<Frame> framesOf(const std::string& bytes) {
  std::vector<Frame> out;
  size_t at = 0;
  while (at < bytes.size()) {
    EXPECT_GE(bytes.size() - at, 8u) << "a cut frame header";
    if (bytes.size() - at < 8) break;
    uint32_t kind = 0, length = 0;
    std::memcpy(&kind, bytes.data() + at, 4);
    std::memcpy(&length, bytes.data() + at + 4, 4);
    size_t whole = 8 + length + (8 - length % 8) % 8;
    EXPECT_LE(whole, bytes.size() - at) << "a cut frame";
    if (whole > bytes.size() - at) break;
    out.push_back({kind, bytes.substr(at + 8, length)});
    at += whole;
  }
  return out;
}

// The columns of all events frames, as the page reads them (web/src/wire.js).
struct Columns {
  int axes = 3;
  std::vector<uint8_t> kind, flags;
  std::vector<uint32_t> line;
  std::vector<double> end, center, time, dt;
  size_t ownPositions = 0;
};

template <class T>
void take(const std::string& p, size_t& at, size_t count, std::vector<T>* into) {
  const size_t bytes = count * sizeof(T);
  EXPECT_LE(at + bytes, p.size());
  if (into && count) {  // memcpy from or to a null pointer is undefined even for 0 bytes
    size_t old = into->size();
    into->resize(old + count);
    std::memcpy(into->data() + old, p.data() + at, bytes);
  }
  at += bytes;
}

Columns columnsOf(const std::vector<Frame>& frames) {
  Columns c;
  for (const auto& f : frames) {
    if (f.kind != static_cast<uint32_t>(FrameKind::Events)) continue;
    uint32_t h[kBatchHeader];
    std::memcpy(h, f.payload.data(), sizeof h);
    const size_t n = h[0], m = h[1], starts = h[2], pos = h[3], arcs = h[4], path = h[5];
    const size_t A = h[6];
    c.axes = static_cast<int>(A);
    c.ownPositions += pos;
    size_t at = sizeof h;
    const std::string& p = f.payload;
    take<double>(p, at, n, &c.time);
    take<double>(p, at, pos * 3 * A, nullptr);
    take<double>(p, at, starts * A, nullptr);
    take<double>(p, at, m * A, &c.end);
    take<double>(p, at, m * A, nullptr);  // mend
    take<double>(p, at, arcs * 3, &c.center);
    take<double>(p, at, path * A, nullptr);
    take<double>(p, at, n, &c.dt);
    take<float>(p, at, m, nullptr);  // feed
    take<uint32_t>(p, at, n, &c.line);
    take<uint32_t>(p, at, n, nullptr);  // block
    take<int32_t>(p, at, n, nullptr);   // N
    take<uint16_t>(p, at, n, nullptr);  // file
    take<uint16_t>(p, at, m, nullptr);  // path count
    take<uint8_t>(p, at, n, &c.kind);
    take<uint8_t>(p, at, n, &c.flags);
    take<uint8_t>(p, at, arcs, nullptr);
    EXPECT_EQ(at, p.size()) << "the columns fill the payload exactly";
  }
  return c;
}

std::string binaryRun(const json& request) {
  std::string out;
  runViewerJob(request, [&](std::string_view f) { out.append(f); });
  return out;
}

}  // namespace

TEST(ViewerStream, FramesCarryEveryEventAsColumns) {
  const std::string program =
      "O0001\nG21 G90 G17 G54\n#1 = 5\nG00 X0 Y0 Z0\nG01 X10. F600.\nG03 X10. Y10. I0 J5.\n"
      "G04 P500\n#1 = 6\nG00 Z5.\nM30\n";
  std::vector<Frame> frames = framesOf(binaryRun({{"program", program}, {"name", "p.nc"}}));
  ASSERT_GE(frames.size(), 3u);
  EXPECT_EQ(frames.front().kind, static_cast<uint32_t>(FrameKind::Hello));
  EXPECT_EQ(json::parse(frames.front().payload)["format"], "ncvm-viewer");
  ASSERT_EQ(frames.back().kind, static_cast<uint32_t>(FrameKind::End));
  json end = json::parse(frames.back().payload);
  ASSERT_TRUE(end["ok"].get<bool>()) << end.dump();
  EXPECT_EQ(end["state"]["end"], "M30");
  EXPECT_EQ(end["files"], json::array({"p.nc"}));

  Columns c = columnsOf(frames);
  ASSERT_EQ(c.kind.size(), end["events"].get<size_t>());
  // The same events as the JSON trace, line for line.
  json j = runJob({{"program", program}, {"name", "p.nc"}});
  ASSERT_EQ(countLines(j["trace"].get<std::string>()), c.kind.size());
  std::istringstream trace(j["trace"].get<std::string>());
  std::string l;
  for (size_t i = 0; std::getline(trace, l); ++i) {
    json e = json::parse(l);
    EXPECT_EQ(e["line"].get<uint32_t>(), c.line[i]) << l;
    EXPECT_EQ(e["type"] == "move", c.kind[i] <= 3) << l;
    if (e["type"] == "dwell") {
      EXPECT_EQ(c.kind[i], static_cast<uint8_t>(EventKind::Dwell));
      EXPECT_DOUBLE_EQ(c.dt[i], 0.5);
    }
    if (e["type"] == "move" && e["mode"] == "ccw") {
      EXPECT_TRUE(c.flags[i] & kArc);
      EXPECT_EQ(c.center, (std::vector<double>{10, 5, 0}));
    }
  }
  // Four moves; the block end and positions follow the moves, so none is sent apart after
  // the first move.
  ASSERT_EQ(c.end.size(), 4u * static_cast<size_t>(c.axes));
  EXPECT_DOUBLE_EQ(c.end[2 * static_cast<size_t>(c.axes) + 1], 10.0);  // the arc ends at Y10
  EXPECT_LE(c.ownPositions, 1u);
  EXPECT_DOUBLE_EQ(c.time.back(), end["state"]["cycle_time"].get<double>());

  // The steps: #1 = 5 then 6, each once; the trace lines of the events that are not moves.
  std::vector<int> setAt;
  std::vector<uint64_t> notes;
  std::string noteText;
  for (const auto& f : frames) {
    if (f.kind == static_cast<uint32_t>(FrameKind::Steps)) {
      json s = json::parse(f.payload);
      for (const auto& st : s["steps"])
        if (st[1].contains("l") && st[1]["l"].contains("#1"))
          setAt.push_back(st[1]["l"]["#1"].get<int>());
      for (const auto& n : s["notes"]) notes.push_back(n.get<uint64_t>());
    }
    if (f.kind == static_cast<uint32_t>(FrameKind::Notes)) noteText += f.payload;
  }
  EXPECT_EQ(setAt, (std::vector<int>{5, 6}));
  EXPECT_EQ(countLines(noteText), notes.size());
  for (uint64_t i : notes) EXPECT_GT(c.kind[i], 3) << "a note is not a move";
}

// Where work zero is on the machine, before the events frame of its batch: the page draws
// the path fixed on the machine. A switch to G55 after two cutting moves that the time
// model still holds in its look-ahead comes after them (the timing stage keeps the order).
TEST(ViewerStream, WorkZeroMovesAreSentInOrderWithTheMoves) {
  const std::string program =
      "O0001\nG21 G90 G17 G54\nG00 X0 Y0 Z0\nG01 X10. F600.\nY10.\nG55\nG01 X5.\n"
      "G10 L2 P2 X20.\nG01 X6.\nM30\n";
  const std::string setup =
      "[timing]\nmodel = \"dynamic\"\n[work_offsets]\nG54 = [1.0, 2.0, 3.0]\nG55 = [5.0, 6.0, "
      "7.0]\n";
  std::vector<Frame> frames =
      framesOf(binaryRun({{"program", program}, {"name", "p.nc"}, {"setup", setup}}));
  EXPECT_EQ(json::parse(frames.front().payload)["frame"], "work");
  json origins = json::array();
  bool eventsSeen = false;
  for (const auto& f : frames) {
    eventsSeen = eventsSeen || f.kind == static_cast<uint32_t>(FrameKind::Events);
    if (f.kind != static_cast<uint32_t>(FrameKind::Origins)) continue;
    EXPECT_FALSE(eventsSeen) << "origins come before the events of their batch";
    json o = json::parse(f.payload);
    for (const auto& each : o["origins"]) origins.push_back(each);
  }
  Columns c = columnsOf(frames);
  std::vector<size_t> moves;  // event index of each move
  for (size_t i = 0; i < c.kind.size(); ++i)
    if (c.kind[i] <= 3) moves.push_back(i);
  ASSERT_EQ(moves.size(), 5u);
  ASSERT_EQ(origins.size(), 3u) << origins.dump();
  EXPECT_EQ(origins[0], json::array({0, 1.0, 2.0, 3.0}));
  EXPECT_EQ(origins[1], json::array({moves[3], 5.0, 6.0, 7.0})) << "from G01 X5. on";
  EXPECT_GT(origins[2][0].get<size_t>(), moves[3]);
  EXPECT_LE(origins[2][0].get<size_t>(), moves[4]);
  EXPECT_EQ(origins[2][1], 20.0);
}

// The physical tools for the page to draw: a ball mill's profile rises to its radius at its
// rim, a face mill is short, a probe is its ball, a tool without a diameter is left out; a
// lathe insert is its outline on the side its tip direction gives.
TEST(ViewerTools, TheSetupsToolsAsTheSimulationShapesThem) {
  json j = runJob({{"program", "O1\nM30\n"},
                   {"setup",
                    "[tools.1]\ntype = \"ball\"\ndiameter = 10.0\n[tools.2]\ntype = \"face\"\n"
                    "diameter = 50.0\n[tools.3]\ntype = \"probe\"\ndiameter = 4.0\n"
                    "[tools.4]\ntype = \"flat\"\n"}});
  ASSERT_TRUE(j["ok"].get<bool>()) << j.dump();
  const json& t = j["tools"];
  EXPECT_EQ(t["1"]["profile"].front(), json::array({0.0, 0.0}));
  EXPECT_EQ(t["1"]["profile"].back(), json::array({5.0, 5.0}));
  EXPECT_DOUBLE_EQ(t["2"]["length"].get<double>(), 17.5);
  EXPECT_EQ(t["3"], json({{"type", "probe"}, {"diameter", 4.0}}));
  EXPECT_FALSE(t.contains("4"));
  json lathe = runJob({{"program", "O1\nM30\n"},
                       {"setup",
                        "[machine]\nkind = \"lathe\"\n[tools.1]\ntype = \"insert\"\n"
                        "nose_radius = 0.8\ntip = 3\n"}});
  ASSERT_TRUE(lathe["ok"].get<bool>()) << lathe.dump();
  const json& outline = lathe["tools"]["1"]["outline"];
  ASSERT_GT(outline.size(), 3u);
  double rmin = 1e9, zmin = 1e9, rmax = -1e9;
  for (const auto& p : outline) {
    rmin = std::min(rmin, p[0].get<double>());
    zmin = std::min(zmin, p[1].get<double>());
    rmax = std::max(rmax, p[0].get<double>());
  }
  // Tip 3: the imaginary tip is the outline's lower left corner, the insert above and right.
  EXPECT_NEAR(rmin, 0.0, 0.01);
  EXPECT_NEAR(zmin, 0.0, 0.01);
  EXPECT_GT(rmax, 5.0);
}

TEST(ViewerStream, AFailureIsAnEndFrame) {
  std::vector<Frame> frames =
      framesOf(binaryRun({{"program", "O1\nM30\n"}, {"setup", "[machine\n"}}));
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_EQ(frames[0].kind, static_cast<uint32_t>(FrameKind::End));
  json end = json::parse(frames[0].payload);
  EXPECT_FALSE(end["ok"].get<bool>());
  EXPECT_NE(end["error"].get<std::string>().find("setup error"), std::string::npos);
}

TEST_F(ServerTest, BinaryRunStreamsFramesByTextAndByPath) {
  httplib::Client c = client();
  // The text, with its folder as the library (M98 P2000 finds O2000.nc).
  auto r = c.Post("/api/run.bin",
                  json{{"program", "O0001\nG00 X1.\nM98 P2000\nM30\n"},
                       {"name", "p1.nc"},
                       {"root", "root"},
                       {"dir", "parts"}}
                      .dump(),
                  "application/json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);
  EXPECT_EQ(r->get_header_value("Content-Type"), "application/octet-stream");
  std::vector<Frame> frames = framesOf(r->body);
  ASSERT_FALSE(frames.empty());
  json end = json::parse(frames.back().payload);
  ASSERT_TRUE(end["ok"].get<bool>()) << end.dump();
  EXPECT_EQ(end["state"]["moves"], 2);
  // By path: the server reads the file (its size bounded by the program cap, not the body's).
  r = c.Post("/api/run.bin", json{{"root", "root"}, {"path", "parts/p1.nc"}}.dump(),
             "application/json");
  ASSERT_TRUE(r);
  frames = framesOf(r->body);
  ASSERT_FALSE(frames.empty());
  end = json::parse(frames.back().payload);
  ASSERT_TRUE(end["ok"].get<bool>()) << end.dump();
  EXPECT_EQ(end["name"], "p1.nc");
  EXPECT_EQ(end["state"]["moves"], 2);
  // Nothing outside the roots, by path either.
  for (const char* bad : {"../secret.nc", "parts/link.nc", "/etc/passwd", "parts/none.nc"}) {
    r = c.Post("/api/run.bin", json{{"root", "root"}, {"path", bad}}.dump(), "application/json");
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 404) << bad;
    EXPECT_EQ(r->body.find("SECRET"), std::string::npos) << bad;
  }
}

// No absolute server path in the binary answer either: the file names of the end frame and
// the notes' text (a dwell of a sub-program found in the library) are named by their root.
TEST_F(ServerTest, BinaryRunNamesFilesByTheirRoot) {
  write(root.path / "parts" / "O2001.nc", "O2001\nG04 X0.1\nM99\n");
  auto r = client().Post("/api/run.bin",
                         json{{"program", "O0001\nM98 P2001\nM30\n"},
                              {"name", "p1.nc"},
                              {"root", "root"},
                              {"dir", "parts"}}
                             .dump(),
                         "application/json");
  ASSERT_TRUE(r);
  std::vector<Frame> frames = framesOf(r->body);
  ASSERT_FALSE(frames.empty());
  json end = json::parse(frames.back().payload);
  ASSERT_TRUE(end["ok"].get<bool>()) << end.dump();
  EXPECT_EQ(r->body.find(fs::canonical(root.path).string()), std::string::npos)
      << "an absolute server path in the binary answer";
  bool named = false;
  for (const auto& f : end["files"])
    named |= f.is_string() && f.get<std::string>() == "root/parts/O2001.nc";
  EXPECT_TRUE(named) << end["files"].dump();
}

TEST_F(ServerTest, BinaryRunTimeoutIsItsEndFrame) {
  auto r =
      client().Post("/api/run.bin",
                    json{{"program", "O0001\nWHILE[1EQ1]DO1\nG91 G01 X0.001 F1000.\nEND1\nM30\n"},
                         {"setup", "[limits]\nmax_blocks = 1000000000\n"}}
                        .dump(),
                    "application/json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);  // the stream had begun
  std::vector<Frame> frames = framesOf(r->body);
  ASSERT_FALSE(frames.empty());
  EXPECT_GT(frames.size(), 2u) << "the events before the timeout were streamed";
  ASSERT_EQ(frames.back().kind, static_cast<uint32_t>(FrameKind::End));
  json end = json::parse(frames.back().payload);
  EXPECT_FALSE(end["ok"].get<bool>());
  EXPECT_NE(end["error"].get<std::string>().find("--timeout"), std::string::npos) << end.dump();
}

TEST_F(ServerTest, OversizedRequestsNameTheLimitAndItsOption) {
  httplib::Client c = client();
  // Over the body limit: refused before any handler, with the message all the same.
  auto r = c.Post("/api/run.bin", std::string(100 * 1024, ' '), "application/json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 413);
  EXPECT_NE(r->body.find("--max-upload-mb"), std::string::npos) << r->body;
  // A program over the program cap.
  r = c.Post("/api/run.bin", json{{"program", std::string(20 * 1024, 'G')}}.dump(),
             "application/json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 413);
  EXPECT_NE(r->body.find("--max-program-mb"), std::string::npos) << r->body;
}

TEST_F(ServerTest, NoCompressionOnLoopback) {
  auto r = client().Get("/api/info", {{"Accept-Encoding", "br, gzip, deflate"}});
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);
  EXPECT_EQ(r->get_header_value("Content-Encoding"), "");
  EXPECT_TRUE(json::parse(r->body).contains("version"));
}

// Setups in layers through the HTTP server and its worker process (setup_layers.hpp): the
// layer files listed by GET /api/setups, applied in the order sent around the program's own
// setup; and the stock along the timeline as kind 6 frames of /api/run.bin.
TEST_F(ServerTest, SetupLayersAndStockSnapshotsThroughTheWorker) {
  write(root.path / "parts" / "cut-x150.nc", "O0003\nG90 G54 G00 X1.\nM30\n");
  write(root.path / "parts" / "cut.toml", "[work_offsets]\nG54 = [10.0, 0.0, 0.0]\n");
  write(root.path / "parts" / "shift.toml", "[work_offsets]\nG54 = [100.0, 0.0, 0.0]\n");
  auto listed = client().Get("/api/setups");
  ASSERT_TRUE(listed);
  json files = json::parse(listed->body)["roots"][0]["files"];
  EXPECT_EQ(files, json({"parts/cut.toml", "parts/p1.toml", "parts/shift.toml"}));
  auto machineX = [&](const json& setups) {
    auto r = post(json{{"root", "root"}, {"path", "parts/cut-x150.nc"}, {"setups", setups}}.dump());
    EXPECT_TRUE(r);
    if (!r) return -1.0;
    EXPECT_EQ(r->status, 200) << r->body;
    return json::parse(r->body)["state"]["position"]["machine"][0].get<double>();
  };
  const json shift = {{"root", "root"}, {"path", "parts/shift.toml"}};
  EXPECT_DOUBLE_EQ(machineX(json::array({{{"tab", true}}, shift})), 101.0);  // the later layer wins
  EXPECT_DOUBLE_EQ(machineX(json::array({shift, {{"tab", true}}})), 11.0);
  EXPECT_DOUBLE_EQ(machineX(json::array({shift})),
                   11.0);  // the program's own setup last when not placed
  auto refused = post(json{{"root", "root"},
                           {"path", "parts/cut-x150.nc"},
                           {"setups", {{{"root", "root"}, {"path", "parts/link.nc"}}}}}
                          .dump());
  ASSERT_TRUE(refused);
  EXPECT_EQ(refused->status, 400);

  const std::string stock =
      "[tools.1]\ntype = \"flat\"\ndiameter = 10.0\n"
      "[stock]\nmin = [0.0, 0.0, -10.0]\nmax = [50.0, 20.0, 0.0]\ncell = 0.5\n";
  auto r = client().Post("/api/run.bin",
                         json{{"program",
                               "O1\nT1 M06\nG00 X-10. Y10. Z-2.\nG01 X60. F500.\n"
                               "G00 Z20.\nM30\n"},
                              {"setup", stock},
                              {"stock_every", 1}}
                             .dump(),
                         "application/json");
  ASSERT_TRUE(r);
  size_t shots = 0;
  json end;
  for (const Frame& f : framesOf(r->body)) {
    if (f.kind == static_cast<uint32_t>(FrameKind::Stock)) ++shots;
    if (f.kind == static_cast<uint32_t>(FrameKind::End)) end = json::parse(f.payload);
  }
  ASSERT_TRUE(end["ok"].get<bool>()) << end.dump();
  EXPECT_EQ(shots, end["state"]["moves"].get<size_t>());  // one before each move
  EXPECT_EQ(end["stock_snapshots"]["count"].get<size_t>(), shots);
}
