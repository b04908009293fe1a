#pragma once
// Where a URDF's package://NAME/... meshes are, guessed from where the URDF lies: a robot
// description copied off a ROS workspace keeps its packages as folders (NAME/urdf/robot.urdf,
// NAME/meshes/...), so the folder holding NAME is on the URDF's path or beside one of its parents.
#include <string>
#include <vector>

namespace demoplan {

// The package names the URDF's mesh URIs use (package://NAME/...), each once, in file order.
// Throws InputError naming the file when it cannot be read.
std::vector<std::string> urdf_package_names(const std::string& urdf_file);

// Directories D such that D/NAME is a directory, for every NAME the URDF uses: the URDF's folder
// and its parents up to `levels` above it are searched, nearest first. Names not found are left
// out (loading the URDF then names the mesh it cannot find).
std::vector<std::string> guess_package_paths(const std::string& urdf_file, int levels = 4);

}  // namespace demoplan
