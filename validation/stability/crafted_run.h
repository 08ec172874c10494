// Crafted GPU runs for the stability suite: a FilterSpec compiled in process (the compiler
// driver), a hand-made shadow map (R32F normalized depth) and hand-placed receivers, every pass
// run by the run harness (runtime/harness/run_harness.h), the visibility (and any intermediate
// image) read back.
// Receivers are placed exactly: the light view is the identity, so a receiver at shadow-map uv
// (u, v) and normalized depth d sits at z = near + d (far - near), x = (2u - 1) z tanHalfFov
// (frame.glsl conventions; the briefing's receiver test z < d - bias). A sun frame
// (frame_ortho.glsl) puts it at x = (2u - 1) halfExtent; a point light's frame (frame_cube.glsl:
// six faces in a 3x3 atlas, each with tan(half fov) = tanHalfFov > 1 for the guard band) takes
// receivers by their light-view position (Receiver::position, see cubeReceiver).
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "manifest/compiled_passes.h"
#include "manifest/frame_uniforms.h"
#include "manifest/manifest.h"
#include "runtime/executor/host_image.h"
#include "spec/filter_spec.h"

namespace shadowc::rt {
class VulkanContext;
}

namespace shadowc::validation {

struct CompiledFilter {
  FilterSpec spec;
  CompiledPasses passes;  // the manifest and its SPIR-V, in memory
};

// Compiles once per distinct spec per process (the spec JSON plus the debug flags is the key).
// Throws std::runtime_error with the compiler log when the filter does not compile.
// `naiveDemo`: the spec is a naive form the checker rejects on purpose (driver::Options::checkBuiltSpec).
const CompiledFilter& compileCached(const FilterSpec& spec, bool naiveDemo = false);

// Checked spec from DSL text; throws std::runtime_error with the diagnostics on errors.
FilterSpec specFromSource(const std::string& text, const std::string& name);

// The projection of a crafted frame: the three forms of templates/frame*.glsl.
enum class Projection { Spot, Sun, Point };

struct LightFrame {  // aggregate order kept: {tanHalfFov, near, far, lightWidth} (tests/gpu)
  // Spot: tan(half fov); Point: each cube face's tan(half fov) (the runtime's 1.5, kCubeTanHalf).
  double tanHalfFov = 1.0, nearZ = 1.0, farZ = 11.0;
  // World units (used by filters with `size: scene`). Sun: the penumbra slope 2 tan(angle / 2)
  // (frame_ortho.glsl, sunPenumbraSlope); Point: the sphere's diameter 2R (frame_cube.glsl).
  double lightWidth = 0.5;
  double halfExtent = 1.0;  // Sun: half the orthographic box's side (lightParams.x), world units
  Projection projection = Projection::Spot;
};
LightFrame sunFrame(double halfExtent, double nearZ, double farZ, double angleDegrees);
LightFrame pointFrame(double tanHalf, double nearZ, double farZ, double radius);

struct Receiver {
  double u = 0.5, v = 0.5, d = 0.5;  // map uv (the atlas's for a point light) and normalized depth
  // Unit normal in light view; unset = facing the light (its centre; a sun: -z, N.L = 1).
  std::optional<std::array<double, 3>> normal;
  // Light-view position; when set it is the receiver (u, v, d are then its light-space
  // coordinates, filled by the maker: cubeReceiver). Required for a point light.
  std::optional<std::array<double, 3>> position;
};

// A depth map, row-major, `size` x `size`.
struct DepthMap {
  uint32_t size = 0;
  std::vector<float> depth;
  float at(int x, int y) const;  // clamp to edge
};
DepthMap constantMap(uint32_t size, float d);

ShadowcFrame makeFrame(const LightFrame& light, uint32_t mapSize, uint32_t screenW, uint32_t screenH);
// World (= light view) position of a receiver, in double and as the GPU sees it (fp32).
std::array<double, 3> receiverPosition(const LightFrame& light, const Receiver& r);
// The receiver's normal as runCrafted writes it: its own, else facing the light (its centre; a
// sun: -z).
std::array<double, 3> receiverNormal(const LightFrame& light, const Receiver& r);
// The normalized depth the shade pass computes for the receiver (fp32 arithmetic of frame.glsl,
// frame_ortho.glsl, frame_cube.glsl).
double gpuReceiverDepth(const LightFrame& light, const Receiver& r);

// ---- point lights: the cube atlas of frame_cube.glsl, in double ----------------------------
// Face of a light-view direction (major axis, ties x before y before z; f = 2 axis + negative).
int cubeFace(const std::array<double, 3>& p);
// Face coordinates (x_f, y_f, z_f) of a light-view point for face f: z_f = s p[a],
// x_f = p[(a + 1) % 3], y_f = p[(a + 2) % 3].
std::array<double, 3> cubeFaceCoords(int face, const std::array<double, 3>& p);
// The inverse: light-view point of face coordinates.
std::array<double, 3> cubeFromFace(int face, const std::array<double, 3>& q);
// A receiver at light-view position p: (u, v) its atlas uv, d its normalized face depth.
// `face` < 0: the face frame_cube.glsl picks (major axis); else the given face (siblings).
Receiver cubeReceiver(const LightFrame& light, uint32_t mapSize, const std::array<double, 3>& p, int face = -1);

struct CraftedResult {
  std::vector<float> visibility;                // one per receiver
  std::map<std::string, rt::HostImage> images;  // the requested intermediate images (level 0, layer 0)
};

CraftedResult runCrafted(rt::VulkanContext& ctx, const CompiledFilter& filter, const DepthMap& map,
                         const std::vector<Receiver>& receivers, const LightFrame& light,
                         const std::vector<std::string>& downloads = {});

// Receivers at the centres of texels (x, y) of a map of `size`.
inline Receiver atTexel(uint32_t size, double x, double y, double d) {
  return {(x + 0.5) / double(size), (y + 0.5) / double(size), d, std::nullopt};
}

}  // namespace shadowc::validation
