#pragma once
// Where a mobile base stands for a grasp or a release: the base from the handle's reach, then
// the arm by projection (inverse reachability, as Vahrenkamp et al. place a base, 2013).
// The arm's reach is sampled once from the model: random arm configurations and where each puts
// the gripper frame in the base body's frame. For a handle, reach samples at the handle's height
// are turned about the vertical to best match the handle's orientation; the best one gives the
// base yaw, the base position where its gripper meets the handle, and the arm's seed. Only
// seeds whose base and arm (up to the hand, which must come close to the part) clear the
// furniture are taken: box bounds, exact for the benchmark's boxed furniture.
// Without furniture or handle in reach the caller keeps its uniform seed.
#include <cstdint>
#include <memory>
#include <random>
#include <vector>

#include "core/model/mobile_base.h"
#include "core/scene/scene.h"

namespace demoplan {

struct BaseSamplerOptions {
  int reach_samples = 20000;       // arm configurations in the reach map
  double height_tolerance = 0.05;  // m: reach samples whose gripper is this close to the handle's height
  int candidates = 16;             // reach samples clear of the furniture per seed; the best oriented wins
  int attempts = 20;               // draws allowed per candidate before taking what cleared
  std::uint64_t seed = 1;          // the reach map's own generator: the same map in every run
};

class BaseSampler {
public:
  // `arm`: the configuration slots that move the gripper relative to the body.
  BaseSampler(const Scene& scene, const MobileBase& base, std::vector<int> arm, BaseSamplerOptions options = {});

  // Writes base and arm slots of q (the others are kept) for the gripper frame at `target`, in
  // the world (link -1) or in a robot link rigid with the body (the deck: the base then only
  // needs a free spot). False, q unspecified in those slots, when no draw cleared the furniture.
  bool sample(const Pose& target, int link, Eigen::VectorXd& q, std::mt19937_64& rng) const;
  // The robot up to the hand clear of the furniture at q (bounding boxes against the furniture's).
  bool clear_of_furniture(const Eigen::VectorXd& q) const;

  const MobileBase& base() const { return base_; }
  size_t reach_size() const { return reach_->size(); }

private:
  struct Reach {
    Eigen::VectorXd arm;  // values of the arm slots
    Pose gripper;         // in the body frame
  };
  struct Box {
    Pose pose;  // world (furniture) or link frame (the robot's)
    Eigen::Vector3d half;
    int link = -1;  // the robot's
  };
  // Indices into reach_ of the samples whose gripper height is within the tolerance of z.
  std::pair<size_t, size_t> height_window(double z) const;

  const Scene& scene_;
  MobileBase base_;
  std::vector<int> arm_;
  BaseSamplerOptions options_;
  static std::shared_ptr<const std::vector<Reach>> reach_map(const Scene& scene, const MobileBase& base,
                                                             const std::vector<int>& arm,
                                                             const BaseSamplerOptions& options);

  std::shared_ptr<const std::vector<Reach>> reach_;  // by gripper height, shared (reach_map)
  std::vector<Box> furniture_, robot_;
  double body_height_ = 0.0;  // of the body frame above the world's origin
  Eigen::VectorXd lower_, upper_;
};

}  // namespace demoplan
