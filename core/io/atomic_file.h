#pragma once
// Files written whole or not at all: the bytes go to a temporary file beside the target, which is
// then renamed over it, so a crash or a full disk never leaves a half-written file behind.
#include <string>
#include <string_view>

namespace demoplan {

// Throws InputError naming `path` when it cannot be written.
void write_file_atomic(const std::string& path, std::string_view bytes);

}  // namespace demoplan
