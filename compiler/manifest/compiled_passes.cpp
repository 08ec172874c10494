#include "manifest/compiled_passes.h"

#include <cctype>
#include <fstream>
#include <iterator>
#include <stdexcept>

namespace shadowc {

CompiledPasses CompiledPasses::fromDirectory(const std::filesystem::path& dirOrManifest) {
  std::filesystem::path file = dirOrManifest;
  if (std::filesystem::is_directory(file)) file /= "manifest.json";
  const std::filesystem::path dir = file.parent_path().empty() ? std::filesystem::path(".") : file.parent_path();
  CompiledPasses c;
  c.manifest = loadManifest(file.string());
  for (const Pass& pass : c.manifest.passes)
    for (const PassForm& form : formsOf(pass)) {  // every form: the executor picks one later
      if (c.files.count(form.spirv)) continue;    // passes that share a shader (mip1..mipK)
      std::ifstream in(dir / form.spirv, std::ios::binary);
      if (!in)
        throw std::runtime_error("pass '" + pass.name + "': SPIR-V file '" + (dir / form.spirv).string() +
                                 "' not found");
      c.files.emplace(form.spirv, std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>()));
    }
  return c;
}

bool CompiledPasses::isManifest(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) return std::filesystem::exists(path / "manifest.json", ec);
  std::ifstream in(path, std::ios::binary);
  for (int ch; (ch = in.get()) != std::ifstream::traits_type::eof();)
    if (!std::isspace(ch)) return ch == '{';
  return false;
}

}  // namespace shadowc
