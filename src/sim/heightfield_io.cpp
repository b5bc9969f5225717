#include "sim/heightfield_io.hpp"

#include <fmt/format.h>

#include <bit>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace ncvm {

static_assert(std::endian::native == std::endian::little, "height maps are little-endian");

std::string encodeHeightMap(const HeightField& f) {
  std::string out = fmt::format("NCVM-HMAP 1 {} {} {:.9g} {:.9g} {:.9g}\n", f.nx(), f.ny(), f.x0(),
                                f.y0(), f.cell());
  const auto* bytes = reinterpret_cast<const char*>(f.data().data());
  out.append(bytes, f.bytes());
  return out;
}

HeightField loadHeightMap(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot open the height map");
  std::string header;
  std::getline(in, header);
  std::istringstream h(header);
  std::string magic;
  int version = 0, nx = 0, ny = 0;
  double x0 = 0, y0 = 0, cell = 0;
  h >> magic >> version >> nx >> ny >> x0 >> y0 >> cell;
  if (!h || magic != "NCVM-HMAP" || version != 1 || nx <= 0 || ny <= 0 || !(cell > 0) ||
      static_cast<double>(nx) * ny > 2.0e9)
    throw std::runtime_error(path + ": not an ncvm height map (NCVM-HMAP 1 nx ny x0 y0 cell)");
  HeightField f(x0, y0, cell, nx, ny, 0.0f);
  std::vector<float> z(static_cast<size_t>(nx) * static_cast<size_t>(ny));
  in.read(reinterpret_cast<char*>(z.data()),
          static_cast<std::streamsize>(z.size() * sizeof(float)));
  if (in.gcount() != static_cast<std::streamsize>(z.size() * sizeof(float)))
    throw std::runtime_error(path + ": height map truncated");
  for (int j = 0; j < ny; ++j)
    std::memcpy(f.row(j), z.data() + static_cast<size_t>(j) * static_cast<size_t>(nx),
                static_cast<size_t>(nx) * sizeof(float));
  return f;
}

}  // namespace ncvm
