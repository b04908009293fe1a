#include "core/io/atomic_file.h"

#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>

#include "core/error.h"

namespace demoplan {

void write_file_atomic(const std::string& path, std::string_view bytes) {
  // A name of this process and call: two writers of one file (two processes filling a cache)
  // never share the temporary file; the last rename wins, whole.
  static std::atomic<unsigned> calls{0};
  const std::string tmp = path + ".tmp" + std::to_string(getpid()) + "-" + std::to_string(calls++);
  {
    std::ofstream out(tmp, std::ios::trunc | std::ios::binary);
    if (!out) throw InputError(path, "", "cannot write file");
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.flush();
    if (!out) {
      out.close();
      std::error_code ec;
      std::filesystem::remove(tmp, ec);
      throw InputError(path, "", "write failed");
    }
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) throw InputError(path, "", "cannot replace file: " + ec.message());
}

}  // namespace demoplan
