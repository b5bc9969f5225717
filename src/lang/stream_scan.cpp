#include "lang/stream_scan.hpp"

#include <algorithm>

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#elif defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace ncvm {
namespace {
bool isBlank(char c) {
  return c == ' ' || c == '\t' || c == '\r';
}

// The bytes of a CAM program's lines: digits, '.', '-', ' ', '\r', '\n' and upper-case letters
// other than O, no two letters in a row. Returns how many bytes from p are such (a multiple of
// the vector width; the rest goes through the byte rules); counts their '\n' and keeps
// whether the last byte was a letter.
#if defined(__x86_64__) && defined(__GNUC__)
#define NCVM_SCAN_AVX2 1
[[gnu::target("avx2")]] uint64_t sumBytes(__m256i counters) {
  const __m256i sums = _mm256_sad_epu8(counters, _mm256_setzero_si256());
  return static_cast<uint64_t>(_mm256_extract_epi64(sums, 0)) +
         static_cast<uint64_t>(_mm256_extract_epi64(sums, 1)) +
         static_cast<uint64_t>(_mm256_extract_epi64(sums, 2)) +
         static_cast<uint64_t>(_mm256_extract_epi64(sums, 3));
}

[[gnu::target("avx2")]] size_t plainRunAvx2(const char* p, size_t n, uint64_t& lines,
                                            bool& letter) {
  const __m256i dash = _mm256_set1_epi8('-' - 1), nine = _mm256_set1_epi8('9' + 1);
  const __m256i slash = _mm256_set1_epi8('/');
  const __m256i a = _mm256_set1_epi8('A' - 1), z = _mm256_set1_epi8('Z' + 1),
                o = _mm256_set1_epi8('O');
  const __m256i sp = _mm256_set1_epi8(' '), nl = _mm256_set1_epi8('\n'),
                cr = _mm256_set1_epi8('\r');
  __m256i counters = _mm256_setzero_si256();
  int rounds = 0;
  size_t k = 0;
  for (; n - k >= 32; k += 32) {
    const __m256i b = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(p + k));
    // Signed compares: bytes from 0x80 are negative, in no range.
    const __m256i number = _mm256_andnot_si256(
        _mm256_cmpeq_epi8(b, slash),
        _mm256_and_si256(_mm256_cmpgt_epi8(b, dash), _mm256_cmpgt_epi8(nine, b)));
    const __m256i upper =
        _mm256_andnot_si256(_mm256_cmpeq_epi8(b, o),
                            _mm256_and_si256(_mm256_cmpgt_epi8(b, a), _mm256_cmpgt_epi8(z, b)));
    const __m256i newline = _mm256_cmpeq_epi8(b, nl);
    const __m256i blank = _mm256_or_si256(_mm256_cmpeq_epi8(b, sp), _mm256_cmpeq_epi8(b, cr));
    const __m256i good =
        _mm256_or_si256(_mm256_or_si256(number, upper), _mm256_or_si256(newline, blank));
    if (_mm256_movemask_epi8(good) != -1) break;
    const auto letters = static_cast<uint32_t>(_mm256_movemask_epi8(upper));
    if ((letters & (letters >> 1)) != 0 || (letter && (letters & 1u))) break;
    letter = (letters >> 31) != 0;
    counters = _mm256_sub_epi8(counters, newline);
    if (++rounds == 255) {
      lines += sumBytes(counters);
      counters = _mm256_setzero_si256();
      rounds = 0;
    }
  }
  lines += sumBytes(counters);
  return k;
}
#endif

#if defined(__SSE2__)
size_t plainRunSse2(const char* p, size_t n, uint64_t& lines, bool& letter) {
  const __m128i dash = _mm_set1_epi8('-' - 1), nine = _mm_set1_epi8('9' + 1),
                slash = _mm_set1_epi8('/');
  const __m128i a = _mm_set1_epi8('A' - 1), z = _mm_set1_epi8('Z' + 1), o = _mm_set1_epi8('O');
  const __m128i sp = _mm_set1_epi8(' '), nl = _mm_set1_epi8('\n'), cr = _mm_set1_epi8('\r');
  __m128i counters = _mm_setzero_si128();
  int rounds = 0;
  auto sum = [&] {
    const __m128i sums = _mm_sad_epu8(counters, _mm_setzero_si128());
    lines += static_cast<uint64_t>(_mm_cvtsi128_si64(sums)) +
             static_cast<uint64_t>(_mm_cvtsi128_si64(_mm_unpackhi_epi64(sums, sums)));
    counters = _mm_setzero_si128();
    rounds = 0;
  };
  size_t k = 0;
  for (; n - k >= 16; k += 16) {
    const __m128i b = _mm_loadu_si128(reinterpret_cast<const __m128i*>(p + k));
    const __m128i number = _mm_andnot_si128(
        _mm_cmpeq_epi8(b, slash), _mm_and_si128(_mm_cmpgt_epi8(b, dash), _mm_cmplt_epi8(b, nine)));
    const __m128i upper = _mm_andnot_si128(
        _mm_cmpeq_epi8(b, o), _mm_and_si128(_mm_cmpgt_epi8(b, a), _mm_cmplt_epi8(b, z)));
    const __m128i newline = _mm_cmpeq_epi8(b, nl);
    const __m128i blank = _mm_or_si128(_mm_cmpeq_epi8(b, sp), _mm_cmpeq_epi8(b, cr));
    const __m128i good = _mm_or_si128(_mm_or_si128(number, upper), _mm_or_si128(newline, blank));
    if (_mm_movemask_epi8(good) != 0xFFFF) break;
    const auto letters = static_cast<uint32_t>(_mm_movemask_epi8(upper));
    if ((letters & (letters >> 1)) != 0 || (letter && (letters & 1u))) break;
    letter = (letters >> 15) != 0;
    counters = _mm_sub_epi8(counters, newline);
    if (++rounds == 255) sum();
  }
  sum();
  return k;
}
#endif

size_t plainRun(const char* p, size_t n, uint64_t& lines, bool& letter) {
#if defined(NCVM_SCAN_AVX2)
  static const bool avx2 = __builtin_cpu_supports("avx2");
  if (avx2) return plainRunAvx2(p, n, lines, letter);
#endif
#if defined(__SSE2__)
  return plainRunSse2(p, n, lines, letter);
#else
  (void)p, (void)n, (void)lines, (void)letter;
  return 0;
#endif
}

}  // namespace

void StreamScan::piece(std::string_view text) {
  const char* p = text.data();
  const size_t n = text.size();
  // A UTF-8 byte-order mark at the start of the file is no program text (the compiler skips it).
  size_t k = first_ && text.starts_with("\xEF\xBB\xBF") ? 3 : 0;
  while (ok_ && k < n) {
    // Outside comments, whole vectors of plain bytes at once; then the byte rules for the next
    // sixteen bytes.
    if (!comment_) {
      if (const size_t run = plainRun(p + k, n - k, lines_, letter_); run > 0) {
        k += run;
        // Conservative in the first piece: an O after a run is never taken for the header.
        lineStart_ = false;
        header_ = true;
      }
    }
    const size_t m = std::min<size_t>(16, n - k);
    scalar(p + k, m);
    k += m;
  }
  first_ = false;
}

void StreamScan::scalar(const char* p, size_t n) {
  for (size_t k = 0; k < n && ok_; ++k) {
    const char c = p[k];
    if (c == '\n') ++lines_;
    if (comment_) {
      if (c == ')' || c == '\n') comment_ = false;
      if (c == '\n') lineStart_ = true, letter_ = false;
      continue;
    }
    if (c == '\n') {
      lineStart_ = true;
      letter_ = false;
    } else if (isBlank(c)) {
      // Blanks keep lineStart_; two letters apart are two words to the compiler.
      letter_ = false;
    } else if (c >= 'A' && c <= 'Z') {
      // The one program header: an O at the start of the first piece's first block.
      if (c == 'O' && !(first_ && lineStart_ && !header_)) ok_ = false;
      if (letter_) ok_ = false;  // a keyword, a function name or a letter without a number
      header_ = true;
      letter_ = true;
      lineStart_ = false;
    } else if ((c >= '0' && c <= '9') || c == '.' || c == '-' || c == '+') {
      letter_ = false;
      lineStart_ = false;
    } else if (c == '(') {
      comment_ = true;
      letter_ = false;
      lineStart_ = false;  // "(...)O1" is no header: the compiler reads O as a word there
    } else if (c == '%') {
      // A separator once the file has shown one in its first piece; otherwise everything
      // before it would be leader.
      if (!first_ && !percentFirst_) ok_ = false;
      if (first_) percentFirst_ = true;
      letter_ = false;
      lineStart_ = true;
    } else {
      ok_ = false;  // '#', '[', ',', ';', '/', '<', ':', ')', lower case, bytes past ASCII
    }
  }
}

}  // namespace ncvm
