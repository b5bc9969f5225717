#include "lang/program_stream.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "core/alarm.hpp"
#include "lang/stream_scan.hpp"

namespace ncvm {
namespace {

// The compiled arrays of a program, not its identity (number, name, label, header, stream).
void swapCompiled(Program& a, Program& b) {
  std::swap(a.blocks, b.blocks);
  std::swap(a.words, b.words);
  std::swap(a.macroOps, b.macroOps);
  std::swap(a.code, b.code);
  std::swap(a.consts, b.consts);
  std::swap(a.exprs, b.exprs);
  std::swap(a.prints, b.prints);
  std::swap(a.strings, b.strings);
  std::swap(a.errors, b.errors);
  std::swap(a.structural, b.structural);
  std::swap(a.lostLoops, b.lostLoops);
  std::swap(a.labels, b.labels);
  std::swap(a.loopParents, b.loopParents);
}

// Records where each piece the compiler takes starts in the file.
class CountingChunks final : public LineChunks {
 public:
  explicit CountingChunks(StreamChunks& inner) : inner_(inner) {}
  std::string_view next() override {
    std::string_view s = inner_.next();
    last_ = s.size();
    return s;
  }
  size_t lineHint() const override { return inner_.lineHint(); }
  size_t last() const { return last_; }

 private:
  StreamChunks& inner_;
  size_t last_ = 0;
};

}  // namespace

bool ProgramStream::scan(const std::string& path, uint64_t size, size_t pieceBytes,
                         uint32_t& lines) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  StreamChunks chunks(in, size, pieceBytes);
  StreamScan scan;
  for (std::string_view s = chunks.next(); !s.empty() && scan.streamable(); s = chunks.next())
    scan.piece(s);
  if (!scan.streamable() || scan.lines() >= UINT32_MAX) return false;
  lines = static_cast<uint32_t>(scan.lines()) + 1;
  return true;
}

ProgramStream::Identity ProgramStream::identityOf(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return Identity{};
  return Identity{static_cast<uint64_t>(st.st_dev), static_cast<uint64_t>(st.st_ino),
                  static_cast<uint64_t>(st.st_size), static_cast<int64_t>(st.st_mtim.tv_sec),
                  static_cast<int64_t>(st.st_mtim.tv_nsec)};
}

ProgramStream::ProgramStream(const std::string& path, uint32_t fileId, std::string stem,
                             const ParseOptions& options, size_t pieceBytes, uint32_t lineBound,
                             Program& program)
    : path_(path),
      fileId_(fileId),
      stem_(std::move(stem)),
      options_(options),
      pieceBytes_(pieceBytes),
      prog_(program),
      lineBound_(lineBound) {
  options_.piecewise = true;
  identity_ = identityOf(path_);
  start();
}

ProgramStream::~ProgramStream() = default;

// The compiler's pieces until the first block: the program's header and first piece.
void ProgramStream::start() {
  in_ = std::ifstream(path_, std::ios::binary);
  if (!in_) throw std::runtime_error(path_ + ": cannot open");
  chunks_ = std::make_unique<StreamChunks>(in_, identity_.size, pieceBytes_);
  counting_ = std::make_unique<CountingChunks>(*chunks_);
  compiler_ = std::make_unique<PieceCompiler>(*counting_, fileId_, stem_, options_);
  base_ = 0;
  offset_ = 0;
  pieces_.clear();
  advanced_ = false;
  ParsedFile& parsed = compiler_->parsed();
  // Comments before the first header may yet give way to it ("(PART NAME)" then "O0001").
  while (compileNext())
    if (!parsed.programs.empty() && !parsed.programs.front().blocks.empty() &&
        !compiler_->onlyComments())
      break;
  // What StreamScan accepts compiles to one program without loops or jumps; anything else
  // (a file of nothing but comments, say) is loaded whole by the caller instead.
  usable_ =
      parsed.programs.size() == 1 && !compiler_->hasControlFlow() && !compiler_->onlyComments();
  if (!usable_) return;
  Program& first = parsed.programs.front();
  if (!prog_.stream) {  // the first start: the program is new
    prog_.number = first.number;
    prog_.name = first.name;
    prog_.loc = first.loc;
  }
  Program empty;
  swapCompiled(prog_, empty);
  swapCompiled(prog_, first);
  compiler_->continueInto(prog_);
  firstLine_ = prog_.blocks.empty() ? 1 : prog_.blocks.front().loc.line;
  prog_.stream = this;
}

bool ProgramStream::compileNext() {
  const uint32_t firstLine = compiler_->line() + 1;
  if (!compiler_->next()) return false;
  const auto bytes = static_cast<uint32_t>(static_cast<const CountingChunks&>(*counting_).last());
  pieces_.push_back(Piece{offset_, firstLine, bytes});
  offset_ += bytes;
  return true;
}

bool ProgramStream::advance() {
  if (materialized_) return false;
  const auto size = static_cast<uint32_t>(prog_.blocks.size());
  std::swap(prog_.blocks, spareBlocks_);
  std::swap(prog_.words, spareWords_);
  prog_.blocks.clear();
  prog_.words.clear();
  prog_.labels.clear();
  while (compileNext())
    if (!prog_.blocks.empty()) {
      base_ += size;
      advanced_ = true;
      return true;
    }
  // The end of the text: the last piece stays (the executor's last block is in it).
  std::swap(prog_.blocks, spareBlocks_);
  std::swap(prog_.words, spareWords_);
  return false;
}

bool ProgramStream::unchanged() const {
  return identityOf(path_) == identity_;
}

void ProgramStream::checkUnchanged() const {
  if (!unchanged()) throw AlarmError(AlarmId::ProgramFileChanged, path_ + " changed while it ran");
}

uint32_t ProgramStream::materialize() {
  checkUnchanged();
  std::ifstream in(path_, std::ios::binary);
  if (!in) throw AlarmError(AlarmId::ProgramFileChanged, path_ + " cannot be read again");
  StreamChunks chunks(in, identity_.size);
  ParseOptions whole = options_;
  whole.piecewise = false;
  ParsedFile parsed = parseProgramChunks(chunks, fileId_, stem_, whole);
  if (parsed.programs.size() != 1)
    throw AlarmError(AlarmId::ProgramFileChanged, path_ + " no longer holds one program");
  // The arrays the executor is reading stay alive (retired_), as do the last piece's.
  retired_.emplace_back();
  swapCompiled(retired_.back(), prog_);
  swapCompiled(prog_, parsed.programs.front());
  materialized_ = true;
  prog_.stream = nullptr;
  const uint32_t base = base_;
  base_ = 0;
  return base;
}

void ProgramStream::rewind() {
  if (materialized_ || !advanced_) return;
  checkUnchanged();
  start();
  if (!usable_) throw AlarmError(AlarmId::ProgramFileChanged, path_ + " changed while it ran");
}

int32_t ProgramStream::sequenceAt(uint32_t line) {
  auto it = std::upper_bound(pieces_.begin(), pieces_.end(), line,
                             [](uint32_t l, const Piece& p) { return l < p.firstLine; });
  if (it == pieces_.begin() || !unchanged()) return -1;
  const Piece& piece = *(it - 1);
  std::ifstream in(path_, std::ios::binary);
  auto buf = std::make_unique_for_overwrite<char[]>(piece.bytes);
  in.seekg(static_cast<std::streamoff>(piece.offset));
  in.read(buf.get(), static_cast<std::streamsize>(piece.bytes));
  if (static_cast<size_t>(in.gcount()) != piece.bytes) return -1;
  const std::string_view text(buf.get(), piece.bytes);
  size_t k = piece.offset == 0 && text.starts_with("\xEF\xBB\xBF") ? 3 : 0;  // a UTF-8 BOM
  for (uint32_t l = piece.firstLine; l < line; ++l) {
    const void* nl = std::memchr(text.data() + k, '\n', text.size() - k);
    if (!nl) return -1;
    k = static_cast<size_t>(static_cast<const char*>(nl) - text.data()) + 1;
  }
  // As the compiler reads N: digits after it, no point, at most eight.
  while (k < text.size() && (text[k] == ' ' || text[k] == '\t' || text[k] == '\r')) ++k;
  if (k + 1 >= text.size() || text[k] != 'N' || text[k + 1] < '0' || text[k + 1] > '9') return -1;
  int64_t n = 0;
  int digits = 0;
  for (++k; k < text.size() && text[k] >= '0' && text[k] <= '9'; ++k, ++digits)
    n = std::min<int64_t>(n * 10 + (text[k] - '0'), 999999999);
  if ((k < text.size() && text[k] == '.') || digits > 8) return -1;
  return static_cast<int32_t>(n);
}

}  // namespace ncvm
