#pragma once
// The bundled benchmark data with YCBV_05's handles as upstream revised them in 2024
// (objects/ycbv/srdf-2024, gtamp README section 3): every handle 3.2 cm lower, which puts the
// hand inside the bottle for the top grasp and the side handles out of reach from several base
// poses. shelf_1 from Panda pose 0 and shelf_2 from Panda poses 0-3 cannot be done with it:
// tests that need a demonstration the robot cannot carry out use it. Built once per process as
// a folder of links beside the real data, with only that SRDF swapped.
#include <filesystem>
#include <string>
#include <unistd.h>

namespace demoplan::testdata {

inline std::string data_dir_with_2024_bottle(const std::string& data_dir) {
  namespace fs = std::filesystem;
  const fs::path src = fs::absolute(data_dir);
  const fs::path dst = fs::temp_directory_path() / ("demoplan-gtamp-2024-" + std::to_string(::getpid()));
  if (fs::exists(dst / "tasks")) return dst.string();
  static const struct Cleanup {  // links only: removing them leaves the real data alone
    fs::path dir;
    ~Cleanup() {
      std::error_code ec;
      fs::remove_all(dir, ec);
    }
  } cleanup{dst};
  // Every entry a link to the real one, but for the folders on the way to the swapped file.
  auto mirror = [](const fs::path& from, const fs::path& to, const std::string& except) {
    fs::create_directories(to);
    for (const auto& e : fs::directory_iterator(from))
      if (e.path().filename() != except && !fs::exists(fs::symlink_status(to / e.path().filename())))
        fs::create_symlink(e.path(), to / e.path().filename());
  };
  mirror(src, dst, "objects");
  mirror(src / "objects", dst / "objects", "ycbv");
  mirror(src / "objects" / "ycbv", dst / "objects" / "ycbv", "srdf");
  mirror(src / "objects" / "ycbv" / "srdf", dst / "objects" / "ycbv" / "srdf", "obj_000005.srdf");
  fs::create_symlink(src / "objects" / "ycbv" / "srdf-2024" / "obj_000005.srdf",
                     dst / "objects" / "ycbv" / "srdf" / "obj_000005.srdf");
  return dst.string();
}

}  // namespace demoplan::testdata
