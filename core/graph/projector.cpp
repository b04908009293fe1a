#include "core/graph/projector.h"

#include <cmath>
#include <sstream>

namespace demoplan {

ConstraintProjector::ConstraintProjector(const Scene& scene, const ConstraintGraph& graph,
                                         ProjectorOptions options)
    : scene_(scene), graph_(graph), options_(options) {
  const RobotModel& m = scene.robot.model;
  lower_ = m.lower_limits();
  upper_ = m.upper_limits();
  std::vector<int> links{-1};
  for (const auto& s : graph.states)
    for (const auto& p : s.objects)
      if (p.link >= 0) links.push_back(p.link);
  for (int link : links) {
    if (solvers_.count(link)) continue;
    IkProblem p;
    p.model = &m;
    p.base = link < 0 ? scene.robot.base : Pose::Identity();
    p.root_link = link < 0 ? 0 : link;
    p.link = scene.robot.gripper_link;
    p.link_T_frame = scene.robot.gripper().pose;
    p.active = graph.reach_joints;
    IkOptions follow = options.ik;
    follow.max_attempts = 1;
    follow.max_iterations = options.follow_iterations;
    solvers_[link] = {std::make_unique<IkSolver>(p, options.ik), std::make_unique<IkSolver>(p, follow), nullptr};
  }
  if (const auto base = find_mobile_base(m)) {
    std::vector<int> arm;
    for (int j : graph.reach_joints)
      if (j != base->x && j != base->y && j != base->yaw) arm.push_back(j);
    Solvers& world = solvers_.at(-1);
    IkProblem p = world.reach->problem();
    p.active = arm;
    world.reach_arm = std::make_unique<IkSolver>(p, options.ik);
    base_sampler_ = std::make_unique<BaseSampler>(scene, *base, std::move(arm), options.base);
  }
}

void ConstraintProjector::open_gripper(Eigen::VectorXd& q) const {
  for (size_t k = 0; k < graph_.gripper_joints.size(); ++k)
    q[graph_.gripper_joints[k]] = graph_.gripper_open[static_cast<long>(k)];
}

Eigen::VectorXd ConstraintProjector::sample_configuration(int state, std::mt19937_64& rng) const {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Eigen::VectorXd q(lower_.size());
  for (long i = 0; i < q.size(); ++i) {
    const double lo = std::isfinite(lower_[i]) ? lower_[i] : -M_PI;
    const double hi = std::isfinite(upper_[i]) ? upper_[i] : M_PI;
    q[i] = lo + u(rng) * (hi - lo);
  }
  if (graph_.states[state].kind == StateKind::Grasp) open_gripper(q);
  return q;
}

Pose ConstraintProjector::handle_target(int transition, int* link) const {
  const GraphTransition& t = graph_.transitions[transition];
  // Grasp: the object where it rests before; release: where it rests after.
  const int placement_state = t.kind == TransitionKind::Grasp ? t.from : t.to;
  const ObjectPlacement& p = graph_.states[placement_state].objects[t.object];
  if (link) *link = p.link;
  return p.pose * scene_.objects[t.object].srdf.handles[t.handle].pose;
}

std::pair<double, double> ConstraintProjector::handle_residual(int transition, const Eigen::VectorXd& q) const {
  int link = -1;
  const Pose target = handle_target(transition, &link);
  const Pose at = solvers_for(link).reach->frame_pose(q);
  return {(at.translation() - target.translation()).norm(), log3(at.linear().transpose() * target.linear()).norm()};
}

TransitionSample ConstraintProjector::sample_on_transition(int transition, std::mt19937_64& rng) const {
  const GraphTransition& t = graph_.transitions[transition];
  Eigen::VectorXd seed = sample_configuration(t.from, rng);
  int link = -1;
  const Pose target = handle_target(transition, &link);
  // A part on the robot's deck moves with the base: where the base stands does not change its
  // reach, and the uniform seed keeps the arm's own configurations around the deck.
  if (base_sampler_ && link < 0 &&
      std::uniform_real_distribution<double>(0.0, 1.0)(rng) >= options_.uniform_base_fraction) {
    Eigen::VectorXd q = seed;
    if (base_sampler_->sample(target, link, q, rng)) return sample_from(transition, q, true, rng);
  }
  return sample_from(transition, seed, false, rng);
}

IkResult ConstraintProjector::project(int transition, const Eigen::VectorXd& seed, std::mt19937_64& rng) const {
  int link = -1;
  const Pose target = handle_target(transition, &link);
  Eigen::VectorXd q0 = seed;
  open_gripper(q0);
  return solvers_for(link).reach->solve(target, q0, rng);
}

TransitionSample ConstraintProjector::sample_on_transition(int transition, const Eigen::VectorXd& seed,
                                                           std::mt19937_64& rng) const {
  return sample_from(transition, seed, false, rng);
}

TransitionSample ConstraintProjector::sample_from(int transition, const Eigen::VectorXd& seed, bool base_placed,
                                                  std::mt19937_64& rng) const {
  const GraphTransition& t = graph_.transitions[transition];
  TransitionSample out;
  out.transition = transition;
  out.state_from = t.from;
  out.state_to = t.to;
  int target_link = -1;
  const Pose handle = handle_target(transition, &target_link);
  const IkSolver* arm_only = base_placed ? solvers_for(target_link).reach_arm.get() : nullptr;
  IkResult contact;
  if (arm_only) {
    Eigen::VectorXd q0 = seed;
    open_gripper(q0);
    contact = arm_only->solve(handle, q0, rng);
  }
  // When the arm alone cannot turn the hand onto the handle, the base may help.
  if (!contact.success) {
    const int before = contact.iterations;
    contact = project(transition, seed, rng);
    contact.iterations += before;
  }
  out.ik_attempts = contact.attempts;
  out.ik_iterations = contact.iterations;
  auto describe = [](const IkResult& r) {
    std::ostringstream s;
    s << "residual " << r.position_error * 1000 << " mm, " << r.rotation_error * 180 / M_PI << " deg";
    return s.str();
  };
  if (!contact.success) {
    out.failure = "the handle is out of reach (" + describe(contact) + ")";
    return out;
  }
  // Back off along the approach axis (x) by the handle's clearance, step by step, each step
  // solved from the previous one so the gripper follows the axis.
  int link = -1;
  const Pose contact_target = handle_target(transition, &link);
  const IkSolver& follow = *solvers_for(link).follow;
  const double clearance = scene_.objects[t.object].srdf.handles[t.handle].clearance;
  const int steps = std::max(1, static_cast<int>(std::ceil(clearance / options_.approach_step)));
  const Eigen::Vector3d axis = contact_target.linear().col(0);
  std::vector<Eigen::VectorXd> back{contact.q};  // from the handle outwards
  Pose target = contact_target;
  for (int k = 1; k <= steps; ++k) {
    target.translation() = contact_target.translation() - (clearance * k / steps) * axis;
    const IkResult r = follow.solve(target, back.back(), rng);
    out.ik_iterations += r.iterations;
    if (!r.success) {
      out.failure = "the approach along the handle's axis leaves the reachable space (" + describe(r) + ")";
      return out;
    }
    // Halfway between two steps the gripper must still be on the axis.
    const Pose mid = follow.frame_pose(0.5 * (back.back() + r.q));
    const Eigen::Vector3d offset = mid.translation() - contact_target.translation();
    if ((offset - offset.dot(axis) * axis).norm() > options_.straightness) {
      out.failure = "the approach leaves the handle's axis between two steps";
      return out;
    }
    back.push_back(r.q);
  }
  out.ok = true;
  if (t.kind == TransitionKind::Grasp) out.path.assign(back.rbegin(), back.rend());  // approach
  else out.path = std::move(back);                                                    // retreat
  return out;
}

}  // namespace demoplan
