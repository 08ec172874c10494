// runtime/shaders/* embedded at build time (cmake/Embed.cmake, target shadowc_runtime_shaders).
#pragma once

#include <span>
#include <string_view>

#include "embed/embedded_file.h"

namespace shadowc::runtime_shaders {
std::span<const EmbeddedFile> all();
std::string_view find(std::string_view path);  // empty view when absent
}  // namespace shadowc::runtime_shaders
