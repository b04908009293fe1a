#pragma once
// Where the tools keep what they compute once and reuse between runs (contour models, fitted
// meshes): a cache folder of the user's, which can be deleted at any time.
#include <string>

namespace demoplan {

// $XDG_CACHE_HOME/demoplan/<name>, else ~/.cache/demoplan/<name>; "" without either variable.
std::string user_cache_folder(const std::string& name);

}  // namespace demoplan
