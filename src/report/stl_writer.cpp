#include "report/stl_writer.hpp"

#include <array>
#include <cmath>
#include <cstring>
#include <vector>

#include "report/atomic_file.hpp"

namespace ncvm {
namespace {

using V = std::array<float, 3>;

struct Mesh {
  std::string out;
  uint32_t count = 0;
  void tri(const V& a, const V& b, const V& c) {
    V u{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, w{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    V n{u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
    float len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (len > 0)
      for (auto& x : n) x /= len;
    char buf[50];
    std::memcpy(buf, n.data(), 12);
    std::memcpy(buf + 12, a.data(), 12);
    std::memcpy(buf + 24, b.data(), 12);
    std::memcpy(buf + 36, c.data(), 12);
    buf[48] = buf[49] = 0;
    out.append(buf, 50);
    ++count;
  }
};

}  // namespace

std::string encodeStl(const HeightField& f, int maxSamples) {
  // Sample columns/rows: every `step`-th cell, always including the last one.
  auto samples = [&](int n) {
    int step = std::max(1, (n + maxSamples - 1) / std::max(1, maxSamples));
    std::vector<int> s;
    for (int k = 0; k < n; k += step) s.push_back(k);
    if (s.back() != n - 1) s.push_back(n - 1);
    return s;
  };
  std::vector<int> cols = samples(f.nx()), rows = samples(f.ny());
  // The outline runs through the outer cell centres: the mesh is the stock half a cell in.
  auto top = [&](size_t ci, size_t rj) {
    return V{static_cast<float>(f.cellX(cols[ci])), static_cast<float>(f.cellY(rows[rj])),
             f.at(cols[ci], rows[rj])};
  };
  // The stock's bottom when the setup gives it, else a base below the deepest cut.
  float lowest = f.top();
  for (float z : f.data()) lowest = std::min(lowest, z);
  const float zb =
      f.bottom() < lowest ? (f.bottom() > -1e8f ? f.bottom() : lowest - 5.0f) : lowest - 1.0f;
  auto low = [&](V v) { return V{v[0], v[1], zb}; };
  Mesh m;
  m.out.assign(80, '\0');
  std::memcpy(m.out.data(), "ncvm stock", 10);
  m.out.append(4, '\0');
  const size_t nc = cols.size(), nr = rows.size();
  for (size_t j = 0; j + 1 < nr; ++j)
    for (size_t i = 0; i + 1 < nc; ++i) {
      V a = top(i, j), b = top(i + 1, j), c = top(i + 1, j + 1), d = top(i, j + 1);
      m.tri(a, b, c);
      m.tri(a, c, d);
    }
  // Boundary counter-clockwise seen from above, then walls (outward) and the bottom fan.
  std::vector<V> ring;
  for (size_t i = 0; i + 1 < nc; ++i) ring.push_back(top(i, 0));
  for (size_t j = 0; j + 1 < nr; ++j) ring.push_back(top(nc - 1, j));
  for (size_t i = nc - 1; i > 0; --i) ring.push_back(top(i, nr - 1));
  for (size_t j = nr - 1; j > 0; --j) ring.push_back(top(0, j));
  V centre{static_cast<float>((f.cellX(0) + f.cellX(f.nx() - 1)) / 2),
           static_cast<float>((f.cellY(0) + f.cellY(f.ny() - 1)) / 2), zb};
  for (size_t k = 0; k < ring.size(); ++k) {
    const V& a = ring[k];
    const V& b = ring[(k + 1) % ring.size()];
    m.tri(a, low(a), low(b));
    m.tri(a, low(b), b);
    m.tri(centre, low(b), low(a));
  }
  std::memcpy(m.out.data() + 80, &m.count, 4);
  return m.out;
}

void writeStl(const std::string& path, const HeightField& f, int maxSamples) {
  writeFileAtomic(path, encodeStl(f, maxSamples));
}

}  // namespace ncvm
