// A mesh file's own materials (OBJ's mtllib and usemtl, glTF's base colour,
// 3MF's base materials) in the image: each face drawn in its material, by
// the GL renderer and the ray-cast reference alike.
#include <sys/stat.h>

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "image/image.hpp"
#include "mesh/io/mesh_file.hpp"
#include "scene/scene_parser.hpp"
#include "tests/mesh/interchange_writers.hpp"
#include "tests/mesh/mesh_builders.hpp"
#include "tests/render/image_agreement.hpp"
#include "tests/scratch_folder.hpp"

namespace umbra {
namespace {

class MeshMaterials : public test::ScratchFolder {
 protected:
  // The floor z = -0.5 as two squares, x < 0 (face 0) and x > 0 (face 1), with a
  // box above it to cast a shadow onto both.
  static PolygonSoup floor_of_two_squares() {
    return test::make_soup({{-1, -1, -0.5}, {0, -1, -0.5}, {0, 1, -0.5}, {-1, 1, -0.5}, {1, -1, -0.5}, {1, 1, -0.5}},
                           {{0, 1, 2}, {0, 2, 3}, {1, 4, 5}, {1, 5, 2}});
  }

  Scene scene_with(const std::string& mesh_line) {
    return parse_scene_text("light 0.3 0.2 3\nmaterial grey diffuse 0.5 0.5 0.5\n" + mesh_line +
                                "\nsphere 0 0 0 0.25 material grey\n",
                            (folder_ / "t.scene").string());
  }
};

using test::expect_images_agree;

test::RenderedImages render_both(const Scene& scene, RenderMethod method = RenderMethod::kAuto) {
  return test::render_gl_and_ray_cast(scene, 80, method);
}

// The floor spans pixels 15 to 65 of 80 each way: at x = 20 it is red (no
// green or blue), at x = 60 blue, on two rows (y = 20 and 60),
// both rows clear of the sphere's shadow.
void expect_red_left_blue_right(const Image& image) {
  for (const int y : {20, 60}) {
    EXPECT_GT(image.at(20, y, 0), 30) << "y " << y;
    EXPECT_EQ(image.at(20, y, 1), 0) << "y " << y;
    EXPECT_EQ(image.at(20, y, 2), 0) << "y " << y;
    EXPECT_GT(image.at(60, y, 2), image.at(60, y, 0) + 30) << "y " << y;  // blue, with a white highlight (Ks)
  }
}

TEST_F(MeshMaterials, ObjUsemtlColoursEachFaceInBothRenderers) {
  write("floor.mtl", "# two colours\nnewmtl red paint\nKa 0 0 0\nKd 1 0 0\n\nnewmtl blue\nKd 0 0 1\nKs 0.5 0.5 0.5\nNs 20\nmap_Kd blue.png\n");
  const PolygonSoup floor = floor_of_two_squares();
  std::string obj = "mtllib floor.mtl\n" + test::obj_text(floor);
  obj.insert(obj.find("f "), "usemtl red paint\n");
  obj.insert(obj.find("f 2 5"), "usemtl blue\n");
  write("floor.obj", obj);
  const Scene scene = scene_with("mesh floor.obj");
  ASSERT_EQ(scene.materials.size(), 4u);  // default, grey, and the file's two
  EXPECT_EQ(scene.materials[2].name, "floor.obj:red paint");
  EXPECT_EQ(scene.materials[3].specular, glm::dvec3(0.5));
  EXPECT_EQ(scene.meshes[0].triangle_materials, (std::vector<int>{2, 2, 3, 3}));
  ASSERT_EQ(scene.warnings.size(), 2u);  // and that the floor is open
  // Its texture map is missing: said once, and its faces keep Kd.
  EXPECT_EQ(scene.warnings[0].message, "material \"blue\"'s texture map \"" + (folder_ / "blue.png").string() +
                                           "\": does not exist: its faces take the material's Kd colour");
  const test::RenderedImages r = render_both(scene);
  expect_red_left_blue_right(r.gl);
  expect_red_left_blue_right(r.cpu);
  expect_images_agree(scene, r);
  for (const RenderMethod method : {RenderMethod::kShadowMap, RenderMethod::kPlanar, RenderMethod::kTriangles})
    expect_red_left_blue_right(render_both(scene, method).gl);
}

// Exports often hold a quad and two triangles over the same area. Each
// pixel takes each light's direct term once, whichever faces cover it: every
// method's image is the ray-cast one, which sees one surface per pixel.
TEST_F(MeshMaterials, OverlappingCoplanarFacesAreLitOnce) {
  // The floor z = -0.5 as a quad, and again as two triangles: along the
  // quad's own diagonal (the same depths exactly), then along the other one.
  write("doubled.obj", "v -1 -1 -0.5\nv 1 -1 -0.5\nv 1 1 -0.5\nv -1 1 -0.5\nf 1 2 3 4\nf 1 2 3\nf 1 3 4\nf 1 2 4\nf 2 3 4\n");
  // Dim enough that light counted twice would not saturate.
  const Scene scene = parse_scene_text(
      "light 0.3 0.2 3 color 0.5 0.5 0.5\nlight -0.5 0.4 2.5 color 0.3 0.3 0.3\nmaterial dim diffuse 0.4 0.4 0.4\n"
      "mesh doubled.obj material dim\nsphere 0 0 0 0.25\n",
      (folder_ / "t.scene").string());
  for (const RenderMethod method : {RenderMethod::kAuto, RenderMethod::kZFail, RenderMethod::kShadowMap, RenderMethod::kPlanar}) {
    SCOPED_TRACE(method_name(method));
    const test::RenderedImages r = render_both(scene, method);
    if (method == RenderMethod::kShadowMap || method == RenderMethod::kPlanar) {
      // Their shadows differ from the exact ones; compare lit pixels of the floor.
      for (const int y : {20, 60})
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(int(r.gl.at(20, y, c)), int(r.cpu.at(20, y, c)), 1) << "y " << y;
    } else {
      expect_images_agree(scene, r);
    }
  }
}

TEST_F(MeshMaterials, AMaterialNamedInTheSceneCoversTheFilesOwn) {
  write("floor.mtl", "newmtl red\nKd 1 0 0\n");
  std::string obj = "mtllib floor.mtl\nusemtl red\n" + test::obj_text(floor_of_two_squares());
  write("floor.obj", obj);
  const Scene scene = scene_with("mesh floor.obj material grey");
  EXPECT_EQ(scene.materials.size(), 2u);
  EXPECT_TRUE(scene.meshes[0].triangle_materials.empty());
  EXPECT_EQ(scene.meshes[0].material, 1);
}

TEST_F(MeshMaterials, MissingLibrariesAndNamesAreSaidOnce) {
  std::string obj = "mtllib gone.mtl\nusemtl red\n" + test::obj_text(floor_of_two_squares());
  write("floor.obj", obj);
  const Scene scene = scene_with("mesh floor.obj");
  ASSERT_EQ(scene.warnings.size(), 3u);  // and that the floor is open
  EXPECT_EQ(scene.warnings[0].where.line, 1);
  EXPECT_EQ(scene.warnings[0].message, "material library \"" + (folder_ / "gone.mtl").string() + "\" not found: its materials are left out");
  EXPECT_EQ(scene.warnings[1].message, "material \"red\" is in no material library: its faces keep the scene's material");
}

// A library is read from where the model's maps are (its own folder, unless
// --any-texture-path), as a regular file: one outside was read with no word
// where maps are confined, and a FIFO was called "not found".
TEST_F(MeshMaterials, ALibraryOutsideTheModelsFolderOrNotAFileIsSaidAndLeftOut) {
  std::filesystem::create_directories(folder_ / "model");
  write("outside.mtl", "newmtl red\nKd 1 0 0\n");
  ASSERT_EQ(::mkfifo((folder_ / "model" / "pipe.mtl").c_str(), 0600), 0);
  for (const auto& [library, said] :
       {std::pair{std::string("../outside.mtl"), "\" lies outside " + (folder_ / "model").string()},
        {std::string("pipe.mtl"), "\" is not a regular file (a FIFO): its materials are left out"}}) {
    write("model/floor.obj", "mtllib " + library + "\nusemtl red\n" + test::obj_text(floor_of_two_squares()));
    const Scene scene = scene_with("mesh model/floor.obj");
    ASSERT_FALSE(scene.warnings.empty());
    EXPECT_EQ(scene.warnings[0].where.line, 1);
    EXPECT_NE(scene.warnings[0].message.find(said), std::string::npos) << scene.warnings[0].message;
    EXPECT_TRUE(scene.meshes[0].triangle_materials.empty()) << library << ": its materials were read";
  }
}

// map_Kd's options: -clamp on takes coordinates outside [0, 1] to the
// map's edge; any other (-s, -o, ...) is said, not silently passed over.
TEST_F(MeshMaterials, MapOptionsAreAppliedOrSaid) {
  Image green(2, 2, 3, 0);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 2; ++x) green.at(x, y, 1) = 200;
  write_png(green, (folder_ / "green.png").string());
  write("floor.mtl", "newmtl red\nKd 1 0 0\nmap_Kd -clamp on -s 2 2 1 -o -0.5 0 0 green.png\n");
  write("floor.obj", "mtllib floor.mtl\nusemtl red\n" + test::obj_text(floor_of_two_squares()));
  const Scene scene = scene_with("mesh floor.obj");
  ASSERT_FALSE(scene.warnings.empty());
  EXPECT_EQ(scene.warnings[0].message, "material \"red\"'s map_Kd option -s 2 2 1 is not applied: its map is drawn as if the option "
                                       "were not there");
  const Material& red = scene.materials.back();  // the file's, after the scene's default and grey
  ASSERT_TRUE(red.texture) << red.name;
  EXPECT_EQ(red.texture->wrap_u, TextureImage::Wrap::kClampToEdge);
  EXPECT_EQ(red.texture->wrap_v, TextureImage::Wrap::kClampToEdge);
}

TEST_F(MeshMaterials, ABrokenLibraryIsAWarningAndANameWithSpacesIsOneLibrary) {
  // A decimal comma, as a German locale writes it: the statement is passed
  // over with a warning, the rest of the library read, the OBJ with it.
  write("my model.mtl", "newmtl red\nKd 0,8 0,2 0,2\nnewmtl blue\nKd 0 0 1\nNs x\n");
  write("floor.obj", "mtllib my model.mtl\nusemtl blue\n" + test::obj_text(floor_of_two_squares()));
  const PolygonSoup soup = read_polygon_soup((folder_ / "floor.obj").string());
  ASSERT_EQ(soup.materials.size(), 2u);
  EXPECT_EQ(soup.materials[1].diffuse, glm::dvec3(0, 0, 1));
  ASSERT_EQ(soup.warnings.size(), 1u);
  EXPECT_EQ(soup.warnings[0].line, 1);
  EXPECT_EQ(soup.warnings[0].message, "material library \"" + (folder_ / "my model.mtl").string() +
                                          "\": 2 statements it could not read were passed over, the first at line 2: "
                                          "expected a number for the red, got \"0,8\"");
  EXPECT_EQ(soup.polygon_material(0), 1);
}

TEST_F(MeshMaterials, GltfAndThreeMfColoursReachTheImage) {
  const PolygonSoup floor = floor_of_two_squares();
  // glTF: one primitive in red; 3MF: base material "blue" on every face.
  write("floor.gltf", test::gltf_json(floor, test::gltf_buffer(floor), {}));
  const Scene gltf = scene_with("mesh floor.gltf");
  const test::RenderedImages g = render_both(gltf);
  EXPECT_GT(g.gl.at(60, 20, 0), 30);
  EXPECT_EQ(g.gl.at(60, 20, 2), 0);
  expect_images_agree(gltf, g);
  write("floor.3mf", test::threemf(R"(<basematerials id="1"><base name="blue" displaycolor="#0000FF"/></basematerials>)" +
                                       test::threemf_object(2, floor, 0),
                                   R"(<item objectid="2"/>)"));
  const Scene three = scene_with("mesh floor.3mf");
  const test::RenderedImages t = render_both(three);
  EXPECT_EQ(t.gl.at(20, 20, 0), 0);
  EXPECT_GT(t.gl.at(20, 20, 2), 30);
  expect_images_agree(three, t);
}

}  // namespace
}  // namespace umbra
