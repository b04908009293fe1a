// Every program writer, on paths through real configurations of the benchmark scenes: a small
// reader per format parses the output back to the path's waypoints (within 1e-6 rad) and its
// gripper actions, in order.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <regex>
#include <sstream>

#include "core/error.h"
#include "core/export/export_job.h"
#include "core/export/program_writers.h"
#include "core/io/json_file.h"
#include "core/trajectory/time_parameterization.h"
#include "tests/core/transition_path.h"

namespace demoplan {
namespace {

namespace fs = std::filesystem;
using testing_support::BenchmarkPathCase;
using Actions = std::vector<std::pair<size_t, GripperAction>>;  // (waypoint, action)

struct Prepared {
  BenchmarkPathCase c;
  JointLimitSet limits;
  Trajectory trajectory;
  RobotAxes axes;
};

const Prepared& prepared(const std::string& task, const std::string& robot) {
  static std::map<std::string, std::unique_ptr<Prepared>> cache;
  auto& p = cache[task + "/" + robot];
  if (!p) {
    p = std::make_unique<Prepared>();
    p->c = testing_support::benchmark_transition_path(DEMOPLAN_DATA_DIR, task, robot);
    p->limits = trajectory_limits(p->c.scene.robot.model);
    p->trajectory = time_parameterize(p->c.path, p->limits);
    p->axes = robot_axes(p->c.scene.robot.model, p->c.scene.robot.gripper().link,
                         benchmark_base_joints(DEMOPLAN_DATA_DIR, robot));
  }
  return *p;
}

Actions path_actions(const Path& path) {
  Actions out;
  for (size_t k = 0; k < path.waypoints.size(); ++k)
    if (path.waypoints[k].action != GripperAction::None) out.push_back({k, path.waypoints[k].action});
  return out;
}

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::vector<double> numbers(const std::string& s) {
  std::vector<double> out;
  static const std::regex number(R"([-+]?\d+(\.\d+)?([eE][-+]?\d+)?)");
  for (auto it = std::sregex_iterator(s.begin(), s.end(), number); it != std::sregex_iterator(); ++it)
    out.push_back(std::stod(it->str()));
  return out;
}

// Max |difference| between parsed joint values and the waypoint's values at `slots`.
double error_at(const std::vector<double>& parsed, const Eigen::VectorXd& q, const std::vector<int>& slots) {
  if (parsed.size() != slots.size()) return 1e9;
  double e = 0;
  for (size_t i = 0; i < slots.size(); ++i) e = std::max(e, std::abs(parsed[i] - q[slots[i]]));
  return e;
}

class Export : public ::testing::Test {
protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("demoplan_test_export_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  // The format's program in memory, then on disk as the CLI and the dialog save it.
  ProgramOutput run(const Prepared& p, const std::string& format, const std::string& file, ExportOptions o = {}) {
    o.robot = p.c.path.robot;
    o.source = "test path " + p.c.path.task;
    const std::string path = (dir_ / file).string();
    ProgramOutput out = program_writer(format, path).write(input(p, o), path);
    write_program_files(out.files);
    return out;
  }
  static ProgramInput input(const Prepared& p, const ExportOptions& o) {
    return {p.c.path, p.trajectory, p.limits, p.c.scene.robot.model, p.axes, o};
  }
  fs::path dir_;
};

TEST_F(Export, UrScriptMovejGivesTheWaypointsAndTheGripper) {
  const Prepared& p = prepared("shelf_1", "ur5");
  run(p, "urscript", "pick.script");
  const std::string text = read_text(dir_ / "pick.script");
  EXPECT_NE(text.find("# Robot: ur5"), std::string::npos);
  EXPECT_NE(text.find("Limits used"), std::string::npos);
  std::vector<std::vector<double>> moves;
  Actions actions;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("  movej([", 0) == 0) {
      const std::string list = line.substr(line.find('[') + 1, line.find(']') - line.find('[') - 1);
      moves.push_back(numbers(list));
      const double r = numbers(line.substr(line.find("r="))).front();
      const size_t k = moves.size() - 1;
      if (k == 0 || p.trajectory.stops[k]) {
        EXPECT_EQ(r, 0.0) << "rest waypoint " << k << " must not be blended";
      } else {
        EXPECT_LE(r, 0.02);
      }
    }
    if (line == "  gripper_close()") actions.push_back({moves.size() - 1, GripperAction::Grasp});
    if (line == "  gripper_open()") actions.push_back({moves.size() - 1, GripperAction::Release});
  }
  ASSERT_EQ(moves.size(), p.c.path.waypoints.size());
  for (size_t k = 0; k < moves.size(); ++k) EXPECT_LT(error_at(moves[k], p.c.path.waypoints[k].q, p.axes.arm), 1e-6) << k;
  EXPECT_EQ(actions, path_actions(p.c.path));
}

TEST_F(Export, UrScriptServojStreamRestsAtTheStops) {
  const Prepared& p = prepared("shelf_1", "ur5");
  ExportOptions o;
  o.servoj = true;
  o.rate = 500;
  const ProgramOutput r = run(p, "urscript", "stream.script", o);
  std::vector<std::vector<double>> stream;
  std::vector<size_t> rests;  // stream index at each "stopj"
  Actions actions;
  std::istringstream in(read_text(dir_ / "stream.script"));
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("  servoj([", 0) == 0) {
      const std::string list = line.substr(line.find('[') + 1, line.find(']') - line.find('[') - 1);
      stream.push_back(numbers(list));
      EXPECT_NE(line.find(", 0.0020, 0.1, 300)"), std::string::npos) << line;
    }
    if (line.rfind("  stopj(", 0) == 0) rests.push_back(stream.size() - 1);
    if (line == "  gripper_close()") actions.push_back({rests.size(), GripperAction::Grasp});
    if (line == "  gripper_open()") actions.push_back({rests.size(), GripperAction::Release});
  }
  EXPECT_EQ(stream.size(), r.samples);
  // Each block ends exactly on its resting waypoint; the gripper acts after the right block.
  const auto blocks = motion_blocks(p.trajectory);
  ASSERT_EQ(rests.size(), blocks.size());
  Actions expected;
  for (size_t b = 0; b < blocks.size(); ++b) {
    EXPECT_LT(error_at(stream[rests[b]], p.c.path.waypoints[blocks[b].last].q, p.axes.arm), 1e-6) << b;
    if (p.c.path.waypoints[blocks[b].last].action != GripperAction::None)
      expected.push_back({b + 1, p.c.path.waypoints[blocks[b].last].action});
  }
  EXPECT_EQ(actions, expected);
  // Steps of 2 ms within the velocity limits.
  for (size_t i = 1; i < stream.size(); ++i)
    for (size_t j = 0; j < 6; ++j)
      EXPECT_LE(std::abs(stream[i][j] - stream[i - 1][j]) / 0.002, p.limits.velocity[p.axes.arm[j]] * (1 + 1e-6));
}

void check_krl(const Prepared& p, const fs::path& src, bool ptp) {
  const std::string dat_text = read_text(fs::path(src).replace_extension(".dat"));
  const std::string src_text = read_text(src);
  EXPECT_NE(src_text.find("DEF pick( )"), std::string::npos);
  EXPECT_NE(dat_text.find("DEFDAT pick PUBLIC"), std::string::npos);
  EXPECT_NE(src_text.find("; Robot: " + p.c.path.robot), std::string::npos);
  // Targets.
  const std::vector<std::string> names = p.axes.arm.size() == 7 ? std::vector<std::string>{"A1", "A2", "E1", "A3", "A4", "A5", "A6"}
                                                                 : std::vector<std::string>{"A1", "A2", "A3", "A4", "A5", "A6"};
  std::map<size_t, std::vector<double>> targets;
  static const std::regex decl(R"(DECL E6AXIS XP(\d+)=\{(.*)\})");
  std::istringstream din(dat_text);
  for (std::string line; std::getline(din, line);) {
    std::smatch m;
    if (!std::regex_match(line, m, decl)) continue;
    std::map<std::string, double> axis;
    std::istringstream parts(m[2].str());
    for (std::string part; std::getline(parts, part, ',');) axis[part.substr(0, 2)] = std::stod(part.substr(3));
    EXPECT_EQ(axis.size(), 12u) << line;
    std::vector<double> q;
    for (const auto& n : names) q.push_back(axis[n] * M_PI / 180.0);
    targets[std::stoul(m[1].str())] = q;
  }
  ASSERT_EQ(targets.size(), p.c.path.waypoints.size());
  for (size_t k = 0; k < targets.size(); ++k) EXPECT_LT(error_at(targets[k], p.c.path.waypoints[k].q, p.axes.arm), 1e-6) << k;
  // Motions in order, one kind per block, the gripper after the right waypoint.
  std::vector<size_t> order;
  Actions actions;
  bool in_spline = false;
  static const std::regex motion(R"(\s*(PTP|SPTP) XP(\d+)( C_PTP)?)");
  std::istringstream sin(src_text);
  for (std::string line; std::getline(sin, line);) {
    std::smatch m;
    if (line == "PTP_SPLINE") in_spline = true;
    if (line == "ENDSPLINE") in_spline = false;
    if (std::regex_match(line, m, motion)) {
      EXPECT_EQ(m[1].str() == "SPTP", in_spline) << "PTP and SPLINE mixed: " << line;
      if (!ptp) {
        EXPECT_FALSE(m[3].matched);
      }
      order.push_back(std::stoul(m[2].str()));
    }
    if (line.rfind("$OUT[1] = TRUE", 0) == 0) actions.push_back({order.back(), GripperAction::Grasp});
    if (line.rfind("$OUT[1] = FALSE", 0) == 0) actions.push_back({order.back(), GripperAction::Release});
  }
  ASSERT_EQ(order.size(), p.c.path.waypoints.size());
  for (size_t k = 0; k < order.size(); ++k) EXPECT_EQ(order[k], k);
  EXPECT_EQ(actions, path_actions(p.c.path));
}

TEST_F(Export, KrlSplineModule) {
  const Prepared& p = prepared("shelf_1", "ur5");
  const ProgramOutput r = run(p, "krl", "pick.src");
  EXPECT_EQ(r.files.size(), 2u);
  check_krl(p, dir_ / "pick.src", false);
}

TEST_F(Export, KrlPtpModuleForASevenAxisArm) {
  const Prepared& p = prepared("shelf_1", "panda");
  ExportOptions o;
  o.krl_ptp = true;
  run(p, "krl", "pick.src", o);
  check_krl(p, dir_ / "pick.src", true);
}

TEST_F(Export, SunriseApplicationForTheKmr) {
  const Prepared& p = prepared("waiter_0", "kmr_iiwa");
  const ProgramOutput r = run(p, "sunrise", "WaiterPick.java");
  EXPECT_FALSE(r.warnings.empty());  // the platform moves on its own
  const std::string text = read_text(dir_ / "WaiterPick.java");
  EXPECT_NE(text.find("public class WaiterPick extends RoboticsAPIApplication"), std::string::npos);
  EXPECT_NE(text.find("// Robot: kmr_iiwa"), std::string::npos);
  std::vector<std::vector<double>> waypoints;
  std::vector<size_t> order;
  Actions actions;
  const auto& W = p.c.path.waypoints;
  Eigen::Vector3d base(W[0].q[p.axes.base[0]], W[0].q[p.axes.base[1]], W[0].q[p.axes.base[2]]);
  static const std::regex ptp(R"(ptp\(WAYPOINTS\[(\d+)\]\))");
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (line.find("    new JointPosition(") == 0) waypoints.push_back(numbers(line.substr(0, line.find(')'))));
    for (auto it = std::sregex_iterator(line.begin(), line.end(), ptp); it != std::sregex_iterator(); ++it)
      order.push_back(std::stoul((*it)[1].str()));
    if (line.find("MobilePlatformRelativeMotion(") != std::string::npos && line.find("kmp.move") != std::string::npos) {
      const auto d = numbers(line.substr(line.find("Motion(")));
      ASSERT_EQ(d.size(), 3u);
      // Relative to the platform at the start of the move: rotate into the base pose frame.
      base += Eigen::Vector3d(std::cos(base[2]) * d[0] - std::sin(base[2]) * d[1],
                              std::sin(base[2]) * d[0] + std::cos(base[2]) * d[1], d[2]);
      const size_t k = order.size();  // the arm's ptp to waypoint k follows
      EXPECT_LT((base - Eigen::Vector3d(W[k].q[p.axes.base[0]], W[k].q[p.axes.base[1]], W[k].q[p.axes.base[2]]))
                    .cwiseAbs().maxCoeff(), 1e-6) << k;
    }
    if (line == "    closeGripper();") actions.push_back({order.back(), GripperAction::Grasp});
    if (line == "    openGripper();") actions.push_back({order.back(), GripperAction::Release});
  }
  ASSERT_EQ(waypoints.size(), W.size());
  for (size_t k = 0; k < W.size(); ++k) EXPECT_LT(error_at(waypoints[k], W[k].q, p.axes.arm), 1e-6) << k;
  ASSERT_EQ(order.size(), W.size());
  for (size_t k = 0; k < order.size(); ++k) EXPECT_EQ(order[k], k);
  EXPECT_EQ(actions, path_actions(p.c.path));
  EXPECT_LT((base - Eigen::Vector3d(W.back().q[p.axes.base[0]], W.back().q[p.axes.base[1]], W.back().q[p.axes.base[2]]))
                .cwiseAbs().maxCoeff(), 1e-6);
}

TEST_F(Export, FrankaTrajectoryAt1kHzWithinFrankaLimits) {
  const Prepared& p = prepared("shelf_1", "panda");
  run(p, "franka", "pick.json");
  const Json j = read_json_file((dir_ / "pick.json").string());
  EXPECT_EQ(j["format"], "demoplan-franka-trajectory");
  EXPECT_EQ(j["version"], 1);
  EXPECT_EQ(j["rate_hz"], 1000.0);
  const auto& W = p.c.path.waypoints;
  // Motion steps as arrays; every step starts and ends at rest (equal first/last two rows).
  std::vector<std::vector<std::vector<double>>> motions;
  std::vector<int> motion_of_step;
  Actions actions;
  size_t last_waypoint = 0;
  std::map<int, size_t> step_last_waypoint;
  for (const auto& w : j["waypoints"]) step_last_waypoint[w["step"].get<int>()] = w["index"].get<size_t>();
  for (size_t s = 0; s < j["steps"].size(); ++s) {
    const Json& step = j["steps"][s];
    if (step["type"] == "motion") {
      motions.push_back(step["q"].get<std::vector<std::vector<double>>>());
      motion_of_step.push_back(static_cast<int>(motions.size()) - 1);
      last_waypoint = step_last_waypoint[static_cast<int>(s)];
    } else {
      motion_of_step.push_back(-1);
      actions.push_back({last_waypoint, step["action"] == "grasp" ? GripperAction::Grasp : GripperAction::Release});
    }
  }
  EXPECT_EQ(actions, path_actions(p.c.path));
  // Waypoints: rests exactly at a step's ends, the others by cubic interpolation at their time.
  ASSERT_EQ(j["waypoints"].size(), W.size());
  for (const auto& w : j["waypoints"]) {
    const size_t k = w["index"];
    const int step = w["step"];
    if (step < 0) {
      EXPECT_LT(error_at(j["start"].get<std::vector<double>>(), W[k].q, p.axes.arm), 1e-6);
      continue;
    }
    const auto& q = motions[motion_of_step[step]];
    const double x = w["time"].get<double>() * 1000.0;
    const long i0 = std::clamp(static_cast<long>(std::floor(x)) - 1, 0L, static_cast<long>(q.size()) - 4);
    std::vector<double> at(7, 0.0);
    for (long a = i0; a < i0 + 4; ++a) {
      double l = 1;
      for (long b = i0; b < i0 + 4; ++b)
        if (b != a) l *= (x - b) / static_cast<double>(a - b);
      for (size_t jj = 0; jj < 7; ++jj) at[jj] += l * q[a][jj];
    }
    if (p.trajectory.stops[k]) at = q.back();
    EXPECT_LT(error_at(at, W[k].q, p.axes.arm), 1e-6) << "waypoint " << k;
  }
  // What libfranka checks, by finite differences at 1 kHz, each step padded with rest.
  static const double vmax[7] = {2.175, 2.175, 2.175, 2.175, 2.61, 2.61, 2.61};
  static const double amax[7] = {15, 7.5, 10, 12.5, 15, 20, 20};
  static const double jmax[7] = {7500, 3750, 5000, 6250, 7500, 10000, 10000};
  for (auto q : motions) {
    q.insert(q.begin(), 2, q.front());
    q.insert(q.end(), 2, q.back());
    for (size_t i = 3; i < q.size(); ++i)
      for (size_t jj = 0; jj < 7; ++jj) {
        const double v = (q[i][jj] - q[i - 1][jj]) * 1e3;
        const double a = (q[i][jj] - 2 * q[i - 1][jj] + q[i - 2][jj]) * 1e6;
        const double jk = (q[i][jj] - 3 * q[i - 1][jj] + 3 * q[i - 2][jj] - q[i - 3][jj]) * 1e9;
        ASSERT_LE(std::abs(v), vmax[jj]) << i;
        ASSERT_LE(std::abs(a), amax[jj]) << i;
        ASSERT_LE(std::abs(jk), jmax[jj] * 1.01) << i;  // 1e-10 rad rounding in the file
      }
  }
}

void check_sampled_rows(const Prepared& p, const std::vector<std::vector<double>>& rows, const std::vector<int>& slots) {
  // Each waypoint, in order, is one of the rows.
  size_t from = 0;
  for (size_t k = 0; k < p.c.path.waypoints.size(); ++k) {
    bool found = false;
    for (size_t i = from; i < rows.size() && !found; ++i)
      if (error_at(rows[i], p.c.path.waypoints[k].q, slots) < 1e-6) found = true, from = i;
    EXPECT_TRUE(found) << "waypoint " << k;
  }
}

TEST_F(Export, RosYamlJointTrajectories) {
  for (const auto& [task, robot] : {std::pair{"waiter_0", "kmr_iiwa"}, std::pair{"shelf_1", "panda"}}) {
    const Prepared& p = prepared(task, robot);
    run(p, "ros-yaml", "pick.yaml");
    const std::string text = read_text(dir_ / "pick.yaml");
    std::vector<int> slots = p.axes.base;
    slots.insert(slots.end(), p.axes.arm.begin(), p.axes.arm.end());
    std::string names = "      joint_names: [";
    for (size_t i = 0; i < slots.size(); ++i) names += (i ? ", " : "") + p.limits.names[slots[i]];
    EXPECT_NE(text.find(names + "]"), std::string::npos) << names;
    std::vector<std::vector<double>> rows;
    Actions actions;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
      if (line.rfind("        - positions: [", 0) == 0) rows.push_back(numbers(line.substr(line.find('['))));
      if (line == "    gripper_after: grasp") actions.push_back({0, GripperAction::Grasp});
      if (line == "    gripper_after: release") actions.push_back({0, GripperAction::Release});
    }
    check_sampled_rows(p, rows, slots);
    Actions expected = path_actions(p.c.path);
    for (auto& a : expected) a.first = 0;
    EXPECT_EQ(actions, expected);
  }
}

TEST_F(Export, CsvRows) {
  const Prepared& p = prepared("shelf_1", "ur5");
  ExportOptions o;
  o.rate = 50;
  run(p, "csv", "pick.csv", o);
  std::istringstream in(read_text(dir_ / "pick.csv"));
  std::vector<std::vector<double>> rows;
  Actions actions;
  bool closed = false;
  std::string header;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    if (header.empty()) {
      header = line;
      EXPECT_EQ(line.rfind("time,shoulder_pan_joint,", 0), 0u) << line;
      continue;
    }
    const auto v = numbers(line);
    ASSERT_EQ(v.size(), 1 + 12 + 2u);
    rows.push_back(std::vector<double>(v.begin() + 1, v.begin() + 7));
    const bool now = v[13] == 1;
    const long waypoint = static_cast<long>(v[14]);
    if (waypoint >= 0) {
      EXPECT_LT(error_at(rows.back(), p.c.path.waypoints[waypoint].q, p.axes.arm), 1e-6);
    }
    if (now != closed) actions.push_back({static_cast<size_t>(waypoint), now ? GripperAction::Grasp : GripperAction::Release});
    closed = now;
  }
  check_sampled_rows(p, rows, p.axes.arm);
  EXPECT_EQ(actions, path_actions(p.c.path));
}

TEST_F(Export, FormatsRefuseRobotsThatDoNotFit) {
  const Prepared& panda = prepared("shelf_1", "panda");
  const Prepared& kmr = prepared("waiter_0", "kmr_iiwa");
  const Prepared& ur5 = prepared("shelf_1", "ur5");
  auto message = [&](const Prepared& p, const std::string& format, const std::string& file) {
    try {
      run(p, format, file);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message(panda, "urscript", "a.script").find("6-axis"), std::string::npos);
  EXPECT_NE(message(kmr, "krl", "a.src").find("mobile base"), std::string::npos);
  EXPECT_NE(message(ur5, "franka", "a.json").find("Panda"), std::string::npos);
  EXPECT_NE(message(ur5, "sunrise", "A.java").find("7-axis"), std::string::npos);
  EXPECT_NE(message(ur5, "krl", "9lives.src").find("module name"), std::string::npos);
  EXPECT_NE(message(ur5, "pdf", "a.pdf").find("unknown format"), std::string::npos);
}

std::string read_bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

TEST(ExportRegistry, ListsTheSixFormatsOnce) {
  EXPECT_EQ(program_format_ids(), (std::vector<std::string>{"urscript", "krl", "sunrise", "franka", "ros-yaml", "csv"}));
  std::set<std::string> ids, extensions;
  for (const ProgramWriter* w : program_writers()) {
    SCOPED_TRACE(w->id());
    ids.insert(w->id());
    extensions.insert(w->format().extension);
    EXPECT_FALSE(w->format().label.empty());
    EXPECT_EQ(w->format().extension.front(), '.');
    EXPECT_GT(w->format().default_rate, 0.0);
    EXPECT_EQ(find_program_writer(w->id()), w);
    const std::string name = w->file_name("shelf 1 panda");
    EXPECT_EQ(name.substr(name.size() - w->format().extension.size()), w->format().extension) << name;
  }
  EXPECT_EQ(ids.size(), program_writers().size());
  EXPECT_EQ(extensions.size(), program_writers().size());
  EXPECT_EQ(find_program_writer("pdf"), nullptr);
  try {
    program_writer("pdf", "out/a.pdf");
    ADD_FAILURE() << "no error for an unknown format";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("out/a.pdf"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("unknown format 'pdf'"), std::string::npos) << e.what();
  }
}

TEST(ExportRegistry, SampleRatesAndFileNames) {
  ExportOptions o;
  EXPECT_EQ(program_writer("urscript", "").sample_rate(o), 125.0);
  EXPECT_EQ(program_writer("csv", "").sample_rate(o), 100.0);
  EXPECT_EQ(program_writer("ros-yaml", "").sample_rate(o), 100.0);
  EXPECT_EQ(program_writer("franka", "").sample_rate(o), 1000.0);
  o.rate = 500;
  EXPECT_EQ(program_writer("urscript", "").sample_rate(o), 500.0);
  EXPECT_EQ(program_writer("csv", "").sample_rate(o), 500.0);
  EXPECT_EQ(program_writer("franka", "").sample_rate(o), 1000.0);  // libfranka's cycle, whatever the options
  EXPECT_EQ(program_writer("urscript", "").file_name("shelf 1"), "shelf_1.script");
  EXPECT_EQ(program_writer("franka", "").file_name("shelf_1"), "shelf_1.json");
  EXPECT_EQ(program_writer("krl", "").file_name("a_very_long_project_name_indeed"), "A_VERY_LONG_PROJECT_NAME.src");
  EXPECT_EQ(program_writer("sunrise", "").file_name("2 arms"), "Job2Arms.java");
}

// Every registered format: what write() holds in memory is byte for byte what reaches the disk.
TEST_F(Export, EveryFormatWritesToMemoryWhatItWritesToDisk) {
  const std::vector<const Prepared*> robots{&prepared("shelf_1", "ur5"), &prepared("shelf_1", "panda"),
                                            &prepared("waiter_0", "kmr_iiwa")};
  for (const ProgramWriter* w : program_writers()) {
    SCOPED_TRACE(w->id());
    const std::string file = (dir_ / w->file_name("same bytes")).string();
    std::optional<ProgramOutput> out;
    for (const Prepared* p : robots) {
      ExportOptions o;
      o.robot = p->c.path.robot;
      try {
        out = w->write(input(*p, o), file);
        break;
      } catch (const InputError&) {  // the format does not fit this robot: the next one
      }
    }
    ASSERT_TRUE(out) << "no test robot fits";
    ASSERT_FALSE(out->files.empty());
    EXPECT_EQ(out->files.front().name, file);
    for (const ProgramFile& f : out->files) EXPECT_FALSE(fs::exists(f.name)) << f.name << " written before asked";
    write_program_files(out->files);
    for (const ProgramFile& f : out->files) {
      EXPECT_GT(f.text.size(), 200u) << f.name;
      EXPECT_EQ(read_bytes(f.name), f.text) << f.name;
    }
  }
}

// The pipeline the CLI and the dialog share: timing, the check at the format's rate, the program
// in memory; the disk untouched.
TEST_F(Export, ExportJobChecksAtTheFormatsRateAndWritesNothing) {
  struct Case {
    std::string task, robot, format;
    double rate;
    bool servoj;
    double expected_rate;
  };
  for (const Case& c : {Case{"shelf_1", "ur5", "urscript", 0, true, 125}, Case{"shelf_1", "ur5", "csv", 0, false, 100},
                        Case{"shelf_1", "ur5", "csv", 50, false, 50}, Case{"shelf_1", "panda", "franka", 0, false, 1000}}) {
    SCOPED_TRACE(c.format + " " + c.robot);
    const Prepared& p = prepared(c.task, c.robot);
    ExportSettings s;
    s.format = c.format;
    s.rate = c.rate;
    s.servoj = c.servoj;
    s.source = "test.path.json";
    s.file = (dir_ / program_writer(c.format, "").file_name("job")).string();
    const ExportReport r = run_export_job(p.c.scene, p.c.path, s);
    EXPECT_EQ(r.rate_hz, c.expected_rate);
    EXPECT_TRUE(r.check_ok) << (r.violations.empty() ? "" : r.violations.front());
    EXPECT_GT(r.duration_s, 0.5);
    EXPECT_NEAR(r.trapezoid_ratio, r.trapezoid_duration_s / r.duration_s, 1e-12);
    EXPECT_GE(r.samples_checked, static_cast<size_t>(r.duration_s * c.expected_rate));
    EXPECT_LE(r.peak_velocity_ratio, 1.0);
    EXPECT_EQ(r.waypoints, p.c.path.waypoints.size());
    EXPECT_FALSE(r.limits.empty());
    ASSERT_EQ(r.files.size(), 1u);
    EXPECT_EQ(r.files.front().name, s.file);
    EXPECT_NE(r.files.front().text.find("test.path.json"), std::string::npos);  // the header names the source
    if (c.format != "urscript" || c.servoj) {
      EXPECT_GT(r.streamed_samples, 0u);
    }
    EXPECT_FALSE(fs::exists(s.file));
  }
  ExportSettings s;
  s.format = "urscript";
  s.file = "arm.script";
  try {
    run_export_job(prepared("shelf_1", "panda").c.scene, prepared("shelf_1", "panda").c.path, s);
    ADD_FAILURE() << "URScript accepted a 7-axis arm";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("arm.script"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("6-axis"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists("arm.script"));
}

// The report carries the timed trajectory for the dialog's plots: the exported joints, samples
// from start to end at every waypoint's time, the limits, and the rests with their gripper actions.
TEST_F(Export, ExportJobReportsTheTrajectoryForPlotting) {
  const Prepared& p = prepared("shelf_1", "panda");
  ExportSettings s;
  s.format = "csv";
  s.velocity_scale = 0.5;
  s.file = (dir_ / "job.csv").string();
  const ExportReport r = run_export_job(p.c.scene, p.c.path, s);
  ASSERT_TRUE(r.check_ok);
  const ExportTrajectory& t = r.trajectory;
  EXPECT_EQ(t.joints, p.axes.arm);  // a fixed arm: no base joints
  ASSERT_GE(t.samples.size(), 100u);
  EXPECT_LE(t.samples.size(), 2000u + p.c.path.waypoints.size() + 2);
  EXPECT_DOUBLE_EQ(t.samples.front().t, 0.0);
  EXPECT_NEAR(t.samples.back().t, r.duration_s, 1e-9);
  for (size_t i = 1; i < t.samples.size(); ++i) ASSERT_GT(t.samples[i].t, t.samples[i - 1].t);
  // The limits are the ones the export used: half the URDF's velocities.
  EXPECT_NEAR(t.limits.velocity[t.joints[0]], 0.5 * p.limits.velocity[t.joints[0]], 1e-12);
  EXPECT_EQ(t.rest_times.size(), r.rests);
  EXPECT_EQ(t.rest_actions.size(), r.rests);
  EXPECT_DOUBLE_EQ(t.rest_times.front(), 0.0);
  EXPECT_NEAR(t.rest_times.back(), r.duration_s, 1e-9);
  // Each sample within the velocity limit; the rests are where the robot stands still.
  for (const TrajectorySample& x : t.samples)
    for (int j : t.joints) ASSERT_LE(std::abs(x.v[j]), t.limits.velocity[j] * (1 + 1e-9));
  const Eigen::VectorXd v_rest = r.trajectory.samples.front().v;
  EXPECT_LT(v_rest.norm(), 1e-9);
  size_t grasps = 0;
  for (GripperAction a : t.rest_actions) grasps += a == GripperAction::Grasp;
  EXPECT_EQ(grasps, static_cast<size_t>(std::count_if(p.c.path.waypoints.begin(), p.c.path.waypoints.end(),
                                                      [](const Waypoint& w) { return w.action == GripperAction::Grasp; })));
}

}  // namespace
}  // namespace demoplan
