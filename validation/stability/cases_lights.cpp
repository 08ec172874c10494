// Light types: the stability suite on a sun's orthographic frame (frame_ortho.glsl) and
// a point light's cube atlas (frame_cube.glsl), with crafted maps and exactly placed receivers.
//  * sun_depth_range_*: far - near of 1e-3 and 1e4 world units in an orthographic frame, the
//    filters a sun serves (pcf, blur VSM, SAT VSM, VSSM, EVSM4), as depth_range_* for a spot.
//  * sun_penumbra_*: a flat occluder over a flat receiver plane at a known orthographic distance,
//    PCSS (grid search) and VSSM: the blocker estimate is the occluder's depth and the kernel the
//    closed form  w = k slope (z_r - z_b) / (2 halfExtent) map texels (k = sqrt(3)/2 for a box,
//    slope = 2 tan(angle / 2)); a sun of 0.01 degrees (one-texel kernels) and one of 8 degrees
//    whose search region is wider than the map.
//  * point_cube_seam*: receivers on both sides of the +x / +z face seam of the cube atlas, under
//    an occluder edge lying on the seam: agreement with the reference in the receiver's face, and
//    continuity (the jump between receivers 1e-4 apart on either side of the seam).
//  * point_cube_grazing: N.L = 0 on a cube face with a slope-scaled bias.
// Siblings (naive rows, passing when they FAIL): the reference with the spot's perspective widths
// on the sun frame; the reference reading the opposite face's cell; the atlas and frame rendered
// without a guard band (tan(half fov) = 1), where kernels at a seam read another face's cell.
#include <fmt/format.h>

#include <cmath>

#include "validation/stability/case_support.h"

namespace shadowc::validation {
namespace {

constexpr uint32_t kMap = 128;

bool endsWith(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// A library filter and its naive twin (same body, a name with `suffix`): the case's run tells
// them apart by the name.
std::vector<FilterSpec> withTwin(std::vector<FilterSpec> filters, const std::string& name, const std::string& body,
                                 const std::string& suffix) {
  filters.push_back(libraryFilter(name + suffix, body));
  return filters;
}

// ---- sun ---------------------------------------------------------------------------------------

const char* const kSunPcf = "light sun(angle: scene)\ndepth\nsampling grid(5x5)";
const char* const kSunVsmBlur = "light sun(angle: scene)\nmoments linear\nblur gaussian(radius: 4)";
const char* const kSunVsmSat = "light sun(angle: scene)\nmoments linear\nstorage sat(int32)\nkernel fixed(15)";
const char* const kSunVssm =
    "light sun(angle: scene)\nmoments linear\nstorage sat(int32)\nblocker moments\nkernel uniform(4)\nfallback "
    "pcf(2x2)";
const char* const kSunEvsm4 = "light sun(angle: scene)\nmoments evsm4(40, 5)\nblur box(radius: 2)";

// The orthographic frame of a depth range: near 0.1 (so that the perspective widths of the naive
// row, which divide by near * z_r, differ from the orthographic ones), the box as wide as deep.
LightFrame sunRangeFrame(double range) {
  return sunFrame(0.5 * range, 0.1, 0.1 + range, 10.0);  // slope 0.175: search ~0.175 d, ~11 texels
}

void addSunCases(std::vector<StabilityCase>& out) {
  for (double range : {1e-3, 1e4}) {
    const std::vector<FilterSpec> filters =
        withTwin({libraryFilter("sun_pcf_grid5", kSunPcf), libraryFilter("sun_vsm_blur", kSunVsmBlur),
                  libraryFilter("sun_vsm_sat_fixed15", kSunVsmSat), libraryFilter("sun_vssm_uniform", kSunVssm),
                  libraryFilter("sun_evsm4", kSunEvsm4)},
                 "sun_vssm_uniform", kSunVssm, "_perspective_ref");
    out.push_back(makeCase(
        fmt::format("sun_depth_range_{:g}", range),
        fmt::format("orthographic frame, near 0.1, far 0.1 + {0:g}, half extent {1:g}, sun 10 degrees", range,
                    0.5 * range),
        filters, [](const FilterSpec& s) { return s.light.type == LightType::Sun; },
        [range](SuiteContext& ctx, const FilterSpec& s) {
          CaseResult b = bounded(s);
          ReferenceForm form;
          if (endsWith(s.name, "_perspective_ref")) {
            // The sibling: the GPU's orthographic lookup against the reference with the spot's
            // widths W (z_r - near) / (2 near tan z_r), tan = lightParams.x = halfExtent.
            b.naive = true;
            form.perspectiveWidths = true;
          }
          // No widened bound for VSSM at 1e-3 (depth_range_0.001 for a spot needs 1.01e-3): its
          // receivers here stay clear of the int32 SAT's variance floor (measured 5.5e-5).
          std::vector<Receiver> rs;
          for (int i = 0; i < 32; ++i) rs.push_back(atTexel(kMap, 7 + 3 * i, 9 + 2 * i, 0.2 + 0.025 * i));
          return evaluate(ctx, b, s, noiseMap(kMap, 15, 0.1, 0.9), rs, sunRangeFrame(range), form);
        }));
  }

  // Flat occluder (depth 0.2, texels x < 64) over a flat receiver plane (0.8 elsewhere), frame
  // near 1, far 11, half extent 0.5: z_r - z_b = 6 world units, z_r - near = 8. Receivers on the
  // plane (d 0.8) every quarter texel across the occluder's edge, rows 64 and 20.
  for (double angle : {0.01, 8.0}) {
    const std::string tag = angle < 1 ? "0.01deg" : "8deg";
    const std::string pcss = fmt::format(
        "light sun(angle: {:g})\ndepth\nblocker search(taps: 25, pattern: grid)\nkernel penumbra(max: 255)\n"
        "sampling grid(7x7)",
        angle);
    const std::string vssm = fmt::format(
        "light sun(angle: {:g})\nmoments linear\nstorage sat(int32, corners: bilinear)\nblocker moments\n"
        "kernel uniform(4, max: 255)\nfallback pcf(2x2)",
        angle);
    std::vector<FilterSpec> filters = {libraryFilter("sun_pcss_grid", pcss), libraryFilter("sun_vssm", vssm)};
    if (angle > 1) {  // at 0.01 degrees every width is one texel in either form: no sibling there
      filters = withTwin(filters, "sun_pcss_grid", pcss, "_perspective_ref");
      filters = withTwin(filters, "sun_vssm", vssm, "_perspective_ref");
    }
    const double slope = sunPenumbraSlope(angle);
    // Closed form on this map (128 texels over 2 halfExtent = 1 world unit): search
    // slope * 8 / 1 * 128, penumbra box sqrt(3)/2 slope * 6 / 1 * 128 texels.
    const double searchTexels = slope * 8.0 * kMap, penumbraTexels = std::sqrt(3.0) / 2 * slope * 6.0 * kMap;
    out.push_back(makeCase(
        "sun_penumbra_" + tag,
        fmt::format("flat occluder 6 world units over a flat receiver, sun {:g} degrees: search {:.3g} texels, "
                    "penumbra box {:.3g} texels (closed form, map {})",
                    angle, searchTexels, penumbraTexels, kMap),
        filters, [](const FilterSpec& s) { return s.light.type == LightType::Sun; },
        [searchTexels, penumbraTexels](SuiteContext& ctx, const FilterSpec& s) {
          CaseResult b = bounded(s);
          ReferenceForm form;
          if (endsWith(s.name, "_perspective_ref")) {
            b.naive = true;
            form.perspectiveWidths = true;
          }
          DepthMap map = constantMap(kMap, 0.8f);
          for (uint32_t y = 0; y < kMap; ++y)
            for (uint32_t x = 0; x < 64; ++x) map.depth[size_t(y) * kMap + x] = 0.2f;
          std::vector<Receiver> rs;
          for (double row : {64.5, 20.5})
            for (int i = 0; i <= 320; ++i)
              rs.push_back({(24.0 + i / 4.0 + 0.01) / kMap, row / kMap, 0.8, std::nullopt});
          CaseResult r = evaluate(ctx, b, s, map, rs, sunFrame(0.5, 1.0, 11.0, 0.0), form);
          r.detail += fmt::format("; closed form: search {:.4g}, penumbra {:.4g} texels", searchTexels, penumbraTexels);
          return r;
        }));
  }
}

// ---- point light: the cube atlas ----------------------------------------------------------------

constexpr uint32_t kCubeMap = 300;  // 100-texel faces
constexpr double kCubeNear = 0.5, kCubeFar = 10.0;

// Occluder: the plane y = -1 where z > x > 0.3 (its edge z = x lies in the plane x = z of the +x /
// +z seam; x > 0.3 keeps it out of the -y and -z faces' cells next to that seam, so that a kernel
// reading them without a guard band reads empty texels); nothing else is in the map (1 = empty). Each atlas texel holds
// the normalized face depth of its centre's ray in its face's projection of tan(half fov) `tanHalf` (the guard band
// for 1.5).
DepthMap cubeAtlas(double tanHalf) {
  DepthMap m = constantMap(kCubeMap, 1.0f);
  const uint32_t n = kCubeMap / 3;
  for (int f = 0; f < 6; ++f)
    for (uint32_t j = 0; j < n; ++j)
      for (uint32_t i = 0; i < n; ++i) {
        const double uf = (i + 0.5) / n, vf = (j + 0.5) / n;
        const auto dir = cubeFromFace(f, {(2 * uf - 1) * tanHalf, (2 * vf - 1) * tanHalf, 1.0});
        if (!(dir[1] < 0)) continue;
        const double t = -1.0 / dir[1];  // face z of the hit: the face coordinates' z is 1
        if (!(t * dir[2] > t * dir[0] && t * dir[0] > 0.3)) continue;
        const double d = std::clamp((t - kCubeNear) / (kCubeFar - kCubeNear), 0.0, 1.0);
        m.depth[size_t((f / 3) * n + j) * kCubeMap + (f % 3) * n + i] = float(d);
      }
  return m;
}

LightFrame cubeFrame(double tanHalf) { return pointFrame(tanHalf, kCubeNear, kCubeFar, 0.3); }

// Seam pairs on the floor y = -2: P+ = (s (1 + e), -2, s (1 - e)) in face +x (lit side of the
// edge) and P- = (s (1 - e), -2, s (1 + e)) in face +z (shadowed side), e = 1e-4 (a hundredth of a
// texel); then receivers 0.3 to 8 texels from the seam on both sides.
std::vector<Receiver> seamReceivers(const LightFrame& light) {
  std::vector<Receiver> rs;
  for (double s : {3.03, 3.37, 3.81, 4.21, 4.66, 5.13})
    for (double e : {1e-4, -1e-4}) rs.push_back(cubeReceiver(light, kCubeMap, {s * (1 + e), -2.0, s * (1 - e)}));
  for (double s : {3.2, 4.4})
    for (double e : {0.002, 0.005, 0.01, 0.02, 0.04, 0.06})
      for (double sign : {1.0, -1.0})
        rs.push_back(cubeReceiver(light, kCubeMap, {s * (1 + sign * e), -2.0, s * (1 - sign * e)}));
  return rs;
}
constexpr size_t kSeamPairs = 6;

const char* const kCubePcf = "light point(radius: scene)\ndepth\nsampling grid(5x5)";
const char* const kCubePcss =
    "light point(radius: 0.3)\ndepth\nblocker search(taps: 25, pattern: grid)\nkernel penumbra\nsampling grid(7x7)";
const char* const kCubeVsm = "light point(radius: scene)\nmoments linear\nblur gaussian(radius: 3)";

std::vector<FilterSpec> cubeFilters() {
  return {libraryFilter("point_pcf_grid5", kCubePcf), libraryFilter("point_pcss_grid", kCubePcss),
          libraryFilter("point_vsm_blur", kCubeVsm)};
}

// The continuity bound of a filter across the seam. The edge lies on the seam, so the two faces
// see mirror images of one straight edge; the mirror moves the texel grid by 2 (83.33 - 83) =
// 0.67 texel. A grid PCF of n x n taps steps by one row (1/n) when the grid moves across a texel
// boundary, within a face as much as across the seam; the blurred VSM changes by at most its
// largest slope over that 0.67 texel.
// Why the PCF bound equals the measured jump (0.2 for 5 x 5): a PCF value is k / n^2 (k of n^2 taps
// lit), so a jump is a whole number of taps; one row is n taps, 1/n, which this edge reaches, and
// the next possible jump, (n + 1) / n^2, lies 1/n^2 (0.04 for n = 5) above the bound. The bound
// thus separates "one row" from "more than one row"; its 1e-6 is only the fp32 rounding of the two
// k / n^2 values (<= 2^-24 each), not a margin on a measurement.
CaseResult seamBound(const FilterSpec& s) {
  CaseResult r;
  if (isMoments(s)) {
    r.bound = 0.1;
    r.boundReason = "blurred moments (radius 3) across a 0.8 contrast edge: Chebyshev moves <= 0.15 per texel, x 0.67";
  } else {
    const int n = std::max(1, s.sampling.gridN);
    r.bound = 1.0 / n + 1e-6;
    r.boundReason = fmt::format("one row of the {0}x{0} tap grid crossing a texel boundary: 1/{0}", n);
  }
  return r;
}

void addPointCases(std::vector<StabilityCase>& out) {
  const auto point = [](const FilterSpec& s) { return s.light.type == LightType::Point; };
  out.push_back(
      makeCase("point_cube_seam",
               "cube atlas (100-texel faces, tan(half fov) 1.5): receivers 1e-4 to 0.06 x s from the +x / +z seam, an "
               "occluder edge on the seam",
               withTwin(cubeFilters(), "point_pcf_grid5", kCubePcf, "_mirrored_face_ref"), point,
               [](SuiteContext& ctx, const FilterSpec& s) {
                 CaseResult b = bounded(s);
                 ReferenceForm form;
                 if (endsWith(s.name, "_mirrored_face_ref")) {
                   b.naive = true;  // the reference reading the opposite face's cell (+x -> -x, +z -> -z)
                   form.mirroredCubeFace = true;
                 }
                 const LightFrame light = cubeFrame(1.5);
                 return evaluate(ctx, b, s, cubeAtlas(1.5), seamReceivers(light), light, form);
               }));

  out.push_back(makeCase(
      "point_cube_seam_continuity",
      "the jump between receivers 2e-4 x s apart on either side of the +x / +z seam (face +x vs face +z)",
      withTwin(withTwin(cubeFilters(), "point_pcf_grid5", kCubePcf, "_no_guard_band"), "point_pcss_grid", kCubePcss,
               "_no_guard_band"),
      point, [](SuiteContext& ctx, const FilterSpec& s) {
        CaseResult r = seamBound(s);
        r.filter = s.name;
        // The sibling: faces rendered and looked up with tan(half fov) = 1 (no guard band): a
        // kernel at the seam reads the next cell of the atlas, another face.
        r.naive = endsWith(s.name, "_no_guard_band");
        const double tanHalf = r.naive ? 1.0 : 1.5;
        const LightFrame light = cubeFrame(tanHalf);
        const std::vector<Receiver> rs = seamReceivers(light);
        const CraftedResult run = runCrafted(ctx.vk, compileCached(s), cubeAtlas(tanHalf), rs, light);
        countValues(r, run.visibility);
        r.worstError = 0;
        for (size_t k = 0; k < kSeamPairs; ++k) {
          const double a = run.visibility[2 * k], c = run.visibility[2 * k + 1];
          const double jump = std::isfinite(a) && std::isfinite(c) ? std::fabs(a - c) : INFINITY;
          if (!(jump <= r.worstError)) {
            r.worstError = jump;
            r.detail = fmt::format("worst pair s = {:.2f}: face {} {:.6g} vs face {} {:.6g}", rs[2 * k].position->at(0),
                                   cubeFace(*rs[2 * k].position), a, cubeFace(*rs[2 * k + 1].position), c);
          }
        }
        settle(r);
        return r;
      }));

  // Grazing light on a cube face: receivers below the light (face -y) with normals perpendicular to
  // the direction to the light's centre (N.L = 0, and 1e-7 on odd receivers), a slope-scaled bias.
  const char* const kPcfSlope =
      "light point(radius: scene)\ndepth\nsampling grid(3x3)\nbias slope(0.005, constant: 0.001)";
  const std::vector<FilterSpec> grazing =
      withTwin({libraryFilter("point_pcf_slope_bias", kPcfSlope),
                libraryFilter("point_vsm_slope_bias",
                              "light point(radius: scene)\nmoments linear\nblur box(radius: 1)\n"
                              "bias slope(0.005, constant: 0.001)")},
               "point_pcf_slope_bias", kPcfSlope, "_mirrored_face_ref");
  out.push_back(makeCase(
      "point_cube_grazing", "face -y under the occluder's edge, normals perpendicular to the light (N.L = 0, 1e-7)",
      grazing, point, [](SuiteContext& ctx, const FilterSpec& s) {
        CaseResult b = bounded(s);
        ReferenceForm form;
        if (endsWith(s.name, "_mirrored_face_ref")) {
          b.naive = true;
          form.mirroredCubeFace = true;
        }
        const LightFrame light = cubeFrame(1.5);
        std::vector<Receiver> rs;
        for (int i = 0; i < 32; ++i) {
          const double x = 0.7 + 0.03 * i, z = 1.5 - 0.03 * i;  // across the edge z = x near i = 13
          Receiver r = cubeReceiver(light, kCubeMap, {x, -2.0 - 0.05 * (i % 5), z});
          const auto& p = *r.position;
          // A unit vector perpendicular to p (N.L = 0), tilted towards the light by 1e-7 on odd i.
          std::array<double, 3> n = {p[1], -p[0], 0.0};
          const double len = std::sqrt(n[0] * n[0] + n[1] * n[1]);
          const double pl = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
          const double tilt = (i & 1) ? 1e-7 : 0.0;
          r.normal =
              std::array<double, 3>{n[0] / len - tilt * p[0] / pl, n[1] / len - tilt * p[1] / pl, -tilt * p[2] / pl};
          rs.push_back(r);
        }
        return evaluate(ctx, b, s, cubeAtlas(1.5), rs, light, form);
      }));
}

}  // namespace

void addLightCases(std::vector<StabilityCase>& out) {
  addSunCases(out);
  addPointCases(out);
}

}  // namespace shadowc::validation
