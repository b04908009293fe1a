#pragma once
// A read-only description of a constraint graph for the UI and logs: its states, its
// transitions, and the constraints each state imposes, in words and numbers.
#include <nlohmann/json.hpp>
#include <string>

#include "core/graph/constraint_graph.h"
#include "core/graph/pick_feasibility.h"

namespace demoplan {

// {"states": [{"name", "kind", "constraints": [..]}], "transitions": [{"name", "kind", "from",
//  "to", "object", "handle", "approach_state"}], "start", "goal"}. Positions in metres, angles
// in degrees (roll, pitch, yaw as URDF writes them).
nlohmann::json describe_graph(const Scene& scene, const ConstraintGraph& graph);

// The same as indented text, one state or transition a line.
std::string describe_graph_text(const Scene& scene, const ConstraintGraph& graph);

// [{"pick", "object", "feasible", "handles", "reason"}]: which picks can be done, and why not.
nlohmann::json describe_picks(const Scene& scene, const FeasibilityReport& report);

}  // namespace demoplan
