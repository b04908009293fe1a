#pragma once
// Where the bundled data lives, for every demoplan executable: the benchmark data folder
// (robots, objects, furniture, tasks) and the sample project shown on first start.
#include <string>

namespace demoplan::app {

// $DEMOPLAN_DATA_DIR, else <prefix>/share/demoplan/gtamp beside an installed executable,
// else the source tree's resources/gtamp, else the configured install location.
std::string default_data_dir();

// The bundled sample project file (resources/sample/... or <prefix>/share/demoplan/sample/...);
// empty when it is not there.
std::string default_sample_project();

}  // namespace demoplan::app
