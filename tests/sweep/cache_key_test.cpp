// The sweep row key (sweep/cache_key.h): equal inputs give one key, and the emitted code's
// content hash is part of it, so rows measured with another shadowc's shaders are not reused.
#include "sweep/cache_key.h"

#include <gtest/gtest.h>

namespace shadowc::sweep {
namespace {

KeyInputs inputs() {
  KeyInputs in;
  in.spec = {{"name", "f"}, {"kernel", "fixed(3)"}};
  in.shader = "specialized";
  in.emitted = "xxh3-128:00112233445566778899aabbccddeeff";
  in.sceneHash = "scene";
  in.screen = 64;
  in.map = 256;
  in.referenceSamples = 8;
  in.runs = 1;
  in.warmup = 0;
  return in;
}

TEST(CacheKey, SameInputsSameKeyAndTheEmittedCodeIsPartOfIt) {
  EXPECT_EQ(cacheKey(inputs()), cacheKey(inputs()));
  EXPECT_EQ(cacheKey(inputs()).size(), 32u);
  KeyInputs other = inputs();
  other.emitted = "xxh3-128:ffeeddccbbaa99887766554433221100";  // same spec, a changed template
  EXPECT_NE(cacheKey(other), cacheKey(inputs()));
  KeyInputs map = inputs();
  map.map = 512;
  EXPECT_NE(cacheKey(map), cacheKey(inputs()));
}

}  // namespace
}  // namespace shadowc::sweep
