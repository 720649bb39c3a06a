#pragma once
// GPU buffers for what the scene draws: the triangles (flat normals, grouped
// by material), a box that sphere fragments are ray-cast from, and shadow
// volumes: those of spheres and triangles re-uploaded each frame as the light
// moves, those of meshes with static vertices and per-frame indices.

#include <cstdint>
#include <map>
#include <optional>
#include <vector>

#include "render/draw_pacing.hpp"
#include "scene/scene.hpp"
#include "silhouette/shadow_volume.hpp"

namespace umbra {

class SurfaceBuffers {
 public:
  explicit SurfaceBuffers(const Scene& scene);
  ~SurfaceBuffers();
  SurfaceBuffers(const SurfaceBuffers&) = delete;
  SurfaceBuffers& operator=(const SurfaceBuffers&) = delete;

  struct TriangleGroup {
    int material = 0;
    // Its meshes' Mesh::back_faces: where not kDrawn, their back faces are
    // culled when seen from outside the box [closed_lo, closed_hi] round them.
    BackFaces back_faces = BackFaces::kDrawn;
    glm::dvec3 closed_lo{0.0}, closed_hi{0.0};
    int first_vertex = 0;
    int vertex_count = 0;
  };
  const std::vector<TriangleGroup>& triangle_groups() const { return groups_; }
  // Seen from `viewpoint` (the eye, or the light for a shadow map; none where
  // the rays start from no one point outside every box, which culls
  // nothing): a closed group's back faces are culled when the viewpoint is
  // outside its box, where
  // they are never visible (and where rasterisation lets one show at an
  // outline pixel, two-sided shading would paint it unlit); from inside, as
  // when a viewer zooms into a mesh, they are drawn.
  // They are sent through `pacing`.
  void draw_triangle_group(const TriangleGroup& group, const std::optional<glm::dvec3>& viewpoint, DrawPacing& pacing) const;
  // Where `group`'s back faces are culled on trust (BackFaces::kHiddenUnlessSeen)
  // from `viewpoint`, with every surface's depth already drawn: asks whether
  // one would show. Its back faces are drawn a little behind where they are
  // (a polygon offset, which a back face folded against a front face along
  // a silhouette edge never beats), with the depth test and no writes, under
  // an occlusion query. Only where culls_on_trust, with a program that
  // places the triangles as the triangle shader does.
  bool culls_on_trust(const TriangleGroup& group, const std::optional<glm::dvec3>& viewpoint) const;
  void ask_whether_back_faces_show(const TriangleGroup& group, DrawPacing& pacing);
  // The answers to every question asked since last time, waiting for them:
  // whether some back face showed. Where one did, a shell crosses itself in
  // sight, and its group is drawn whole from then on.
  bool back_faces_showed();
  void draw_sphere_box() const;
  // Light `light`, at `position`, for the triangles drawn next: each
  // triangle's exact side of it (the orientation predicate), for the shader
  // to light a face only from the side the light is on. Worked out once per
  // position of each light, on every core.
  void use_light(size_t light, const glm::dvec3& position);
  // Material `material`'s texture map as a GL texture, or 0 when it has none.
  unsigned material_texture(int material) const;

 private:
  void upload_textures(const Scene& scene);

  // Where the buffer's triangles come from, in its order: a scene triangle,
  // or a mesh's triangles (all, or those listed in `subset`).
  struct Run {
    int material;
    const Mesh* closed_mesh;  // the mesh it is, if its back faces are ever culled
    const Triangle* triangle;
    const Mesh* mesh;
    const std::vector<uint32_t>* subset;  // into mesh_subsets_
    size_t first = 0;  // its first triangle's place in the buffer
  };
  std::vector<Run> runs_;
  std::vector<std::map<int, std::vector<uint32_t>>> mesh_subsets_;  // per mesh, its triangles of each material
  size_t triangle_count_ = 0;
  // Each triangle's light code for `position` (write_light_codes), into
  // light_codes_, in the buffer's order.
  void write_light_codes(const glm::dvec3& position);
  // Per light: the position whose codes `buffer` holds, one byte a
  // triangle, which the vertex shader reads through `texture` (a texture
  // buffer) at its triangle, gl_VertexID / 3: a third of the bytes of an
  // attribute per vertex to send each time the light moves.
  struct LightSides {
    std::optional<glm::dvec3> position;  // none until first written
    unsigned buffer = 0, texture = 0;
  };
  std::vector<LightSides> light_sides_;
  std::vector<uint8_t> light_codes_;  // kept so that a moving light allocates nothing

  std::vector<TriangleGroup> groups_;
  std::vector<uint8_t> back_faces_seen_;  // per group: some showed, so it is drawn whole
  bool culls(const TriangleGroup& group, const std::optional<glm::dvec3>& viewpoint) const;
  void draw_triangles(const TriangleGroup& group, DrawPacing& pacing) const;  // with the culling as it is set
  // Occlusion queries, made as needed and kept; the first `asked_` are
  // waiting for their answers, each about group `asked_group_[k]`.
  std::vector<unsigned> queries_;
  std::vector<size_t> asked_group_;
  size_t asked_ = 0;
  unsigned triangle_vao_ = 0, triangle_vbo_ = 0;
  unsigned color_vbo_ = 0;  // per vertex, parallel to triangle_vbo_; only when some mesh has vertex colours
  unsigned uv_vbo_ = 0;     // likewise, texture coordinates; only when some mesh has them
  unsigned normal_vbo_ = 0;  // likewise, shading normals; only when some mesh is smooth
  std::vector<unsigned> textures_;  // per material: its texture map, or 0
  unsigned box_vao_ = 0, box_vbo_ = 0, box_ibo_ = 0;
};

class VolumeBuffer {
 public:
  VolumeBuffer();
  ~VolumeBuffer();
  VolumeBuffer(const VolumeBuffer&) = delete;
  VolumeBuffer& operator=(const VolumeBuffer&) = delete;

  // A volume's vertices and triangles, for one frame.
  void upload(const ShadowVolume& volume);
  // A mesh's volume vertices, once: its N points with w = 1, then the same N
  // points with w = 0, which the volume shader moves to infinity away from
  // the light. Each frame then sends only upload_indices.
  void upload_mesh_vertices(const std::vector<glm::dvec3>& positions);
  void upload_indices(const uint32_t* indices, size_t count);
  void draw(DrawPacing& pacing) const;

 private:
  void upload_vertices(const std::vector<float>& xyzw, unsigned usage);

  unsigned vao_ = 0, vbo_ = 0, ibo_ = 0;
  int index_count_ = 0;
};

}  // namespace umbra
