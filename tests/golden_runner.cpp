// Runs every tests/golden/**/<name>.expect as one GoogleTest case (format:
// tests/golden/README.md). The trace is produced by the real JSONL writer and parsed back,
// so these tests also pin the trace format.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "app/session.hpp"
#include "machine/setup.hpp"
#include "report/trace_writer.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

struct GoldenCase {
  fs::path expect;
  std::string name;
  bool checkMode = false;  // `mode: check`: nothing runs, so there is no streamed run to compare
};

// ctest and gtest name a case by its file, not by a hex dump of the struct.
void PrintTo(const GoldenCase& c, std::ostream* os) {
  *os << c.name;
}

bool isCheckMode(const fs::path& expect) {
  std::ifstream in(expect);
  for (std::string line; std::getline(in, line);) {
    auto b = line.find_first_not_of(" \t");
    if (b == std::string::npos || line.compare(b, 5, "mode:") != 0) continue;
    auto v = line.find_first_not_of(" \t", b + 5);
    if (v != std::string::npos && line.compare(v, 5, "check") == 0) return true;
  }
  return false;
}

std::vector<GoldenCase> findCases() {
  std::vector<GoldenCase> out;
  fs::path root = fs::path(NCVM_TEST_DATA) / "golden";
  for (const auto& e : fs::recursive_directory_iterator(root)) {
    if (e.path().extension() != ".expect") continue;
    std::string rel = fs::relative(e.path(), root).replace_extension().string();
    std::string name;
    for (char c : rel) name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
    out.push_back({e.path(), name, isCheckMode(e.path())});
  }
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
  return out;
}

std::string trim(std::string s) {
  size_t b = s.find_first_not_of(" \t\r");
  size_t e = s.find_last_not_of(" \t\r");
  return b == std::string::npos ? "" : s.substr(b, e - b + 1);
}

// "value ~tol" -> (json value, tolerance)
std::pair<json, double> parseValue(const std::string& text) {
  double tol = 1e-9;
  std::string v = text;
  // A '~' outside a string sets the tolerance.
  bool inString = false;
  for (size_t k = 0; k < text.size(); ++k) {
    if (text[k] == '"') inString = !inString;
    if (text[k] == '~' && !inString) {
      v = trim(text.substr(0, k));
      tol = std::stod(text.substr(k + 1));
      break;
    }
  }
  return {json::parse(v), tol};
}

// Walks "a.b[2].c" through a JSON value; a missing step gives null.
json walk(const json& root, const std::string& path) {
  const json* cur = &root;
  size_t i = 0;
  static const json null = nullptr;
  while (i < path.size()) {
    if (path[i] == '.') {
      ++i;
      continue;
    }
    if (path[i] == '[') {
      size_t close = path.find(']', i);
      size_t idx = std::stoul(path.substr(i + 1, close - i - 1));
      if (!cur->is_array() || idx >= cur->size()) return null;
      cur = &(*cur)[idx];
      i = close + 1;
      continue;
    }
    size_t stop = path.find_first_of(".[", i);
    std::string key = path.substr(i, stop == std::string::npos ? std::string::npos : stop - i);
    if (!cur->is_object() || !cur->contains(key)) return null;
    cur = &(*cur)[key];
    i = stop == std::string::npos ? path.size() : stop;
  }
  return *cur;
}

bool near(const json& got, const json& want, double tol, std::string& why) {
  if (want.is_number()) {
    if (!got.is_number()) {
      why = "not a number";
      return false;
    }
    double d = std::fabs(got.get<double>() - want.get<double>());
    if (d > tol) {
      why = "differs by " + std::to_string(d);
      return false;
    }
    return true;
  }
  if (want.is_array()) {
    if (!got.is_array() || got.size() < want.size()) {
      why = "array size";
      return false;
    }
    for (size_t k = 0; k < want.size(); ++k)
      if (!near(got[k], want[k], tol, why)) {
        why = "element " + std::to_string(k) + ": " + why;
        return false;
      }
    return true;
  }
  if (got != want) {
    why = "differs";
    return false;
  }
  return true;
}

std::string readFile(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// A case's session as `ncvm run` would load it: the setup (the case's .toml, else the
// default) with the case's set: lines, the program, every other program in its folder (as --lib
// would add them), its .lib folder and the bundled macros; a [stock] is simulated (its
// analysis is state.stock, no files written). `stream` streams the main program in pieces of
// 61 bytes whatever its size.
std::unique_ptr<ncvm::Session> caseSession(const fs::path& program, const fs::path& setupFile,
                                           const fs::path& lib,
                                           const std::vector<std::string>& sets,
                                           bool stream = false) {
  ncvm::Setup setup =
      fs::exists(setupFile) ? ncvm::loadSetup(setupFile.string()) : ncvm::defaultSetup();
  for (const auto& s : sets) ncvm::applySetting(setup, s);
  auto session = std::make_unique<ncvm::Session>(setup);
  if (stream) session->streamMainProgram({0, 61});
  session->addProgramFile(program.string());
  std::vector<fs::path> others;
  for (const auto& e : fs::directory_iterator(program.parent_path()))
    if (e.path().extension() == ".nc" && e.path() != program) others.push_back(e.path());
  std::sort(others.begin(), others.end());
  for (const auto& o : others) session->store().addFile(o.string());
  if (fs::is_directory(lib)) session->addLibrary(lib.string());
  session->addBundledMacros();
  if (session->setup().stock.present) session->simulateStock("");
  return session;
}

class Golden : public ::testing::TestWithParam<GoldenCase> {};

TEST_P(Golden, Run) {
  const GoldenCase& c = GetParam();
  fs::path program = fs::path(c.expect).replace_extension(".nc");
  fs::path setupFile = fs::path(c.expect).replace_extension(".toml");
  fs::path lib = fs::path(c.expect).replace_extension(".lib");
  ASSERT_TRUE(fs::exists(program)) << program;

  std::vector<std::pair<int, std::string>> lines;
  std::string mode = "run";
  std::vector<std::string> sets;
  {
    std::istringstream in(readFile(c.expect));
    std::string line;
    int no = 0;
    while (std::getline(in, line)) {
      ++no;
      line = trim(line);
      if (line.empty() || line[0] == '#') continue;
      if (line.rfind("mode:", 0) == 0)
        mode = trim(line.substr(5));
      else if (line.rfind("set:", 0) == 0)
        sets.push_back(trim(line.substr(4)));
      else
        lines.emplace_back(no, line);
    }
  }

  std::unique_ptr<ncvm::Session> owned = caseSession(program, setupFile, lib, sets);
  ncvm::Session& session = *owned;

  json state, check, trace = json::array();
  std::string printed;
  if (mode == "check") {
    check = session.check();
  } else {
    ncvm::TraceWriter writer(session.files(), nullptr, 1ull << 30, session.setup().reportedAxes());
    auto r = session.run(&writer);
    state = r.state;
    printed = r.printed;
    std::istringstream in(writer.buffer());
    std::string l;
    while (std::getline(in, l)) trace.push_back(json::parse(l));
  }

  for (const auto& [no, line] : lines) {
    SCOPED_TRACE(c.expect.string() + ":" + std::to_string(no) + ": " + line);
    size_t colon = line.find(": ");
    ASSERT_NE(colon, std::string::npos) << "expectation needs 'path: value'";
    std::string key = trim(line.substr(0, colon));
    std::string value = trim(line.substr(colon + 2));
    if (key == "end") {
      EXPECT_EQ(state["end"], value);
      continue;
    }
    if (key == "alarm") {
      if (value == "none") {
        EXPECT_TRUE(state["alarm"].is_null()) << state["alarm"].dump();
        continue;
      }
      std::istringstream v(value);
      std::string code, word;
      int atLine = -1;
      v >> code >> word >> atLine;
      ASSERT_FALSE(state["alarm"].is_null()) << "expected alarm " << code;
      EXPECT_EQ(state["alarm"]["code"], code) << state["alarm"].dump();
      if (atLine >= 0) {
        EXPECT_EQ(state["alarm"]["line"], atLine) << state["alarm"].dump();
      }
      continue;
    }
    if (key == "output") {
      EXPECT_EQ(printed, json::parse(value).get<std::string>());
      continue;
    }
    json got;
    if (key.rfind("state.", 0) == 0) {
      got = walk(state, key.substr(6));
    } else if (key.rfind("check.", 0) == 0) {
      got = walk(check, key.substr(6));
    } else if (key.rfind("count.", 0) == 0) {
      std::string type = key.substr(6);
      got = std::count_if(trace.begin(), trace.end(),
                          [&](const json& e) { return e["type"] == type; });
    } else if (key.rfind("trace", 0) == 0) {
      // trace[3].field or trace.<type>[i].field
      std::string rest = key.substr(5);
      if (!rest.empty() && rest[0] == '[') {
        got = walk(trace, rest);
      } else {
        size_t open = rest.find('[');
        std::string type = rest.substr(1, open - 1);
        json filtered = json::array();
        for (const auto& e : trace)
          if (e["type"] == type) filtered.push_back(e);
        got = walk(filtered, rest.substr(open));
      }
    } else {
      FAIL() << "unknown expectation key " << key;
    }
    auto [want, tol] = parseValue(value);
    std::string why;
    EXPECT_TRUE(near(got, want, tol, why))
        << "got " << got.dump() << ", want " << want.dump() << " (" << why << ")";
  }
}

// The same case with its main program streamed (program_stream.hpp: compiled in pieces of
// 61 bytes while it runs, whatever its size): the trace and the state must be the same bytes
// as the whole program's. Programs the stream scan refuses are compiled whole both times.
class GoldenStreamed : public ::testing::TestWithParam<GoldenCase> {};

std::vector<GoldenCase> runCases() {
  std::vector<GoldenCase> out;
  for (auto& c : findCases())
    if (!c.checkMode) out.push_back(std::move(c));
  return out;
}

TEST_P(GoldenStreamed, RunIsTheSame) {
  const GoldenCase& c = GetParam();
  fs::path program = fs::path(c.expect).replace_extension(".nc");
  fs::path setupFile = fs::path(c.expect).replace_extension(".toml");
  fs::path lib = fs::path(c.expect).replace_extension(".lib");
  std::vector<std::string> sets;
  {
    std::istringstream in(readFile(c.expect));
    std::string line;
    while (std::getline(in, line)) {
      line = trim(line);
      if (line.rfind("set:", 0) == 0) sets.push_back(trim(line.substr(4)));
    }
  }
  auto runOnce = [&](bool stream, bool& streamed) {
    std::unique_ptr<ncvm::Session> session = caseSession(program, setupFile, lib, sets, stream);
    streamed = session->main() && session->main()->stream;
    ncvm::TraceWriter writer(session->files(), nullptr, 1ull << 30,
                             session->setup().reportedAxes());
    auto r = session->run(&writer);
    return writer.buffer() + "\n" + r.state.dump(1) + "\n" + r.printed;
  };
  bool streamed = false, unused = false;
  const std::string whole = runOnce(false, unused);
  const std::string piecewise = runOnce(true, streamed);
  if (std::getenv("NCVM_SHOW_STREAMED") && streamed) std::printf("streamed: %s\n", c.name.c_str());
  EXPECT_EQ(whole, piecewise) << (streamed ? "streamed" : "not streamed");
}

INSTANTIATE_TEST_SUITE_P(All, Golden, ::testing::ValuesIn(findCases()),
                         [](const ::testing::TestParamInfo<GoldenCase>& i) {
                           return i.param.name;
                         });
INSTANTIATE_TEST_SUITE_P(All, GoldenStreamed, ::testing::ValuesIn(runCases()),
                         [](const ::testing::TestParamInfo<GoldenCase>& i) {
                           return i.param.name;
                         });

}  // namespace
