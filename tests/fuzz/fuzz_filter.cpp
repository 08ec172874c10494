// libFuzzer target: the filter language front end (lex -> parse -> check) on arbitrary bytes.
// Every input must end in diagnostics or a spec, never a crash, a sanitizer report or a throw.
#include <cstddef>
#include <cstdint>
#include <string>

#include "spec/load_filter.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const shadowc::LoadResult result = shadowc::loadFilterSource(text, "fuzz.shadow");
  // The caret printer indexes the source by the diagnostics' locations: fuzz it too.
  (void)shadowc::formatDiagnostics(result);
  if (result.spec) (void)shadowc::specToJson(*result.spec).dump();
  return 0;
}
