// embed-ncvm: runs a program with ncvm's C++ API and prints what a caller typically wants:
// how it ended, the alarm, the warnings, the cycle time and the longest feed move.
//   embed-ncvm PROGRAM [SETUP.toml | PRESET | KEY=VALUE]...
// Exit status as `ncvm run`: 0 normal end, 3 alarm, 2 a usage or setup error.
#include <cstdio>
#include <ncvm/ncvm.hpp>
#include <string>

namespace {

// Counts the moves by kind and keeps the longest feed move, as the run reports them.
class MoveStats final : public ncvm::api::EventHandler {
 public:
  void onMove(const ncvm::api::Move& m) override {
    ++count;
    if (m.kind == ncvm::api::MoveKind::Rapid) return;
    ++feedMoves;
    if (m.length > longest) {
      longest = m.length;
      longestLine = m.at.line;
    }
  }
  void onTool(const ncvm::api::ToolSelect& t) override { tools += t.change ? 1 : 0; }
  int count = 0, feedMoves = 0, tools = 0;
  double longest = 0;
  unsigned longestLine = 0;
};

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s PROGRAM [SETUP.toml | PRESET | KEY=VALUE]...\n", argv[0]);
    return 2;
  }
  try {
    ncvm::api::Job job;
    // In order, as the command line's --setup and --set: later ones override.
    for (int k = 2; k < argc; ++k) {
      const std::string arg = argv[k];
      if (arg.find('=') != std::string::npos)
        job.set(arg);  // KEY=VALUE, e.g. DPI=1
      else if (arg.size() > 5 && arg.substr(arg.size() - 5) == ".toml")
        job.loadSetup(arg);
      else
        job.loadPreset(arg);  // e.g. fanuc-0i-mf, from PREFIX/share/ncvm/presets
    }
    job.addProgramFile(argv[1]);

    MoveStats stats;
    const ncvm::api::RunResult r = job.run(&stats);
    std::printf("ncvm %s: %s ended: %s\n", ncvm::api::version().c_str(), argv[1],
                ncvm::api::endReasonName(r.end).c_str());
    std::printf("  %llu blocks, %d moves (%d feed), %d tool changes, %.2f s (length/feed)\n",
                static_cast<unsigned long long>(r.stats.blocks), stats.count, stats.feedMoves,
                stats.tools, r.stats.simpleTime);
    if (stats.feedMoves)
      std::printf("  longest feed move: %.3f at line %u\n", stats.longest, stats.longestLine);
    for (const auto& w : r.warnings)
      std::printf("%s:%d:%d: %s %s\n", w.where.file.c_str(), w.where.line, w.where.column,
                  w.code.c_str(), w.message.c_str());
    if (r.alarm) {
      std::printf("%s:%d:%d: %s %s\n", r.alarm->where.file.c_str(), r.alarm->where.line,
                  r.alarm->where.column, r.alarm->code.c_str(), r.alarm->message.c_str());
      return 3;
    }
    return 0;
  } catch (const ncvm::api::Error& e) {
    std::fprintf(stderr, "embed-ncvm: %s\n", e.what());
    return 2;
  }
}
