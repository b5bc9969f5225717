#include "app/session.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>

#include "app/machine_state.hpp"
#include "exec/gcode_table.hpp"
#include "sim/stock_model.hpp"
#include "sim/stock_probe.hpp"
#include "timing/timing_stage.hpp"

#ifndef NCVM_SOURCE_MACROS
#define NCVM_SOURCE_MACROS ""
#endif

namespace ncvm {

std::string bundledMacrosFolder() {
  namespace fs = std::filesystem;
  if (const char* env = std::getenv("NCVM_MACROS"); env && *env) return env;
  std::error_code ec;
  fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    fs::path installed = exe.parent_path() / ".." / "share" / "ncvm" / "macros";
    if (fs::is_directory(installed, ec)) return installed.string();
  }
  if (fs::is_directory(NCVM_SOURCE_MACROS, ec)) return NCVM_SOURCE_MACROS;
  return {};
}

static ParseOptions parseOptionsFor(const Setup& s) {
  ParseOptions o;
  o.maxLineLength = s.limits.maxLineLength;
  o.eightDigitO = s.programNumberDigits == 8;
  o.hIsAxis = s.kind == MachineKind::Lathe && s.axes[5].present;
  o.blockSkip = s.blockSkip;
  for (size_t k = 0; k < 10; ++k) {
    o.callG[k] = static_cast<int>(s.param(std::to_string(6050 + k), 0));
    o.callM[k] = static_cast<int>(s.param(std::to_string(6080 + k), 0));
  }
  return o;
}

Session::Session(Setup setup)
    : setup_(std::move(setup)),
      store_(files_, parseOptionsFor(setup_), setup_.limits.maxFileBytes) {}

void Session::addProgramFile(const std::string& path) {
  ownFiles_.push_back(path);
  auto progs = store_.addFile(path, !main_ && stream_ ? &*stream_ : nullptr);
  if (!main_ && !progs.empty()) main_ = progs.front();
  ownPrograms_.insert(ownPrograms_.end(), progs.begin(), progs.end());
}

void Session::addProgramText(std::string_view text, const std::string& name) {
  auto progs = store_.addText(text, name);
  if (!main_ && !progs.empty()) main_ = progs.front();
  ownPrograms_.insert(ownPrograms_.end(), progs.begin(), progs.end());
}

void Session::addLibrary(const std::string& dir, std::string_view except) {
  store_.addFolder(dir, except);
}

void Session::addBundledMacros() {
  std::string dir = bundledMacrosFolder();
  if (!dir.empty()) store_.addFolder(dir);
}

nlohmann::json alarmJson(const Alarm& a, const SourceFiles& files) {
  return nlohmann::json{{"code", a.code},
                        {"text", a.text},
                        {"file", files.name(a.loc.file)},
                        {"line", a.loc.line},
                        {"col", a.loc.col},
                        {"n", a.n ? nlohmann::json(*a.n) : nlohmann::json(nullptr)}};
}

namespace {
nlohmann::json axesJson(const AxisArray& a, int n) {
  nlohmann::json j = nlohmann::json::array();
  for (int k = 0; k < n; ++k) j.push_back(a[static_cast<size_t>(k)]);
  return j;
}
}  // namespace

nlohmann::json modalJson(const ModalState& m, const Setup& setup) {
  nlohmann::json modal = nlohmann::json::object();
  // The groups a series has, found once per series: the web viewer asks after every event
  // that changes the modal state.
  static const auto groupsOf = [] {
    std::array<std::array<bool, kGroups>, 8> known{};
    for (const auto& info : gcodeTable())
      for (int s = 0; s < 8; ++s)
        if ((info.seriesMask & (1u << s)) && info.group > 0 && info.group < kGroups)
          known[static_cast<size_t>(s)][static_cast<size_t>(info.group)] = true;
    return known;
  }();
  const unsigned bit = seriesBit(setup.series());
  for (int g = 1; g < kGroups; ++g) {
    bool known = false;
    for (int s = 0; s < 8; ++s)
      known |= (bit & (1u << s)) && groupsOf[static_cast<size_t>(s)][static_cast<size_t>(g)];
    if (known) modal[std::to_string(g)] = m.g[static_cast<size_t>(g)] / 10.0;
  }
  modal["F"] = m.feed;
  modal["S"] = m.speed;
  modal["T"] = m.tool;
  modal["D"] = m.dOffset;
  modal["H"] = m.hOffset;
  modal["units"] = m.unit == InputUnit::Inch ? "inch" : "mm";
  return modal;
}

Session::Result Session::run(EventSink* sink, const nlohmann::json* machineState) {
  Result r;
  std::optional<Alarm> late;
  if (!main_) {
    std::string names;
    for (const auto& f : ownFiles_) names += (names.empty() ? "" : ", ") + f;
    throw std::runtime_error(names.empty()
                                 ? std::string("no program to run")
                                 : "no program to run: " + names + " holds no program text");
  }
  EventSink none;
  for (const auto& [n, v] : setup_.initialVars)
    if (n >= 200 && n <= 499 && !setup_.commonVars200)
      throw SetupError(fmt::format("vars.#{}: #200-#499 need options.common_vars_200 = true", n),
                       "vars");
  // The stock model listens beside the caller's sink; it is built first so a setup it
  // cannot simulate stops the job before anything runs. probe.use_stock simulates the
  // stock even without simulateStock (then nothing is written).
  if (setup_.probe.useStock && !setup_.stock.present)
    throw SetupError("probe.use_stock: G31 against the stock needs a [stock] section",
                     "probe.use_stock");
  std::unique_ptr<StockModel> stock =
      stockOn_ || setup_.probe.useStock ? makeStockModel(setup_) : nullptr;
  if (setup_.probe.useStock && !stock->probeWorld())
    throw SetupError("probe.use_stock: this stock model cannot be probed", "probe.use_stock");
  // The time model sits between the control and the caller's sinks.
  std::unique_ptr<TimingStage> stage;
  // Without a sink the stage keeps no events, only what the time report needs. It runs on
  // the control's thread (a worker thread beside the control did not pay: docs/performance.md,
  // "The time stage's worker thread, removed").
  if (timing_) stage = std::make_unique<TimingStage>(setup_, sink);
  if (stage) {
    // Each file's line table is allocated once, at the file's size, when its first line runs.
    std::vector<uint32_t> lines;
    for (const Program& p : store_.programs()) {
      if (p.blocks.empty()) continue;
      const SourceLoc& last = p.blocks.back().loc;
      if (last.file >= lines.size()) lines.resize(last.file + 1);
      // A streamed program holds one piece: its file's line count stands for its last block.
      const uint32_t lastLine = p.stream ? p.stream->lineBound() : last.line;
      lines[last.file] = std::max(lines[last.file], lastLine);
    }
    stage->setLineCounts(std::move(lines));
  }
  EventSink* first = stage ? static_cast<EventSink*>(stage.get()) : sink ? sink : &none;
  // The stock takes every event straight from the control, before the stage's look-ahead
  // holds cutting moves back: when a G31 asks the stock, every earlier move is in it. It
  // needs no modelled times.
  FanoutSink both;
  // Before the stock takes a move, the watcher sees the stock of the moves before it.
  struct StockWatch final : EventSink {
    StockModel* model = nullptr;
    const std::function<void(StockModel&, uint64_t)>* watch = nullptr;
    uint64_t moves = 0;
    void onMove(const MoveEvent&) override { (*watch)(*model, moves++); }
  } watch;
  if (stock && stockWatch_) {
    watch.model = stock.get();
    watch.watch = &stockWatch_;
    both.add(&watch);
  }
  if (stock) {
    both.add(stock.get());
    both.add(first);
    first = &both;
  }
  store_.rewindStreams();  // a streamed main program starts at its first piece again
  Executor exec(setup_, store_, *first);
  std::unique_ptr<StockProbe> stockProbe;
  if (setup_.probe.useStock) {
    const double unitsPerMm = setup_.initialUnit == InputUnit::Inch ? 1 / 25.4 : 1.0;
    stockProbe = std::make_unique<StockProbe>(*stock->probeWorld(), unitsPerMm,
                                              [&exec] { return exec.workOriginMm(); });
    exec.setStockProbe(stockProbe.get());
  }
  if (machineState) {
    MachineMemory mem = exec.memory();
    memoryFromJson(*machineState, setup_, mem);
    exec.memory() = mem;
    exec.restartFromMemory();
  }
  if (inspector_) inspector_(exec);
  r.end = exec.run(*main_);
  if (stage) {
    try {
      stage->finish();
    } catch (const AlarmError& e) {
      // A sink refused the moves the stage still held (the trace size limit).
      if (!exec.alarm()) {
        Alarm a;
        a.code = e.code();
        a.text = e.text();
        late = a;
        r.end = EndReason::Limit;
      }
    }
    r.timing = std::make_shared<TimeReport>(stage->takeReport());
  }
  r.machineState = memoryToJson(exec.memory(), setup_);
  r.alarm = late ? late : exec.alarm();
  r.stats = exec.stats();
  r.warnings = exec.warnings();
  r.printed = exec.printed();

  nlohmann::json& s = r.state;
  s["end"] = endReasonName(r.end);
  s["alarm"] = r.alarm ? alarmJson(*r.alarm, files_) : nlohmann::json(nullptr);
  s["program"] = main_->label;
  int axes = setup_.reportedAxes();
  s["position"] = {{"work", axesJson(exec.workPosition(), axes)},
                   {"machine", axesJson(exec.machinePosition(), axes)}};
  s["modal"] = modalJson(exec.modal(), setup_);
  nlohmann::json vars = nlohmann::json::object();
  for (const auto& [n, v] : exec.userVariables()) vars["#" + std::to_string(n)] = v;
  s["vars"] = vars;
  // The interface signal outputs as the program left them (what the PMC last got).
  nlohmann::json outputs = nlohmann::json::object();
  for (int k = 0; k < 32; ++k)
    if ((exec.signalOutputs(0) >> k) & 1u) outputs["#" + std::to_string(1100 + k)] = 1;
  outputs["#1132"] = exec.signalOutputs(0);
  outputs["#1133"] = exec.signalOutputs(1);
  s["signals"] = outputs;
  s["work_offsets"] = workOffsetsJson(exec.memory(), setup_, true);
  s["tool_offsets"] = toolOffsetsJson(exec.memory(), setup_);
  // cycle_time is the modelled time ([timing] model = "dynamic") or length / feed.
  s["cycle_time"] = r.timing ? r.timing->total().model : r.stats.time;
  s["cycle_time_simple"] = r.stats.time;
  if (r.timing) {
    // The time report's lines keep no origin: the top blocks' program and N come from the
    // block on the line.
    auto lineOrigin = [this](uint32_t file, uint32_t line, const std::string*& program,
                             int32_t& n) {
      for (const Program& p : store_.programs()) {
        if (p.stream) {  // only its last piece is compiled: the N comes from the file
          if (p.blocks.empty() || p.blocks.front().loc.file != file ||
              line < p.stream->firstLine() || line > p.stream->lineBound())
            continue;
          program = &p.label;
          n = p.stream->sequenceAt(line);
          return;
        }
        if (p.blocks.empty() || p.blocks.front().loc.file != file ||
            line < p.blocks.front().loc.line || line > p.blocks.back().loc.line)
          continue;
        auto b = std::lower_bound(p.blocks.begin(), p.blocks.end(), line,
                                  [](const Block& x, uint32_t l) { return x.loc.line < l; });
        if (b != p.blocks.end() && b->loc.line == line) {
          program = &p.label;
          n = b->n;
          return;
        }
      }
    };
    s["timing"] = r.timing->toJson(files_, setup_.timing.dynamic, 10, lineOrigin);
  }
  s["blocks"] = r.stats.blocks;
  s["moves"] = r.stats.moves;
  s["path_length"] = {{"rapid", r.stats.rapidLength}, {"feed", r.stats.feedLength}};
  nlohmann::json warns = nlohmann::json::array();
  for (const auto& w : r.warnings)
    warns.push_back({{"code", w.code},
                     {"text", w.text},
                     {"file", files_.name(w.loc.file)},
                     {"line", w.loc.line}});
  s["warnings"] = warns;
  if (stock) {
    r.stock = stock->finish(stockOut_);
    s["stock"] = r.stock;
    if (viewerGrid_ > 0) r.viewerStock = stock->viewerStock(viewerGrid_);
  }
  return r;
}

namespace {
// A G73 block of the lathe's pattern-repeating cycle: P and Q (the contour's sequence
// numbers), or U/W (the escape) without a Z; a mill's peck-drilling G73 has a Z.
bool latheForm(const Word* w, uint32_t n) {
  bool p = false, q = false, uw = false, z = false;
  for (uint32_t k = 0; k < n; ++k) {
    p |= w[k].letter == 'P';
    q |= w[k].letter == 'Q';
    uw |= w[k].letter == 'U' || w[k].letter == 'W';
    z |= w[k].letter == 'Z';
  }
  return (p && q) || (uw && !z);
}
}  // namespace

nlohmann::json Session::check() const {
  struct Finding {
    bool alarm;
    Alarm a;
  };
  std::vector<Finding> found;
  bool dpi = setup_.dpi();
  for (const Program* p : ownPrograms_) {
    for (const auto& a : p->errors) found.push_back({true, a});
    // DO/END and literal GOTO errors are alarms only if the block runs (a Renishaw macro may
    // hold a branch to an N it never takes): warnings here, under the alarm's code.
    for (Alarm a : p->structural) {
      a.text += a.code == alarmCode(AlarmId::MissingEnd)
                    ? ": an alarm when the WHILE is false (the control then looks for the END)"
                    : ": an alarm when this block runs";
      found.push_back({false, std::move(a)});
    }
    for (const Block& b : p->blocks) {
      if (b.kind != BlockKind::Nc) continue;
      const Word* w = p->words.data() + b.firstWord;
      bool macroCall = false, latheCycle = false;
      bool subCall = false;  // M98: its Q is a sequence number
      for (uint32_t k = 0; k < b.nWords; ++k) {
        subCall |= w[k].letter == 'M' && w[k].kind == WordKind::Literal && w[k].value == 98;
        if (w[k].letter != 'G' || w[k].kind != WordKind::Literal) continue;
        // A G word far out of range (G314445000) is the run's alarm, not a cast to overflow here.
        if (!(w[k].value >= 0 && w[k].value < 1000)) continue;
        int g = static_cast<int>(w[k].value * 10 + 0.5);
        macroCall |= g == 650 || g == 660;
        // Lathe multiple repetitive cycles take P/Q sequence numbers, R pass counts and
        // P/Q/R in least increments by design (G74-G76): no decimal-point warning there.
        latheCycle |= setup_.kind == MachineKind::Lathe && g >= 700 && g <= 780;
        // A lathe program checked with a mill setup: G70-G72 are no mill codes (the run
        // raises PS0010), and a G73 in the lathe form (P and Q, or U/W without Z) is the
        // pattern-repeating cycle, not peck drilling (whose Q and R are lengths).
        latheCycle |= g == 700 || g == 710 || g == 720 || (g == 730 && latheForm(w, b.nWords));
      }
      uint32_t seen = 0;
      for (uint32_t k = 0; k < b.nWords; ++k) {
        const Word& wd = w[k];
        if (wd.letter < 'A' || wd.letter > 'Z') continue;
        uint32_t bit = 1u << (wd.letter - 'A');
        if ((seen & bit) && wd.letter != 'G' && wd.letter != 'M' && !macroCall) {
          Alarm a{"W002",
                  fmt::format("{} given twice in one block: the last one counts", wd.letter),
                  SourceLoc{b.loc.file, b.loc.line, wd.col}, std::nullopt, p->number};
          found.push_back({false, a});
        }
        seen |= bit;
        bool lengthAddress =
            std::string_view("XYZUVWIJKRQABC").find(wd.letter) != std::string_view::npos;
        if (latheCycle && (wd.letter == 'Q' || wd.letter == 'P' || wd.letter == 'R'))
          lengthAddress = false;
        if (subCall && wd.letter == 'Q') lengthAddress = false;
        if (!dpi && lengthAddress && wd.kind == WordKind::Literal && !(wd.flags & kHasPoint) &&
            wd.value != 0) {
          // Divided, not multiplied, by the increments per unit: 3 / 10000 prints as 0.0003,
          // 3 * 0.0001 as 0.00030000000000000003 (fmt prints the shortest exact form).
          const double perMm = setup_.increment == IncrementSystem::IsA   ? 100
                               : setup_.increment == IncrementSystem::IsC ? 10000
                                                                          : 1000;
          Alarm a{"W001",
                  fmt::format("{}{} has no decimal point: it means {} least increments ({} mm or "
                              "{} in), not {}",
                              wd.letter, wd.value, wd.value, wd.value / perMm,
                              wd.value / (perMm * 10), wd.value),
                  SourceLoc{b.loc.file, b.loc.line, wd.col}, std::nullopt, p->number};
          found.push_back({false, a});
        }
      }
    }
  }
  std::stable_sort(found.begin(), found.end(), [](const Finding& x, const Finding& y) {
    if (x.a.loc.file != y.a.loc.file) return x.a.loc.file < y.a.loc.file;
    if (x.a.loc.line != y.a.loc.line) return x.a.loc.line < y.a.loc.line;
    return x.a.loc.col < y.a.loc.col;
  });
  nlohmann::json out{{"alarms", nlohmann::json::array()}, {"warnings", nlohmann::json::array()}};
  for (const auto& f : found)
    out[f.alarm ? "alarms" : "warnings"].push_back(alarmJson(f.a, files_));
  return out;
}

}  // namespace ncvm
