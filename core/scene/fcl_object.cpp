#include "core/scene/fcl_object.h"

#include <fcl/fcl.h>

#include "core/scene/bvh_cache.h"

namespace demoplan {

std::shared_ptr<const fcl::CollisionObject<double>> fcl_object(const Geometry& g) {
  auto own = [](std::shared_ptr<fcl::CollisionGeometryd> geometry) {
    return std::make_shared<const fcl::CollisionObjectd>(std::move(geometry));
  };
  if (auto* b = std::get_if<BoxShape>(&g.shape)) return own(std::make_shared<fcl::Boxd>(b->size));
  if (auto* c = std::get_if<CylinderShape>(&g.shape)) return own(std::make_shared<fcl::Cylinderd>(c->radius, c->length));
  if (auto* s = std::get_if<SphereShape>(&g.shape)) return own(std::make_shared<fcl::Sphered>(s->radius));
  const auto& m = std::get<MeshShape>(g.shape);
  return shared_mesh_bvh(*m.mesh, m.scale);
}

}  // namespace demoplan
