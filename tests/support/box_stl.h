#pragma once
// A part a test makes itself: a closed box of sx x sy x sz units (millimetres, as CAD files
// are) centred at the origin, written as binary STL.
#include <array>
#include <cstdint>
#include <filesystem>
#include <fstream>

namespace demoplan::test {

inline void write_box_stl(const std::filesystem::path& file, float sx, float sy, float sz) {
  std::ofstream out(file, std::ios::binary);
  char header[80] = "test box, millimetres";
  out.write(header, 80);
  const std::uint32_t n = 12;
  out.write(reinterpret_cast<const char*>(&n), 4);
  auto v = [&](int i) {
    return std::array<float, 3>{(i & 1 ? 0.5f : -0.5f) * sx, (i & 2 ? 0.5f : -0.5f) * sy, (i & 4 ? 0.5f : -0.5f) * sz};
  };
  const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& f : faces)
    for (const auto& t : {std::array<int, 3>{f[0], f[1], f[2]}, std::array<int, 3>{f[0], f[2], f[3]}}) {
      const float normal[3] = {0, 0, 0};
      out.write(reinterpret_cast<const char*>(normal), 12);
      for (int k : t) out.write(reinterpret_cast<const char*>(v(k).data()), 12);
      const std::uint16_t attr = 0;
      out.write(reinterpret_cast<const char*>(&attr), 2);
    }
}

}  // namespace demoplan::test
