// content_hash of manifest.json: XXH3-128 (libxxhash, Debian's libxxhash-dev) over every
// emitted file but the manifest, in file-name order, each as name, NUL, 8-byte little-endian
// size, bytes. The hash only has to detect change, not resist an attacker, so a fast
// non-cryptographic hash with a frozen, specified output (xxHash 0.8 "XXH3 stable") fits
// better than SHA-256; the algorithm is named in the value: "xxh3-128:<32 hex digits>".
#pragma once

#include <string>
#include <vector>

namespace shadowc {

struct EmittedFile {
  std::string name;  // relative to the output directory
  std::string bytes;
};

std::string contentHash(const std::vector<EmittedFile>& files);  // skips "manifest.json"

}  // namespace shadowc
