// Writes a whole file atomically: to a unique temporary name in the same directory, then
// rename() over the target, so readers see either the old file or the complete new one.
#pragma once

#include <filesystem>
#include <string_view>

namespace shadowc::rt {

// Creates the parent directory if needed. Throws std::runtime_error("<path>: cannot write: why").
void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes);

}  // namespace shadowc::rt
