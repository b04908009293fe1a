#pragma once
// The demonstrator's hand as the synthetic videos draw it: a palm with a thumb and a forearm.
// Palm frame: origin at the palm centre, z the palm normal (towards the held part), x along
// the fingers; the forearm leaves the wrist along -x.
#include "perception/render/render_mesh.h"

namespace demoplan::perception {

RenderMesh hand_mesh();

}  // namespace demoplan::perception
