#include "emit/template_includes.h"

#include "embed/embedded_file.h"

namespace shadowc {

std::string_view templateText(std::string_view path) { return templates::find(path); }

TemplateResolver templateIncludes() {
  return [](const std::string& name) -> std::optional<std::string> {
    // The backend does not pass the including file's folder, so siblings inside lookup/ and
    // passes/ are found by trying those folders after the templates root.
    for (const char* dir : {"", "lookup/", "passes/"}) {
      const std::string_view text = templates::find(std::string(dir) + name);
      if (!text.empty()) return std::string(text);
    }
    return std::nullopt;
  };
}

}  // namespace shadowc
