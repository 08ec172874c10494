// Shared by the emit tests: the sample filter files, compiled through the driver (driver/driver.h).
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "backend/spirv_backend.h"
#include "driver/driver.h"
#include "support/test_support.h"

namespace shadowc::test {

inline std::vector<std::string> sampleFilterNames() {
  std::vector<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(sourceDir() / "samples" / "filters"))
    if (e.path().extension() == ".shadow") names.push_back(e.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

inline std::filesystem::path samplePath(const std::string& name) {
  return sourceDir() / "samples" / "filters" / (name + ".shadow");
}

inline driver::Options optimizeOption(bool optimize) {
  driver::Options o;
  o.optimize = optimize;
  return o;
}

// A sample filter file through the whole pipeline.
inline driver::Result compileSample(const std::string& name, bool optimize = true) {
  return driver::compileFile(samplePath(name).string(), optimizeOption(optimize));
}

// A file of the artifact; fails the test when the compile failed or the file is absent.
inline std::string artifactFile(const driver::Result& r, const std::string& name) {
  if (!r.artifact) {
    ADD_FAILURE() << "no artifact:\n" << r.log;
    return {};
  }
  if (const std::string* bytes = r.artifact->file(name)) return *bytes;
  ADD_FAILURE() << "no emitted file " << name;
  return {};
}

// name -> bytes of every file in a directory.
inline std::map<std::string, std::string> readDir(const std::filesystem::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    files[e.path().filename().string()] = readFile(e.path());
  return files;
}

inline std::vector<uint32_t> spirvWords(const std::string& bytes) {
  std::vector<uint32_t> words(bytes.size() / 4);
  for (size_t i = 0; i < words.size(); ++i)
    for (int b = 0; b < 4; ++b)
      words[i] |= static_cast<uint32_t>(static_cast<unsigned char>(bytes[4 * i + b])) << (8 * b);
  return words;
}

// Every .spv file of the artifact passes spirv-val (a failure per module, named `label/file`);
// returns how many modules there were.
inline int expectEverySpirvValid(const driver::Artifact& a, const std::string& label) {
  int modules = 0;
  for (const auto& f : a.files)
    if (f.name.ends_with(".spv")) {
      EXPECT_EQ(validateSpirv(spirvWords(f.bytes)), "") << label << "/" << f.name;
      ++modules;
    }
  return modules;
}

}  // namespace shadowc::test
