#include "core/part/grasp_handles.h"

#include <fcl/fcl.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <chrono>
#include <optional>
#include <cmath>
#include <sstream>

#include "core/error.h"
#include "core/model/kinematics.h"
#include "core/part/mesh_lines.h"
#include "core/part/resting_placements.h"
#include "core/scene/bvh_cache.h"
#include "core/scene/fcl_object.h"

namespace demoplan {

ParallelGripper parallel_gripper(const RobotModel& model, const Srdf& srdf) {
  if (srdf.grippers.empty()) throw InputError(srdf.path, "gripper", "the robot has no gripper");
  const GraspFrame& g = srdf.grippers.front();
  const int link = model.link_index(g.link);
  if (link < 0)
    throw InputError(srdf.path, "gripper '" + g.name + "' link", "link '" + g.link + "' is not in " + model.urdf_path);
  if (!(g.clearance > 0)) throw InputError(srdf.path, "gripper '" + g.name + "' clearance", "must be > 0 (the opening, m)");
  const std::vector<int> hand = model.subtree_links(link);
  Eigen::VectorXd q = Eigen::VectorXd::Zero(model.nq);
  for (const Joint& j : model.joints) {
    if (j.q_index < 0) continue;
    const bool finger = std::find(hand.begin(), hand.end(), j.child_link) != hand.end();
    q[j.q_index] = finger ? j.limits.upper : std::clamp(0.0, j.limits.lower, j.limits.upper);
  }
  model.enforce_mimic(q);
  PoseVector poses;
  forward_kinematics(model, q, Pose::Identity(), poses);
  const Pose frame_inv = (poses[link] * g.pose).inverse();
  ParallelGripper out;
  out.opening = g.clearance;
  for (int l : hand)
    for (Geometry geometry : model.links[l].collisions) {
      geometry.origin = frame_inv * poses[l] * geometry.origin;
      out.hand.push_back(std::move(geometry));
    }
  return out;
}

namespace {

using Clock = std::chrono::steady_clock;

struct Line {
  bool fits = false;
  Eigen::Vector3d centre;  // midway between the contacts
  double width = 0.0;
  double antipodality = 0.0;  // 0..1
};

class Generator {
public:
  Generator(const TriangleMesh& mesh, double scale, const Eigen::Vector3d& com, const ParallelGripper& gripper,
            const GraspOptions& options)
      : com_(com), gripper_(gripper), o_(options), cos_friction_(std::cos(options.friction_angle)) {
    vertices_.reserve(mesh.vertices.size());
    for (const auto& v : mesh.vertices) vertices_.push_back(v.cast<double>() * scale);
    triangles_ = &mesh.triangles;
    part_.emplace(*shared_mesh_bvh(mesh, Eigen::Vector3d::Constant(scale)));
    flat_faces_ = flat_faces();
    for (const Geometry& g : gripper.hand) {
      hand_.push_back(*fcl_object(g));
      hand_origin_.push_back(g.origin);
    }
  }

  GraspReport run(const std::string& link, const std::string& prefix) {
    const auto t0 = Clock::now();
    std::vector<GeneratedHandle> found;
    for (const Eigen::Vector3d& z : closing_directions()) {
      const MeshLines lines(vertices_, *triangles_, z);
      // Approach directions about z, the first along the part axis farthest from z, or along
      // the part's own long side across z where the mesh frame is turned off it.
      Eigen::Vector3d axis = Eigen::Vector3d::UnitX();
      for (int i = 1; i < 3; ++i)
        if (std::abs(Eigen::Vector3d::Unit(i).dot(z)) < std::abs(axis.dot(z))) axis = Eigen::Vector3d::Unit(i);
      const Eigen::Vector3d u = first_approach((axis - axis.dot(z) * z).normalized(), z), v = z.cross(u);
      const int approaches = std::max(1, static_cast<int>(std::lround(2 * M_PI / o_.approach_step)));
      // Along the part's axes first, then between them: equal grasps keep this order.
      for (int i = 0; i < approaches; ++i) {
        const int k = i < (approaches + 1) / 2 ? 2 * i : 2 * (i - (approaches + 1) / 2) + 1;
        const double theta = 2 * M_PI * k / approaches;
        const Eigen::Vector3d x = std::cos(theta) * u + std::sin(theta) * v;
        const Eigen::Vector3d y = z.cross(x);
        search_approach(lines, x, y, z, found);
      }
    }
    report_.candidates = static_cast<int>(found.size());
    report_.handles = cluster(std::move(found), link, prefix);
    if (report_.handles.empty()) report_.why_none = why_none();
    report_.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    return report_;
  }

private:
  // The first approach about z: `axis` (across z), unless the part seen along z has a clear
  // long direction off the approaches from it and no flat face on them: a scanned bottle drawn
  // turned in its mesh frame (YCB-V's mustard, 27 degrees) is grasped across its own sides.
  Eigen::Vector3d first_approach(const Eigen::Vector3d& axis, const Eigen::Vector3d& z) const {
    const Eigen::Vector3d w = z.cross(axis);
    // The surface's second moments in the (axis, w) plane, each triangle integrated exactly
    // (E[p p^T] over a triangle = (a a^T + b b^T + c c^T + s s^T) / 12, s = a + b + c).
    Eigen::Matrix2d m = Eigen::Matrix2d::Zero();
    Eigen::Vector2d mean = Eigen::Vector2d::Zero();
    double total = 0.0;
    for (const auto& t : *triangles_) {
      const Eigen::Vector3d a = vertices_[t[0]], b = vertices_[t[1]], c = vertices_[t[2]];
      const double area = 0.5 * (b - a).cross(c - a).norm();
      auto in_plane = [&](const Eigen::Vector3d& p) { return Eigen::Vector2d(p.dot(axis), p.dot(w)); };
      const Eigen::Vector2d pa = in_plane(a), pb = in_plane(b), pc = in_plane(c), ps = pa + pb + pc;
      m += area / 12.0 * (pa * pa.transpose() + pb * pb.transpose() + pc * pc.transpose() + ps * ps.transpose());
      mean += area / 3.0 * ps;
      total += area;
    }
    if (!(total > 0)) return axis;
    mean /= total;
    m = m / total - mean * mean.transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(m);
    const double minor = eig.eigenvalues()[0], major = eig.eigenvalues()[1];
    if (!(major > 1.2 * minor)) return axis;  // round or square across z: no long side
    auto on_grid = [&](const Eigen::Vector3d& d) {  // within 10 degrees of an approach from axis
      return std::abs(std::remainder(std::atan2(d.dot(w), d.dot(axis)), o_.approach_step)) < 0.17;
    };
    // A flat face across z on the grid says the mesh frame is the part's own (a CAD part):
    // keep it, as a person grasps an L-bracket along its legs, not along its inertia axes.
    for (const Eigen::Vector3d& n : flat_faces_)
      if (std::abs(n.dot(z)) < 0.17 && on_grid(n)) return axis;
    const Eigen::Vector3d d = eig.eigenvectors()(0, 1) * axis + eig.eigenvectors()(1, 1) * w;
    return on_grid(d) ? axis : d.normalized();
  }

  // The part's axes, their diagonals, and the normals of its largest flat faces (one sign each).
  std::vector<Eigen::Vector3d> closing_directions() const {
    std::vector<Eigen::Vector3d> dirs;
    auto add = [&](Eigen::Vector3d d) {
      d.normalize();
      for (const auto& e : dirs)
        if (std::abs(e.dot(d)) > std::cos(0.17)) return;  // within 10 degrees: already there
      dirs.push_back(d);
    };
    const Eigen::Vector3d X = Eigen::Vector3d::UnitX(), Y = Eigen::Vector3d::UnitY(), Z = Eigen::Vector3d::UnitZ();
    for (const auto& d : {X, Y, Z, Eigen::Vector3d(X + Y), Eigen::Vector3d(X - Y), Eigen::Vector3d(X + Z),
                          Eigen::Vector3d(X - Z), Eigen::Vector3d(Y + Z), Eigen::Vector3d(Y - Z)})
      add(d);
    for (size_t i = 0; i < flat_faces_.size() && i < 6; ++i) add(flat_faces_[i]);
    return dirs;
  }

  // Normals of the part's flat faces, largest first: area-weighted normals grouped within 10
  // degrees (either sign), those holding at least 5 % of the surface.
  std::vector<Eigen::Vector3d> flat_faces() const {
    struct Face {
      Eigen::Vector3d normal;
      double area;
    };
    std::vector<Face> faces;
    double total = 0.0;
    for (const auto& t : *triangles_) {
      const Eigen::Vector3d n = (vertices_[t[1]] - vertices_[t[0]]).cross(vertices_[t[2]] - vertices_[t[0]]);
      const double area = 0.5 * n.norm();
      if (area <= 0) continue;
      total += area;
      const Eigen::Vector3d unit = n.normalized();
      auto it = std::find_if(faces.begin(), faces.end(), [&](const Face& f) { return std::abs(f.normal.dot(unit)) > std::cos(0.17); });
      if (it == faces.end()) faces.push_back({unit, area});
      else it->area += area;
    }
    std::sort(faces.begin(), faces.end(), [](const Face& a, const Face& b) { return a.area > b.area; });
    std::vector<Eigen::Vector3d> out;
    for (const Face& f : faces)
      if (f.area >= 0.05 * total) out.push_back(f.normal);
    return out;
  }

  Line line_through(const MeshLines& lines, const Eigen::Vector3d& point) {
    ++report_.closing_lines;
    Line out;
    const std::vector<LineCrossing> hits = lines.cross(point);
    if (hits.size() < 2) return out;
    const LineCrossing& a = hits.front();
    const LineCrossing& b = hits.back();
    out.width = b.t - a.t;
    const double ca = std::abs(a.normal.dot(lines.direction())), cb = std::abs(b.normal.dot(lines.direction()));
    if (ca < cos_friction_ || cb < cos_friction_) return out;
    min_width_seen_ = std::min(min_width_seen_, out.width);  // of the lines whose faces face each other
    if (out.width < o_.min_width || out.width > gripper_.opening - 2 * o_.width_margin) return out;
    ++report_.fitting_lines;
    out.fits = true;
    out.centre = point + 0.5 * (a.t + b.t) * lines.direction();
    out.antipodality = 0.5 * ((ca - cos_friction_) + (cb - cos_friction_)) / (1 - cos_friction_);
    return out;
  }

  bool hand_free(const Pose& handle) {
    ++report_.hand_checks;
    fcl::CollisionRequestd request;
    for (size_t i = 0; i < hand_.size(); ++i) {
      hand_[i].setTransform((handle * hand_origin_[i]).matrix().topLeftCorner<3, 3>(), (handle * hand_origin_[i]).translation());
      fcl::CollisionResultd result;
      if (fcl::collide(&*part_, &hand_[i], request, result) > 0) return false;
    }
    return true;
  }

  static Pose frame(const Eigen::Vector3d& centre, const Eigen::Vector3d& x, const Eigen::Vector3d& y,
                    const Eigen::Vector3d& z) {
    Pose p = Pose::Identity();
    p.linear().col(0) = x;
    p.linear().col(1) = y;
    p.linear().col(2) = z;
    p.translation() = centre;
    return p;
  }

  // For closing lines side by side across the fingers, the deepest grasp the palm allows.
  void search_approach(const MeshLines& lines, const Eigen::Vector3d& x, const Eigen::Vector3d& y,
                       const Eigen::Vector3d& z, std::vector<GeneratedHandle>& found) {
    double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300;
    for (const auto& p : vertices_) {
      const Eigen::Vector3d d = p - com_;
      xmin = std::min(xmin, d.dot(x)), xmax = std::max(xmax, d.dot(x));
      ymin = std::min(ymin, d.dot(y)), ymax = std::max(ymax, d.dot(y));
    }
    std::vector<double> offsets{0.0};
    for (double b = o_.lateral_step; b < 0.8 * std::max(-ymin, ymax); b += o_.lateral_step) {
      if (b < 0.8 * ymax) offsets.push_back(b);
      if (-b > 0.8 * ymin) offsets.push_back(-b);
    }
    for (double b : offsets) {
      // Grasp at depth a along the approach: valid when the line fits and the open hand is free.
      auto grasp_at = [&](double a, Line& line) {
        line = line_through(lines, com_ + a * x + b * y);
        return line.fits && hand_free(frame(line.centre, x, y, z));
      };
      // No deeper than the centre of mass: past it the fingers would hold the far half only.
      Line line;
      double deep = std::min(xmax, 0.0), a = deep;
      bool ok = false;
      for (; a >= xmin; a -= o_.depth_step) {
        if ((ok = grasp_at(a, line))) break;
        deep = a;
      }
      if (!ok) continue;
      // Bisect between the last failing depth and the first good one.
      double lo = a, hi = deep;
      Line best = line;
      while (hi - lo > o_.depth_tolerance) {
        const double mid = 0.5 * (lo + hi);
        Line l;
        if (grasp_at(mid, l)) lo = mid, best = l;
        else hi = mid;
      }
      // Keep the palm clear of the part.
      Line back;
      if (grasp_at(lo - o_.palm_clearance, back)) best = back, lo -= o_.palm_clearance;
      // Centred: the fingers close across the centre of mass (only the offset across the
      // fingers is a choice; depth and the midpoint between the contacts follow from the part).
      auto add = [&](const Line& l, double depth) {
        const double lateral = std::abs((l.centre - com_).dot(y));
        const double centred = 1.0 - std::min(1.0, lateral / std::max(0.5 * (ymax - ymin), 1e-6));
        const double engaged = std::min(1.0, (depth - xmin) / 0.03);
        const double flat = flatness(lines, l, x, y);
        GeneratedHandle h;
        h.width = l.width;
        h.quality = 0.35 * l.antipodality + 0.35 * centred + 0.15 * flat + 0.15 * engaged;
        h.frame.pose = frame(l.centre, x, y, z);
        h.frame.clearance = std::min(gripper_.opening, l.width + 2 * o_.width_margin);
        found.push_back(h);
        // The same grasp with the fingers swapped (turned half a turn about the approach).
        h.frame.pose = frame(l.centre, x, -y, -z);
        found.push_back(h);
      };
      add(best, lo);
      // Shallower ones too, nearer the side the hand comes from: an arm that cannot reach the
      // deepest grasp (a shelf's board above, a corner) may reach these.
      for (double a = lo - o_.depth_variant_step; a - xmin >= o_.min_engagement; a -= o_.depth_variant_step) {
        Line l;
        if (grasp_at(a, l)) add(l, a);
      }
    }
  }

  // How evenly the part fills the finger pads: widths of lines beside the centre line.
  double flatness(const MeshLines& lines, const Line& line, const Eigen::Vector3d& x, const Eigen::Vector3d& y) {
    const double pad = 0.008;
    double lo = line.width, hi = line.width;
    for (const Eigen::Vector3d& d : {Eigen::Vector3d(pad * x), Eigen::Vector3d(-pad * x), Eigen::Vector3d(pad * y),
                                     Eigen::Vector3d(-pad * y)}) {
      const std::vector<LineCrossing> hits = lines.cross(line.centre + d);
      const double w = hits.size() < 2 ? 0.0 : hits.back().t - hits.front().t;
      lo = std::min(lo, w), hi = std::max(hi, w);
    }
    return 1.0 - std::min(1.0, (hi - lo) / 0.01);
  }

  std::vector<GeneratedHandle> cluster(std::vector<GeneratedHandle> found, const std::string& link,
                                       const std::string& prefix) const {
    // Ranked by quality to the percent: within that, the order they were made in (axes first).
    std::stable_sort(found.begin(), found.end(), [](const GeneratedHandle& a, const GeneratedHandle& b) {
      return std::lround(a.quality * 100) > std::lround(b.quality * 100);
    });
    std::vector<GeneratedHandle> out;
    for (auto& h : found) {
      if (static_cast<int>(out.size()) >= o_.max_handles) break;
      const bool near = std::any_of(out.begin(), out.end(), [&](const GeneratedHandle& k) {
        const double d = (k.frame.pose.translation() - h.frame.pose.translation()).norm();
        const double angle = Eigen::AngleAxisd(k.frame.pose.linear().transpose() * h.frame.pose.linear()).angle();
        return d < o_.cluster_distance && angle < o_.cluster_angle;
      });
      if (near) continue;
      h.frame.link = link;
      h.frame.name = prefix + std::to_string(out.size());
      out.push_back(h);
    }
    return out;
  }

  std::string why_none() const {
    std::ostringstream s;
    s.precision(3);
    if (report_.fitting_lines == 0) {
      if (min_width_seen_ > gripper_.opening - 2 * o_.width_margin && min_width_seen_ < 1e300)
        s << "the part is too wide for the gripper: its narrowest closing line is " << min_width_seen_ * 1000
          << " mm, the gripper opens " << gripper_.opening * 1000 << " mm";
      else
        s << "no two faces of the part face each other within " << o_.friction_angle * 180 / M_PI
          << " degrees and the gripper's opening of " << gripper_.opening * 1000 << " mm";
    } else {
      s << "every grasp that fits the opening puts the open hand into the part (" << report_.hand_checks
        << " hand poses checked)";
    }
    return s.str();
  }

  Eigen::Vector3d com_;
  std::vector<Eigen::Vector3d> flat_faces_;  // flat_faces(), computed once
  const ParallelGripper& gripper_;
  GraspOptions o_;
  double cos_friction_;
  std::vector<Eigen::Vector3d> vertices_;
  const std::vector<std::array<std::uint32_t, 3>>* triangles_ = nullptr;
  std::optional<fcl::CollisionObjectd> part_;  // a copy of the shared BVH's object
  std::vector<fcl::CollisionObjectd> hand_;
  PoseVector hand_origin_;
  double min_width_seen_ = 1e300;
  GraspReport report_;
};

}  // namespace

GraspReport generate_handles(const TriangleMesh& mesh, double scale, const Eigen::Vector3d& com,
                             const ParallelGripper& gripper, const GraspOptions& options, const std::string& link,
                             const std::string& prefix) {
  if (mesh.triangles.empty()) throw InputError(mesh.path, "", "the mesh has no triangles");
  if (gripper.hand.empty()) throw std::invalid_argument("the gripper has no collision geometry");
  Generator generator(mesh, scale, com, gripper, options);
  return generator.run(link, prefix);
}

GraspReport use_generated_handles(SceneObject& object, const ParallelGripper& gripper, const GraspOptions& options) {
  const RobotModel& m = object.model;
  for (const Link& link : m.links)
    for (const Geometry& g : link.collisions)
      if (const auto* mesh = std::get_if<MeshShape>(&g.shape); mesh && mesh->mesh && link.name == m.links[0].name) {
        if (!g.origin.isApprox(Pose::Identity()) || mesh->scale.minCoeff() != mesh->scale.maxCoeff())
          throw InputError(object.srdf.path, "handles", "the part's mesh is offset or scaled unevenly in its URDF");
        // The centre of mass of the mesh itself (as resting_placements.h computes it).
        GraspReport r = generate_handles(*mesh->mesh, mesh->scale.x(), centre_of_mass(*mesh->mesh, mesh->scale.x()),
                                         gripper, options, link.name, "generated_");
        if (r.handles.empty())
          throw InputError(object.srdf.path, "handles", "no grasp generated for '" + object.id + "': " + r.why_none);
        object.srdf.handles.clear();
        for (const auto& h : r.handles) object.srdf.handles.push_back(h.frame);
        return r;
      }
  throw InputError(object.srdf.path, "handles", "'" + object.id + "' has no collision mesh on its root link");
}

bool handle_matches(const Pose& generated, const Pose& hand_made) {
  const double d = (generated.translation() - hand_made.translation()).norm();
  const double a = Eigen::AngleAxisd(generated.linear().transpose() * hand_made.linear()).angle();
  return d <= 0.01 && a <= 15 * M_PI / 180;
}

}  // namespace demoplan
