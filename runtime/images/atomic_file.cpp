#include "runtime/images/atomic_file.h"

#include <fmt/format.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace shadowc::rt {

void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes) {
  auto fail = [&](const std::string& why) {
    throw std::runtime_error(fmt::format("{}: cannot write: {}", path.string(), why));
  };
  std::error_code ec;
  if (path.has_parent_path()) {
    std::filesystem::create_directories(path.parent_path(), ec);
    if (ec) fail(ec.message());
  }
  static std::atomic<unsigned> counter{0};
  const std::filesystem::path tmp =
      path.string() + fmt::format(".tmp.{}.{}", static_cast<long>(::getpid()), counter.fetch_add(1));
  std::FILE* f = std::fopen(tmp.c_str(), "wb");
  if (f == nullptr) fail(std::strerror(errno));
  const bool ok = std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size() && std::fflush(f) == 0;
  const int closeResult = std::fclose(f);
  if (!ok || closeResult != 0) {
    std::filesystem::remove(tmp, ec);
    fail("short write");
  }
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    const std::string why = ec.message();
    std::filesystem::remove(tmp, ec);
    fail(why);
  }
}

}  // namespace shadowc::rt
