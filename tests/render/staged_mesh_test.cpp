// A mesh file rendered on its own: the scene umbra stages for it (stood on a
// floor in its up axis, one light above, a raised three-quarter view), its
// text saved and read back as the same scene, and its shadow masks against
// exact shadow rays, for meshes the tests write and a real exported model.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "hard_case_scenes.hpp"
#include "image_agreement.hpp"
#include "image/image.hpp"
#include "mask_comparison.hpp"
#include "scene/camera.hpp"
#include "scene/scene_parser.hpp"
#include "scene/staged_scene.hpp"
#include "tests/mesh/interchange_writers.hpp"
#include "tests/mesh/mesh_builders.hpp"
#include "tests/scratch_folder.hpp"

namespace umbra {
namespace {

const std::string kEngine = "/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb";

// A torus at its native size, far from the origin, as glTF binary.
std::string write_torus_glb() {
  PolygonSoup torus = test::triangulated(test::quad_torus(24, 12, 40.0, 10.0));
  for (glm::dvec3& p : torus.points) p += glm::dvec3(300, -200, 50);
  const std::string buffer = test::gltf_buffer(torus);
  test::GltfOptions tilted;
  tilted.node = R"("mesh": 0, "rotation": [0.3826834, 0, 0, 0.9238795])";  // 45 degrees about x
  return test::write_mesh("torus.glb", test::glb(test::gltf_json(torus, buffer, tilted, true), buffer));
}

TEST(StagedMesh, AMeshFileIsToldFromASceneByItsContent) {
  EXPECT_TRUE(is_mesh_file(write_torus_glb()));
  EXPECT_TRUE(is_mesh_file(test::write_mesh("cube-no-extension", test::obj_text(test::unit_cube()))));
  EXPECT_FALSE(is_mesh_file(test::write_mesh("s.scene", "light 0 0 2\n")));
  EXPECT_FALSE(is_mesh_file(test::write_mesh("scene-no-extension", "light 0 0 2\nsphere 0 0 0 0.5\n")));
  EXPECT_FALSE(is_mesh_file("/nonexistent/mesh.obj"));
}

// A name a scene cannot write (a double quote, a line break) is staged all
// the same; the staged text says so where the name would be.
TEST(StagedMesh, ANameAsceneCannotWriteIsStagedAllTheSame) {
  const Scene plain = parse_scene_or_mesh_file(test::write_mesh("cube.obj", test::obj_text(test::unit_cube())));
  for (const char* name : {"say \"cheese\".obj", "two\nlines.obj"}) {
    std::string text;
    const Scene scene = parse_scene_or_mesh_file(test::write_mesh(name, test::obj_text(test::unit_cube())), {}, &text);
    ASSERT_EQ(scene.meshes.size(), 1u) << name;
    EXPECT_EQ(scene.meshes[0].positions.points(), plain.meshes[0].positions.points());
    EXPECT_EQ(scene.camera, plain.camera);
    std::string written = name;
    std::replace_if(written.begin(), written.end(), [](char c) { return c == '"' || c == '\n'; }, '?');
    const size_t line = text.find("\nmesh \"" + written + "\" fit");
    ASSERT_NE(line, std::string::npos) << text;
    EXPECT_EQ(text.find("  # a scene cannot name this file (a double quote or a line break in its name): rename it\n", line),
              text.find('\n', line + 1) - 89)
        << text;
    EXPECT_EQ(text.find("two\nlines"), std::string::npos);
  }
}

TEST(StagedMesh, WarningsAndErrorsNameTheMeshFileNotTheStagedScene) {
  // An open box: its warning belongs to the file, not to line 7 of a scene
  // the user never wrote.
  const std::string open = test::write_mesh("open-box.obj", test::obj_text(test::without_faces(test::unit_cube(), {0, 1})));
  const Scene scene = parse_scene_or_mesh_file(open);
  ASSERT_EQ(scene.warnings.size(), 1u);
  EXPECT_EQ(scene.warnings[0].where.str(), open);
  EXPECT_EQ(scene.warnings[0].message, "mesh \"open-box.obj\" is open, 1 hole: edge-multiplicity volume");
  // A file-level error: said of the file, once.
  const std::string point = test::write_mesh("point.obj", "v 1 1 1\nv 1 1 1\nv 1 1 1\nf 1 2 3\n");
  try {
    parse_scene_or_mesh_file(point);
    ADD_FAILURE() << "a mesh without area was staged";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), point + ": has no faces with area to fit");
  }
}

TEST(StagedMesh, StandsTheMeshOnAFloorUnderALightAboveItAndItsTextIsTheSameScene) {
  const std::string path = write_torus_glb();
  std::string text;
  const Scene scene = parse_scene_or_mesh_file(path, {}, &text);
  EXPECT_EQ(scene.path, path + " (staged)");
  ASSERT_EQ(scene.meshes.size(), 1u);
  const Mesh& m = scene.meshes[0];
  // Fitted: centred, its longest side 2.
  const glm::dvec3 size = m.bounds_max - m.bounds_min;
  EXPECT_NEAR(std::max({size.x, size.y, size.z}), 2.0, 1e-12);
  EXPECT_NEAR(glm::length(m.bounds_min + m.bounds_max), 0.0, 1e-12);
  EXPECT_TRUE(m.components.all_cast_from_silhouette());
  EXPECT_TRUE(scene.warnings.empty());
  // On the floor: two triangles a thousandth below the model's lowest point
  // (so that a face lying on the floor does not fight it over depth),
  // reaching far past it.
  ASSERT_EQ(scene.triangles.size(), 2u);
  for (const Triangle& t : scene.triangles)
    for (const glm::dvec3& p : {t.a, t.b, t.c}) {
      EXPECT_LE(p.z, m.bounds_min.z - 1e-3);
      EXPECT_GT(p.z, m.bounds_min.z - 1e-3 - 1e-6);
      EXPECT_GT(std::max(std::abs(p.x), std::abs(p.y)), 20.0);
    }
  // One light, above the model; the camera from the front, above the floor.
  ASSERT_EQ(scene.lights.size(), 1u);
  EXPECT_GT(scene.lights[0].position.z, m.bounds_max.z);
  ASSERT_TRUE(scene.camera_from.has_value());
  EXPECT_EQ(scene.camera.up, glm::dvec3(0, 0, 1));
  EXPECT_LT(scene.camera.eye.y, m.bounds_min.y);
  EXPECT_GT(scene.camera.eye.z, m.bounds_max.z);

  // The text, saved beside the mesh, is the same scene.
  const std::string saved = (std::filesystem::path(path).parent_path() / "torus.scene").string();
  std::ofstream(saved) << text;
  const Scene again = parse_scene_file(saved);
  EXPECT_EQ(again.meshes[0].positions.points(), m.positions.points());
  EXPECT_EQ(again.camera, scene.camera);
  EXPECT_EQ(again.lights[0].position, scene.lights[0].position);
  EXPECT_EQ(again.triangles[1].c, scene.triangles[1].c);
}

// glTF is +y up by its specification, 3MF +z: the same column written in
// each stands up the same way, in the same picture.
TEST(StagedMesh, AYUpGltfColumnAndAZUpThreeMfColumnStageToTheSamePicture) {
  const PolygonSoup column = test::triangulated(test::prism({{0, 0}, {1, 0}, {1, 0.5}, {0, 0.5}}, 0.0, 4.0));  // +z up
  PolygonSoup y_up = column;
  for (glm::dvec3& p : y_up.points) p = {p.x, p.z, -p.y};  // +z to +y, and the front (-y) to +z, glTF's front
  // Both red, with no specular term: the same material in either format.
  test::GltfOptions red;
  red.material = R"({"name": "red", "pbrMetallicRoughness": {"baseColorFactor": [1, 0, 0, 1], "metallicFactor": 0, "roughnessFactor": 1}})";
  const std::string buffer = test::gltf_buffer(y_up);
  const std::string gltf = test::write_mesh("column.glb", test::glb(test::gltf_json(y_up, buffer, red, true), buffer));
  const std::string threemf = test::write_mesh(
      "column.3mf", test::threemf(R"(<basematerials id="1"><base name="red" displaycolor="#FF0000"/></basematerials>)" +
                                      test::threemf_object(2, column, 0),
                                  R"(<item objectid="2"/>)"));
  std::string text_a, text_b;
  const Scene a = parse_scene_or_mesh_file(gltf, {}, &text_a), b = parse_scene_or_mesh_file(threemf, {}, &text_b);
  // The same stage: light, floor and camera, after the mesh's line.
  EXPECT_EQ(text_a.substr(text_a.find("\nlight")), text_b.substr(text_b.find("\nlight")));
  // Tall, whichever file it came from.
  EXPECT_NEAR(a.meshes[0].bounds_max.z - a.meshes[0].bounds_min.z, 2.0, 1e-12);
  EXPECT_NEAR(b.meshes[0].bounds_max.z - b.meshes[0].bounds_min.z, 2.0, 1e-12);
  const test::RenderedImages pictures_a = test::render_gl_and_ray_cast(a, 96), pictures_b = test::render_gl_and_ray_cast(b, 96);
  EXPECT_EQ(pictures_a.gl.pixels, pictures_b.gl.pixels);
  EXPECT_EQ(pictures_a.cpu.pixels, pictures_b.cpu.pixels);
}

// A cube fills its fitted box; staged, its shadow still falls on the floor in
// view, every pixel sees the floor or the cube, and none is black.
TEST(StagedMesh, ACubesShadowIsInViewAndNoPixelIsBlack) {
  const Scene scene = parse_scene_or_mesh_file(test::write_mesh("cube.obj", test::obj_text(test::unit_cube())));
  const int size = 100;
  int shadowed_floor = 0, background = 0;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const auto hit = nearest_hit(scene, scene.camera.pixel_ray(size, size, x, y));
      if (!hit) ++background;
      else if (hit->object < 2 && shadow_ray_blocked(scene, hit->point, hit->object, scene.lights[0].position)) ++shadowed_floor;
    }
  EXPECT_EQ(background, 0);
  EXPECT_GE(shadowed_floor, size * size / 100) << "the cube's shadow covers under 1% of the frame";
  const test::RenderedImages pictures = test::render_gl_and_ray_cast(scene, size);
  for (const Image* image : {&pictures.gl, &pictures.cpu})
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x)
        EXPECT_FALSE(image->at(x, y, 0) == 0 && image->at(x, y, 1) == 0 && image->at(x, y, 2) == 0) << x << ", " << y;
}

TEST(StagedMesh, MaskMatchesExactShadowRays) {
  test::expect_masks_match_reference(parse_scene_or_mesh_file(write_torus_glb()), 160, 160, 64);
}

// A real exported model: the two-cylinder engine of Khronos's glTF sample
// models, as Debian's assimp-testmodels ships it (121,496 faces, of which
// 11,160 repeat a vertex once equal points merge, so 110,336 triangles; 96
// components, 67 of them open; at its native size of about +-370), as
// umbra check reports it.
TEST(StagedMesh, RealEngineModelMaskMatchesExactShadowRays) {
  if (!std::filesystem::exists(kEngine)) GTEST_SKIP() << "needs Debian's assimp-testmodels (build.sh installs it)";
  const Scene scene = parse_scene_or_mesh_file(kEngine);
  ASSERT_EQ(scene.meshes.size(), 1u);
  EXPECT_EQ(scene.meshes[0].triangles.size(), 110336u);
  EXPECT_EQ(scene.meshes[0].components.components, 96u);
  EXPECT_EQ(scene.meshes[0].components.silhouette_components, 29u);
  // Small: the reference casts every pixel's rays against every triangle.
  test::expect_masks_match_reference(scene, 64, 64, 64);
}


// How far across and up the frame (1: its edge) the staged mesh's framing
// points and their shadows on the floor reach, in a picture `aspect` wide.
struct FrameReach {
  double across = 0.0, up = 0.0;
};
FrameReach frame_reach(const Scene& scene, double aspect) {
  const glm::dvec3 light = scene.lights[0].position;
  const double floor_z = scene.triangles[0].a.z;
  const glm::dmat4 view_projection = scene.camera.view_projection(aspect, 0.01);
  FrameReach reach;
  for (const glm::dvec3& p : framing_points(scene.meshes[0])) {
    EXPECT_GT(light.z, p.z) << "the light should be above the model";
    const glm::dvec3 shadow = light + (p - light) * ((light.z - floor_z) / (light.z - p.z));
    for (const glm::dvec3& q : {p, shadow}) {
      const glm::dvec4 clip = view_projection * glm::dvec4(q, 1.0);
      reach.across = std::max(reach.across, std::abs(clip.x / clip.w));
      reach.up = std::max(reach.up, std::abs(clip.y / clip.w));
    }
  }
  return reach;
}

void expect_framed(const Scene& scene, double aspect) {
  const FrameReach reach = frame_reach(scene, aspect);
  EXPECT_LE(reach.across, 1.0);
  EXPECT_LE(reach.up, 1.0);
  EXPECT_GT(std::max(reach.across, reach.up), 0.8);  // framed, not lost in the middle
}

// The frame is filled by its field of view each way: Khronos's engine at
// 150x600 keeps every framing point and its shadow in the frame (once cut
// off at both sides), and at 600x150 fills the width it has.
TEST(StagedMesh, APortraitFrameHoldsTheModelAndItsShadowAcross) {
  if (!std::filesystem::exists(kEngine)) GTEST_SKIP() << "needs Debian's assimp-testmodels (build.sh installs it)";
  for (const double aspect : {150.0 / 600.0, 1.0, 600.0 / 150.0}) {
    SCOPED_TRACE(aspect);
    StagingOptions framed;
    framed.frame_aspect = aspect;
    expect_framed(parse_scene_or_mesh_file(kEngine, {}, nullptr, framed), aspect);
  }
}

StagingOptions staged_with(const StageView& view) {
  StagingOptions staging;
  staging.view = view;
  return staging;
}

// Wherever the camera or the light is put, by angles, the frame holds the
// model and its whole shadow; --light-angle (light_turn_deg) turns the
// staged light before the camera frames its shadow, which once left it.
TEST(StagedMesh, TheFrameHoldsTheModelAndItsShadowWhereverTheCameraAndLightAre) {
  if (!std::filesystem::exists(kEngine)) GTEST_SKIP() << "needs Debian's assimp-testmodels (build.sh installs it)";
  std::vector<StageView> views(6);
  views[0].camera_azimuth_deg = 200.0, views[0].camera_elevation_deg = 60.0;
  views[1].camera_azimuth_deg = -80.0, views[1].camera_elevation_deg = 10.0, views[1].fov_deg = 60.0;
  views[2].light_azimuth_deg = 90.0, views[2].light_elevation_deg = 25.0;
  views[3].light_turn_deg = 180.0;
  views[4].light = glm::dvec3(0.5, 3.0, 1.5);
  views[5].light_elevation_deg = 80.0, views[5].camera_elevation_deg = -20.0;
  for (const StageView& view : views) {
    const Scene scene = parse_scene_or_mesh_file(kEngine, {}, nullptr, staged_with(view));
    SCOPED_TRACE(scene.lights[0].position.x);
    expect_framed(scene, 1.0);
  }
}

// The framing depends on the model, its shadow and the options that move the
// camera, never on the floor or the background: a dataset's object masks,
// drawn without a floor, line up with its pictures (turning the floor off
// once moved the engine's eye from (3.46, 0.05, 1.55) to (2.93, 0, 1.65)).
TEST(StagedMesh, TheFloorAndTheBackgroundMoveNoCamera) {
  if (!std::filesystem::exists(kEngine)) GTEST_SKIP() << "needs Debian's assimp-testmodels (build.sh installs it)";
  const Camera staged = parse_scene_or_mesh_file(kEngine).camera;
  StagingOptions no_floor, catcher, coloured, transparent;
  no_floor.no_floor = true;
  catcher.floor_catches_shadow = true;
  coloured.floor_color = glm::dvec3(0.2, 0.3, 0.4);
  transparent.background = Background{glm::dvec3(0.0), true};
  for (const StagingOptions& staging : {no_floor, catcher, coloured, transparent}) {
    const Scene scene = parse_scene_or_mesh_file(kEngine, {}, nullptr, staging);
    EXPECT_EQ(scene.camera, staged) << "eye " << scene.camera.eye.x << " " << scene.camera.eye.y << " " << scene.camera.eye.z;
  }
}

// The angles say where the camera and light are, round the model's centre,
// in one convention: azimuth 0 from the front (-y), growing toward +x.
TEST(StagedMesh, CameraAndLightAnglesPlaceThemRoundTheModel) {
  const std::string cube = test::write_mesh("angles.obj", test::obj_text(test::unit_cube()));
  StageView view;
  view.camera_azimuth_deg = 90.0, view.camera_elevation_deg = 0.0;
  view.light_azimuth_deg = 180.0, view.light_elevation_deg = 90.0;
  const Scene scene = parse_scene_or_mesh_file(cube, {}, nullptr, staged_with(view));
  const glm::dvec3 look = glm::normalize(scene.camera.eye - scene.camera.target);
  EXPECT_NEAR(look.x, 1.0, 1e-12);  // from +x, level
  EXPECT_NEAR(look.z, 0.0, 1e-12);
  const glm::dvec3 centre = scene.meshes[0].bounds_min / 2.0 + scene.meshes[0].bounds_max / 2.0;
  const glm::dvec3 light = scene.lights[0].position;
  EXPECT_NEAR(light.x, centre.x, 1e-5);  // straight above, 4 half-sizes up (written to 6 digits)
  EXPECT_NEAR(light.y, centre.y, 1e-5);
  EXPECT_NEAR(light.z, centre.z + 4.0, 1e-5);
  // Zoom brings the camera nearer along the same line; --eye and --target
  // place it outright; --light puts the light there.
  StageView zoomed = view;
  zoomed.camera_zoom = 2.0;
  const Scene near = parse_scene_or_mesh_file(cube, {}, nullptr, staged_with(zoomed));
  EXPECT_NEAR(glm::length(near.camera.eye - near.camera.target), glm::length(scene.camera.eye - scene.camera.target) / 2, 1e-5);
  StageView placed;
  placed.eye = glm::dvec3(3, -4, 2), placed.target = glm::dvec3(0, 0, 0.5), placed.light = glm::dvec3(-2, 1, 3);
  const Scene there = parse_scene_or_mesh_file(cube, {}, nullptr, staged_with(placed));
  EXPECT_EQ(there.camera.eye, glm::dvec3(3, -4, 2));
  EXPECT_EQ(there.camera.target, glm::dvec3(0, 0, 0.5));
  EXPECT_EQ(there.lights[0].position, glm::dvec3(-2, 1, 3));
}

// The staged text's line that says why the pose is not the format's ("" when none).
std::string pose_note(const std::string& text) {
  const size_t at = text.find("\n# up is ");
  return at == std::string::npos ? "" : text.substr(at + 1, text.find('\n', at + 1) - at - 1);
}

// A model built standing on another axis than its format's: a Y-up "animal"
// (long in z, its feet at y = 0) saved as STL, whose convention (+z up)
// would stand it on its tail, stands on its feet; so does Debian's real
// one, assimp's Wuson.stl, and a Z-up house plan saved as OBJ (+y up),
// assimp's regr01.obj, on its floor. A figure standing on its format's
// axis, and a model centred on the origin, keep the convention.
TEST(StagedMesh, AModelBuiltStandingOnAnotherAxisStandsOnIt) {
  const PolygonSoup animal = test::box_triangles({-0.5, 0.0, -1.5}, {0.5, 1.5, 1.5});
  std::string text;
  const Scene scene = parse_scene_or_mesh_file(test::write_mesh("animal.stl", test::stl_text(animal)), {}, &text);
  EXPECT_EQ(pose_note(text), "# up is +y, not +z as its format has it: it was built standing on that axis (its base is at 0 along it, "
                             "not along +z), on a footprint at least 1.5 times as large");
  EXPECT_NE(text.find("mesh \"animal.stl\" fit rotate 1 0 0 90 "), std::string::npos) << text;
  const glm::dvec3 size = scene.meshes[0].bounds_max - scene.meshes[0].bounds_min;
  EXPECT_NEAR(size.z, 1.0, 1e-12);  // 1.5 of its 3 fitted to 2: standing on its feet
  // Its text reads back as the same scene, the note a comment.
  const std::string saved = (std::filesystem::path(scene.meshes[0].path).parent_path() / "animal.scene").string();
  std::ofstream(saved) << text;
  EXPECT_EQ(parse_scene_file(saved).meshes[0].positions.points(), scene.meshes[0].positions.points());

  const PolygonSoup figure = test::box_triangles({-0.25, 0.0, -0.15}, {0.25, 1.8, 0.15});  // Y-up, as OBJ has it
  parse_scene_or_mesh_file(test::write_mesh("figure.obj", test::obj_text(figure)), {}, &text);
  EXPECT_EQ(pose_note(text), "");
  parse_scene_or_mesh_file(write_torus_glb(), {}, &text);
  EXPECT_EQ(pose_note(text), "");

  const std::string models = "/usr/share/assimp/models/";
  if (!std::filesystem::exists(models + "STL/Wuson.stl")) GTEST_SKIP() << "needs Debian's assimp-testmodels (build.sh installs it)";
  parse_scene_or_mesh_file(models + "STL/Wuson.stl", {}, &text);
  EXPECT_EQ(pose_note(text).substr(0, 16), "# up is +y, not ");
  parse_scene_or_mesh_file(models + "OBJ/regr01.obj", {}, &text);
  EXPECT_EQ(pose_note(text).substr(0, 16), "# up is +z, not ");
  // --up decides outright.
  StagingOptions up;
  up.up = "+z";
  parse_scene_or_mesh_file(models + "STL/Wuson.stl", {}, &text, up);
  EXPECT_EQ(pose_note(text), "");
}

// A staged mesh is shaded smooth, unless it has as many triangles as the
// picture has pixels: then no facet of it shows, and it is drawn flat, said
// in a comment, unless the crease angle is given.
TEST(StagedMesh, AMeshFinerThanThePictureIsDrawnFlat) {
  const std::string torus = write_torus_glb();  // 24 x 12 quads: 576 triangles
  StagingOptions staging;
  std::string text;
  staging.frame_pixels = 577;
  EXPECT_EQ(parse_scene_or_mesh_file(torus, {}, &text, staging).meshes[0].triangle_normals.size(), 576u);
  EXPECT_NE(text.find(" smooth 30\n"), std::string::npos) << text;
  staging.frame_pixels = 576;
  const Scene flat = parse_scene_or_mesh_file(torus, {}, &text, staging);
  EXPECT_TRUE(flat.meshes[0].triangle_normals.empty());
  EXPECT_EQ(text.find(" smooth "), std::string::npos) << text;
  EXPECT_NE(text.find("\n# shaded flat: 576 triangles for 576 pixels are finer than the picture and show no facets "
                      "(--crease-angle smooths them all the same)\n"),
            std::string::npos)
      << text;
  staging.crease_given = true;
  EXPECT_EQ(parse_scene_or_mesh_file(torus, {}, &text, staging).meshes[0].triangle_normals.size(), 576u);
}

// Whether the camera sees the model (in at least 2% of a 60x60 frame) and the
// light reaches nearly all of what it sees of it.
bool seen_and_lit(const Scene& scene) {
  const int size = 60;
  int seen = 0, lit = 0;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const auto hit = nearest_hit(scene, scene.camera.pixel_ray(size, size, x, y));
      if (!hit || hit->object < int(scene.triangles.size())) continue;  // the floor's triangles come first
      ++seen;
      lit += reference_mask_value(scene, size, size, x, y, 0) == kMaskLit;
    }
  return seen >= size * size / 50 && lit >= seen * 9 / 10;
}

// The sine of the staged camera's elevation over what it looks at.
double camera_rise(const Scene& scene) { return glm::normalize(scene.camera.eye - scene.camera.target).z; }

// The way a staged mesh's faces turn, summed by area, or only its faces
// that have texture coordinates.
glm::dvec3 faces_turn(const Mesh& mesh, bool textured_only = false) {
  glm::dvec3 sum(0.0);
  for (size_t t = 0; t < mesh.triangles.size(); ++t)
    if (!textured_only || (!mesh.triangle_uvs.empty() && mesh.triangle_uvs[t] != std::array<glm::vec2, 3>{}))
      sum += glm::cross(mesh.positions[mesh.triangles[t][1]] - mesh.positions[mesh.triangles[t][0]],
                        mesh.positions[mesh.triangles[t][2]] - mesh.positions[mesh.triangles[t][0]]);
  return sum;
}

// A flat part lies flat, its face up and lit, and is seen from higher up
// (60 degrees) so that its face reads, never by its edge or from below: a
// quad lying face up in a Y-up OBJ keeps its pose, one lying face down is
// turned over, a panel standing across x in an STL and one standing in a
// Y-up OBJ (as glTF's texture transform sample does) lie down face up, and
// Debian's real triangle.stl lies as it is.
TEST(StagedMesh, AFlatPartLiesFlatAndShowsItsLitFace) {
  std::string text;
  const PolygonSoup up = test::make_soup({{0, 0, 0}, {2, 0, 0}, {2, 0, -1}, {0, 0, -1}}, {{0, 1, 2}, {0, 2, 3}});  // facing +y
  const Scene kept = parse_scene_or_mesh_file(test::write_mesh("face-up.obj", test::obj_text(up)), {}, &text);
  EXPECT_EQ(pose_note(text), "");
  EXPECT_NEAR(camera_rise(kept), std::sin(glm::radians(60.0)), 1e-6);
  EXPECT_GT(faces_turn(kept.meshes[0]).z, 0.0);
  EXPECT_TRUE(seen_and_lit(kept));
  const Scene over = parse_scene_or_mesh_file(test::write_mesh("face-down.obj", test::obj_text(test::all_reversed(up))), {}, &text);
  EXPECT_EQ(pose_note(text), "# up is -y, not +y as its format has it: it is flat and lay face down, so it is turned over to show its face");
  EXPECT_GT(faces_turn(over.meshes[0]).z, 0.0);
  EXPECT_TRUE(seen_and_lit(over));
  // Standing across x (its face toward +x), in an STL: laid down on its back.
  const PolygonSoup across = test::make_soup({{0, 0, 0}, {0, 2, 0}, {0, 2, 1}, {0, 0, 1}}, {{0, 1, 2}, {0, 2, 3}});
  const Scene laid = parse_scene_or_mesh_file(test::write_mesh("across.stl", test::stl_text(across)), {}, &text);
  EXPECT_EQ(pose_note(text), "# up is +x, not +z as its format has it: it is flat and stood on its edge, so it lies flat, its face up");
  EXPECT_NEAR(camera_rise(laid), std::sin(glm::radians(60.0)), 1e-6);
  EXPECT_GT(faces_turn(laid.meshes[0]).z, 0.0);
  EXPECT_TRUE(seen_and_lit(laid));
  // Standing in a Y-up OBJ, its face toward +z at z = 0.
  const PolygonSoup upright = test::make_soup({{0, -0.5, 0}, {2, -0.5, 0}, {2, 0.5, 0}, {0, 0.5, 0}}, {{0, 1, 2}, {0, 2, 3}});
  const Scene down = parse_scene_or_mesh_file(test::write_mesh("upright.obj", test::obj_text(upright)), {}, &text);
  EXPECT_EQ(pose_note(text), "# up is +z, not +y as its format has it: it is flat and stood on its edge, so it lies flat, its face up");
  EXPECT_GT(faces_turn(down.meshes[0]).z, 0.0);
  EXPECT_TRUE(seen_and_lit(down));
  // Standing at a slant along the default view's line of sight (azimuth
  // 35): not flat along an axis, it stands, the camera turned to its face,
  // which looks to azimuth -55.
  const glm::dvec3 along(std::sin(glm::radians(35.0)), -std::cos(glm::radians(35.0)), 0.0);
  const PolygonSoup slanted = test::make_soup({{0, 0, 0}, 2.0 * along, 2.0 * along + glm::dvec3(0, 0, 1), {0, 0, 1}}, {{0, 1, 2}, {0, 2, 3}});
  const Scene faced = parse_scene_or_mesh_file(test::write_mesh("slanted.stl", test::stl_text(slanted)), {}, &text);
  EXPECT_EQ(pose_note(text), "");
  EXPECT_TRUE(seen_and_lit(faced));
  const std::string triangle = "/usr/share/assimp/models/STL/triangle.stl";
  if (!std::filesystem::exists(triangle)) GTEST_SKIP() << "needs Debian's assimp-testmodels (build.sh installs it)";
  const Scene real = parse_scene_or_mesh_file(triangle, {}, &text);
  EXPECT_EQ(pose_note(text), "");
  EXPECT_GT(faces_turn(real.meshes[0]).z, 0.0);
  EXPECT_TRUE(seen_and_lit(real));
}

// One plate at two sizes, as a printer's beds of one family come, posed and
// seen alike: a closed box 220 x 220 x 3 (flat: thinner than 2% of its
// side) and 150 x 150 x 3 (not flat) lie as their STL has them, seen from
// 60 degrees up, at the same angles. A thin box textured on its underside
// only (a label's side) is turned over to show it, and a panel of labels
// built over its backing stands on its back.
TEST(StagedMesh, PlatesLieFlatAlikeAndShowTheirTexturedSide) {
  std::string text;
  const Scene large = parse_scene_or_mesh_file(
      test::write_mesh("bed_220.stl", test::stl_text(test::box_triangles(glm::dvec3(0.0), glm::dvec3(220, 220, 3)))), {}, &text);
  EXPECT_EQ(pose_note(text), "");
  const Scene small = parse_scene_or_mesh_file(
      test::write_mesh("bed_150.stl", test::stl_text(test::box_triangles(glm::dvec3(0.0), glm::dvec3(150, 150, 3)))), {}, &text);
  EXPECT_EQ(pose_note(text), "");
  EXPECT_NE(text.find("\n# seen from 60 degrees up, not 30: it lies low (its height under a tenth of its footprint's side), so its face "
                      "reads\n"),
            std::string::npos)
      << text;
  for (const Scene* bed : {&large, &small}) {
    EXPECT_NEAR(camera_rise(*bed), std::sin(glm::radians(60.0)), 1e-6);
    EXPECT_TRUE(seen_and_lit(*bed));
  }
  EXPECT_NEAR(glm::dot(glm::normalize(large.camera.eye - large.camera.target), glm::normalize(small.camera.eye - small.camera.target)), 1.0,
              1e-9);
  // The label: a 2 x 1 x 0.01 box (Y-up OBJ) whose face at y = 0 (its underside) is mapped.
  const std::filesystem::path folder = std::filesystem::path(test::write_mesh("label.mtl", "newmtl label\nmap_Kd label.png\nnewmtl plain\nKd 0.8 0.8 0.8\n")).parent_path();
  Image map(2, 2, 3);
  for (uint8_t& v : map.pixels) v = 200;
  write_png(map, (folder / "label.png").string());
  const PolygonSoup box = test::box_triangles(glm::dvec3(0.0), glm::dvec3(2, 0.01, 1));
  std::string obj = "mtllib label.mtl\n";
  for (const glm::dvec3& p : box.points) obj += "v " + std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) + "\n";
  obj += "vt 0 0\nvt 1 0\nvt 1 1\n";
  for (size_t f = 0; f < box.polygon_count(); ++f) {
    const uint32_t* c = box.polygon(f);
    const bool underside = box.points[c[0]].y == 0.0 && box.points[c[1]].y == 0.0 && box.points[c[2]].y == 0.0;
    obj += underside ? "usemtl label\nf " + std::to_string(c[0] + 1) + "/1 " + std::to_string(c[1] + 1) + "/2 " + std::to_string(c[2] + 1) + "/3\n"
                     : "usemtl plain\nf " + std::to_string(c[0] + 1) + " " + std::to_string(c[1] + 1) + " " + std::to_string(c[2] + 1) + "\n";
  }
  const Scene label = parse_scene_or_mesh_file(test::write_mesh("label.obj", obj), {}, &text);
  EXPECT_EQ(pose_note(text), "# up is -y, not +y as its format has it: it is flat and lay face down, so it is turned over to show its face");
  EXPECT_GT(faces_turn(label.meshes[0], true).z, 0.0);
  // assimp's four labels over a dark backing, built on z = 0 (the backing
  // behind, below 0): it lies on its back, its labels up, not on its face.
  const std::string labels = "/usr/share/assimp/models/glTF2/issue_3269/texcoord_crash.gltf";
  if (!std::filesystem::exists(labels)) GTEST_SKIP() << "needs Debian's assimp-testmodels (build.sh installs it)";
  const Scene real = parse_scene_or_mesh_file(labels, {}, &text);
  EXPECT_EQ(pose_note(text), "# up is +z, not +y as its format has it: it was built standing on that axis (its base is at 0 along it, not "
                             "along +y), on a footprint at least 1.5 times as large, and stands on its back to show its face");
  EXPECT_GT(faces_turn(real.meshes[0], true).z, 0.0);
}

// A spindly model is framed first, its shadow after: a lamp post (a pole
// 2 tall, an arm 1 long at its top), whose shadow reaches twice as far as
// the post does from its centre, spans 60% of the picture's height or more
// (70%); framed round its whole shadow, it spanned 52%. Its shadow still
// shows. A solid model keeps its whole shadow in the frame
// (StagedMesh.TheFrameHoldsTheModelAndItsShadowWhereverTheCameraAndLightAre).
TEST(StagedMesh, ASpindlyModelIsFramedBeforeItsShadow) {
  const PolygonSoup post = test::combine(test::box_triangles(glm::dvec3(0.0), glm::dvec3(0.1, 0.1, 2.0)),
                                         test::box_triangles(glm::dvec3(0.1, 0.0, 1.9), glm::dvec3(1.0, 0.1, 2.0)));
  std::string text;
  const Scene scene = parse_scene_or_mesh_file(test::write_mesh("post.stl", test::stl_text(post)), {}, &text);
  EXPECT_NE(text.find("\n# its shadow runs out of the frame: framed whole, it would leave the model small (moving the light frames it "
                      "whole)\n"),
            std::string::npos)
      << text;
  const int size = 120;
  int top = size, bottom = -1, shadow = 0;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const auto hit = nearest_hit(scene, scene.camera.pixel_ray(size, size, x, y));
      if (hit && hit->object >= int(scene.triangles.size())) top = std::min(top, y), bottom = std::max(bottom, y);
      shadow += hit && hit->object < int(scene.triangles.size()) && reference_mask_value(scene, size, size, x, y, 0) == kMaskUnlit;
    }
  EXPECT_GT(bottom - top + 1, 0.6 * size) << "the post spans rows " << top << " to " << bottom;
  EXPECT_GT(shadow, 100) << "its shadow should show";
}

// A camera turned round the model sees it where the ray-cast reference does:
// the GL's image and mask against the reference's, from behind and below the
// default view, with the light moved too.
TEST(StagedMesh, ATurnedCameraAndMovedLightDrawWhatTheReferenceSees) {
  StageView view;
  view.camera_azimuth_deg = 160.0, view.camera_elevation_deg = 20.0;  // the floor's far edge just out of view
  view.light_azimuth_deg = 120.0, view.light_elevation_deg = 40.0;
  const Scene scene = parse_scene_or_mesh_file(write_torus_glb(), {}, nullptr, staged_with(view));
  test::expect_masks_match_reference(scene, 120, 120, 64);
  test::expect_images_agree(scene, test::render_gl_and_ray_cast(scene, 120));
}

}  // namespace
}  // namespace umbra

namespace umbra {
namespace {

class StagedSceneText : public test::ScratchFolder {};

// What a scene holds that staging sets, compared value by value.
void expect_same_stage(const Scene& drawn, const Scene& read) {
  ASSERT_EQ(drawn.lights.size(), read.lights.size());
  for (size_t i = 0; i < drawn.lights.size(); ++i) {
    EXPECT_EQ(drawn.lights[i].position, read.lights[i].position);
    EXPECT_EQ(drawn.lights[i].color, read.lights[i].color);
    EXPECT_EQ(drawn.lights[i].ambient, read.lights[i].ambient);
    EXPECT_EQ(drawn.lights[i].where.line, read.lights[i].where.line);
  }
  ASSERT_EQ(drawn.materials.size(), read.materials.size());
  for (size_t i = 0; i < drawn.materials.size(); ++i) {
    const Material &a = drawn.materials[i], &b = read.materials[i];
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.ambient, b.ambient) << a.name;
    EXPECT_EQ(a.diffuse, b.diffuse) << a.name;
    EXPECT_EQ(a.specular, b.specular) << a.name;
    EXPECT_EQ(a.shininess, b.shininess) << a.name;
    EXPECT_EQ(a.shadow_catcher, b.shadow_catcher) << a.name;
    EXPECT_EQ(bool(a.texture), bool(b.texture)) << a.name;
  }
  ASSERT_EQ(drawn.triangles.size(), read.triangles.size());
  for (size_t i = 0; i < drawn.triangles.size(); ++i) {
    const Triangle &a = drawn.triangles[i], &b = read.triangles[i];
    EXPECT_TRUE(a.a == b.a && a.b == b.b && a.c == b.c) << "floor triangle " << i;
    EXPECT_EQ(a.material, b.material);
    EXPECT_EQ(a.where.line, b.where.line);
  }
  EXPECT_EQ(drawn.camera, read.camera);
  ASSERT_TRUE(drawn.camera_from && read.camera_from);
  EXPECT_EQ(drawn.camera_from->line, read.camera_from->line);
  EXPECT_EQ(drawn.background.transparent, read.background.transparent);
  EXPECT_EQ(drawn.background.color, read.background.color);
  EXPECT_EQ(drawn.fill.headlight, read.fill.headlight);
  EXPECT_EQ(drawn.fill.sky, read.fill.sky);
  EXPECT_EQ(drawn.fill.ground, read.fill.ground);
  EXPECT_EQ(drawn.fill.up, read.fill.up);
  EXPECT_EQ(drawn.tone, read.tone);
  EXPECT_EQ(drawn.size, read.size);
  EXPECT_EQ(drawn.antialias, read.antialias);
  EXPECT_EQ(drawn.antialias_all, read.antialias_all);
  ASSERT_EQ(drawn.meshes.size(), 1u);
  ASSERT_EQ(read.meshes.size(), 1u);
  const Mesh &a = drawn.meshes[0], &b = read.meshes[0];
  EXPECT_EQ(a.fit, b.fit);
  EXPECT_EQ(a.rotation_axis, b.rotation_axis);
  EXPECT_EQ(a.rotation_deg, b.rotation_deg);
  EXPECT_EQ(a.smooth_deg, b.smooth_deg);
  EXPECT_EQ(a.plain, b.plain);
  EXPECT_EQ(a.triangles, b.triangles);
  ASSERT_EQ(a.positions.size(), b.positions.size());
  for (size_t i = 0; i < a.positions.size(); ++i) ASSERT_EQ(a.positions[i], b.positions[i]) << "point " << i;
  EXPECT_EQ(a.triangle_materials, b.triangle_materials);
}

// Every staged scene of the bundled meshes and of real files, with the
// options that change the stage, is a value that its own text (what
// --explain prints and --save-scene saves) reads back as: staging sets its
// values as the text will read, and parses none of it.
TEST_F(StagedSceneText, EveryStagedSceneReadsBackFromItsTextAsTheSameValues) {
  std::vector<std::string> meshes;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(UMBRA_SOURCE_DIR) + "/scenes/meshes"))
    if (entry.path().extension() != ".py") meshes.push_back(entry.path().string());
  for (const std::string& real : {kEngine, std::string("/usr/share/assimp/models/OFF/Wuson.off"),
                                 std::string("/usr/share/assimp/models/STL/Spider_binary.stl")})
    if (std::filesystem::exists(real)) meshes.push_back(real);
  ASSERT_GE(meshes.size(), 4u);
  std::vector<StagingOptions> variants(6);
  variants[5].view.orthographic = true, variants[5].view.camera_zoom = 1.3;
  variants[1].no_floor = true, variants[1].crease_deg = 33.333333, variants[1].crease_given = true;
  variants[2].floor_catches_shadow = true, variants[2].background = Background{glm::dvec3(0.0), true};
  variants[3].floor_color = glm::dvec3(0.1234567, 0.2, 0.3), variants[3].model_color = glm::dvec3(0.7, 0.61111111, 0.5);
  variants[3].background = Background{glm::dvec3(1.0 / 3.0, 0.5, 0.25), false};
  variants[3].width = 320, variants[3].height = 200, variants[3].antialias = 2, variants[3].antialias_all = true;
  variants[4].view.camera_azimuth_deg = 123.456789, variants[4].view.camera_elevation_deg = -12.3456789;
  variants[4].view.light_azimuth_deg = 10.0 / 3.0, variants[4].view.fov_deg = 47.1111111, variants[4].frame_aspect = 1.7;
  for (const std::string& mesh : meshes) {
    // A copy beside the scene text, which names it by its file name.
    const std::string copy = (folder_ / std::filesystem::path(mesh).filename()).string();
    std::filesystem::copy_file(mesh, copy, std::filesystem::copy_options::overwrite_existing);
    for (size_t v = 0; v < variants.size(); ++v) {
      SCOPED_TRACE(mesh + ", variant " + std::to_string(v));
      std::string text;
      const Scene drawn = parse_scene_or_mesh_file(copy, {}, &text, variants[v]);
      const Scene read = parse_scene_file(write("staged.scene", text));
      expect_same_stage(drawn, read);
    }
  }
}

}  // namespace
}  // namespace umbra
