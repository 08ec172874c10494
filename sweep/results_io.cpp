#include "sweep/results_io.h"

#include <fmt/format.h>

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "runtime/images/atomic_file.h"
#include "sweep/pareto.h"
#include "sweep/shader_ratio.h"

namespace shadowc::sweep {
namespace {

using nlohmann::json;
using nlohmann::ordered_json;

rt::Metrics metricsFromJson(const json& j) {
  rt::Metrics m;
  m.pixels = j.at("pixels").get<uint64_t>();
  m.compared = j.at("compared").get<uint64_t>();
  m.rmse = j.at("rmse").get<double>();
  m.mae = j.at("mae").get<double>();
  m.maxAbsError = j.at("max_abs_error").get<double>();
  m.p99AbsError = j.at("p99_abs_error").get<double>();
  m.lightBleeding = j.at("light_bleeding").get<double>();
  m.overDarkening = j.at("over_darkening").get<double>();
  m.nonFinite = j.at("non_finite").get<uint64_t>();
  m.outOfRange = j.at("out_of_range").get<uint64_t>();
  m.invalidReference = j.at("invalid_reference").get<uint64_t>();
  return m;
}

std::string csvField(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::string readFile(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error(file.string() + ": cannot read");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

ordered_json rowToJson(const Row& r) {
  ordered_json j;
  j["key"] = r.key;
  j["variant_index"] = r.variantIndex;
  j["case_index"] = r.caseIndex;
  j["variant"] = r.variant;
  j["base"] = r.base;
  ordered_json params = ordered_json::object();
  for (const auto& [k, v] : r.params) params[k] = v;
  j["params"] = std::move(params);
  j["shader"] = r.shader;
  j["case"] = r.caseLabel;
  j["scene"] = r.scene;
  j["scene_hash"] = r.sceneHash;
  j["screen"] = r.screen;
  j["map"] = r.map;
  j["reference_samples"] = r.referenceSamples;
  j["runs"] = r.runs;
  j["warmup"] = r.warmup;
  j["content_hash"] = r.contentHash;
  j["total_ms"] = r.totalMs;
  j["total"] = rt::toJson(r.total);
  j["clock"] = r.clock;
  j["rejected_runs"] = r.rejectedRuns;
  if (!r.busyWarning.empty()) j["busy_warning"] = r.busyWarning;
  ordered_json passes = ordered_json::array();
  for (const auto& p : r.passes) passes.push_back({{"name", p.name}, {"kind", p.kind}, {"median_ms", p.medianMs}});
  j["passes"] = std::move(passes);
  j["metrics"] = rt::toJson(r.metrics);
  if (r.work) j["work"] = rt::workJson(*r.work);
  if (r.predictedMs) j["predicted_ms"] = *r.predictedMs;
  j["device"] = r.device;
  j["images"] = {{"result", r.resultImage}, {"error", r.errorImage}, {"reference", r.referenceImage}};
  j["filter_text"] = r.filterText;
  j["normalized_text"] = r.normalizedText;
  j["spec"] = r.spec;
  return j;
}

Row rowFromJson(const json& j) {
  try {
    Row r;
    r.key = j.at("key").get<std::string>();
    r.variantIndex = j.at("variant_index").get<size_t>();
    r.caseIndex = j.at("case_index").get<size_t>();
    r.variant = j.at("variant").get<std::string>();
    r.base = j.at("base").get<std::string>();
    for (const auto& [k, v] : j.at("params").items()) r.params.emplace_back(k, v.get<std::string>());
    r.shader = j.at("shader").get<std::string>();
    r.caseLabel = j.at("case").get<std::string>();
    r.scene = j.at("scene").get<std::string>();
    r.sceneHash = j.at("scene_hash").get<std::string>();
    r.screen = j.at("screen").get<uint32_t>();
    r.map = j.at("map").get<uint32_t>();
    r.referenceSamples = j.at("reference_samples").get<int>();
    r.runs = j.at("runs").get<int>();
    r.warmup = j.at("warmup").get<int>();
    r.contentHash = j.at("content_hash").get<std::string>();
    r.totalMs = j.at("total_ms").get<double>();
    // Rows from before intervals have none: their time is the median alone (pareto.h).
    if (j.contains("total")) r.total = rt::timingStatsFromJson(j.at("total"));
    // Rows written before the host-clock check carry neither: they were timed on device timestamps.
    r.clock = j.value("clock", std::string("device timestamps"));
    r.rejectedRuns = j.value("rejected_runs", 0);
    r.busyWarning = j.value("busy_warning", std::string());
    for (const auto& p : j.at("passes"))
      r.passes.push_back(
          {p.at("name").get<std::string>(), p.at("kind").get<std::string>(), p.at("median_ms").get<double>()});
    r.metrics = metricsFromJson(j.at("metrics"));
    if (j.contains("work")) r.work = rt::workFromJson(j.at("work"));
    if (j.contains("predicted_ms")) r.predictedMs = j.at("predicted_ms").get<double>();
    r.device = j.at("device").get<std::string>();
    r.resultImage = j.at("images").at("result").get<std::string>();
    r.errorImage = j.at("images").at("error").get<std::string>();
    r.referenceImage = j.at("images").at("reference").get<std::string>();
    r.filterText = j.at("filter_text").get<std::string>();
    r.normalizedText = j.at("normalized_text").get<std::string>();
    r.spec = j.at("spec");
    return r;
  } catch (const json::exception& e) {
    throw std::runtime_error(std::string("malformed result row: ") + e.what());
  }
}

std::string resultsJson(const Results& res) {
  const auto front = frontiers(res.rows);
  std::vector<bool> onFrontier(res.rows.size(), false);
  ordered_json f = ordered_json::object();
  for (const auto& [c, members] : front) {
    ordered_json keys = ordered_json::array();
    for (size_t i : members) {
      onFrontier[i] = true;
      keys.push_back(res.rows[i].key);
    }
    if (!members.empty()) f[res.rows[members.front()].caseLabel] = std::move(keys);
  }
  ordered_json j;
  j["format"] = "shadowc-sweep-results";
  j["version"] = kResultsVersion;
  j["sweep"] = res.sweep;
  j["shard"] = res.shard;
  j["stats"] = {
      {"rows", res.rows.size()}, {"ran", res.stats.ran}, {"cached", res.stats.cached}, {"skipped", res.skipped.size()}};
  ordered_json skipped = ordered_json::array();
  for (const auto& s : res.skipped)
    skipped.push_back(
        {{"variant_index", s.variantIndex}, {"variant", s.variant}, {"code", s.code}, {"message", s.message}});
  j["skipped"] = std::move(skipped);
  j["frontier"] = std::move(f);
  ordered_json rows = ordered_json::array();
  const std::vector<ShaderPair> pairs = shaderPairs(res.rows);
  for (size_t i = 0; i < res.rows.size(); ++i) {
    ordered_json row = rowToJson(res.rows[i]);
    row["frontier"] = bool(onFrontier[i]);
    if (const std::optional<double> ratio = pairedRatio(pairs, i)) row["specialized_over_generic"] = *ratio;
    rows.push_back(std::move(row));
  }
  j["rows"] = std::move(rows);
  return j.dump(2) + "\n";
}

Results parseResultsJson(const std::string& text, const std::string& label) {
  json j;
  try {
    j = json::parse(text);
  } catch (const json::parse_error& e) {
    throw std::runtime_error(fmt::format("{}: malformed JSON: {}", label, e.what()));
  }
  if (!j.is_object() || j.value("format", "") != "shadowc-sweep-results")
    throw std::runtime_error(label + ": not a shadowc sweep results.json");
  if (j.value("version", 0) != kResultsVersion)
    throw std::runtime_error(
        fmt::format("{}: results version {} (this shadowc reads {})", label, j.value("version", 0), kResultsVersion));
  Results r;
  try {
    r.sweep = j.at("sweep").get<std::string>();
    r.shard = j.at("shard").get<std::string>();
    r.stats.ran = j.at("stats").at("ran").get<size_t>();
    r.stats.cached = j.at("stats").at("cached").get<size_t>();
    for (const auto& s : j.at("skipped"))
      r.skipped.push_back({s.at("variant_index").get<size_t>(), s.at("variant").get<std::string>(),
                           s.at("code").get<std::string>(), s.at("message").get<std::string>()});
    for (const auto& row : j.at("rows")) r.rows.push_back(rowFromJson(row));
  } catch (const std::exception& e) {
    throw std::runtime_error(fmt::format("{}: {}", label, e.what()));
  }
  return r;
}

Results readResultsJson(const std::filesystem::path& file) { return parseResultsJson(readFile(file), file.string()); }

std::string resultsCsv(const Results& res) {
  const std::vector<FrontierMark> marks = frontierMarks(res.rows);
  std::string out =
      "case,scene,screen,map,variant,base,shader,params,total_ms,rmse,mae,max_abs_error,p99_abs_error,light_bleeding,"
      "over_darkening,non_finite,frontier,passes_ms,content_hash,key,spec,specialized_over_generic,clock,rejected_runs,"
      "runs,total_min_ms,total_p90_ms,total_ci_low_ms,total_ci_high_ms,total_cv,frontier_tie,tied_with,"
      "work_per_receiver,predicted_ms\n";
  const std::vector<ShaderPair> pairs = shaderPairs(res.rows);
  for (size_t i = 0; i < res.rows.size(); ++i) {
    const Row& r = res.rows[i];
    std::string params, passes;
    for (const auto& [k, v] : r.params) params += (params.empty() ? "" : ";") + k + "=" + v;
    for (const auto& p : r.passes) passes += fmt::format("{}{}={:.4f}", passes.empty() ? "" : ";", p.name, p.medianMs);
    const rt::Metrics& m = r.metrics;
    const std::optional<double> ratio = pairedRatio(pairs, i);
    const FrontierMark& mark = marks[i];
    std::string tied;
    for (size_t k : mark.tiedWith) tied += (tied.empty() ? "" : ";") + res.rows[k].variant;
    out += fmt::format(
        "{},{},{},{},{},{},{},{},{:.4f},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{},{},{},{},{},{},{},{},{},{},{:.4f},"
        "{:.4f},{:.4f},{:.4f},{:.4f},{},{},{},{}\n",
        csvField(r.caseLabel), csvField(r.scene), r.screen, r.map, csvField(r.variant), csvField(r.base), r.shader,
        csvField(params), r.totalMs, m.rmse, m.mae, m.maxAbsError, m.p99AbsError, m.lightBleeding, m.overDarkening,
        m.nonFinite, mark.membership != Membership::Off ? 1 : 0, csvField(passes), r.contentHash, r.key,
        csvField(r.spec.dump()), ratio ? fmt::format("{:.4f}", *ratio) : "", csvField(r.clock), r.rejectedRuns, r.runs,
        r.total.minMs, r.total.p90Ms, r.total.n > 0 ? r.total.ciLowMs : r.totalMs,
        r.total.n > 0 ? r.total.ciHighMs : r.totalMs, r.total.cv, mark.membership == Membership::Tied ? 1 : 0,
        csvField(tied), csvField(r.work ? rt::workFields(*r.work) : ""),
        r.predictedMs ? fmt::format("{:.4f}", *r.predictedMs) : "");
  }
  return out;
}

std::filesystem::path cachePath(const std::filesystem::path& dir, const std::string& key) {
  return dir / "cache" / (key + ".json");
}

std::optional<Row> readCachedRow(const std::filesystem::path& dir, const std::string& key) {
  const std::filesystem::path file = cachePath(dir, key);
  std::error_code ec;
  if (!std::filesystem::exists(file, ec)) return std::nullopt;
  try {
    Row r = rowFromJson(json::parse(readFile(file)));
    if (r.key != key) return std::nullopt;
    return r;
  } catch (const std::exception&) {
    return std::nullopt;  // a damaged cache entry is re-run, not trusted
  }
}

void writeCachedRow(const std::filesystem::path& dir, const Row& row) {
  rt::writeFileAtomically(cachePath(dir, row.key), rowToJson(row).dump(2) + "\n");
}

}  // namespace shadowc::sweep
