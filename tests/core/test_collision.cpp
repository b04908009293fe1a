// Hand-made colliding and near-miss configurations on the real shelf_1 scene.
#include <gtest/gtest.h>

#include <random>
#include <thread>

#include "core/demo/benchmark_scene.h"
#include "core/scene/collision_checker.h"

using namespace demoplan;

static const std::string kData = DEMOPLAN_DATA_DIR;

namespace {

bool any_pair(const std::vector<CollisionPair>& pairs, const std::string& a, const std::string& b) {
  for (const auto& p : pairs)
    if ((p.first.find(a) != std::string::npos && p.second.find(b) != std::string::npos) ||
        (p.first.find(b) != std::string::npos && p.second.find(a) != std::string::npos))
      return true;
  return false;
}

class ShelfScene : public ::testing::Test {
protected:
  static void SetUpTestSuite() {
    task_ = new BenchmarkTask(load_benchmark_task(kData, "shelf_1"));
    scene_ = new Scene(build_benchmark_scene(*task_, "panda", 0));
    checker_ = new CollisionChecker(*scene_);
  }
  static void TearDownTestSuite() {
    delete checker_;
    delete scene_;
    delete task_;
  }

  SceneState start() const { return benchmark_start_state(*task_, *scene_); }
  const SceneFurniture& furniture(const std::string& kind) const {
    for (const auto& f : scene_->furniture)
      if (f.kind == kind) return f;
    throw std::runtime_error("no " + kind);
  }
  // Lowest point of object o's mesh in its own frame (metres, URDF scale applied).
  double object_bottom(int o) const {
    const auto& g = scene_->objects[o].model.links[0].collisions[0];
    const auto& m = std::get<MeshShape>(g.shape);
    return m.mesh->bounds().min().z() * m.scale.z();
  }
  Eigen::VectorXd random_q(std::mt19937_64& rng) const {
    const auto& model = scene_->robot.model;
    const Eigen::VectorXd lo = model.lower_limits(), hi = model.upper_limits();
    std::uniform_real_distribution<double> u(0, 1);
    Eigen::VectorXd q(model.nq);
    for (int i = 0; i < model.nq; ++i) q[i] = lo[i] + u(rng) * (hi[i] - lo[i]);
    return q;
  }

  static BenchmarkTask* task_;
  static Scene* scene_;
  static CollisionChecker* checker_;
};
BenchmarkTask* ShelfScene::task_ = nullptr;
Scene* ShelfScene::scene_ = nullptr;
CollisionChecker* ShelfScene::checker_ = nullptr;

}  // namespace

TEST_F(ShelfScene, ArmThroughTheTableCollidesWithTheTable) {
  // Search seeded random configurations for one whose hand is 5 cm below the table top,
  // well inside the table's outline: the arm must then pass through the top.
  const auto& table = furniture("table");
  const Pose& top = table.link_poses[table.model.link_index("desk")];
  std::mt19937_64 rng(7);
  auto data = checker_->make_data();
  int found = 0;
  for (int i = 0; i < 200000 && found < 5; ++i) {
    SceneState s = start();
    s.q = random_q(rng);
    const Eigen::Vector3d hand = top.inverse() * gripper_pose(*scene_, s.q).translation();
    if (hand.z() > -0.05 || hand.z() < -0.3 || std::abs(hand.x()) > 0.4 || std::abs(hand.y()) > 0.25) continue;
    ++found;
    EXPECT_TRUE(checker_->in_collision(s, data));
    EXPECT_TRUE(any_pair(checker_->collisions(s, data), "robot/", "_table/desk"));
  }
  EXPECT_EQ(found, 5);
}

TEST_F(ShelfScene, ObjectInsideAShelfBoardCollidesWithIt) {
  const auto& shelf = furniture("shelf");
  const Pose& board = shelf.link_poses[shelf.model.link_index("top_desk")];
  SceneState s = start();
  s.objects[1] = board;  // object centre at the board's top surface: half of it in the board
  auto data = checker_->make_data();
  EXPECT_TRUE(any_pair(checker_->collisions(s, data), "object/YCBV_05", "_shelf/top_desk"));
}

TEST_F(ShelfScene, GripperInsideAnObjectCollides) {
  SceneState s = start();
  s.objects[0] = gripper_pose(*scene_, s.q);  // object centred between the closed fingers
  auto data = checker_->make_data();
  const auto pairs = checker_->collisions(s, data);
  EXPECT_TRUE(any_pair(pairs, "object/YCBV_02", "robot/panda_"));
  // Allowing the gripper's links leaves no robot contact (the arm does not reach the object).
  AllowedContacts allowed;
  allowed.allow_gripper(*scene_, 0);
  EXPECT_FALSE(any_pair(checker_->collisions(s, data, allowed), "object/YCBV_02", "robot/"));
}

TEST_F(ShelfScene, ObjectOneMillimetreAboveTheTableIsFreeAndOneBelowCollides) {
  const auto& table = furniture("table");
  const Pose& top = table.link_poses[table.model.link_index("desk")];
  auto data = checker_->make_data();
  SceneState s = start();
  const int o = 0;
  s.objects[1].translation().x() += 10.0;  // the other object rests 1 mm from the shelf: away
  s.objects[o].linear().setIdentity();  // upright, so the mesh's lowest z is its bottom
  s.objects[o].translation() = top.translation();  // table centre, clear of the robot's box
  s.objects[o].translation().z() += -object_bottom(o) + 0.001;
  ASSERT_FALSE(checker_->in_collision(s, data));
  const DistanceResult d = checker_->distance(s, data);
  EXPECT_NEAR(d.distance, 0.001, 1e-5);
  EXPECT_NE(d.pair.second.find("_table/desk"), std::string::npos);

  s.objects[o].translation().z() -= 0.002;  // 1 mm into the table top
  EXPECT_TRUE(any_pair(checker_->collisions(s, data), "object/YCBV_02", "_table/desk"));
  // Resting on the table is an allowed contact.
  AllowedContacts rests;
  rests.allow_object_furniture(o, static_cast<int>(&table - scene_->furniture.data()));
  EXPECT_FALSE(any_pair(checker_->collisions(s, data, rests), "object/YCBV_02", "_table/"));
}

TEST_F(ShelfScene, ObjectOneMillimetreFromTheGripperIsFreeAndOneMillimetreIntoItCollides) {
  auto data = checker_->make_data();
  SceneState s = start();
  // In front of the hand, 10 cm further along the approach axis than the grasp point.
  Pose front = gripper_pose(*scene_, s.q);
  front.translation() += 0.2 * front.linear().col(0);
  s.objects[0] = front;
  s.objects[1].translation().x() += 10.0;  // it rests 1 mm from the shelf: away
  const DistanceResult d = checker_->object_distance(s, data, 0);
  ASSERT_GT(d.distance, 0.005);
  ASSERT_NE(d.pair.first.find("object/YCBV_02"), std::string::npos) << d.pair.first << " " << d.pair.second;
  EXPECT_NEAR((d.second_point - d.first_point).norm(), d.distance, 1e-6);
  // Translating by t along the nearest-point direction changes every distance by at most t,
  // so moving by d - 1 mm leaves exactly 1 mm; by d + 1 mm the nearest features overlap.
  const Eigen::Vector3d u = (d.second_point - d.first_point).normalized();
  SceneState near = s;
  near.objects[0].translation() += (d.distance - 0.001) * u;
  EXPECT_FALSE(checker_->in_collision(near, data));
  EXPECT_NEAR(checker_->object_distance(near, data, 0).distance, 0.001, 1e-5);
  SceneState into = s;
  into.objects[0].translation() += (d.distance + 0.001) * u;
  EXPECT_TRUE(any_pair(checker_->collisions(into, data), "object/YCBV_02", "robot/"));
}

TEST_F(ShelfScene, SelfCollisionIsFoundAndDisabledPairsAreNeverReported) {
  const auto& model = scene_->robot.model;
  const auto body = model.rigid_bodies();
  std::mt19937_64 rng(3);
  auto data = checker_->make_data();
  int self_hits = 0;
  for (int i = 0; i < 3000; ++i) {
    SceneState s = start();
    s.q = random_q(rng);
    for (const auto& p : checker_->collisions(s, data)) {
      if (p.first.rfind("robot/", 0) != 0 || p.second.rfind("robot/", 0) != 0) continue;
      ++self_hits;
      const std::string a = p.first.substr(6), b = p.second.substr(6);
      EXPECT_FALSE(scene_->robot.srdf.collision_disabled(a, b)) << a << " " << b;
      EXPECT_NE(body[model.link_index(a)], body[model.link_index(b)]) << a << " " << b;
    }
  }
  EXPECT_GT(self_hits, 10);  // random Panda configurations fold into themselves often enough
}

TEST_F(ShelfScene, AttachedObjectFollowsTheGripper) {
  SceneState s = start();
  s.objects[0] = gripper_pose(*scene_, s.q);
  s.attachments.push_back(attach_to_gripper(*scene_, s, 0));
  s.q[0] += 0.5;
  s.q[3] += 0.3;
  PoseVector links;
  forward_kinematics(scene_->robot.model, s.q, scene_->robot.base, links);
  update_attached_objects(links, s);
  EXPECT_LT((s.objects[0].matrix() - gripper_pose(*scene_, s.q).matrix()).cwiseAbs().maxCoeff(), 1e-12);
  // The checker places attached objects itself, from the state's q.
  AllowedContacts allowed;
  allowed.allow_gripper(*scene_, 0);
  auto data = checker_->make_data();
  SceneState stale = s;
  stale.objects[0] = Pose::Identity();  // ignored: the attachment decides
  EXPECT_EQ(checker_->collisions(stale, data, allowed).size(), checker_->collisions(s, data, allowed).size());
}

TEST_F(ShelfScene, ConcurrentQueriesAgreeWithSequentialOnes) {
  std::mt19937_64 rng(11);
  std::vector<SceneState> states;
  for (int i = 0; i < 400; ++i) {
    SceneState s = start();
    s.q = random_q(rng);
    if (i % 3 == 0) s.objects[1].translation().z() -= 0.01 * (i % 7);  // some objects sink
    states.push_back(s);
  }
  std::vector<char> expected(states.size());
  auto data = checker_->make_data();
  for (size_t i = 0; i < states.size(); ++i) expected[i] = checker_->in_collision(states[i], data);
  std::vector<std::vector<char>> got(2, std::vector<char>(states.size()));
  std::vector<std::thread> threads;
  for (int t = 0; t < 2; ++t)
    threads.emplace_back([&, t] {
      auto d = checker_->make_data();
      for (int rep = 0; rep < 3; ++rep)
        for (size_t i = 0; i < states.size(); ++i) got[t][i] = checker_->in_collision(states[i], d);
    });
  for (auto& th : threads) th.join();
  EXPECT_EQ(got[0], expected);
  EXPECT_EQ(got[1], expected);
  int colliding = 0;
  for (char c : expected) colliding += c;
  EXPECT_GT(colliding, 0);
  EXPECT_LT(colliding, static_cast<int>(states.size()));
}
