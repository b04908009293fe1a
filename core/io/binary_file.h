#pragma once
// Small binary files the tools keep between runs (fitted and parsed meshes): written as raw
// values appended to a string, read back with every read checked against the end, and a fast
// content hash to name and check them.
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace demoplan {

// FNV-1a over 8-byte words (then the last bytes): tens of megabytes in milliseconds. Not
// cryptographic: it tells contents apart, it does not defend against forgery.
std::uint64_t hash_bytes(const void* data, size_t bytes, std::uint64_t seed = 0xcbf29ce484222325ull);

// The whole file; false when it cannot be read.
bool read_whole_file(const std::string& file, std::string& bytes);

template <typename T>
void put_bytes(std::string& out, const T& value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof value);
}
inline void put_string(std::string& out, const std::string& s) {
  put_bytes(out, static_cast<std::uint64_t>(s.size()));
  out += s;
}
// A vector of plain values (as bytes).
template <typename T>
void put_vector(std::string& out, const std::vector<T>& v) {
  put_bytes(out, static_cast<std::uint64_t>(v.size()));
  out.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
}

// Reads what put_* wrote; each call false (and nothing read) past the end.
struct ByteReader {
  const char* at;
  const char* end;

  size_t left() const { return static_cast<size_t>(end - at); }
  template <typename T>
  bool get(T& value) {
    if (left() < sizeof value) return false;
    std::memcpy(static_cast<void*>(&value), at, sizeof value);
    at += sizeof value;
    return true;
  }
  bool get_string(std::string& s) {
    std::uint64_t n = 0;
    if (!get(n) || n > left()) return false;
    s.assign(at, n);
    at += n;
    return true;
  }
  template <typename T>
  bool get_vector(std::vector<T>& v) {
    std::uint64_t n = 0;
    if (!get(n) || n > left() / sizeof(T)) return false;
    v.resize(n);
    std::memcpy(static_cast<void*>(v.data()), at, n * sizeof(T));
    at += n * sizeof(T);
    return true;
  }
};

}  // namespace demoplan
