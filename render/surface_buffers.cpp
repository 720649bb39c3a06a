#include "render/surface_buffers.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "mesh/predicates/orientation.hpp"
#include "render/gl.hpp"
#include "render/shaders.hpp"
#include "scene/terminator.hpp"

namespace umbra {
namespace {

// A mesh triangle's three corners' values (colours, texture coordinates),
// written at its place `at` among the buffer's triangles; nothing for a mesh
// without them, whose triangles keep the buffer's filling.
template <typename Corner>
void put_corners(std::vector<float>& buffer, size_t at, const std::vector<std::array<Corner, 3>>& corners, size_t t) {
  if (corners.empty()) return;
  constexpr size_t kFloats = sizeof(Corner) / sizeof(float);
  float* out = buffer.data() + at * 3 * kFloats;
  for (const Corner& c : corners[t])
    for (size_t k = 0; k < kFloats; ++k) *out++ = c[glm::length_t(k)];
}

// Vertex attribute `index`, `components` floats a vertex: from `values` in a
// buffer of its own (`vbo`), or where there are none, `constant` in every
// component for every vertex, with no memory spent.
void per_vertex_attribute(GLuint index, int components, const std::vector<float>& values, float constant, unsigned& vbo) {
  if (values.empty()) {
    glVertexAttrib4f(index, constant, constant, constant, 1.0f);
    return;
  }
  glGenBuffers(1, &vbo);
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(values.size() * sizeof(float)), values.data(), GL_STATIC_DRAW);
  glVertexAttribPointer(index, components, GL_FLOAT, GL_FALSE, GLsizei(components * sizeof(float)), nullptr);
  glEnableVertexAttribArray(index);
}

}  // namespace

SurfaceBuffers::SurfaceBuffers(const Scene& scene) {
  // The scene's triangles and every mesh's, grouped by material and by
  // whether they belong to a closed mesh, one draw call per group; flat
  // normals, as the shadows are flat-faced.
  // Sorted as runs (a scene triangle, a whole mesh, or a mesh's triangles of
  // one material) rather than triangle by triangle: a million-triangle mesh
  // is one run, copied once.
  // Kept (runs_, with the meshes' per-material subsets they point into), for
  // use_light to walk the triangles in the buffer's order.
  std::vector<Run>& runs = runs_;
  std::vector<std::map<int, std::vector<uint32_t>>>& by_material = mesh_subsets_;
  by_material.resize(scene.meshes.size());
  size_t& triangle_count = triangle_count_;
  triangle_count = scene.triangles.size();
  for (const Triangle& t : scene.triangles) runs.push_back({t.material, nullptr, &t, nullptr, nullptr});
  for (size_t k = 0; k < scene.meshes.size(); ++k) {
    const Mesh& mesh = scene.meshes[k];
    const Mesh* closed = mesh.back_faces != BackFaces::kDrawn ? &mesh : nullptr;
    triangle_count += mesh.triangles.size();
    if (mesh.triangle_materials.empty()) {
      runs.push_back({mesh.material, closed, nullptr, &mesh, nullptr});
      continue;
    }
    for (uint32_t t = 0; t < mesh.triangles.size(); ++t) by_material[k][mesh.triangle_materials[t]].push_back(t);
    for (const auto& [material, triangles] : by_material[k]) runs.push_back({material, closed, nullptr, &mesh, &triangles});
  }
  GLint most_codes = 0;  // the GL promises 65,536; llvmpipe holds 2^27, as NVIDIA's GPUs commonly do
  glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &most_codes);
  if (triangle_count > size_t(most_codes))
    throw std::runtime_error("the scene has " + std::to_string(triangle_count) + " triangles, more than the " +
                             std::to_string(most_codes) + " this GL's texture buffers hold (one light code a triangle)");
  const auto back_faces_of = [](const Run& run) { return run.closed_mesh ? run.closed_mesh->back_faces : BackFaces::kDrawn; };
  std::stable_sort(runs.begin(), runs.end(), [&](const Run& a, const Run& b) {
    return a.material != b.material ? a.material < b.material : back_faces_of(a) < back_faces_of(b);
  });
  // Each triangle's three vertices (position xyz, normal xyz) written at its
  // place straight into the GL's buffer, mapped, on every core: no copy of
  // our own to fault in and hand over (345 MB at 4.8M triangles).
  constexpr size_t kFloatsPerTriangle = 18;
  const GLsizeiptr bytes = GLsizeiptr(triangle_count * kFloatsPerTriangle * sizeof(float));
  glGenVertexArrays(1, &triangle_vao_);
  glGenBuffers(1, &triangle_vbo_);
  glBindVertexArray(triangle_vao_);
  glBindBuffer(GL_ARRAY_BUFFER, triangle_vbo_);
  glBufferData(GL_ARRAY_BUFFER, bytes, nullptr, GL_STATIC_DRAW);
  float* const data = bytes == 0 ? nullptr
                                 : static_cast<float*>(glMapBufferRange(GL_ARRAY_BUFFER, 0, bytes,
                                                                        GL_MAP_WRITE_BIT | GL_MAP_INVALIDATE_BUFFER_BIT));
  if (bytes != 0 && !data) throw std::runtime_error("the GL could not map a vertex buffer of " + std::to_string(bytes) + " bytes");
  const auto put = [data](size_t at, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    const glm::dvec3 n = glm::cross(b - a, c - a);  // flipped toward the eye in the shader
    float* out = data + at * kFloatsPerTriangle;
    for (const glm::dvec3* p : {&a, &b, &c}) {
      *out++ = float(p->x), *out++ = float(p->y), *out++ = float(p->z);
      *out++ = float(n.x), *out++ = float(n.y), *out++ = float(n.z);
    }
  };
  // Vertex colours, when some mesh has them: a second buffer in the same
  // order, white for every other triangle. Without it, attribute 2 is the
  // constant white, and no memory is spent.
  const bool coloured = std::any_of(scene.meshes.begin(), scene.meshes.end(), [](const Mesh& m) { return !m.triangle_colors.empty(); });
  std::vector<float> colours(coloured ? triangle_count * 9 : 0, 1.0f);
  // Texture coordinates likewise, when some mesh has them; (0, 0) elsewhere,
  // where no texture is sampled.
  const bool textured = std::any_of(scene.meshes.begin(), scene.meshes.end(), [](const Mesh& m) { return !m.triangle_uvs.empty(); });
  std::vector<float> uvs(textured ? triangle_count * 6 : 0, 0.0f);
  // Shading normals likewise, when some mesh is smooth; (0, 0, 0), flat, elsewhere.
  const bool smooth = std::any_of(scene.meshes.begin(), scene.meshes.end(), [](const Mesh& m) { return !m.triangle_normals.empty(); });
  std::vector<float> normals(smooth ? triangle_count * 9 : 0, 0.0f);
  size_t placed = 0;  // triangles laid out so far
  for (Run& run : runs) {
    run.first = placed;
    const bool closed = run.closed_mesh != nullptr;
    if (groups_.empty() || groups_.back().material != run.material || groups_.back().back_faces != back_faces_of(run)) {
      groups_.push_back({run.material, back_faces_of(run), glm::dvec3(0.0), glm::dvec3(0.0), int(3 * placed), 0});
      if (closed) groups_.back().closed_lo = run.closed_mesh->bounds_min, groups_.back().closed_hi = run.closed_mesh->bounds_max;
    }
    TriangleGroup& group = groups_.back();
    if (closed)
      group.closed_lo = glm::min(group.closed_lo, run.closed_mesh->bounds_min), group.closed_hi = glm::max(group.closed_hi, run.closed_mesh->bounds_max);
    if (run.triangle) {
      put(placed++, run.triangle->a, run.triangle->b, run.triangle->c);
      group.vertex_count += 3;
      continue;
    }
    const std::vector<glm::dvec3>& p = run.mesh->positions;
    const auto& triangles = run.mesh->triangles;
    const size_t count = run.subset ? run.subset->size() : triangles.size();
    // Isolated: while it waits for its share, this thread takes none of the
    // other work under way (umbra render makes the plan meanwhile).
    tbb::this_task_arena::isolate([&] {
      tbb::parallel_for(tbb::blocked_range<size_t>(0, count, 16384), [&, first = placed](const tbb::blocked_range<size_t>& r) {
        for (size_t i = r.begin(); i < r.end(); ++i) {
          const size_t k = run.subset ? (*run.subset)[i] : i;
          const auto& t = triangles[k];
          put(first + i, p[t[0]], p[t[1]], p[t[2]]);
          if (coloured) put_corners(colours, first + i, run.mesh->triangle_colors, k);
          if (textured) put_corners(uvs, first + i, run.mesh->triangle_uvs, k);
          if (smooth) put_corners(normals, first + i, run.mesh->triangle_normals, k);
        }
      });
    });
    placed += count;
    group.vertex_count += 3 * int(count);
  }
  back_faces_seen_.assign(groups_.size(), 0);
  if (data && glUnmapBuffer(GL_ARRAY_BUFFER) != GL_TRUE)
    throw std::runtime_error("the GL lost the vertex buffer's contents while it was mapped");
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), nullptr);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), reinterpret_cast<void*>(3 * sizeof(float)));
  glEnableVertexAttribArray(0);
  glEnableVertexAttribArray(1);
  per_vertex_attribute(2, 3, colours, 1.0f, color_vbo_);
  per_vertex_attribute(3, 2, uvs, 0.0f, uv_vbo_);
  per_vertex_attribute(5, 3, normals, 0.0f, normal_vbo_);
  upload_textures(scene);

  const float corners[] = {-1, -1, -1, 1, -1, -1, 1, 1, -1, -1, 1, -1, -1, -1, 1, 1, -1, 1, 1, 1, 1, -1, 1, 1};
  const unsigned faces[] = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                            3, 6, 2, 3, 7, 6, 0, 4, 7, 0, 7, 3, 1, 2, 6, 1, 6, 5};  // outward
  glGenVertexArrays(1, &box_vao_);
  glGenBuffers(1, &box_vbo_);
  glGenBuffers(1, &box_ibo_);
  glBindVertexArray(box_vao_);
  glBindBuffer(GL_ARRAY_BUFFER, box_vbo_);
  glBufferData(GL_ARRAY_BUFFER, sizeof corners, corners, GL_STATIC_DRAW);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, box_ibo_);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof faces, faces, GL_STATIC_DRAW);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float), nullptr);
  glEnableVertexAttribArray(0);
  glBindVertexArray(0);
}

SurfaceBuffers::~SurfaceBuffers() {
  const GLuint buffers[] = {triangle_vbo_, box_vbo_, box_ibo_, color_vbo_, uv_vbo_, normal_vbo_};
  glDeleteBuffers(6, buffers);
  for (const LightSides& sides : light_sides_) {
    glDeleteBuffers(1, &sides.buffer);
    glDeleteTextures(1, &sides.texture);
  }
  const GLuint arrays[] = {triangle_vao_, box_vao_};
  glDeleteVertexArrays(2, arrays);
  glDeleteTextures(GLsizei(textures_.size()), textures_.data());
  glDeleteQueries(GLsizei(queries_.size()), queries_.data());
}

// Each material's texture map, once (materials may share one), for the
// triangle shader to filter (shaders.hpp).
void SurfaceBuffers::upload_textures(const Scene& scene) {
  textures_.assign(scene.materials.size(), 0);
  std::map<const TextureImage*, GLuint> uploaded;
  GLint largest = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &largest);
  for (size_t m = 0; m < scene.materials.size(); ++m) {
    const TextureImage* image = scene.materials[m].texture.get();
    if (!image) continue;
    if (const auto it = uploaded.find(image); it != uploaded.end()) {
      textures_[m] = it->second;
      continue;
    }
    if (image->width > largest || image->height > largest)
      throw std::runtime_error("texture map " + image->name + " is " + std::to_string(image->width) + "x" +
                               std::to_string(image->height) + ", larger than the GL's " + std::to_string(largest) +
                               "x" + std::to_string(largest));
    GLuint texture = 0;
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, image->width, image->height, 0, GL_RGBA, GL_UNSIGNED_BYTE, image->rgba.data());
    // The shader filters and wraps (texelFetch); a single level needs a
    // filter without mipmaps to be complete.
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    textures_[m] = uploaded[image] = texture;
  }
  glBindTexture(GL_TEXTURE_2D, 0);
}

void SurfaceBuffers::use_light(size_t light, const glm::dvec3& position) {
  if (triangle_count_ == 0) return;
  if (light_sides_.size() <= light) light_sides_.resize(light + 1);
  LightSides& sides = light_sides_[light];
  glActiveTexture(GL_TEXTURE0 + shaders::kLightCodeUnit);
  if (!sides.position || *sides.position != position) {
    write_light_codes(position);
    if (sides.buffer == 0) glGenBuffers(1, &sides.buffer);
    glBindBuffer(GL_TEXTURE_BUFFER, sides.buffer);
    glBufferData(GL_TEXTURE_BUFFER, GLsizeiptr(light_codes_.size()), light_codes_.data(), GL_DYNAMIC_DRAW);
    glBindBuffer(GL_TEXTURE_BUFFER, 0);
    if (sides.texture == 0) {
      glGenTextures(1, &sides.texture);
      glBindTexture(GL_TEXTURE_BUFFER, sides.texture);
      glTexBuffer(GL_TEXTURE_BUFFER, GL_R8UI, sides.buffer);  // stays attached while the buffer's data is replaced
    }
    sides.position = position;
  }
  glBindTexture(GL_TEXTURE_BUFFER, sides.texture);
  glActiveTexture(GL_TEXTURE0 + shaders::kMaterialTextureUnit);
}

void SurfaceBuffers::write_light_codes(const glm::dvec3& position) {
  // Per triangle, its side of the light plus one (bits 0 and 1), and for a
  // smooth mesh, bit 2 where it is on the terminator, where its normals
  // rather than its faces say where the light ends (terminator.hpp).
  light_codes_.resize(triangle_count_);
  uint8_t* const codes = light_codes_.data();
  const auto code = [](int side, uint8_t on_terminator) { return uint8_t((side + 1) | on_terminator << 2); };
  // A smooth mesh's sides and terminator, worked out whole, once for all its
  // runs: the terminator needs the sides round each point. A flat mesh's
  // sides are worked out below, each triangle in the one run that holds it.
  struct SmoothSides {
    std::vector<int8_t> sides;
    std::vector<uint8_t> terminator;
  };
  std::map<const Mesh*, SmoothSides> smooth;
  for (const Run& run : runs_) {
    if (run.triangle) {
      const Triangle& t = *run.triangle;
      codes[run.first] = code(orientation(t.a, t.b, t.c, position), 0);
      continue;
    }
    const Mesh& mesh = *run.mesh;
    const SmoothSides* known = nullptr;
    if (!mesh.triangle_normals.empty()) {
      auto [found, first_run] = smooth.try_emplace(&mesh);
      if (first_run) {
        found->second.sides = triangle_light_sides(mesh, position);
        found->second.terminator = terminator_triangles(mesh, found->second.sides);
      }
      known = &found->second;
    }
    const std::vector<glm::dvec3>& p = mesh.positions;
    const size_t count = run.subset ? run.subset->size() : mesh.triangles.size();
    // Isolated: while it waits for its share, this thread takes none of the
    // other work under way (umbra render makes the plan meanwhile).
    tbb::this_task_arena::isolate([&] {
      tbb::parallel_for(tbb::blocked_range<size_t>(0, count, 16384), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t i = r.begin(); i < r.end(); ++i) {
          const size_t k = run.subset ? (*run.subset)[i] : i;
          const auto& t = mesh.triangles[k];
          codes[run.first + i] = known ? code(known->sides[k], known->terminator[k])
                                       : code(orientation(p[t[0]], p[t[1]], p[t[2]], position), 0);
        }
      });
    });
  }
}

unsigned SurfaceBuffers::material_texture(int material) const {
  return size_t(material) < textures_.size() ? textures_[size_t(material)] : 0;
}

bool SurfaceBuffers::culls(const TriangleGroup& group, const std::optional<glm::dvec3>& viewpoint) const {
  if (!viewpoint) return false;
  const bool outside = glm::any(glm::lessThan(*viewpoint, group.closed_lo)) || glm::any(glm::greaterThan(*viewpoint, group.closed_hi));
  const bool seen = back_faces_seen_[size_t(&group - groups_.data())];
  return outside && (group.back_faces == BackFaces::kHidden || (group.back_faces == BackFaces::kHiddenUnlessSeen && !seen));
}

bool SurfaceBuffers::culls_on_trust(const TriangleGroup& group, const std::optional<glm::dvec3>& viewpoint) const {
  return group.back_faces == BackFaces::kHiddenUnlessSeen && culls(group, viewpoint);
}

void SurfaceBuffers::ask_whether_back_faces_show(const TriangleGroup& group, DrawPacing& pacing) {
  if (asked_ == queries_.size()) {
    queries_.push_back(0);
    glGenQueries(1, &queries_.back());
    asked_group_.push_back(0);
  }
  asked_group_[asked_] = size_t(&group - groups_.data());
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1.0f, 4.0f);  // a slope's worth and a few units of depth, as the volumes' caps are pushed
  glEnable(GL_CULL_FACE);
  glCullFace(GL_FRONT);
  glBeginQuery(GL_ANY_SAMPLES_PASSED, queries_[asked_++]);
  draw_triangles(group, pacing);
  glEndQuery(GL_ANY_SAMPLES_PASSED);
  glDisable(GL_POLYGON_OFFSET_FILL);
}

bool SurfaceBuffers::back_faces_showed() {
  bool shown = false;
  for (size_t k = 0; k < asked_; ++k) {
    GLuint passed = 0;
    glGetQueryObjectuiv(queries_[k], GL_QUERY_RESULT, &passed);
    if (passed) back_faces_seen_[asked_group_[k]] = 1, shown = true;
  }
  asked_ = 0;
  return shown;
}

void SurfaceBuffers::draw_triangle_group(const TriangleGroup& group, const std::optional<glm::dvec3>& viewpoint,
                                         DrawPacing& pacing) const {
  if (culls(group, viewpoint)) {
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
  }
  draw_triangles(group, pacing);
}

void SurfaceBuffers::draw_triangles(const TriangleGroup& group, DrawPacing& pacing) const {
  glBindVertexArray(triangle_vao_);
  pacing.draw(size_t(group.vertex_count / 3), [&](size_t first, size_t count) {
    const GLint first_vertex = group.first_vertex + GLint(3 * first);
    // Mesa's llvmpipe (lp_setup_analyse_triangles, a fast path for one
    // Windows compositor) treats a draw of exactly 9 vertices whose last
    // triangle is level on screen (all three at one window y, as a triangle
    // whose plane holds the eye is) as a rectangle, and draws nothing when
    // the first two do not make one. So 3 triangles are drawn as 2 + 1.
    if (count == 3) {
      glDrawArrays(GL_TRIANGLES, first_vertex, 6);
      glDrawArrays(GL_TRIANGLES, first_vertex + 6, 3);
    } else {
      glDrawArrays(GL_TRIANGLES, first_vertex, GLsizei(3 * count));
    }
  });
  glDisable(GL_CULL_FACE);
}

void SurfaceBuffers::draw_sphere_box() const {
  // Back faces only: they cover the sphere whether the eye is outside the box or in it.
  glEnable(GL_CULL_FACE);
  glCullFace(GL_FRONT);
  glBindVertexArray(box_vao_);
  glDrawElements(GL_TRIANGLES, 36, GL_UNSIGNED_INT, nullptr);
  glDisable(GL_CULL_FACE);
}

VolumeBuffer::VolumeBuffer() {
  glGenVertexArrays(1, &vao_);
  glGenBuffers(1, &vbo_);
  glGenBuffers(1, &ibo_);
  glBindVertexArray(vao_);
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ibo_);
  glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, 4 * sizeof(float), nullptr);
  glEnableVertexAttribArray(0);
  glBindVertexArray(0);
}

VolumeBuffer::~VolumeBuffer() {
  const GLuint buffers[] = {vbo_, ibo_};
  glDeleteBuffers(2, buffers);
  glDeleteVertexArrays(1, &vao_);
}

void VolumeBuffer::upload_vertices(const std::vector<float>& xyzw, unsigned usage) {
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(xyzw.size() * sizeof(float)), xyzw.data(), usage);
}

void VolumeBuffer::upload_indices(const uint32_t* indices, size_t count) {
  glBindVertexArray(vao_);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(count * sizeof(uint32_t)), indices, GL_STREAM_DRAW);
  glBindVertexArray(0);
  index_count_ = int(count);
}

void VolumeBuffer::upload(const ShadowVolume& volume) {
  std::vector<float> vertices;
  vertices.reserve(volume.vertices.size() * 4);
  for (const glm::dvec4& v : volume.vertices) vertices.insert(vertices.end(), {float(v.x), float(v.y), float(v.z), float(v.w)});
  upload_vertices(vertices, GL_STREAM_DRAW);
  upload_indices(volume.triangles.empty() ? nullptr : volume.triangles[0].data(), volume.triangles.size() * 3);
}

void VolumeBuffer::upload_mesh_vertices(const std::vector<glm::dvec3>& positions) {
  std::vector<float> vertices;
  vertices.reserve(positions.size() * 8);
  for (float w : {1.0f, 0.0f})
    for (const glm::dvec3& p : positions) vertices.insert(vertices.end(), {float(p.x), float(p.y), float(p.z), w});
  upload_vertices(vertices, GL_STATIC_DRAW);
}

void VolumeBuffer::draw(DrawPacing& pacing) const {
  if (index_count_ == 0) return;
  glBindVertexArray(vao_);
  pacing.draw(size_t(index_count_ / 3), [](size_t first, size_t count) {
    glDrawElements(GL_TRIANGLES, GLsizei(3 * count), GL_UNSIGNED_INT,
                   reinterpret_cast<const void*>(3 * first * sizeof(uint32_t)));
  });
}

}  // namespace umbra
