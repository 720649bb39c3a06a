#pragma once
// `umbra check MESH --picture OUT.png`: the mesh staged as `umbra render`
// stages it, with what the check found drawn where it is: border edges,
// non-manifold edges and non-manifold vertices in colours of their own,
// thick enough to see at any size (fainter where a surface hides them),
// self-intersecting faces and faces to flip tinted, and a legend with the
// counts.

#include <array>
#include <cstdint>
#include <string>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "image/image.hpp"
#include "mesh/check/mesh_report.hpp"
#include "mesh/io/polygon_soup.hpp"
#include "render/headless_context.hpp"
#include "scene/mesh_placement.hpp"
#include "scene/scene.hpp"
#include "scene/staged_scene.hpp"

namespace umbra {

// What each kind of defect is drawn in.
struct DefectColours {
  static constexpr std::array<uint8_t, 3> kBorderEdge{235, 35, 35};
  static constexpr std::array<uint8_t, 3> kNonManifoldEdge{35, 95, 255};
  static constexpr std::array<uint8_t, 3> kNonManifoldVertex{210, 0, 210};
  static constexpr std::array<uint8_t, 3> kSelfIntersectingFace{255, 140, 0};
  static constexpr std::array<uint8_t, 3> kFaceToFlip{0, 175, 205};
};

class DefectPicture {
 public:
  // `soup` staged with its faces tinted by `report`, made with every
  // defect listed (CheckOptions::max_examples), in a picture `width` x
  // `height`; `own_up` is the up axis its format has (MeshFormat::up).
  // `view`: the staged camera's orbit (umbra check's --camera-azimuth, ...).
  // Throws InputError where the mesh cannot be staged (no faces).
  DefectPicture(const PolygonSoup& soup, const MeshReport& report, const std::string& own_up, int width, int height,
                const StageView& view = {});

  // Where the file's point `file_point` shows: x and y in pixels (x right,
  // y down, a pixel's centre at its index + 0.5), and its distance along the
  // camera's view axis.
  glm::dvec3 project(const glm::dvec3& file_point) const;

  // The picture, drawn on `gl`.
  Image draw(HeadlessGl gl) const;

 private:
  const MeshReport& report_;
  Scene scene_;
  MeshPlacement placed_;
  int width_, height_;
};

}  // namespace umbra
