// The server's dispatch: the LSP life cycle, document sync, diagnostics when due, errors.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "lsp/server.hpp"

using namespace ncvm;
using namespace ncvm::lsp;
using nlohmann::json;

namespace {
json request(int id, const std::string& method, json params = json::object()) {
  return {{"jsonrpc", "2.0"}, {"id", id}, {"method", method}, {"params", params}};
}
json notification(const std::string& method, json params) {
  return {{"jsonrpc", "2.0"}, {"method", method}, {"params", params}};
}
json openParams(const std::string& text) {
  return {{"textDocument",
           {{"uri", "untitled:a"}, {"languageId", "fanuc"}, {"version", 1}, {"text", text}}}};
}
Server makeServer() {
  ServerOptions o;
  o.noMacros = true;
  return Server(defaultSetup(), o);
}
}  // namespace

TEST(LspServer, AnswersInitializeWithItsCapabilitiesAndRefusesRequestsBefore) {
  Server s = makeServer();
  auto early = s.handle(request(1, "textDocument/hover"));
  ASSERT_EQ(early.size(), 1u);
  EXPECT_EQ(early[0]["error"]["code"], -32002);
  auto init = s.handle(request(2, "initialize", {{"capabilities", json::object()}}));
  ASSERT_EQ(init.size(), 1u);
  const json& caps = init[0]["result"]["capabilities"];
  EXPECT_EQ(caps["textDocumentSync"]["change"], 1);
  EXPECT_TRUE(caps["hoverProvider"] && caps["definitionProvider"] &&
              caps["documentSymbolProvider"]);
  EXPECT_EQ(init[0]["result"]["serverInfo"]["name"], "ncvm");
}

TEST(LspServer, PublishesDiagnosticsAfterOpenAndChangeAndClearsThemOnClose) {
  Server s = makeServer();
  s.handle(request(1, "initialize"));
  EXPECT_TRUE(s.handle(notification("textDocument/didOpen", openParams("G01 X1. F0\n"))).empty());
  EXPECT_TRUE(s.hasPending() && s.urgent());
  auto d = s.publishDue();
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0]["method"], "textDocument/publishDiagnostics");
  EXPECT_EQ(d[0]["params"]["diagnostics"][0]["code"], "PS0011");
  EXPECT_FALSE(s.hasPending());
  // A change waits for the editor's pause (not urgent), then the fixed text has none.
  s.handle(notification("textDocument/didChange",
                        {{"textDocument", {{"uri", "untitled:a"}, {"version", 2}}},
                         {"contentChanges", {{{"text", "G01 X1. F10.\n"}}}}}));
  EXPECT_TRUE(s.hasPending());
  EXPECT_FALSE(s.urgent());
  d = s.publishDue();
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0]["params"]["version"], 2);
  EXPECT_TRUE(d[0]["params"]["diagnostics"].empty()) << d[0].dump();
  d = s.handle(notification("textDocument/didClose", {{"textDocument", {{"uri", "untitled:a"}}}}));
  ASSERT_EQ(d.size(), 1u);
  EXPECT_TRUE(d[0]["params"]["diagnostics"].empty());
}

TEST(LspServer, RoutesFeatureRequestsAndAnswersErrorsForBadOnes) {
  Server s = makeServer();
  s.handle(request(1, "initialize"));
  s.handle(notification("textDocument/didOpen", openParams("O0100\nG01 X1.\n")));
  const json at = {{"textDocument", {{"uri", "untitled:a"}}},
                   {"position", {{"line", 1}, {"character", 1}}}};
  auto h = s.handle(request(2, "textDocument/hover", at));
  EXPECT_NE(h[0]["result"]["contents"]["value"].get<std::string>().find("G01"), std::string::npos);
  EXPECT_EQ(h[0]["result"]["contents"]["value"].get<std::string>().find("→"), std::string::npos);
  s.handle(notification(
      "textDocument/didOpen",
      {{"textDocument",
        {{"uri", "untitled:g"}, {"version", 1}, {"text", "O0100\nN5 #1=1\nGOTO5\n"}}}}));
  auto jump = s.handle(request(
      9, "textDocument/hover",
      {{"textDocument", {{"uri", "untitled:g"}}}, {"position", {{"line", 2}, {"character", 4}}}}));
  EXPECT_NE(jump[0]["result"]["contents"]["value"].get<std::string>().find("→ untitled:g:2"),
            std::string::npos);
  auto sym = s.handle(request(3, "textDocument/documentSymbol", at));
  EXPECT_EQ(sym[0]["result"][0]["name"], "O0100");
  auto c = s.handle(request(4, "textDocument/completion", at));
  EXPECT_FALSE(c[0]["result"]["items"].empty());
  auto def = s.handle(request(5, "textDocument/definition", at));
  EXPECT_TRUE(def[0]["result"].is_null());
  auto unknown = s.handle(request(6, "textDocument/rename", at));
  EXPECT_EQ(unknown[0]["error"]["code"], -32601);
  auto closed = s.handle(request(
      7, "textDocument/hover",
      {{"textDocument", {{"uri", "untitled:b"}}}, {"position", {{"line", 0}, {"character", 0}}}}));
  EXPECT_EQ(closed[0]["error"]["code"], -32602);
  auto noPosition =
      s.handle(request(8, "textDocument/hover", {{"textDocument", {{"uri", "untitled:a"}}}}));
  EXPECT_TRUE(noPosition[0].contains("error"));
}

TEST(LspServer, ExitsWithZeroOnlyAfterShutdown) {
  Server a = makeServer();
  a.handle(request(1, "initialize"));
  auto r = a.handle(request(2, "shutdown"));
  EXPECT_TRUE(r[0].contains("result") && r[0]["result"].is_null());
  EXPECT_EQ(a.handle(request(3, "textDocument/hover"))[0]["error"]["code"], -32600);
  a.handle(notification("exit", json::object()));
  EXPECT_TRUE(a.exited());
  EXPECT_EQ(a.exitCode(), 0);
  Server b = makeServer();
  b.handle(notification("exit", json::object()));
  EXPECT_TRUE(b.exited());
  EXPECT_EQ(b.exitCode(), 1);
}

TEST(LspServer, ADocumentWithoutSetupOptionsUsesTheSetupBesideIt) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "ncvm-lsp-setup-beside";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "part.toml") << "[machine]\nkind = \"lathe\"\n";
  std::ofstream(dir / "broken.toml") << "[machine\n";
  Server s = makeServer();
  s.handle(request(1, "initialize"));
  const auto hoverAt = [&](const std::string& file, int id) {
    const std::string uri = pathToUri((dir / file).string());
    s.handle(notification("textDocument/didOpen",
                          {{"textDocument", {{"uri", uri}, {"version", 1}, {"text", "#2001\n"}}}}));
    return s.handle(request(
        id, "textDocument/hover",
        {{"textDocument", {{"uri", uri}}}, {"position", {{"line", 0}, {"character", 1}}}}))[0];
  };
  EXPECT_NE(hoverAt("part.nc", 2)["result"]["contents"]["value"].get<std::string>().find("X wear"),
            std::string::npos);  // part.toml: a lathe
  EXPECT_NE(hoverAt("other.nc", 3)["result"]["contents"]["value"].get<std::string>().find("H"),
            std::string::npos);  // no setup beside it: the server's mill
  const auto broken = hoverAt("broken.nc", 4);
  EXPECT_NE(broken["error"]["message"].get<std::string>().find("broken.toml"), std::string::npos);
  const auto diags = s.publishDue();
  bool reported = false;
  for (const auto& d : diags)
    if (d["params"]["uri"] == pathToUri((dir / "broken.nc").string()))
      reported = d["params"]["diagnostics"][0]["message"].get<std::string>().find("setup error") !=
                 std::string::npos;
  EXPECT_TRUE(reported);
  fs::remove_all(dir);
}
