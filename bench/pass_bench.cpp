// pass_bench: every prefilter pass kind against the device's copy limit, and each lookup's shade
// cost per pixel (a benchmark, never a test: it prints medians, nothing here can fail CI).
//
// lavapipe is bound by per-texel image load/store, not by memory (docs/performance.md
// "Prefilter passes against the copy limit"), so a pass is measured against a plain compute copy of an image of the
// same size and format, timed in the same process on the same device (the anchor); the tables print ratios. Every
// filter is compiled by the driver and run through the run harness (warm-up, then the median of the timed runs); the
// copies are a hand-built manifest run the same way.
//
// Passes with several forms (docs/manifest.md "Pass forms") are timed in each, beside the
// executor's own choice for the device.
// Usage: pass_bench [runs] [sample-substrings, '|'-separated] [map sizes, comma separated] [filter folders, comma
// separated] [scene] [screen] [device]
//   defaults: 5 runs after 2 warm-ups, every sample, 512,1024,2048, samples/filters, two_planes,
//   screen 256^2, lavapipe (else a Vulkan device index or name substring, e.g. nvidia) (the scene: a built-in name or a
//   .json path, as `shadowc validate --scene`). bench/filters holds inputs that are no samples (the mixed scheme, the
//   unfused moments + SAT reference).
// Run with MESA_SHADER_CACHE_DISABLE=true so that runs are comparable.
#include <fmt/core.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "compiler/backend/spirv_backend.h"
#include "compiler/driver/driver.h"
#include "runtime/harness/scene_run.h"
#include "runtime/vulkan/vulkan_context.h"
#include "shadowc_source_dir.h"

namespace fs = std::filesystem;
using namespace shadowc;

namespace {

constexpr int kWarmup = 2;

struct CopyFormat {
  ImageFormat format;
  const char* qualifier;  // GLSL image format qualifier
  bool integer;
};

const std::vector<CopyFormat>& copyFormats() {
  static const std::vector<CopyFormat> f = {
      {ImageFormat::R32F, "r32f", false},       {ImageFormat::RG32F, "rg32f", false},
      {ImageFormat::RGBA32F, "rgba32f", false}, {ImageFormat::RG16F, "rg16f", false},
      {ImageFormat::RGBA16F, "rgba16f", false}, {ImageFormat::RG16Unorm, "rg16", false},
      {ImageFormat::RG32UI, "rg32ui", true},    {ImageFormat::RGBA32UI, "rgba32ui", true},
  };
  return f;
}

std::string spirvBytes(const std::string& name, const std::string& glsl) {
  const SpirvResult r = compileGlsl(glsl, ShaderStage::Compute, name, {}, BackendOptions{});
  if (!r.ok) throw std::runtime_error(name + ": " + r.log);
  return std::string(reinterpret_cast<const char*>(r.words.data()), r.words.size() * 4);
}

// One copy pass per format (src -> dst, map size, 8x8 groups: the planner's texel passes use the
// same), plus the one-texel visibility pass the harness needs.
CompiledPasses copyPasses() {
  CompiledPasses c;
  Manifest& m = c.manifest;
  m.filter = "copy_anchor";
  auto addImage = [&](std::string name, ImageFormat f, SizeDomain d, ImageRole role) {
    ImageDesc im;
    im.name = std::move(name);
    im.format = f;
    im.size.domain = d;
    im.role = role;
    m.images.push_back(im);
  };
  for (const CopyFormat& f : copyFormats()) {
    const std::string tag = f.qualifier;
    addImage("src_" + tag, f.format, SizeDomain::Map, ImageRole::Internal);
    addImage("dst_" + tag, f.format, SizeDomain::Map, ImageRole::Internal);
    const std::string type = f.integer ? "uimage2D" : "image2D";
    const std::string glsl = fmt::format(R"(#version 460
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 0, {0}) readonly uniform {1} src;
layout(set = 0, binding = 1, {0}) writeonly uniform {1} dst;
void main() {{
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(dst)))) return;
  imageStore(dst, p, imageLoad(src, p));
}}
)",
                                         f.qualifier, type);
    Pass p;
    p.name = "copy_" + tag;
    p.kind = "copy";
    p.spirv = p.name + ".spv";
    p.glsl = p.name + ".glsl";
    p.dispatch.size.domain = SizeDomain::Map;
    p.bindings = {{0, "src_" + tag, Access::StorageRead, -1}, {1, "dst_" + tag, Access::StorageWrite, -1}};
    c.files[p.spirv] = spirvBytes(p.name, glsl);
    m.passes.push_back(p);
  }
  addImage("visibility", ImageFormat::R32F, SizeDomain::Screen, ImageRole::OutputVisibility);
  Pass v;
  v.name = "visibility";
  v.kind = "clear";
  v.spirv = "visibility.spv";
  v.glsl = "visibility.glsl";
  v.dispatch.size.domain = SizeDomain::Screen;
  v.bindings = {{0, "visibility", Access::StorageWrite, -1}};
  c.files[v.spirv] = spirvBytes("visibility", R"(#version 460
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 0, r32f) writeonly uniform image2D visibility;
void main() { imageStore(visibility, ivec2(gl_GlobalInvocationID.xy), vec4(1.0)); }
)");
  m.passes.push_back(v);
  return c;
}

// The format of the map-level image a pass writes (its anchor), or nullopt.
std::optional<ImageFormat> writtenFormat(const Manifest& m, const Pass& p) {
  for (const Binding& b : p.bindings)
    if (b.access == Access::StorageWrite || b.access == Access::StorageReadWrite)
      for (const ImageDesc& im : m.images)
        if (im.name == b.image) return im.format;
  return std::nullopt;
}

// Texel fetches per shaded pixel, worst case, from the spec (what the lookup templates read):
// a SAT box is 4 texel reads of the SAT (sat.glsl; 16 with bilinear corners), a uniform m x m walk
// with whole-texel corners reads each row two columns (4 corners) a step, sharing corners along a
// row: 4 m ceil((m + 1) / 2) reads (vssm.glsl shadowc_uniformWalk), plus the root's 4 first (both
// `subdivide` forms test it); a quadtree counts every node, a PCF
// leaf n^2 reads, a PCF tap 1 depth read (bilinear = 4 texels, counted as 1 gather-like sample here), a min-max early
// out 4 reads of one pyramid level.
std::string fetchesPerPixel(const FilterSpec& s) {
  const bool moments = s.representation == Representation::Moments;
  const bool sat = moments && s.storage.sat != SatKind::None;
  long long n = s.earlyOutMinMax ? 4 : 0;
  if (!moments) {
    const long long pcf =
        s.sampling.pattern == PcfPattern::Poisson ? s.sampling.taps : 1LL * s.sampling.gridN * s.sampling.gridN;
    const long long search = s.blocker.kind == BlockerKind::Search ? s.blocker.taps : 0;
    return fmt::format("{} ({} search + {} pcf{})", n + pcf + search, search, pcf, n ? " + 4 minmax" : "");
  }
  if (!sat) return fmt::format("{} (moments texels{})", n + s.moments.layers, n ? " + 4 minmax" : "");
  const long long perBox = s.storage.fractionalCorners ? 16 : 4;
  auto reads = [&](Subdivision sub, int m, int h) -> long long {
    if (sub == Subdivision::Uniform && m > 1)
      return perBox + (s.storage.fractionalCorners ? perBox * m * m : 4LL * m * ((m + 2) / 2));
    if (sub == Subdivision::Quadtree) return perBox * (((1LL << (2 * (h + 1))) - 1) / 3);  // every node
    return perBox;
  };
  const long long blocker = s.blocker.kind == BlockerKind::Moments
                                ? reads(s.blocker.subdivision, s.blocker.uniformM, s.blocker.quadtreeHeight)
                                : 0;
  const long long kernel = reads(s.kernel.subdivision, s.kernel.uniformN, s.kernel.quadtreeHeight);
  const long long leaves = s.kernel.subdivision == Subdivision::Quadtree  ? (1LL << (2 * s.kernel.quadtreeHeight))
                           : s.kernel.subdivision == Subdivision::Uniform ? 1LL * s.kernel.uniformN * s.kernel.uniformN
                                                                          : 1;
  const long long fallback = s.fallback.pcf ? leaves * s.fallback.n * s.fallback.n : 0;
  const long long contact = s.contact.enabled ? 1LL * s.contact.n * s.contact.n : 0;
  const long long total = n + blocker + kernel + fallback;  // contact replaces the kernel walk
  return fmt::format("{} ({} blocker + {} kernel SAT reads{}{}{})", total, blocker, kernel,
                     fallback ? fmt::format(" + {} fallback", fallback) : "",
                     contact ? fmt::format("; contact path {}", contact) : "", n ? " + 4 minmax" : "");
}

std::vector<uint32_t> parseSizes(const std::string& s) {
  std::vector<uint32_t> out;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, ',');) out.push_back(static_cast<uint32_t>(std::stoul(item)));
  return out;
}

// `only` is one substring or several separated by '|' ("sat|minmax"); empty matches all.
bool matches(const std::string& name, const std::string& only) {
  std::stringstream in(only);
  for (std::string item; std::getline(in, item, '|');)
    if (name.find(item) != std::string::npos) return true;
  return only.empty();
}

// "auto" (the executor's own choice: the shade row and every pass with one form), then each form
// name of passes that have several, in the order the manifest lists them.
std::vector<std::string> formNames(const Manifest& m) {
  std::vector<std::string> names{rt::kPassFormAuto};
  for (const Pass& p : m.passes)
    if (!p.forms.empty())
      for (const PassForm& f : formsOf(p))
        if (std::find(names.begin(), names.end(), f.name) == names.end()) names.push_back(f.name);
  return names;
}

std::string repeat(const std::string& s, size_t n) {
  std::string out;
  for (size_t i = 0; i < n; ++i) out += s;
  return out;
}

}  // namespace

int main(int argc, char** argv) try {
  const int runs = argc > 1 ? std::max(1, std::atoi(argv[1])) : 5;
  const std::string only = argc > 2 ? argv[2] : "";
  const std::vector<uint32_t> sizes = parseSizes(argc > 3 ? argv[3] : "512,1024,2048");
  std::vector<fs::path> folders;
  std::stringstream folderList(argc > 4 ? argv[4] : "");
  for (std::string item; std::getline(folderList, item, ',');) folders.emplace_back(item);
  if (folders.empty()) folders.push_back(fs::path(SHADOWC_SOURCE_DIR) / "samples" / "filters");
  const std::string sceneName = argc > 5 ? argv[5] : "two_planes";
  const uint32_t screen = argc > 6 ? static_cast<uint32_t>(std::stoul(argv[6])) : 256;
  rt::VulkanOptions device;
  if (argc > 7) device.device = argv[7];  // as `shadowc validate --device`: an index or a name substring

  std::vector<driver::Artifact> filters;
  for (const fs::path& folder : folders)
    for (const auto& e : fs::directory_iterator(folder))
      if (e.path().extension() == ".shadow" && matches(e.path().stem().string(), only)) {
        driver::Result r = driver::compileFile(e.path().string());
        if (!r.artifact) {
          fmt::print(stderr, "skipping {}:\n{}", e.path().filename().string(), r.log);
          continue;
        }
        filters.push_back(std::move(*r.artifact));
      }
  std::sort(filters.begin(), filters.end(), [](const auto& a, const auto& b) { return a.spec.name < b.spec.name; });
  const CompiledPasses copies = copyPasses();

  rt::VulkanContext ctx(device);
  fmt::print("device: {}; screen {}^2, {}; {} warm-up + {} timed runs, medians (ms)\n\n", ctx.describe(), screen,
             sceneName, kWarmup, runs);
  const rt::RunOptions options{kWarmup, runs, {}};

  // Per map size: the copy anchors, then every filter's passes.
  std::map<uint32_t, std::map<ImageFormat, double>> anchor;
  struct Row {
    std::string filter, kind;
    ImageFormat format;
    std::map<uint32_t, double> ms;
  };
  std::vector<Row> rows;  // prefilter kinds
  struct Shade {
    std::string filter, fetches;
    std::map<uint32_t, double> ms, rmse;
  };
  std::vector<Shade> shades;
  for (const driver::Artifact& a : filters) shades.push_back({a.spec.name, fetchesPerPixel(a.spec), {}, {}});

  for (uint32_t map : sizes) {
    rt::SceneSettings settings;
    settings.scene = sceneName;
    settings.screen = screen;
    settings.map = map;
    const auto scene = rt::prepareScene(ctx, settings);
    rt::RunInputs copyIn;
    copyIn.mapSize = map;
    copyIn.width = copyIn.height = screen;
    copyIn.frame = scene->setup.frame;
    const rt::RunOutputs c = rt::runPasses(ctx, copies, copyIn, options);
    for (size_t i = 0; i < copyFormats().size(); ++i)
      anchor[map][copyFormats()[i].format] = c.timing->passes[i].medianMs;

    for (size_t f = 0; f < filters.size(); ++f) {
      const driver::Artifact& a = filters[f];
      // A filter whose passes come in several forms runs once more per form (the executor's
      // override): rows "sat [serial]", "sat [parallel]" beside "sat", the auto choice, which alone
      // counts in the totals below.
      for (const std::string& form : formNames(a.manifest)) {
        rt::RunOptions run = options;
        run.passForm = form;
        const rt::SceneRunResult r = rt::runOnScene(ctx, a.passes(), *scene, run);
        std::map<std::string, std::pair<ImageFormat, double>> byKind;  // prefilter kind -> (format, ms)
        for (size_t p = 0; p < a.manifest.passes.size(); ++p) {
          const Pass& pass = a.manifest.passes[p];
          const double ms = r.outputs.timing->passes[p].medianMs;
          if (pass.kind == "shade") {
            if (form != rt::kPassFormAuto) continue;
            shades[f].ms[map] = ms;
            shades[f].rmse[map] = r.metrics.rmse;
            continue;
          }
          const bool forced = form != rt::kPassFormAuto;
          if (forced && pass.forms.empty()) continue;
          const std::string kind = forced ? pass.kind + " [" + form + "]" : pass.kind;
          auto [it, fresh] = byKind.try_emplace(kind, writtenFormat(a.manifest, pass).value_or(ImageFormat::R32F), 0.0);
          it->second.second += ms;
        }
        for (const auto& [kind, v] : byKind) {
          auto row = std::find_if(rows.begin(), rows.end(),
                                  [&](const Row& x) { return x.filter == a.spec.name && x.kind == kind; });
          if (row == rows.end()) row = rows.insert(rows.end(), Row{a.spec.name, kind, v.first, {}});
          row->ms[map] = v.second;
        }
      }
    }
  }

  auto header = [&](const std::string& first) {
    std::string h = "| " + first;
    for (uint32_t map : sizes) h += fmt::format(" | {0}² ms | {0}² ÷ copy", map);
    fmt::print("{} |\n|---|---|---|{}\n", h, repeat("---:|---:|", sizes.size()));
  };
  fmt::print("### Copy anchor (one storage image to another, same size and format, 8×8 groups)\n\n| format |");
  for (uint32_t map : sizes) fmt::print(" {}² ms |", map);
  fmt::print("\n|---|{}\n", repeat("---:|", sizes.size()));
  for (const CopyFormat& f : copyFormats()) {
    fmt::print("| {} |", toString(f.format));
    for (uint32_t map : sizes) fmt::print(" {:.2f} |", anchor[map][f.format]);
    fmt::print("\n");
  }
  fmt::print(
      "\n### Prefilter passes (kind = sum of that kind's passes: SAT = rows + columns, mips and min-max = "
      "every level)\n\n");
  header("filter | pass kind | written format");
  std::sort(rows.begin(), rows.end(),
            [](const Row& a, const Row& b) { return std::tie(a.kind, a.filter) < std::tie(b.kind, b.filter); });
  for (const Row& r : rows) {
    fmt::print("| {} | {} | {}", r.filter, r.kind, toString(r.format));
    for (uint32_t map : sizes) {
      const double ms = r.ms.count(map) ? r.ms.at(map) : 0, a = anchor[map][r.format];
      fmt::print(" | {:.2f} | {:.2f}", ms, a > 0 ? ms / a : 0);
    }
    fmt::print(" |\n");
  }
  // Every pass before the shade, as one number per filter (the "moments + SAT" done-when line).
  fmt::print("\n### All prefilter passes together ÷ one RG32F copy\n\n| filter |");
  for (uint32_t map : sizes) fmt::print(" {}² ms | ÷ RG32F copy |", map);
  fmt::print("\n|---|{}\n", repeat("---:|---:|", sizes.size()));
  for (const driver::Artifact& a : filters) {
    std::map<uint32_t, double> total;
    for (const Row& r : rows)
      if (r.filter == a.spec.name && r.kind.find(" [") == std::string::npos)  // the auto choice only
        for (const auto& [map, ms] : r.ms) total[map] += ms;
    if (total.empty()) continue;
    fmt::print("| {} |", a.spec.name);
    for (uint32_t map : sizes)
      fmt::print(" {:.2f} | {:.2f} |", total[map], total[map] / anchor[map][ImageFormat::RG32F]);
    fmt::print("\n");
  }
  fmt::print(
      "\n### Shade pass per pixel ({}² pixels; fetches per pixel: worst case from the spec)\n\n| filter | fetches / "
      "pixel |",
      screen);
  for (uint32_t map : sizes) fmt::print(" {}² map µs/pixel | RMSE |", map);
  fmt::print("\n|---|---|{}\n", repeat("---:|---:|", sizes.size()));
  const double pixels = double(screen) * screen;
  for (const Shade& s : shades) {
    fmt::print("| {} | {} |", s.filter, s.fetches);
    for (uint32_t map : sizes)
      fmt::print(" {:.3f} | {:.4f} |", s.ms.count(map) ? 1000.0 * s.ms.at(map) / pixels : 0,
                 s.rmse.count(map) ? s.rmse.at(map) : 0);
    fmt::print("\n");
  }
  return 0;
} catch (const std::exception& e) {
  fmt::print(stderr, "pass_bench: {}\n", e.what());
  return 1;
}
