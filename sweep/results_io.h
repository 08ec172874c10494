// results.json, results.csv and the per-row cache files (docs/sweep.md "Results", "Resume"):
// one format, read back by resume and by merge. Every write is atomic (rt::writeFileAtomically),
// so an interrupted sweep leaves whole files or none.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "sweep/sweep_row.h"

namespace shadowc::sweep {

inline constexpr int kResultsVersion = 3;  // 2: rows carry normalized_text; 3: and their total's interval

nlohmann::ordered_json rowToJson(const Row& row);
Row rowFromJson(const nlohmann::json& j);  // throws std::runtime_error naming the missing field

// results.json: the sweep, stats, skipped variants, the rows (each with "frontier": bool) and
// the frontier per case as lists of keys.
std::string resultsJson(const Results& results);
Results parseResultsJson(const std::string& text, const std::string& label);
Results readResultsJson(const std::filesystem::path& file);

// results.csv: one line per row, RFC 4180 quoting; the spec as compact JSON in one field.
std::string resultsCsv(const Results& results);

// DIR/cache/<key>.json: one finished row. A missing or unreadable file is a miss.
std::filesystem::path cachePath(const std::filesystem::path& dir, const std::string& key);
std::optional<Row> readCachedRow(const std::filesystem::path& dir, const std::string& key);
void writeCachedRow(const std::filesystem::path& dir, const Row& row);

}  // namespace shadowc::sweep
