#include "support/suggest.h"

#include <algorithm>
#include <cctype>

namespace shadowc::support {
namespace {

char fold(char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); }

template <typename It>
std::string closest(std::string_view word, It first, It last) {
  const size_t limit = std::max<size_t>(1, word.size() / 3);
  std::string_view best;
  size_t bestDistance = limit + 1;
  for (It it = first; it != last; ++it) {
    const std::string_view c = *it;
    const size_t d = editDistance(word, c);
    if (d < bestDistance) bestDistance = d, best = c;
  }
  return std::string(best);
}

}  // namespace

size_t editDistance(std::string_view a, std::string_view b) {
  std::vector<size_t> prev(b.size() + 1), cur(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t subst = prev[j - 1] + (fold(a[i - 1]) == fold(b[j - 1]) ? 0 : 1);
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, subst});
    }
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

std::string closestMatch(std::string_view word, const std::vector<std::string_view>& candidates) {
  return closest(word, candidates.begin(), candidates.end());
}
std::string closestMatch(std::string_view word, const std::vector<std::string>& candidates) {
  return closest(word, candidates.begin(), candidates.end());
}
std::string closestMatch(std::string_view word, std::initializer_list<std::string_view> candidates) {
  return closest(word, candidates.begin(), candidates.end());
}

}  // namespace shadowc::support
