// Loads a triangle mesh file (OBJ, glTF 2, PLY, Collada... anything assimp reads) into one
// Mesh in the file's own coordinates (node transforms applied, all sub-meshes merged).
#pragma once

#include <filesystem>

#include "runtime/scene/scene.h"

namespace shadowc::rt {

// Throws SceneError("<path>: cannot load mesh: <assimp's reason>") on failure, or when the file
// holds no triangles.
Mesh loadMeshFile(const std::filesystem::path& path);

}  // namespace shadowc::rt
