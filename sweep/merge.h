// `shadowc sweep merge DIR... -o OUT`: shard outputs (or any sweep folders) into one result
// set. Rows are joined by cache key (the same key is the same measurement; the first folder
// given wins), their images copied into OUT, and the cache entries too, so OUT can resume.
#pragma once

#include <filesystem>
#include <vector>

#include "sweep/sweep_row.h"

namespace shadowc::sweep {

// Throws std::runtime_error naming a folder without a readable results.json.
Results mergeResults(const std::vector<std::filesystem::path>& dirs, const std::filesystem::path& out);

}  // namespace shadowc::sweep
