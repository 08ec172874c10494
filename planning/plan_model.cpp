#include "planning/plan_model.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string_view>

namespace shadowc::plan_model {
std::string_view find(std::string_view path);  // samples/plan/* embedded (planning/CMakeLists.txt)
}

namespace shadowc::planning {

const std::vector<std::string> kErrorTerms = {"one", "penumbra_fraction", "penumbra_fraction_x_log2_width",
                                              "contact_fraction", "multi_depth_x_penumbra_fraction"};

// What makes a variant err: how much of the image lies in a penumbra, how wide the penumbrae
// are (log2, in texels: a fixed kernel's error grows with the width it cannot follow), how
// much is in contact, and how much penumbra holds several occluder depths.
std::vector<double> errorTerms(const SceneStats& s) {
  const double pen = s.receivers ? double(s.penumbra) / double(s.receivers) : 0.0;
  return {1.0, pen, pen * std::log2(1.0 + s.penumbraTexels.p50), s.contactFraction(), s.multiDepthFraction() * pen};
}

double PlanModel::predictMs(const std::string& variant, uint32_t mapSize, uint32_t screenSize) const {
  const auto it = variants.find(variant);
  if (it == variants.end()) throw std::invalid_argument("the plan model has no variant '" + variant + "'");
  return it->second.msPerMtexel * double(mapSize) * mapSize * 1e-6 +
         it->second.msPerMpixel * double(screenSize) * screenSize * 1e-6;
}

double PlanModel::predictRmse(const std::string& variant, const SceneStats& s) const {
  const auto it = variants.find(variant);
  if (it == variants.end()) throw std::invalid_argument("the plan model has no variant '" + variant + "'");
  const std::vector<double> x = errorTerms(s);
  double e = 0;
  for (size_t k = 0; k < x.size() && k < it->second.coefficients.size(); ++k) e += it->second.coefficients[k] * x[k];
  return std::max(e, it->second.rmseFloor);
}

namespace {

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// Solves (X^T X + lambda I) c = X^T y by Gaussian elimination with partial pivoting.
std::vector<double> ridge(const std::vector<std::vector<double>>& X, const std::vector<double>& y, double lambda) {
  const size_t n = X.empty() ? 0 : X[0].size();
  std::vector<std::vector<double>> A(n, std::vector<double>(n + 1, 0.0));
  for (size_t r = 0; r < X.size(); ++r)
    for (size_t i = 0; i < n; ++i) {
      for (size_t j = 0; j < n; ++j) A[i][j] += X[r][i] * X[r][j];
      A[i][n] += X[r][i] * y[r];
    }
  for (size_t i = 1; i < n; ++i) A[i][i] += lambda;  // the intercept is not shrunk
  for (size_t c = 0; c < n; ++c) {
    size_t p = c;
    for (size_t r = c + 1; r < n; ++r)
      if (std::abs(A[r][c]) > std::abs(A[p][c])) p = r;
    std::swap(A[c], A[p]);
    if (std::abs(A[c][c]) < 1e-15) continue;
    for (size_t r = 0; r < n; ++r) {
      if (r == c) continue;
      const double f = A[r][c] / A[c][c];
      for (size_t k = c; k <= n; ++k) A[r][k] -= f * A[c][k];
    }
  }
  std::vector<double> coef(n, 0.0);
  for (size_t i = 0; i < n; ++i) coef[i] = std::abs(A[i][i]) < 1e-15 ? 0.0 : A[i][n] / A[i][i];
  return coef;
}

}  // namespace

VariantModel fitVariant(std::vector<CalibrationRun> runs) {
  VariantModel m;
  std::vector<double> perTexel, perPixel;
  std::vector<std::vector<double>> X;
  std::vector<double> y;
  m.rmseFloor = runs.empty() ? 0 : 1.0;
  for (const CalibrationRun& r : runs) {
    perTexel.push_back(r.mapMs / (double(r.map) * r.map * 1e-6));
    perPixel.push_back(r.shadeMs / (double(r.screen) * r.screen * 1e-6));
    X.push_back(r.terms);
    y.push_back(r.rmse);
    m.rmseFloor = std::min(m.rmseFloor, r.rmse);
  }
  m.msPerMtexel = median(perTexel);
  m.msPerMpixel = median(perPixel);
  m.coefficients = ridge(X, y, 1e-3);
  m.runs = std::move(runs);
  return m;
}

PlanModel parseModel(const std::string& text, const std::string& label) {
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(label + ": error: malformed plan model JSON: " + e.what());
  }
  try {
    PlanModel m;
    const auto& r = j.at("rules");
    m.rules.penumbraTexels = r.at("penumbra_texels");
    m.rules.penumbraQuantile = r.at("penumbra_quantile");
    m.rules.contactFraction = r.at("contact_fraction");
    m.rules.multiDepthFraction = r.at("multi_depth_fraction");
    m.rules.uniformFraction = r.at("uniform_fraction");
    m.rules.satTexels = r.at("sat_texels");
    m.rules.quadtreeTexels = r.at("quadtree_texels");
    m.rules.slopeDegrees = r.at("slope_degrees");
    m.rules.cascadeDepthRatio = r.value("cascade_depth_ratio", PlanRules{}.cascadeDepthRatio);
    m.rules.confirmMargin = r.at("confirm_margin");
    m.rules.confirmTimeSlack = r.at("confirm_time_slack");
    m.generatedBy = j.at("generated_by");
    m.screen = j.at("calibration").at("screen");
    m.map = j.at("calibration").at("map");
    m.samples = j.at("calibration").at("samples");
    for (const auto& [name, v] : j.at("variants").items()) {
      VariantModel vm;
      vm.msPerMtexel = v.at("cost").at("ms_per_mtexel");
      vm.msPerMpixel = v.at("cost").at("ms_per_mpixel");
      vm.coefficients = v.at("error").at("coefficients").get<std::vector<double>>();
      vm.rmseFloor = v.at("error").at("rmse_floor");
      for (const auto& run : v.at("runs")) {
        CalibrationRun c;
        c.scene = run.at("scene");
        c.screen = run.at("screen");
        c.map = run.at("map");
        c.rmse = run.at("rmse");
        c.totalMs = run.at("total_ms");
        c.mapMs = run.at("map_ms");
        c.shadeMs = run.at("shade_ms");
        c.terms = run.at("terms").get<std::vector<double>>();
        vm.runs.push_back(std::move(c));
      }
      m.variants[name] = std::move(vm);
    }
    return m;
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(label + ": error: plan model: " + e.what());
  }
}

PlanModel loadModel(const std::string& path) {
  if (path.empty()) {
    const std::string_view text = plan_model::find("model.json");
    if (text.empty()) throw std::runtime_error("no plan model built in (samples/plan/model.json)");
    return parseModel(std::string(text), "samples/plan/model.json");
  }
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": error: cannot read the plan model");
  std::stringstream ss;
  ss << in.rdbuf();
  return parseModel(ss.str(), path);
}

std::string modelToJson(const PlanModel& m) {
  nlohmann::ordered_json j;
  j["format_version"] = 2;  // 2: runs carry their screen and map
  j["generated_by"] = m.generatedBy;
  j["calibration"] = {{"screen", m.screen}, {"map", m.map}, {"samples", m.samples}};
  j["rules"] = {
      {"penumbra_texels", m.rules.penumbraTexels},        {"penumbra_quantile", m.rules.penumbraQuantile},
      {"contact_fraction", m.rules.contactFraction},      {"multi_depth_fraction", m.rules.multiDepthFraction},
      {"uniform_fraction", m.rules.uniformFraction},      {"sat_texels", m.rules.satTexels},
      {"quadtree_texels", m.rules.quadtreeTexels},        {"slope_degrees", m.rules.slopeDegrees},
      {"cascade_depth_ratio", m.rules.cascadeDepthRatio}, {"confirm_margin", m.rules.confirmMargin},
      {"confirm_time_slack", m.rules.confirmTimeSlack}};
  j["error_terms"] = kErrorTerms;
  nlohmann::ordered_json vs = nlohmann::ordered_json::object();
  for (const auto& [name, v] : m.variants) {
    nlohmann::ordered_json jv;
    jv["cost"] = {{"ms_per_mtexel", v.msPerMtexel}, {"ms_per_mpixel", v.msPerMpixel}};
    jv["error"] = {{"coefficients", v.coefficients}, {"rmse_floor", v.rmseFloor}};
    auto& runs = jv["runs"] = nlohmann::ordered_json::array();
    for (const CalibrationRun& r : v.runs)
      runs.push_back({{"scene", r.scene},
                      {"screen", r.screen},
                      {"map", r.map},
                      {"rmse", r.rmse},
                      {"total_ms", r.totalMs},
                      {"map_ms", r.mapMs},
                      {"shade_ms", r.shadeMs},
                      {"terms", r.terms}});
    vs[name] = std::move(jv);
  }
  j["variants"] = std::move(vs);
  return j.dump(1) + "\n";
}

}  // namespace shadowc::planning
