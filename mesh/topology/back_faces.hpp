#pragma once
// Whether a mesh's back faces may be culled, as loading decides it for the
// renderer: the check's facing of its shells (solid_orientation.hpp), and
// the one question left that the picture answers more cheaply than a search.

#include <cstdint>

namespace umbra {

enum class BackFaces : uint8_t {
  // Some shell is open, faces into what it bounds, lies inside another, or
  // crosses its own faces: every face is drawn.
  kDrawn,
  // Every shell closed, facing out of the solid it bounds, and (a search
  // says) crossing none of its own faces: seen from outside the mesh's box,
  // no back face is ever nearer than a front face, so they are culled.
  kHidden,
  // As kHidden, except that no search asked whether a shell crosses itself:
  // only where one does can a back face be nearer than every front face. The
  // renderer culls them, then asks the picture whether any back face would
  // have shown (an occlusion query), and draws the mesh whole where one would.
  kHiddenUnlessSeen,
};

}  // namespace umbra
