// The demonstration: every validation rule on hand-made demonstrations, the demonstrations the
// benchmark's subgoals give, the edits the operator makes, and the JSON file (round trip and
// every kind of broken file).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "core/demo/benchmark_demonstration.h"
#include "core/demo/benchmark_task.h"
#include "core/demo/demonstration.h"
#include "core/error.h"
#include "core/io/json_file.h"

using namespace demoplan;

static const std::string kData = DEMOPLAN_DATA_DIR;

namespace {

namespace fs = std::filesystem;

const std::vector<std::string> kTasksWithSubgoals{"shelf_0", "shelf_1", "shelf_2", "tunnel_0", "waiter_0"};

Pose pose_at(double x, double y, double z, double yaw = 0.0) {
  Pose T = Pose::Identity();
  T.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  T.translation() = Eigen::Vector3d(x, y, z);
  return T;
}

// Two objects A and B; A picked at frame 10 and placed at 20, then B picked at 30 and placed
// at 40. Valid.
Demonstration two_picks() {
  Demonstration d;
  d.task = "hand_made";
  d.fps = 25.0;
  d.object_ids = {"A", "B"};
  const PoseList p0{pose_at(0, 0, 0), pose_at(1, 0, 0)};
  const PoseList p1{pose_at(0, 1, 0, 0.5), pose_at(1, 0, 0)};
  const PoseList p2{pose_at(0, 1, 0, 0.5), pose_at(1, 1, 0, -0.3)};
  d.events = {{10, 0, EventType::Grasp, 0.9, p0, {}},
              {20, 0, EventType::Release, 0.8, p1, {}},
              {30, 1, EventType::Grasp, 1.0, p1, {}},
              {40, 1, EventType::Release, 0.5, p2, {}}};
  return d;
}

std::string all_messages(const std::vector<DemonstrationIssue>& issues) {
  std::string s;
  for (const auto& i : issues) s += "  [" + std::to_string(i.event) + "] " + i.message + "\n";
  return s;
}

// Exactly one issue, at `event`, whose message contains every part.
void expect_one_issue(const Demonstration& d, int event, const std::vector<std::string>& parts) {
  const auto issues = validate(d);
  ASSERT_EQ(issues.size(), 1u) << all_messages(issues);
  EXPECT_EQ(issues[0].event, event) << issues[0].message;
  for (const auto& p : parts)
    EXPECT_NE(issues[0].message.find(p), std::string::npos) << "'" << p << "' not in: " << issues[0].message;
}

bool exactly_equal(const Pose& a, const Pose& b) { return a.matrix() == b.matrix(); }

// Runs f, which must throw InputError; returns what() ("" and a failure otherwise).
std::string input_error(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "threw a non-InputError exception: " << e.what();
    return "";
  }
  ADD_FAILURE() << "no exception thrown";
  return "";
}

void expect_mentions(const std::string& what, const std::vector<std::string>& parts) {
  for (const auto& p : parts) EXPECT_NE(what.find(p), std::string::npos) << "'" << p << "' not in: " << what;
}

// The task files, loaded once for the whole binary.
const BenchmarkTask& task(const std::string& name) {
  static std::map<std::string, BenchmarkTask> cache;
  auto it = cache.find(name);
  if (it == cache.end()) it = cache.emplace(name, load_benchmark_task(kData, name)).first;
  return it->second;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Validation rules, one test each.

TEST(DemonstrationValidate, HandMadeDemonstrationIsValid) {
  const auto issues = validate(two_picks());
  EXPECT_TRUE(issues.empty()) << all_messages(issues);
}

TEST(DemonstrationValidate, NoEvents) {
  Demonstration d = two_picks();
  d.events.clear();
  expect_one_issue(d, -1, {"no grasp or release event"});
}

TEST(DemonstrationValidate, NoObjects) {
  Demonstration d;
  d.task = "empty";
  const auto issues = validate(d);
  ASSERT_EQ(issues.size(), 2u) << all_messages(issues);  // no object, and so no event either
  EXPECT_EQ(issues[0].event, -1);
  EXPECT_NE(issues[0].message.find("names no object"), std::string::npos) << issues[0].message;
  EXPECT_NE(issues[1].message.find("no grasp or release event"), std::string::npos) << issues[1].message;
}

TEST(DemonstrationValidate, ReleaseWithoutGrasp) {
  Demonstration d = two_picks();
  d.events.erase(d.events.begin() + 2);  // B's grasp: B's release at 40 is now without one
  expect_one_issue(d, 2, {"release of B", "frame 40", "release without a grasp"});
}

TEST(DemonstrationValidate, GraspOfAnObjectAlreadyHeld) {
  Demonstration d = two_picks();
  d.events[1].type = EventType::Grasp;  // A grasped at 10 and again at 20
  const auto issues = validate(d);
  ASSERT_GE(issues.size(), 1u);
  EXPECT_EQ(issues[0].event, 1) << all_messages(issues);
  expect_mentions(issues[0].message, {"grasp of A", "frame 20", "already held"});
  // Grasped twice and never released (B's grasp at 30 while A is held is reported as well).
  bool never_released = false;
  for (const auto& i : issues)
    if (i.event == -1 && i.message.find("A is grasped but never released") != std::string::npos) never_released = true;
  EXPECT_TRUE(never_released) << all_messages(issues);
}

TEST(DemonstrationValidate, TwoObjectsHeldAtOnce) {
  Demonstration d = two_picks();
  d.events[2].frame = 15;  // B grasped at 15 while A is held until 20
  std::swap(d.events[1], d.events[2]);
  expect_one_issue(d, 1, {"grasp of B", "frame 15", "A is still held", "one object at a time"});
}

TEST(DemonstrationValidate, GraspNeverReleased) {
  Demonstration d = two_picks();
  d.events.pop_back();  // B's release
  expect_one_issue(d, -1, {"B", "grasped but never released"});
}

TEST(DemonstrationValidate, EventsOutOfFrameOrder) {
  Demonstration d = two_picks();
  d.events[2].frame = 5;  // B's grasp at 5, listed after A's release at 20
  expect_one_issue(d, 2, {"grasp of B", "frame 5", "comes before", "frame 20"});
}

TEST(DemonstrationValidate, EqualFramesAreInOrder) {
  Demonstration d = two_picks();
  d.events[2].frame = 20;  // B picked in the frame A is placed
  EXPECT_TRUE(validate(d).empty()) << all_messages(validate(d));
}

TEST(DemonstrationValidate, WrongNumberOfPoses) {
  Demonstration d = two_picks();
  d.events[1].poses.pop_back();
  expect_one_issue(d, 1, {"release of A", "frame 20", "1 object poses", "expected 2"});
  d = two_picks();
  d.events[3].poses.push_back(Pose::Identity());
  expect_one_issue(d, 3, {"release of B", "frame 40", "3 object poses", "expected 2"});
}

TEST(DemonstrationValidate, NanPose) {
  Demonstration d = two_picks();
  d.events[2].poses[1].translation().y() = std::numeric_limits<double>::quiet_NaN();
  expect_one_issue(d, 2, {"grasp of B", "frame 30", "pose of B", "not finite"});
  d = two_picks();
  d.events[0].poses[0].linear()(1, 2) = std::numeric_limits<double>::infinity();
  expect_one_issue(d, 0, {"grasp of A", "frame 10", "pose of A", "not finite"});
}

TEST(DemonstrationValidate, NonOrthonormalRotation) {
  Demonstration d = two_picks();
  d.events[1].poses[1].linear() *= 1.001;  // scaled
  expect_one_issue(d, 1, {"release of A", "frame 20", "rotation of B", "not orthonormal"});
  d = two_picks();
  d.events[3].poses[0].linear().col(2) *= -1.0;  // a reflection: orthogonal, determinant -1
  expect_one_issue(d, 3, {"release of B", "frame 40", "rotation of A", "not orthonormal"});
  // Within the tolerance (1e-5) of a rotation: accepted, as the raw video poses need.
  d = two_picks();
  d.events[3].poses[0].linear() *= 1.0 + 1e-7;
  EXPECT_TRUE(validate(d).empty()) << all_messages(validate(d));
}

TEST(DemonstrationValidate, ConfidenceOutOfRange) {
  for (double c : {-0.01, 1.01, std::numeric_limits<double>::quiet_NaN()}) {
    SCOPED_TRACE(c);
    Demonstration d = two_picks();
    d.events[2].confidence = c;
    expect_one_issue(d, 2, {"grasp of B", "frame 30", "confidence", "[0, 1]"});
  }
  Demonstration d = two_picks();
  d.events[0].confidence = 0.0;
  d.events[1].confidence = 1.0;
  EXPECT_TRUE(validate(d).empty()) << all_messages(validate(d));
}

TEST(DemonstrationValidate, WrongNumberOfPoseFrames) {
  Demonstration d = two_picks();
  d.events[2].pose_frames = {"kmr_link"};
  expect_one_issue(d, 2, {"grasp of B", "frame 30", "1 pose frames", "expected 2"});
  d.events[2].pose_frames = {"", "kmr_link"};  // one per object: fine
  EXPECT_TRUE(validate(d).empty()) << all_messages(validate(d));
}

TEST(DemonstrationValidate, UnknownObjectIndex) {
  Demonstration d = two_picks();
  d.events[3].object = 2;
  const auto issues = validate(d);
  ASSERT_GE(issues.size(), 1u);
  EXPECT_EQ(issues[0].event, 3) << all_messages(issues);
  expect_mentions(issues[0].message, {"event 3", "unknown object"});
}

// ---------------------------------------------------------------------------------------------
// Demonstrations from the benchmark's subgoals.

TEST(BenchmarkDemonstration, EveryTaskWithSubgoalsGivesAValidDemonstration) {
  for (const auto& name : kTasksWithSubgoals) {
    SCOPED_TRACE(name);
    const BenchmarkTask& t = task(name);
    const Demonstration d = demonstration_from_subgoals(t);
    const auto issues = validate(d);
    EXPECT_TRUE(issues.empty()) << all_messages(issues);
    EXPECT_EQ(d.task, name);
    EXPECT_EQ(d.object_ids, t.planning_object_ids);

    // The segments, independently from the file's convenience field "contact_segments".
    const Json json = read_json_file(t.file);
    const Json& expected = json.at("contact_segments");
    const auto segments = contact_segments(t);
    ASSERT_EQ(segments.size(), expected.size());
    for (size_t k = 0; k < segments.size(); ++k) {
      EXPECT_EQ(segments[k].object, expected[k].at("object_index").get<int>()) << k;
      EXPECT_EQ(segments[k].first, expected[k].at("first").get<int>()) << k;
      EXPECT_EQ(segments[k].last, expected[k].at("last").get<int>()) << k;
    }
    // Two columns per segment (README 4.1).
    ASSERT_EQ(t.subgoal_poses.size(), t.planning_object_ids.size());
    ASSERT_EQ(t.subgoal_poses.front().size(), 2 * segments.size());

    ASSERT_EQ(d.events.size(), 2 * segments.size());
    for (size_t k = 0; k < segments.size(); ++k) {
      SCOPED_TRACE("segment " + std::to_string(k));
      const ContactEvent& g = d.events[2 * k];
      const ContactEvent& r = d.events[2 * k + 1];
      EXPECT_EQ(g.type, EventType::Grasp);
      EXPECT_EQ(r.type, EventType::Release);
      EXPECT_EQ(g.object, segments[k].object);
      EXPECT_EQ(r.object, segments[k].object);
      EXPECT_EQ(g.frame, segments[k].first);
      EXPECT_EQ(r.frame, segments[k].last + 1);
      EXPECT_EQ(g.confidence, 1.0);
      EXPECT_EQ(r.confidence, 1.0);
      ASSERT_EQ(g.poses.size(), t.planning_object_ids.size());
      ASSERT_EQ(r.poses.size(), t.planning_object_ids.size());
      for (size_t o = 0; o < t.planning_object_ids.size(); ++o) {
        EXPECT_TRUE(exactly_equal(g.poses[o], t.subgoal_poses[o][2 * k])) << "object " << o;
        EXPECT_TRUE(exactly_equal(r.poses[o], t.subgoal_poses[o][2 * k + 1])) << "object " << o;
      }
      // The contacts are true exactly within the segment.
      size_t row = 0;
      for (size_t seen = 0; row < t.objects.size(); ++row)
        if (t.objects[row].in_planning_model && seen++ == static_cast<size_t>(segments[k].object)) break;
      ASSERT_LT(row, t.contacts.size());
      const auto& c = t.contacts[row];
      for (int f = segments[k].first; f <= segments[k].last; ++f) EXPECT_TRUE(c[f]) << f;
      if (segments[k].first > 0) {
        EXPECT_FALSE(c[segments[k].first - 1]);
      }
      if (segments[k].last + 1 < static_cast<int>(c.size())) {
        EXPECT_FALSE(c[segments[k].last + 1]);
      }
    }
  }
}

TEST(BenchmarkDemonstration, TaskWithoutSubgoalsIsAnInputError) {
  const BenchmarkTask& t = task("test_0");
  ASSERT_TRUE(t.subgoal_poses.empty());
  const std::string what = input_error([&] { demonstration_from_subgoals(t); });
  expect_mentions(what, {t.file, "subgoal_objects_poses", "no subgoals"});
}

// ---------------------------------------------------------------------------------------------
// Edits.

TEST(DemonstrationEdit, InsertKeepsFrameOrder) {
  Demonstration d = two_picks();
  // Room for every insertion: see InsertReturnsTheIndexWhenTheEventsGrow for what happens
  // when the vector reallocates.
  d.events.reserve(16);
  const PoseList p = d.events[0].poses;
  EXPECT_EQ(insert_event(d, {25, 1, EventType::Grasp, 0.3, p, {}}), 2u);
  EXPECT_EQ(insert_event(d, {0, 0, EventType::Grasp, 0.3, p, {}}), 0u);
  const size_t last = insert_event(d, {99, 0, EventType::Release, 0.3, p, {}});
  EXPECT_EQ(last, d.events.size() - 1);
  // An event at the frame of existing ones goes after them.
  const size_t at = insert_event(d, {20, 1, EventType::Release, 0.7, p, {}});
  ASSERT_LT(at, d.events.size());
  EXPECT_EQ(d.events[at].frame, 20);
  EXPECT_EQ(d.events[at].confidence, 0.7);
  EXPECT_EQ(d.events[at - 1].frame, 20);
  EXPECT_GT(d.events[at + 1].frame, 20);
  ASSERT_EQ(d.events.size(), 8u);
  for (size_t i = 1; i < d.events.size(); ++i) EXPECT_LE(d.events[i - 1].frame, d.events[i].frame);
  EXPECT_EQ(d.events.front().frame, 0);
  EXPECT_EQ(d.events.back().frame, 99);
}

// Disabled: insert_event (core/demo/demonstration.cpp:96) returns
// `d.events.insert(it, e) - d.events.begin()`; the two operands of the overloaded iterator
// operator- are unsequenced, and GCC evaluates d.events.begin() first, so when insert()
// reallocates the vector the result is the distance to the freed buffer (garbage such as
// 12297829382473034432). Fix: `const auto index = it - d.events.begin();
// d.events.insert(it, std::move(e)); return static_cast<size_t>(index);`.
TEST(DemonstrationEdit, InsertReturnsTheIndexWhenTheEventsGrow) {
  for (size_t extra = 0; extra < 8; ++extra) {
    Demonstration d = two_picks();
    d.events.shrink_to_fit();
    for (size_t k = 0; k < extra; ++k) {
      const size_t index = insert_event(d, {100 + static_cast<int>(k), 0, EventType::Grasp, 1.0, {}, {}});
      ASSERT_EQ(index, d.events.size() - 1) << "capacity " << d.events.capacity();
    }
    d.events.shrink_to_fit();  // the next insertion reallocates
    const size_t index = insert_event(d, {15, 1, EventType::Grasp, 1.0, {}, {}});
    EXPECT_EQ(index, 1u) << "with " << extra << " extra events";
    ASSERT_GE(d.events.size(), 2u);
    EXPECT_EQ(d.events[1].frame, 15);
  }
}

TEST(DemonstrationEdit, MoveReordersAndReturnsTheNewIndex) {
  Demonstration d = two_picks();
  // A's grasp (10) after B's grasp (30): index 0 -> 2.
  EXPECT_EQ(move_event(d, 0, 35), 2u);
  ASSERT_EQ(d.events.size(), 4u);
  EXPECT_EQ(d.events[2].frame, 35);
  EXPECT_EQ(d.events[2].object, 0);
  EXPECT_EQ(d.events[2].type, EventType::Grasp);
  EXPECT_EQ(d.events[2].confidence, 0.9);  // the rest of the event travels with it
  EXPECT_TRUE(exactly_equal(d.events[2].poses[1], pose_at(1, 0, 0)));
  for (size_t i = 1; i < d.events.size(); ++i) EXPECT_LE(d.events[i - 1].frame, d.events[i].frame);
  // Back to the front.
  EXPECT_EQ(move_event(d, 2, 1), 0u);
  EXPECT_EQ(d.events[0].frame, 1);
  EXPECT_EQ(d.events[0].object, 0);
  // Within its neighbours: stays.
  EXPECT_EQ(move_event(d, 1, 21), 1u);
  EXPECT_EQ(d.events[1].frame, 21);
  // To the end.
  EXPECT_EQ(move_event(d, 0, 1000), 3u);
  EXPECT_EQ(d.events[3].frame, 1000);
  EXPECT_THROW(move_event(d, 4, 5), std::out_of_range);
}

TEST(DemonstrationEdit, RemoveAndSetObjectPose) {
  Demonstration d = two_picks();
  remove_event(d, 1);
  ASSERT_EQ(d.events.size(), 3u);
  EXPECT_EQ(d.events[0].frame, 10);
  EXPECT_EQ(d.events[1].frame, 30);
  EXPECT_EQ(d.events[2].frame, 40);
  EXPECT_THROW(remove_event(d, 3), std::out_of_range);

  const Pose p = pose_at(0.3, -0.2, 0.9, 1.2);
  set_object_pose(d, 2, 0, p);
  EXPECT_TRUE(exactly_equal(d.events[2].poses[0], p));
  EXPECT_TRUE(exactly_equal(d.events[2].poses[1], pose_at(1, 1, 0, -0.3)));  // the other unchanged
  EXPECT_TRUE(exactly_equal(d.events[1].poses[0], pose_at(0, 1, 0, 0.5)));   // other events unchanged
  EXPECT_THROW(set_object_pose(d, 3, 0, p), std::out_of_range);
  EXPECT_THROW(set_object_pose(d, 0, 2, p), std::out_of_range);
  EXPECT_THROW(set_object_pose(d, 0, -1, p), std::out_of_range);
}

TEST(DemonstrationEdit, ValidateFollowsBadEditsAndTheirUndo) {
  const Demonstration original = demonstration_from_subgoals(task("shelf_1"));
  ASSERT_TRUE(validate(original).empty());
  Demonstration d = original;
  const std::string second = d.object_ids[d.events[2].object];

  // Moving the first release before its grasp.
  const int release_frame = d.events[1].frame;
  const size_t moved = move_event(d, 1, d.events[0].frame - 1);
  EXPECT_EQ(moved, 0u);
  auto issues = validate(d);
  ASSERT_FALSE(issues.empty());
  EXPECT_EQ(issues[0].event, 0);
  EXPECT_NE(issues[0].message.find("release without a grasp"), std::string::npos) << all_messages(issues);
  EXPECT_EQ(move_event(d, moved, release_frame), 1u);
  EXPECT_TRUE(validate(d).empty()) << all_messages(validate(d));

  // Moving the second grasp into the first segment.
  const int grasp_frame = d.events[2].frame;
  EXPECT_EQ(move_event(d, 2, d.events[0].frame + 1), 1u);
  issues = validate(d);
  ASSERT_EQ(issues.size(), 1u) << all_messages(issues);
  EXPECT_EQ(issues[0].event, 1);
  EXPECT_NE(issues[0].message.find("grasp of " + second), std::string::npos) << issues[0].message;
  EXPECT_NE(issues[0].message.find("one object at a time"), std::string::npos) << issues[0].message;
  EXPECT_EQ(move_event(d, 1, grasp_frame), 2u);
  EXPECT_TRUE(validate(d).empty());

  // Removing the last release, then inserting it back.
  const ContactEvent last = d.events.back();
  remove_event(d, d.events.size() - 1);
  issues = validate(d);
  ASSERT_EQ(issues.size(), 1u) << all_messages(issues);
  EXPECT_NE(issues[0].message.find(d.object_ids[last.object] + " is grasped but never released"), std::string::npos)
      << issues[0].message;
  const size_t reinserted = insert_event(d, last);
  EXPECT_EQ(reinserted, d.events.size() - 1);
  EXPECT_TRUE(validate(d).empty());

  // A non-orthonormal pose, then the original one.
  const Pose good = d.events[1].poses[1];
  Pose bad = good;
  bad.linear()(0, 1) += 0.01;
  set_object_pose(d, 1, 1, bad);
  issues = validate(d);
  ASSERT_EQ(issues.size(), 1u) << all_messages(issues);
  EXPECT_EQ(issues[0].event, 1);
  EXPECT_NE(issues[0].message.find("rotation of " + d.object_ids[1]), std::string::npos) << issues[0].message;
  set_object_pose(d, 1, 1, good);
  EXPECT_TRUE(validate(d).empty());

  // After all that the demonstration is the original again.
  ASSERT_EQ(d.events.size(), original.events.size());
  for (size_t i = 0; i < d.events.size(); ++i) {
    EXPECT_EQ(d.events[i].frame, original.events[i].frame);
    EXPECT_EQ(d.events[i].object, original.events[i].object);
    EXPECT_EQ(d.events[i].type, original.events[i].type);
    for (size_t o = 0; o < d.object_ids.size(); ++o)
      EXPECT_TRUE(exactly_equal(d.events[i].poses[o], original.events[i].poses[o]));
  }
}

// ---------------------------------------------------------------------------------------------
// JSON files.

class DemonstrationFile : public ::testing::Test {
protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("demoplan_test_demonstration_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  // A valid file of shelf_1's demonstration, edited by `edit`, written to `name`.
  std::string broken(const std::string& name, const std::function<void(Json&)>& edit) const {
    const std::string valid = path("valid_" + name);
    save_demonstration(valid, demonstration_from_subgoals(task("shelf_1")));
    Json j = read_json_file(valid);
    edit(j);
    const std::string p = path(name);
    std::ofstream(p) << j.dump(1);
    return p;
  }

  fs::path dir_;
};

TEST_F(DemonstrationFile, SaveThenLoadRoundTripsBitForBit) {
  for (const auto& name : kTasksWithSubgoals) {
    SCOPED_TRACE(name);
    Demonstration d = demonstration_from_subgoals(task(name));
    // Confidences and poses with every bit of the mantissa in use.
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (auto& e : d.events) {
      e.confidence = u(rng);
      Pose T = Pose::Identity();
      T.linear() = Eigen::Quaterniond(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5).normalized().toRotationMatrix();
      T.translation() = Eigen::Vector3d(u(rng), -u(rng), 1e-7 * u(rng));
      e.poses.back() = T;
    }
    d.events.front().confidence = 1.0;
    d.events.back().confidence = 0.0;
    d.fps = 29.97;
    const std::string file = path(name + ".json");
    save_demonstration(file, d);
    for (const auto& entry : fs::directory_iterator(fs::path(file).parent_path()))
      EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos) << entry.path();  // no temporary left
    const Demonstration l = load_demonstration(file);
    EXPECT_EQ(l.task, d.task);
    EXPECT_EQ(l.fps, d.fps);
    EXPECT_EQ(l.object_ids, d.object_ids);
    ASSERT_EQ(l.events.size(), d.events.size());
    for (size_t i = 0; i < d.events.size(); ++i) {
      SCOPED_TRACE("event " + std::to_string(i));
      EXPECT_EQ(l.events[i].frame, d.events[i].frame);
      EXPECT_EQ(l.events[i].object, d.events[i].object);
      EXPECT_EQ(l.events[i].type, d.events[i].type);
      EXPECT_EQ(l.events[i].confidence, d.events[i].confidence);
      ASSERT_EQ(l.events[i].poses.size(), d.events[i].poses.size());
      for (size_t o = 0; o < d.events[i].poses.size(); ++o)
        EXPECT_TRUE(exactly_equal(l.events[i].poses[o], d.events[i].poses[o]))
            << "object " << o << "\n" << l.events[i].poses[o].matrix() << "\n" << d.events[i].poses[o].matrix();
    }
    EXPECT_TRUE(validate(l).empty());
    // Saving what was loaded gives the same file.
    const std::string again = path(name + "_again.json");
    save_demonstration(again, l);
    EXPECT_EQ(read_json_file(file), read_json_file(again));
  }
}

TEST_F(DemonstrationFile, PoseFramesRoundTrip) {
  Demonstration d = two_picks();
  d.events[1].pose_frames = {"kmr_link", ""};
  d.events[3].pose_frames = {"", "base_link"};
  const std::string file = path("frames.json");
  save_demonstration(file, d);
  const Demonstration l = load_demonstration(file);
  ASSERT_EQ(l.events.size(), 4u);
  EXPECT_TRUE(l.events[0].pose_frames.empty());
  EXPECT_EQ(l.events[1].pose_frames, (std::vector<std::string>{"kmr_link", ""}));
  EXPECT_EQ(l.events[3].pose_frames, (std::vector<std::string>{"", "base_link"}));
  EXPECT_EQ(l.events[1].pose_frame(0), "kmr_link");
  EXPECT_EQ(l.events[0].pose_frame(1), "");
  // An object the demonstration does not have.
  Json j = read_json_file(file);
  j["events"][1]["pose_frames"]["C"] = "kmr_link";
  const std::string broken_file = path("frames_broken.json");
  std::ofstream(broken_file) << j.dump(1);
  expect_mentions(input_error([&] { load_demonstration(broken_file); }),
                  {broken_file, "events[1].pose_frames", "'C' is not in objects"});
}

TEST_F(DemonstrationFile, DoubtsRoundTripAndBadOnesNameTheirField) {
  Demonstration d = two_picks();
  d.doubts = {{1, 10, 24, "B moves from the start of the video"}, {0, 40, 40, "A: frame 40: not rigid"}};
  const std::string file = path("doubts.json");
  save_demonstration(file, d);
  const Demonstration l = load_demonstration(file);
  ASSERT_EQ(l.doubts.size(), 2u);
  EXPECT_EQ(l.doubts[0].object, 1);
  EXPECT_EQ(l.doubts[0].first_frame, 10);
  EXPECT_EQ(l.doubts[0].last_frame, 24);
  EXPECT_EQ(l.doubts[1].message, "A: frame 40: not rigid");
  EXPECT_TRUE(validate(l).empty());  // doubts do not stop planning
  // Without doubts the key is left out, as files of earlier versions have it.
  save_demonstration(file, two_picks());
  EXPECT_FALSE(read_json_file(file).contains("doubts"));
  Json j = read_json_file(file);
  j["doubts"] = Json::array({{{"object", "A"}, {"first_frame", 9}, {"last_frame", 3}, {"message", "m"}}});
  const std::string backwards = path("doubts_backwards.json");
  std::ofstream(backwards) << j.dump(1);
  expect_mentions(input_error([&] { load_demonstration(backwards); }), {backwards, "doubts[0].last_frame"});
  j["doubts"][0]["object"] = "Z";
  const std::string unknown = path("doubts_unknown.json");
  std::ofstream(unknown) << j.dump(1);
  expect_mentions(input_error([&] { load_demonstration(unknown); }), {unknown, "doubts[0].object", "'Z' is not in objects"});
}

TEST_F(DemonstrationFile, SaveOverwritesAnExistingFile) {
  const std::string file = path("d.json");
  std::ofstream(file) << "not json";
  Demonstration d = two_picks();
  save_demonstration(file, d);
  EXPECT_EQ(load_demonstration(file).events.size(), 4u);
}

TEST_F(DemonstrationFile, UnknownVersion) {
  const std::string f = broken("version.json", [](Json& j) { j["version"] = 2; });
  expect_mentions(input_error([&] { load_demonstration(f); }), {f, "version", "unsupported version 2"});
}

TEST_F(DemonstrationFile, WrongFormatName) {
  const std::string f = broken("format.json", [](Json& j) { j["format"] = "demoplan-scene"; });
  expect_mentions(input_error([&] { load_demonstration(f); }), {f, "format", "demoplan-demonstration"});
  const std::string missing = broken("no_format.json", [](Json& j) { j.erase("format"); });
  expect_mentions(input_error([&] { load_demonstration(missing); }), {missing, "format", "missing"});
}

TEST_F(DemonstrationFile, UnknownObjectName) {
  const std::string f = broken("object.json", [](Json& j) { j["events"][2]["object"] = "YCBV_99"; });
  expect_mentions(input_error([&] { load_demonstration(f); }), {f, "events[2].object", "YCBV_99", "not in objects"});
}

TEST_F(DemonstrationFile, BadTypeString) {
  const std::string f = broken("type.json", [](Json& j) { j["events"][1]["type"] = "Release"; });
  expect_mentions(input_error([&] { load_demonstration(f); }), {f, "events[1].type", "'grasp' or 'release'"});
}

TEST_F(DemonstrationFile, NonOrthonormalRotation) {
  const std::string f = broken("rotation.json", [](Json& j) { j["events"][3]["poses"]["YCBV_05"][0][1] = 0.5; });
  expect_mentions(input_error([&] { load_demonstration(f); }), {f, "events[3].poses.YCBV_05", "orthonormal"});
}

TEST_F(DemonstrationFile, OtherBrokenFields) {
  struct Case {
    std::string name;
    std::function<void(Json&)> edit;
    std::vector<std::string> parts;
  };
  const std::vector<Case> cases{
      {"missing_pose", [](Json& j) { j["events"][0]["poses"].erase("YCBV_02"); }, {"events[0].poses.YCBV_02", "missing"}},
      {"null_pose_cell", [](Json& j) { j["events"][1]["poses"]["YCBV_02"][2][3] = nullptr; }, {"events[1].poses.YCBV_02[2][3]"}},
      {"negative_frame", [](Json& j) { j["events"][0]["frame"] = -3; }, {"events[0].frame", ">= 0"}},
      {"fractional_frame", [](Json& j) { j["events"][0]["frame"] = 3.5; }, {"events[0].frame", "integer"}},
      {"zero_fps", [](Json& j) { j["fps"] = 0; }, {"fps", "> 0"}},
      {"no_events", [](Json& j) { j.erase("events"); }, {"events", "missing"}},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    const std::string f = broken(c.name + ".json", c.edit);
    auto parts = c.parts;
    parts.push_back(f);
    expect_mentions(input_error([&] { load_demonstration(f); }), parts);
  }
  // Not JSON, and no file at all.
  const std::string garbage = path("garbage.json");
  std::ofstream(garbage) << "{\"format\": ";
  expect_mentions(input_error([&] { load_demonstration(garbage); }), {garbage, "invalid JSON"});
  expect_mentions(input_error([&] { load_demonstration(path("absent.json")); }), {"absent.json", "cannot open"});
}

TEST_F(DemonstrationFile, ConfidenceIsOptionalAndDefaultsToOne) {
  const std::string f = broken("no_confidence.json", [](Json& j) { j["events"][0].erase("confidence"); });
  const Demonstration d = load_demonstration(f);
  EXPECT_EQ(d.events[0].confidence, 1.0);
}
