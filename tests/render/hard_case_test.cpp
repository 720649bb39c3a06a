// The hard cases of numerical stability (docs/hard-cases.md): each scene's
// mask must match exact shadow rays on the CPU, every volume vertex must be
// finite where it should be and a true direction where it is at infinity, and
// every volume must be closed. Where the answer is an error, it is the exact
// error.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "hard_case_scenes.hpp"
#include "volume_soundness.hpp"
#include "mask_comparison.hpp"
#include "tests/render/image_agreement.hpp"
#include "scene/scene_checks.hpp"
#include "scene/scene_parser.hpp"
#include "render/render_plan.hpp"
#include "render/volume_reach.hpp"
#include "silhouette/mesh_caster.hpp"
#include "silhouette/mesh_volume.hpp"
#include "silhouette/volume_topology.hpp"

namespace umbra {
namespace {

using test::box_obj;
using test::expect_sound_volumes;
using test::floor_text;
using test::write_mesh;

RenderPlan plan_for(const Scene& scene) {
  RenderSettings settings;
  settings.width = settings.height = 120;
  return make_render_plan(scene, settings);
}

void expect_hard_case_holds(const Scene& scene, int segments = 64) {
  expect_sound_volumes(scene);
  test::expect_masks_match_reference(scene, 120, 120, segments);
}

std::string volume_phrase_of(const Scene& scene, size_t caster) { return plan_for(scene).lights[0].casters[caster].volume_phrase; }

// --- spheres -----------------------------------------------------------------

// Light 1 sits `gap` (relative to R) outside the sphere, towards the camera.
Scene light_near_sphere(double gap) {
  const double r = 0.4;
  const glm::dvec3 centre(0.1, -0.1, -0.3), dir = glm::normalize(glm::dvec3(0.3, 0.4, 0.866));
  const glm::dvec3 l = centre + dir * (r * (1.0 + gap));
  std::ostringstream text;
  text.precision(17);
  text << "light " << l.x << " " << l.y << " " << l.z << "\n" << floor_text() << "sphere " << centre.x << " "
       << centre.y << " " << centre.z << " " << r << "\nsphere -0.6 0.5 -0.8 0.15\n";
  return parse_scene_text(text.str(), "near.scene");
}

TEST(HardSphere, LightAThousandthOfTheRadiusOutside) { expect_hard_case_holds(light_near_sphere(1e-3)); }

TEST(HardSphere, LightABillionthOfTheRadiusOutside) { expect_hard_case_holds(light_near_sphere(1e-9)); }

std::string sphere_error(const std::string& text) {
  try {
    require_lights_off_casters(parse_scene_text(text, "s.scene"));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(HardSphere, LightOnOrInsideIsAnErrorAtTheSphere) {
  const std::string error = "s.scene:2:1: light 1 (line 1) is inside or on this sphere, which then has no shadow "
                            "volume; move the light outside the sphere";
  EXPECT_EQ(sphere_error("light 0 0 0.5\nsphere 0 0 0 0.5\n"), error);             // on it
  EXPECT_EQ(sphere_error("light 0.3 0.4 0\nsphere 0 0 0 0.5\n"), error);           // on it, 0.3^2 + 0.4^2 rounds
  EXPECT_EQ(sphere_error("light 0 0 0.1\nsphere 0 0 0 0.5\n"), error);             // inside
  EXPECT_EQ(sphere_error("light 0 0 0.5000000000000001\nsphere 0 0 0 0.5\n"), "");  // one ulp outside
}

// --- triangles ---------------------------------------------------------------

// A vertical triangle in the plane y = 0; the light is `offset` off that plane.
Scene light_by_triangle_plane(double offset) {
  std::ostringstream text;
  text.precision(17);
  text << "light 0.3 " << offset << " 1.5\n"
       << floor_text() << "triangle -0.4 0 -0.6  0.4 0 -0.6  0 0 0.3\nsphere 0.3 0.4 -0.6 0.2\n";
  return parse_scene_text(text.str(), "plane.scene");
}

// How many of the pixels that see scene object `object` the reference's mask
// (for light 1) calls lit, at size x size.
int reference_lit_pixels_of(const Scene& scene, int object, int size) {
  int lit = 0;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const auto hit = nearest_hit(scene, scene.camera.pixel_ray(size, size, x, y));
      lit += hit && hit->object == object && reference_mask_value(scene, size, size, x, y, 0) == kMaskLit;
    }
  return lit;
}

TEST(HardTriangle, LightInItsPlaneCastsNothing) {
  const Scene scene = light_by_triangle_plane(0.0);
  EXPECT_EQ(volume_phrase_of(scene, 2), "none: its plane contains the light, so it is seen edge-on");
  expect_hard_case_holds(scene);
}

TEST(HardTriangle, LightInItsPlaneLightsNeitherSideOfIt) {
  // Seen from its side, so that it fills much of the view: every pixel of it
  // is unlit, in the reference and in the GL (where n . l rounded at each
  // point speckled both).
  Scene scene = light_by_triangle_plane(0.0);
  scene.camera = Camera{glm::dvec3(1.5, -2.0, 1.0), glm::dvec3(0.0, 0.0, -0.4), glm::dvec3(0.0, 0.0, 1.0), 50.0};
  const int triangle = int(scene.spheres.size()) + 2;  // after the spheres and the floor's two
  EXPECT_EQ(reference_lit_pixels_of(scene, triangle, 120), 0);
  expect_hard_case_holds(scene);
}

TEST(HardTriangle, LightWithin1e7OfItsPlane) {
  for (const double offset : {1e-7, -1e-7, 1e-15}) {
    const Scene scene = light_by_triangle_plane(offset);
    EXPECT_EQ(volume_phrase_of(scene, 2), "three side quads");
    expect_hard_case_holds(scene);
  }
}

TEST(HardTriangle, DegenerateTrianglesCastNothingAndSliversTheirShadow) {
  const Scene scene = parse_scene_text("light 0.2 0.3 1.8\n" + floor_text() +
                                           "triangle 0.1 0.1 0  0.1 0.1 0  0.4 0.2 0\n"         // a repeated vertex
                                           "triangle -0.5 0 0  0 0.25 0  0.5 0.5 0\n"          // collinear
                                           "triangle 0 0 0  0 0 0  0 0 0\n"                    // a point
                                           "triangle -0.6 -0.5 -0.2  0.6 -0.5 -0.2  0 -0.4999 -0.2\n"  // a sliver
                                           "sphere 0 0.4 -0.6 0.2\n",
                                       "degenerate.scene");
  EXPECT_EQ(volume_phrase_of(scene, 2), "none: degenerate (collinear vertices)");
  EXPECT_EQ(volume_phrase_of(scene, 3), "none: degenerate (collinear vertices)");
  EXPECT_EQ(volume_phrase_of(scene, 4), "none: degenerate (collinear vertices)");
  EXPECT_EQ(volume_phrase_of(scene, 5), "three side quads");
  EXPECT_EQ(scene.warnings.size(), 3u);
  expect_hard_case_holds(scene);
}

// --- meshes ------------------------------------------------------------------

Scene mesh_scene(const std::string& light, const std::string& obj_name, const std::string& obj) {
  return parse_scene_text(light + floor_text() + "mesh \"" + write_mesh(obj_name, obj) + "\"\n", "mesh.scene");
}

TEST(HardMesh, LightInTheirFacesPlanes) {
  // The box [-0.3, 0.3]^2 x [-0.7, -0.1]: lights in its top face's plane, in
  // two side faces' planes at once, and on the line of a top edge.
  const std::string box = box_obj(-0.3, 0.3, -0.7, -0.1);
  for (const char* light : {"light 0.9 0.2 -0.1\n", "light 0.3 0.3 1.5\n", "light 0.3 -1.2 -0.1\n"}) {
    SCOPED_TRACE(light);
    const Scene scene = mesh_scene(light, "box.obj", box);
    ASSERT_TRUE(scene.meshes[0].components.all_cast_from_silhouette());
    expect_hard_case_holds(scene);
  }
}

TEST(HardMesh, LightInAPlaneTwoBoxesShare) {
  // Two boxes whose faces x = 0.6 lie in one plane, the light in it, seen from
  // the side those faces turn to: each face is unlit throughout, in the
  // reference's mask and the GL's alike.
  const std::string boxes = box_obj(glm::dvec3(0.2, -0.8, -1.0), glm::dvec3(0.6, -0.3, -0.4)) +
                            box_obj(glm::dvec3(0.2, 0.3, -1.0), glm::dvec3(0.6, 0.8, -0.2), 8);
  Scene scene = mesh_scene("light 0.6 0 1.2\n", "two_boxes.obj", boxes);
  scene.camera = Camera{glm::dvec3(2.2, 0.3, 1.4), glm::dvec3(0.0, 0.0, -0.6), glm::dvec3(0.0, 0.0, 1.0), 50.0};
  ASSERT_TRUE(scene.meshes[0].components.all_cast_from_silhouette());
  const int first_box_triangle = 2;  // after the floor's two
  for (const int face_x_06 : {6, 7, 18, 19}) EXPECT_EQ(reference_lit_pixels_of(scene, first_box_triangle + face_x_06, 120), 0);
  expect_hard_case_holds(scene);
}

TEST(HardMesh, NearlyCoplanarNeighbours) {
  // The top is a fan whose centre is raised 1e-12, or by one unit in the
  // last place: its four faces are that far from coplanar, and the light lies
  // in the plane of the box's top edges, so their sides of the light are
  // decided within rounding.
  const double ulp = std::nextafter(-0.1, 0.0) + 0.1;
  for (const double bump : {1e-12, -1e-12, ulp, -ulp}) {
    SCOPED_TRACE(bump);
    const Scene scene = mesh_scene("light 0.8 0.5 -0.1\n", "fan.obj", test::fan_top_box_obj(-0.3, 0.3, -0.7, -0.1, bump));
    ASSERT_TRUE(scene.meshes[0].components.all_cast_from_silhouette());
    expect_hard_case_holds(scene);
  }
}

TEST(HardMesh, LightOnTheSurfaceIsAnErrorAtTheMesh) {
  const std::string box = write_mesh("on_box.obj", box_obj(-0.3, 0.3, -0.7, -0.1));
  for (const char* light : {"light 0.3 0.3 -0.1\n",     // a vertex
                            "light 0 0.3 -0.1\n",       // an edge
                            "light 0.1 -0.2 -0.1\n"}) {  // inside the top face
    SCOPED_TRACE(light);
    try {
      require_lights_off_casters(parse_scene_text(std::string(light) + "mesh \"" + box + "\"\n", "on.scene"));
      ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
      EXPECT_STREQ(e.what(), "on.scene:2:1: light 1 (line 1) is on the surface of this mesh, where its shadow volume is "
                             "undefined; move the light off the surface");
    }
  }
  EXPECT_NO_THROW(require_lights_off_casters(parse_scene_text("light 0.3 0.3 -0.0999\nmesh \"" + box + "\"\n", "off.scene")));
}

TEST(HardMesh, LightInsideAClosedMeshDarkensEverythingOutsideIt) {
  // The physically right answer: the box blocks every ray from the light.
  const Scene scene = parse_scene_text("light 0 0 -0.3\n" + floor_text() + "sphere 0.6 0.6 -0.8 0.1\nmesh \"" +
                                           write_mesh("big_box.obj", box_obj(-0.5, 0.5, -0.6, 0.0)) +
                                           "\" scale 1\n",
                                       "inside.scene");
  expect_sound_volumes(scene);
  RenderSettings settings;
  settings.width = settings.height = 80;
  const RenderPlan plan = make_render_plan(scene, settings);
  HeadlessContext context(80, 80);
  ShadowRenderer renderer(scene, plan);
  const Image mask = renderer.render_mask(0);
  int surface = 0;
  for (uint8_t v : mask.pixels) {
    EXPECT_NE(v, kMaskLit);
    surface += v != kMaskNoSurface;
  }
  EXPECT_GT(surface, 80 * 80 / 4);  // the floor and the box fill about 30% of the view
  test::expect_masks_match_reference(scene, 80, 80, 64);
}

// --- scale -------------------------------------------------------------------

// demo.scene with everything (camera included) multiplied by `s`.
Scene scaled_demo(double s) {
  Scene scene = parse_scene_file(std::string(UMBRA_SOURCE_DIR) + "/scenes/demo.scene");
  scene.camera.eye *= s;
  scene.camera.target *= s;
  for (Light& l : scene.lights) l.position *= s;
  for (Sphere& sp : scene.spheres) {
    sp.center *= s;
    sp.radius *= s;
  }
  for (Triangle& t : scene.triangles) {
    t.a *= s;
    t.b *= s;
    t.c *= s;
  }
  return scene;
}

TEST(HardScale, SceneScaledBy1e6) { expect_hard_case_holds(scaled_demo(1e6)); }

TEST(HardScale, SceneScaledBy1eMinus6) { expect_hard_case_holds(scaled_demo(1e-6)); }

TEST(HardScale, LightAMillionAway) {
  Scene scene = parse_scene_file(std::string(UMBRA_SOURCE_DIR) + "/scenes/demo.scene");
  scene.lights[0].position = glm::normalize(glm::dvec3(0.3, 0.4, 1.0)) * 1e6;
  expect_hard_case_holds(scene);
}

// A light 1e20 away, past the 2e19 at which a float squared overflows: the
// GL once shaded lit faces unlit (normalize() squared the light's vector),
// and the reference's shadow rays started 1e-9 of their length, 1e11, out,
// past every blocker, and found no shadow. The masks and the pictures agree.
TEST(HardScale, LightBeyondAFloatsSquare) {
  Scene scene = parse_scene_file(std::string(UMBRA_SOURCE_DIR) + "/scenes/demo.scene");
  scene.lights[0].position = glm::normalize(glm::dvec3(0.3, 0.4, 1.0)) * 1e20;
  expect_hard_case_holds(scene);
  test::expect_images_agree(scene, test::render_gl_and_ray_cast(scene, 120));
}

// A floor millions of units wide: the near plane, a fraction of the scene's
// depth, once went past the model (the sphere's top, 3 from the default
// eye), and the GL drew background alone; and the floor's points,
// interpolated across triangles 6e6 wide, were lit a float's rounding of
// their corners away from where they are.
TEST(HardScale, AFloorMillionsOfUnitsWide) {
  const Scene scene = parse_scene_text("light 0.6 0.8 1.6\nsphere 0 0 0 0.4\nfloor -0.5 size 3e6\n", "wide.scene");
  EXPECT_LT(plan_for(scene).near_plane, 3.0);
  expect_hard_case_holds(scene);
  test::expect_images_agree(scene, test::render_gl_and_ray_cast(scene, 120));
}

// Directions whose length underflows: hemisphere up 1e-320 0 0 is +x, as
// the camera's up of 1e-320 is; once NaN, every pixel black.
TEST(HardScale, DirectionsTooShortToSquare) {
  const Scene scene = parse_scene_text("light 0.6 0.8 1.6\nsphere 0 0 0 0.4\nfloor -0.5\nhemisphere up 1e-320 0 0\n"
                                       "camera eye 0 -3 1 target 0 0 0 up 0 0 1e-320 fovy 45\n",
                                       "tiny.scene");
  EXPECT_EQ(scene.fill.up, glm::dvec3(1, 0, 0));
  EXPECT_EQ(scene.camera.up, glm::dvec3(0, 0, 1));
  test::expect_images_agree(scene, test::render_gl_and_ray_cast(scene, 120));
}

// --- how far the volumes reach (volume_reach.hpp) ----------------------------

// A light just above a level triangle throws its shadow nine times the
// triangle's distance from it, (-0.55 + 1) / (-0.55 + 0.6), onto the floor:
// the volume must reach that far, and a reach short of it loses the shadow.
TEST(HardReach, ALightJustAboveItsCasterThrowsTheShadowNineTimesAsFar) {
  const Scene scene = parse_scene_text(
      "light 0 0 -0.55\n" + floor_text() + "triangle -0.06 -0.05 -0.6  0.06 -0.05 -0.6  0 0.07 -0.6\n", "long.scene");
  EXPECT_NEAR(plan_for(scene).lights[0].volume_reach, 9.0 * kVolumeReachMargin, 1e-12);
  expect_hard_case_holds(scene);
  // z-pass enters the volume above the floor seen from overhead; z-fail
  // counts it behind the floor, where a short volume would not be.
  test::expect_masks_match_reference(scene, 120, 120, 64, 0.0, RenderMethod::kZFail);
}

// Spheres round the light on every side over the floor: within their box
// along every axis, so the volumes go to infinity, vertices with w = 0.
TEST(HardReach, ALightAmongItsCastersExtrudesToInfinity) {
  const Scene scene = parse_scene_text("light 0 0 -0.5\n" + floor_text() +
                                           "sphere 0.5 0 -0.5 0.15\nsphere -0.5 0 -0.5 0.15\n"
                                           "sphere 0 0.5 -0.5 0.15\nsphere 0 -0.5 -0.5 0.15\n",
                                       "among.scene");
  EXPECT_TRUE(std::isinf(plan_for(scene).lights[0].volume_reach));
  expect_hard_case_holds(scene);
}

// --- the camera and the stencil ----------------------------------------------

TEST(HardView, TheNearPlaneDoesNotDependOnWhereTheTargetLies) {
  // The default view, looking at points 300 away, 1e-3 away, or at the
  // origin: the same near plane, and the whole scene in view.
  const std::string demo = test::read_file(std::string(UMBRA_SOURCE_DIR) + "/scenes/demo.scene");
  const RenderPlan spec_view = plan_for(parse_scene_text(demo, "demo.scene"));
  for (const char* target : {"0 0 -300", "0 0 3.399", "0 0 0"}) {
    SCOPED_TRACE(target);
    const Scene scene = parse_scene_text(demo + "camera eye 0 0 3.4 target " + target + " up 0 1 0 fovy 45\n", "demo.scene");
    EXPECT_EQ(plan_for(scene).near_plane, spec_view.near_plane);
    expect_hard_case_holds(scene);
  }
}

TEST(HardView, TheNearPlaneStaysInFrontOfTheNearestSurface) {
  // The eye 0.005 in front of the demo's surfaces' box, looking into it: a
  // fraction of the scene's size (0.03) would put the near plane behind the
  // nearest surface.
  const std::string demo = test::read_file(std::string(UMBRA_SOURCE_DIR) + "/scenes/demo.scene");
  const SceneBounds b = surface_bounds(parse_scene_text(demo, "demo.scene"));
  std::ostringstream camera;
  camera.precision(17);
  camera << "camera eye 0.1 0.2 " << b.hi.z + 0.005 << " target 0.1 0.2 " << b.lo.z << " up 0 1 0 fovy 90\n";
  const Scene scene = parse_scene_text(demo + camera.str(), "demo.scene");
  const RenderPlan plan = plan_for(scene);
  EXPECT_LT(plan.near_plane, 0.005);
  EXPECT_GT(plan.near_plane, 0.004);
  expect_hard_case_holds(scene);
}

// A ground plane reaching far behind the eye: the surfaces' box holds the
// eye, or a corner of it lies behind the eye. Nothing in front of the eye may
// be clipped: the near plane stays closer than the ground below the eye,
// and the GL image draws what the ray-cast reference sees. (The ground's
// shadow volumes reach behind the eye too, with dark caps whose edges at
// infinity cross the plane through the eye.)
Scene sphere_on_ground(const std::string& camera) {
  return parse_scene_text("light 2 -3 6\nsphere 0 0 0 1\n"
                          "triangle -500 -500 -1  500 -500 -1  500 500 -1\n"
                          "triangle -500 -500 -1  500 500 -1  -500 500 -1\n" +
                              camera,
                          "ground.scene");
}

void expect_nothing_clipped(const Scene& scene, double eye_height) {
  EXPECT_LE(plan_for(scene).near_plane, eye_height);
  test::expect_images_agree(scene, test::render_gl_and_ray_cast(scene, 120));
  expect_hard_case_holds(scene);
}

TEST(HardView, AGroundPlaneBehindTheEyeIsNotClipped) {
  expect_nothing_clipped(sphere_on_ground("camera eye 0 -6 0 target 0 0 0 up 0 0 1 fovy 45\n"), 1.0);
}

TEST(HardView, AnEyeAboveAGroundPlaneThatReachesBehindItClipsNothing) {
  expect_nothing_clipped(sphere_on_ground("camera eye 0 -6 3 target 0 0 -0.5 up 0 0 1 fovy 45\n"), 4.0);
}

TEST(HardView, TheDefaultViewInsideTheSurfacesBoxClipsNothing) {
  // A floor y = -1 reaching 500 every way holds the default eye (0, 0, 3.4)
  // inside the surfaces' box.
  const Scene scene = parse_scene_text("light 0.5 2 2\nsphere 0 0 0 0.6\n"
                                       "triangle -500 -1 -500  -500 -1 500  500 -1 500\n"
                                       "triangle -500 -1 -500  500 -1 500  500 -1 -500\n",
                                       "floor.scene");
  EXPECT_LE(plan_for(scene).near_plane, 1.0);
  test::expect_images_agree(scene, test::render_gl_and_ray_cast(scene, 120));
  expect_hard_case_holds(scene);
}

TEST(HardView, ACameraMovedIntoAClosedMeshSeesItsInside) {
  // Culling is decided per frame from where the eye is: a renderer made for
  // the default view (outside the box, so back faces are culled), then the
  // camera moved inside the box, as zooming in `umbra view` does. Lit from
  // inside, the walls the eye now sees are the mesh's back faces.
  Scene scene = mesh_scene("light 0.2 0.1 0.1\n", "room.obj", box_obj(-0.6, 0.6, -0.9, 0.3));
  ASSERT_TRUE(scene.meshes[0].components.all_cast_from_silhouette());
  require_lights_off_casters(scene);
  RenderSettings settings;
  settings.width = settings.height = 100;
  const std::vector<MeshCaster> casters = prepare_mesh_casters(scene);
  RenderPlan plan = make_render_plan(scene, casters, settings);
  HeadlessContext context(100, 100);
  ShadowRenderer renderer(scene, plan);
  (void)renderer.render_mask(0);
  scene.camera = Camera{{0.1, -0.1, 0.0}, {0.0, 0.0, -1.0}, {0.0, 1.0, 0.0}, 60.0};
  update_render_plan(scene, casters, plan);
  const Image mask = renderer.render_mask(0);
  const test::MaskComparison r = test::compare_with_reference(scene, plan, mask, 0);
  EXPECT_EQ(r.unexplained, 0) << r.first_unexplained << " (" << r.differing << " of " << r.surface_pixels << " differ)";
  EXPECT_TRUE(test::within_boundary_bound(r)) << r.excused_boundary << " excused of " << r.boundary_pixels;
  EXPECT_EQ(r.surface_pixels, 100 * 100);  // the walls all round
}

TEST(HardView, NearPlaneCutsThroughAVolume) {
  // The side plane of the small triangle's volume through its edge y = 0
  // passes through (0, -0.1, 2.2); the eye is 0.005 from it, closer than the
  // near plane, so the near plane's rectangle straddles the volume's side.
  const Scene scene = parse_scene_text("light 0 0.1 3\ncamera eye 0 -0.095 2.2 target 0 -0.095 0 up 0 1 0 fovy 60\n" +
                                           floor_text() +
                                           "triangle -0.1 0 2.6  0.1 0 2.6  0 0.2 2.6\nsphere 0.3 0.2 -0.5 0.3\n",
                                       "near.scene");
  expect_hard_case_holds(scene);
}

// The k-th of `count` points strung along the ray from the light (1.5, 0, 1)
// to the floor point F = (-0.5, 0, -1), away from the camera's line of sight
// to F, between 0.3 and 0.6 of the way.
glm::dvec3 on_the_light_ray(int k, int count) {
  const glm::dvec3 light(1.5, 0.0, 1.0), f(-0.5, 0.0, -1.0);
  return light + (0.3 + 0.3 * k / count) * (f - light);
}

// `count` small level triangles strung along that ray: the floor round F is
// inside all `count` volumes.
Scene triangles_along_a_light_ray(int count) {
  std::ostringstream text;
  text.precision(17);
  text << "light 1.5 0 1\n" << floor_text();
  for (int k = 0; k < count; ++k) {
    const glm::dvec3 c = on_the_light_ray(k, count);
    text << "triangle " << c.x - 0.06 << " " << c.y - 0.05 << " " << c.z << "  " << c.x + 0.06 << " " << c.y - 0.05
         << " " << c.z << "  " << c.x << " " << c.y + 0.07 << " " << c.z << "\n";
  }
  return parse_scene_text(text.str(), "stack.scene");
}

TEST(HardCount, CountsOf255And256And300And1000) {
  // 256 is the case an 8-bit stencil's wrapping gets wrong (256 mod 256 = 0
  // reads as lit); the float count holds every one.
  for (const int count : {255, 256, 300, 1000}) {
    SCOPED_TRACE(count);
    const Scene scene = triangles_along_a_light_ray(count);
    ASSERT_TRUE(shadow_ray_blocked(scene, {-0.5, 0.0, -1.0}, 0, scene.lights[0].position));
    test::expect_masks_match_reference(scene, 100, 100, 64);
  }
}

TEST(HardCount, TrianglesAndAMeshCountedTogether) {
  // 256 triangles' volumes and the box's, counted in one pass: the box
  // shadows part of the floor while the 256 triangles shadow the floor round F.
  Scene scene = triangles_along_a_light_ray(256);
  const Scene with_mesh = parse_scene_text(
      "light 1.5 0 1\n" + floor_text() + "mesh \"" + write_mesh("batch_box.obj", box_obj(0.2, 0.6, -0.9, -0.5)) + "\"\n",
      "box.scene");
  scene.meshes = with_mesh.meshes;
  test::expect_masks_match_reference(scene, 100, 100, 64);
}

// One mesh of `count` level squares (open, two triangles each) strung along
// the ray from the light to the floor point F = (-0.5, 0, -1), as in
// triangles_along_a_light_ray: the floor round F, which the camera sees, lies
// behind every one.
std::string squares_along_a_light_ray(int count) {
  std::ostringstream obj;
  obj.precision(17);
  for (int k = 0; k < count; ++k) {
    const glm::dvec3 c = on_the_light_ray(k, count);
    for (const auto& [dx, dy] : {std::pair{-0.05, -0.05}, {0.05, -0.05}, {0.05, 0.05}, {-0.05, 0.05}})
      obj << "v " << c.x + dx << " " << c.y + dy << " " << c.z << "\n";
    obj << "f " << 4 * k + 1 << " " << 4 * k + 2 << " " << 4 * k + 3 << "\nf " << 4 * k + 1 << " " << 4 * k + 3 << " "
        << 4 * k + 4 << "\n";
  }
  return obj.str();
}

// The same with thin closed boxes: one mesh of `count` closed components.
std::string boxes_along_a_light_ray(int count) {
  std::string obj;
  for (int k = 0; k < count; ++k) {
    const glm::dvec3 c = on_the_light_ray(k, count);
    obj += box_obj(c - glm::dvec3(0.05, 0.05, 0.0), c + glm::dvec3(0.05, 0.05, 0.0005), 8 * k);
  }
  return obj;
}

// The number of the scene's mesh triangles the segment from `point` to the light crosses.
int mesh_layers_over(const Scene& scene, const glm::dvec3& point) {
  Scene just_meshes = scene;
  just_meshes.triangles.clear();
  just_meshes.spheres.clear();
  int layers = 0;
  for (const Mesh& m : scene.meshes)
    for (const auto& t : m.triangles) {
      Scene one = just_meshes;
      one.meshes.clear();
      one.triangles.push_back({m.positions[t[0]], m.positions[t[1]], m.positions[t[2]], 0, {}});
      layers += shadow_ray_blocked(one, point, -1, scene.lights[0].position);
    }
  return layers;
}

TEST(HardCount, OneOpenMeshOf256And300LayersOverVisiblePixels) {
  for (const int count : {256, 300}) {
    SCOPED_TRACE(count);
    const Scene scene = parse_scene_text(
        "light 1.5 0 1\n" + floor_text() + "mesh \"" + write_mesh("squares.obj", squares_along_a_light_ray(count)) + "\"\n",
        "squares.scene");
    ASSERT_FALSE(scene.meshes[0].components.all_cast_from_silhouette());
    ASSERT_GE(mesh_layers_over(scene, {-0.5, 0.0, -1.0}), count);
    // Never per-triangle volumes, nor the mesh cut into parts: one
    // edge-multiplicity volume, all its layers in one count.
    const RenderPlan plan = plan_for(scene);
    const CasterEntry& mesh = plan.lights[0].casters.back();
    ASSERT_EQ(mesh.kind, "mesh");
    EXPECT_EQ(mesh.mesh_volume, 0);
    EXPECT_EQ(plan.lights[0].mesh_volumes.size(), 1u);
    EXPECT_TRUE(mesh.volume.triangles.empty());
    EXPECT_NE(mesh.volume_phrase.find("edge-multiplicity volume"), std::string::npos) << mesh.volume_phrase;
    test::expect_masks_match_reference(scene, 100, 100, 64);
  }
}

TEST(HardCount, OneClosedMeshOf256LayersOverVisiblePixels) {
  const Scene scene = parse_scene_text(
      "light 1.5 0 1\n" + floor_text() + "mesh \"" + write_mesh("boxes.obj", boxes_along_a_light_ray(256)) + "\"\n",
      "boxes.scene");
  ASSERT_TRUE(scene.meshes[0].components.all_cast_from_silhouette());
  // Each box is crossed twice on the way to the light, of which its silhouette volume counts one.
  ASSERT_GE(mesh_layers_over(scene, {-0.5, 0.0, -1.0}), 2 * 256);
  test::expect_masks_match_reference(scene, 100, 100, 64);
}

TEST(HardCount, AMeshOf255LayersAndATriangleShareNoCountThatReaches256) {
  // The reviewer's case: 255 closed plates in one mesh and one triangle on
  // the same light rays, 256 layers in all.
  Scene scene = triangles_along_a_light_ray(1);
  const Scene plates = parse_scene_text(
      "light 1.5 0 1\n" + floor_text() + "mesh \"" + write_mesh("plates255.obj", boxes_along_a_light_ray(255)) + "\"\n",
      "plates.scene");
  scene.meshes = plates.meshes;
  ASSERT_TRUE(shadow_ray_blocked(scene, {-0.5, 0.0, -1.0}, -1, scene.lights[0].position));
  for (const RenderMethod method : {RenderMethod::kAuto, RenderMethod::kZFail})
    test::expect_masks_match_reference(scene, 100, 100, 64, 0.0, method);
}

TEST(HardCount, AMeshVolumeOverlappingItself300Times) {
  std::ostringstream obj;
  for (int k = 0; k < 300; ++k) obj << box_obj(-0.3, 0.3, -0.6 + 0.002 * k, -0.6 + 0.002 * k + 0.001, 8 * k);
  const Scene scene = mesh_scene("light 0.05 0.1 1.8\n", "plates.obj", obj.str());
  ASSERT_TRUE(scene.meshes[0].components.all_cast_from_silhouette());
  test::expect_masks_match_reference(scene, 100, 100, 64);
}

}  // namespace
}  // namespace umbra
