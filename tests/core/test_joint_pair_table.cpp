// The self-pair distance table (joint_pair_table.h): which pairs get one, and that it proves a
// pair free only where FCL finds no contact, on random and near-contact configurations.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "core/demo/benchmark_scene.h"
#include "core/scene/bvh_cache.h"
#include "core/scene/collision_checker.h"
#include "core/scene/joint_pair_table.h"

using namespace demoplan;

static const std::string kData = DEMOPLAN_DATA_DIR;

namespace {

CollisionOptions fcl_alone() {
  CollisionOptions o;
  o.fast_path = false;
  return o;
}

struct Robot {
  BenchmarkTask task;
  Scene scene;
  CollisionChecker fcl;
  CollisionData data;
  std::vector<std::unique_ptr<GeometryBound>> bounds;  // LinkGeometry points at them

  Robot(const std::string& task_name, const std::string& robot)
      : task(load_benchmark_task(kData, task_name)),
        scene(build_benchmark_scene(task, robot, 0)),
        fcl(scene, fcl_alone()),
        data(fcl.make_data()) {}

  const RobotModel& model() const { return scene.robot.model; }

  LinkGeometry geometry(const std::string& link) {
    const int l = model().link_index(link);
    const Geometry& g = model().links.at(l).collisions.at(0);
    const auto& mesh = std::get<MeshShape>(g.shape);
    SharedMesh shared = shared_mesh(*mesh.mesh, mesh.scale);
    bounds.push_back(std::make_unique<GeometryBound>(mesh_bound(shared.spheres)));
    return {l, g.origin, shared.bvh, bounds.back().get()};
  }

  std::unique_ptr<JointPairTable> table(const std::string& a, const std::string& b) {
    return JointPairTable::make(model(), geometry(a), geometry(b));
  }

  // FCL's verdict for one pair: is it among the colliding pairs of the whole scene?
  bool touch(const Eigen::VectorXd& q, const std::string& a, const std::string& b) {
    SceneState s = benchmark_start_state(task, scene);
    s.q = q;
    for (const auto& p : fcl.collisions(s, data))
      if ((p.first == "robot/" + a && p.second == "robot/" + b) ||
          (p.first == "robot/" + b && p.second == "robot/" + a))
        return true;
    return false;
  }
};

}  // namespace

TEST(JointPairTable, ChainsOfOneOrTwoRevoluteJointsGetATable) {
  Robot panda("shelf_0", "panda");
  auto forearm_flange = panda.table("panda_link5", "panda_link7");
  ASSERT_TRUE(forearm_flange);
  EXPECT_EQ(forearm_flange->joint_count(), 2);
  auto forearm_hand = panda.table("panda_hand", "panda_link5");  // either order
  ASSERT_TRUE(forearm_hand);
  EXPECT_EQ(forearm_hand->joint_count(), 2);
  auto wrist = panda.table("panda_link6", "panda_link7");
  ASSERT_TRUE(wrist);
  EXPECT_EQ(wrist->joint_count(), 1);
  EXPECT_FALSE(panda.table("panda_link3", "panda_link7"));       // four joints
  EXPECT_FALSE(panda.table("panda_link7", "panda_hand"));        // one rigid body
  EXPECT_FALSE(panda.table("panda_link5", "panda_leftfinger"));  // a prismatic joint
  EXPECT_FALSE(panda.table("panda_leftfinger", "panda_rightfinger"));  // neither above the other
  // The grid is fine enough for its travel bound and starts empty.
  EXPECT_GT(forearm_hand->node_count(), 1000u);
  EXPECT_EQ(forearm_hand->nodes_measured(), 0u);
}

TEST(JointPairTable, ProvesFreeOnlyWhereFclFindsNoContact) {
  Robot panda("shelf_0", "panda");
  const RobotModel& m = panda.model();
  const Eigen::VectorXd lo = m.lower_limits(), hi = m.upper_limits();
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  auto random_q = [&] {
    Eigen::VectorXd q(m.nq);
    for (int k = 0; k < m.nq; ++k) q[k] = lo[k] + u(rng) * (hi[k] - lo[k]);
    return q;
  };
  for (const auto& [a, b] : {std::pair<std::string, std::string>{"panda_link5", "panda_link7"},
                             {"panda_link5", "panda_hand"}}) {
    auto table = panda.table(a, b);
    ASSERT_TRUE(table);
    int random_free = 0, random_proven = 0, contacts = 0, near_contact = 0, wrong = 0;
    for (int i = 0; i < 1500; ++i) {
      const Eigen::VectorXd q = random_q();
      const bool touch = panda.touch(q, a, b);
      const bool proven = table->certainly_free(q);
      wrong += touch && proven;
      contacts += touch;
      random_free += !touch;
      random_proven += proven;
      if (!touch) continue;
      // Bisect towards a free configuration: states within a micro-radian of the contact.
      Eigen::VectorXd in = q, out = random_q();
      if (panda.touch(out, a, b)) continue;
      for (int step = 0; step < 20; ++step) {
        const Eigen::VectorXd mid = 0.5 * (in + out);
        const bool t = panda.touch(mid, a, b);
        wrong += t && table->certainly_free(mid);
        (t ? in : out) = mid;
        ++near_contact;
      }
      wrong += table->certainly_free(out) && panda.touch(out, a, b);
    }
    SCOPED_TRACE(a + " / " + b);
    EXPECT_EQ(wrong, 0);
    EXPECT_GT(contacts, 15);        // the pair does touch in random configurations
    EXPECT_GT(near_contact, 300);
    // What it is for: most configurations where the pair is free are proven so without FCL.
    EXPECT_GT(random_proven, random_free / 2);
    EXPECT_GT(table->nodes_measured(), 100u);
  }
}
