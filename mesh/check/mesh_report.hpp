#pragma once
// What `umbra check` finds in one mesh file: a value type that the check
// fills and that prints itself as text or as one line of JSON.
//
// Counts are measured after merging points with equal coordinates (STL repeats
// every point; other files often do), and degenerate and duplicate faces are
// left out of the topology so that each defect is reported once.

#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>

#include "mesh/io/polygon_soup.hpp"
#include "mesh/topology/component_shape.hpp"

namespace umbra {

// A vertex or face as the file has it: its position in the file counting
// from 0, its line (0 in binary files), and where it is in the file's
// coordinates (a face: the mean of its distinct corners).
struct ElementRef {
  uint32_t index = 0;
  int line = 0;
  glm::dvec3 at{0.0};
};
using ElementPair = std::pair<ElementRef, ElementRef>;

struct ComponentReport {
  size_t faces = 0;
  size_t vertices = 0;
  size_t edges = 0;
  size_t border_edges = 0;
  size_t border_loops = 0;
  size_t non_manifold_edges = 0;       // three or more faces
  size_t non_manifold_vertices = 0;    // two or more fans of its own faces round one vertex, on no non-manifold edge
  size_t overlapping_diagonals = 0;    // polygons' diagonals, once triangulated, along another edge (component_shape.hpp)
  int64_t euler_characteristic = 0;    // V - E + F
  bool closed = false;                 // a closed 2-manifold: is_closed_2_manifold(shape())
  bool manifold = false;               // no non-manifold edge or vertex
  bool orientable = false;             // faces can be flipped to agree on every edge
  bool consistently_oriented = false;  // they already agree
  std::optional<int64_t> genus;        // manifold and orientable: (2 - chi - loops) / 2
  // Closed and orientable: do its faces (once they agree) point away from the
  // solid it bounds? Outward for a shell round solid; into the cavity for a
  // hollow solid's inner shell, whose volume is then negative.
  std::optional<bool> outward;
  // Closed and orientable: the volume its triangles enclose once their faces
  // agree, negative where they face into it (an inverted solid, or the inner
  // shell of a hollow one). (The JSON's "volume": not a shadow volume.)
  std::optional<double> enclosed_volume;
  // Closed and orientable, crossing none of its own faces, and enclosing
  // positive volume once turned as the renderer turns it (only where
  // `outward` is false): from outside its box its back faces are hidden
  // behind its front faces, and the renderer culls them. Shells that cross
  // each other may each be one; nesting plays no part.
  bool hides_back_faces = false;

  // Its faces as the renderer draws them: orientable ones flipped to agree.
  ComponentShape shape() const {
    return {border_edges, non_manifold_edges, non_manifold_vertices, orientable, overlapping_diagonals};
  }
  bool casts_from_silhouette() const { return umbra::casts_from_silhouette(shape()); }
};

struct SelfIntersectionReport {
  bool checked = false;   // false when the time limit is 0
  bool complete = false;  // false when the time limit stopped the search
  size_t face_pairs = 0;  // pairs of faces that intersect other than at shared vertices and edges
  double seconds = 0.0;
  double time_limit_seconds = 0.0;
};

// Which shadow volume the renderer gives a mesh, decided per component
// (casts_from_silhouette): from the silhouette of every component, by edge
// multiplicity for every component, or each component its own way.
enum class VolumeKind { kSilhouette, kEdgeMultiplicity, kMixed };
const char* volume_kind_name(VolumeKind kind);

// The JSON line for a file that could not be read: {"path": ..., "error": ...},
// valid UTF-8 as print_json's lines are.
std::string json_error_line(const std::string& path, const std::string& error);
// {"path": ..., "passed_over": why, "kind": kind}: a file found in a folder
// and not checked, in no format umbra reads ("unsupported-format").
std::string json_passed_over_line(const std::string& path, const std::string& why, const std::string& kind);

struct MeshReport {
  std::string path;
  std::string format;
  size_t file_vertices = 0;
  size_t file_faces = 0;          // as read: a polygon that revisits a vertex counts as the triangles it is split into (warnings say so)
  size_t triangles = 0;           // after triangulating polygons
  size_t vertices = 0;            // distinct positions used by a face
  size_t merged_vertices = 0;     // points that repeat an earlier point's coordinates
  size_t isolated_vertices = 0;   // distinct positions no face uses
  size_t edges = 0;
  size_t border_edges = 0;
  size_t border_loops = 0;
  size_t non_manifold_edges = 0;    // shared by more than two faces
  size_t non_manifold_vertices = 0; // faces around it form more than one fan, within a component or across components that touch there (vertices of non-manifold edges not counted)
  size_t duplicate_faces = 0;       // same vertices as an earlier face, in any order
  size_t degenerate_faces = 0;      // a repeated vertex, or all vertices on one line
  size_t inconsistent_edges = 0;    // two faces traverse the edge in the same direction
  size_t faces_to_flip = 0;         // the fewest flips that make every orientable component consistent
  size_t non_orientable_components = 0;
  size_t inward_components = 0;     // closed, orientable components that face into the solid they bound
  size_t undecided_components = 0;  // closed, orientable components whose facing has no sound answer (solid_orientation.hpp)
  int64_t euler_characteristic = 0;
  SelfIntersectionReport self_intersections;
  glm::dvec3 bbox_min{0.0}, bbox_max{0.0};
  double area = 0.0;  // of the triangles
  // The sum of the closed, orientable components' volumes (a hollow solid's
  // cavity takes its own away); none when no component is closed.
  std::optional<double> enclosed_volume;
  std::vector<ComponentReport> components;
  std::vector<ReadWarning> warnings;  // the reader's, for quirks it read past

  // Offending elements of each kind, to find them in the file: as many as
  // CheckOptions::max_examples says; the printed reports list the first
  // kMaxExamples.
  struct Examples {
    std::vector<ElementPair> border_edges;        // the edge's two vertices
    std::vector<ElementPair> non_manifold_edges;  // the edge's two vertices
    std::vector<ElementRef> non_manifold_vertices;
    std::vector<ElementPair> duplicate_faces;     // (face, the earlier face it repeats)
    std::vector<ElementRef> degenerate_faces;
    std::vector<ElementRef> faces_to_flip;
    std::vector<ElementPair> self_intersections;  // two faces
  } examples;
  static constexpr size_t kMaxExamples = 5;

  // A closed, consistently oriented 2-manifold without self-intersections or
  // degenerate or duplicate faces: it can cast its shadow from its silhouette.
  bool is_closed_manifold() const;
  // Why it is not, one short phrase per reason; empty when it is.
  std::vector<std::string> problems() const;
  // The problems that decide the shadow method: no faces, border, non-manifold
  // edges or vertices, orientation.
  std::vector<std::string> topology_problems() const;
  // The shadow method the renderer uses for this mesh, from its components'
  // (whether the faces agree on their orientation or not: it flips them to
  // agree first). None: edge multiplicity.
  VolumeKind volume_kind() const;
  size_t silhouette_components() const;
  // Every component hides its back faces (ComponentReport::hides_back_faces):
  // the renderer may cull the mesh's back faces.
  bool back_faces_hidden() const;
  // What loading the mesh for rendering changes, or "": "366 duplicate faces
  // dropped, 1234 faces flipped to agree".
  std::string loading_changes() const;
  // "closed 2-manifold: ..." or "not a closed 2-manifold (...): ..."
  std::string verdict() const;
  // The verdict's first words, without the reasons and the shadow: "closed
  // 2-manifold", "closed and consistently oriented, but not clean", "...,
  // not known to be clean", "not a closed 2-manifold" or "no faces".
  std::string verdict_head() const;
  // Why it is not a solid, as a printer or a simulation needs one: faces,
  // closed, manifold at every edge and vertex, consistently oriented, every
  // closed component facing outward, and no face crossing another (a
  // complete search). One plain phrase per reason; empty for a solid.
  std::vector<std::string> solid_problems() const;
  bool is_solid() const { return solid_problems().empty(); }
  // "solid", or "not a solid: " and each of solid_problems.
  std::string solid_verdict() const;

  void print_text(std::ostream& out) const;
  void print_json(std::ostream& out) const;  // one line, keys documented in docs/check.md
  // One line: "PATH: FORMAT, T triangles, C components: VERDICT", the
  // solid verdict where `solid` (umbra check --solid asks it).
  void print_brief(std::ostream& out, bool solid = false) const;
};

}  // namespace umbra
