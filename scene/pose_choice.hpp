#pragma once
// Which way up a staged mesh stands. Each format has its convention (+z up
// for STL and 3MF, +y for the others), but files often break it: a Y-up
// model exported to STL stands on its tail, a Z-up plan saved as OBJ on its
// side, and a flat part stands on its edge or lies face down. Where the convention
// plainly gives a pose that does not read, a better one is chosen from the
// geometry, and said.

#include <optional>
#include <string>

#include "scene/scene.hpp"

namespace umbra {

struct PoseChoice {
  std::string up;   // the file's axis to stand up: "+x" ... "-z"
  std::string why;  // why, for the staged scene's text (--explain): "it is flat and would lie flat, ..."
};

// For `mesh`, loaded fitted with its file's axis `format_up` turned to +z
// (the stage's up), a better up axis, or none when the convention's pose
// reads. It reads unless:
// - the model is flat (its thinnest side under 2% of its longest) and does
//   not lie flat with its face up: it is laid flat, its face up, so that the
//   camera sees its face, as it sees a plate's that lies flat as it is. Its
//   face is the side its textured faces turn to (`materials` are the mesh's
//   scene's), else the side a one-sided model's faces turn to, else, for one
//   that stood, the side most of its triangles turn to, else the side the
//   camera saw;
// - the model was plainly built standing on another axis: its lowest point
//   is at 0 along that axis and not along the convention's (a plan drawn on
//   z = 0, a figure on y = 0), and it stands there on a footprint at least
//   1.5 times as large; a panel whose face (its textured faces', or a
//   one-sided model's) plainly turns the other way, down into the floor,
//   stands on its back instead.
std::optional<PoseChoice> better_pose(const Mesh& mesh, const std::string& format_up, const std::vector<Material>& materials);

// Whether `mesh` (on the stage) lies low: its height under a tenth of its
// footprint's shorter side, as a plate lying flat, whatever its thickness.
// The default camera sees it from higher up, so that its face reads.
bool lies_low(const Mesh& mesh);

// How much of the box `mesh` shows a camera looking along `direction` (a
// unit vector) its faces cover, from 0 to 1: 0.39 for CGAL's diplodocus and
// 0.22 for a lamp post, spindly; 0.6 to 0.8 for a bunny, a torus, a sphere
// or a box. Counted on a 64 x 64 grid over that box: the cells whose centres a
// face covers, and the cell of each face's centroid (a face smaller than a
// cell covers no centre), of up to 2^16 faces spread over the mesh (a finer
// mesh has hundreds of faces to a cell).
double silhouette_fill(const Mesh& mesh, const glm::dvec3& direction);

// For a flat model standing upright (as --up may stand it), the turn about the stage's up (in
// degrees) of the default camera and light that puts both on the side its
// faces turn to (by area; the stage's front, -y, when they turn neither
// way), the camera seeing its face as it sees a model's front. Flat is thin
// along a stage axis, or thin across a slanted plane of its own that most of
// its area faces (a panel turned about the vertical, or tilted: the camera
// then turned to the side its upper face looks to). None for a model that
// is not flat, or lies level, whose front is the stage's.
std::optional<double> view_turn_facing(const Mesh& mesh);

}  // namespace umbra
