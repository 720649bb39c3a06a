// Back faces of a closed mesh are culled only where culling is provably
// invisible: every shell closed, crossing none of its own faces, and
// enclosing positive volume as drawn. Where every shell faces out as
// loaded, whether one crosses itself is left to the picture
// (BackFaces::kHiddenUnlessSeen); where one must be turned, a search decides.
// Two shells that cross each other are culled as they are, neither turned; a
// shell whose walls cross (a lobe turned inside out) is drawn whole once its
// back faces show; either way the picture is the ray-cast reference's. A
// caller drawing many views searches once instead of asking at each.
#include <gtest/gtest.h>

#include "scene/mesh_loader.hpp"
#include "scene/scene_parser.hpp"
#include "tests/mesh/mesh_builders.hpp"
#include "tests/render/image_agreement.hpp"
#include "tests/render/mask_comparison.hpp"
#include "tests/scratch_folder.hpp"

namespace umbra {
namespace {

class ShellCulling : public test::ScratchFolder {
 protected:
  // The mesh fitted into the cube over a floor, seen from a raised corner.
  Scene scene_of(const PolygonSoup& soup) {
    write("shells.obj", test::obj_text(soup));
    return parse_scene_text("light 1.5 -2 3\n"
                            "triangle -1 -1 -1  1 -1 -1  1 1 -1\ntriangle -1 -1 -1  1 1 -1  -1 1 -1\n"
                            "mesh shells.obj fit\n"
                            "camera eye 2.2 -2.6 2.4 target 0 0 -0.3 up 0 0 1 fovy 45\n",
                            (folder_ / "t.scene").string());
  }
};

TEST_F(ShellCulling, CrossingShellsAreCulledAsTheyAreNotTurned) {
  const Scene scene = scene_of(test::box_through_l_prism());
  // Were they not to cross, the box would lie in the prism: a search decides.
  EXPECT_EQ(scene.meshes[0].back_faces, BackFaces::kHidden);
  test::expect_images_agree(scene, test::render_gl_and_ray_cast(scene, 120));
}

TEST_F(ShellCulling, AShellWithAnInsideOutLobeIsDrawnWhole) {
  const Scene scene = scene_of(test::bow_tie_prism());
  EXPECT_EQ(scene.meshes[0].back_faces, BackFaces::kHiddenUnlessSeen);  // the picture finds the lobe
  test::expect_images_agree(scene, test::render_gl_and_ray_cast(scene, 120));
  test::expect_masks_match_reference(scene, 120, 120, 48);
  test::expect_images_agree(scene, test::render_gl_and_ray_cast(scene, 120, RenderMethod::kShadowMap));
}

TEST_F(ShellCulling, ACleanSolidIsCulledAndAnInwardOneTurnedFirst) {
  const Scene clean = scene_of(test::unit_cube());
  EXPECT_EQ(clean.meshes[0].back_faces, BackFaces::kHiddenUnlessSeen);
  test::expect_images_agree(clean, test::render_gl_and_ray_cast(clean, 120));
  const Scene inward = scene_of(test::all_reversed(test::unit_cube()));  // searched, then turned
  EXPECT_EQ(inward.meshes[0].back_faces, BackFaces::kHidden);
  test::expect_images_agree(inward, test::render_gl_and_ray_cast(inward, 120));
  // A hollow solid's cavity encloses negative volume: drawn whole (it is
  // hidden from outside all the same).
  const Scene hollow = scene_of(test::hollow_cube());
  EXPECT_EQ(hollow.meshes[0].back_faces, BackFaces::kDrawn);
  test::expect_images_agree(hollow, test::render_gl_and_ray_cast(hollow, 120));
}

// umbra view searches once before its first frame rather than asking the
// picture at every view: the same pictures, with nothing left to ask.
TEST_F(ShellCulling, ASearchSettlesWhatThePictureWouldHaveAsked) {
  Scene clean = scene_of(test::unit_cube()), lobed = scene_of(test::bow_tie_prism());
  Scene inward = scene_of(test::all_reversed(test::unit_cube())), hollow = scene_of(test::hollow_cube());
  for (Scene* scene : {&clean, &lobed, &inward, &hollow}) settle_back_faces_by_search(*scene);
  EXPECT_EQ(clean.meshes[0].back_faces, BackFaces::kHidden);
  EXPECT_EQ(lobed.meshes[0].back_faces, BackFaces::kDrawn);  // its lobe's walls cross
  EXPECT_EQ(inward.meshes[0].back_faces, BackFaces::kHidden);  // searched at load: as it was
  EXPECT_EQ(hollow.meshes[0].back_faces, BackFaces::kDrawn);
  test::expect_images_agree(clean, test::render_gl_and_ray_cast(clean, 120));
  test::expect_images_agree(lobed, test::render_gl_and_ray_cast(lobed, 120));
}

}  // namespace
}  // namespace umbra
