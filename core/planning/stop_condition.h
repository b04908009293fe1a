#pragma once
// When a planner must stop before it has solved its problem (OMPL's
// PlannerTerminationCondition): a wall-clock deadline, an operator's cancel flag, or both. The
// planner polls it; whoever starts the planner owns the flag and keeps it alive until solve()
// returns.
#include <atomic>
#include <chrono>
#include <limits>
#include <optional>

namespace demoplan {

class StopCondition {
public:
  using Clock = std::chrono::steady_clock;

  // Never stops by itself.
  StopCondition() = default;
  // Stops `time_limit_s` seconds from now, or when `cancel` becomes true.
  explicit StopCondition(double time_limit_s, const std::atomic<bool>* cancel = nullptr)
      : time_limit_s_(time_limit_s), cancel_(cancel) {
    if (time_limit_s < kForever) deadline_ = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                                               std::chrono::duration<double>(time_limit_s));
  }

  bool cancelled() const { return cancel_ && cancel_->load(std::memory_order_relaxed); }
  bool timed_out() const { return deadline_ && Clock::now() >= *deadline_; }
  bool should_stop() const { return cancelled() || timed_out(); }
  // The time limit it was made with (infinity without one), for messages.
  double time_limit_s() const { return time_limit_s_; }
  const std::atomic<bool>* cancel_flag() const { return cancel_; }

private:
  static constexpr double kForever = 1e9;  // s: beyond this a limit is no limit
  double time_limit_s_ = std::numeric_limits<double>::infinity();
  const std::atomic<bool>* cancel_ = nullptr;
  std::optional<Clock::time_point> deadline_;
};

}  // namespace demoplan
