#include "emit/content_hash.h"

#include <fmt/format.h>
#include <xxhash.h>

#include <algorithm>

namespace shadowc {

std::string contentHash(const std::vector<EmittedFile>& files) {
  std::vector<const EmittedFile*> order;
  for (const auto& f : files)
    if (f.name != "manifest.json") order.push_back(&f);
  std::sort(order.begin(), order.end(), [](const EmittedFile* a, const EmittedFile* b) { return a->name < b->name; });
  XXH3_state_t* state = XXH3_createState();
  XXH3_128bits_reset(state);
  for (const EmittedFile* f : order) {
    XXH3_128bits_update(state, f->name.data(), f->name.size() + 1);  // includes the NUL
    unsigned char size[8];
    for (int i = 0; i < 8; ++i) size[i] = static_cast<unsigned char>(static_cast<uint64_t>(f->bytes.size()) >> (8 * i));
    XXH3_128bits_update(state, size, sizeof size);
    XXH3_128bits_update(state, f->bytes.data(), f->bytes.size());
  }
  const XXH128_hash_t h = XXH3_128bits_digest(state);
  XXH3_freeState(state);
  return fmt::format("xxh3-128:{:016x}{:016x}", h.high64, h.low64);
}

}  // namespace shadowc
