// "Did you mean" for scene names and JSON keys: the closest candidate by edit distance.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace shadowc::rt {

size_t editDistance(std::string_view a, std::string_view b);
// The closest candidate within max(2, |word| / 3) edits, or "" when none is close.
std::string closestMatch(std::string_view word, const std::vector<std::string>& candidates);

}  // namespace shadowc::rt
