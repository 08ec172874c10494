// The built-in scenes: each one a known hard case for soft-shadow filters (docs/scenes.md says
// why). They are written in the JSON scene format itself, so samples/scenes/<name>.json is
// exactly builtinSceneJson(name) (checked by tests/runtime/scene_builtin_test.cpp) and the
// built-in and the file load to the same Scene and the same contentHash.
// Conventions: y is up, the receiver floor is at y = 0 unless said otherwise.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <fstream>
#include <iterator>
#include <map>
#include <nlohmann/json.hpp>

#include "runtime/scene/scene.h"
#include "shadowc_source_dir.h"
#include "support/suggest.h"

namespace shadowc::rt {
namespace {

using nlohmann::ordered_json;

ordered_json v3(double x, double y, double z) { return ordered_json::array({x, y, z}); }

ordered_json camera(ordered_json eye, ordered_json target, double fovY = 45) {
  return {{"eye", eye}, {"target", target}, {"up", v3(0, 1, 0)}, {"fov_y", fovY}};
}

ordered_json light(const char* shape, ordered_json position, ordered_json direction, double size,
                   ordered_json up = v3(0, 0, 1)) {
  return {{"shape", shape}, {"position", position}, {"direction", direction}, {"up", up}, {"size", size}};
}

// A sun: direction of travel and angular diameter in degrees (docs/scenes.md).
ordered_json sun(ordered_json direction, double angleDegrees, ordered_json up = v3(0, 0, 1)) {
  return {{"type", "sun"}, {"direction", direction}, {"up", up}, {"angle", angleDegrees}};
}

// A point light: a sphere of `radius` at `position`, shining every way (docs/scenes.md).
ordered_json pointLight(ordered_json position, double radius) {
  return {{"type", "point"}, {"position", position}, {"radius", radius}};
}

ordered_json transform(ordered_json translate, ordered_json rotate = nullptr, ordered_json scale = nullptr) {
  ordered_json t = {{"translate", translate}};
  if (!rotate.is_null()) t["rotate"] = rotate;
  if (!scale.is_null()) t["scale"] = scale;
  return t;
}

ordered_json plane(const char* name, double sx, double sz, ordered_json xform) {
  return {{"type", "plane"}, {"name", name}, {"size", {sx, sz}}, {"transform", xform}};
}
ordered_json box(const char* name, ordered_json size, ordered_json xform) {
  return {{"type", "box"}, {"name", name}, {"size", size}, {"transform", xform}};
}
ordered_json sphere(const char* name, double radius, ordered_json xform) {
  return {{"type", "sphere"}, {"name", name}, {"radius", radius},
          {"segments", 32},   {"rings", 16},  {"transform", xform}};
}
ordered_json meshObject(const char* name, const std::string& path, ordered_json xform) {
  return {{"type", "mesh"}, {"name", name}, {"path", path}, {"transform", xform}};
}
// Where Debian's assimp-testmodels package installs its models.
const std::string kAssimpModels = "/usr/share/assimp/models";
ordered_json floorPlane(double size = 10) { return plane("floor", size, size, transform(v3(0, 0, 0))); }

// tiny_penumbra's occluders: six bars 0.12 wide and 3 long, 0.4 apart, 1 unit above the floor, turned 30
// degrees about y.
ordered_json grate() {
  ordered_json objects = {floorPlane()};
  const double x[] = {-1.0, -0.6, -0.2, 0.2, 0.6, 1.0};  // written out: -1 + 0.4 i is not these doubles
  for (int i = 0; i < 6; ++i)
    objects.push_back(
        box(fmt::format("bar{}", i).c_str(), v3(0.12, 0.05, 3), transform(v3(x[i], 1.0, 0), v3(0, 30, 0))));
  return objects;
}

ordered_json scene(const char* name, const char* description, ordered_json cam, ordered_json lit,
                   ordered_json objects) {
  return {{"name", name}, {"description", description}, {"camera", cam}, {"light", lit}, {"objects", objects}};
}

const std::map<std::string, ordered_json>& builtins() {
  static const std::map<std::string, ordered_json> table = [] {
    std::map<std::string, ordered_json> t;
    const ordered_json down = v3(0, -1, 0);
    t["two_planes"] =
        scene("two_planes",
              "One square occluder above a floor, both parallel to the light: the case where VSM's Chebyshev bound, "
              "the VSSM blocker estimate and the PCSS penumbra formula are all exact.",
              camera(v3(0, 6, 8), v3(0, 0, 0)), light("rect", v3(0, 6, 0), down, 1.0),
              {floorPlane(), plane("occluder", 2, 2, transform(v3(0, 2, 0)))});
    // lauritzen2008 sec. 3.1, Fig. 2: A casts a shadow onto B; C lies entirely in B's shadow, yet a filter
    // region straddling A's edge sees depths a and b only, so plain VSM lets eq. (4) worth of light through
    // onto C. The camera sits below B to look at C.
    t["stacked_planes"] =
        scene("stacked_planes",
              "Lauritzen 2008 Fig. 2 light bleeding: plane A (y=4) half covers plane B (y=2), which fully shadows the "
              "floor C; plain VSM leaks light onto C under A's edge (eq. 4).",
              camera(v3(0, 1.2, 3.5), v3(0, 0, -1), 60), light("rect", v3(0, 8, 0), down, 0.6),
              {floorPlane(), plane("B", 4, 4, transform(v3(0, 2, 0))), plane("A", 3, 3, transform(v3(-1.5, 4, 0)))});
    t["contact"] =
        scene("contact",
              "Boxes and spheres resting on the floor: the penumbra shrinks to zero where they touch it (contact "
              "hardening), and the blocker depth equals the receiver depth there.",
              camera(v3(3, 4, 7), v3(0, 0.5, 0)), light("rect", v3(1, 7, 1), ordered_json(v3(-0.1, -1, -0.1)), 1.5),
              {floorPlane(), box("cube", v3(1, 1, 1), transform(v3(-1.5, 0.5, 0), v3(0, 20, 0))),
               sphere("ball", 0.7, transform(v3(1.2, 0.7, 0.5))),
               box("pillar", v3(0.6, 2, 0.6), transform(v3(0, 1, -1.5), v3(0, 30, 0)))});
    t["overlapping_occluders"] =
        scene("overlapping_occluders",
              "Non-planar blockers at several depths overlapping as seen from the light: the average-blocker depth of "
              "PCSS/VSSM is wrong for every one of them, and filter regions hold several depth layers.",
              camera(v3(0, 7, 8), v3(0, 0.5, 0)), light("rect", v3(0, 8, 0), down, 1.2),
              {floorPlane(), sphere("low_ball", 0.6, transform(v3(-0.5, 1.0, 0.3))),
               box("tilted_box", v3(1.2, 0.3, 1.2), transform(v3(0.4, 2.5, -0.2), v3(25, 30, 15))),
               sphere("high_ball", 0.5, transform(v3(0.6, 4.0, 0.6))),
               box("plank", v3(3, 0.08, 0.4), transform(v3(0, 3.2, 0), v3(0, 45, 0)))});
    t["large_penumbra"] =
        scene("large_penumbra",
              "A 4-unit light close to the occluder: penumbrae span a large fraction of the shadow map, so fixed "
              "kernels and small blocker searches fail and SAT/mip filters must cover huge regions.",
              camera(v3(0, 7, 9), v3(0, 0, 0)), light("rect", v3(0, 5, 0), down, 4.0),
              {floorPlane(14), box("block", v3(1.5, 0.5, 1.5), transform(v3(0, 2.5, 0)))});
    // A light as wide as its height above the occluder: the light's form factor varies by a factor of
    // about 2.5 across it as seen from the floor under the tray, so a filter that counts the
    // visible part of the light uniformly misses the truth by several percent (docs/dsl.md "weights").
    t["lamp_table"] =
        scene("lamp_table",
              "A 1.5-unit lamp 1 unit above a thin tray over a table: the light is as wide as its height above the "
              "occluder, so how the filter weighs the parts of the light decides its error.",
              camera(v3(0, 3.2, 3.2), v3(0, 0, 0)), light("rect", v3(0, 1.8, 0), down, 1.5),
              {floorPlane(6), plane("tray", 0.8, 0.8, transform(v3(-0.1, 0.8, 0.05), v3(0, 20, 0)))});
    t["small_penumbra"] =
        scene("small_penumbra",
              "A 0.05-unit light far away, occluder near the floor: penumbrae narrower than a shadow-map texel, so the "
              "result is limited by resolution and bias, and any blur over-softens.",
              camera(v3(0, 5, 6), v3(0, 0, 0)), light("rect", v3(0, 10, 0), down, 0.05),
              {floorPlane(), box("block", v3(1.5, 0.4, 1.5), transform(v3(0, 0.8, 0), v3(0, 30, 0)))});
    // PCSS width W (zr - zb) / zb = 0.05 * 1 / 7 = 0.007 world units at the floor, about 0.75 texels of a
    // 1024^2 map over this floor: resolution, not filtering, decides the edges (docs/planning.md
    // "Map size"); the grate's many edges make them a large share of the image.
    t["tiny_penumbra"] =
        scene("tiny_penumbra",
              "A 0.05-unit light 8 units up over a grate of thin bars 1 unit above the floor: penumbrae about 0.75 "
              "texels wide at 1024^2, so every filter errs along the many edges until the map is larger.",
              camera(v3(0, 3.5, 3.5), v3(0, 0, 0)), light("rect", v3(0, 8, 0), down, 0.05), grate());
    // The light sits at the origin looking down; occluders at 1e-3, 1, 100 and near the floor at 1e4, so
    // the fitted near/far planes are about 1e-3 and 1e4 (fp32 depth, moment and SAT precision).
    t["depth_range"] = scene(
        "depth_range",
        "Depths from 1e-3 to 1e4 in one map: a tiny occluder right in front of the light, others at 1, 100 and "
        "near the floor 1e4 away; stresses fp32/fp16 depth, moment and SAT precision and bias scaling.",
        camera(v3(0, -3000, 9000), v3(0, -10000, 0), 60), light("rect", v3(0, 0, 0), down, 1e-4),
        {plane("floor", 20000, 20000, transform(v3(0, -10000, 0))),
         plane("tiny", 4e-4, 4e-4, transform(v3(3e-4, -1e-3, 0))), plane("small", 0.3, 0.3, transform(v3(-0.3, -1, 0))),
         box("medium", v3(30, 30, 30), transform(v3(0, -100, 30))),
         sphere("near_floor", 500, transform(v3(-2500, -9500, -2500)))});
    t["grazing"] = scene(
        "grazing",
        "The light skims the floor at about 3 degrees: shadows stretch far, shadow-map texels cover long strips "
        "of the receiver, and slope-dependent bias decides between acne and peter-panning.",
        camera(v3(8, 6, 12), v3(0, 0, 0)),
        light("rect", v3(0, 1.0, -18), ordered_json(v3(0, -1, 18)), 0.5, v3(0, 1, 0)),
        {plane("floor", 12, 20, transform(v3(0, 0, 0))), box("post", v3(0.3, 1.2, 0.3), transform(v3(-1, 0.6, -6))),
         box("wall", v3(3, 0.5, 0.2), transform(v3(1.5, 0.25, -2))), sphere("ball", 0.4, transform(v3(-2, 0.4, 2)))});
    t["thin_occluders"] =
        scene("thin_occluders",
              "Poles and bars thinner than the penumbra and near a texel wide: shadows never reach full darkness, "
              "features are lost by coarse maps and averaged away by big kernels.",
              camera(v3(0, 6, 8), v3(0, 0.5, 0)), light("rect", v3(0, 7, 0), down, 1.0),
              {floorPlane(), box("pole_1", v3(0.05, 3, 0.05), transform(v3(-2, 1.5, 0))),
               box("pole_2", v3(0.05, 3, 0.05), transform(v3(2, 1.5, 0))),
               box("bar", v3(4, 0.03, 0.03), transform(v3(0, 3, 0))),
               box("bar_low", v3(4, 0.02, 0.02), transform(v3(0, 0.5, 1), v3(0, 20, 0))),
               box("slat_1", v3(0.02, 0.02, 3), transform(v3(-0.5, 2, 0))),
               box("slat_2", v3(0.02, 0.02, 3), transform(v3(0.5, 2, 0)))});
    t["empty"] = scene("empty",
                       "Only the receiver: nothing casts a shadow, every lit pixel must stay exactly 1 (acne, bias, "
                       "SAT and moment round-off show up as darkening).",
                       camera(v3(0, 6, 8), v3(0, 0, 0)), light("disk", v3(0, 6, 0), down, 1.0), {floorPlane()});
    // The camera sits below the occluder and looks down, so it sees only the floor (all dark).
    t["fully_occluded"] =
        scene("fully_occluded",
              "The floor lies entirely under a larger occluder: every receiver must be exactly 0 (moments with zero "
              "variance, P -> 1 in the blocker estimate, min-max early outs).",
              camera(v3(0, 1.2, 4.5), v3(0, 0, 0), 26), light("rect", v3(0, 5, 0), down, 1.0),
              {floorPlane(8), plane("roof", 12, 12, transform(v3(0, 1.5, 0)))});
    t["mesh"] =
        scene("mesh",
              "A torus knot loaded from samples/scenes/knot.obj through assimp: curved self-shadowing geometry with "
              "several depth layers, smooth normals, no planar occluder anywhere.",
              camera(v3(3, 5, 6), v3(0, 0.8, 0)), light("disk", v3(1, 7, 1), ordered_json(v3(-0.15, -1, -0.15)), 1.0),
              {floorPlane(8),
               {{"type", "mesh"},
                {"name", "knot"},
                {"path", "knot.obj"},
                {"transform", transform(v3(0, 2.0, 0), v3(20, 0, 0), 2.0)}}});
    // Meshes nobody here made: Debian's assimp-testmodels (scripts/install-deps.sh), loaded through
    // assimp by their absolute install path. Scale and lift put each on the floor at y = 0.
    t["duck"] = scene("duck",
                      "The COLLADA duck (assimp-testmodels Collada/duck.dae, 4212 triangles): smooth curved surfaces "
                      "that shadow themselves (head over neck and breast, tail over back); terminators and acne.",
                      camera(v3(2.6, 2.4, 3.6), v3(0.15, 1.0, 0)),
                      light("disk", v3(2.0, 6, 1.5), ordered_json(v3(-0.3, -1, -0.25)), 1.0),
                      {floorPlane(8), meshObject("duck", kAssimpModels + "/Collada/duck.dae",
                                                 transform(v3(0, -0.148, 0), v3(0, -30, 0), 1.5))});
    t["spider"] = scene("spider",
                        "The assimp-testmodels spider (OBJ/spider.obj, 1368 triangles): eight legs thinner than the "
                        "penumbra touching the floor, a body above them; thin features, contact and overlap.",
                        camera(v3(0.5, 3.5, 4.5), v3(0, 0.3, 0)),
                        light("rect", v3(0.6, 6, 0.8), ordered_json(v3(-0.1, -1, -0.13)), 1.0),
                        {floorPlane(8), meshObject("spider", kAssimpModels + "/OBJ/spider.obj",
                                                   transform(v3(0.3, 0.85, 0.2), v3(0, 20, 0), 0.02))});
    t["engine"] = scene(
        "engine",
        "The glTF 2 two-cylinder engine (assimp-testmodels glTF2/2CylinderEngine, 121496 triangles, 34 parts): "
        "dense machinery, many overlapping parts at several depths, small gaps and thin rods.",
        camera(v3(3.9, 4.2, 5.4), v3(0, 0.5, 0)),
        light("rect", v3(1.0, 7, 1.5), ordered_json(v3(-0.15, -1, -0.2)), 1.5),
        {floorPlane(8), meshObject("engine", kAssimpModels + "/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb",
                                   transform(v3(0, 1.1, 0), nullptr, 0.006))});
    // A sun over two parallel planes: a half-plane edge at height 1 (x < 0) over the floor. The
    // visibility across the penumbra is the cosine-weighted fraction of the sun's cone of directions
    // that passes the edge, a closed form (tests/gpu/sun_closed_form_test.cpp). The sun is enlarged
    // to 4 degrees so its penumbra (1 * 2 tan 2 deg = 0.07) spans texels and pixels.
    t["sun_two_planes"] =
        scene("sun_two_planes",
              "A 4-degree sun straight down over a half-plane edge at height 1 above the floor: the penumbra is the "
              "fraction of the sun's disk that passes the edge, known in closed form.",
              camera(v3(0, 0.45, 1.2), v3(0, 0, 0), 40), sun(down, 4.0),
              {floorPlane(4), plane("edge", 3, 3, transform(v3(-1.5, 1, 0)))});
    // Outdoors: the real sun (0.53 degrees) low in the sky over a street of boxes, a sphere and a
    // pole: long thin shadows, contact at every base, penumbrae from a few texels to a fraction.
    t["sun_outdoor"] =
        scene("sun_outdoor",
              "The real sun (0.53 degrees) at about 54 degrees elevation over a 24 m ground with buildings, a sphere "
              "and a pole: long shadows, contact at every base, penumbrae of a few texels.",
              camera(v3(0, 5, 14), v3(0, 0, 0), 50), sun(ordered_json(v3(0.5, -0.8, -0.3)), 0.53),
              {floorPlane(24), box("building_a", v3(3, 6, 3), transform(v3(-5, 3, -3))),
               box("building_b", v3(2, 3.5, 4), transform(v3(3, 1.75, -5))),
               box("wall", v3(6, 1.2, 0.3), transform(v3(0, 0.6, 3))), sphere("sphere", 1.0, transform(v3(4, 1, 3))),
               box("pole", v3(0.15, 5, 0.15), transform(v3(-2, 2.5, 5)))});
    // A room lit by a point light at 1.5 m: floor, back and side walls, casters on the floor. Seen
    // from the light, the floor's cube-face seams are the lines |x| = 1.5 and |z| = 1.5; the box
    // at x = 1.5, the crate at z = -1.5 and the sphere near the corner x = z = -1.5 throw shadows
    // across them (tests/gpu/point_room_test.cpp measures the error there).
    t["point_room"] =
        scene("point_room",
              "A 6 m room (floor, back and side walls) lit by a 0.15 m point light 1.5 m up: cube shadow maps, with "
              "casters whose penumbrae cross the faces' seams on the floor and shadows that climb the walls.",
              camera(v3(0, 4.6, 6.8), v3(0, 0.4, -0.2), 55), pointLight(v3(0, 1.5, 0), 0.15),
              {floorPlane(6), plane("back_wall", 6, 3, transform(v3(0, 1.5, -3), v3(90, 0, 0))),
               plane("left_wall", 3, 6, transform(v3(-3, 1.5, 0), v3(0, 0, -90))),
               plane("right_wall", 3, 6, transform(v3(3, 1.5, 0), v3(0, 0, 90))),
               box("seam_box", v3(0.4, 0.7, 0.4), transform(v3(1.5, 0.35, 0.4))),
               box("seam_crate", v3(0.8, 0.5, 0.5), transform(v3(-0.3, 0.25, -1.5), v3(0, 20, 0))),
               sphere("corner_sphere", 0.3, transform(v3(-1.4, 0.55, 1.3))),
               box("pillar", v3(0.2, 1.0, 0.2), transform(v3(0.9, 0.5, 1.6)))});
    // Cascades: a camera 6 m up looking along a 160 m street, casters from 5 m to
    // 150 m away, so one map fitted to the scene spends most texels where the camera sees little.
    // Three posts stand just before the three splits of `cascades 4` (practical, lambda 0.5, at
    // camera depths 24.3, 50.9 and 89.9 m for this camera) so that their shadows cross each
    // cascade border. A 1.5-degree sun (3x the real one) keeps the penumbrae a few texels wide
    // even in the far cascades; a 2 m fence along the whole left side lays one straight penumbra
    // along the street, across every border (tests/gpu/cascades_test.cpp, docs/accuracy.md "Cascaded sun").
    t["sun_outdoor_long"] = scene(
        "sun_outdoor_long",
        "A 1.5-degree sun over a 12 m x 160 m street seen from 6 m up along its length: posts, walls and boxes "
        "from 5 m to 150 m away, the case cascaded shadow maps are for.",
        camera(v3(0, 6, 8), v3(0, 0, -40), 45), sun(ordered_json(v3(0.45, -0.75, -0.35)), 1.5),
        {plane("street", 12, 160, transform(v3(0, 0, -72))), box("post_1", v3(0.2, 3, 0.2), transform(v3(-2, 1.5, 2))),
         box("wall_1", v3(3, 1.5, 0.3), transform(v3(2, 0.75, -4))),
         box("box_1", v3(1.5, 2, 1.5), transform(v3(-3, 1, -9))),
         box("post_2", v3(0.3, 5, 0.3), transform(v3(-1, 2.5, -14.2))),
         box("wall_2", v3(5, 2.5, 0.4), transform(v3(4, 1.25, -28))),
         box("post_3", v3(0.4, 7, 0.4), transform(v3(-4, 3.5, -40.6))),
         box("box_2", v3(3, 4, 3), transform(v3(3, 2, -60))),
         box("post_4", v3(0.6, 10, 0.6), transform(v3(-3, 5, -79.9))),
         box("wall_3", v3(8, 4, 0.6), transform(v3(1, 2, -110))), box("box_3", v3(5, 6, 5), transform(v3(-2, 3, -140))),
         box("fence", v3(0.2, 2, 150), transform(v3(-5.5, 1, -71)))});
    return t;
  }();
  return table;
}

std::filesystem::path builtinMeshDir() { return std::filesystem::path(SHADOWC_SOURCE_DIR) / "samples" / "scenes"; }

}  // namespace

std::vector<std::string> builtinSceneNames() {
  std::vector<std::string> names;
  for (const auto& [name, j] : builtins()) names.push_back(name);
  return names;
}

std::string builtinSceneJson(const std::string& name) {
  auto it = builtins().find(name);
  if (it == builtins().end()) throw SceneError(fmt::format("unknown built-in scene '{}'", name));
  return it->second.dump(2) + "\n";
}

std::string builtinSceneDescription(const std::string& name) {
  auto it = builtins().find(name);
  return it == builtins().end() ? std::string() : it->second.value("description", std::string());
}

Scene loadScene(const std::string& nameOrPath) {
  if (builtins().count(nameOrPath) != 0) {
    return parseScene(builtinSceneJson(nameOrPath), "builtin:" + nameOrPath, builtinMeshDir());
  }
  const std::filesystem::path path(nameOrPath);
  const bool looksLikePath = path.has_extension() || nameOrPath.find('/') != std::string::npos;
  if (!looksLikePath) {
    const std::string near = support::closestMatch(nameOrPath, builtinSceneNames());
    throw SceneError(fmt::format("unknown scene '{}'{} (built-in scenes: {}; or give a path to a .json file)",
                                 nameOrPath, near.empty() ? "" : fmt::format(", did you mean '{}'?", near),
                                 fmt::join(builtinSceneNames(), ", ")));
  }
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw SceneError(fmt::format("{}: error: scene file not found", nameOrPath));
  }
  std::ifstream in(path, std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in.good() && !in.eof()) throw SceneError(fmt::format("{}: error: cannot read the scene file", nameOrPath));
  return parseScene(text, nameOrPath, path.parent_path());
}

}  // namespace shadowc::rt
