#pragma once
// One URDF collision geometry as an FCL collision object at the identity: meshes carry their
// process-wide shared BVH (bvh_cache.h), primitives are made fresh. Copy the object and set the
// copy's transform (see bvh_cache.h for why not to construct one around a shared geometry).
#include <memory>

#include "core/model/robot_model.h"
#include "core/scene/fcl_forward.h"

namespace demoplan {

std::shared_ptr<const fcl::CollisionObject<double>> fcl_object(const Geometry& geometry);

}  // namespace demoplan
