#include "runtime/scene/mesh_loader.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <fmt/format.h>
#include <fmt/std.h>

#include <assimp/Importer.hpp>

namespace shadowc::rt {

Mesh loadMeshFile(const std::filesystem::path& path) {
  if (!std::filesystem::is_regular_file(path)) {
    throw SceneError(fmt::format("{}: cannot load mesh: file not found", path.string()));
  }
  Assimp::Importer importer;
  // Points and lines are dropped (SortByPType + the removal flag): only triangles cast shadows.
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  const unsigned flags = aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_GenSmoothNormals |
                         aiProcess_PreTransformVertices | aiProcess_SortByPType;
  const aiScene* scene = importer.ReadFile(path.string(), flags);
  if (scene == nullptr) {
    throw SceneError(fmt::format("{}: cannot load mesh: {}", path.string(), importer.GetErrorString()));
  }
  Mesh out;
  out.name = path.filename().string();
  for (unsigned mi = 0; mi < scene->mNumMeshes; ++mi) {
    const aiMesh* m = scene->mMeshes[mi];
    if ((m->mPrimitiveTypes & aiPrimitiveType_TRIANGLE) == 0) continue;
    const auto base = static_cast<uint32_t>(out.positions.size());
    for (unsigned v = 0; v < m->mNumVertices; ++v) {
      out.positions.emplace_back(m->mVertices[v].x, m->mVertices[v].y, m->mVertices[v].z);
      glm::vec3 n(0, 1, 0);
      if (m->HasNormals()) n = glm::vec3(m->mNormals[v].x, m->mNormals[v].y, m->mNormals[v].z);
      const float len = glm::length(n);
      out.normals.push_back(len > 0 && std::isfinite(len) ? n / len : glm::vec3(0, 1, 0));
    }
    for (unsigned f = 0; f < m->mNumFaces; ++f) {
      const aiFace& face = m->mFaces[f];
      if (face.mNumIndices != 3) continue;
      for (int k = 0; k < 3; ++k) out.indices.push_back(base + face.mIndices[k]);
    }
  }
  if (out.indices.empty()) {
    throw SceneError(fmt::format("{}: cannot load mesh: the file holds no triangles", path.string()));
  }
  return out;
}

}  // namespace shadowc::rt
