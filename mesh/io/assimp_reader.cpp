// The formats umbra does not parse itself (3DS, Collada, FBX, Blender,
// LightWave, DirectX .x, AC3D, ...), read through Assimp's importers with no
// post-processing: nothing joined, fixed or generated, so that the check
// sees what the importer gives. The scene graph's transforms are applied to
// each mesh instance; faces are kept as polygons (umbra triangulates them as
// it does every format's); points and lines are left out and said. Every
// file Assimp opens is served by umbra: the model's own bytes from memory,
// and the files it names (LightWave's objects, external buffers) only from
// inside the folder its texture maps may come from.

#include <assimp/BaseImporter.h>
#include <assimp/DefaultIOStream.h>
#include <assimp/IOSystem.hpp>
#include <assimp/Importer.hpp>
#include <assimp/MemoryIOWrapper.h>
#include <assimp/config.h>
#include <assimp/importerdesc.h>
#include <assimp/material.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cmath>
#include <cctype>
#include <filesystem>
#include <vector>

#include "mesh/file_extension.hpp"
#include "mesh/input_error.hpp"
#include "mesh/io/mesh_readers.hpp"
#include "mesh/io/texture_file.hpp"

namespace umbra {
namespace {

// The most bytes of a file a model names (a LightWave scene's objects, an
// external buffer): as much as one mesh file may hold.
constexpr size_t kMostCompanionBytes = size_t(1) << 32;

// Assimp's file system: the model's bytes as they were mapped, and the
// files it names read whole, when `files` lets them be.
class ConfinedFiles : public Assimp::IOSystem {
 public:
  ConfinedFiles(std::string_view bytes, const std::string& path, ModelFiles& files) : bytes_(bytes), path_(path), files_(files) {}

  bool Exists(const char* file) const override {
    std::error_code ec;
    return is_model(file) || (files_.refusal(file).empty() && std::filesystem::is_regular_file(file, ec));
  }
  char getOsSeparator() const override { return '/'; }

  Assimp::IOStream* Open(const char* file, const char* mode) override {
    if (std::string(mode).find_first_of("wa+") != std::string::npos) return nullptr;  // nothing is written
    if (is_model(file)) return new Assimp::MemoryIOStream(reinterpret_cast<const uint8_t*>(bytes_.data()), bytes_.size());
    if (!files_.refusal(file).empty()) return nullptr;
    std::vector<unsigned char> read;
    std::string error;
    if (!read_regular_file(file, kMostCompanionBytes, read, error)) return nullptr;
    auto* owned = new uint8_t[read.size()];
    std::copy(read.begin(), read.end(), owned);
    return new Assimp::MemoryIOStream(owned, read.size(), true);
  }
  void Close(Assimp::IOStream* stream) override { delete stream; }

 private:
  bool is_model(const char* file) const {
    return std::filesystem::path(file).lexically_normal() == std::filesystem::path(path_).lexically_normal();
  }
  std::string_view bytes_;
  std::string path_;
  ModelFiles& files_;
};

// `path`, or where it is missing the file in its folder whose name differs
// from its name in case alone: DOS-era exporters named maps in capitals
// (3DS's "TEST.PNG" for test.png).
std::filesystem::path file_in_any_case(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::exists(path, ec)) return path;
  const std::string name = lowercase(path.filename().string());
  for (std::filesystem::directory_iterator it(path.parent_path().empty() ? "." : path.parent_path(), ec), end; !ec && it != end;
       it.increment(ec))
    if (lowercase(it->path().filename().string()) == name) return path.parent_path() / it->path().filename();
  return path;
}

// The scene's colours and maps as umbra's materials. A map is the diffuse
// one (or PBR's base colour): inside the file (Assimp's "*N"), or a file
// beside it, read as OBJ's are.
std::vector<SoupMaterial> materials_of(const aiScene& scene, const std::string& path, ModelFiles& files, PolygonSoup& soup,
                                       const ReadOptions& maps) {
  std::vector<SoupMaterial> materials;
  TextureBudget budget;
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  for (unsigned i = 0; i < scene.mNumMaterials; ++i) {
    const aiMaterial& m = *scene.mMaterials[i];
    SoupMaterial material;
    aiString name;
    material.name = m.Get(AI_MATKEY_NAME, name) == AI_SUCCESS ? name.C_Str() : "material " + std::to_string(i);
    aiColor4D base;
    aiColor3D color;
    if (m.Get(AI_MATKEY_BASE_COLOR, base) == AI_SUCCESS) material.diffuse = {base.r, base.g, base.b};
    else if (m.Get(AI_MATKEY_COLOR_DIFFUSE, color) == AI_SUCCESS) material.diffuse = {color.r, color.g, color.b};
    if (m.Get(AI_MATKEY_COLOR_SPECULAR, color) == AI_SUCCESS) material.specular = {color.r, color.g, color.b};
    float shininess = 0.0f;
    if (m.Get(AI_MATKEY_SHININESS, shininess) == AI_SUCCESS && shininess > 0.0f) material.shininess = shininess;
    aiString map;
    if (maps.read && (m.GetTexture(aiTextureType_DIFFUSE, 0, &map) == AI_SUCCESS || m.GetTexture(aiTextureType_BASE_COLOR, 0, &map) == AI_SUCCESS)) {
      std::string error;
      if (const aiTexture* inside = scene.GetEmbeddedTexture(map.C_Str())) {
        const std::string label = "the model's map " + std::string(map.C_Str());
        if (inside->mHeight == 0) {  // a compressed image (PNG, JPEG), mWidth bytes long
          material.texture = decode_texture({reinterpret_cast<const char*>(inside->pcData), inside->mWidth}, label, error, &budget);
        } else if (budget.take(static_cast<long long>(inside->mWidth) * inside->mHeight)) {  // texels, BGRA
          auto image = std::make_shared<TextureImage>();
          image->name = label;
          image->width = int(inside->mWidth), image->height = int(inside->mHeight);
          image->rgba.resize(size_t(inside->mWidth) * inside->mHeight * 4);
          for (size_t t = 0; t < size_t(inside->mWidth) * inside->mHeight; ++t) {
            const aiTexel& texel = inside->pcData[t];
            image->rgba[t * 4] = texel.r, image->rgba[t * 4 + 1] = texel.g, image->rgba[t * 4 + 2] = texel.b, image->rgba[t * 4 + 3] = texel.a;
          }
          material.texture = image;
        } else {
          error = "its texels would take the model's maps past what one model may hold";
        }
      } else {
        std::string file = map.C_Str();
        std::replace(file.begin(), file.end(), '\\', '/');  // Windows exporters' paths
        material.texture = files.texture(file_in_any_case((folder / file).lexically_normal()).string(), error);
      }
      if (!material.texture && !error.empty())
        soup.warn(0, "material \"" + material.name + "\"'s texture map \"" + map.C_Str() + "\": " + error +
                         ": its faces take the material's colour");
    }
    materials.push_back(std::move(material));
  }
  return materials;
}

// Every mesh instance of the scene graph, placed by its nodes' transforms.
void add_instances(const aiScene& scene, PolygonSoup& soup, bool textured) {
  struct Pending {
    const aiNode* node;
    aiMatrix4x4 parent;
  };
  std::vector<Pending> pending{{scene.mRootNode, aiMatrix4x4()}};
  bool colored = true, normals = false;
  for (unsigned i = 0; i < scene.mNumMeshes; ++i) colored = colored && scene.mMeshes[i]->HasVertexColors(0);
  size_t lines = 0;
  std::vector<glm::vec3> point_normals;
  while (!pending.empty()) {
    const Pending next = pending.back();
    pending.pop_back();
    if (!next.node) continue;
    const aiMatrix4x4 m = next.parent * next.node->mTransformation;
    // Normals turn by the inverse transpose of the transform's linear part.
    const aiMatrix3x3 turn = aiMatrix3x3(aiMatrix4x4(m).Inverse().Transpose());
    for (unsigned k = 0; k < next.node->mNumMeshes; ++k) {
      if (next.node->mMeshes[k] >= scene.mNumMeshes) continue;
      const aiMesh& mesh = *scene.mMeshes[next.node->mMeshes[k]];
      const uint32_t first = uint32_t(soup.points.size());
      for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
        const aiVector3D& p = mesh.mVertices[v];
        const double x = p.x, y = p.y, z = p.z;
        const glm::dvec3 placed{m.a1 * x + m.a2 * y + m.a3 * z + m.a4, m.b1 * x + m.b2 * y + m.b3 * z + m.b4,
                                m.c1 * x + m.c2 * y + m.c3 * z + m.c4};
        // As umbra's own readers do: a coordinate that is not a number is the file's defect, named.
        if (!std::isfinite(placed.x) || !std::isfinite(placed.y) || !std::isfinite(placed.z))
          throw InputError({soup.path, 0, 0}, "mesh " + std::to_string(next.node->mMeshes[k]) + " vertex " + std::to_string(v) +
                                                  " has a coordinate that is not a finite number" +
                                                  (std::isfinite(x) && std::isfinite(y) && std::isfinite(z) ? " once placed by its node's transform" : ""),
                            InputProblem::kMalformed);
        soup.points.push_back(placed);
        if (colored) {
          const aiColor4D& c = mesh.mColors[0][v];
          soup.point_colors.push_back({std::clamp(c.r, 0.0f, 1.0f), std::clamp(c.g, 0.0f, 1.0f), std::clamp(c.b, 0.0f, 1.0f)});
        }
        aiVector3D n(0.0f);
        if (mesh.HasNormals()) n = turn * mesh.mNormals[v], normals = true;
        point_normals.push_back({n.x, n.y, n.z});
      }
      for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
        const aiFace& face = mesh.mFaces[f];
        if (face.mNumIndices < 3 || std::any_of(face.mIndices, face.mIndices + face.mNumIndices,
                                                 [&](unsigned index) { return index >= mesh.mNumVertices; })) {
          ++lines;
          continue;
        }
        for (unsigned c = 0; c < face.mNumIndices; ++c) {
          soup.corners.push_back(first + face.mIndices[c]);
          if (textured) {
            const aiVector3D uv = mesh.HasTextureCoords(0) ? mesh.mTextureCoords[0][face.mIndices[c]] : aiVector3D(0.0f);
            soup.corner_uvs.push_back({uv.x, 1.0f - uv.y});  // Assimp's v runs up the image, the soup's down
          }
        }
        soup.end_polygon(0);
        soup.polygon_materials.push_back(mesh.mMaterialIndex < scene.mNumMaterials ? int(mesh.mMaterialIndex) : -1);
      }
    }
    for (unsigned c = 0; c < next.node->mNumChildren; ++c) pending.push_back({next.node->mChildren[c], m});
  }
  if (normals) soup.set_corner_normals_of_points(point_normals);
  if (lines > 0)
    soup.warn(0, std::to_string(lines) + (lines == 1 ? " point or line" : " points and lines") +
                     " (faces of fewer than 3 corners) are not drawn");
}

// The name of the importer that reads `path`: of those that claim its
// extension (glTF's two importers both claim .gltf), the first whose own
// test of the content takes it.
std::string importer_of(Assimp::Importer& importer, const std::string& path) {
  std::string extension = lowercase_extension(path);
  if (!extension.empty()) extension.erase(0, 1);
  std::string name = "importer";
  for (size_t i = 0; i < importer.GetImporterCount(); ++i) {
    const aiImporterDesc* info = importer.GetImporterInfo(i);
    const std::string claimed = std::string(" ") + info->mFileExtensions + " ";
    if (claimed.find(" " + extension + " ") == std::string::npos) continue;
    if (name == "importer") name = info->mName;  // the extension's first, where none takes the content
    if (importer.GetImporter(i)->CanRead(path, importer.GetIOHandler(), true)) {
      name = info->mName;
      break;
    }
  }
  if (const size_t link = name.find(" (http"); link != std::string::npos) name.erase(link);  // Blender's names its site
  return name;
}

}  // namespace

std::vector<std::string_view> assimp_extensions() {
  static const std::vector<std::string> extensions = [] {
    // umbra's own readers' formats; names too generic to claim (.xml, .raw,
    // .prj, .scn); files that hold no mesh (motion capture, cameras); and
    // STEP, which is CAD exchange and not the IFC Assimp reads of it.
    const std::vector<std::string> left_out = {".obj", ".off", ".ply", ".stl", ".gltf", ".glb", ".3mf", ".xml", ".raw", ".prj",
                                               ".scn", ".bvh", ".csm", ".mot", ".md5anim", ".md5camera", ".step", ".stp"};
    std::string list;
    Assimp::Importer().GetExtensionList(list);  // "*.3d;*.3ds;..."
    std::vector<std::string> kept;
    for (size_t start = 0; start < list.size();) {
      const size_t end = std::min(list.find(';', start), list.size());
      std::string extension = lowercase(list.substr(start, end - start));
      if (extension.rfind("*.", 0) == 0) extension.erase(0, 1);
      if (extension.size() > 1 && std::find(left_out.begin(), left_out.end(), extension) == left_out.end()) kept.push_back(extension);
      start = end + 1;
    }
    return kept;
  }();
  return {extensions.begin(), extensions.end()};
}

std::string assimp_up_axis(const std::string& path) {
  const std::string extension = lowercase_extension(path);
  for (const char* z_up : {".3ds", ".ase", ".ask", ".blend", ".dxf", ".ifc", ".ifczip", ".md2", ".md3", ".mdc", ".mdl", ".bsp", ".pk3"})
    if (extension == z_up) return "+z";
  return "+y";
}

PolygonSoup read_assimp(std::string_view bytes, const std::string& path, const ReadOptions& maps) {
  ModelFiles files(maps, path);
  Assimp::Importer importer;
  importer.SetIOHandler(new ConfinedFiles(bytes, path, files));  // the importer owns it
  importer.SetPropertyBool(AI_CONFIG_IMPORT_NO_SKELETON_MESHES, true);  // no meshes made up for a skeleton
  const std::string importer_name = importer_of(importer, path);
  const aiScene* scene = importer.ReadFile(path, 0);
  if (!scene || !scene->mRootNode)
    throw InputError({path, 0, 0},
                     "Assimp's " + importer_name + " cannot read it" + (*importer.GetErrorString() ? std::string(": ") + importer.GetErrorString() : ""),
                     InputProblem::kMalformed);
  PolygonSoup soup;
  soup.path = path;
  soup.format = "read through Assimp's " + importer_name;
  soup.materials = materials_of(*scene, path, files, soup, maps);
  const bool textured = std::any_of(soup.materials.begin(), soup.materials.end(), [](const SoupMaterial& m) { return bool(m.texture); });
  add_instances(*scene, soup, textured);
  return soup;
}

}  // namespace umbra
