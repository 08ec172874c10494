// Writes emitted files into an output directory all-or-nothing: every file goes to a temp
// name in the same directory first; only when all of them are written and flushed are they
// renamed over their final names (rename is atomic within a file system). A failure removes
// the temp files and leaves the directory as it was.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "emit/content_hash.h"

namespace shadowc {

// Returns an empty string on success, else one line saying what failed.
std::string writeFilesAtomically(const std::filesystem::path& dir, const std::vector<EmittedFile>& files);

}  // namespace shadowc
