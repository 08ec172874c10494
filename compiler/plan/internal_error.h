// A broken invariant inside the compiler — never bad user input, which the checker rejects
// with a located diagnostic. plan/ and emit/ throw it where their input should already have
// been validated; the message says it is a shadowc bug.
#pragma once

#include <stdexcept>
#include <string>

namespace shadowc {

struct InternalError : std::logic_error {
  explicit InternalError(const std::string& what)
      : std::logic_error("internal error (a shadowc bug, please report it): " + what) {}
};

}  // namespace shadowc
