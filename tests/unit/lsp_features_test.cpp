// The language server's features, each on a small document: diagnostics (check and the dry
// run), hover, go to definition, document symbols and completion.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>

#include "lsp/completion.hpp"
#include "lsp/definition.hpp"
#include "lsp/diagnostics.hpp"
#include "lsp/hover.hpp"
#include "lsp/symbols.hpp"

using namespace ncvm;
using namespace ncvm::lsp;
namespace fs = std::filesystem;

namespace {
// A folder of its own per test, removed afterwards.
struct TempFolder {
  fs::path dir;
  TempFolder() {
    dir = fs::temp_directory_path() /
          ("ncvm-lsp-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "-" +
           ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  ~TempFolder() { fs::remove_all(dir); }
  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(dir / name) << text;
    return (dir / name).string();
  }
};

ServerOptions noMacros() {
  ServerOptions o;
  o.noMacros = true;
  return o;
}

std::string hoverText(const Setup& s, const Document& d, int line, int character) {
  const auto h = hover(s, d, line, character);
  return h.is_null() ? "" : h["contents"]["value"].get<std::string>();
}
}  // namespace

TEST(LspDiagnostics, ReportsCheckWarningsAndTheDryRunsAlarmAtTheirWords) {
  DocumentStore docs;
  Document& d = docs.open("untitled:a", "O0100\nG00 X10 Y0.\nG01 X5. F0\nM30\n", 1);
  const auto diags = diagnose(defaultSetup(), noMacros(), docs, d);
  ASSERT_EQ(diags.size(), 2u) << diags.dump(1);
  EXPECT_EQ(diags[0]["code"], "W001");
  EXPECT_EQ(diags[0]["severity"], 2);
  EXPECT_EQ(diags[0]["source"], "ncvm check");
  EXPECT_EQ(diags[0]["range"]["start"], (nlohmann::json{{"line", 1}, {"character", 4}}));
  EXPECT_EQ(diags[0]["range"]["end"], (nlohmann::json{{"line", 1}, {"character", 7}}));
  EXPECT_EQ(diags[1]["code"], "PS0011");  // feed zero, found only by running
  EXPECT_EQ(diags[1]["severity"], 1);
  EXPECT_EQ(diags[1]["range"]["start"]["line"], 2);
}

TEST(LspDiagnostics, ASyntaxErrorIsReportedOnceThoughBothCheckAndRunFindIt) {
  DocumentStore docs;
  Document& d = docs.open("untitled:a", "O0100\nG01 X1. Y F10.\nM30\n", 1);
  const auto diags = diagnose(defaultSetup(), noMacros(), docs, d);
  ASSERT_EQ(diags.size(), 1u) << diags.dump(1);
  EXPECT_EQ(diags[0]["code"], "PS0005");
  EXPECT_EQ(diags[0]["source"], "ncvm check");
}

TEST(LspDiagnostics, TheDryRunOfAnEndlessLoopStopsAtTheBlockLimit) {
  DocumentStore docs;
  Document& d =
      docs.open("untitled:a", "O0100\nWHILE [1 EQ 1] DO1\n#100 = #100 + 1\nEND1\nM30\n", 1);
  ServerOptions o = noMacros();
  o.dryRunBlocks = 5000;
  const auto diags = diagnose(defaultSetup(), o, docs, d);
  ASSERT_EQ(diags.size(), 1u) << diags.dump(1);
  EXPECT_EQ(diags[0]["code"], "PS9001");
  EXPECT_EQ(diags[0]["severity"], 2);
  EXPECT_NE(diags[0]["message"].get<std::string>().find("5000 blocks"), std::string::npos);
}

TEST(LspDiagnostics, ASubprogramIsCheckedButNotRunOnItsOwn) {
  DocumentStore docs;
  // Run alone, the vacant #26 and the M99 restart would be an endless loop or a false alarm.
  Document& d =
      docs.open("untitled:a", "O9010\nIF [#26 EQ #0] GOTO 9\nG91 G01 Z-#26 F0\nN9 M99\n", 1);
  EXPECT_TRUE(diagnose(defaultSetup(), noMacros(), docs, d).empty());
  docs.change("untitled:a", "O9010\nG91 G01 Z10 F0\nM99\n", 2);
  const auto diags = diagnose(defaultSetup(), noMacros(), docs, d);
  ASSERT_EQ(diags.size(), 1u) << diags.dump(1);
  EXPECT_EQ(diags[0]["code"], "W001");  // check still looks at it
}

TEST(LspDiagnostics, AnAlarmInACalledProgramNamesItsFile) {
  TempFolder tmp;
  tmp.write("sub.nc", "O2000\nG01 X1. F0\nM99\n");
  DocumentStore docs;
  Document& d = docs.open(pathToUri((tmp.dir / "main.nc").string()), "O0100\nM98 P2000\nM30\n", 1);
  const auto diags = diagnose(defaultSetup(), noMacros(), docs, d);
  ASSERT_EQ(diags.size(), 1u) << diags.dump(1);
  EXPECT_EQ(diags[0]["code"], "PS0011");
  EXPECT_NE(diags[0]["message"].get<std::string>().find("sub.nc:2:"), std::string::npos);
}

TEST(LspHover, ExplainsGAndMCodesAddressesVariablesAndKeywords) {
  DocumentStore docs;
  Document& d = docs.open("untitled:a", "G01 X1. F100 M08\n#1=#5021+#3001\nIF[#1GT0]GOTO10\n", 1);
  const ncvm::Setup mill = defaultSetup();
  EXPECT_NE(hoverText(mill, d, 0, 1).find("G01: linear"), std::string::npos);
  EXPECT_NE(hoverText(mill, d, 0, 5).find("X axis"), std::string::npos);
  EXPECT_NE(hoverText(mill, d, 0, 9).find("feedrate"), std::string::npos);
  EXPECT_NE(hoverText(mill, d, 0, 14).find("M08: coolant on"), std::string::npos);
  EXPECT_NE(hoverText(mill, d, 1, 1).find("G65 argument A"), std::string::npos);
  EXPECT_EQ(hoverText(mill, d, 1, 5),
            "#5021: current position (machine coordinates) of axis 1 (X) · read-only");
  EXPECT_NE(hoverText(mill, d, 1, 11).find("millisecond timer"), std::string::npos);
  EXPECT_NE(hoverText(mill, d, 2, 6).find("greater than"), std::string::npos);
  EXPECT_NE(hoverText(mill, d, 2, 14).find("N10"), std::string::npos);
}

TEST(LspHover, FollowsTheMachineKindAndTheSetupsCodeCalls) {
  DocumentStore docs;
  Document& d = docs.open("untitled:a", "#2001 #5022 G71 G100\n", 1);
  ncvm::Setup lathe = defaultSetup(MachineKind::Lathe);
  EXPECT_NE(hoverText(lathe, d, 0, 2).find("X wear offset of offset 1"), std::string::npos);
  EXPECT_NE(hoverText(lathe, d, 0, 8).find("axis 2 (Z)"), std::string::npos);
  EXPECT_NE(hoverText(lathe, d, 0, 13).find("G71:"), std::string::npos);
  ncvm::Setup mill = defaultSetup();
  EXPECT_NE(hoverText(mill, d, 0, 2).find("tool length (H) wear of offset 1"), std::string::npos);
  EXPECT_NE(hoverText(mill, d, 0, 8).find("axis 2 (Y)"), std::string::npos);
  EXPECT_NE(hoverText(mill, d, 0, 13).find("not a G code"), std::string::npos);
  applySetting(mill, "6050=100");
  EXPECT_NE(hoverText(mill, d, 0, 18).find("calls macro O9010"), std::string::npos);
}

TEST(LspDefinition, GoesToCalledProgramsInOpenDocumentsTheFolderAndLibFolders) {
  TempFolder tmp;
  tmp.write("beside.nc", "%\n(A SUB)\nO2000\nM99\n%\n");
  fs::create_directories(tmp.dir / "lib");
  const std::string lib = tmp.write("lib/macro.nc", "O9010\nM99\n");
  DocumentStore docs;
  docs.open("untitled:other", "\nO3000 (OPEN)\nM99\n", 1);
  Document& d = docs.open(pathToUri((tmp.dir / "main.nc").string()),
                          "O0100\nM98 P2000\nG65 P3000 A1.\nG100 X1.\nM98 P4000\n", 1);
  ServerOptions o = noMacros();
  o.libs = {(tmp.dir / "lib").string()};
  ncvm::Setup s = defaultSetup();
  applySetting(s, "6050=100");
  auto at = definition(s, o, docs, d, 1, 6);
  ASSERT_FALSE(at.is_null());
  EXPECT_EQ(at["uri"], pathToUri((tmp.dir / "beside.nc").string()));
  EXPECT_EQ(at["range"]["start"]["line"], 2);
  at = definition(s, o, docs, d, 2, 6);
  EXPECT_EQ(at["uri"], "untitled:other");
  EXPECT_EQ(at["range"]["start"]["line"], 1);
  at = definition(s, o, docs, d, 3, 2);  // G100 calls O9010 (parameter 6050)
  EXPECT_EQ(at["uri"], pathToUri(lib));
  EXPECT_TRUE(definition(s, o, docs, d, 4, 6).is_null());           // no O4000 anywhere
  EXPECT_TRUE(definition(s, noMacros(), docs, d, 3, 2).is_null());  // without --lib
}

TEST(LspDefinition, GoesFromGotoToItsLabelInTheSameProgram) {
  DocumentStore docs;
  Document& d =
      docs.open("untitled:a", "O0100\nN10 #1=1\nGOTO 10\nM30\nO0200\nGOTO10\n/N10 M99\n", 1);
  const auto a = definition(defaultSetup(), noMacros(), docs, d, 2, 6);
  EXPECT_EQ(a["range"]["start"], (nlohmann::json{{"line", 1}, {"character", 0}}));
  const auto b = definition(defaultSetup(), noMacros(), docs, d, 5, 5);
  EXPECT_EQ(b["range"]["start"], (nlohmann::json{{"line", 6}, {"character", 1}}));
  EXPECT_EQ(calledProgram(30100, true, defaultSetup()), 100);  // M98 P3 0100: three times
  EXPECT_EQ(calledProgram(30100, false, defaultSetup()), 30100);
}

TEST(LspSymbols, ListsProgramsWithTheirLabels) {
  DocumentStore docs;
  Document& d = docs.open("untitled:a", "%\nO0100 (MAIN)\nN1 G00 X0.\nN2 M30\n%\n", 1);
  const auto syms = documentSymbols(defaultSetup(), noMacros(), docs, d);
  ASSERT_EQ(syms.size(), 1u) << syms.dump(1);
  EXPECT_EQ(syms[0]["name"], "O0100");
  EXPECT_EQ(syms[0]["detail"], "(MAIN)");
  EXPECT_EQ(syms[0]["range"]["start"]["line"], 1);
  EXPECT_EQ(syms[0]["range"]["end"]["line"], 3);
  ASSERT_EQ(syms[0]["children"].size(), 2u);
  EXPECT_EQ(syms[0]["children"][1]["name"], "N2");
  EXPECT_EQ(syms[0]["children"][1]["selectionRange"]["start"]["line"], 3);
}

TEST(LspSymbols, NamesAProgramByItsNameOrByTheFileWithoutAHeader) {
  DocumentStore docs;
  Document& named = docs.open("file:///tmp/pocket.nc", "<POCKET>\nN1 M99\n", 1);
  EXPECT_EQ(documentSymbols(defaultSetup(), noMacros(), docs, named)[0]["name"], "<POCKET>");
  Document& bare = docs.open("file:///tmp/bare.nc", "G00 X1.\nN5 M30\n", 1);
  const auto syms = documentSymbols(defaultSetup(), noMacros(), docs, bare);
  ASSERT_EQ(syms.size(), 1u);
  EXPECT_NE(syms[0]["name"].get<std::string>().front(), '<') << syms[0]["name"];
  EXPECT_EQ(syms[0]["children"][0]["name"], "N5");
}

TEST(LspCompletion, OffersTheSeriesGCodesAndTheSystemVariables) {
  DocumentStore docs;
  Document& d = docs.open("untitled:a", "G7\n#50\nX1.\n", 1);
  auto labels = [](const nlohmann::json& list) {
    std::set<std::string> out;
    for (const auto& i : list["items"]) out.insert(i["label"].get<std::string>());
    return out;
  };
  const auto lathe = labels(complete(defaultSetup(MachineKind::Lathe), d, 0, 2));
  const auto mill = labels(complete(defaultSetup(), d, 0, 2));
  EXPECT_TRUE(lathe.count("G71") && lathe.count("G76"));
  EXPECT_TRUE(mill.count("G43") && mill.count("G54.1"));
  EXPECT_FALSE(mill.count("G71"));  // a lathe cycle
  const auto vars = complete(defaultSetup(), d, 1, 3);
  const auto names = labels(vars);
  EXPECT_TRUE(names.count("#5021") && names.count("#5023") && names.count("#3001"));
  EXPECT_FALSE(names.count("#5024"));  // the default mill has three axes
  EXPECT_FALSE(names.count("#100"));   // a common variable, not a system one
  EXPECT_EQ(vars["items"][0]["textEdit"]["range"]["start"]["character"], 0);
  EXPECT_TRUE(complete(defaultSetup(), d, 2, 3)["items"].empty());
}
