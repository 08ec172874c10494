#include "emit/output_writer.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>

namespace shadowc {

std::string writeFilesAtomically(const std::filesystem::path& dir, const std::vector<EmittedFile>& files) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir))
    return "cannot create output directory '" + dir.string() + "': " + (ec ? ec.message() : "not a directory");
  const std::string suffix = ".shadowc-tmp-" + std::to_string(::getpid());
  std::vector<fs::path> temps;
  auto cleanup = [&] {
    for (const auto& t : temps) fs::remove(t, ec);
  };
  for (const auto& f : files) {
    const fs::path tmp = dir / (f.name + suffix);
    temps.push_back(tmp);
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (out) out.write(f.bytes.data(), static_cast<std::streamsize>(f.bytes.size()));
    out.flush();
    if (!out) {
      const std::string why = std::strerror(errno);
      cleanup();
      return "cannot write '" + (dir / f.name).string() + "': " + why;
    }
  }
  for (size_t i = 0; i < files.size(); ++i) {
    fs::rename(temps[i], dir / files[i].name, ec);
    if (ec) {
      cleanup();
      return "cannot rename into '" + (dir / files[i].name).string() + "': " + ec.message();
    }
  }
  return {};
}

}  // namespace shadowc
