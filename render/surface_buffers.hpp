#pragma once
// GPU buffers for what the scene draws: the triangles (flat normals, grouped
// by material), a box that sphere fragments are ray-cast from, and the
// shadow volumes of one light, re-uploaded each frame as the light moves.

#include <vector>

#include "mesh/scene.hpp"
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
    int first_vertex = 0;
    int vertex_count = 0;
  };
  const std::vector<TriangleGroup>& triangle_groups() const { return groups_; }
  void draw_triangle_group(const TriangleGroup& group) const;
  void draw_sphere_box() const;

 private:
  std::vector<TriangleGroup> groups_;
  unsigned triangle_vao_ = 0, triangle_vbo_ = 0;
  unsigned box_vao_ = 0, box_vbo_ = 0, box_ibo_ = 0;
};

class VolumeBuffer {
 public:
  VolumeBuffer();
  ~VolumeBuffer();
  VolumeBuffer(const VolumeBuffer&) = delete;
  VolumeBuffer& operator=(const VolumeBuffer&) = delete;

  void upload(const ShadowVolume& volume);
  void draw() const;

 private:
  unsigned vao_ = 0, vbo_ = 0, ibo_ = 0;
  int index_count_ = 0;
};

}  // namespace umbra
