// Setups in layers (server/setup_layers.hpp): a run request's "setups" applied in order as
// `--setup` given more than once, the tab's setup in its place, files only from the presets
// and the server's folders, errors naming the layer.
#include "server/setup_layers.hpp"

#include <gtest/gtest.h>

#include <string>

#include "app/session.hpp"
#include "server/request_checks.hpp"
#include "server/run_job.hpp"
#include "server/web_server.hpp"

using namespace ncvm;
using namespace ncvm::server;
using nlohmann::json;

namespace {

const std::string kSource = NCVM_SOURCE_DIR;

ServerConfig config() {
  ServerConfig c;
  c.catalog.add("examples", kSource + "/examples");
  c.presetsDir = kSource + "/presets";
  return c;
}

// The run of a request as the server and its worker make it.
json serverRun(const json& body) {
  RunRequest r = runRequestFromBody(body.dump(), config());
  EXPECT_EQ(r.status, 200) << r.error;
  return runJob(r.job);
}

// The same program on the command line's path: --setup FILE for each file, in order.
json cliRun(const std::string& program, const std::vector<std::string>& setups, bool stock) {
  Setup s = defaultSetup();
  for (const auto& f : setups) loadSetupInto(s, kSource + "/" + f);
  Session session(s);
  session.addProgramFile(kSource + "/" + program);
  session.addBundledMacros();
  if (stock) session.simulateStock("");
  return session.run(nullptr).state;
}

const char* kFace = "face-milling-g42/face-milling-g42.nc";

}  // namespace

TEST(SetupLayers, APresetUnderTheProgramsOwnSetupAsTheCommandLine) {
  // By path, the program's own setup (face-milling-g42.toml) is the tab's layer, last.
  json layered = serverRun({{"root", "examples"},
                            {"path", kFace},
                            {"setups", {{{"root", "presets"}, {"path", "fanuc-0i-mf.toml"}}}}});
  ASSERT_TRUE(layered["ok"].get<bool>()) << layered.dump();
  json cli =
      cliRun(std::string("examples/") + kFace,
             {"presets/fanuc-0i-mf.toml", "examples/face-milling-g42/face-milling-g42.toml"}, true);
  EXPECT_DOUBLE_EQ(layered["state"]["cycle_time"].get<double>(), cli["cycle_time"].get<double>());
  // The preset's dynamic time model is what changed it.
  json own = serverRun({{"root", "examples"}, {"path", kFace}});
  EXPECT_NE(own["state"]["cycle_time"].get<double>(), layered["state"]["cycle_time"].get<double>());
}

TEST(SetupLayers, LaterLayersOverrideEarlierOnes) {
  // The tab's text puts X rapids at 1 m/min; before the preset, the preset's 36 m/min wins.
  const json program = {{"program", "O1\nG21 G90 G00 X500. Y0\nM30\n"}, {"name", "p.nc"}};
  json body = program;
  body["setup"] = "[axes.X]\nrapid = 1000\n";
  const json preset = {{"root", "presets"}, {"path", "fanuc-0i-mf.toml"}};
  body["setups"] = {preset, {{"tab", true}}};
  json slow = serverRun(body);
  body["setups"] = {{{"tab", true}}, preset};
  json fast = serverRun(body);
  ASSERT_TRUE(slow["ok"].get<bool>()) << slow.dump();
  ASSERT_TRUE(fast["ok"].get<bool>()) << fast.dump();
  EXPECT_GT(slow["state"]["cycle_time"].get<double>(), 29.0);  // 500 mm at 1000 mm/min
  EXPECT_LT(fast["state"]["cycle_time"].get<double>(), 2.0);
}

TEST(SetupLayers, AJobFileAfterTheFoldersSetupAddsTheStock) {
  // As examples/lathe-cycles/stock-o0402.toml says: --setup setup.toml --setup stock-o0402.toml.
  const std::string prog = "lathe-cycles/g71-g70-rough-turning.nc";
  json layered = serverRun(
      {{"root", "examples"},
       {"path", prog},
       {"setups",
        {{{"tab", true}}, {{"root", "examples"}, {"path", "lathe-cycles/stock-o0402.toml"}}}}});
  ASSERT_TRUE(layered["ok"].get<bool>()) << layered.dump();
  ASSERT_TRUE(layered.contains("stock"));
  json cli =
      cliRun("examples/" + prog,
             {"examples/lathe-cycles/setup.toml", "examples/lathe-cycles/stock-o0402.toml"}, true);
  EXPECT_EQ(layered["state"]["stock"], cli["stock"]);
  EXPECT_FALSE(serverRun({{"root", "examples"}, {"path", prog}}).contains("stock"));
}

TEST(SetupLayers, OnlySetupFilesOfTheServersFolders) {
  const ServerConfig cf = config();
  for (const json& layer :
       {json{{"root", "presets"}, {"path", "../examples/lathe-cycles/setup.toml"}},
        json{{"root", "nowhere"}, {"path", "setup.toml"}},
        json{{"root", "examples"}, {"path", "lathe-cycles/g90-taper.nc"}},
        json{{"root", "presets"}, {"path", "/etc/passwd"}}, json("setup.toml")}) {
    RunRequest r =
        runRequestFromBody(json{{"program", "O1\nM30\n"}, {"setups", {layer}}}.dump(), cf);
    EXPECT_EQ(r.status, 400) << layer.dump();
  }
  json files = setupFiles(cf);
  EXPECT_NE(std::find(files["presets"].begin(), files["presets"].end(), "fanuc-0i-mf.toml"),
            files["presets"].end());
  const json& ex = files["roots"][0]["files"];
  EXPECT_NE(std::find(ex.begin(), ex.end(), "lathe-cycles/stock-o0402.toml"), ex.end());
}

TEST(SetupLayers, AnErrorNamesItsLayerNotATemporaryFile) {
  json r = serverRun({{"program", "O1\nM30\n"},
                      {"setup", "[machine]\nkind = \"mill\"\nbogus_key = 1\n"},
                      {"setup_name", "job.toml"},
                      {"setups", {{{"root", "presets"}, {"path", "fanuc-0i-mf.toml"}}}}});
  ASSERT_FALSE(r["ok"].get<bool>());
  const std::string error = r["error"];
  EXPECT_NE(error.find("job.toml"), std::string::npos) << error;
  EXPECT_EQ(error.find("ncvm-setup-"), std::string::npos) << error;
}
