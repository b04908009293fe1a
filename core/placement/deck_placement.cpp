#include "core/placement/deck_placement.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>
#include <set>
#include <sstream>

#include "core/demo/rest_pose.h"
#include "core/graph/constraint_graph.h"
#include "core/graph/projector.h"
#include "core/graph/state_validity.h"
#include "core/scene/collision_checker.h"
#include "core/scene/support.h"

namespace demoplan {

bool DeckPlacementReport::changed() const {
  return std::any_of(rests.begin(), rests.end(), [](const DeckRest& r) { return r.changed; });
}

bool DeckPlacementReport::feasible() const {
  return std::all_of(rests.begin(), rests.end(), [](const DeckRest& r) { return r.feasible; });
}

std::vector<std::string> DeckPlacementReport::notes() const {
  std::vector<std::string> out;
  for (const auto& r : rests) out.push_back(r.note);
  return out;
}

namespace {

// Index of the pick an event belongs to: its grasp, or the grasp before its release.
int pick_of_event(const Demonstration& d, int e) {
  int grasps = 0;
  for (int i = 0; i <= e; ++i) grasps += d.events[i].type == EventType::Grasp;
  return grasps - 1;
}

// Position in the placement sequence an event sees: before its pick for a grasp, after it for a
// release.
int placement_seen(const Demonstration& d, int e) {
  return pick_of_event(d, e) + (d.events[e].type == EventType::Release ? 1 : 0);
}

double wrap(double a) { return std::atan2(std::sin(a), std::cos(a)); }

std::string percent(double rate) { return std::to_string(static_cast<int>(std::lround(rate * 100))) + " %"; }

// One end of a pick that touches the deck: the release onto it or the grasp from it.
struct DeckEnd {
  int rest = -1;
  int pick = -1;
  bool release = false;  // true: the release onto the deck; false: the grasp from it
  int position = -1;     // placement position the object rests at on the deck meanwhile
};

struct EndScore {
  double rate = 0.0;  // min(deck end, other end) with the best handle
  int handle = -1;    // index into the pick's grasp states
};

struct Candidate {
  Pose pose;
  double deviation = 0.0;
  double offset = 0.0, yaw = 0.0;
};

class Chooser {
public:
  Chooser(const Scene& scene, Demonstration& demo, const DeckPlacementOptions& o, const StopCondition& stop,
          const DeckPlacementProgress& progress)
      : scene_(scene), demo_(demo), o_(o), stop_(stop), progress_(progress), graph_(build_constraint_graph(scene, demo)),
        projector_(scene, graph_), checker_(scene), validity_(scene, graph_, checker_), data_(checker_.make_data()),
        identity_links_(scene.robot.model.links.size(), Pose::Identity()) {
    for (size_t f = 0; f < scene.furniture.size(); ++f)
      for (size_t ob = 0; ob < scene.objects.size(); ++ob)
        rests_allowed_.allow_object_furniture(static_cast<int>(ob), static_cast<int>(f));
    for (const auto& s : support_polygons(scene))
      if (s.robot_link >= 0) surfaces_.push_back(s);
  }

  DeckPlacementReport run() {
    find_rests();
    DeckPlacementReport report;
    // Every rest starts hidden far below its link, so that objects not chosen yet are no obstacle.
    for (size_t r = 0; r < rests_.size(); ++r) set_pose(r, hidden(r));
    for (size_t r = 0; r < rests_.size(); ++r) other_end_rates(r);
    std::vector<size_t> order(rests_.size());
    for (size_t r = 0; r < order.size(); ++r) order[r] = r;
    std::stable_sort(order.begin(), order.end(),
                     [&](size_t a, size_t b) { return rests_[a].position_on < rests_[b].position_on; });
    for (size_t i = 0; i < order.size() && !stopped_; ++i) {
      if (stop_.should_stop()) {
        stopped_ = true;
        break;
      }
      done_rests_ = static_cast<int>(i);
      choose(order[i]);
    }
    if (stopped_) {
      report.stopped = true;
      return report;
    }
    for (const auto& r : rests_) {
      for (int e = r.out.first_event; e <= r.out.last_event; ++e) demo_.events[e].poses[r.out.object] = r.out.chosen;
      report.rests.push_back(r.out);
    }
    return report;
  }

private:
  struct Rest {
    DeckRest out;
    int surface = -1;                 // index into surfaces_
    int face = -1;                    // resting face of the object
    int position_on = 0, position_off = 0;  // placement positions of the stay
    std::vector<int> states;          // graph states that see it there
    std::vector<DeckEnd> ends;
    // Per end (same order as `ends`) and grasp state of its pick: collision-free rate of the
    // other end (the grasp before the release onto the deck, the release after the grasp off).
    std::vector<std::vector<double>> other;
    bool chosen = false;
  };

  // Far below the link, each object somewhere else.
  Pose hidden(size_t r) const {
    Pose p = Pose::Identity();
    p.translation() << 0.0, 0.0, -100.0 - 10.0 * static_cast<double>(rests_[r].out.object);
    return p;
  }

  int placement_state(int position) const {
    if (graph_.picks.empty()) return graph_.start_state;
    return position < static_cast<int>(graph_.picks.size()) ? graph_.picks[position].from : graph_.picks.back().to;
  }

  void find_rests() {
    const int events = static_cast<int>(demo_.events.size());
    for (size_t o = 0; o < demo_.object_ids.size(); ++o) {
      const int ob = static_cast<int>(o);
      for (int e = 0; e < events; ++e) {
        const std::string& frame = demo_.events[e].pose_frame(ob);
        if (frame.empty()) continue;
        int last = e;
        while (last + 1 < events && demo_.events[last + 1].pose_frame(ob) == frame &&
               demo_.events[last + 1].poses[o].isApprox(demo_.events[e].poses[o], 1e-12))
          ++last;
        add_rest(ob, frame, e, last);
        e = last;
      }
    }
  }

  void add_rest(int o, const std::string& frame, int first, int last) {
    Rest r;
    r.out.object = o;
    r.out.link = frame;
    r.out.first_event = first;
    r.out.last_event = last;
    r.out.demonstrated = r.out.chosen = demo_.events[first].poses[o];
    const ContactEvent &a = demo_.events[first], &b = demo_.events[last];
    if (a.object == o && a.type == EventType::Release) r.out.pick_on = pick_of_event(demo_, first);
    if (b.object == o && b.type == EventType::Grasp) r.out.pick_off = pick_of_event(demo_, last);
    r.position_on = placement_seen(demo_, first);
    r.position_off = placement_seen(demo_, last);

    // The surface and the face it rests on.
    const int link = scene_.robot.model.link_index(frame);
    const auto faces = object_contact_polygons(scene_.objects[o]);
    for (size_t s = 0; s < surfaces_.size() && r.surface < 0; ++s) {
      if (surfaces_[s].robot_link != link) continue;
      const PlacementCheck p = check_placement(scene_, {surfaces_[s]}, identity_links_, o, r.out.demonstrated);
      if (p.placed) r.surface = static_cast<int>(s), r.face = p.object_polygon;
    }
    for (size_t s = 0; s < surfaces_.size() && r.surface < 0; ++s) {
      if (surfaces_[s].robot_link != link) continue;
      SnapOptions loose;
      loose.max_distance = 0.2;
      loose.max_outside = 1.0;
      if (auto snapped = snap_to_support(faces, r.out.demonstrated, {surfaces_[s].vertices}, loose))
        r.surface = static_cast<int>(s), r.face = snapped->face;
    }

    std::set<int> states;
    for (int pos = r.position_on; pos <= r.position_off; ++pos) states.insert(placement_state(pos));
    for (int k = r.position_on; k <= std::min(r.position_off, static_cast<int>(graph_.picks.size()) - 1); ++k)
      for (size_t g = 0; g < graph_.states.size(); ++g)
        if (graph_.states[g].kind == StateKind::Grasp && graph_.states[g].step == k) states.insert(static_cast<int>(g));
    r.states.assign(states.begin(), states.end());
    const int index = static_cast<int>(rests_.size());
    if (r.out.pick_on >= 0) r.ends.push_back({index, r.out.pick_on, true, r.position_on});
    if (r.out.pick_off >= 0) r.ends.push_back({index, r.out.pick_off, false, r.position_off});
    rests_.push_back(std::move(r));
  }

  void set_pose(size_t r, const Pose& pose) {
    const int o = rests_[r].out.object;
    for (int s : rests_[r].states) graph_.states[s].objects[o].pose = pose;
  }

  std::mt19937_64 rng_for(size_t r, size_t candidate, int salt) const {
    std::seed_seq seq{static_cast<std::uint64_t>(o_.seed), static_cast<std::uint64_t>(r),
                      static_cast<std::uint64_t>(candidate), static_cast<std::uint64_t>(salt)};
    return std::mt19937_64(seq);
  }

  // Collision-free rate of a transition over at most n samples, stopping at `enough` successes.
  double rate(int transition, int n, int enough, std::mt19937_64& rng) {
    int ok = 0, k = 0;
    for (; k < n && ok < enough; ++k) {
      const TransitionSample s = projector_.sample_on_transition(transition, rng);
      if (s.ok && validity_.transition_free(s, data_)) ++ok;
    }
    return k ? static_cast<double>(ok) / k : 0.0;
  }

  int enough(int n) const { return std::max(1, static_cast<int>(std::ceil(o_.accept_rate * n - 1e-9))); }

  // The other end of each deck end, per handle: it does not depend on where the object rides.
  void other_end_rates(size_t r) {
    Rest& rest = rests_[r];
    for (size_t e = 0; e < rest.ends.size(); ++e) {
      const DeckEnd& end = rest.ends[e];
      const GraphPick& p = graph_.picks[end.pick];
      std::vector<double> rates(p.grasp_states.size(), 0.0);
      const int other_state = end.release ? p.from : p.to;
      const bool on_robot = graph_.states[other_state].objects[rest.out.object].link >= 0;
      for (size_t h = 0; h < p.grasp_states.size(); ++h) {
        if (on_robot) {  // moved from one robot surface to another: judged at the deck ends
          rates[h] = 1.0;
          continue;
        }
        std::mt19937_64 rng = rng_for(r, e, static_cast<int>(h) + 1000);
        const int n = 2 * o_.samples;
        rates[h] = rate(end.release ? p.grasp[h] : p.release[h], n, enough(n), rng);
      }
      rest.other.push_back(std::move(rates));
    }
  }

  // The deck end of a pick: the best handle's min(deck end rate, other end rate). Screening
  // stops at the first handle with one collision-free deck-end sample.
  EndScore score_end(const DeckEnd& end, bool screen, std::mt19937_64& rng, int samples = 0) {
    if (samples <= 0) samples = o_.samples;
    const Rest& rest = rests_[end.rest];
    const GraphPick& p = graph_.picks[end.pick];
    const size_t e = &end - rest.ends.data();
    const std::vector<double>& other = rest.other[e];
    std::vector<size_t> order(p.grasp_states.size());
    for (size_t h = 0; h < order.size(); ++h) order[h] = h;
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return other[a] > other[b]; });
    EndScore best;
    for (size_t h : order) {
      if (other[h] <= 0.0) break;
      const int t = end.release ? p.release[h] : p.grasp[h];
      if (screen) {
        if (rate(t, o_.screen_samples, 1, rng) > 0) return {1.0, static_cast<int>(h)};
        continue;
      }
      const double r = std::min(other[h], rate(t, samples, enough(samples), rng));
      if (r > best.rate) best = {r, static_cast<int>(h)};
      if (best.rate >= o_.accept_rate) break;
    }
    return best;
  }

  // The deck ends a pose of rest r bears on: its own, and those of chosen rests while it rides.
  std::vector<const DeckEnd*> ends_affected(size_t r) const {
    std::vector<const DeckEnd*> out;
    for (const auto& e : rests_[r].ends) out.push_back(&e);
    for (size_t q = 0; q < rests_.size(); ++q) {
      if (q == r || !rests_[q].chosen) continue;
      for (const auto& e : rests_[q].ends)
        if (e.position >= rests_[r].position_on && e.position <= rests_[r].position_off) out.push_back(&e);
    }
    return out;
  }

  bool placed(size_t r, const Pose& pose) const {
    const Rest& rest = rests_[r];
    if (rest.surface < 0) return false;
    return check_placement(scene_, {surfaces_[rest.surface]}, identity_links_, rest.out.object, pose).placed;
  }

  // Free of the robot in its initial configuration and of the objects riding at the same time.
  bool clear_at_rest(size_t r) {
    const std::string name = "object/" + scene_.objects[rests_[r].out.object].id;
    for (int pos = rests_[r].position_on; pos <= rests_[r].position_off; ++pos) {
      const SceneState s = scene_state(scene_, graph_, placement_state(pos), graph_.q_start);
      for (const auto& c : checker_.collisions(s, data_, rests_allowed_))
        if (c.first == name || c.second == name) return false;
    }
    return true;
  }

  std::vector<Candidate> candidates(size_t r) const {
    const Rest& rest = rests_[r];
    std::vector<Candidate> out{{rest.out.demonstrated, 0.0, 0.0, 0.0}};
    if (rest.surface < 0) return out;
    const auto& poly = surfaces_[rest.surface].vertices;
    const PolygonPlane plane = polygon_plane(poly);
    const auto faces = object_contact_polygons(scene_.objects[rest.out.object]);
    Eigen::Vector3d c_obj = Eigen::Vector3d::Zero();
    for (const auto& v : faces[rest.face]) c_obj += v;
    c_obj /= static_cast<double>(faces[rest.face].size());
    const Pose& demo = rest.out.demonstrated;
    const Eigen::Vector3d c = demo * c_obj;
    auto uv = [&](const Eigen::Vector3d& x) {
      return Eigen::Vector2d((x - plane.origin).dot(plane.u), (x - plane.origin).dot(plane.v));
    };
    const Eigen::Vector2d c2 = uv(c);
    Eigen::Vector2d lo = uv(poly[0]), hi = lo;
    for (const auto& v : poly) lo = lo.cwiseMin(uv(v)), hi = hi.cwiseMax(uv(v));
    std::vector<Eigen::Vector2d> positions{c2};
    const double step = o_.grid_step;
    const int nu = static_cast<int>(std::floor((hi.x() - lo.x()) / step)), nv = static_cast<int>(std::floor((hi.y() - lo.y()) / step));
    const double u0 = lo.x() + 0.5 * (hi.x() - lo.x() - nu * step), v0 = lo.y() + 0.5 * (hi.y() - lo.y() - nv * step);
    for (int i = 0; i <= nu; ++i)
      for (int j = 0; j <= nv; ++j) positions.emplace_back(u0 + i * step, v0 + j * step);
    for (size_t pi = 0; pi < positions.size(); ++pi) {
      const Eigen::Vector3d target = c + (positions[pi].x() - c2.x()) * plane.u + (positions[pi].y() - c2.y()) * plane.v;
      if (!projects_inside(plane, poly, target)) continue;
      for (int k = 0; k < o_.yaw_steps; ++k) {
        if (pi == 0 && k == 0) continue;  // the demonstrated pose itself
        const double yaw = wrap(2.0 * M_PI * k / o_.yaw_steps);
        const Eigen::Matrix3d rot = Eigen::AngleAxisd(yaw, plane.normal).toRotationMatrix();
        Candidate cand;
        cand.pose = Pose::Identity();
        cand.pose.linear() = rot * demo.linear();
        cand.pose.translation() = target + rot * (demo.translation() - c);
        cand.offset = (target - c).norm();
        cand.yaw = yaw;
        cand.deviation = cand.offset + o_.metres_per_radian * std::abs(yaw);
        out.push_back(cand);
      }
    }
    std::stable_sort(out.begin() + 1, out.end(), [](const Candidate& a, const Candidate& b) { return a.deviation < b.deviation; });
    return out;
  }

  std::string end_name(const DeckEnd& e) const {
    return "pick " + std::to_string(e.pick + 1) + (e.release ? " (onto the deck)" : " (off the deck)");
  }

  struct Rating {
    double worst = 0.0;
    std::vector<EndScore> scores;  // per end of ends_affected()
    std::string weakest;
  };

  // Rates the pose the rest has now: every deck end it bears on, the weakest counts.
  Rating rate_pose(size_t r, int samples, int salt) {
    // The same random seeds for every candidate (common random numbers): candidates differ by
    // their pose, not by their luck.
    std::mt19937_64 rng = rng_for(r, 0, salt);
    Rating out;
    out.worst = 1.0;
    for (const DeckEnd* e : ends_affected(r)) {
      out.scores.push_back(score_end(*e, false, rng, samples));
      if (out.scores.back().rate < out.worst) out.worst = out.scores.back().rate, out.weakest = end_name(*e);
    }
    return out;
  }

  void choose(size_t r) {
    Rest& rest = rests_[r];
    DeckRest& out = rest.out;
    const std::string id = scene_.objects[out.object].id;
    std::string demo_problem;  // why the demonstrated pose was not taken
    struct Rated {
      size_t candidate;
      Rating rating;
    };
    std::vector<Rated> rated;
    bool accepted = false;
    const std::vector<Candidate> cands = candidates(r);
    for (size_t ci = 0; ci < cands.size() && out.candidates_rated < o_.max_rated && !accepted; ++ci) {
      if (stop_.should_stop()) {
        stopped_ = true;
        return;
      }
      if (progress_)
        progress_(static_cast<double>(done_rests_) + static_cast<double>(out.candidates_rated) / o_.max_rated,
                  static_cast<int>(rests_.size()));
      const Candidate& cand = cands[ci];
      auto reject = [&](const std::string& why) {
        if (ci == 0) demo_problem = why;
      };
      if (!placed(r, cand.pose)) {
        reject("it is not inside the " + surfaces_[std::max(rest.surface, 0)].name + " polygon");
        continue;
      }
      set_pose(r, cand.pose);
      if (!clear_at_rest(r)) {
        reject("it collides with the robot or another object on the deck");
        continue;
      }
      std::mt19937_64 rng = rng_for(r, 0, 0);
      bool pass = true;
      for (const DeckEnd* e : ends_affected(r))
        if (score_end(*e, true, rng).handle < 0) {
          pass = false;
          reject(end_name(*e) + " has no handle that is collision-free at both ends in " +
                 std::to_string(o_.screen_samples) + " samples");
          break;
        }
      if (!pass) continue;
      ++out.candidates_rated;
      Rating rating = rate_pose(r, o_.samples, 1);
      accepted = rating.worst >= o_.accept_rate;
      if (!accepted) reject(rating.weakest + " is collision-free in only " + percent(rating.worst) + " of the samples");
      rated.push_back({ci, std::move(rating)});
    }
    // Nothing easy: the few best rated again with more samples, the estimates being coarse.
    if (!accepted && !rated.empty()) {
      std::stable_sort(rated.begin(), rated.end(),
                       [](const Rated& a, const Rated& b) { return a.rating.worst > b.rating.worst; });
      rated.resize(std::min<size_t>(rated.size(), o_.refine));
      for (auto& c : rated) {
        if (c.rating.worst <= 0.0) continue;
        set_pose(r, cands[c.candidate].pose);
        c.rating = rate_pose(r, o_.refine_samples, 2);
      }
      std::stable_sort(rated.begin(), rated.end(),
                       [](const Rated& a, const Rated& b) { return a.rating.worst > b.rating.worst; });
    }
    const Rated* pick = accepted ? &rated.back() : rated.empty() ? nullptr : &rated.front();
    double best_rate = pick ? pick->rating.worst : 0.0;
    Candidate best = pick ? cands[pick->candidate] : cands.front();
    std::vector<EndScore> best_scores = pick ? pick->rating.scores : std::vector<EndScore>{};
    if (best_rate <= 0.0) {  // nothing feasible: keep the demonstration's pose
      best = cands.front();
      best_scores.clear();
    }
    out.chosen = best.pose;
    out.changed = !best.pose.isApprox(out.demonstrated, 1e-12);
    out.feasible = best_rate > 0.0;
    out.rate = std::max(best_rate, 0.0);
    out.offset_m = best.offset;
    out.yaw_deg = best.yaw * 180.0 / M_PI;
    for (size_t k = 0; k < best_scores.size() && k < rest.ends.size(); ++k) {
      const DeckEnd& e = rest.ends[k];
      if (best_scores[k].handle < 0) continue;
      const GraphPick& p = graph_.picks[e.pick];
      const std::string handle = scene_.objects[out.object].srdf.handles[graph_.states[p.grasp_states[best_scores[k].handle]].handle].name;
      (e.release ? out.handle_on : out.handle_off) = handle;
    }
    set_pose(r, out.chosen);
    rest.chosen = true;

    std::ostringstream note;
    note << id << " on " << out.link;
    if (out.pick_on >= 0 || out.pick_off >= 0) {
      note << " (";
      if (out.pick_on >= 0) note << "put there by pick " << out.pick_on + 1;
      if (out.pick_on >= 0 && out.pick_off >= 0) note << ", ";
      if (out.pick_off >= 0) note << "taken off by pick " << out.pick_off + 1;
      note << ")";
    }
    note << ": ";
    if (!out.feasible)
      note << "no pose on the deck makes its picks feasible (" << demo_problem << "); kept the demonstrated pose";
    else if (!out.changed)
      note << "demonstrated pose kept";
    else {
      note.precision(2);
      note << std::fixed << "moved " << out.offset_m << " m and turned " << std::lround(out.yaw_deg)
           << " deg from the demonstrated pose (to x " << out.chosen.translation().x() << ", y "
           << out.chosen.translation().y() << " m in " << out.link << "), where " << demo_problem;
    }
    if (out.feasible) {
      note << " (handles";
      if (!out.handle_on.empty()) note << " " << out.handle_on << " on";
      if (!out.handle_off.empty()) note << (out.handle_on.empty() ? " " : ", ") << out.handle_off << " off";
      note << "; weakest end " << percent(out.rate) << " collision-free)";
    }
    out.note = note.str();
  }

  const Scene& scene_;
  Demonstration& demo_;
  DeckPlacementOptions o_;
  const StopCondition& stop_;
  const DeckPlacementProgress& progress_;
  bool stopped_ = false;
  int done_rests_ = 0;
  ConstraintGraph graph_;
  ConstraintProjector projector_;
  CollisionChecker checker_;
  StateValidity validity_;
  CollisionData data_;
  PoseVector identity_links_;
  AllowedContacts rests_allowed_;  // objects may touch furniture: only the deck's neighbours count
  std::vector<SupportPolygon> surfaces_;
  std::vector<Rest> rests_;
};

}  // namespace

DeckPlacement place_on_deck(const Scene& scene, const Demonstration& demo, const DeckPlacementOptions& options,
                            const StopCondition& stop, const DeckPlacementProgress& progress) {
  DeckPlacement out{demo, {}};
  bool any = false;
  for (const auto& e : demo.events)
    for (const auto& f : e.pose_frames) any |= !f.empty();
  if (!any) return out;
  const auto t0 = std::chrono::steady_clock::now();
  Chooser chooser(scene, out.demonstration, options, stop, progress);
  out.report = chooser.run();
  out.report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (out.report.stopped) out.demonstration = demo;
  return out;
}

}  // namespace demoplan
