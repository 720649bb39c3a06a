// glTF 2.0, as .gltf (JSON with external or embedded buffers) or .glb, read
// with tinygltf: every triangle primitive of the default scene's meshes, each
// placed by its node's transform; triangle strips and fans become triangles,
// points and lines are skipped with a warning. baseColorFactor and the
// metallic-roughness factors map onto the Phong terms; baseColorTexture, with
// TEXCOORD_0, multiplies the base colour. Other textures are not drawn.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <filesystem>
#include <map>
#include <memory>
#include <set>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat4x4.hpp>
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

// tinygltf's image loader: images are decoded as texture maps are (with
// stb_image, RGBA). One that cannot be is noted in `failures` (by image) and
// left empty: its materials keep their base colour, and the mesh still loads.
bool decode_image(tinygltf::Image* image, const int index, std::string*, std::string*, int, int,
                  const unsigned char* bytes, int size, void* failures) {
  std::string error;
  const auto texture = decode_texture(std::string_view(reinterpret_cast<const char*>(bytes), size_t(std::max(size, 0))),
                                      image->name, error);
  if (!texture) {
    (*static_cast<std::map<int, std::string>*>(failures))[index] = error;
    return true;
  }
  image->width = texture->width;
  image->height = texture->height;
  image->component = 4;
  image->bits = 8;
  image->pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
  image->image = texture->rgba;
  return true;
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
  GltfReader(const tinygltf::Model& model, PolygonSoup& soup, const std::map<int, std::string>& image_failures, TextureMaps maps)
      : model_(model), soup_(soup), image_failures_(image_failures), maps_(maps) {}

  void read() {
    for (const tinygltf::Material& m : model_.materials) {
      soup_.materials.push_back(phong_of(m));
      if (maps_ == TextureMaps::kRead) soup_.materials.back().texture = base_colour_texture(m);
      textured_ = textured_ || soup_.materials.back().texture;
    }
    if (model_.scenes.empty()) {
      // No scene: every mesh, as it is, once.
      for (size_t m = 0; m < model_.meshes.size(); ++m) add_mesh(int(m), glm::dmat4(1.0));
      return;
    }
    require_trees();
    const int scene = model_.defaultScene >= 0 && size_t(model_.defaultScene) < model_.scenes.size() ? model_.defaultScene : 0;
    for (int node : model_.scenes[size_t(scene)].nodes) add_node(node, glm::dmat4(1.0));
  }

 private:
  [[noreturn]] void fail(const std::string& message) const { throw InputError({soup_.path, 0, 0}, message); }

  // A material's baseColorTexture as a texture map, made once per glTF
  // texture (an image and its sampler's wrapping); null, with a warning once
  // per texture, where it cannot be drawn.
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
    if (info.extensions.count("KHR_texture_transform")) return refuse("has KHR_texture_transform, which umbra does not apply");
    if (size_t(info.index) >= model_.textures.size()) return refuse("does not exist");
    const tinygltf::Texture& texture = model_.textures[size_t(info.index)];
    if (texture.source < 0 || size_t(texture.source) >= model_.images.size()) return refuse("has no image");
    const tinygltf::Image& image = model_.images[size_t(texture.source)];
    const std::string name = !image.uri.empty() && image.uri.rfind("data:", 0) != 0 ? image.uri
                             : !image.name.empty()                                 ? image.name
                                                                                    : "image " + std::to_string(texture.source);
    if (const auto failed = image_failures_.find(texture.source); failed != image_failures_.end())
      return refuse("(" + name + ") " + failed->second);
    if (image.image.empty() || image.component != 4 || image.width <= 0 || image.height <= 0)
      return refuse("(" + name + ") could not be read");
    auto map = std::make_shared<TextureImage>();
    map->name = name;
    map->width = image.width;
    map->height = image.height;
    map->rgba = image.image;
    if (texture.sampler >= 0 && size_t(texture.sampler) < model_.samplers.size()) {
      map->wrap_u = wrap_of(model_.samplers[size_t(texture.sampler)].wrapS);
      map->wrap_v = wrap_of(model_.samplers[size_t(texture.sampler)].wrapT);
    }
    return cached->second = std::move(map);
  }

  // glTF's nodes form trees: no node has two parents. A graph would be read
  // once along every path to a node, which a few hundred bytes can make
  // exponential; refused, the work is bounded by the file.
  void require_trees() const {
    std::vector<int> parent(model_.nodes.size(), -1);
    for (size_t n = 0; n < model_.nodes.size(); ++n)
      for (const int child : model_.nodes[n].children) {
        if (child < 0 || size_t(child) >= model_.nodes.size()) continue;  // said where it is read
        if (parent[size_t(child)] >= 0 && parent[size_t(child)] != int(n))
          fail("not a valid glTF 2.0 file: node " + std::to_string(child) + " has two parents (nodes " +
               std::to_string(parent[size_t(child)]) + " and " + std::to_string(n) + "); glTF's nodes form trees");
        parent[size_t(child)] = int(n);
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
  glm::dvec3 position_at(const tinygltf::Accessor& accessor, const unsigned char* p, const std::string& what) const {
    glm::dvec3 xyz;
    for (int k = 0; k < 3; ++k) {
      switch (accessor.componentType) {
        case TINYGLTF_COMPONENT_TYPE_FLOAT: xyz[k] = read_as<float>(p, k); break;
        case TINYGLTF_COMPONENT_TYPE_BYTE: xyz[k] = normalised(read_as<int8_t>(p, k), 127.0, accessor.normalized); break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: xyz[k] = normalised(read_as<uint8_t>(p, k), 255.0, accessor.normalized); break;
        case TINYGLTF_COMPONENT_TYPE_SHORT: xyz[k] = normalised(read_as<int16_t>(p, k), 32767.0, accessor.normalized); break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: xyz[k] = normalised(read_as<uint16_t>(p, k), 65535.0, accessor.normalized); break;
        default: fail(what + "'s POSITION must be floats, or bytes or shorts (KHR_mesh_quantization)");
      }
    }
    return xyz;
  }

  // The primitive's COLOR_0 (RGB, or RGBA read as RGB), one per point, into
  // soup_.point_colors from `first` on; floats or normalised unsigned bytes
  // or shorts, as glTF 2.0 allows. Points of primitives without colours are white.
  void add_colours(const tinygltf::Primitive& primitive, uint32_t first, size_t count, const std::string& what) {
    const auto colour = primitive.attributes.find("COLOR_0");
    if (colour == primitive.attributes.end()) {
      if (!soup_.point_colors.empty()) soup_.point_colors.resize(soup_.points.size(), glm::vec3(1.0f));
      return;
    }
    if (colour->second < 0 || size_t(colour->second) >= model_.accessors.size()) fail(what + "'s COLOR_0 accessor does not exist");
    const tinygltf::Accessor& accessor = model_.accessors[size_t(colour->second)];
    if (accessor.type != TINYGLTF_TYPE_VEC3 && accessor.type != TINYGLTF_TYPE_VEC4) fail(what + "'s COLOR_0 must be VEC3 or VEC4");
    if (accessor.count != count) fail(what + "'s COLOR_0 has " + std::to_string(accessor.count) + " colours for " +
                                      std::to_string(count) + " vertices");
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

  // The primitive's TEXCOORD_0, one per point, into point_uvs_ from `first`
  // on: floats, or (KHR_mesh_quantization) integers, normalised or not.
  // Points of primitives without it take (0, 0).
  void add_texture_coordinates(const tinygltf::Primitive& primitive, uint32_t first, size_t count, const std::string& what) {
    point_uvs_.resize(first, glm::vec2(0.0f));
    const auto uv = primitive.attributes.find("TEXCOORD_0");
    if (uv == primitive.attributes.end()) {
      point_uvs_.resize(first + count, glm::vec2(0.0f));
      return;
    }
    if (uv->second < 0 || size_t(uv->second) >= model_.accessors.size()) fail(what + "'s TEXCOORD_0 accessor does not exist");
    const tinygltf::Accessor& accessor = model_.accessors[size_t(uv->second)];
    if (accessor.type != TINYGLTF_TYPE_VEC2) fail(what + "'s TEXCOORD_0 must be VEC2");
    if (accessor.count != count) fail(what + "'s TEXCOORD_0 has " + std::to_string(accessor.count) + " coordinates for " +
                                      std::to_string(count) + " vertices");
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
        if (textured_) soup_.corner_uvs.insert(soup_.corner_uvs.end(), {point_uvs_[first + a], point_uvs_[first + b], point_uvs_[first + c]});
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
  const std::map<int, std::string>& image_failures_;  // why an image could not be decoded, by image
  const TextureMaps maps_;
  std::map<int, std::shared_ptr<const TextureImage>> textures_;  // by glTF texture
  bool textured_ = false;              // some material has a texture map: corners get texture coordinates
  std::vector<glm::vec2> point_uvs_;   // TEXCOORD_0 per point, while textured_
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

// What tinygltf would read wrongly or not name: glTF 1.0 (a GLB header of
// version 1, or dictionaries where 2.0 has arrays), compressed meshes, a
// mesh whose "primitives" is not an array (tinygltf reads none, silently).
void require_gltf_2(std::string_view bytes, bool binary, const std::string& path) {
  const auto refuse = [&](const std::string& message) { throw InputError({path, 0, 0}, message); };
  const std::string version_one =
      "glTF 1.0, which umbra does not read: only glTF 2.0 (convert it, with gltf-pipeline or Blender, say)";
  if (binary && bytes.size() >= 8) {
    uint32_t version = 0;
    std::memcpy(&version, bytes.data() + 4, 4);
    if (version == 1) refuse(version_one);
  }
  const std::string_view text = json_of(bytes, binary);
  const nlohmann::json json = nlohmann::json::parse(text.begin(), text.end(), nullptr, false);
  if (!json.is_object()) return;
  const auto version = json.find("asset");
  if (version != json.end() && version->is_object() && version->contains("version") && (*version)["version"].is_string() &&
      (*version)["version"].get<std::string>().substr(0, 2) == "1.")
    refuse(version_one);
  for (const char* key : {"meshes", "nodes", "accessors", "buffers", "bufferViews"})
    if (json.contains(key) && json[key].is_object()) refuse(version_one);
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

PolygonSoup read_gltf(std::string_view bytes, const std::string& path, TextureMaps maps) {
  tinygltf::TinyGLTF loader;
  std::map<int, std::string> image_failures;
  if (maps == TextureMaps::kRead) loader.SetImageLoader(decode_image, &image_failures);
  else loader.SetImageLoader(skip_image, nullptr);
  tinygltf::Model model;
  std::string error, warning;
  const std::string folder = std::filesystem::path(path).parent_path().string();
  const bool binary = bytes.substr(0, 4) == "glTF";
  if (bytes.size() > std::numeric_limits<unsigned>::max()) throw InputError({path, 0, 0}, "too large for the glTF reader (4 GiB or more)");
  require_gltf_2(bytes, binary, path);
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
  GltfReader(model, soup, image_failures, maps).read();
  return soup;
}

}  // namespace umbra
