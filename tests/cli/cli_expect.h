// Expectations on a shadowc run that should fail with one clear error (both CLI test files use
// them: a mistake gets exactly one `error:` line naming it, and no report after it).
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "support/test_support.h"

namespace shadowc::test {

inline int errorLines(const std::string& err) {
  int n = 0;
  for (size_t at = 0; (at = err.find("error:", at)) != std::string::npos; ++at) ++n;
  return n;
}

inline void expectOneError(const CliResult& r, const std::string& phrase) {
  EXPECT_NE(r.code, 0) << r.out << r.err;
  EXPECT_EQ(errorLines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find(phrase), std::string::npos) << "expected '" << phrase << "' in:\n" << r.err;
  EXPECT_EQ(r.out.find("rmse"), std::string::npos) << "no report after an error";
}

}  // namespace shadowc::test
