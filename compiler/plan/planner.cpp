#include "plan/planner.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "plan/image_formats.h"
#include "plan/quadtree_tables.h"
#include "plan/shade_plan.h"
#include "plan/template_codes.h"

namespace shadowc {
namespace {

constexpr SizeRule kMap{SizeDomain::Map, 0};
constexpr SizeRule kScreen{SizeDomain::Screen, 0};

// The prefilter passes compute in fp32: their reals are stored as the fp32 value the pass folds in.
Real fp32(double v) { return Real{static_cast<double>(static_cast<float>(v))}; }
RealList fp32(const std::vector<double>& values) {
  RealList out;
  for (double v : values) out.values.push_back(fp32(v).value);
  return out;
}

class Planner {
 public:
  explicit Planner(const FilterSpec& spec) : spec_(spec) { graph_.manifest.filter = spec.name; }

  PassGraph run() {
    addImage({"gbuffer_position", ImageFormat::RGBA32F, kScreen, 1, 1, ImageRole::InputPosition, false});
    addImage({"gbuffer_normal", ImageFormat::RGBA32F, kScreen, 1, 1, ImageRole::InputNormal, false});
    addImage({"visibility", ImageFormat::R32F, kScreen, 1, 1, ImageRole::OutputVisibility, false});
    const bool hardwareDepth = spec_.depthInput.format != DepthInputFormat::Linear;
    addImage({"shadow_depth", ImageFormat::R32F, kMap, 1, 1,
              hardwareDepth ? ImageRole::Internal : ImageRole::InputDepth, false});
    if (hardwareDepth) planDepthConvert();
    const bool moments = spec_.representation == Representation::Moments;
    if (moments) planMoments();
    if (spec_.earlyOutMinMax) planMinMax();
    planShade();
    return std::move(graph_);
  }

 private:
  void addImage(ImageDesc d) { graph_.manifest.images.push_back(std::move(d)); }

  Pass& addPass(std::string name, std::string kind, std::array<uint32_t, 3> local, Dispatch dispatch,
                PassSource source) {
    Pass p;
    p.name = std::move(name);
    p.kind = std::move(kind);
    p.glsl = source.stem + ".glsl";
    p.spirv = source.stem + ".spv";
    p.localSize = local;
    p.dispatch = dispatch;
    graph_.manifest.passes.push_back(std::move(p));
    graph_.sources.push_back(std::move(source));
    return graph_.manifest.passes.back();
  }

  // `depth_input d32|d24`: the engine's depth attachment in, the linear shadow_depth every later
  // pass samples out (passes/depth_convert.comp); the projection is the light's.
  void planDepthConvert() {
    const ImageFormat format = spec_.depthInput.format == DepthInputFormat::D32 ? ImageFormat::D32F : ImageFormat::D24;
    addImage({"hardware_depth", format, kMap, 1, 1, ImageRole::InputHardwareDepth, false});
    Specialization v;
    v.add("SHADOWC_DEPTH_REVERSED", spec_.depthInput.reversed);
    v.add("SHADOWC_DEPTH_ORTHO", spec_.light.type == LightType::Sun);
    Pass& p = addPass("depth_convert", "depth_convert", {8, 8, 1}, {kMap, DispatchMode::Texels},
                      {"passes/depth_convert.comp", "depth_convert", std::move(v)});
    p.bindings = {{0, "frame", Access::Uniform, -1},
                  {1, "hardware_depth", Access::Sampled, -1},
                  {2, "shadow_depth", Access::StorageWrite, 0}};
  }

  Specialization momentsValues() const {
    Specialization v;
    v.add("SHADOWC_WARP", warpCode(spec_.moments.warp));
    v.add("SHADOWC_EXP_POSITIVE", fp32(spec_.moments.positiveExponent));
    v.add("SHADOWC_EXP_NEGATIVE", fp32(spec_.moments.negativeExponent));
    v.add("SHADOWC_LAYERS", static_cast<long long>(spec_.moments.layers));
    v.add("SHADOWC_MOMENTS_FORMAT", momentsFormat(spec_));
    // Moment shadow maps: the sec. 4.3 quantization for 16-bit storage (image_formats.h).
    if (spec_.moments.warp == Warp::Msm) v.add("SHADOWC_MSM_QUANTIZED", msmQuantized(spec_));
    return v;
  }

  // Fused prefilter (docs/performance.md "The fused prefilters"): when only the summed-area
  // table reads the moments (no blur, no mips), the SAT row scan warps the light depth itself (sat_rows.comp
  // SHADOWC_SAT_FROM_DEPTH) and neither a moments pass nor a moments image exists: two full-map passes instead of
  // three.
  bool fusedSat() const {
    const bool blur = spec_.prefilter.blur != BlurKind::None && spec_.prefilter.blurRadius > 0;
    return spec_.storage.sat != SatKind::None && !blur && !spec_.prefilter.mips;
  }

  // moments: depth -> warped (per-layer remapped) moments; the same values fold into the fused
  // SAT row pass.
  Specialization layerMomentsValues(bool lloyd) const {
    Specialization d = momentsValues();
    d.add("SHADOWC_SPLITS", fp32(spec_.moments.splits));  // layers+1 after normalization
    d.add("SHADOWC_OVERLAP", fp32(spec_.moments.overlap));
    d.add("SHADOWC_SPLITS_FROM_IMAGE", lloyd);
    return d;
  }

  void planMoments() {
    const int layers = std::max(1, spec_.moments.layers);
    const bool mips = spec_.prefilter.mips;
    const int levels = mips ? pyramidLevels(spec_) : 1;
    const bool lloyd = layers > 1 && spec_.moments.split == SplitPlacement::Lloyd;
    if (lloyd) planLloyd(layers);
    if (fusedSat()) {
      planSat(layers, lloyd);
      return;
    }
    addImage({"moments", momentsFormat(spec_), kMap, levels, layers, ImageRole::Internal, true});

    Pass& m = addPass("moments", "moments", {8, 8, 1}, {kMap, DispatchMode::Texels},
                      {"passes/moments.comp", "moments", layerMomentsValues(lloyd)});
    m.bindings = {{0, "shadow_depth", Access::Sampled, -1}, {1, "moments", Access::StorageWrite, 0}};
    if (lloyd) m.bindings.push_back({2, "splits", Access::Sampled, -1});

    if (spec_.prefilter.blur != BlurKind::None && spec_.prefilter.blurRadius > 0) {
      addImage({"moments_tmp", momentsFormat(spec_), kMap, 1, layers, ImageRole::Internal, false});
      const int r = spec_.prefilter.blurRadius;
      for (int axis = 0; axis < 2; ++axis) {
        Specialization b = momentsValues();
        b.add("SHADOWC_BLUR_AXIS", static_cast<long long>(axis));
        b.add("SHADOWC_BLUR_RADIUS", static_cast<long long>(r));
        b.add("SHADOWC_BLUR_WEIGHTS", fp32(blurWeights(spec_.prefilter.blur, r)));
        const std::string name = axis == 0 ? "blur_h" : "blur_v";
        Pass& p =
            addPass(name, "blur", {8, 8, 1}, {kMap, DispatchMode::Texels}, {"passes/blur.comp", name, std::move(b)});
        const char* from = axis == 0 ? "moments" : "moments_tmp";
        const char* to = axis == 0 ? "moments_tmp" : "moments";
        p.bindings = {{0, from, Access::StorageRead, 0}, {1, to, Access::StorageWrite, 0}};
      }
    }

    for (int k = 1; k < levels; ++k) {
      Pass& p = addPass("mip" + std::to_string(k), "mip", {8, 8, 1}, {{SizeDomain::Map, k}, DispatchMode::Texels},
                        {"passes/mip.comp", "mip", momentsValues()});
      p.bindings = {{0, "moments", Access::StorageRead, k - 1}, {1, "moments", Access::StorageWrite, k}};
    }

    if (spec_.storage.sat != SatKind::None) planSat(layers, false);
  }

  // Lloyd split placement (lauritzen2008 sec. 4.1) runs before the moments pass, which reads
  // the splits. One workgroup: dispatch extent 1x1 (shift 16) with local size 256.
  // `splits` must be layers+1 texels wide; sizes are relative to the map, so the shift keeps
  // it wide enough for every map of at least 64 texels (the pyramid's minimum as well).
  Specialization lloydValues(int layers) const {
    Specialization v;
    v.add("SHADOWC_LAYERS", static_cast<long long>(layers));
    v.add("SHADOWC_LLOYD_ITERATIONS", static_cast<long long>(std::max(1, spec_.moments.lloydIterations)));
    return v;
  }

  void planLloyd(int layers) {
    int shift = 6;
    while (shift > 0 && (64 >> shift) < layers + 1) --shift;
    addImage({"splits", ImageFormat::R32F, {SizeDomain::Map, shift}, 1, 1, ImageRole::Internal, false});
    Pass& p = addPass("lloyd", "lloyd", {256, 1, 1}, {{SizeDomain::Map, 16}, DispatchMode::Texels},
                      {"passes/lloyd.comp", "lloyd", lloydValues(layers)});
    p.bindings = {{0, "shadow_depth", Access::Sampled, -1}, {1, "splits", Access::StorageWrite, 0}};
  }

  // The SAT as a row scan then a column scan (sat_rows.comp, sat_columns.comp). Fused: the row
  // scan reads the light depth (and the Lloyd splits) instead of the moments image.
  void planSat(int layers, bool lloyd) {
    const bool fused = fusedSat();
    addImage({"sat", satFormat(spec_), kMap, 1, layers, ImageRole::Internal, false});
    Specialization d = fused ? layerMomentsValues(lloyd) : momentsValues();
    d.add("SHADOWC_SAT_KIND", satKindCode(spec_.storage.sat));
    d.add("SHADOWC_SAT_FORMAT", satFormat(spec_));
    d.add("SHADOWC_SAT_FROM_DEPTH", fused);
    Pass& rows =
        addPass("sat_rows", "sat", {64, 1, 1}, {kMap, DispatchMode::Rows}, {"passes/sat_rows.comp", "sat_rows", d});
    if (parallelSat())
      addParallelForm(rows, DispatchMode::RowGroups, {"passes/sat_rows_parallel.comp", "sat_rows_parallel", d});
    if (fused) {
      rows.bindings = {{0, "shadow_depth", Access::Sampled, -1}, {1, "sat", Access::StorageWrite, 0}};
      if (lloyd) rows.bindings.push_back({2, "splits", Access::Sampled, -1});
    } else {
      rows.bindings = {{0, "moments", Access::StorageRead, 0}, {1, "sat", Access::StorageWrite, 0}};
    }
    Specialization c;
    c.add("SHADOWC_LAYERS", static_cast<long long>(layers));
    c.add("SHADOWC_SAT_KIND", satKindCode(spec_.storage.sat));
    c.add("SHADOWC_SAT_FORMAT", satFormat(spec_));
    Pass& cols = addPass("sat_columns", "sat", {64, 1, 1}, {kMap, DispatchMode::Columns},
                         {"passes/sat_columns.comp", "sat_columns", c});
    if (parallelSat())
      addParallelForm(cols, DispatchMode::ColumnGroups,
                      {"passes/sat_columns_parallel.comp", "sat_columns_parallel", std::move(c)});
    cols.bindings = {{0, "sat", Access::StorageReadWrite, 0}};
  }

  // An int32 SAT's scans come in two forms with bit-identical tables (sat_common.glsl "Two
  // forms"): the serial scan, one invocation per row or column, for CPU devices (the pass as
  // added), and a workgroup of SHADOWC_SAT_TILE_CHUNKS invocations per row or column for GPUs,
  // where one invocation per row is bound by latency (Nehab et al. 2011). fp32 sums depend on the
  // order, and the blocked one is less precise for small boxes: fp32 tables keep the serial form.
  bool parallelSat() const { return spec_.storage.sat == SatKind::Int32; }
  void addParallelForm(Pass& pass, DispatchMode mode, PassSource source) {
    pass.form = passFormNames()[0];  // "serial"
    pass.formNeeds.device = FormDevice::Cpu;
    PassForm f;
    f.name = passFormNames()[1];  // "parallel"
    f.needs.device = FormDevice::Gpu;
    f.spirv = source.stem + ".spv";
    f.glsl = source.stem + ".glsl";
    f.localSize = {256, 1, 1};  // read back from the shader by the emitter
    f.dispatch = {kMap, mode};
    pass.forms.push_back(std::move(f));
    graph_.sources.back().forms.push_back(std::move(source));
  }

  static Specialization minmaxValues(bool level0, bool two) {
    Specialization v;
    v.add("SHADOWC_MINMAX_LEVEL0", level0);
    v.add("SHADOWC_MINMAX_TWO", two);
    return v;
  }

  // The pyramid in about levels/2 dispatches (minmax.comp): the first reads the light depth and
  // writes levels 0, 1 and 2; each further one reads level k and writes k+1 and k+2 (only k+1
  // when it is the top).
  void planMinMax() {
    const int levels = pyramidLevels(spec_);  // >= 2
    addImage({"minmax", ImageFormat::RG32F, kMap, levels, 1, ImageRole::Internal, false});
    // `from` is the level read (level 0 is the light depth itself), `top` the last one written.
    for (int from = 0; from < levels - 1;) {
      const int top = std::min(from + 2, levels - 1);
      const bool level0 = from == 0, two = top - from == 2;
      std::string name = "minmax";
      for (int k = level0 ? 0 : from + 1; k <= top; ++k) name += std::to_string(k);
      const std::string stem = std::string("minmax") + (level0 ? "_depth" : "") + (two ? "_two" : "");
      Pass& p = addPass(name, "minmax", {8, 8, 1}, {{SizeDomain::Map, top}, DispatchMode::Texels},
                        {"passes/minmax.comp", stem, minmaxValues(level0, two)});
      if (level0)
        p.bindings = {{0, "shadow_depth", Access::Sampled, -1}, {1, "minmax", Access::StorageWrite, top}};
      else
        p.bindings = {{0, "minmax", Access::StorageRead, from}, {1, "minmax", Access::StorageWrite, top}};
      if (level0) p.bindings.push_back({2, "minmax", Access::StorageWrite, 0});
      if (two) p.bindings.push_back({3, "minmax", Access::StorageWrite, top - 1});
      from = top;
    }
  }

  void planShade() {
    Pass& s = addPass("shade", "shade", {8, 8, 1}, {kScreen, DispatchMode::Texels},
                      {"shade.comp", "shade", planShadeSpecialization(spec_)});
    s.bindings = {{0, "frame", Access::Uniform, -1},
                  {1, "gbuffer_position", Access::StorageRead, -1},
                  {2, "gbuffer_normal", Access::StorageRead, -1},
                  {3, "visibility", Access::StorageWrite, -1},
                  {4, "shadow_depth", Access::Sampled, -1}};
    auto has = [&](const char* name) {
      const auto& ims = graph_.manifest.images;
      return std::any_of(ims.begin(), ims.end(), [&](const ImageDesc& d) { return d.name == name; });
    };
    // With a SAT the lookup reads only the table (resources.glsl): the moments are not bound even
    // where a blur pass still makes them.
    if (has("moments") && !has("sat")) s.bindings.push_back({5, "moments", Access::Sampled, -1});
    if (has("sat")) s.bindings.push_back({6, "sat", Access::Sampled, -1});
    if (has("minmax")) s.bindings.push_back({7, "minmax", Access::Sampled, -1});
    if (has("splits")) s.bindings.push_back({8, "splits", Access::Sampled, -1});
    // Algorithm 2's Next/Child tables, read by the walk from a small read-only buffer.
    if (const int h = quadtreeTableHeight(spec_)) {
      graph_.manifest.buffers.push_back(quadtreeTableBuffer(buildQuadtreeTables(h)));
      s.bindings.push_back({kQuadtreeTableBinding, kQuadtreeTableBuffer, Access::StorageBufferRead, -1});
    }
  }

  const FilterSpec& spec_;
  PassGraph graph_;
};

}  // namespace

int pyramidLevels(const FilterSpec& spec) {
  const double texels = std::max(2.0, spec.kernel.maxTexels);
  const int k = static_cast<int>(std::ceil(std::log2(texels) - 1e-9));
  return std::clamp(k, 1, kMaxPyramidLevel) + 1;
}

// Separable blur weights w[0..r], w[k] = w[-k], summing to 1 over [-r, r].
// Gaussian sigma = r/2 keeps the tails at the window edge near 2 sigma.
std::vector<double> blurWeights(BlurKind kind, int r) {
  std::vector<double> w(static_cast<size_t>(r) + 1, 1.0);
  if (kind == BlurKind::Gaussian) {
    const double sigma = std::max(0.5, r / 2.0);
    for (int k = 0; k <= r; ++k) w[k] = std::exp(-(k * k) / (2.0 * sigma * sigma));
  }
  double total = w[0];
  for (int k = 1; k <= r; ++k) total += 2.0 * w[k];
  for (double& x : w) x /= total;
  return w;
}

PassGraph planPasses(const FilterSpec& spec) { return Planner(spec).run(); }

}  // namespace shadowc
