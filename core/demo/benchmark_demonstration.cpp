#include "core/demo/benchmark_demonstration.h"

#include <algorithm>

#include "core/error.h"

namespace demoplan {

namespace {
// Rows of task.contacts/raw_poses that are planning objects, in planning order.
std::vector<size_t> planning_rows(const BenchmarkTask& task) {
  std::vector<size_t> rows;
  for (size_t i = 0; i < task.objects.size(); ++i)
    if (task.objects[i].in_planning_model) rows.push_back(i);
  return rows;
}
}  // namespace

std::vector<ContactSegment> contact_segments(const BenchmarkTask& task) {
  std::vector<ContactSegment> out;
  const auto rows = planning_rows(task);
  for (size_t o = 0; o < rows.size(); ++o) {
    const auto& c = task.contacts[rows[o]];
    for (int t = 0; t < static_cast<int>(c.size()); ++t) {
      if (!c[t] || (t > 0 && c[t - 1])) continue;
      int last = t;
      while (last + 1 < static_cast<int>(c.size()) && c[last + 1]) ++last;
      out.push_back({static_cast<int>(o), t, last});
    }
  }
  std::sort(out.begin(), out.end(), [](auto& a, auto& b) { return a.first < b.first; });
  return out;
}

Demonstration demonstration_from_subgoals(const BenchmarkTask& task) {
  if (task.subgoal_poses.empty())
    throw InputError(task.file, "subgoal_objects_poses", "the task has no subgoals (null)");
  const auto segments = contact_segments(task);
  const size_t columns = task.subgoal_poses.front().size();
  if (columns != 2 * segments.size())
    throw InputError(task.file, "subgoal_objects_poses",
                     std::to_string(columns) + " columns for " + std::to_string(segments.size()) +
                         " contact segments (expected two per segment)");
  Demonstration d;
  d.task = task.name();
  d.object_ids = task.planning_object_ids;
  auto column = [&](size_t c) {
    PoseList poses;
    for (const auto& row : task.subgoal_poses) poses.push_back(row[c]);
    return poses;
  };
  for (size_t k = 0; k < segments.size(); ++k) {
    const auto& s = segments[k];
    d.events.push_back({s.first, s.object, EventType::Grasp, 1.0, column(2 * k)});
    d.events.push_back({s.last + 1, s.object, EventType::Release, 1.0, column(2 * k + 1)});
  }
  return d;
}

}  // namespace demoplan
