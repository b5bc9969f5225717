#pragma once
// The number of '\n' in a text, to size a program's arrays before it is compiled. SSE2 (every
// x86-64) compares 16 bytes at a time and sums the matches in byte counters, a few
// instructions per 16 bytes; memchr per line cost about 20 instructions a line.
#include <cstddef>
#include <string_view>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace ncvm {

inline size_t countNewlines(std::string_view text) {
  const char* p = text.data();
  size_t n = text.size(), count = 0, k = 0;
#if defined(__SSE2__)
  const __m128i newline = _mm_set1_epi8('\n');
  while (n - k >= 16) {
    // At most 255 rounds before the byte counters (0xFF per match, subtracted) could wrap.
    __m128i counters = _mm_setzero_si128();
    for (int round = 0; round < 255 && n - k >= 16; ++round, k += 16) {
      const __m128i bytes = _mm_loadu_si128(reinterpret_cast<const __m128i*>(p + k));
      counters = _mm_sub_epi8(counters, _mm_cmpeq_epi8(bytes, newline));
    }
    const __m128i sums = _mm_sad_epu8(counters, _mm_setzero_si128());  // two 64-bit sums
    count += static_cast<size_t>(_mm_cvtsi128_si64(sums)) +
             static_cast<size_t>(_mm_cvtsi128_si64(_mm_unpackhi_epi64(sums, sums)));
  }
#endif
  for (; k < n; ++k) count += p[k] == '\n';
  return count;
}

}  // namespace ncvm
