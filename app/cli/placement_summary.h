#pragma once
// What `place` and `merge` print and draw of a placement result: the ranked table on stderr,
// the JSON on stdout, and the heat map of the region (PNG or SVG; needs the build with Qt 6).
#include <string>

#include <nlohmann/json.hpp>

#include "core/placement/placement_result.h"

namespace demoplan::cli {

// The best candidates (at most `rows`) and the search's counts, for a person.
void print_placement_summary(const PlacementResult& result, int rows = 10);
// The result's JSON with the file it was written to.
nlohmann::json placement_summary_json(const PlacementResult& result, const std::string& out);
// Throws InputError for an extension other than .png/.svg or a build without Qt.
void write_placement_heat_map(const std::string& file, const PlacementResult& result);

}  // namespace demoplan::cli
