#include "core/planning/single_state/ompl_single_state.h"

#include <chrono>
#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <thread>

#include <ompl/base/MotionValidator.h>
#include <ompl/base/ProblemDefinition.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/StateValidityChecker.h>
#include <ompl/base/objectives/PathLengthOptimizationObjective.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/geometric/planners/informedtrees/BITstar.h>
#include <ompl/geometric/planners/kpiece/KPIECE1.h>
#include <ompl/geometric/planners/prm/PRM.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include "core/error.h"
#include "core/graph/state_validity.h"

namespace demoplan {

namespace {

namespace ob = ompl::base;
namespace og = ompl::geometric;

constexpr double kStep = 0.3;  // rad: extension range, our RRT-Connect's (ConnectParams::step)

// The joints OMPL moves (all but the gripper's in a grasp state) and the rest of q, fixed.
struct JointMap {
  std::vector<int> moving;
  Eigen::VectorXd fixed;
  Eigen::VectorXd q(const ob::State* s) const {
    Eigen::VectorXd out = fixed;
    const double* v = s->as<ob::RealVectorStateSpace::StateType>()->values;
    for (size_t i = 0; i < moving.size(); ++i) out[moving[i]] = v[i];
    return out;
  }
  void set(const Eigen::VectorXd& q, ob::State* s) const {
    double* v = s->as<ob::RealVectorStateSpace::StateType>()->values;
    for (size_t i = 0; i < moving.size(); ++i) v[i] = q[moving[i]];
  }
};

// One CollisionData per thread that asks (OMPL's PRM checks from a second thread).
class ThreadCollisionData {
public:
  explicit ThreadCollisionData(const CollisionChecker& checker) : checker_(checker) {}
  CollisionData& get() const {
    std::lock_guard lock(mutex_);
    auto& d = data_[std::this_thread::get_id()];
    if (!d) d = std::make_unique<CollisionData>(checker_.make_data());
    return *d;
  }

private:
  const CollisionChecker& checker_;
  mutable std::mutex mutex_;
  mutable std::map<std::thread::id, std::unique_ptr<CollisionData>> data_;
};

struct Checks {
  const StateValidity& validity;
  int state;
  const JointMap& map;
  const ThreadCollisionData& data;
};

class ValidityChecker final : public ob::StateValidityChecker {
public:
  ValidityChecker(const ob::SpaceInformationPtr& si, const Checks& c) : ob::StateValidityChecker(si), c_(c) {}
  bool isValid(const ob::State* s) const override {
    return c_.validity.configuration_free(c_.state, c_.map.q(s), c_.data.get());
  }

private:
  Checks c_;
};

// Edges checked as our planner checks them (StateValidity::segment_free at its resolution), not
// by OMPL's bisection over a fraction of the space's extent.
class MotionValidator final : public ob::MotionValidator {
public:
  MotionValidator(const ob::SpaceInformationPtr& si, const Checks& c) : ob::MotionValidator(si), c_(c) {}
  bool checkMotion(const ob::State* s1, const ob::State* s2) const override {
    const Eigen::VectorXd a = c_.map.q(s1), b = c_.map.q(s2);
    CollisionData& d = c_.data.get();
    const bool ok = c_.validity.configuration_free(c_.state, b, d) && c_.validity.segment_free(c_.state, a, b, d);
    (ok ? valid_ : invalid_)++;
    return ok;
  }
  // The same samples in order from s1; the last free one is reported.
  bool checkMotion(const ob::State* s1, const ob::State* s2, std::pair<ob::State*, double>& last_valid) const override {
    const Eigen::VectorXd a = c_.map.q(s1), b = c_.map.q(s2);
    CollisionData& d = c_.data.get();
    const int steps = std::max(1, static_cast<int>(std::ceil((b - a).norm() / c_.validity.resolution())));
    for (int k = 1; k <= steps; ++k) {
      const double t = static_cast<double>(k) / steps;
      if (!c_.validity.configuration_free(c_.state, a + (b - a) * t, d)) {
        last_valid.second = static_cast<double>(k - 1) / steps;
        if (last_valid.first) si_->getStateSpace()->interpolate(s1, s2, last_valid.second, last_valid.first);
        invalid_++;
        return false;
      }
    }
    valid_++;
    return true;
  }

private:
  Checks c_;
};

// OMPL's messages are kept for the result's message, not printed.
class CapturedOutput final : public ompl::msg::OutputHandler {
public:
  void log(const std::string& text, ompl::msg::LogLevel level, const char*, int) override {
    if (level >= ompl::msg::LOG_WARN) last = text;
  }
  std::string last;
};

ob::PlannerPtr make_ompl_planner(const std::string& name, const ob::SpaceInformationPtr& si) {
  if (name == "ompl-rrtconnect") {
    auto p = std::make_shared<og::RRTConnect>(si);
    p->setRange(kStep);
    return p;
  }
  if (name == "ompl-kpiece") {
    auto p = std::make_shared<og::KPIECE1>(si);
    p->setRange(kStep);
    return p;
  }
  if (name == "ompl-prm") return std::make_shared<og::PRM>(si);
  if (name == "ompl-bitstar") return std::make_shared<og::BITstar>(si);
  return nullptr;
}

}  // namespace

SingleStateResult solve_single_state_ompl(const PlanningProblem& problem, int state, const Eigen::VectorXd& q_from,
                                          const Eigen::VectorXd& q_to, const std::string& planner,
                                          const StopCondition& stop, std::uint64_t seed, double resolution) {
  static std::mutex ompl_mutex;  // the seed and the output handler are OMPL globals
  std::lock_guard lock(ompl_mutex);
  CapturedOutput output;
  ompl::msg::useOutputHandler(&output);
  struct Restore {
    ~Restore() { ompl::msg::restorePreviousOutputHandler(); }
  } restore;
  // Seeds every RNG OMPL makes from here on (samplers, the planner's own, projections).
  ompl::RNG::setSeed(static_cast<std::uint_fast32_t>(seed % 0xFFFFFFFFu) + 1);

  const ConstraintGraph& graph = *problem.graph;
  const RobotModel& robot = problem.scene->robot.model;
  JointMap map;
  map.fixed = q_from;
  std::vector<bool> is_gripper(q_from.size(), false);
  if (graph.states[state].kind == StateKind::Grasp)
    for (int j : graph.gripper_joints) is_gripper[j] = true;
  for (int j = 0; j < q_from.size(); ++j)
    if (!is_gripper[j]) map.moving.push_back(j);

  // Our sampler's box: the joint limits, [-pi, pi] for a continuous joint; widened to hold the
  // ends so that they are in bounds.
  const Eigen::VectorXd lower = robot.lower_limits(), upper = robot.upper_limits();
  auto space = std::make_shared<ob::RealVectorStateSpace>(static_cast<unsigned>(map.moving.size()));
  ob::RealVectorBounds bounds(static_cast<unsigned>(map.moving.size()));
  for (size_t i = 0; i < map.moving.size(); ++i) {
    const int j = map.moving[i];
    const double lo = std::isfinite(lower[j]) ? lower[j] : -M_PI, hi = std::isfinite(upper[j]) ? upper[j] : M_PI;
    bounds.setLow(i, std::min({lo, q_from[j], q_to[j]}));
    bounds.setHigh(i, std::max({hi, q_from[j], q_to[j]}));
  }
  space->setBounds(bounds);

  const StateValidity validity(*problem.scene, graph, *problem.checker, resolution);
  const ThreadCollisionData data(*problem.checker);
  const Checks checks{validity, state, map, data};
  auto si = std::make_shared<ob::SpaceInformation>(space);
  si->setStateValidityChecker(std::make_shared<ValidityChecker>(si, checks));
  si->setMotionValidator(std::make_shared<MotionValidator>(si, checks));
  // What OMPL itself discretizes (path checks, interpolation counts): the same step.
  si->setStateValidityCheckingResolution(resolution / space->getMaximumExtent());
  si->setup();

  SingleStateResult out;
  ob::ScopedState<> start(space), goal(space);
  map.set(q_from, start.get());
  map.set(q_to, goal.get());
  if (!si->isValid(start.get()) || !si->isValid(goal.get())) {
    out.message = "an end of the motion is in collision";
    return out;
  }
  auto pdef = std::make_shared<ob::ProblemDefinition>(si);
  // A planner that ends near q_to (KPIECE) finishes with a straight move to it, checked below.
  pdef->setStartAndGoalStates(start, goal, resolution);
  // Stop at the first solution (OMPL's default objective is never satisfied: PRM and BIT*
  // would refine until the time limit).
  auto objective = std::make_shared<ob::PathLengthOptimizationObjective>(si);
  objective->setCostThreshold(objective->infiniteCost());
  pdef->setOptimizationObjective(objective);
  ob::PlannerPtr p = make_ompl_planner(planner, si);
  if (!p) throw InputError("planner", planner, "not an OMPL planner demoplan offers");
  p->setProblemDefinition(pdef);
  p->setup();

  const auto t0 = std::chrono::steady_clock::now();
  const ob::PlannerStatus status = p->solve(ob::PlannerTerminationCondition([&stop] { return stop.should_stop(); }));
  out.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (status != ob::PlannerStatus::EXACT_SOLUTION) {
    out.message = stop.cancelled() ? "cancelled"
                  : stop.timed_out() ? "no path within the time limit"
                                     : "OMPL: " + status.asString() + (output.last.empty() ? "" : " (" + output.last + ")");
    return out;
  }
  const auto& path = *pdef->getSolutionPath()->as<og::PathGeometric>();
  for (std::size_t k = 0; k < path.getStateCount(); ++k) out.path.push_back(map.q(path.getState(k)));
  // The ends as given (OMPL's copies are the same numbers); a planner that stopped within the
  // goal tolerance of q_to gets one more straight move, checked as any other.
  out.path.front() = q_from;
  if ((out.path.back() - q_to).norm() <= 1e-9) {
    out.path.back() = q_to;
  } else if (validity.segment_free(state, out.path.back(), q_to, data.get())) {
    out.path.push_back(q_to);
  } else {
    out.path.clear();
    out.message = "the last move to q_to collides";
    return out;
  }
  out.solved = true;
  return out;
}

}  // namespace demoplan
