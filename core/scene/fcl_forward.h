#pragma once
// FCL's collision object, named without including FCL: headers of core/scene pass FCL objects
// around while FCL itself stays in the .cpp files.

namespace fcl {
template <typename S>
class CollisionObject;
}  // namespace fcl
