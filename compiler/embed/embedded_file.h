// A text file compiled into the binary by cmake/Embed.cmake (templates, runtime shaders).
#pragma once

#include <span>
#include <string_view>

namespace shadowc {
struct EmbeddedFile {
  std::string_view path;  // relative to the embedded folder, e.g. "frame.glsl"
  std::string_view text;
};
}  // namespace shadowc

// Each embedded set declares its accessors like this (see cmake/Embed.cmake):
namespace shadowc::templates {
std::span<const EmbeddedFile> all();
std::string_view find(std::string_view path);  // empty view when absent
}  // namespace shadowc::templates
