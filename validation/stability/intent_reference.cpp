#include "validation/stability/intent_reference.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>

#include "plan/planner.h"
#include "runtime/reference/cpu_filters.h"
#include "spec/precision.h"

namespace shadowc::validation {
namespace {

double clamp01(double v) { return std::clamp(v, 0.0, 1.0); }
double unit(double v) { return v >= 0.0 ? std::min(v, 1.0) : 0.0; }

// Chebyshev upper bound (chebyshev.glsl) and Lauritzen's linstep.
double chebyshev(double mean, double meanSq, double t, double minVariance) {
  if (t <= mean) return 1.0;
  const double variance = std::max(meanSq - mean * mean, minVariance);
  const double dt = t - mean;
  const double denom = variance + dt * dt;
  return denom > 0 ? unit(variance / denom) : 0.0;
}
// The minimum variance of linear moments: the spec's, raised for an int32 SAT to the variance
// noise of its 16.16 box means (templates/lookup/sat.glsl, shadowc_satVarianceFloor).
double satVarianceFloor(const FilterSpec& s) {
  const bool int32Sat =
      s.representation == Representation::Moments && s.storage.sat == SatKind::Int32 && s.moments.warp == Warp::Linear;
  return int32Sat ? 2.4e-5 : 0.0;
}
double minVarianceOf(const FilterSpec& s) { return std::max(s.moments.minVariance, satVarianceFloor(s)); }

double reduceBleeding(const FilterSpec& s, double p) {
  const double a = std::clamp(s.moments.bleedingReduction, 0.0, 0.999);
  return a > 0 ? clamp01((p - a) / (1 - a)) : p;
}

// power-cdf eq. 3-4 with the exact beta (no clamp): the intent.
double powerCdf(double zmin, double zmax, double mean, double d) {
  if (zmin > zmax) std::swap(zmin, zmax);
  mean = std::clamp(mean, zmin, zmax);
  if (d <= mean) return 1.0;
  if (d >= zmax) return 0.0;  // beyond every occluder (also zmax == zmin)
  const double dz = zmax - zmin;
  const double t = (d - zmin) / dz;
  if (zmax - mean <= 0) return 0.0;  // every texel at zmax < d handled above; mean == zmax < d
  const double beta = (mean - zmin) / (zmax - mean);
  if (beta == 0) return 0.0;  // all mass at zmin < d: fully shadowed
  const double tMean = beta / (beta + 1);
  const double denom = 1 - std::pow(tMean, beta);
  return unit((1 - std::pow(t, beta)) / denom);
}

// A kernel as a box in texel units (x0, y0, x1, y1), texel i covering [i, i+1) (kernel.glsl).
using Box = std::array<double, 4>;

struct Geometry {
  double t;       // biased receiver depth (fp32-emulated receiver depth minus bias)
  double cx, cy;  // continuous texel coordinates
  double zr;      // view z of the receiver (a point light: its face's z)
  double lightWidth;
};

// shade_plan.cpp's SHADOWC_SUN_BOX_SCALE: the box standing for the sun's disk (same second
// moment, side D sqrt(3) / 2); Poisson taps of the depth representation keep the diameter.
double sunBoxScale(const FilterSpec& s) {
  const bool diskTaps = s.representation == Representation::Depth && s.sampling.pattern == PcfPattern::Poisson;
  return diskTaps ? 1.0 : std::sqrt(3.0) / 2.0;
}
// shade_plan.cpp's SHADOWC_CUBE_KERNEL_MAX (face uv): what the guard band holds.
double cubeKernelMax(const FilterSpec& s) { return s.prefilter.mips ? 1.0 / 18.0 : 0.25; }

class Evaluator {
 public:
  Evaluator(const FilterSpec& s, const DepthMap& map, const LightFrame& light, double widthScale,
            const MomentsField* field, bool perspectiveWidths)
      : s_(s),
        map_(map),
        light_(light),
        scale_(widthScale),
        field_(field),
        form_(perspectiveWidths ? Projection::Spot : light.projection) {}

  // lightParams.x: tan(half fov), or a sun's halfExtent (what a spot-compiled lookup reads as tan).
  double paramX() const { return light_.projection == Projection::Sun ? light_.halfExtent : light_.tanHalfFov; }
  // frame_cube.glsl shadowc_cubeWidthUV: face uv -> atlas uv, clamped to the guard band.
  double cubeWidth(double faceUV) const {
    return std::min(faceUV, cubeKernelMax(s_)) * double(map_.size / 3) / double(map_.size);
  }
  // Width in uv of the blocker search (frame.glsl / frame_ortho.glsl / frame_cube.glsl).
  double searchUV(const Geometry& g) const {
    const double n = light_.nearZ;
    if (form_ == Projection::Sun) return g.lightWidth * std::max(g.zr - n, 0.0) / (2 * light_.halfExtent);
    const double perspective = g.lightWidth / (2 * n * paramX()) * (g.zr - n) / g.zr;
    return form_ == Projection::Point ? cubeWidth(perspective) : perspective;
  }
  double penumbraUV(const Geometry& g, double zb) const {
    const double n = light_.nearZ;
    if (form_ == Projection::Sun)
      return sunBoxScale(s_) * g.lightWidth * std::max(g.zr - zb, 0.0) / (2 * light_.halfExtent);
    const double perspective = g.lightWidth / (2 * n * paramX()) * n * (g.zr - zb) / (zb * g.zr);
    return form_ == Projection::Point ? cubeWidth(perspective) : perspective;
  }
  double searchTexels(const Geometry& g) const { return clampTexels(searchUV(g) * map_.size * scale_); }
  double penumbraTexels(const Geometry& g, double zBlocker) const {
    const double zb = std::max(light_.nearZ + clamp01(zBlocker) * (light_.farZ - light_.nearZ), light_.nearZ);
    return clampTexels(penumbraUV(g, zb) * map_.size * scale_);
  }
  // shade_plan.cpp's SHADOWC_KERNEL_MAX_TEXELS (int32 SATs sum wide boxes in pieces, sat.glsl).
  double maxTexels() const { return std::clamp(s_.kernel.maxTexels, 1.0, spec::kMaxKernelTexels); }
  double clampTexels(double w) const { return w >= 1.0 ? std::min(w, maxTexels()) : 1.0; }
  std::array<int, 4> kernelRect(double cx, double cy, double w) const {
    const int n = int(clampTexels(w) + 0.5);
    const int last = int(map_.size) - 1;
    const int lx = int(std::floor(cx - 0.5 * n + 0.5)), ly = int(std::floor(cy - 0.5 * n + 0.5));
    return {std::clamp(lx, 0, last), std::clamp(ly, 0, last), std::clamp(lx + n - 1, 0, last),
            std::clamp(ly + n - 1, 0, last)};
  }

  // kernel.glsl shadowc_kernelBox: the rectangle's texels, or the continuous box with fractional
  // SAT corners (sat.glsl).
  Box kernelBox(double cx, double cy, double w) const {
    if (!s_.storage.fractionalCorners || s_.storage.sat == SatKind::None) {
      const auto r = kernelRect(cx, cy, w);
      return {double(r[0]), double(r[1]), double(r[2] + 1), double(r[3] + 1)};
    }
    const double h = 0.5 * clampTexels(w), size = map_.size;
    const double lx = std::clamp(cx - h, 0.0, size - 1), ly = std::clamp(cy - h, 0.0, size - 1);
    return {lx, ly, std::clamp(cx + h, lx + 1, size), std::clamp(cy + h, ly + 1, size)};
  }
  std::vector<double> boxMoments(const Box& b, int layer) const {
    if (s_.storage.fractionalCorners) return field_->boxMeanFrac(b[0], b[1], b[2], b[3], layer);
    return field_->boxMean(int(b[0]), int(b[1]), int(b[2]) - 1, int(b[3]) - 1, layer);
  }

  double pcfGrid(double cx, double cy, double w, double t, int n) const {
    double lit = 0;
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const double px = cx + (i + 0.5 - 0.5 * n) * (w / n), py = cy + (j + 0.5 - 0.5 * n) * (w / n);
        lit += map_.at(int(std::floor(px)), int(std::floor(py))) < t ? 0.0 : 1.0;
      }
    return lit / (n * n);
  }

  // ---- moments ---------------------------------------------------------------------------
  void ensureField() const {}
  std::vector<double> bilinear(double u, double v, int layer) const {
    const double x = u * map_.size - 0.5, y = v * map_.size - 0.5;
    const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
    const double fx = x - x0, fy = y - y0;
    std::vector<double> out(4, 0.0);
    const double w[4] = {(1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy};
    const int dx[4] = {0, 1, 0, 1}, dy[4] = {0, 0, 1, 1};
    for (int k = 0; k < 4; ++k) {
      const auto m = field_->texel(x0 + dx[k], y0 + dy[k], layer);
      for (int c = 0; c < 4; ++c) out[c] += w[k] * m[c];
    }
    return out;
  }
  std::vector<double> kernelMoments(const Geometry& g, const Box& box, int layer) const {
    ensureField();
    if (s_.storage.sat != SatKind::None) return boxMoments(box, layer);
    return bilinear(g.cx / map_.size, g.cy / map_.size, layer);
  }
  double estimate(const std::vector<double>& m, double d, double minVariance) const {
    switch (s_.moments.warp) {
      case Warp::Linear:
        return reduceBleeding(s_, chebyshev(m[0], m[1], d, std::max(minVariance, satVarianceFloor(s_))));
      case Warp::Exp: {
        const double c = s_.moments.positiveExponent;
        return unit(m[0] * std::exp(-c * (d - 1)));
      }
      case Warp::Evsm2:
      case Warp::Evsm4: {
        const double dc = clamp01(d);
        const double cp = s_.moments.positiveExponent, cn = s_.moments.negativeExponent;
        const double ep = std::exp(cp * (dc - 1)), sp = cp * ep;
        double v = reduceBleeding(s_, chebyshev(m[0], m[1], ep, minVariance * sp * sp));
        if (s_.moments.warp == Warp::Evsm4) {
          const double en = std::exp(-cn * (dc - 1)), sn = cn * en;
          v = std::min(v, reduceBleeding(s_, chebyshev(m[2], m[3], -en, minVariance * sn * sn)));
        }
        return v;
      }
      case Warp::PowerCdf:
        return powerCdf(m[0], m[1], m[2], d);
      case Warp::Msm:  // Hamburger 4MSM on the exact (unquantized) moments, in double
        return rt::cpu::msmVisibility({m[0], m[1], m[2], m[3]}, d, s_.moments.momentBias, s_.moments.bleedingReduction);
    }
    return 0;
  }
  double split(int i) const { return s_.moments.splits[i]; }
  std::array<double, 2> layerRange(int i) const {
    if (s_.moments.layers == 1) return {0.0, 1.0};
    return {split(i) - s_.moments.overlap, split(i + 1) + s_.moments.overlap};
  }
  double layerVisibility(const Geometry& g, const Box& rect, double d, int layer) const {
    const auto r = layerRange(layer);
    const double w = std::max(r[1] - r[0], 1e-6);
    const double dl = s_.moments.layers > 1 ? clamp01((d - r[0]) / w) : d;
    const double mv = s_.moments.layers > 1 ? s_.moments.minVariance / (w * w) : s_.moments.minVariance;
    return estimate(kernelMoments(g, rect, layer), dl, mv);
  }
  double filteredVisibility(const Geometry& g, const Box& rect, double d) const {
    const int layers = s_.moments.layers;
    int j = 0;
    for (int i = 1; i < layers; ++i)
      if (d >= split(i)) j = i;
    double v = layerVisibility(g, rect, d, j);
    const double delta = s_.moments.overlap;
    if (layers > 1 && delta > 0) {
      if (j + 1 < layers && d > split(j + 1) - delta) {
        const double t = clamp01((d - (split(j + 1) - delta)) / (2 * delta));
        v = v + (layerVisibility(g, rect, d, j + 1) - v) * t;
      } else if (j > 0 && d < split(j) + delta) {
        const double t = clamp01((d - (split(j) - delta)) / (2 * delta));
        const double prev = layerVisibility(g, rect, d, j - 1);
        v = prev + (v - prev) * t;
      }
    }
    return v;
  }

  // ---- VSSM (vssm.glsl, Algorithm 2) -----------------------------------------------------
  struct Acc {
    double ex = 0, ex2 = 0, vsm = 0, lit = 0, pcf = 0, pcfOcc = 0, pcfDepth = 0;
  };
  // vssm.glsl shadowc_subBox: integer partition of whole texels, or continuous with fractional corners.
  Box subRect(const Box& root, int ix, int iy, int den) const {
    if (s_.storage.fractionalCorners) {
      const double sx = root[2] - root[0], sy = root[3] - root[1];
      return {root[0] + ix * sx / den, root[1] + iy * sy / den, root[0] + (ix + 1) * sx / den,
              root[1] + (iy + 1) * sy / den};
    }
    const int x0 = int(root[0]), y0 = int(root[1]), sx = int(root[2]) - x0, sy = int(root[3]) - y0;
    return {double(x0 + (ix * sx) / den), double(y0 + (iy * sy) / den), double(x0 + ((ix + 1) * sx) / den),
            double(y0 + ((iy + 1) * sy) / den)};
  }
  static double area(const Box& r) { return (r[2] - r[0]) * (r[3] - r[1]); }
  int classify(const Box& r, double d, Acc& a) const {
    const double area = Evaluator::area(r);
    if (!(area > 0)) return 0;
    const auto m = boxMoments(r, 0);
    const double variance = m[1] - m[0] * m[0];
    if (m[0] >= d && variance < s_.kernel.litThreshold) {
      a.lit += area;
      return 0;
    }
    if (m[0] < d) {
      a.ex += m[0] * area;
      a.ex2 += m[1] * area;
      a.vsm += area;
      return 0;
    }
    return 1;
  }
  bool rootLit(const Box& r, double d, Acc& a) const {
    const double area = Evaluator::area(r);
    if (!(area > 0)) return false;
    const auto m = boxMoments(r, 0);
    if (!(m[0] >= d && m[1] - m[0] * m[0] < s_.kernel.litThreshold)) return false;
    a.lit += area;
    return true;
  }
  void resolveLeaf(const Box& r, double d, Acc& a) const {
    const double area = Evaluator::area(r);
    if (!(area > 0)) return;
    if (!s_.fallback.pcf) {
      a.lit += area;
      return;
    }
    const int n = std::max(1, s_.fallback.n);
    const double sx = r[2] - r[0], sy = r[3] - r[1];
    double occ = 0, depthSum = 0;
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const int tx = int(std::floor(r[0] + (i + 0.5) * sx / n)), ty = int(std::floor(r[1] + (j + 0.5) * sy / n));
        const double z = map_.at(tx, ty);
        if (z < d) {
          occ += 1;
          depthSum += z;
        }
      }
    const double scale = area / (n * n);
    a.pcf += area;
    a.pcfOcc += occ * scale;
    a.pcfDepth += depthSum * scale;
  }
  void walk(const Box& root, Subdivision sub, int param, bool nonPlanarOnly, double d, Acc& a) const {
    if (sub == Subdivision::Quadtree) {
      const std::function<void(int, int, int)> visit = [&](int ix, int iy, int den) {
        const auto r = subRect(root, ix, iy, den);
        if (classify(r, d, a) != 1) return;
        if (den < (1 << param)) {
          for (int j = 0; j < 2; ++j)
            for (int i = 0; i < 2; ++i) visit(2 * ix + i, 2 * iy + j, 2 * den);
        } else {
          resolveLeaf(r, d, a);
        }
      };
      visit(0, 0, 1);
      return;
    }
    const int den = sub == Subdivision::Uniform ? param : 1;
    // vssm.glsl shadowc_uniformWalk: Algorithm 1 subdivides only a non-planar root; `always`
    // still accepts a fully lit root first (Algorithm 2 L9-L11, shadowc_rootLit).
    if (sub == Subdivision::Uniform && den > 1) {
      const auto r = subRect(root, 0, 0, 1);
      if (nonPlanarOnly ? classify(r, d, a) != 1 : rootLit(r, d, a)) return;
    }
    for (int j = 0; j < den; ++j)
      for (int i = 0; i < den; ++i) {
        const auto r = subRect(root, i, j, den);
        if (classify(r, d, a) == 1) resolveLeaf(r, d, a);
      }
  }
  double vssmBlocker(const Box& rect, double d) const {
    Acc a;
    walk(rect, s_.blocker.subdivision,
         s_.blocker.subdivision == Subdivision::Quadtree ? s_.blocker.quadtreeHeight : s_.blocker.uniformM,
         s_.blocker.uniformNonPlanarOnly, d, a);
    double a1 = 0, z1 = 0;
    if (a.vsm > 0) {
      const double mean = a.ex / a.vsm, meanSq = a.ex2 / a.vsm;
      const double p = chebyshev(mean, meanSq, d, minVarianceOf(s_));
      if (1 - p > 1e-4) {
        z1 = std::clamp((mean - p * d) / (1 - p), 0.0, d);
        a1 = (1 - p) * a.vsm;
      }
    }
    const double total = a1 + a.pcfOcc;
    if (!(total > 1e-6)) return -1;
    return std::clamp((z1 * a1 + a.pcfDepth) / total, 0.0, d);
  }
  double vssmVisibility(const Box& rect, double d) const {
    Acc a;
    walk(rect, s_.kernel.subdivision,
         s_.kernel.subdivision == Subdivision::Quadtree ? s_.kernel.quadtreeHeight : s_.kernel.uniformN,
         s_.kernel.uniformNonPlanarOnly, d, a);
    double l = 1;
    if (a.vsm > 0) l = reduceBleeding(s_, chebyshev(a.ex / a.vsm, a.ex2 / a.vsm, d, minVarianceOf(s_)));
    const double l1 = a.pcf > 0 ? 1 - a.pcfOcc / a.pcf : 1;
    const double total = a.vsm + a.lit + a.pcf;
    if (!(total > 0)) return 1;
    return unit((l * a.vsm + a.lit + l1 * a.pcf) / total);
  }

  // Exact over every texel that can change the result: the kernel, one texel for bilinear taps
  // and the blur's radius (a blurred moment holds texels that far away).
  double earlyOut(const std::array<int, 4>& rect, double d) const {  // -1 = undecided
    const int last = int(map_.size) - 1;
    const bool blurred = s_.representation == Representation::Moments && s_.prefilter.blur != BlurKind::None;
    const int g = 1 + (blurred ? std::max(0, s_.prefilter.blurRadius) : 0);
    double lo = INFINITY, hi = -INFINITY;
    for (int y = std::max(rect[1] - g, 0); y <= std::min(rect[3] + g, last); ++y)
      for (int x = std::max(rect[0] - g, 0); x <= std::min(rect[2] + g, last); ++x) {
        lo = std::min(lo, double(map_.at(x, y)));
        hi = std::max(hi, double(map_.at(x, y)));
      }
    if (lo >= d) return 1;
    if (hi < d) return 0;
    return -1;
  }

  double visibility(const Geometry& g) const {
    const bool penumbra = s_.kernel.size == KernelSize::Penumbra;
    const int tech = s_.representation == Representation::Depth ? (s_.blocker.kind == BlockerKind::Search ? 1 : 0)
                                                                : (s_.blocker.kind == BlockerKind::Moments ? 3 : 2);
    if (s_.earlyOutMinMax) {
      const double w = (tech == 1 || tech == 3 || penumbra) ? searchTexels(g) : s_.kernel.fixedTexels;
      const double e = earlyOut(kernelRect(g.cx, g.cy, w), g.t);
      if (e >= 0) return e;
    }
    if (tech == 3) {
      ensureField();
      const double zb = vssmBlocker(kernelBox(g.cx, g.cy, searchTexels(g)), g.t);
      if (zb < 0) return 1;
      const double w = penumbra ? penumbraTexels(g, zb) : s_.kernel.fixedTexels;
      return vssmVisibility(kernelBox(g.cx, g.cy, w), g.t);
    }
    if (tech == 2) {
      const double w = penumbra ? searchTexels(g) : s_.kernel.fixedTexels;
      return unit(filteredVisibility(g, kernelBox(g.cx, g.cy, w), g.t));
    }
    if (tech == 1) {  // pcss.glsl: grid blocker search, the penumbra estimate, grid PCF
      const double ws = searchTexels(g);
      const int n = std::max(1, int(std::lround(std::sqrt(double(std::max(1, s_.blocker.taps))))));
      double sum = 0, count = 0;
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          const double px = g.cx + (i + 0.5 - 0.5 * n) * (ws / n), py = g.cy + (j + 0.5 - 0.5 * n) * (ws / n);
          const double z = map_.at(int(std::floor(px)), int(std::floor(py)));
          if (z < g.t) {
            sum += z;
            count += 1;
          }
        }
      if (!(count > 0)) return 1;
      return pcfGrid(g.cx, g.cy, penumbraTexels(g, sum / count), g.t, std::max(1, s_.sampling.gridN));
    }
    // Depth representation, grid pattern, fixed kernel or the whole search region.
    const double w = penumbra ? searchTexels(g) : s_.kernel.fixedTexels;
    return pcfGrid(g.cx, g.cy, w, g.t, std::max(1, s_.sampling.gridN));
  }

 private:
  const FilterSpec& s_;
  const DepthMap& map_;
  LightFrame light_;
  double scale_;
  const MomentsField* field_;
  Projection form_;  // the width formulas' projection
};

}  // namespace

std::vector<double> warpMoments(const FilterSpec& s, double d) {
  const double cp = s.moments.positiveExponent, cn = s.moments.negativeExponent;
  switch (s.moments.warp) {
    case Warp::Linear:
      return {d, d * d, 0, 0};
    case Warp::Exp:
      return {std::exp(cp * (d - 1)), 0, 0, 0};
    case Warp::Evsm2: {
      const double e = std::exp(cp * (d - 1));
      return {e, e * e, 0, 0};
    }
    case Warp::Evsm4: {
      const double ep = std::exp(cp * (d - 1)), en = std::exp(-cn * (d - 1));
      return {ep, ep * ep, -en, en * en};
    }
    case Warp::PowerCdf:
      return {d, d, d, 0};
    case Warp::Msm: {
      const auto b = rt::cpu::msmPowerMoments(d);
      return {b[0], b[1], b[2], b[3]};
    }
  }
  return {0, 0, 0, 0};
}

MomentsField::MomentsField(const FilterSpec& s, const DepthMap& map) : size(map.size), layers(s.moments.layers) {
  const size_t n = size_t(size) * size;
  raw_.assign(n * layers * 4, 0.0);
  const std::vector<double>& splits = s.moments.splits;
  for (int l = 0; l < layers; ++l)
    for (size_t i = 0; i < n; ++i) {
      double d = map.depth[i];
      if (layers > 1) {
        const double p = splits[l] - s.moments.overlap, q = splits[l + 1] + s.moments.overlap;
        d = clamp01((d - p) / std::max(q - p, 1e-6));
      }
      const auto m = warpMoments(s, d);
      for (int c = 0; c < 4; ++c) raw_[(l * n + i) * 4 + c] = m[c];
    }
  blurred_ = raw_;
  if (s.prefilter.blur != BlurKind::None && s.prefilter.blurRadius > 0) {
    const int r = s.prefilter.blurRadius;
    const auto w = blurWeights(s.prefilter.blur, r);
    const bool pcdf = s.moments.warp == Warp::PowerCdf;
    const int last = int(size) - 1;
    for (int axis = 0; axis < 2; ++axis) {
      std::vector<double> out(blurred_.size());
      for (int l = 0; l < layers; ++l)
        for (int y = 0; y <= last; ++y)
          for (int x = 0; x <= last; ++x) {
            auto at = [&](int k, int c) {
              const int xx = axis == 0 ? std::clamp(x + k, 0, last) : x,
                        yy = axis == 1 ? std::clamp(y + k, 0, last) : y;
              return blurred_[((l * n) + size_t(yy) * size + xx) * 4 + c];
            };
            for (int c = 0; c < 4; ++c) {
              double sum = w[0] * at(0, c), lo = at(0, c), hi = at(0, c);
              for (int k = 1; k <= r; ++k) {
                sum += w[k] * (at(-k, c) + at(k, c));
                lo = std::min({lo, at(-k, c), at(k, c)});
                hi = std::max({hi, at(-k, c), at(k, c)});
              }
              if (pcdf && c == 0) sum = lo;
              if (pcdf && c == 1) sum = hi;
              out[((l * n) + size_t(y) * size + x) * 4 + c] = sum;
            }
          }
      blurred_ = std::move(out);
    }
  }
  const size_t s1 = size + 1;
  prefix_.assign(s1 * s1 * layers * 4, 0.0);
  for (int l = 0; l < layers; ++l)
    for (uint32_t y = 0; y < size; ++y)
      for (uint32_t x = 0; x < size; ++x)
        for (int c = 0; c < 4; ++c) {
          auto P = [&](size_t xx, size_t yy) -> double& { return prefix_[((l * s1 * s1) + yy * s1 + xx) * 4 + c]; };
          P(x + 1, y + 1) = raw_[((l * n) + size_t(y) * size + x) * 4 + c] + P(x, y + 1) + P(x + 1, y) - P(x, y);
        }
}

std::vector<double> MomentsField::boxMean(int x0, int y0, int x1, int y1, int layer) const {
  const size_t s1 = size + 1;
  std::vector<double> out(4, 0.0);
  const double area = double(x1 - x0 + 1) * (y1 - y0 + 1);
  if (area <= 0) return out;
  for (int c = 0; c < 4; ++c) {
    auto P = [&](int xx, int yy) { return prefix_[((layer * s1 * s1) + size_t(yy) * s1 + size_t(xx)) * 4 + c]; };
    out[c] = (P(x1 + 1, y1 + 1) - P(x0, y1 + 1) - P(x1 + 1, y0) + P(x0, y0)) / area;
  }
  return out;
}

// The integral up to a continuous point is bilinear between the integer prefix sums (the texels
// are constant), so the box integral is the 4-corner difference of interpolated prefix sums.
std::vector<double> MomentsField::boxMeanFrac(double x0, double y0, double x1, double y1, int layer) const {
  const size_t s1 = size + 1;
  std::vector<double> out(4, 0.0);
  const double area = (x1 - x0) * (y1 - y0);
  if (!(area > 0)) return out;
  for (int c = 0; c < 4; ++c) {
    auto P = [&](int xx, int yy) { return prefix_[((layer * s1 * s1) + size_t(yy) * s1 + size_t(xx)) * 4 + c]; };
    auto I = [&](double x, double y) {
      const int ix = std::clamp(int(std::floor(x)), 0, int(size) - 1),
                iy = std::clamp(int(std::floor(y)), 0, int(size) - 1);
      const double fx = x - ix, fy = y - iy;
      return (1 - fx) * (1 - fy) * P(ix, iy) + fx * (1 - fy) * P(ix + 1, iy) + (1 - fx) * fy * P(ix, iy + 1) +
             fx * fy * P(ix + 1, iy + 1);
    };
    out[c] = (I(x1, y1) - I(x0, y1) - I(x1, y0) + I(x0, y0)) / area;
  }
  return out;
}

std::vector<double> MomentsField::texel(int x, int y, int layer) const {
  const int last = int(size) - 1;
  x = std::clamp(x, 0, last);
  y = std::clamp(y, 0, last);
  const size_t i = (size_t(layer) * size * size + size_t(y) * size + x) * 4;
  return {blurred_[i], blurred_[i + 1], blurred_[i + 2], blurred_[i + 3]};
}

bool intentModels(const FilterSpec& s) {
  if (s.contact.enabled || s.bias.kind == BiasKind::ReceiverPlane) return false;
  if (s.representation == Representation::Depth)
    return s.sampling.pattern == PcfPattern::Grid &&
           (s.blocker.kind == BlockerKind::None ||
            (s.blocker.kind == BlockerKind::Search && s.blocker.pattern == SamplePattern::Grid));
  if (s.prefilter.mips && s.storage.sat == SatKind::None) return false;
  if (s.moments.layers > 1 && s.moments.split == SplitPlacement::Lloyd) return false;
  if (s.blocker.kind == BlockerKind::Search) return false;
  return true;
}

// The light width the shader reads (kernel.glsl shadowc_lightWidth): the frame's lightParams.w, or
// the folded SHADOWC_LIGHT_WIDTH (shade_plan.cpp: a sun's penumbra slope, a sphere's diameter, 0
// for a point-shaped spot light, else the size).
static double shaderLightWidth(const FilterSpec& s, const LightFrame& light) {
  if (s.light.sizeFromScene) return light.lightWidth;
  if (light.projection == Projection::Sun) return sunPenumbraSlope(s.light.angleDegrees);
  if (light.projection == Projection::Point || s.light.type == LightType::Point) return 2 * s.light.size;
  return s.light.shape == LightShape::Point ? 0.0 : s.light.size;
}

// shadowc_lookup.glsl shadowc_lightBehind, in double, for a light w wide (h = w / 2): spot, the
// rectangle in the light view's z = 0 plane; sun, the cap of half-angle atan(h) around -z; point,
// the sphere of radius h at the origin.
static bool lightBehind(const LightFrame& light, double w, const std::array<double, 3>& p,
                        const std::array<double, 3>& n) {
  const bool sun = light.projection == Projection::Sun, cube = light.projection == Projection::Point;
  const double h = 0.5 * w;
  const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  const double toLight = -(n[0] * p[0] + n[1] * p[1] + n[2] * p[2]);
  if (sun) return len > 0 && n[2] >= len * h / std::sqrt(1 + h * h);
  if (cube) return toLight + h * len <= 0;
  return toLight + h * (std::fabs(n[0]) + std::fabs(n[1])) <= 0;
}

// bias.glsl shadowc_biasedLightPosition: the receiver moved along its normal by SHADOWC_NORMAL_OFFSET
// texels, a texel being 2 z tanHalfFov / mapSize world units at the receiver's depth z (spot),
// 2 halfExtent / mapSize (sun), 2 z_f tanHalfFov / (mapSize / 3) in its cube face (point). Its uv
// and depth are those of the moved point (frame.glsl, frame_ortho.glsl, frame_cube.glsl); nullopt
// when the moved point lies behind a spot or sun light (the shader calls it lit).
static std::optional<Receiver> normalOffsetReceiver(const FilterSpec& s, const LightFrame& light, uint32_t mapSize,
                                                    const Receiver& r) {
  const auto p = receiverPosition(light, r);
  const auto n = receiverNormal(light, r);
  double texelWorld = 2 * light.halfExtent / mapSize;
  if (light.projection == Projection::Spot) texelWorld = 2 * std::max(p[2], 0.0) * light.tanHalfFov / mapSize;
  if (light.projection == Projection::Point)
    texelWorld = 2 * cubeFaceCoords(cubeFace(p), p)[2] * light.tanHalfFov / double(mapSize / 3);
  const double k = s.bias.normalOffset * texelWorld;
  const std::array<double, 3> q = {p[0] + k * n[0], p[1] + k * n[1], p[2] + k * n[2]};
  if (light.projection == Projection::Point) {
    Receiver moved = cubeReceiver(light, mapSize, q);
    moved.normal = n;
    return moved;
  }
  if (!(q[2] > 0)) return std::nullopt;
  const double scale = light.projection == Projection::Spot ? q[2] * light.tanHalfFov : light.halfExtent;
  Receiver moved{0.5 + 0.5 * q[0] / scale, 0.5 + 0.5 * q[1] / scale, (q[2] - light.nearZ) / (light.farZ - light.nearZ),
                 n, q};
  return moved;
}

IntentReference::IntentReference(const FilterSpec& spec, const DepthMap& map, const LightFrame& light,
                                 ReferenceForm form)
    : spec_(spec), map_(map), light_(light), form_(form) {
  if (intentModels(spec) && spec.representation == Representation::Moments)
    field_ = std::make_unique<MomentsField>(spec, map);
}
IntentReference::~IntentReference() = default;

std::vector<double> IntentReference::operator()(const Receiver& given) const {
  const FilterSpec& s = spec_;
  const DepthMap& map = map_;
  const LightFrame& light = light_;
  if (!intentModels(s)) return {};
  const bool sun = light.projection == Projection::Sun, cube = light.projection == Projection::Point;
  // shadowc_lookup.glsl shadowc_lightBehind: no part of the light in front of the receiver's
  // tangent plane -> the shadowing term's 0, before anything else (even outside the frustum).
  const double lightWidth = shaderLightWidth(s, light);
  if (s.backfaceShadowed && given.normal &&
      lightBehind(light, lightWidth, receiverPosition(light, given), *given.normal))
    return {0.0};
  Receiver r = given;
  if (s.bias.kind == BiasKind::NormalOffset) {
    const std::optional<Receiver> moved = normalOffsetReceiver(s, light, map.size, given);
    if (!moved) return {1.0};
    r = *moved;
  }
  const auto p = receiverPosition(light, r);
  // Outside the shadow map's frustum nothing was rendered that could shadow it (lit).
  if (!(r.u >= 0 && r.u <= 1 && r.v >= 0 && r.v <= 1)) return {1.0};
  Geometry g;
  double u = r.u, v = r.v;
  if (cube && form_.mirroredCubeFace) {  // the same face-local uv in the opposite face's cell
    const int f = cubeFace(p), m = f ^ 1;
    const double cell = double(map.size / 3) / double(map.size);
    u += (m % 3 - f % 3) * cell;
    v += (m / 3 - f / 3) * cell;
  }
  g.cx = u * map.size;
  g.cy = v * map.size;
  g.zr = std::max(cube ? cubeFaceCoords(cubeFace(p), p)[2] : p[2], light.nearZ);
  g.lightWidth = lightWidth;
  double bias = s.bias.constant;
  if (s.bias.kind == BiasKind::SlopeScaled) {
    // L: towards the light's centre (spot, point; bias.glsl), or -z for a sun (its ortho form).
    std::array<double, 3> l = {-p[0], -p[1], -p[2]};
    if (sun) l = {0.0, 0.0, -1.0};
    const double llen = std::sqrt(l[0] * l[0] + l[1] * l[1] + l[2] * l[2]);
    std::array<double, 3> n = r.normal ? *r.normal : std::array<double, 3>{l[0] / llen, l[1] / llen, l[2] / llen};
    const double nl = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) * llen;
    const double ndotl = nl > 0 ? clamp01((n[0] * l[0] + n[1] * l[1] + n[2] * l[2]) / nl) : 0.0;
    bias = std::max(s.bias.slope * (1 - ndotl), s.bias.constant);
  }
  g.t = gpuReceiverDepth(light, r) - bias;
  std::vector<double> out;
  for (double scale : {1.0, 1.0 + 2e-4, 1.0 - 2e-4}) {
    const double v = Evaluator(s, map, light, scale, field_.get(), form_.perspectiveWidths).visibility(g);
    if (std::none_of(out.begin(), out.end(), [&](double o) { return o == v; })) out.push_back(v);
  }
  return out;
}

}  // namespace shadowc::validation
