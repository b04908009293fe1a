#include "core/io/binary_file.h"

#include <algorithm>
#include <fstream>

namespace demoplan {

std::uint64_t hash_bytes(const void* data, size_t bytes, std::uint64_t h) {
  const auto* p = static_cast<const unsigned char*>(data);
  size_t i = 0;
  for (; i + 8 <= bytes; i += 8) {
    std::uint64_t word;
    std::memcpy(&word, p + i, 8);
    h = (h ^ word) * 0x100000001b3ull;
    h ^= h >> 29;
  }
  for (; i < bytes; ++i) h = (h ^ p[i]) * 0x100000001b3ull;
  return h;
}

bool read_whole_file(const std::string& file, std::string& bytes) {
  std::ifstream in(file, std::ios::binary | std::ios::ate);
  if (!in) return false;
  bytes.assign(static_cast<size_t>(std::max<std::streamoff>(0, in.tellg())), '\0');
  in.seekg(0);
  return static_cast<bool>(in.read(bytes.data(), static_cast<std::streamsize>(bytes.size())));
}

}  // namespace demoplan
