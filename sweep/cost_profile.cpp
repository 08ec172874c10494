#include "sweep/cost_profile.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "embed/embedded_file.h"
#include "plan/image_formats.h"
#include "spec/filter_spec.h"

namespace shadowc::cost_profiles {
std::span<const EmbeddedFile> all();
std::string_view find(std::string_view path);
}  // namespace shadowc::cost_profiles

namespace shadowc::sweep {

namespace {

using nlohmann::json;
using nlohmann::ordered_json;

constexpr const char* kShadeKind = "shade";

double mtexels(uint32_t side) { return double(side) * side * 1e-6; }

std::string readText(const std::filesystem::path& file, const std::string& what) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error(file.string() + ": error: cannot read the " + what);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace

// The warp's stored channels (image_formats.h) times the layers.
double momentChannelsOfSpec(const nlohmann::json& spec) {
  if (!spec.is_object() || !spec.contains("moments") || !spec["moments"].is_object()) return 0;
  const json& m = spec["moments"];
  const std::string warp = m.value("warp", std::string());
  for (Warp w : {Warp::Linear, Warp::Exp, Warp::Evsm2, Warp::Evsm4, Warp::PowerCdf, Warp::Msm})
    if (warp == name(w)) return double(momentChannels(w)) * m.value("layers", 1);
  return 0;
}

namespace {

struct PassPoint {
  double mtexels, mchannels, ms;
};

// min ||A x - b||^2 subject to x >= 0, by cyclic coordinate descent on the columns scaled to
// unit norm (the counts span nine orders of magnitude). Converges to the unique optimum of this
// convex problem; a fixed sweep order keeps it deterministic.
std::vector<double> nnls(const std::vector<std::vector<double>>& A, const std::vector<double>& b) {
  const size_t n = A.empty() ? 0 : A[0].size();
  std::vector<double> scale(n, 0.0), x(n, 0.0), r = b;  // r = b - A x
  for (size_t j = 0; j < n; ++j) {
    for (const auto& row : A) scale[j] += row[j] * row[j];
    scale[j] = std::sqrt(scale[j]);
  }
  for (int sweep = 0; sweep < 20000; ++sweep) {
    double moved = 0;
    for (size_t j = 0; j < n; ++j) {
      if (scale[j] == 0) continue;
      double g = 0;  // column j (scaled) . r
      for (size_t i = 0; i < A.size(); ++i) g += A[i][j] / scale[j] * r[i];
      const double next = std::max(0.0, x[j] + g);
      const double d = next - x[j];
      if (d == 0) continue;
      for (size_t i = 0; i < A.size(); ++i) r[i] -= d * A[i][j] / scale[j];
      x[j] = next;
      moved = std::max(moved, std::abs(d));
    }
    if (moved < 1e-13) break;
  }
  for (size_t j = 0; j < n; ++j) x[j] = scale[j] == 0 ? 0 : x[j] / scale[j];
  return x;
}

// Each equation divided by its measurement: the fit minimizes relative error, so a 0.05 ms pass
// weighs as much as a 50 ms one (the profile is judged by ratios).
void addRelative(std::vector<std::vector<double>>& A, std::vector<double>& b, std::vector<double> features,
                 double measured) {
  if (!(measured > 0)) return;
  for (double& f : features) f /= measured;
  A.push_back(std::move(features));
  b.push_back(1.0);
}

PassCost fitPass(const std::vector<PassPoint>& points) {
  std::vector<std::vector<double>> A;
  std::vector<double> b;
  for (const PassPoint& p : points) addRelative(A, b, {1.0, p.mtexels, p.mchannels}, p.ms);
  PassCost c;
  if (A.empty()) return c;
  const std::vector<double> x = nnls(A, b);
  c.fixedMs = x[0];
  c.msPerMtexel = x[1];
  c.msPerMchannel = x[2];
  c.samples = A.size();
  return c;
}

CostSample sampleFromJson(const json& r, const std::string& label, size_t i) {
  const std::string at = fmt::format("{}: error: rows[{}]", label, i);
  try {
    CostSample s;
    s.variant = r.at("variant").get<std::string>();
    s.caseLabel = r.at("case").get<std::string>();
    s.scene = r.value("scene", std::string());
    s.screen = r.at("screen").get<uint32_t>();
    s.map = r.at("map").get<uint32_t>();
    s.totalMs = r.at("total_ms").get<double>();
    s.device = r.value("device", std::string());
    for (const auto& p : r.at("passes"))
      s.passes.push_back(
          {p.at("name").get<std::string>(), p.at("kind").get<std::string>(), p.at("median_ms").get<double>()});
    if (r.contains("work")) s.work = rt::workFromJson(r["work"]);
    if (r.contains("spec")) s.momentChannels = momentChannelsOfSpec(r["spec"]);
    return s;
  } catch (const json::exception& e) {
    throw std::runtime_error(fmt::format("{}: {}", at, e.what()));
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(fmt::format("{}.work: {}", at, e.what()));
  }
}

}  // namespace

CostSample costSample(const Row& row) {
  return {row.variant, row.caseLabel, row.scene,   row.device, row.screen,
          row.map,     row.passes,    row.totalMs, row.work,   momentChannelsOfSpec(row.spec)};
}

std::vector<CostSample> readCostSamples(const std::filesystem::path& file) {
  json j;
  try {
    j = json::parse(readText(file, "sweep results"));
  } catch (const json::exception& e) {
    throw std::runtime_error(file.string() + ": error: malformed JSON: " + e.what());
  }
  if (!j.is_object() || !j.contains("rows") || !j["rows"].is_array())
    throw std::runtime_error(file.string() + ": error: expected sweep results with \"rows\"");
  std::vector<CostSample> out;
  for (size_t i = 0; i < j["rows"].size(); ++i) out.push_back(sampleFromJson(j["rows"][i], file.string(), i));
  return out;
}

size_t attachCounts(std::vector<CostSample>& samples, const std::vector<CostSample>& counted) {
  std::map<std::pair<std::string, std::string>, const CostSample*> byKey;
  for (const CostSample& c : counted)
    if (c.work) byKey.emplace(std::make_pair(c.variant, c.caseLabel), &c);
  size_t missing = 0;
  for (CostSample& s : samples) {
    if (s.work) continue;
    const auto it = byKey.find({s.variant, s.caseLabel});
    if (it == byKey.end()) {
      ++missing;
      continue;
    }
    s.work = it->second->work;
    if (s.momentChannels == 0) s.momentChannels = it->second->momentChannels;
  }
  return missing;
}

std::optional<double> CostProfile::passMs(const PassTime& pass, const CostSample& sample) const {
  if (pass.kind == kShadeKind) {
    if (!sample.work || shade.samples == 0) return std::nullopt;
    double ms = shade.fixedMs + shade.msPerMpixel * mtexels(sample.screen);
    for (size_t k = 0; k < sample.work->fields.size(); ++k) {
      const auto it = shade.msPerMcount.find(sample.work->fields[k]);
      if (it != shade.msPerMcount.end()) ms += it->second * double(sample.work->totals[k]) * 1e-6;
    }
    return ms;
  }
  // By the pass's name, else by its kind (a pass of a name the calibration did not run).
  const PassCost* cost = nullptr;
  if (const auto byName = passes.find(pass.name); byName != passes.end())
    cost = &byName->second;
  else if (const auto byKind = kinds.find(pass.kind); byKind != kinds.end())
    cost = &byKind->second;
  if (!cost) return std::nullopt;
  const double mt = mtexels(sample.map);
  return cost->fixedMs + cost->msPerMtexel * mt + cost->msPerMchannel * mt * sample.momentChannels;
}

std::optional<double> CostProfile::frameMs(const CostSample& sample) const {
  double ms = 0;
  for (const PassTime& p : sample.passes) {
    const std::optional<double> t = passMs(p, sample);
    if (!t) return std::nullopt;
    ms += *t;
  }
  return sample.passes.empty() ? std::nullopt : std::optional<double>(ms);
}

CostProfile fitCostProfile(const std::vector<CostSample>& samples, const std::string& device,
                           const std::string& command) {
  CostProfile p;
  p.device = device;
  p.generatedBy = command;
  // The shade pass: one equation per counted sample; the counters are the union of fields seen.
  std::vector<std::string> fields;
  for (const CostSample& s : samples)
    if (s.work)
      for (const std::string& f : s.work->fields)
        if (std::find(fields.begin(), fields.end(), f) == fields.end()) fields.push_back(f);
  std::sort(fields.begin(), fields.end());
  std::vector<std::vector<double>> A;
  std::vector<double> b;
  std::map<std::string, std::vector<PassPoint>> byName, byKind;
  for (const CostSample& s : samples) {
    for (const PassTime& pass : s.passes) {
      if (pass.kind != kShadeKind) {
        const PassPoint point{mtexels(s.map), mtexels(s.map) * s.momentChannels, pass.medianMs};
        byName[pass.name].push_back(point);
        byKind[pass.kind].push_back(point);
        continue;
      }
      if (!s.work) continue;
      std::vector<double> f = {1.0, mtexels(s.screen)};
      for (const std::string& field : fields) {
        const std::optional<uint64_t> t = s.work->total(field);
        f.push_back(t ? double(*t) * 1e-6 : 0.0);
      }
      addRelative(A, b, std::move(f), pass.medianMs);
    }
  }
  if (A.empty())
    throw std::runtime_error(
        "no shade pass with work counts to fit: run the calibration sweep with \"counters\": true "
        "(docs/cost.md), or give --counts-from a counted sweep of the same variants and cases");
  const std::vector<double> x = nnls(A, b);
  p.shade.fixedMs = x[0];
  p.shade.msPerMpixel = x[1];
  for (size_t k = 0; k < fields.size(); ++k) p.shade.msPerMcount[fields[k]] = x[2 + k];
  p.shade.samples = A.size();
  for (const auto& [name, points] : byName) p.passes[name] = fitPass(points);
  for (const auto& [kind, points] : byKind) p.kinds[kind] = fitPass(points);
  return p;
}

FitQuality assessFit(const CostProfile& profile, const std::vector<CostSample>& samples, double ratio) {
  FitQuality q;
  std::vector<double> logs;
  for (const CostSample& s : samples) {
    const std::optional<double> predicted = profile.frameMs(s);
    if (!predicted || !(s.totalMs > 0) || !(*predicted > 0)) {
      ++q.unpriced;
      continue;
    }
    const double l = std::abs(std::log(*predicted / s.totalMs));
    logs.push_back(l);
    if (l <= std::log(ratio)) ++q.within;
    if (l >= q.maxAbsLog) {
      q.maxAbsLog = l;
      q.worst = fmt::format("{} on {}: predicted {:.3f} ms, measured {:.3f} ms", s.variant, s.caseLabel, *predicted,
                            s.totalMs);
    }
  }
  q.priced = logs.size();
  if (!logs.empty()) {
    std::sort(logs.begin(), logs.end());
    const size_t n = logs.size();
    q.medianAbsLog = n % 2 ? logs[n / 2] : 0.5 * (logs[n / 2 - 1] + logs[n / 2]);
  }
  return q;
}

std::string costProfileToJson(const CostProfile& p) {
  ordered_json j;
  j["format"] = "shadowc-cost-profile";
  j["version"] = 1;
  j["device"] = p.device;
  j["generated_by"] = p.generatedBy;
  ordered_json counts = ordered_json::object();
  for (const auto& [field, c] : p.shade.msPerMcount) counts[field] = c;
  j["shade"] = {{"fixed_ms", p.shade.fixedMs},
                {"ms_per_mpixel", p.shade.msPerMpixel},
                {"ms_per_mcount", std::move(counts)},
                {"samples", p.shade.samples}};
  auto passTable = [](const std::map<std::string, PassCost>& m) {
    ordered_json t = ordered_json::object();
    for (const auto& [name, c] : m)
      t[name] = {{"fixed_ms", c.fixedMs},
                 {"ms_per_mtexel", c.msPerMtexel},
                 {"ms_per_mtexel_channel", c.msPerMchannel},
                 {"samples", c.samples}};
    return t;
  };
  j["passes"] = passTable(p.passes);
  j["kinds"] = passTable(p.kinds);
  return j.dump(1) + "\n";
}

CostProfile parseCostProfile(const std::string& text, const std::string& label) {
  json j;
  try {
    j = json::parse(text);
  } catch (const json::exception& e) {
    throw std::runtime_error(label + ": error: malformed cost profile JSON: " + e.what());
  }
  try {
    if (!j.is_object() || j.value("format", std::string()) != "shadowc-cost-profile")
      throw std::runtime_error(label + ": error: not a cost profile (\"format\" is not \"shadowc-cost-profile\")");
    if (j.at("version") != 1) throw std::runtime_error(label + ": error: cost profile version must be 1");
    CostProfile p;
    p.device = j.at("device");
    p.generatedBy = j.at("generated_by");
    const json& s = j.at("shade");
    p.shade.fixedMs = s.at("fixed_ms");
    p.shade.msPerMpixel = s.at("ms_per_mpixel");
    p.shade.samples = s.at("samples");
    for (const auto& [field, c] : s.at("ms_per_mcount").items()) p.shade.msPerMcount[field] = c.get<double>();
    auto readTable = [](const json& t, std::map<std::string, PassCost>& m) {
      for (const auto& [name, c] : t.items())
        m[name] = {c.at("fixed_ms"), c.at("ms_per_mtexel"), c.at("ms_per_mtexel_channel"), c.at("samples")};
    };
    readTable(j.at("passes"), p.passes);
    readTable(j.at("kinds"), p.kinds);
    auto negative = [](double v) { return !(v >= 0) || !std::isfinite(v); };
    bool bad = negative(p.shade.fixedMs) || negative(p.shade.msPerMpixel);
    for (const auto& [f, c] : p.shade.msPerMcount) bad = bad || negative(c);
    for (const auto* m : {&p.passes, &p.kinds})
      for (const auto& [n, c] : *m)
        bad = bad || negative(c.fixedMs) || negative(c.msPerMtexel) || negative(c.msPerMchannel);
    if (bad) throw std::runtime_error(label + ": error: cost profile coefficients must be finite and >= 0");
    return p;
  } catch (const json::exception& e) {
    throw std::runtime_error(label + ": error: cost profile: " + e.what());
  }
}

CostProfile loadCostProfile(const std::filesystem::path& file) {
  return parseCostProfile(readText(file, "cost profile"), file.string());
}

std::vector<std::string> builtInCostProfiles() {
  std::vector<std::string> names;
  for (const EmbeddedFile& f : cost_profiles::all()) {
    std::string n(f.path);
    if (n.ends_with(".json")) names.push_back(n.substr(0, n.size() - 5));
  }
  std::sort(names.begin(), names.end());
  return names;
}

CostProfile resolveCostProfile(const std::string& arg) {
  const bool file = arg.find('/') != std::string::npos || arg.ends_with(".json") ||
                    std::filesystem::is_regular_file(arg);
  if (file) return loadCostProfile(arg);
  const std::string_view text = cost_profiles::find(arg + ".json");
  if (!text.empty()) return parseCostProfile(std::string(text), "built-in cost profile " + arg);
  std::string names;
  for (const std::string& n : builtInCostProfiles()) names += (names.empty() ? "" : ", ") + n;
  throw std::runtime_error(
      fmt::format("{}: error: not a built-in cost profile ({}) nor a profile file", arg, names));
}

}  // namespace shadowc::sweep
