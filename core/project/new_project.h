#pragma once
// A new project from a benchmark task, as `demoplan-cli new` and the GUI's New make it: the
// scene it refers to, the demonstration from the task's labels and cleaned poses, and, when
// parts ride on the robot (waiter), the deck placement stage.
#include <string>

#include "core/placement/deck_placement.h"
#include "core/project/project.h"

namespace demoplan {

struct NewProject {
  Project project;
  DeckPlacementReport deck;  // empty when no part rides on the robot
};

// `data_dir`: the benchmark data to load from (project.scene.data_dir is left empty: the bundled
// data). Throws InputError naming the file and the field.
NewProject new_benchmark_project(const std::string& data_dir, const SceneReference& scene,
                                 const StopCondition& stop = {}, const DeckPlacementProgress& progress = {});

// A new project on a cell file: its scene built (every file it names checked, handles generated),
// with `demonstration` when given (its objects must be the cell's parts), else one with the
// cell's parts and no event yet, for the operator to extract from a video or to edit.
NewProject new_cell_project(const std::string& data_dir, const std::string& cell_file,
                            const Demonstration* demonstration = nullptr, const StopCondition& stop = {},
                            const DeckPlacementProgress& progress = {});

}  // namespace demoplan
