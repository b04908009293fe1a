#pragma once
// Contour models kept on disk between runs, as SRT3D keeps its sparse models: building one costs
// about a second per part (642 silhouettes of the mesh), reading it back a few milliseconds. A
// file is named by a key of the mesh's geometry and the model options, so an edited mesh or
// other options never find a stale model.
#include <cstdint>
#include <optional>
#include <string>

#include "perception/tracking/contour_model.h"

namespace demoplan::perception {

// A hash (hash_bytes) of the mesh's vertices and triangles, the options and the file format's version.
std::uint64_t contour_model_key(const RenderMesh& mesh, const ContourModelOptions& options);

// `folder`/<key in hex>.contours; nullopt when it is missing, unreadable or not for this key.
std::optional<ContourModel> read_contour_model(const std::string& folder, std::uint64_t key);
// Written atomically (folder created); a folder that cannot be written is skipped silently:
// the cache only saves time.
void write_contour_model(const std::string& folder, std::uint64_t key, const ContourModel& model);

// The contour model of `mesh`: from `folder` when there, else built and stored there ("" : no
// cache).
ContourModel cached_contour_model(const RenderMesh& mesh, const ContourModelOptions& options, const std::string& folder);

// Where the tools keep them: $XDG_CACHE_HOME/demoplan/contours, else ~/.cache/demoplan/contours
// ("" without either variable).
std::string default_contour_cache_folder();

}  // namespace demoplan::perception
