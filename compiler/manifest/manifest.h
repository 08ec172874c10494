// The manifest: the contract between the compiler and the runtime. The runtime executes what
// is listed here and knows nothing about the technique behind it. Serialized as manifest.json; see docs/manifest.md for
// the schema.
#pragma once

#include <array>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace shadowc {

inline constexpr int kManifestFormatVersion = 1;

enum class ImageFormat {
  R32F,
  RG32F,
  RGBA32F,
  R16F,
  RG16F,
  RGBA16F,
  R16Unorm,
  RG16Unorm,
  RGBA16Unorm,
  R32UI,
  RG32UI,
  RGBA32UI,
  // Depth formats: only an engine's depth attachment, the input of a hardware-depth filter
  // (docs/manifest.md "Hardware depth"); sampled through a depth-aspect view, never stored.
  D32F,  // VK_FORMAT_D32_SFLOAT
  D24    // VK_FORMAT_X8_D24_UNORM_PACK32 (or the depth aspect of D24_UNORM_S8_UINT)
};
// Whether a format is a depth format (its views and copies use the depth aspect).
inline bool isDepthFormat(ImageFormat f) { return f == ImageFormat::D32F || f == ImageFormat::D24; }

// What the runtime must put into (or take out of) an image. Internal images are the
// filter's own business; the others are the fixed interface between harness and filter.
enum class ImageRole {
  Internal,
  InputDepth,        // light-space normalized linear depth, R32F, size "map" (see frame.glsl)
  InputPosition,     // camera G-buffer world position, RGBA32F, w = 1 where geometry
  InputNormal,       // camera G-buffer world normal, RGBA32F
  OutputVisibility,  // R32F in [0,1], size "screen"
  // The engine's light depth attachment as rendered (D32F or D24, standard or reverse Z, the
  // spec's `depth_input`), size "map"; the first pass converts it into the internal shadow_depth.
  InputHardwareDepth
};

enum class SizeDomain { Map, Screen };
struct SizeRule {
  SizeDomain domain = SizeDomain::Map;
  int shift = 0;  // extent = max(1, domain_extent >> shift)
};

struct ImageDesc {
  std::string name;
  ImageFormat format = ImageFormat::R32F;
  SizeRule size;
  int mipLevels = 1;  // 0 = full chain down to 1x1
  int layers = 1;     // array layers (layered moments)
  ImageRole role = ImageRole::Internal;
  bool linearFilter = false;  // sampled with a linear sampler (else nearest)
};

// StorageBufferReadWrite: a buffer the pass adds into (the instrumented build's work counters,
// docs/manifest.md "Work counters"); the runtime resets it to its manifest values before a
// counted run and reads it back after.
enum class Access {
  Sampled,
  StorageRead,
  StorageWrite,
  StorageReadWrite,
  Uniform,
  StorageBufferRead,
  StorageBufferReadWrite
};
struct Binding {
  uint32_t binding = 0;
  // image name, "frame" for the ShadowcFrame uniform buffer, "parameters" for the pass's
  // ParameterBlock, or a buffer's name (StorageBufferRead/ReadWrite: the manifest's `buffers`)
  std::string image;
  Access access = Access::Sampled;
  int level = -1;  // storage views: the mip level bound; -1 = level 0 / whole image
};

enum class DispatchMode {
  Texels,        // one invocation per texel of the domain extent (x, y)
  Rows,          // one invocation per row (y); x covered by the shader's loop (SAT scans)
  Columns,       // one invocation per column (x)
  RowGroups,     // one workgroup per row: h groups, gl_WorkGroupID.x = row (parallel scans)
  ColumnGroups,  // one workgroup per column: w groups, gl_WorkGroupID.x = column
};
struct Dispatch {
  SizeRule size;
  DispatchMode mode = DispatchMode::Texels;
};

enum class ScalarType { U32, I32, F32 };
struct PushConstant {
  std::string name;
  uint32_t offset = 0;
  ScalarType type = ScalarType::U32;
  double value = 0;  // the value the runtime pushes for this pass
};

// A uniform block whose bytes the runtime writes from the manifest: the options of a generic
// shader (`shadowc compile --generic`, docs/cli.md). Each member sits at its std140 offset (the
// shader declares the same offsets with layout(offset = ...)); an array's elements are `stride`
// bytes apart and hold `components` consecutive scalars each.
struct BlockMember {
  std::string name;   // the GLSL member of shadowc_generic
  std::string macro;  // the SHADOWC_* option or shadowc_* table of the template it replaces
  ScalarType type = ScalarType::F32;
  uint32_t offset = 0;
  uint32_t stride = 0;      // bytes between array elements; 0 for a scalar
  uint32_t count = 1;       // declared array length (1 for a scalar); values may fill fewer
  uint32_t components = 1;  // scalars per element (2 for a vec2 array)
  std::vector<double> values;
  friend bool operator==(const BlockMember&, const BlockMember&) = default;
};
struct ParameterBlock {
  uint32_t binding = 0;  // in the pass's set 0 (listed in `bindings` as image "parameters")
  uint32_t size = 0;     // bytes
  std::vector<BlockMember> members;
  friend bool operator==(const ParameterBlock&, const ParameterBlock&) = default;
};
inline constexpr const char* kParametersBinding = "parameters";

// Pass forms (docs/manifest.md "Pass forms"): a pass may come in more than one form, each its
// own shader with the same bindings and bit-identical results (a serial scan for a CPU device, a
// work-efficient one for a GPU). The executor picks one from the device's properties, by what each
// form declares here, never by what the pass does.
enum class FormDevice { Any, Cpu, Gpu };  // the device type a form is meant for
struct FormNeeds {
  FormDevice device = FormDevice::Any;          // preferred device type (auto choice only)
  uint32_t subgroupSizeMin = 0;                 // hard: the device's subgroup size must be at least this
  std::vector<std::string> subgroupOperations;  // hard: compute-stage subgroup operations ("arithmetic", ...)
  friend bool operator==(const FormNeeds&, const FormNeeds&) = default;
};
struct PassForm {
  std::string name;  // unique within the pass, e.g. "serial", "parallel"
  FormNeeds needs;
  std::string spirv, glsl;
  std::array<uint32_t, 3> localSize{8, 8, 1};
  Dispatch dispatch;
};
// Every form name the compiler gives a pass ("serial", "parallel"): what a pass form override may
// name (runtime/executor/pass_forms.h checks it before any work).
const std::vector<std::string>& passFormNames();
// The subgroup operation names a form may need, as VkSubgroupFeatureFlagBits spells them.
const std::vector<std::string>& subgroupOperationNames();

struct Pass {
  std::string name;   // unique, e.g. "sat_rows", "minmax_level3", "shade"
  std::string kind;   // what it does, for reports only: "moments", "blur", "sat", "minmax", "shade", ...
  std::string spirv;  // file name relative to the manifest
  std::string glsl;   // file name relative to the manifest
  std::array<uint32_t, 3> localSize{8, 8, 1};
  Dispatch dispatch;
  std::vector<Binding> bindings;
  std::vector<PushConstant> pushConstants;
  std::optional<ParameterBlock> parameters;  // generic shaders only (JSON "parameters", absent otherwise)
  // A pass with several forms: `form` names the one given by the fields above (spirv, glsl,
  // localSize, dispatch) and `formNeeds` what it needs; `forms` holds the others. Empty form =
  // the pass has one form (JSON keys "form", "needs", "forms" absent).
  std::string form;
  FormNeeds formNeeds;
  std::vector<PassForm> forms;
};

// Every form of a pass, its own first; one unnamed form when the pass has a single one.
std::vector<PassForm> formsOf(const Pass& pass);
// The pass run as `form`: its spirv, glsl, local size and dispatch, no alternatives left.
Pass withForm(Pass pass, const PassForm& form);

// The includable lookup function for engines (docs/integration.md "The lookup's interface").
struct ShadeInterface {
  std::string glsl;       // file with the function and its resource declarations
  std::string function;   // e.g. "shadowc_visibility"
  std::string signature;  // e.g. "float shadowc_visibility(vec3 worldPos, vec3 worldNormal)"
  uint32_t set = 0;       // descriptor set of every binding below (compile --lookup-set)
  std::vector<Binding> bindings;
};

// A read-only storage buffer whose contents the manifest carries (the quadtree's Next/Child
// tables, docs/manifest.md "Buffers"): the runtime uploads `values` once, as consecutive
// little-endian int32, and binds it where a pass lists it with access storage_buffer_read.
// A buffer with `fields` is a work-counter buffer (docs/manifest.md "Work counters"): element k
// (`components` = 2 words: low, high) counts fields[k], summed over every invocation of the
// pass that binds it with access storage_buffer_read_write.
struct BufferDesc {
  std::string name;
  uint32_t components = 1;  // int32 per element (4: the shader reads an ivec4 array)
  std::vector<int32_t> values;
  std::vector<std::string> fields;  // JSON "fields", absent when empty
  friend bool operator==(const BufferDesc&, const BufferDesc&) = default;
};

struct Manifest {
  int formatVersion = kManifestFormatVersion;
  std::string compilerVersion;
  std::string filter;   // filter name
  nlohmann::json spec;  // the normalized FilterSpec (as --print-spec prints it)
  std::vector<ImageDesc> images;
  std::vector<BufferDesc> buffers;  // JSON "buffers", absent when there are none
  std::vector<Pass> passes;         // in execution order
  ShadeInterface shade;
  std::string contentHash;  // hash of every emitted file but the manifest itself
};

// JSON form. toJson is deterministic (fixed key order). fromJson throws ManifestError with
// a one-line message naming the offending field, or a version mismatch.
nlohmann::ordered_json toJson(const Manifest& m);
Manifest manifestFromJson(const nlohmann::json& j);
Manifest loadManifest(const std::string& path);  // reads + parses; throws ManifestError

struct ManifestError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The bytes of a parameter block as the runtime uploads them (zeros where no value is given).
void writeParameterBytes(const ParameterBlock& block, std::vector<uint8_t>& bytes);

const char* toString(ImageFormat f);
const char* toString(ImageRole r);
const char* toString(Access a);
const char* toString(DispatchMode m);
const char* toString(ScalarType t);
const char* toString(SizeDomain d);
const char* toString(FormDevice d);
uint32_t bytesPerTexel(ImageFormat f);
// Width and height of a size rule, given the shadow-map size (square) and the screen size.
std::array<uint32_t, 2> extentOf(const SizeRule& rule, uint32_t mapSize, uint32_t screenWidth, uint32_t screenHeight);

}  // namespace shadowc
