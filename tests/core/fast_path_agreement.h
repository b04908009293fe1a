#pragma once
// The collision checker with its fast path (the default) against FCL alone on the same scene
// states: random configurations with the objects at their start poses, with an object held at
// one of its handles, with the objects moved at random, and configurations bisected towards the
// boundary between a free and a colliding one. Shared by test_collision_fast_path (a few
// thousand states per scene) and bench/fast_path_agreement (a million per scene).
#include <cstdint>
#include <random>
#include <sstream>
#include <string>

#include "core/demo/benchmark_scene.h"
#include "core/scene/collision_checker.h"

namespace demoplan {

struct AgreementCounts {
  long states = 0;
  long colliding = 0;  // as FCL alone says
  long held = 0;       // states with an object in the gripper
  long boundary = 0;   // bisection states
  long disagreements = 0;    // in_collision differs
  long pair_mismatches = 0;  // same answer, another first pair reported
  long answer_only_disagreements = 0;  // asked without a pair (exact tests deferred): differs
  std::string first_disagreement;

  void add(const AgreementCounts& o) {
    states += o.states, colliding += o.colliding, held += o.held, boundary += o.boundary;
    disagreements += o.disagreements, pair_mismatches += o.pair_mismatches;
    answer_only_disagreements += o.answer_only_disagreements;
    if (first_disagreement.empty()) first_disagreement = o.first_disagreement;
  }
};

class FastPathAgreement {
public:
  FastPathAgreement(const std::string& data_dir, const std::string& task_name, const std::string& robot, int pose)
      : task_(load_benchmark_task(data_dir, task_name)),
        scene_(build_benchmark_scene(task_, robot, pose)),
        fast_(scene_),
        fcl_(scene_, fcl_only()),
        fast_data_(fast_.make_data()),
        fcl_data_(fcl_.make_data()),
        start_(benchmark_start_state(task_, scene_)) {}

  const Scene& scene() const { return scene_; }

  // Compares one state; true when both answer alike.
  bool compare(const SceneState& s, const AllowedContacts& allowed, AgreementCounts& c) {
    CollisionPair fast_hit, fcl_hit;
    const bool answer_only = fast_.in_collision(s, fast_data_, allowed);  // first: as the planner asks
    const bool fast = fast_.in_collision(s, fast_data_, allowed, &fast_hit);
    const bool fcl = fcl_.in_collision(s, fcl_data_, allowed, &fcl_hit);
    ++c.states;
    c.colliding += fcl;
    if (answer_only != fcl) {
      ++c.answer_only_disagreements;
      if (c.first_disagreement.empty())
        c.first_disagreement = scene_.name + ": asked without a pair, the fast path says " +
                               (answer_only ? "collision" : "free") + ", FCL the opposite";
    }
    if (fast != fcl) {
      ++c.disagreements;
      if (c.first_disagreement.empty()) {
        std::ostringstream out;
        out << scene_.name << ": fast path " << (fast ? "collision" : "free") << ", FCL "
            << (fcl ? "collision (" + fcl_hit.first + ", " + fcl_hit.second + ")" : "free") << ", q "
            << s.q.transpose();
        c.first_disagreement = out.str();
      }
      return false;
    }
    if (fast && (fast_hit.first != fcl_hit.first || fast_hit.second != fcl_hit.second)) ++c.pair_mismatches;
    return answer_only == fcl;
  }

  // `n` states (at least), of every kind, from `seed`.
  AgreementCounts run(long n, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    AgreementCounts c;
    // Of every 50 draws: 30 random, 12 held, 6 moved objects, and 2 bisections of 20 states
    // (about 45 % of the states lie near a boundary).
    for (long i = 0; c.states < n; ++i) {
      const int kind = static_cast<int>(i % 50);
      AllowedContacts allowed;
      if (kind < 30) {
        compare(random_state(rng, false, allowed), allowed, c);
      } else if (kind < 42) {
        const SceneState s = random_state(rng, true, allowed);
        c.held += !s.attachments.empty();
        compare(s, allowed, c);
      } else if (kind < 48) {
        compare(moved_objects_state(rng), allowed, c);
      } else {
        bisect(rng, kind == 49, c);
      }
    }
    return c;
  }

private:
  static CollisionOptions fcl_only() {
    CollisionOptions o;
    o.fast_path = false;
    return o;
  }

  Eigen::VectorXd random_q(std::mt19937_64& rng) const {
    const auto& m = scene_.robot.model;
    const Eigen::VectorXd lo = m.lower_limits(), hi = m.upper_limits();
    std::uniform_real_distribution<double> u(0, 1);
    Eigen::VectorXd q(m.nq);
    for (int k = 0; k < m.nq; ++k) q[k] = lo[k] + u(rng) * (hi[k] - lo[k]);
    return q;
  }

  // Objects at their start poses; `hold`: one of them held at one of its handles.
  SceneState random_state(std::mt19937_64& rng, bool hold, AllowedContacts& allowed) const {
    SceneState s = start_;
    s.q = random_q(rng);
    if (!hold || scene_.objects.empty()) return s;
    const int o = static_cast<int>(rng() % scene_.objects.size());
    const auto& handles = scene_.objects[o].srdf.handles;
    const Pose handle = handles.empty() ? Pose::Identity() : handles[rng() % handles.size()].pose;
    s.objects[o] = gripper_pose(scene_, s.q) * handle.inverse();  // the handle at the gripper
    s.attachments.push_back(attach_to_gripper(scene_, s, o));
    allowed.allow_gripper(scene_, o);
    return s;
  }

  // Every object moved up to 30 cm and turned at random: object/furniture and object/object
  // pairs are then checked in every query (nothing cached).
  SceneState moved_objects_state(std::mt19937_64& rng) const {
    SceneState s = start_;
    s.q = random_q(rng);
    std::uniform_real_distribution<double> u(-1, 1);
    for (auto& p : s.objects) {
      p.translation() += 0.3 * Eigen::Vector3d(u(rng), u(rng), u(rng));
      const Eigen::Vector3d axis = Eigen::Vector3d(u(rng), u(rng), u(rng)).normalized();
      p.linear() = (Eigen::AngleAxisd(3.0 * u(rng), axis).toRotationMatrix() * p.linear()).eval();
    }
    return s;
  }

  // A free and a colliding state of one kind, then 20 halvings of the segment between them,
  // each midpoint compared: states within a micro-radian of the boundary.
  void bisect(std::mt19937_64& rng, bool hold, AgreementCounts& c) {
    AllowedContacts allowed;
    SceneState a = random_state(rng, hold, allowed);
    SceneState b = a;
    const bool a_hits = fcl_.in_collision(a, fcl_data_, allowed);
    bool found = false;
    for (int tries = 0; tries < 50 && !found; ++tries) {
      b.q = random_q(rng);
      found = fcl_.in_collision(b, fcl_data_, allowed) != a_hits;
    }
    if (!found) return;
    SceneState free_state = a_hits ? b : a, hit_state = a_hits ? a : b;
    for (int step = 0; step < 20; ++step) {
      SceneState mid = free_state;
      mid.q = 0.5 * (free_state.q + hit_state.q);
      ++c.boundary;
      c.held += !mid.attachments.empty();
      compare(mid, allowed, c);
      (fcl_.in_collision(mid, fcl_data_, allowed) ? hit_state : free_state) = mid;
    }
  }

  BenchmarkTask task_;
  Scene scene_;
  CollisionChecker fast_, fcl_;
  CollisionData fast_data_, fcl_data_;
  SceneState start_;
};

}  // namespace demoplan
