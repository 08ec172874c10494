// Shared by the emit tests: the sample filter files, and emitting a file or spec into a dir.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "driver/driver.h"
#include "emit/filter_emitter.h"
#include "emit/output_writer.h"
#include "spec/load_filter.h"
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

inline FilterSpec loadSample(const std::string& name) {
  const LoadResult r = loadFilterFile(samplePath(name).string());
  if (!r.spec) throw std::runtime_error("sample " + name + " does not load:\n" + formatDiagnostics(r));
  return *r.spec;
}

// A spec through the compiler driver (the one place that wires plan and emit), as the
// emitter's result: ok, log, manifest and the sorted files.
inline FilterEmitResult compile(const FilterSpec& spec, bool optimize = true) {
  driver::Options o;
  o.optimize = optimize;
  driver::Result r = driver::compileSpec(spec, o);
  FilterEmitResult out;
  out.ok = r.ok && r.artifact.has_value();
  out.log = r.log;
  if (r.artifact) {
    out.manifest = std::move(r.artifact->manifest);
    out.files = std::move(r.artifact->files);
  }
  return out;
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

}  // namespace shadowc::test
