#pragma once
// Paths as a file stores them: relative to the file's folder where they can be, so a folder of
// files moves as a whole; absolute in memory.
#include <string>

namespace demoplan {

// `absolute` relative to the folder of `file` when both are on the same root; "" stays "".
std::string to_stored(const std::string& absolute, const std::string& file);
// A stored path made absolute against the folder of `file`; "" stays "".
std::string from_stored(const std::string& stored, const std::string& file);

}  // namespace demoplan
