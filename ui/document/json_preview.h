#pragma once
// A program file that is one long JSON line (Franka's 1 kHz trajectory) made readable for the
// preview: objects indented, arrays of numbers kept on one line each. The file itself is not
// changed.
#include <string>

namespace demoplan::ui {

// `text` indented when it is JSON on a single line; anything else is returned as it is.
std::string readable_json(const std::string& text);

}  // namespace demoplan::ui
