// "Did you mean": the one edit-distance suggester of the filter language (compiler/dsl, spec/)
// and the scene loader (runtime/scene). Its own tiny library (shadowc_support) so the runtime
// links it without linking the compiler, as it does shadowc_manifest and shadowc_backend.
#pragma once

#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace shadowc::support {

// Levenshtein distance (two rows, O(|a|*|b|)); ASCII letters compare case-insensitively, so
// "Quadtree" is one typo away from nothing but "quadtree".
size_t editDistance(std::string_view a, std::string_view b);

// The closest candidate when it is close enough to be a plausible typo (at most
// max(1, |word| / 3) edits: a typo changes about one character in three), else "".
// Ties go to the earlier candidate.
std::string closestMatch(std::string_view word, const std::vector<std::string_view>& candidates);
std::string closestMatch(std::string_view word, const std::vector<std::string>& candidates);
std::string closestMatch(std::string_view word, std::initializer_list<std::string_view> candidates);

}  // namespace shadowc::support
