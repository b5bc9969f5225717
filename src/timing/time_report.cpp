#include "timing/time_report.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ncvm {

const char* timeKindName(TimeKind k) {
  static const char* names[] = {"rapid", "cutting", "dwell", "auxiliary"};
  return names[static_cast<int>(k)];
}

OperationTime& TimeReport::op() {
  if (ops_.empty()) {
    ops_.emplace_back();
    ops_.back().tool = tool_;
    cur_ = 0;
  }
  return ops_[cur_];
}

// A place already seen: its operation goes on (true).
bool TimeReport::enterPlace(const PlaceKey& k) {
  auto it = places_.find(k);
  if (it == places_.end()) return false;
  // Entered again: another operation, or this one after it moved (the next pass of a loop;
  // its comment and then its tool change are one entry).
  if (it->second != cur_ || curMoved_) ++ops_[it->second].runs;
  cur_ = it->second;
  curMoved_ = false;
  return true;
}

void TimeReport::startOperation(int tool, const EventOrigin& at, const PlaceKey& k) {
  cur_ = ops_.size();
  OperationTime& o = ops_.emplace_back();
  o.tool = tool;
  o.first = at;
  curMoved_ = false;
  places_.emplace(k, static_cast<uint32_t>(cur_));
}

void TimeReport::toolSelected(int tool, const EventOrigin& at) {
  if (tool == tool_ && !ops_.empty()) return;
  tool_ = tool;
  PlaceKey key{at.file, at.line, tool};
  if (enterPlace(key)) return;
  // A new operation begins with each tool; an empty first one (nothing ran yet) is reused,
  // and so is one a comment just started (the CAM system's name, then its tool change): the
  // tool change's place then leads to it too.
  if (!ops_.empty()) {
    OperationTime& o = ops_[cur_];
    bool emptyStart = ops_.size() == 1 && !o.byComment && o.time.model == 0 && o.time.simple == 0 &&
                      places_.empty();
    if (emptyStart || (o.byComment && !curMoved_)) {
      o.tool = tool;
      if (!o.byComment) o.first = at;
      places_.emplace(key, static_cast<uint32_t>(cur_));
      return;
    }
  }
  startOperation(tool, at, key);
}

void TimeReport::commentSeen(std::string_view text, const EventOrigin& at) {
  size_t b = text.find_first_not_of(' '), e = text.find_last_not_of(' ');
  text = b == std::string_view::npos ? std::string_view{} : text.substr(b, e - b + 1);
  if (text.empty()) return;
  PlaceKey key{at.file, at.line, kCommentPlace};
  if (enterPlace(key)) return;
  // Until the operation has moved, further comments describe it (the tool, the stock...):
  // the first one names it.
  if (!ops_.empty() && !curMoved_) {
    OperationTime& o = ops_[cur_];
    if (o.label.empty()) {
      o.label = std::string(text);
      o.byComment = true;
      if (o.first.line == 0) o.first = at;
      places_.emplace(key, static_cast<uint32_t>(cur_));
    }
    return;
  }
  startOperation(tool_, at, key);
  ops_[cur_].label = std::string(text);
  ops_[cur_].byComment = true;
}

// Out of the per-move path: a file's table is allocated at the file's size, or grows by
// doubling, so this runs once or a few times per file.
void TimeReport::growLines(const EventOrigin& at) {
  if (at.file >= lines_.size()) lines_.resize(at.file + 1);
  LineTable& t = lines_[at.file];
  size_t size = std::max<size_t>(at.line + 1, t.count.size() * 2);
  if (t.count.empty() && at.file < lineCounts_.size() && lineCounts_[at.file] >= at.line)
    size = lineCounts_[at.file] + size_t{1};
  t.model.resize(size);
  if (!t.simple.empty()) t.simple.resize(size);
  t.count.resize(size);
}

// The first move whose simple time is not its model time splits the two columns: until
// then every simple sum was its model sum, bit for bit (called before the model column adds
// this move).
void TimeReport::addSimple(LineTable& t, uint32_t line, double simple) {
  if (t.simple.empty()) t.simple = t.model;
  t.simple[line] += simple;
}

void TimeReport::add(TimeKind kind, const EventOrigin& at, double model, double simple) {
  total_.add(model, simple);
  byKind_[static_cast<size_t>(kind)].add(model, simple);
  OperationTime& o = op();
  o.time.add(model, simple);
  o.byKind[static_cast<size_t>(kind)].add(model, simple);
  if (kind == TimeKind::Dwell) moved(o, 1);
  holes_.other(model, simple);
  addLine(at, model, simple);
}

void TimeReport::addMoveTime(MoveMode mode, const EventOrigin& at, double length, double model,
                             double simple) {
  bool rapid = mode == MoveMode::Rapid;
  TimeKind kind = rapid ? TimeKind::Rapid : TimeKind::Cutting;
  total_.add(model, simple);
  byKind_[static_cast<size_t>(kind)].add(model, simple);
  OperationTime& o = op();
  o.time.add(model, simple);
  o.byKind[static_cast<size_t>(kind)].add(model, simple);
  (rapid ? o.rapidLength : o.feedLength) += length;
  moved(o, 1);
  addLine(at, model, simple);
}

void TimeReport::addCutting(double model, double simple, double length, uint64_t moves) {
  constexpr auto kind = static_cast<size_t>(TimeKind::Cutting);
  total_.add(model, simple);
  byKind_[kind].add(model, simple);
  OperationTime& o = op();
  o.time.add(model, simple);
  o.byKind[kind].add(model, simple);
  o.feedLength += length;
  moved(o, moves);
}

std::vector<ToolTime> TimeReport::byTool() const {
  std::vector<ToolTime> out;
  for (const auto& o : ops_) {
    auto it =
        std::find_if(out.begin(), out.end(), [&](const ToolTime& t) { return t.tool == o.tool; });
    if (it == out.end())
      out.push_back(ToolTime{o.tool, o.time});
    else
      it->time.add(o.time.model, o.time.simple);
  }
  return out;
}

std::vector<LineTime> TimeReport::topLines(size_t n, const LineOrigin& origin) const {
  // One pass keeping the n best (n is small): no copy of every line.
  auto before = [](const LineTime& a, const LineTime& b) {
    if (a.time.model != b.time.model) return a.time.model > b.time.model;
    if (a.at.file != b.at.file) return a.at.file < b.at.file;
    return a.at.line < b.at.line;
  };
  std::vector<LineTime> best;
  if (n == 0) return best;
  // Most lines lose to the n-th best on time alone: no record built for them.
  double floor = -std::numeric_limits<double>::infinity();
  for (size_t f = 0; f < lines_.size(); ++f) {
    const LineTable& tab = lines_[f];
    const double* model = tab.model.data();
    const size_t size = tab.count.size();
    for (size_t ln = 0; ln < size; ++ln) {
      // Once the n best are known most lines lose on time alone: four at a time.
      while (ln + 4 <= size && model[ln] < floor && model[ln + 1] < floor &&
             model[ln + 2] < floor && model[ln + 3] < floor)
        ln += 4;
      if (ln == size) break;
      if (model[ln] < floor || !tab.count[ln]) continue;
      LineTime t{EventOrigin{static_cast<uint32_t>(f), static_cast<uint32_t>(ln), -1, nullptr},
                 tab.count[ln], TimePair{tab.model[ln], tab.simpleAt(ln)}};
      if (best.size() == n && !before(t, best.back())) continue;
      best.insert(std::upper_bound(best.begin(), best.end(), t, before), t);
      if (best.size() > n) best.pop_back();
      if (best.size() == n) floor = best.back().time.model;
    }
  }
  if (origin)
    for (LineTime& l : best) origin(l.at.file, l.at.line, l.at.programName, l.at.n);
  return best;
}

namespace {
nlohmann::json pair(const TimePair& t) {
  return {{"time", t.model}, {"time_simple", t.simple}};
}
nlohmann::json where(const EventOrigin& at, const SourceFiles& files) {
  if (at.line == 0) return nullptr;
  return {{"file", files.name(at.file)},
          {"line", at.line},
          {"n", at.n >= 0 ? nlohmann::json(at.n) : nlohmann::json(nullptr)},
          {"prog", at.programName ? nlohmann::json(*at.programName) : nlohmann::json(nullptr)}};
}
}  // namespace

nlohmann::json TimeReport::toJson(const SourceFiles& files, bool dynamic, size_t topN,
                                  const LineOrigin& origin) const {
  nlohmann::json j;
  j["model"] = dynamic ? "dynamic" : "simple";
  j["total"] = total_.model;
  j["total_simple"] = total_.simple;
  nlohmann::json kinds = nlohmann::json::object();
  for (int k = 0; k < kTimeKinds; ++k)
    kinds[timeKindName(static_cast<TimeKind>(k))] = pair(byKind_[static_cast<size_t>(k)]);
  j["by_type"] = kinds;
  nlohmann::json tools = nlohmann::json::array();
  for (const auto& t : byTool()) {
    nlohmann::json e = pair(t.time);
    e["tool"] = t.tool;
    tools.push_back(e);
  }
  j["by_tool"] = tools;
  nlohmann::json ops = nlohmann::json::array();
  for (const auto& o : ops_) {
    nlohmann::json e = pair(o.time);
    e["tool"] = o.tool;
    e["label"] = o.label.empty() ? nlohmann::json(nullptr) : nlohmann::json(o.label);
    e["start"] = where(o.first, files);
    e["runs"] = o.runs;
    e["path_length"] = {{"rapid", o.rapidLength}, {"feed", o.feedLength}};
    nlohmann::json k = nlohmann::json::object();
    for (int q = 0; q < kTimeKinds; ++q)
      k[timeKindName(static_cast<TimeKind>(q))] = o.byKind[static_cast<size_t>(q)].model;
    e["by_type"] = k;
    ops.push_back(e);
  }
  j["operations"] = ops;
  nlohmann::json top = nlohmann::json::array();
  for (const auto& l : topLines(topN, origin)) {
    nlohmann::json e = where(l.at, files);
    if (e.is_null()) e = nlohmann::json::object();
    e["count"] = l.count;
    e["time"] = l.time.model;
    e["time_simple"] = l.time.simple;
    top.push_back(e);
  }
  j["top_blocks"] = top;
  const DrillStats& d = holes_.stats();
  j["drilling"] = {{"holes", d.holes}, {"pecks", d.pecks}, {"full_retracts", d.fullRetracts}};
  nlohmann::json holes = nlohmann::json::array();
  for (const HoleTime& h : holes_.holes()) {
    nlohmann::json e = pair(h.time);
    e["operation"] = h.op;
    e["tool"] = h.op < ops_.size() ? ops_[h.op].tool : 0;
    e["x"] = h.x;
    e["y"] = h.y;
    e["pecks"] = h.pecks;
    e["full_retracts"] = h.fullRetracts;
    e["runs"] = h.runs;
    holes.push_back(e);
  }
  j["holes"] = holes;
  if (holes_.unlisted() > 0) j["holes_unlisted"] = holes_.unlisted();
  return j;
}

}  // namespace ncvm
