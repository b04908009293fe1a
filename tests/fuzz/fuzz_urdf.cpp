// libFuzzer target: a URDF through our loader (core/model/robot_model.h, parse_urdf), as if it
// were resources/gtamp/robots/franka_panda/fuzz.urdf, so that the Panda's relative mesh paths
// resolve (the meshes are loaded once, through a cache shared by every run).
// Any input must load or throw InputError naming the file (tests/fuzz/fuzz_input.h).
#include "core/model/mesh.h"
#include "core/model/robot_model.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static demoplan::MeshCache meshes;
  static const std::string file = DEMOPLAN_RESOURCE_DIR "/gtamp/robots/franka_panda/fuzz.urdf";
  demoplan::UrdfOptions options;
  options.mesh_cache = &meshes;
  try {
    demoplan::parse_urdf(std::string(reinterpret_cast<const char*>(data), size), file, options);
  } catch (const demoplan::InputError& e) {
    demoplan::fuzz::check_error(e, file);
  }
  return 0;
}
