// DontInline marking of named functions; see dont_inline.h.
#include "backend/dont_inline.h"

#include <cstring>
#include <set>

namespace shadowc {
namespace {

constexpr uint32_t kOpName = 5;
constexpr uint32_t kOpFunction = 54;
constexpr uint32_t kDontInline = 0x2;
constexpr size_t kHeaderWords = 5;

// The literal string of an OpName (operands after the target id), up to its terminating NUL.
std::string literalString(const uint32_t* words, size_t count) {
  std::string s(reinterpret_cast<const char*>(words), count * 4);
  return s.substr(0, std::strlen(s.c_str()));
}

}  // namespace

int markDontInline(std::vector<uint32_t>& words, const std::vector<std::string>& names) {
  if (names.empty() || words.size() < kHeaderWords) return 0;
  std::set<uint32_t> ids;
  for (size_t i = kHeaderWords; i < words.size();) {
    const uint32_t count = words[i] >> 16, op = words[i] & 0xffff;
    if (count == 0 || i + count > words.size()) return 0;  // malformed: leave it to spirv-val
    if (op == kOpName && count > 2) {
      const std::string name = literalString(&words[i + 2], count - 2);
      for (const std::string& n : names)
        if (name.starts_with(n + "(")) ids.insert(words[i + 1]);
    }
    i += count;
  }
  int marked = 0;
  for (size_t i = kHeaderWords; i < words.size();) {
    const uint32_t count = words[i] >> 16, op = words[i] & 0xffff;
    if (op == kOpFunction && count == 5 && ids.count(words[i + 2])) {
      words[i + 3] |= kDontInline;
      ++marked;
    }
    i += count;
  }
  return marked;
}

}  // namespace shadowc
