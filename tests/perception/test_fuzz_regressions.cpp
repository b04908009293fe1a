// Replays, in the normal build, what the fuzzers (tests/fuzz) keep: every seed corpus input
// (tests/fuzz/corpus/<target>/) and every input a fuzzer found a crash, hang or sanitizer report
// with (tests/data/fuzz-regressions/<target>/). Each must load, or throw InputError whose message
// is one line starting with the file it read (DESIGN.md, "Bad input"); a crash or another
// exception fails the test. The parser each target feeds is the fuzz target's own.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "core/demo/benchmark_task.h"
#include "core/demo/demonstration.h"
#include "core/error.h"
#include "core/model/mesh.h"
#include "core/model/robot_model.h"
#include "core/model/srdf.h"
#include "core/path/path.h"
#include "core/placement/placement_result.h"
#include "core/cell/cell.h"
#include "core/project/project.h"
#include "perception/camera/camera_model.h"
#include "perception/camera/charuco_board.h"
#include "perception/extraction/tracks_file.h"
#include "perception/importers/bop_csv.h"
#include "perception/importers/hand_detections.h"
#include "perception/markers/marker_scene.h"
#include "perception/tracking/tracker_init.h"

namespace fs = std::filesystem;
using namespace demoplan;

namespace {

const fs::path kSource = DEMOPLAN_SOURCE_DIR;

std::string read_bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// A scratch folder for this test process, removed at the end.
struct Scratch {
  fs::path dir = fs::temp_directory_path() / ("demoplan-fuzz-regressions-" + std::to_string(::getpid()));
  Scratch() { fs::create_directories(dir); }
  ~Scratch() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
};

// Copies `input` to `file` (the name the fuzz target gives its input: some readers choose by
// extension) and runs `load` on it. Returns how many inputs were fed.
using Load = std::function<void(const std::string& file)>;

size_t expect_each_input_loads_or_fails_cleanly(const std::string& target, const fs::path& file, const Load& load,
                                                const std::string& error_file = "") {
  size_t fed = 0;
  for (const fs::path& dir : {kSource / "tests/fuzz/corpus" / target, kSource / "tests/data/fuzz-regressions" / target}) {
    if (!fs::is_directory(dir)) continue;
    std::vector<fs::path> inputs;
    for (const auto& e : fs::directory_iterator(dir))
      if (e.is_regular_file() && e.path().filename() != "README.md") inputs.push_back(e.path());
    std::sort(inputs.begin(), inputs.end());
    for (const fs::path& input : inputs) {
      SCOPED_TRACE(input.string());
      fs::create_directories(file.parent_path());
      {
        std::ofstream out(file, std::ios::binary | std::ios::trunc);
        const std::string bytes = read_bytes(input);
        out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
      }
      const std::string named = error_file.empty() ? file.string() : error_file;
      try {
        load(file.string());
      } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.rfind(named, 0), 0u) << what;
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
      } catch (const std::exception& e) {
        ADD_FAILURE() << "not an InputError: " << e.what();
      }
      ++fed;
    }
  }
  return fed;
}

class FuzzRegressions : public ::testing::Test {
protected:
  Scratch scratch;
};

TEST_F(FuzzRegressions, Project) {
  EXPECT_GT(expect_each_input_loads_or_fails_cleanly("project", scratch.dir / "input.demoplan",
                                                     [](const std::string& f) { load_project(f); }),
            0u);
}

TEST_F(FuzzRegressions, Cell) {
  EXPECT_GT(expect_each_input_loads_or_fails_cleanly("cell", scratch.dir / "input.cell.json",
                                                     [](const std::string& f) { load_cell(f); }),
            0u);
}

TEST_F(FuzzRegressions, Demonstration) {
  EXPECT_GT(expect_each_input_loads_or_fails_cleanly("demonstration", scratch.dir / "input.json",
                                                     [](const std::string& f) { load_demonstration(f); }),
            0u);
}

TEST_F(FuzzRegressions, Path) {
  EXPECT_GT(expect_each_input_loads_or_fails_cleanly("path", scratch.dir / "input.json",
                                                     [](const std::string& f) { load_path(f); }),
            0u);
}

TEST_F(FuzzRegressions, Placement) {
  EXPECT_GT(expect_each_input_loads_or_fails_cleanly("placement", scratch.dir / "input.json",
                                                     [](const std::string& f) { load_placement_result(f); }),
            0u);
}

TEST_F(FuzzRegressions, Urdf) {
  // As the fuzz target: the text parsed as if it were beside the Panda's meshes.
  const std::string as = kSource.string() + "/resources/gtamp/robots/franka_panda/fuzz.urdf";
  MeshCache meshes;
  UrdfOptions options;
  options.mesh_cache = &meshes;
  EXPECT_GT(expect_each_input_loads_or_fails_cleanly(
                "urdf", scratch.dir / "input.urdf",
                [&](const std::string& f) { parse_urdf(read_bytes(f), as, options); }, as),
            0u);
}

TEST_F(FuzzRegressions, Srdf) {
  EXPECT_GT(expect_each_input_loads_or_fails_cleanly(
                "srdf", scratch.dir / "input.srdf", [](const std::string& f) { parse_srdf(read_bytes(f), "fuzz.srdf"); },
                "fuzz.srdf"),
            0u);
}

TEST_F(FuzzRegressions, BenchmarkTask) {
  const fs::path data = scratch.dir / "data";
  fs::create_directories(data / "tasks");
  for (const char* sub : {"robots", "objects", "furniture"})
    fs::create_directory_symlink(kSource / "resources/gtamp" / sub, data / sub);
  EXPECT_GT(expect_each_input_loads_or_fails_cleanly(
                "task", data / "tasks/fuzz_0.json",
                [&](const std::string&) { load_benchmark_task(data.string(), "fuzz_0"); }),
            0u);
}

TEST_F(FuzzRegressions, Camera) {
  EXPECT_GT(expect_each_input_loads_or_fails_cleanly("camera", scratch.dir / "input.json",
                                                     [](const std::string& f) { perception::load_camera(f); }),
            0u);
}

TEST_F(FuzzRegressions, CameraYaml) {
  EXPECT_GT(expect_each_input_loads_or_fails_cleanly("camera_yaml", scratch.dir / "input.yaml",
                                                     [](const std::string& f) { perception::load_camera(f); }),
            0u);
}

TEST_F(FuzzRegressions, CameraXml) {
  EXPECT_GT(expect_each_input_loads_or_fails_cleanly("camera_xml", scratch.dir / "input.xml",
                                                     [](const std::string& f) { perception::load_camera(f); }),
            0u);
}

TEST_F(FuzzRegressions, MarkerScene) {
  EXPECT_GT(expect_each_input_loads_or_fails_cleanly("marker_scene", scratch.dir / "input.json",
                                                     [](const std::string& f) { perception::load_marker_scene(f); }),
            0u);
}

TEST_F(FuzzRegressions, BopCsv) {
  EXPECT_GT(expect_each_input_loads_or_fails_cleanly("bop_csv", scratch.dir / "input.csv",
                                                     [](const std::string& f) { perception::load_bop_csv(f); }),
            0u);
}

TEST_F(FuzzRegressions, HandDetections) {
  EXPECT_GT(expect_each_input_loads_or_fails_cleanly("hand_detections", scratch.dir / "input.json",
                                                     [](const std::string& f) { perception::load_hand_detections(f); }),
            0u);
}

TEST_F(FuzzRegressions, Tracks) {
  EXPECT_GT(expect_each_input_loads_or_fails_cleanly("tracks", scratch.dir / "input.tracks.json",
                                                     [](const std::string& f) { perception::load_tracks_file(f); }),
            0u);
}

TEST_F(FuzzRegressions, CharucoBoard) {
  EXPECT_GT(expect_each_input_loads_or_fails_cleanly("charuco_board", scratch.dir / "input.json",
                                                     [](const std::string& f) { perception::load_charuco_board(f).make(); }),
            0u);
}

TEST_F(FuzzRegressions, TrackerInit) {
  EXPECT_GT(expect_each_input_loads_or_fails_cleanly("tracker_init", scratch.dir / "input.json",
                                                     [](const std::string& f) { perception::load_tracker_init(f); }),
            0u);
}

// Every fuzz target has a test above: a new tests/fuzz/fuzz_<target>.cpp needs one here too.
TEST(FuzzRegressionsCoverage, EveryFuzzTargetIsReplayed) {
  const std::vector<std::string> replayed{"project", "cell", "demonstration", "path", "placement", "urdf", "srdf",
                                          "task",    "camera",        "camera_yaml",  "camera_xml", "marker_scene",
                                          "bop_csv", "hand_detections", "tracks", "charuco_board", "tracker_init"};
  for (const auto& e : fs::directory_iterator(kSource / "tests/fuzz")) {
    const std::string name = e.path().filename().string();
    if (name.rfind("fuzz_", 0) != 0 || e.path().extension() != ".cpp") continue;
    const std::string target = name.substr(5, name.size() - 5 - 4);
    EXPECT_NE(std::find(replayed.begin(), replayed.end(), target), replayed.end()) << target;
  }
}

}  // namespace
