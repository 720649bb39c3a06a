// glTF 2.0, as .gltf (JSON with external or embedded buffers) or .glb, read
// with tinygltf: every triangle primitive of the default scene's meshes, each
// placed by its node's transform; triangle strips and fans become triangles,
// points and lines are skipped with a warning. baseColorFactor and the
// metallic-roughness factors map onto the Phong terms; baseColorTexture, with
// TEXCOORD_0, multiplies the base colour. Other textures are not drawn.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <initializer_list>
#include <limits>
#include <filesystem>
#include <map>
#include <memory>
#include <set>
#include <tuple>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>
#include <nlohmann/json.hpp>

#include <tiny_gltf.h>

#include "mesh/input_error.hpp"
#include "mesh/io/mesh_readers.hpp"
#include "mesh/io/texture_file.hpp"

namespace umbra {
namespace {

constexpr size_t kMostCorners = size_t(1) << 31;  // as the check takes at most

// tinygltf's image loader when texture maps are skipped: nothing is decoded.
bool skip_image(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) {
  return true;
}

// tinygltf's image loader when maps are read: each image's bytes are kept
// as they are, by image, and decoded only if a material's texture uses them
// (GltfReader::base_colour_texture), once.
using EncodedImages = std::map<int, std::vector<unsigned char>>;
bool keep_encoded(tinygltf::Image*, const int index, std::string*, std::string*, int, int, const unsigned char* bytes, int size,
                  void* encoded) {
  (*static_cast<EncodedImages*>(encoded))[index].assign(bytes, bytes + std::max(size, 0));
  return true;
}

// The files a glTF names by uri (buffers, images), as tinygltf asks for them:
// found beside the model (or by an absolute path), and read only where
// ModelFiles allows and as regular files of bounded size. Why one was not
// read is kept by path, for the warning that names its image.
struct GltfFiles {
  ModelFiles files;
  std::filesystem::path folder;  // the model's
  std::map<std::string, std::string> refused;

  // tinygltf tries the folder it is given, then "."; given "", it asks for
  // the uri itself and "./" and the uri, both of which mean the model's folder.
  std::string path_of(const std::string& uri) const {
    std::string path = std::filesystem::path(uri).is_absolute() ? uri : (folder / uri).lexically_normal().string();
    std::error_code ec;
    // glTF's uris take '/', but some exporters write Windows' '\'.
    if (path.find('\\') != std::string::npos && !std::filesystem::exists(path, ec)) std::replace(path.begin(), path.end(), '\\', '/');
    return path;
  }
};

constexpr size_t kMostGltfFileBytes = size_t(1) << 32;  // as the reader takes at most

bool gltf_file_exists(const std::string& path, void*) {
  std::error_code ec;
  return std::filesystem::exists(path, ec);  // a stat: nothing is opened
}

std::string gltf_file_path(const std::string& uri, void* files) { return static_cast<const GltfFiles*>(files)->path_of(uri); }

bool read_gltf_file(std::vector<unsigned char>* out, std::string* error, const std::string& path, void* user) {
  GltfFiles& files = *static_cast<GltfFiles*>(user);
  std::string why = files.files.refusal(path);
  if (why.empty() && read_regular_file(path, kMostGltfFileBytes, *out, why)) return true;
  if (error) *error = why;
  files.refused[path] = why;
  return false;
}

bool refuse_gltf_write(std::string* error, const std::string&, const std::vector<unsigned char>&, void*) {
  if (error) *error = "umbra writes no glTF files";
  return false;
}

// A uri's %XX escapes decoded, as tinygltf decodes them before it looks for the file.
std::string percent_decoded(const std::string& uri) {
  std::string out;
  for (size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '%' && i + 2 < uri.size() && std::isxdigit((unsigned char)uri[i + 1]) && std::isxdigit((unsigned char)uri[i + 2])) {
      out += char(std::stoi(uri.substr(i + 1, 2), nullptr, 16));
      i += 2;
    } else {
      out += uri[i];
    }
  }
  return out;
}

TextureImage::Wrap wrap_of(int gl_wrap) {
  switch (gl_wrap) {
    case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE: return TextureImage::Wrap::kClampToEdge;
    case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT: return TextureImage::Wrap::kMirroredRepeat;
    default: return TextureImage::Wrap::kRepeat;
  }
}

glm::dmat4 local_transform(const tinygltf::Node& node) {
  if (node.matrix.size() == 16) return glm::make_mat4(node.matrix.data());  // column-major, as glm
  glm::dmat4 m(1.0);
  if (node.translation.size() == 3) m = glm::translate(m, glm::make_vec3(node.translation.data()));
  if (node.rotation.size() == 4) {
    const auto& r = node.rotation;  // x, y, z, w
    m *= glm::mat4_cast(glm::dquat(r[3], r[0], r[1], r[2]));
  }
  if (node.scale.size() == 3) m = glm::scale(m, glm::make_vec3(node.scale.data()));
  return m;
}

// glTF's PBR factors as Phong terms: the base colour is the diffuse colour
// (whatever the metalness: a Phong surface without its colour would be
// black); the highlight is a metal's base colour or a dielectric's 4%,
// dimmed by roughness, and narrows as roughness falls (shininess 2/r^4 - 2,
// the Blinn-Phong exponent of a Beckmann lobe of that roughness; Walter et
// al., "Microfacet Models for Refraction through Rough Surfaces", 2007).
SoupMaterial phong_of(const tinygltf::Material& m) {
  SoupMaterial out;
  out.name = m.name;
  const auto& pbr = m.pbrMetallicRoughness;
  const glm::dvec3 base = pbr.baseColorFactor.size() >= 3
                              ? glm::dvec3(pbr.baseColorFactor[0], pbr.baseColorFactor[1], pbr.baseColorFactor[2])
                              : glm::dvec3(1.0);
  const double metallic = std::clamp(pbr.metallicFactor, 0.0, 1.0);
  const double roughness = std::clamp(pbr.roughnessFactor, 0.05, 1.0);
  out.diffuse = glm::clamp(base, 0.0, 1.0);
  out.specular = glm::mix(glm::dvec3(0.04), out.diffuse, metallic) * (1.0 - roughness);
  out.shininess = std::min(2.0 / std::pow(roughness, 4.0) - 2.0, 1000.0);
  return out;
}

class GltfReader {
 public:
  // `files` and `encoded`: where the images' files were looked for, and
  // their bytes; null when maps are skipped.
  GltfReader(const tinygltf::Model& model, PolygonSoup& soup, const GltfFiles* files, const EncodedImages* encoded)
      : model_(model), soup_(soup), files_(files), encoded_(encoded) {}

  void read() {
    for (const tinygltf::Material& m : model_.materials) {
      soup_.materials.push_back(phong_of(m));
      if (encoded_) soup_.materials.back().texture = base_colour_texture(m);
      textured_ = textured_ || soup_.materials.back().texture;
      uv_transforms_.push_back(soup_.materials.back().texture ? texture_transform(m.pbrMetallicRoughness.baseColorTexture)
                                                              : glm::dmat3(1.0));
    }
    if (model_.scenes.empty()) {
      // No scene: every mesh, as it is, once.
      for (size_t m = 0; m < model_.meshes.size(); ++m) add_mesh(int(m), glm::dmat4(1.0));
      keep_normals();
      return;
    }
    const size_t scene = model_.defaultScene >= 0 && size_t(model_.defaultScene) < model_.scenes.size() ? size_t(model_.defaultScene) : 0;
    require_trees(model_.scenes[scene], scene);
    for (int node : model_.scenes[scene].nodes) add_node(node, glm::dmat4(1.0));
    keep_normals();
  }

 private:
  // The points' normals as their corners', when some primitive has them.
  void keep_normals() {
    if (!any_normals_) return;
    point_normals_.resize(soup_.points.size(), glm::vec3(0.0f));
    soup_.set_corner_normals_of_points(point_normals_);
  }

  [[noreturn]] void fail(const std::string& message) const { throw InputError({soup_.path, 0, 0}, message); }

  // A material's baseColorTexture as a texture map, made once per glTF
  // texture and decoded once per image and wrapping; null, with a warning
  // once per texture, where it cannot be drawn.
  std::shared_ptr<const TextureImage> base_colour_texture(const tinygltf::Material& material) {
    const tinygltf::TextureInfo& info = material.pbrMetallicRoughness.baseColorTexture;
    if (info.index < 0) return nullptr;
    const std::string what = "material \"" + material.name + "\"'s base colour texture";
    const auto [cached, first_time] = textures_.try_emplace(info.index);
    if (!first_time) return cached->second;
    const auto refuse = [&](const std::string& why) {
      soup_.warn(0, what + " " + why + ": its faces take the base colour");
      return nullptr;
    };
    if (info.texCoord != 0) return refuse("uses TEXCOORD_" + std::to_string(info.texCoord) + ", and umbra reads TEXCOORD_0 only");
    if (const auto t = info.extensions.find("KHR_texture_transform"); t != info.extensions.end() && t->second.Has("texCoord") &&
                                                                      t->second.Get("texCoord").GetNumberAsInt() != 0)
      return refuse("has KHR_texture_transform on TEXCOORD_" + std::to_string(t->second.Get("texCoord").GetNumberAsInt()) +
                    ", and umbra reads TEXCOORD_0 only");
    if (size_t(info.index) >= model_.textures.size()) return refuse("does not exist");
    const tinygltf::Texture& texture = model_.textures[size_t(info.index)];
    if (texture.source < 0 || size_t(texture.source) >= model_.images.size()) return refuse("has no image");
    const tinygltf::Image& image = model_.images[size_t(texture.source)];
    const bool external = !image.uri.empty() && image.uri.rfind("data:", 0) != 0;
    const std::string name = external ? image.uri : !image.name.empty() ? image.name : "image " + std::to_string(texture.source);
    const auto encoded = encoded_->find(texture.source);
    if (encoded == encoded_->end()) return refuse("(" + name + ") " + (external ? unread_file(image.uri) : "could not be read"));
    TextureImage::Wrap wrap_u = TextureImage::Wrap::kRepeat, wrap_v = TextureImage::Wrap::kRepeat;
    if (texture.sampler >= 0 && size_t(texture.sampler) < model_.samplers.size()) {
      wrap_u = wrap_of(model_.samplers[size_t(texture.sampler)].wrapS);
      wrap_v = wrap_of(model_.samplers[size_t(texture.sampler)].wrapT);
    }
    auto& decoded = decoded_[{texture.source, wrap_u, wrap_v}];
    if (!decoded.image && decoded.error.empty()) {
      const std::vector<unsigned char>& bytes = encoded->second;
      if (auto map = decode_texture(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), name, decoded.error,
                                    &budget_)) {
        map->wrap_u = wrap_u;
        map->wrap_v = wrap_v;
        decoded.image = std::move(map);
      }
    }
    if (!decoded.image) return refuse("(" + name + ") " + decoded.error);
    return cached->second = decoded.image;
  }

  // A texture's KHR_texture_transform as the affine map of its texture
  // coordinates, translation * rotation * scale, as the extension writes it
  // (Khronos, "KHR_texture_transform", 2018): the UVs turned by `rotation`
  // radians about the origin. The identity without one. An affine map commutes with the
  // blending of corners across a triangle, so it is applied to each
  // corner's coordinates once, on reading, for the GL and the reference alike.
  static glm::dmat3 texture_transform(const tinygltf::TextureInfo& info) {
    const auto found = info.extensions.find("KHR_texture_transform");
    if (found == info.extensions.end() || !found->second.IsObject()) return glm::dmat3(1.0);
    const tinygltf::Value& t = found->second;
    const auto pair = [&](const char* key, double fallback) {
      glm::dvec2 v(fallback);
      if (t.Has(key) && t.Get(key).IsArray() && t.Get(key).ArrayLen() == 2)
        for (int k = 0; k < 2; ++k)
          if (t.Get(key).Get(k).IsNumber()) v[k] = t.Get(key).Get(k).GetNumberAsDouble();
      return std::isfinite(v.x) && std::isfinite(v.y) ? v : glm::dvec2(fallback);
    };
    const glm::dvec2 offset = pair("offset", 0.0), scale = pair("scale", 1.0);
    double rotation = t.Has("rotation") && t.Get("rotation").IsNumber() ? t.Get("rotation").GetNumberAsDouble() : 0.0;
    if (!std::isfinite(rotation)) rotation = 0.0;
    const double c = std::cos(rotation), s = std::sin(rotation);
    // glm's matrices are column-major: these are the columns. The turn is
    // u' = c u + s v, v' = -s u + c v, as the extension's sample model
    // (TextureTransformTest) checks it: the extension's GLSL, read as
    // columns, would turn the other way.
    const glm::dmat3 translation(1, 0, 0, 0, 1, 0, offset.x, offset.y, 1);
    const glm::dmat3 turn(c, -s, 0, s, c, 0, 0, 0, 1);
    const glm::dmat3 scaling(scale.x, 0, 0, 0, scale.y, 0, 0, 0, 1);
    return translation * turn * scaling;
  }

  // Why the image file `uri` names was not read.
  std::string unread_file(const std::string& uri) const {
    const std::string decoded = percent_decoded(uri);
    if (decoded.rfind("file:", 0) == 0)
      return "is a file: URI, which umbra does not follow: name the image by a path relative to the model";
    const std::string path = files_->path_of(decoded);
    if (const auto refused = files_->refused.find(path); refused != files_->refused.end()) return refused->second;
    const std::string why = files_->files.refusal(path);
    return why.empty() ? "could not be read" : why;
  }

  // glTF's nodes form trees: no node has two parents, lists a child twice
  // or is a scene's root twice (the schema's uniqueItems). A graph would be
  // read once along every path to a node, which a few hundred bytes can
  // make exponential; refused, each node is placed at most once per root.
  void require_trees(const tinygltf::Scene& scene, size_t scene_index) const {
    const auto refuse = [&](const std::string& why) { fail("not a valid glTF 2.0 file: " + why + "; glTF's nodes form trees"); };
    std::vector<int> parent(model_.nodes.size(), -1);
    for (size_t n = 0; n < model_.nodes.size(); ++n)
      for (const int child : model_.nodes[n].children) {
        if (child < 0 || size_t(child) >= model_.nodes.size()) continue;  // said where it is read
        if (parent[size_t(child)] == int(n))
          refuse("node " + std::to_string(n) + " lists node " + std::to_string(child) + " as its child twice");
        if (parent[size_t(child)] >= 0)
          refuse("node " + std::to_string(child) + " has two parents (nodes " + std::to_string(parent[size_t(child)]) + " and " +
                 std::to_string(n) + ")");
        parent[size_t(child)] = int(n);
      }
    std::set<int> roots;
    for (const int root : scene.nodes) {
      if (!roots.insert(root).second)
        refuse("scene " + std::to_string(scene_index) + " lists node " + std::to_string(root) + " as a root twice");
    }
  }

  void add_node(int index, const glm::dmat4& parent) {
    if (index < 0 || size_t(index) >= model_.nodes.size()) fail("node " + std::to_string(index) + " does not exist");
    if (!on_path_.insert(index).second)
      fail("node " + std::to_string(index) + " is its own ancestor: the node hierarchy has a cycle");
    const tinygltf::Node& node = model_.nodes[size_t(index)];
    const glm::dmat4 world = parent * local_transform(node);
    if (node.mesh >= 0) add_mesh(node.mesh, world);
    for (int child : node.children) add_node(child, world);
    on_path_.erase(index);
  }

  // An accessor's elements in their buffer, checked once to lie in it.
  struct Elements {
    const unsigned char* first = nullptr;
    size_t stride = 0;
    size_t count = 0;
    const unsigned char* at(size_t i) const { return first + i * stride; }
  };

  Elements elements(const tinygltf::Accessor& accessor, const std::string& what) const {
    if (accessor.sparse.isSparse) fail(what + " uses a sparse accessor, which umbra does not read");
    if (accessor.bufferView < 0 || size_t(accessor.bufferView) >= model_.bufferViews.size())
      fail(what + " has no buffer view");
    const tinygltf::BufferView& view = model_.bufferViews[size_t(accessor.bufferView)];
    if (view.buffer < 0 || size_t(view.buffer) >= model_.buffers.size()) fail(what + "'s buffer view has no buffer");
    const std::vector<unsigned char>& data = model_.buffers[size_t(view.buffer)].data;
    const int stride = accessor.ByteStride(view);
    const int size = tinygltf::GetComponentSizeInBytes(uint32_t(accessor.componentType)) *
                     tinygltf::GetNumComponentsInType(uint32_t(accessor.type));
    if (stride <= 0 || size <= 0) fail(what + " has an invalid component type or stride");
    if (accessor.count == 0) return {};
    // Counts and offsets come from the file: compared so that nothing overflows.
    const size_t start = view.byteOffset + accessor.byteOffset;
    const size_t limit = std::min(data.size(), view.byteOffset + view.byteLength);
    if (start > limit || (accessor.count - 1) > (limit - start) / size_t(stride) ||
        start + (accessor.count - 1) * size_t(stride) + size_t(size) > limit)
      fail(what + " reads past the end of its buffer (" + std::to_string(accessor.count) + " elements)");
    return {data.data() + start, size_t(stride), accessor.count};
  }

  // One position: float, or (as KHR_mesh_quantization allows, which mesh
  // optimisers such as gltfpack write) integers, normalised or not.
  glm::dvec3 position_at(const tinygltf::Accessor& accessor, const unsigned char* p, const std::string& what,
                         const char* attribute = "POSITION") const {
    glm::dvec3 xyz;
    for (int k = 0; k < 3; ++k) {
      switch (accessor.componentType) {
        case TINYGLTF_COMPONENT_TYPE_FLOAT: xyz[k] = read_as<float>(p, k); break;
        case TINYGLTF_COMPONENT_TYPE_BYTE: xyz[k] = normalised(read_as<int8_t>(p, k), 127.0, accessor.normalized); break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: xyz[k] = normalised(read_as<uint8_t>(p, k), 255.0, accessor.normalized); break;
        case TINYGLTF_COMPONENT_TYPE_SHORT: xyz[k] = normalised(read_as<int16_t>(p, k), 32767.0, accessor.normalized); break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: xyz[k] = normalised(read_as<uint16_t>(p, k), 65535.0, accessor.normalized); break;
        default: fail(what + "'s " + attribute + " must be floats, or bytes or shorts (KHR_mesh_quantization)");
      }
    }
    return xyz;
  }

  // The primitive's attribute `name`, one per point: checked to exist, to be
  // of one of `types` (`types_text` in the message) and to give `count` of
  // them (`noun`); null when the primitive has none.
  const tinygltf::Accessor* point_attribute(const tinygltf::Primitive& primitive, const char* name, std::initializer_list<int> types,
                                           const char* types_text, size_t count, const char* noun, const std::string& what) const {
    const auto found = primitive.attributes.find(name);
    if (found == primitive.attributes.end()) return nullptr;
    const std::string named = what + "'s " + name;
    if (found->second < 0 || size_t(found->second) >= model_.accessors.size()) fail(named + " accessor does not exist");
    const tinygltf::Accessor& accessor = model_.accessors[size_t(found->second)];
    if (std::find(types.begin(), types.end(), accessor.type) == types.end()) fail(named + " must be " + types_text);
    if (accessor.count != count)
      fail(named + " has " + std::to_string(accessor.count) + " " + noun + " for " + std::to_string(count) + " vertices");
    return &accessor;
  }

  // The primitive's COLOR_0 (RGB, or RGBA read as RGB), one per point, into
  // soup_.point_colors from `first` on; floats or normalised unsigned bytes
  // or shorts, as glTF 2.0 allows. Points of primitives without colours are white.
  void add_colours(const tinygltf::Primitive& primitive, uint32_t first, size_t count, const std::string& what) {
    const tinygltf::Accessor* const found =
        point_attribute(primitive, "COLOR_0", {TINYGLTF_TYPE_VEC3, TINYGLTF_TYPE_VEC4}, "VEC3 or VEC4", count, "colours", what);
    if (!found) {
      if (!soup_.point_colors.empty()) soup_.point_colors.resize(soup_.points.size(), glm::vec3(1.0f));
      return;
    }
    const tinygltf::Accessor& accessor = *found;
    const Elements rgbs = elements(accessor, what + "'s COLOR_0");
    soup_.point_colors.resize(first, glm::vec3(1.0f));
    for (size_t i = 0; i < rgbs.count; ++i) {
      glm::vec3 rgb;
      for (int k = 0; k < 3; ++k) {
        switch (accessor.componentType) {
          case TINYGLTF_COMPONENT_TYPE_FLOAT: rgb[k] = float(read_as<float>(rgbs.at(i), k)); break;
          case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: rgb[k] = float(read_as<uint8_t>(rgbs.at(i), k) / 255.0); break;
          case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: rgb[k] = float(read_as<uint16_t>(rgbs.at(i), k) / 65535.0); break;
          default: fail(what + "'s COLOR_0 must be floats, or normalised unsigned bytes or shorts");
        }
        rgb[k] = std::isfinite(rgb[k]) ? std::clamp(rgb[k], 0.0f, 1.0f) : 0.0f;
      }
      soup_.point_colors.push_back(rgb);
    }
  }

  // The primitive's NORMAL, one per point, into point_normals_ from `first`
  // on, turned by the node's `world` transform (by its inverse transpose, as
  // normals turn); (0, 0, 0), drawn flat, for points of primitives without.
  void add_normals(const tinygltf::Primitive& primitive, uint32_t first, size_t count, const glm::dmat4& world,
                   const std::string& what) {
    point_normals_.resize(first, glm::vec3(0.0f));
    const tinygltf::Accessor* const found = point_attribute(primitive, "NORMAL", {TINYGLTF_TYPE_VEC3}, "VEC3", count, "normals", what);
    if (!found) {
      point_normals_.resize(first + count, glm::vec3(0.0f));
      return;
    }
    const tinygltf::Accessor& accessor = *found;
    const Elements normals = elements(accessor, what + "'s NORMAL");
    const glm::dmat3 turn = glm::transpose(glm::inverse(glm::dmat3(world)));
    for (size_t i = 0; i < normals.count; ++i) {
      const glm::dvec3 n = turn * position_at(accessor, normals.at(i), what, "NORMAL");
      point_normals_.push_back(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z) ? glm::vec3(n) : glm::vec3(0.0f));
      any_normals_ = true;
    }
  }

  // The primitive's TEXCOORD_0, one per point, into point_uvs_ from `first`
  // on: floats, or (KHR_mesh_quantization) integers, normalised or not.
  // Points of primitives without it take (0, 0).
  void add_texture_coordinates(const tinygltf::Primitive& primitive, uint32_t first, size_t count, const std::string& what) {
    point_uvs_.resize(first, glm::vec2(0.0f));
    const tinygltf::Accessor* const found =
        point_attribute(primitive, "TEXCOORD_0", {TINYGLTF_TYPE_VEC2}, "VEC2", count, "coordinates", what);
    if (!found) {
      point_uvs_.resize(first + count, glm::vec2(0.0f));
      return;
    }
    const tinygltf::Accessor& accessor = *found;
    const Elements uvs = elements(accessor, what + "'s TEXCOORD_0");
    for (size_t i = 0; i < uvs.count; ++i) {
      glm::vec2 st;
      for (int k = 0; k < 2; ++k) {
        double c = 0.0;
        switch (accessor.componentType) {
          case TINYGLTF_COMPONENT_TYPE_FLOAT: c = read_as<float>(uvs.at(i), k); break;
          case TINYGLTF_COMPONENT_TYPE_BYTE: c = normalised(read_as<int8_t>(uvs.at(i), k), 127.0, accessor.normalized); break;
          case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: c = normalised(read_as<uint8_t>(uvs.at(i), k), 255.0, accessor.normalized); break;
          case TINYGLTF_COMPONENT_TYPE_SHORT: c = normalised(read_as<int16_t>(uvs.at(i), k), 32767.0, accessor.normalized); break;
          case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: c = normalised(read_as<uint16_t>(uvs.at(i), k), 65535.0, accessor.normalized); break;
          default: fail(what + "'s TEXCOORD_0 must be floats, or bytes or shorts (KHR_mesh_quantization)");
        }
        st[k] = std::isfinite(c) ? float(c) : 0.0f;
      }
      point_uvs_.push_back(st);
    }
  }

  template <typename T>
  static double read_as(const unsigned char* p, int k) {
    T v;
    std::memcpy(&v, p + k * sizeof(T), sizeof(T));
    return double(v);
  }

  // glTF 2.0's conversion of a normalised integer: c / max, at least -1.
  static double normalised(double c, double max, bool normalized) { return normalized ? std::max(c / max, -1.0) : c; }

  std::vector<uint32_t> indices_of(const tinygltf::Accessor& accessor, const std::string& what) const {
    const Elements list = elements(accessor, what);
    std::vector<uint32_t> indices(list.count);
    switch (accessor.componentType) {
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        for (size_t i = 0; i < list.count; ++i) indices[i] = *list.at(i);
        break;
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        for (size_t i = 0; i < list.count; ++i) {
          uint16_t v;
          std::memcpy(&v, list.at(i), 2);
          indices[i] = v;
        }
        break;
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        for (size_t i = 0; i < list.count; ++i) std::memcpy(&indices[i], list.at(i), 4);
        break;
      default: fail(what + " must be unsigned bytes, shorts or ints");
    }
    return indices;
  }

  void add_mesh(int index, const glm::dmat4& world) {
    if (index < 0 || size_t(index) >= model_.meshes.size()) fail("mesh " + std::to_string(index) + " does not exist");
    const tinygltf::Mesh& mesh = model_.meshes[size_t(index)];
    // A mirroring transform turns the winding round (glTF 2.0, 5.25).
    const bool mirrored = glm::determinant(glm::dmat3(world)) < 0.0;
    for (size_t p = 0; p < mesh.primitives.size(); ++p) {
      const tinygltf::Primitive& primitive = mesh.primitives[p];
      const std::string what = "mesh " + std::to_string(index) + " primitive " + std::to_string(p);
      if (primitive.mode != TINYGLTF_MODE_TRIANGLES && primitive.mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
          primitive.mode != TINYGLTF_MODE_TRIANGLE_FAN) {
        soup_.warn(0, what + " is made of points or lines: skipped");
        continue;
      }
      const auto position = primitive.attributes.find("POSITION");
      if (position == primitive.attributes.end()) fail(what + " has no POSITION attribute");
      if (position->second < 0 || size_t(position->second) >= model_.accessors.size())
        fail(what + "'s POSITION accessor does not exist");
      const tinygltf::Accessor& points = model_.accessors[size_t(position->second)];
      if (points.type != TINYGLTF_TYPE_VEC3) fail(what + "'s POSITION must be VEC3");
      const uint32_t first = uint32_t(soup_.points.size());
      const Elements xyzs = elements(points, what + "'s POSITION");
      if (soup_.points.size() + xyzs.count >= kMostCorners)
        fail("its nodes place more than 2^31 points (" + what + " among them), more than umbra reads");
      soup_.points.reserve(soup_.points.size() + xyzs.count);
      for (size_t i = 0; i < xyzs.count; ++i) {
        const glm::dvec3 xyz = position_at(points, xyzs.at(i), what);
        const glm::dvec3 p3 = glm::dvec3(world * glm::dvec4(xyz, 1.0));
        if (!std::isfinite(p3.x) || !std::isfinite(p3.y) || !std::isfinite(p3.z))
          fail(what + " vertex " + std::to_string(i) + " has a coordinate that is not a finite number");
        soup_.points.push_back(p3);
      }
      add_colours(primitive, first, xyzs.count, what);
      if (textured_) add_texture_coordinates(primitive, first, xyzs.count, what);
      if (encoded_) add_normals(primitive, first, xyzs.count, world, what);
      std::vector<uint32_t> indices;
      if (primitive.indices >= 0) {
        if (size_t(primitive.indices) >= model_.accessors.size()) fail(what + "'s index accessor does not exist");
        indices = indices_of(model_.accessors[size_t(primitive.indices)], what + "'s indices");
        for (size_t i = 0; i < indices.size(); ++i)
          if (indices[i] >= points.count)
            fail(what + " index " + std::to_string(i) + " is " + std::to_string(indices[i]) + ", but the primitive has " +
                 std::to_string(points.count) + " vertices");
      } else {
        indices.resize(points.count);
        for (uint32_t i = 0; i < points.count; ++i) indices[i] = i;
      }
      const size_t triangles = primitive.mode == TINYGLTF_MODE_TRIANGLES ? indices.size() / 3 : std::max<size_t>(indices.size(), 2) - 2;
      // Nodes may place one mesh many times: the work stays bounded by what umbra checks at all.
      if (soup_.corners.size() + 3 * triangles >= kMostCorners)
        fail("its nodes place more than 2^31 triangle corners (" + what + " among them), more than umbra reads");
      soup_.corners.reserve(soup_.corners.size() + 3 * triangles);
      soup_.polygon_starts.reserve(soup_.polygon_starts.size() + triangles);
      soup_.polygon_lines.reserve(soup_.polygon_lines.size() + triangles);
      soup_.polygon_materials.reserve(soup_.polygon_materials.size() + triangles);
      const int material = primitive.material >= 0 && size_t(primitive.material) < soup_.materials.size() ? primitive.material : -1;
      const auto triangle = [&](uint32_t a, uint32_t b, uint32_t c) {
        if (mirrored) std::swap(b, c);
        soup_.corners.insert(soup_.corners.end(), {first + a, first + b, first + c});
        if (textured_) {
          const glm::dmat3& transform = material >= 0 ? uv_transforms_[size_t(material)] : glm::dmat3(1.0);
          for (const uint32_t k : {a, b, c}) soup_.corner_uvs.push_back(glm::vec2(transform * glm::dvec3(point_uvs_[first + k], 1.0)));
        }
        soup_.end_polygon(0);
        soup_.polygon_materials.push_back(material);
      };
      if (primitive.mode == TINYGLTF_MODE_TRIANGLES) {
        if (indices.size() % 3) soup_.warn(0, what + " has " + std::to_string(indices.size() % 3) + " indices after its last whole triangle: ignored");
        for (size_t i = 0; i + 2 < indices.size(); i += 3) triangle(indices[i], indices[i + 1], indices[i + 2]);
      } else if (primitive.mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
        for (size_t i = 0; i + 2 < indices.size(); ++i)
          i % 2 ? triangle(indices[i + 1], indices[i], indices[i + 2]) : triangle(indices[i], indices[i + 1], indices[i + 2]);
      } else {
        for (size_t i = 1; i + 1 < indices.size(); ++i) triangle(indices[0], indices[i], indices[i + 1]);
      }
    }
  }

  const tinygltf::Model& model_;
  PolygonSoup& soup_;
  const GltfFiles* files_;
  const EncodedImages* encoded_;  // null: maps are skipped
  std::map<int, std::shared_ptr<const TextureImage>> textures_;  // by glTF texture
  struct Decoded {
    std::shared_ptr<const TextureImage> image;
    std::string error;
  };
  std::map<std::tuple<int, TextureImage::Wrap, TextureImage::Wrap>, Decoded> decoded_;  // by image and wrapping
  TextureBudget budget_;  // what the images decoded so far hold
  bool textured_ = false;              // some material has a texture map: corners get texture coordinates
  std::vector<glm::vec2> point_uvs_;   // TEXCOORD_0 per point, while textured_
  std::vector<glm::vec3> point_normals_;  // NORMAL per point, for a picture (when maps are read)
  bool any_normals_ = false;
  std::vector<glm::dmat3> uv_transforms_;  // per material: its base colour texture's KHR_texture_transform
  std::set<int> on_path_;  // the nodes from the scene's root to the one being read
};

// The JSON of a .gltf, or of a GLB's first chunk; empty when there is none
// to read (tinygltf then says what is wrong).
std::string_view json_of(std::string_view bytes, bool binary) {
  if (!binary) return bytes;
  if (bytes.size() < 20) return {};
  uint32_t length = 0;
  std::memcpy(&length, bytes.data() + 12, 4);  // little endian, as GLB is
  if (bytes.substr(16, 4) != "JSON" || length > bytes.size() - 20) return {};
  return bytes.substr(20, length);
}

// glTF 1.0: a GLB header of version 1, an asset of version 1.x, or
// dictionaries where 2.0 has arrays; `json` is the file's JSON.
bool is_gltf_1(std::string_view bytes, bool binary, const nlohmann::json& json) {
  if (binary && bytes.size() >= 8) {
    uint32_t version = 0;
    std::memcpy(&version, bytes.data() + 4, 4);
    if (version == 1) return true;
  }
  if (!json.is_object()) return false;
  const auto version = json.find("asset");
  if (version != json.end() && version->is_object() && version->contains("version") && (*version)["version"].is_string() &&
      (*version)["version"].get<std::string>().substr(0, 2) == "1.")
    return true;
  for (const char* key : {"meshes", "nodes", "accessors", "buffers", "bufferViews"})
    if (json.contains(key) && json[key].is_object()) return true;
  return false;
}

// glTF 1.0 and Draco-compressed meshes, which tinygltf does not read, are Assimp's glTF importers'.
bool needs_assimp(std::string_view bytes, bool binary, const nlohmann::json& json) {
#ifdef UMBRA_HAVE_ASSIMP
  return is_gltf_1(bytes, binary, json) || bytes.find("KHR_draco_mesh_compression") != std::string_view::npos;
#else
  (void)bytes, (void)binary, (void)json;
  return false;
#endif
}

// What tinygltf would read wrongly or not name: glTF 1.0, compressed meshes,
// a mesh whose "primitives" is not an array (tinygltf reads none, silently).
void require_gltf_2(std::string_view bytes, bool binary, const nlohmann::json& json, const std::string& path) {
  const auto refuse = [&](const std::string& message) { throw InputError({path, 0, 0}, message); };
  if (is_gltf_1(bytes, binary, json))
    refuse("glTF 1.0, which umbra does not read: only glTF 2.0 (convert it, with gltf-pipeline or Blender, say)");
  if (!json.is_object()) return;
  if (const auto required = json.find("extensionsRequired"); required != json.end() && required->is_array())
    for (const nlohmann::json& name : *required)
      if (name == "EXT_meshopt_compression")
        refuse("its meshes are compressed with EXT_meshopt_compression, which umbra does not read (gltfpack writes it with "
               "-c or -cc, and plain meshes without them)");
  if (const auto meshes = json.find("meshes"); meshes != json.end() && meshes->is_array())
    for (size_t m = 0; m < meshes->size(); ++m) {
      const nlohmann::json& mesh = (*meshes)[m];
      if (mesh.is_object() && mesh.contains("primitives") && !mesh["primitives"].is_array())
        refuse("not a valid glTF 2.0 file: mesh " + std::to_string(m) + "'s \"primitives\" must be an array");
    }
}

}  // namespace

bool gltf_needs_assimp(std::string_view bytes) {
  const bool binary = bytes.substr(0, 4) == "glTF";
  const std::string_view text = json_of(bytes, binary);
  return needs_assimp(bytes, binary, nlohmann::json::parse(text.begin(), text.end(), nullptr, false));
}

PolygonSoup read_gltf(std::string_view bytes, const std::string& path, const ReadOptions& maps) {
  tinygltf::TinyGLTF loader;
  EncodedImages encoded;
  if (maps.read) loader.SetImageLoader(keep_encoded, &encoded);
  else loader.SetImageLoader(skip_image, nullptr);
  // A check decodes no image into a picture: any folder will do there.
  ReadOptions rule = maps;
  rule.anywhere = maps.anywhere || !maps.read;
  std::error_code ec;
  GltfFiles files{ModelFiles(rule, path), std::filesystem::absolute(path, ec).parent_path(), {}};
  loader.SetFsCallbacks({gltf_file_exists, gltf_file_path, read_gltf_file, refuse_gltf_write, &files});
  tinygltf::Model model;
  std::string error, warning;
  const std::string folder;  // GltfFiles::path_of finds a uri beside the model
  const bool binary = bytes.substr(0, 4) == "glTF";
  if (bytes.size() > std::numeric_limits<unsigned>::max()) throw InputError({path, 0, 0}, "too large for the glTF reader (4 GiB or more)");
  const std::string_view text = json_of(bytes, binary);
  const nlohmann::json json = nlohmann::json::parse(text.begin(), text.end(), nullptr, false);
#ifdef UMBRA_HAVE_ASSIMP
  if (needs_assimp(bytes, binary, json)) return read_assimp(bytes, path, maps);
#endif
  require_gltf_2(bytes, binary, json, path);
  const bool ok = binary ? loader.LoadBinaryFromMemory(&model, &error, &warning, reinterpret_cast<const unsigned char*>(bytes.data()),
                                                      unsigned(bytes.size()), folder)
                         : loader.LoadASCIIFromString(&model, &error, &warning, bytes.data(), unsigned(bytes.size()), folder);
  if (!ok) {
    while (!error.empty() && (error.back() == '\n' || error.back() == ' ')) error.pop_back();
    // Draco-compressed primitives have accessors without buffer views, which
    // tinygltf refuses without saying why.
    if (bytes.find("KHR_draco_mesh_compression") != std::string_view::npos)
      throw InputError({path, 0, 0}, "its meshes are Draco-compressed (KHR_draco_mesh_compression), which umbra does not read (tinygltf: " +
                                         error + ")");
    throw InputError({path, 0, 0}, std::string("not a valid ") + (binary ? "GLB" : "glTF") + " file: " +
                                       (error.empty() ? "tinygltf could not read it" : error));
  }
  PolygonSoup soup;
  soup.path = path;
  soup.format = binary ? "glTF (binary .glb)" : "glTF";
  GltfReader(model, soup, &files, maps.read ? &encoded : nullptr).read();
  return soup;
}

}  // namespace umbra
