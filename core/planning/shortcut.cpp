#include "core/planning/shortcut.h"

#include <algorithm>
#include <chrono>
#include <memory>
#include <random>

#include "core/graph/state_validity.h"
#include "core/planning/connect_in_state.h"

namespace demoplan {

namespace {

// The state a segment moves in: its waypoints' state, or the placement state where the
// segment is a transition's approach (pre-grasp -> grasp, release -> retreat).
int segment_state(const ConstraintGraph& g, const Path& p, size_t k) {
  const int a = p.waypoints[k].state, b = p.waypoints[k + 1].state;
  if (a == b) return a;
  return g.states[a].kind == StateKind::Placement ? a : b;
}

Waypoint waypoint_at(const Scene& scene, const ConstraintGraph& g, const Path& p, size_t k, double u) {
  Waypoint w;
  w.q = (1 - u) * p.waypoints[k].q + u * p.waypoints[k + 1].q;
  w.state = segment_state(g, p, k);
  w.state_name = g.states[w.state].name;
  w.objects = scene_state(scene, g, w.state, w.q).objects;
  return w;
}

// A path can leave a placement state and come back to it unchanged: grasp a part and put it
// back where it was, where the planner linked two trees of that state through a grasp state.
// That grasp does nothing for the task but is counted (the benchmark's number of grasps) and
// done by the robot. Joins the first waypoint before such a detour to the first one after it
// within the state (RRT-Connect), for at most `seconds` and `rounds` each.
int remove_detours(const Scene& scene, const ConstraintGraph& graph, const StateValidity& validity,
                   CollisionData& data, Path& path, std::mt19937_64& rng, double seconds, long rounds) {
  std::unique_ptr<ConstraintProjector> sampler;  // built at the first detour: most paths have none
  int removed = 0;
  auto& w = path.waypoints;
  // A waypoint inside a straight approach or retreat cannot be an end: the move must stay whole.
  auto inside_straight_move = [&](size_t k) { return k > 0 && w[k - 1].approach && w[k].approach; };
  for (size_t i = 0; i + 2 < w.size(); ++i) {
    const int s = w[i].state;
    if (graph.states[s].kind != StateKind::Placement || inside_straight_move(i)) continue;
    // j: the first waypoint after the path's last return to s that is not inside the retreat
    // from the put-back (its end, where the path moves on freely).
    size_t back = w.size();
    for (size_t k = w.size() - 1; k > i + 1 && back == w.size(); --k)
      if (w[k].state == s && w[k - 1].state != s) back = k;
    size_t j = back;
    while (j < w.size() && w[j].state == s && inside_straight_move(j)) ++j;
    if (back == w.size() || j == w.size() || w[j].state != s) continue;
    if (!sampler) sampler = std::make_unique<ConstraintProjector>(scene, graph);
    ConnectParams cp;
    cp.deadline = std::chrono::steady_clock::now() +
                  std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(seconds));
    cp.max_rounds = rounds;
    const auto via = connect_in_state(*sampler, validity, data, s, w[i].q, w[j].q, rng, cp);
    if (!via) {  // try the next detour, not this one again from the next waypoint
      while (i + 1 < w.size() && w[i + 1].state == s) ++i;
      continue;
    }
    std::vector<Waypoint> out(w.begin(), w.begin() + static_cast<long>(i) + 1);
    out.back().approach = false;
    for (const auto& q : *via) {
      Waypoint v;
      v.q = q;
      v.state = s;
      v.state_name = graph.states[s].name;
      v.objects = scene_state(scene, graph, s, q).objects;
      out.push_back(std::move(v));
    }
    out.insert(out.end(), w.begin() + static_cast<long>(j), w.end());
    w = std::move(out);
    ++removed;
  }
  return removed;
}

}  // namespace

ShortcutResult shortcut_path(const Scene& scene, const ConstraintGraph& graph, const CollisionChecker& checker,
                             Path& path, const ShortcutParams& params) {
  using Clock = std::chrono::steady_clock;
  const auto t0 = Clock::now();
  ShortcutResult r;
  r.length_before = path.robot_length();
  const StateValidity validity(scene, graph, checker, params.resolution);
  CollisionData data = checker.make_data();
  std::mt19937_64 rng(params.seed);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  if (params.detour_time > 0) r.detours_removed = remove_detours(scene, graph, validity, data, path, rng, params.detour_time,
                                                            params.detour_rounds);
  const auto t1 = Clock::now();  // the shortcut budget starts after the detours
  long failures = 0;  // attempts since the last accepted cut
  while (r.attempts < params.max_attempts && failures < params.max_failures &&
         std::chrono::duration<double>(Clock::now() - t1).count() < params.time_limit) {
    ++r.attempts;
    ++failures;
    auto& w = path.waypoints;
    if (w.size() < 3) break;
    // Two points along the path, by arc length, in the same run of shortcuttable segments.
    std::vector<double> cum{0.0};
    for (size_t k = 1; k < w.size(); ++k) cum.push_back(cum.back() + (w[k].q - w[k - 1].q).norm());
    if (cum.back() <= 0) break;
    auto locate = [&](double d) {
      size_t k = std::upper_bound(cum.begin(), cum.end(), d) - cum.begin();
      k = std::clamp<size_t>(k, 1, w.size() - 1) - 1;
      const double span = cum[k + 1] - cum[k];
      return std::make_pair(k, span > 0 ? (d - cum[k]) / span : 0.0);
    };
    double d1 = u01(rng) * cum.back(), d2 = u01(rng) * cum.back();
    if (d1 > d2) std::swap(d1, d2);
    const auto [k1, u1] = locate(d1);
    const auto [k2, u2] = locate(d2);
    if (k1 == k2) continue;  // one segment is straight already
    const int state = segment_state(graph, path, k1);
    bool same_run = true;
    for (size_t k = k1; k <= k2 && same_run; ++k)
      same_run = !w[k].approach && segment_state(graph, path, k) == state &&
                 (k == k1 || w[k].state == state);  // no waypoint of another state in between
    if (!same_run) continue;
    const Waypoint a = waypoint_at(scene, graph, path, k1, u1);
    const Waypoint b = waypoint_at(scene, graph, path, k2, u2);
    const double old_length = d2 - d1;
    if ((b.q - a.q).norm() >= old_length - 1e-9) continue;
    if (!validity.configuration_free(state, a.q, data) || !validity.configuration_free(state, b.q, data) ||
        !validity.segment_free(state, a.q, b.q, data))
      continue;
    // Keep w[0..k1], then a (unless it is w[k1]), b (unless it is w[k2+1]), then w[k2+1..].
    std::vector<Waypoint> out(w.begin(), w.begin() + static_cast<long>(k1) + 1);
    if (u1 > 0) out.push_back(a);
    if (u2 < 1) out.push_back(b);
    out.insert(out.end(), w.begin() + static_cast<long>(k2) + 1, w.end());
    w = std::move(out);
    ++r.accepted;
    failures = 0;
  }
  r.length_after = path.robot_length();
  r.time_s = std::chrono::duration<double>(Clock::now() - t0).count();
  return r;
}

}  // namespace demoplan
