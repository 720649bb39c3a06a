#include "scene/scene_parser.hpp"

#include <gtest/gtest.h>

#define GLM_ENABLE_EXPERIMENTAL
#include <glm/gtx/component_wise.hpp>
#include <glm/geometric.hpp>

#include <filesystem>
#include <fstream>

#include "tests/mesh/mesh_builders.hpp"
#include "tests/scratch_folder.hpp"

namespace umbra {
namespace {

// The exact message a scene text fails with ("" when it parses).
std::string error_of(const std::string& text) {
  try {
    parse_scene_text(text, "t.scene");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

const std::string kLight = "light 0 0 2\n";

TEST(SceneParser, ParsesTheFormatExample) {
  const Scene s = parse_scene_text(R"(# two spheres over a floor
light 0.6 0.8 1.6
material floor diffuse 0.7 0.7 0.7
material red diffuse 0.9 0.2 0.2 specular 0.5 0.5 0.5 shininess 40
triangle -1 -1 -1   1 -1 -1   1 1 -1 material floor
triangle -1 -1 -1   1 1 -1   -1 1 -1 material floor
sphere 0 0 -0.3 0.35 material red
sphere 0.5 0.4 0.2 0.15
)", "example.scene");
  ASSERT_EQ(s.lights.size(), 1u);
  EXPECT_EQ(s.lights[0].position, glm::dvec3(0.6, 0.8, 1.6));
  EXPECT_EQ(s.lights[0].color, glm::dvec3(1.0));
  EXPECT_EQ(s.lights[0].ambient, glm::dvec3(0.15));
  EXPECT_EQ(s.lights[0].where.line, 2);
  ASSERT_EQ(s.materials.size(), 3u);  // default, floor, red
  EXPECT_EQ(s.materials[2].specular, glm::dvec3(0.5));
  EXPECT_EQ(s.materials[2].shininess, 40.0);
  EXPECT_EQ(s.materials[1].specular, glm::dvec3(0.0));  // defaults
  EXPECT_EQ(s.materials[1].ambient, glm::dvec3(1.0));
  ASSERT_EQ(s.triangles.size(), 2u);
  EXPECT_EQ(s.triangles[1].c, glm::dvec3(-1, 1, -1));
  EXPECT_EQ(s.triangles[0].material, 1);
  ASSERT_EQ(s.spheres.size(), 2u);
  EXPECT_EQ(s.spheres[0].material, 2);
  EXPECT_EQ(s.spheres[1].material, 0);
  EXPECT_EQ(s.spheres[1].radius, 0.15);
  EXPECT_FALSE(s.camera_from.has_value());
  EXPECT_EQ(s.camera.eye, spec_camera().eye);
  EXPECT_TRUE(s.warnings.empty());
}

TEST(SceneParser, LightKeywordsInAnyOrder) {
  const Scene s = parse_scene_text("light 1 2 3 ambient 0.1 0.2 0.3 color 0.5 0.6 0.7\n", "t");
  EXPECT_EQ(s.lights[0].color, glm::dvec3(0.5, 0.6, 0.7));
  EXPECT_EQ(s.lights[0].ambient, glm::dvec3(0.1, 0.2, 0.3));
}

TEST(SceneParser, CommentsBlankLinesTabsAndCarriageReturns) {
  const Scene s = parse_scene_text("\n  # c\n\tlight\t0 0 2 # trailing\r\n\r\nsphere 0 0 0 0.5\n", "t");
  EXPECT_EQ(s.lights.size(), 1u);
  EXPECT_EQ(s.spheres[0].where.line, 5);
  EXPECT_EQ(s.spheres[0].where.column, 1);
}

TEST(SceneParser, CameraStatement) {
  const Scene s = parse_scene_text(kLight + "camera fovy 30 eye 0 1 5 up 0 1 0 target 0 0 0\n", "t");
  ASSERT_TRUE(s.camera_from.has_value());
  EXPECT_EQ(s.camera_from->line, 2);
  EXPECT_EQ(s.camera.eye, glm::dvec3(0, 1, 5));
  EXPECT_EQ(s.camera.fovy_deg, 30.0);
}

TEST(SceneParser, BackgroundIsAColourOrTransparent) {
  EXPECT_EQ(parse_scene_text(kLight, "t").background.color, glm::dvec3(0.0));  // black unless written
  EXPECT_FALSE(parse_scene_text(kLight, "t").background.transparent);
  const Scene coloured = parse_scene_text(kLight + "background 0.2 0.4 1\n", "t");
  EXPECT_EQ(coloured.background.color, glm::dvec3(0.2, 0.4, 1.0));
  EXPECT_FALSE(coloured.background.transparent);
  EXPECT_TRUE(parse_scene_text(kLight + "background transparent\n", "t").background.transparent);
  EXPECT_EQ(error_of(kLight + "background 0.2 0.4 1\nbackground transparent\n"),
            "t.scene:3:1: a second background statement (the first is at line 2)");
  EXPECT_EQ(error_of(kLight + "background clear\n"), "t.scene:2:12: expected a number for the background colour red, got \"clear\"");
  EXPECT_EQ(error_of(kLight + "background transparent 1\n"), "t.scene:2:24: unexpected \"1\" after the end of the background statement");
}

// "default", written once, is the material of everything that names none,
// and may then be named; any other name still cannot be written twice.
TEST(SceneParser, TheDefaultMaterialCanBeWrittenOnce) {
  const Scene s = parse_scene_text(kLight + "material default diffuse 1 0 0\nsphere 0 0 0 0.5\ntriangle 0 0 0 1 0 0 0 1 0 material default\n", "t");
  EXPECT_EQ(s.materials.size(), 1u);
  EXPECT_EQ(s.materials[0].name, "default");
  EXPECT_EQ(s.materials[0].diffuse, glm::dvec3(1, 0, 0));
  EXPECT_EQ(s.spheres[0].material, 0);
  EXPECT_EQ(s.triangles[0].material, 0);
  EXPECT_EQ(error_of(kLight + "sphere 0 0 0 0.5 material default\n"),
            "t.scene:2:27: material \"default\" is not defined (define it on an earlier line)");
  EXPECT_EQ(error_of(kLight + "material default\nmaterial default\n"), "t.scene:3:10: material \"default\" is already defined at line 2");
}

// A floor is the two triangles of the bundled scenes' floors, wound alike,
// and may reach past the cube without a warning.
TEST(SceneParser, AFloorIsTwoTrianglesThatMayReachPastTheCube) {
  const Scene spec = parse_scene_text(kLight + "material grey\nfloor -1 material grey\n", "t");
  ASSERT_EQ(spec.triangles.size(), 2u);
  EXPECT_EQ(spec.triangles[0].a, glm::dvec3(-1, -1, -1));
  EXPECT_EQ(spec.triangles[0].b, glm::dvec3(1, -1, -1));
  EXPECT_EQ(spec.triangles[0].c, glm::dvec3(1, 1, -1));
  EXPECT_EQ(spec.triangles[1].b, glm::dvec3(1, 1, -1));
  EXPECT_EQ(spec.triangles[1].c, glm::dvec3(-1, 1, -1));
  EXPECT_EQ(spec.triangles[1].material, 1);
  const Scene wide = parse_scene_text(kLight + "floor -0.5 centre 2 3 size 50\n", "t");
  EXPECT_EQ(wide.triangles[0].a, glm::dvec3(-48, -47, -0.5));
  EXPECT_EQ(wide.triangles[0].c, glm::dvec3(52, 53, -0.5));
  EXPECT_TRUE(wide.warnings.empty());
  EXPECT_EQ(error_of(kLight + "floor -1 size 0\n"), "t.scene:2:15: the floor size must be positive, got 0");
  EXPECT_EQ(error_of(kLight + "floor -1 centre 1e308 0 size 1e308\n"),
            "t.scene:2:1: the floor's corners overflow double precision: make it smaller");
  EXPECT_EQ(error_of(kLight + "floor\n"), "t.scene:2:6: expected a number for the floor height, got end of line");
}

TEST(SceneParser, AMaterialMayCatchShadows) {
  const Scene s = parse_scene_text(kLight + "material catch shadow-catcher diffuse 1 1 1\nmaterial plain\n", "t");
  EXPECT_TRUE(s.materials[1].shadow_catcher);
  EXPECT_FALSE(s.materials[2].shadow_catcher);
  EXPECT_FALSE(s.materials[0].shadow_catcher);
}

TEST(SceneParser, AntialiasSaysTheSamplesASceneIsDrawnWith) {
  EXPECT_FALSE(parse_scene_text(kLight, "t").antialias);
  EXPECT_EQ(parse_scene_text(kLight + "antialias 3\n", "t").antialias, 3);
  EXPECT_EQ(error_of(kLight + "antialias 5\n"), "t.scene:2:11: antialias takes a whole number of samples per side from 1 to 4, got 5");
  EXPECT_EQ(error_of(kLight + "antialias 2.5\n"), "t.scene:2:11: antialias takes a whole number of samples per side from 1 to 4, got 2.5");
  EXPECT_EQ(error_of(kLight + "antialias 2\nantialias 2\n"), "t.scene:3:1: a second antialias statement");
  // `all`: every pixel, as --antialias-all asks.
  EXPECT_FALSE(parse_scene_text(kLight + "antialias 3\n", "t").antialias_all);
  EXPECT_TRUE(parse_scene_text(kLight + "antialias 2 all\n", "t").antialias_all);
  EXPECT_EQ(error_of(kLight + "antialias 2 every\n"), "t.scene:2:13: unknown keyword \"every\" in antialias (expected all)");
}

// The picture's size, which --size overrides: whole pixels, 1 to 16384 a side.
TEST(SceneParser, SizeSaysThePicturesWidthAndHeight) {
  EXPECT_FALSE(parse_scene_text(kLight, "t").size);
  EXPECT_EQ(parse_scene_text(kLight + "size 640 480\n", "t").size, (std::pair{640, 480}));
  EXPECT_EQ(error_of(kLight + "size 640\n"), "t.scene:2:9: expected a number for the picture height, got end of line");
  EXPECT_EQ(error_of(kLight + "size 0 480\n"), "t.scene:2:6: size takes the picture's width in whole pixels from 1 to 16384, got 0");
  EXPECT_EQ(error_of(kLight + "size 640 480.5\n"),
            "t.scene:2:10: size takes the picture's height in whole pixels from 1 to 16384, got 480.5");
  EXPECT_EQ(error_of(kLight + "size 1 1\nsize 2 2\n"), "t.scene:3:1: a second size statement");
}

// A studio's fill: a headlight, a hemisphere and a tone curve, each said
// once; a spec scene has none, and is clipped as before.
TEST(SceneParser, AFillLightAndAToneCurveAreSaidOnce) {
  const Scene none = parse_scene_text(kLight, "t");
  EXPECT_EQ(none.fill.headlight, glm::dvec3(0.0));
  EXPECT_EQ(none.fill.sky, glm::dvec3(0.0));
  EXPECT_EQ(none.fill.ground, glm::dvec3(0.0));
  EXPECT_EQ(none.tone, ToneCurve::kClip);
  const Scene s = parse_scene_text(kLight + "headlight 0.3 0.3 0.4\nhemisphere ground 0.1 0.1 0.1 sky 0.3 0.3 0.3 up 0 0 2\ntone soft\n", "t");
  EXPECT_EQ(s.fill.headlight, glm::dvec3(0.3, 0.3, 0.4));
  EXPECT_EQ(s.fill.sky, glm::dvec3(0.3));
  EXPECT_EQ(s.fill.ground, glm::dvec3(0.1));
  EXPECT_EQ(s.fill.up, glm::dvec3(0, 0, 1));  // made unit
  EXPECT_EQ(s.tone, ToneCurve::kSoft);
  EXPECT_EQ(parse_scene_text(kLight + "hemisphere sky 1 1 1\n", "t").fill.up, glm::dvec3(0, 0, 1));  // +z unless told
  EXPECT_EQ(error_of(kLight + "headlight 1 1 1\nheadlight 1 1 1\n"), "t.scene:3:1: a second headlight statement (the first is at line 2)");
  EXPECT_EQ(error_of(kLight + "headlight -1 1 1\n"), "t.scene:2:11: the headlight intensity must not be negative");
  EXPECT_EQ(error_of(kLight + "hemisphere sky 1 1 1 up 0 0 0\n"), "t.scene:2:25: the hemisphere's up must not be (0, 0, 0)");
  EXPECT_EQ(error_of(kLight + "tone filmic\n"), "t.scene:2:6: unknown tone curve \"filmic\" (expected clip or soft)");
  EXPECT_EQ(error_of(kLight + "tone soft\ntone clip\n"), "t.scene:3:1: a second tone statement (the first is at line 2)");
}

TEST(SceneParser, NumbersInCLocaleWithExponentsAndSigns) {
  const Scene s = parse_scene_text("light +1e-3 -0.5 2.5E0\n", "t");
  EXPECT_EQ(s.lights[0].position, glm::dvec3(1e-3, -0.5, 2.5));
}

TEST(SceneParserErrors, MisspelledNumberNamesWhatWasExpected) {
  EXPECT_EQ(error_of(kLight + "sphere 0 0 0 O.5\n"),
            "t.scene:2:14: expected a number for the sphere radius, got \"O.5\"");
}

TEST(SceneParserErrors, MissingNumberPointsAtTheEndOfTheLine) {
  EXPECT_EQ(error_of(kLight + "sphere 0 0 0\n"), "t.scene:2:13: expected a number for the sphere radius, got end of line");
}

TEST(SceneParserErrors, NanAndInfAreNotNumbers) {
  EXPECT_EQ(error_of("light nan 0 2\n"), "t.scene:1:7: expected a number for the light position x, got \"nan\"");
  EXPECT_EQ(error_of("light 0 inf 2\n"), "t.scene:1:9: expected a number for the light position y, got \"inf\"");
  EXPECT_EQ(error_of("light 0 0 1e999\n"), "t.scene:1:11: expected a number for the light position z, got \"1e999\"");
}

TEST(SceneParserErrors, UnknownStatement) {
  EXPECT_EQ(error_of(kLight + "  cube 0 0 0 1\n"),
            "t.scene:2:3: unknown statement \"cube\" (expected light, material, sphere, triangle, mesh, camera, background, floor, "
            "antialias, size, headlight, hemisphere or tone)");
}

TEST(SceneParserErrors, KeywordsAreLowerCase) {
  EXPECT_EQ(error_of("Light 0 0 2\n"),
            "t.scene:1:1: unknown statement \"Light\" (expected light, material, sphere, triangle, mesh, camera, background, floor, "
            "antialias, size, headlight, hemisphere or tone)");
}

TEST(SceneParserErrors, UnknownKeyword) {
  EXPECT_EQ(error_of("light 0 0 2 colour 1 1 1\n"),
            "t.scene:1:13: unknown keyword \"colour\" in light (expected color or ambient)");
}

TEST(SceneParserErrors, KeywordGivenTwice) {
  EXPECT_EQ(error_of("light 0 0 2 color 1 1 1 color 1 1 1\n"), "t.scene:1:25: keyword \"color\" is given twice");
}

TEST(SceneParserErrors, NegativeColor) {
  EXPECT_EQ(error_of("light 0 0 2 color 1 -1 1\n"), "t.scene:1:19: the light color must not be negative");
}

TEST(SceneParserErrors, UndefinedMaterial) {
  EXPECT_EQ(error_of(kLight + "sphere 0 0 0 0.5 material red\n"),
            "t.scene:2:27: material \"red\" is not defined (define it on an earlier line)");
}

TEST(SceneParserErrors, MaterialUsedBeforeItsDefinition) {
  EXPECT_EQ(error_of(kLight + "sphere 0 0 0 0.5 material red\nmaterial red\n"),
            "t.scene:2:27: material \"red\" is not defined (define it on an earlier line)");
}

TEST(SceneParserErrors, MaterialDefinedTwice) {
  EXPECT_EQ(error_of(kLight + "material red\nmaterial red diffuse 1 0 0\n"),
            "t.scene:3:10: material \"red\" is already defined at line 2");
}

TEST(SceneParserErrors, NonPositiveRadius) {
  EXPECT_EQ(error_of(kLight + "sphere 0 0 0 -0.5\n"), "t.scene:2:14: the sphere radius must be positive, got -0.5");
  EXPECT_EQ(error_of(kLight + "sphere 0 0 0 0\n"), "t.scene:2:14: the sphere radius must be positive, got 0");
}

TEST(SceneParserErrors, TrailingTokens) {
  EXPECT_EQ(error_of(kLight + "triangle 0 0 0 1 0 0 0 1 0 material\n"),
            "t.scene:2:36: expected a material name, got end of line");
  EXPECT_EQ(error_of("light 0 0 2 color 1 1 1 ambient 0 0 0 extra\n"),
            "t.scene:1:39: unknown keyword \"extra\" in light (expected color or ambient)");
}

TEST(SceneParserErrors, UnterminatedQuote) {
  EXPECT_EQ(error_of(kLight + "mesh \"bunny.obj\n"), "t.scene:2:6: unterminated quoted path (missing closing \")");
}

TEST(SceneParserErrors, MeshStatementSyntaxIsCheckedBeforeAnyFileIsRead) {
  EXPECT_EQ(error_of(kLight + "mesh \"my bunny.obj\" scale 2 rotate 0 1 0 90 translate 0 0 0\n"),
            "t.scene:2:6: mesh file \"my bunny.obj\": cannot open: No such file or directory");
  EXPECT_EQ(error_of(kLight + "mesh bunny.obj scale two\n"), "t.scene:2:22: expected a number for the mesh scale, got \"two\"");
  EXPECT_EQ(error_of(kLight + "mesh bunny.obj scale 0\n"), "t.scene:2:22: the mesh scale must be positive, got 0");
  EXPECT_EQ(error_of(kLight + "mesh bunny.obj rotate 0 0 0 30\n"),
            "t.scene:2:23: the mesh rotation axis must not be (0, 0, 0)");
  // A later syntax error is reported before the missing file.
  EXPECT_EQ(error_of(kLight + "mesh bunny.obj\nsphere 0 0 0 -1\n"), "t.scene:3:14: the sphere radius must be positive, got -1");
}

// Scenes that load real mesh files, written into a folder of the test's own:
// ctest runs tests side by side, and two of them write different "open.obj" files.
class SceneMeshes : public test::ScratchFolder {
 protected:
  void SetUp() override {
    ScratchFolder::SetUp();
    std::filesystem::create_directories(folder_ / "parts");
  }
  // The folder's path with a trailing separator, to which file names are appended.
  std::string dir() const { return folder_.string() + "/"; }
  Scene parse(const std::string& text) { return parse_scene_text(text, dir() + "s.scene"); }
  std::string error(const std::string& text) {
    try {
      parse(text);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
};

const char* const kTetrahedronObj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";

// `plain`: the statement's material alone, without the file's vertex colours.
TEST_F(SceneMeshes, APlainMeshIsDrawnInItsStatementsMaterialAlone) {
  write("coloured.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                        "property uchar red\nproperty uchar green\nproperty uchar blue\nelement face 1\n"
                        "property list uchar int vertex_indices\nend_header\n0 0 0 255 0 0\n1 0 0 0 255 0\n0 1 0 0 0 255\n3 0 1 2\n");
  EXPECT_EQ(parse("light 0 0 5\nmesh coloured.ply\n").meshes[0].triangle_colors.size(), 1u);
  EXPECT_TRUE(parse("light 0 0 5\nmesh coloured.ply plain\n").meshes[0].triangle_colors.empty());
}

// `smooth`: the file's normals, made unit and turned with the mesh (a
// scale turns none), where it gives them: OBJ vn and PLY nx ny nz. A face
// with a corner the file gives none is drawn flat. Without `smooth`, none.
TEST_F(SceneMeshes, ASmoothMeshIsShadedInItsFilesNormalsTurnedWithIt) {
  write("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvn 0 0 2\nvn 1 0 1\n"
                   "f 1//1 2//2 3//1\nf 2//2 4 3//1\n");
  EXPECT_TRUE(parse("light 0 0 5\nmesh tri.obj\n").meshes[0].triangle_normals.empty());
  const Mesh m = parse("light 0 0 5\nmesh tri.obj smooth 30 scale 3 rotate 0 0 1 90\n").meshes[0];
  ASSERT_EQ(m.triangle_normals.size(), 2u);
  const float h = float(std::sqrt(0.5));
  // (1, 0, 1) made unit and turned 90 degrees about z: (0, h, h).
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(m.triangle_normals[0][0][k], glm::vec3(0, 0, 1)[k], 1e-6);
    EXPECT_NEAR(m.triangle_normals[0][1][k], glm::vec3(0, h, h)[k], 1e-6);
    EXPECT_NEAR(m.triangle_normals[0][2][k], glm::vec3(0, 0, 1)[k], 1e-6);
  }
  for (const glm::vec3& n : m.triangle_normals[1]) EXPECT_EQ(n, glm::vec3(0.0f));  // corner 4 has no vn
  write("tri.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                   "property float nx\nproperty float ny\nproperty float nz\nelement face 1\n"
                   "property list uchar int vertex_indices\nend_header\n0 0 0 0 0 1\n1 0 0 0 3 4\n0 1 0 0 0 -1\n3 0 1 2\n");
  const Mesh ply = parse("light 0 0 5\nmesh tri.ply smooth 30\n").meshes[0];
  ASSERT_EQ(ply.triangle_normals.size(), 1u);
  EXPECT_EQ(ply.triangle_normals[0][0], glm::vec3(0, 0, 1));
  EXPECT_NEAR(ply.triangle_normals[0][1].y, 0.6f, 1e-6);
  EXPECT_NEAR(ply.triangle_normals[0][1].z, 0.8f, 1e-6);
  EXPECT_EQ(ply.triangle_normals[0][2], glm::vec3(0, 0, -1));  // as written: the shader turns it to the seen side
}

// Without normals in the file, `smooth DEG` makes them from the faces
// (crease_normals.hpp): a cube's stay its faces' under 30 degrees.
TEST_F(SceneMeshes, ASmoothMeshWithoutNormalsHasItsCreases) {
  write("cube.obj", test::obj_text(test::unit_cube()));
  const Mesh m = parse("light 0 0 5\nmesh cube.obj smooth 30\n").meshes[0];
  ASSERT_EQ(m.triangle_normals.size(), 12u);
  for (size_t t = 0; t < 12; ++t) {
    const auto& [a, b, c] = m.triangles[t];
    const glm::dvec3 face = glm::normalize(glm::cross(m.positions[b] - m.positions[a], m.positions[c] - m.positions[a]));
    for (const glm::vec3& n : m.triangle_normals[t])
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(n[k], face[k], 1e-6);
  }
  EXPECT_EQ(error("light 0 0 5\nmesh cube.obj smooth 200\n"), dir() + "s.scene:2:22: the crease angle must be from 0 to 180 degrees, got 200");
}

// OBJ's Ns 0 is a matte surface, as exporters write it: no highlight, not
// Phong's cos^0 that would light the whole face with Ks; so is any Ns under
// 1 (assimp's regr_3429812.mtl has Ns 0.75 with Ks 0.85, which lit its quad
// white), and illum 1.
TEST_F(SceneMeshes, AnObjMaterialOfShininessUnderOneIsMatte) {
  write("box.mtl", "newmtl matte\nKd 0.2 0.2 0.2\nKs 0.9 0.9 0.9\nNs 0\nnewmtl shiny\nKd 0.2 0.2 0.2\nKs 0.9 0.9 0.9\nNs 40\n"
                   "newmtl diffuse\nKs 0.9 0.9 0.9\nNs 40\nillum 1\nnewmtl rough\nKs 0.85 0.85 0.85\nNs 0.75\n"
                   "newmtl broad\nKs 0.5 0.5 0.5\nNs 1\n");
  write("box.obj", "mtllib box.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nusemtl matte\nf 1 2 3\nusemtl shiny\nf 1 3 2\nusemtl diffuse\nf 2 4 3\n"
                   "usemtl rough\nf 2 3 4\nusemtl broad\nf 1 2 4\n");
  const Scene scene = parse("light 0 0 5\nmesh box.obj\n");
  ASSERT_EQ(scene.materials.size(), 6u);
  EXPECT_EQ(scene.materials[4].specular, glm::dvec3(0.0));  // Ns 0.75
  EXPECT_EQ(scene.materials[5].specular, glm::dvec3(0.5));  // Ns 1: Phong's cosine, kept
  EXPECT_EQ(scene.materials[3].specular, glm::dvec3(0.0));  // illum 1: diffuse alone
  EXPECT_EQ(scene.materials[1].name, "box.obj:matte");
  EXPECT_EQ(scene.materials[1].specular, glm::dvec3(0.0));
  EXPECT_EQ(scene.materials[2].specular, glm::dvec3(0.9));
  EXPECT_EQ(scene.materials[2].shininess, 40.0);
}

TEST_F(SceneMeshes, MeshIsLoadedRelativeToTheSceneAndTransformedScaleRotateTranslate) {
  write("parts/tet.obj", kTetrahedronObj);
  const Scene scene = parse("light 0 0 5\nmaterial red diffuse 1 0 0\n"
                            "mesh parts/tet.obj translate 1 2 3 rotate 0 0 1 90 material red scale 2\n");
  ASSERT_EQ(scene.meshes.size(), 1u);
  const Mesh& m = scene.meshes[0];
  EXPECT_EQ(m.path, dir() + "parts/tet.obj");
  EXPECT_EQ(m.material, 1);
  EXPECT_EQ(m.where.line, 3);
  ASSERT_EQ(m.positions.size(), 4u);
  // (1, 0, 0) scaled to (2, 0, 0), turned 90 degrees about z to (0, 2, 0), moved to (1, 4, 3).
  EXPECT_NEAR(m.positions[1].x, 1.0, 1e-15);
  EXPECT_NEAR(m.positions[1].y, 4.0, 1e-15);
  EXPECT_NEAR(m.positions[1].z, 3.0, 1e-15);
  EXPECT_EQ(m.triangles.size(), 4u);
  EXPECT_TRUE(m.components.all_cast_from_silhouette());
  ASSERT_EQ(scene.warnings.size(), 1u);
  EXPECT_EQ(scene.warnings[0].message,
            "mesh \"parts/tet.obj\" reaches outside the cube [-1,1]^3 that scenes are made for (its box is (-1, 2, 3) to (1, 4, 5); "
            "\"fit\" scales it into the cube)");
}

TEST_F(SceneMeshes, FitCentresTheBoxAndScalesItsLongestSideToTheCubeBeforeTheRest) {
  // A box from (10, 0, 0) to (20, 5, 2), as an engine part at its native size.
  write("part.obj", "v 10 0 0\nv 20 0 0\nv 10 5 0\nv 10 0 2\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
  const Mesh fitted = parse("light 0 0 5\nmesh part.obj fit\n").meshes[0];
  EXPECT_EQ(fitted.bounds_min, glm::dvec3(-1, -0.5, -0.2));
  EXPECT_EQ(fitted.bounds_max, glm::dvec3(1, 0.5, 0.2));
  // Then scale, rotate and translate, whatever their order on the line.
  const Scene moved = parse("light 0 0 5\nmesh part.obj translate 0 0 0.5 scale 0.5 rotate 0 0 1 90 fit\n");
  EXPECT_NEAR(moved.meshes[0].bounds_min.x, -0.25, 1e-15);
  EXPECT_NEAR(moved.meshes[0].bounds_max.y, 0.5, 1e-15);
  EXPECT_NEAR(moved.meshes[0].bounds_min.z, 0.4, 1e-15);
  EXPECT_TRUE(moved.warnings.empty());
  // Fitted and then moved out of the cube, it still warns (without the advice to fit).
  const Scene out = parse("light 0 0 5\nmesh part.obj fit translate 0.5 0 0\n");
  ASSERT_EQ(out.warnings.size(), 1u);
  EXPECT_EQ(out.warnings[0].message,
            "mesh \"part.obj\" reaches outside the cube [-1,1]^3 that scenes are made for (its box is (-0.5, -0.5, -0.2) to (1.5, 0.5, 0.2))");
  // An open mesh outside the cube gets both warnings.
  write("open.obj", "v 0 0 0\nv 2 0 0\nv 0 2 0\nv 0 0 2\nf 1 3 2\nf 1 2 4\nf 1 4 3\n");
  const Scene open = parse("light 0 0 5\nmesh open.obj\n");
  ASSERT_EQ(open.warnings.size(), 2u);
  EXPECT_EQ(open.warnings[1].message, "mesh \"open.obj\" is open, 1 hole: edge-multiplicity volume");
  write("point.obj", "v 1 1 1\nv 1 1 1\nv 1 1 1\nf 1 2 3\n");
  EXPECT_EQ(error("light 0 0 5\nmesh point.obj fit\n"),
            dir() + "s.scene:2:6: mesh file \"" + dir() + "point.obj\" has no faces with area to fit");
  // Corners on one line: triangles, but no area either.
  write("line.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n");
  EXPECT_EQ(error("light 0 0 5\nmesh line.obj fit\n"),
            dir() + "s.scene:2:6: mesh file \"" + dir() + "line.obj\" has no faces with area to fit");
  // A 1e-3 cube far from the origin, fitted: its points land past the
  // cube's faces by rounding alone (about 1e-5), which is no warning.
  write("far.obj", test::obj_text(test::box_triangles(glm::dvec3(1e7, -1e7, 3e7), glm::dvec3(1e7 + 1e-3, -1e7 + 1e-3, 3e7 + 1e-3))));
  const Scene far = parse("light 0 0 5\nmesh far.obj fit\n");
  EXPECT_TRUE(far.warnings.empty()) << far.warnings[0].message;
  EXPECT_GT(glm::compMax(far.meshes[0].bounds_max), 1.0 - 1e-4);
}

TEST_F(SceneMeshes, FitMeasuresTheFacesNotPointsNoFaceUses) {
  // A cube at 100-101 and a stray point at the origin that no face uses:
  // the cube fills the cube [-1,1]^3, not a corner of it.
  write("stray.obj", test::obj_text(test::box_triangles(glm::dvec3(100.0), glm::dvec3(101.0))) + "v 0 0 0\n");
  const Mesh fitted = parse("light 0 0 5\nmesh stray.obj fit\n").meshes[0];
  EXPECT_EQ(fitted.bounds_min, glm::dvec3(-1.0));
  EXPECT_EQ(fitted.bounds_max, glm::dvec3(1.0));
  // An extent that overflows double precision is no extent to fit.
  write("huge.obj", "v -1e308 0 0\nv 1e308 0 0\nv 0 1 0\nf 1 2 3\n");
  EXPECT_EQ(error("light 0 0 5\nmesh huge.obj fit\n"),
            dir() + "s.scene:2:6: mesh file \"" + dir() + "huge.obj\" is too large to fit: its extent overflows double precision");
}

TEST_F(SceneMeshes, OpenMeshGetsAWarningThatSaysHowItCastsItsShadow) {
  write("open.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\n");
  const Scene scene = parse("light 0 0 5\nmesh open.obj\n");
  ASSERT_EQ(scene.warnings.size(), 1u);
  EXPECT_EQ(scene.warnings[0].where.str(), dir() + "s.scene:2:1");
  EXPECT_EQ(scene.warnings[0].message,
            "mesh \"open.obj\" is open, 1 hole: edge-multiplicity volume");
  EXPECT_FALSE(scene.meshes[0].components.all_cast_from_silhouette());
}

TEST_F(SceneMeshes, ErrorInsideTheMeshFileNamesThatFileAndTheStatement) {
  write("bad.obj", "v 0 0 0\nv 1 0 nan\n");
  EXPECT_EQ(error("light 0 0 5\n\nmesh bad.obj\n"),
            dir() + "bad.obj:2:7: the vertex z coordinate is \"nan\", not a finite number (in the mesh of " + dir() +
                "s.scene:3:1)");
  write("short.stl", std::string(90, 'x'));
  EXPECT_EQ(error("light 0 0 5\nmesh short.stl\n"),
            dir() + "s.scene:2:6: mesh file \"" + dir() +
                "short.stl\": not a valid STL file: as binary STL its 2021161080 triangles need 101058054084 bytes but "
                "the file has 90, and it does not begin with \"solid\" as ascii STL does");
}

TEST_F(SceneMeshes, ManyMeshesLoadTogetherInFileOrderAndTheFirstBrokenOneIsReported) {
  write("tet.obj", kTetrahedronObj);
  write("open.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\n");
  write("bad1.obj", "v 0 0 0\nv 1 0 nan\n");
  write("bad2.obj", "v 0 0 0\nv 1 0 inf\n");
  std::string text = "light 0 0 5\n";
  for (int k = 0; k < 12; ++k)
    text += std::string(k % 3 == 1 ? "mesh open.obj" : "mesh tet.obj") + " scale 0.05 translate " + std::to_string(k) + "e-2 0 0\n";
  const Scene scene = parse(text);
  ASSERT_EQ(scene.meshes.size(), 12u);
  for (int k = 0; k < 12; ++k) {
    EXPECT_EQ(scene.meshes[size_t(k)].where.line, k + 2);
    EXPECT_EQ(scene.meshes[size_t(k)].positions[0].x, k / 100.0);
  }
  ASSERT_EQ(scene.warnings.size(), 4u);
  for (size_t w = 0; w < 4; ++w) EXPECT_EQ(scene.warnings[w].where.line, int(3 * w + 3));
  EXPECT_EQ(error(text + "mesh bad2.obj\nmesh tet.obj\nmesh bad1.obj\n"),
            dir() + "bad2.obj:2:7: the vertex z coordinate is \"inf\", not a finite number (in the mesh of " + dir() +
                "s.scene:14:1)");
}

TEST(SceneParserErrors, CameraNeedsEveryPart) {
  EXPECT_EQ(error_of(kLight + "camera eye 0 0 5 target 0 0 0 fovy 40\n"),
            "t.scene:2:38: the camera needs \"up\" (camera eye X Y Z target X Y Z up X Y Z fovy DEG)");
}

TEST(SceneParserErrors, CameraGeometry) {
  // An orthographic camera: its height instead of a lens, never both.
  const Scene ortho = parse_scene_text(kLight + "camera eye 0 0 5 target 0 0 0 up 0 1 0 orthographic 2.5\n", "t");
  EXPECT_TRUE(ortho.camera.orthographic());
  EXPECT_EQ(ortho.camera.ortho_height, 2.5);
  EXPECT_EQ(error_of(kLight + "camera eye 0 0 5 target 0 0 0 up 0 1 0 fovy 40 orthographic 2\n"),
            "t.scene:2:61: a camera has fovy (a perspective) or orthographic HEIGHT, not both");
  EXPECT_EQ(error_of(kLight + "camera eye 0 0 5 target 0 0 0 up 0 1 0 orthographic 0\n"),
            "t.scene:2:53: an orthographic camera's height must be above 0, got 0");
  EXPECT_EQ(error_of(kLight + "camera eye 0 0 5 target 0 0 0 up 0 1 0\n"),
            "t.scene:2:39: the camera needs \"fovy\" (camera eye X Y Z target X Y Z up X Y Z fovy DEG), or orthographic HEIGHT");
  EXPECT_EQ(error_of(kLight + "camera eye 0 0 5 target 0 0 0 up 0 1 0 fovy 180\n"),
            "t.scene:2:45: fovy must be between 0 and 180 degrees, got 180");
  EXPECT_EQ(error_of(kLight + "camera eye 0 0 5 target 0 0 5 up 0 1 0 fovy 40\n"),
            "t.scene:2:1: the camera eye and target are the same point");
  EXPECT_EQ(error_of(kLight + "camera eye 0 0 5 target 0 0 0 up 0 0 1 fovy 40\n"),
            "t.scene:2:1: the camera up vector is zero or parallel to the view direction");
}

TEST(SceneParserErrors, SecondCamera) {
  const std::string camera = "camera eye 0 0 5 target 0 0 0 up 0 1 0 fovy 40\n";
  EXPECT_EQ(error_of(kLight + camera + camera), "t.scene:3:1: a second camera statement (the first is at line 2)");
}

TEST(SceneParserErrors, SceneWithoutLight) {
  EXPECT_EQ(error_of("sphere 0 0 0 0.5\n"), "t.scene: the scene has no light: add a line such as \"light 0.6 0.8 1.6\"");
}

TEST(SceneParserErrors, MissingFile) {
  try {
    parse_scene_file("/nonexistent/x.scene");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "/nonexistent/x.scene: cannot open the scene file: No such file or directory");
  }
}

TEST(SceneParserWarnings, LightAtOrBelowZOne) {
  const Scene s = parse_scene_text("light 0 0 1\n", "t");
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_EQ(s.warnings[0].where.str(), "t:1:1");
  EXPECT_EQ(s.warnings[0].message,
            "light 1 has z <= 1: scenes are lit from z > 1, so the viewpoint may be in shadow");
}

TEST(SceneParserWarnings, ObjectsOutsideTheCubeAndDegenerateTriangles) {
  const Scene s = parse_scene_text(kLight + "sphere 0.9 0 0 0.2\ntriangle 0 0 0  0.5 0.5 0.5  1 1 1\n", "t");
  ASSERT_EQ(s.warnings.size(), 2u);
  EXPECT_EQ(s.warnings[0].message, "sphere reaches outside the cube [-1,1]^3 that scenes are made for");
  EXPECT_EQ(s.warnings[1].message,
            "degenerate triangle (its vertices are collinear): it covers no pixel and casts no shadow");
  EXPECT_EQ(s.warnings[1].where.line, 3);
}

}  // namespace
}  // namespace umbra
