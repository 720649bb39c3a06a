// umbra render MESH --views N --passes ... -o DIR: each view's picture and
// passes, and transforms.json, whose poses and intrinsics put a point of
// the mesh file where the depth pass says it is.

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <nlohmann/json.hpp>

#include "image/exr_file.hpp"
#include "image/image.hpp"
#include "scene/staged_scene.hpp"
#include "tests/mesh/mesh_builders.hpp"
#include "tests/render/mask_comparison.hpp"
#include "tests/tools/command_fixture.hpp"

namespace umbra::test {
namespace {

using nlohmann::json;

class ViewSet : public CommandTest {
 protected:
  // A mesh file written into the scratch folder: `soup` scaled by `scale` and moved by `offset`, as OBJ.
  std::string write_obj(const std::string& name, PolygonSoup soup, double scale, const glm::dvec3& offset) const {
    for (glm::dvec3& p : soup.points) p = scale * p + offset;
    std::ofstream(path(name)) << obj_text(soup);
    return path(name);
  }
  json transforms(const std::string& folder) const { return json::parse(read(path(folder + "/transforms.json"))); }
};

// A frame's camera, in the mesh file's coordinates, as a dataset tool reads it.
struct FrameCamera {
  glm::dmat3 rotation;  // camera axes (x right, y up, z back) as columns
  glm::dvec3 eye;
  double fl_x, fl_y, cx, cy;

  FrameCamera(const json& all, const json& frame) : fl_x(all["fl_x"]), fl_y(all["fl_y"]), cx(all["cx"]), cy(all["cy"]) {
    const json& m = frame["transform_matrix"];
    for (int c = 0; c < 3; ++c)
      for (int r = 0; r < 3; ++r) rotation[c][r] = m[r][c];
    eye = {m[0][3], m[1][3], m[2][3]};
  }
  // The point's pixel (continuous, a pixel's centre at its index + 0.5) and its depth.
  glm::dvec3 project(const glm::dvec3& p) const {
    const glm::dvec3 q = glm::transpose(rotation) * (p - eye);
    return {cx + fl_x * q.x / -q.z, cy - fl_y * q.y / -q.z, -q.z};
  }
  // The direction of the ray through pixel (x, y)'s centre, scaled so that its depth is 1.
  glm::dvec3 ray(int x, int y) const { return rotation * glm::dvec3((x + 0.5 - cx) / fl_x, -(y + 0.5 - cy) / fl_y, -1.0); }
};

// A cube 10 units on a side at (100, 200, 300) in its file: the corner
// nearest each camera, projected with the frame's pose and intrinsics,
// lands on the model, and the depth pass at that pixel's centre is where
// that pixel's ray enters the cube (computed here by hand, slab by slab).
TEST_F(ViewSet, AVertexProjectedWithItsPoseLandsWhereTheDepthPassSaysItIs) {
  const std::string cube = write_obj("cube.obj", unit_cube(), 10.0, {100, 200, 300});
  const CommandResult r = run("render " + cube + " --views 4 --passes depth,object --size 96x64 -o " + path("out"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("wrote 4 views of"), std::string::npos) << r.out;
  const json all = transforms(path("out"));
  EXPECT_EQ(all["w"], 96);
  EXPECT_EQ(all["h"], 64);
  EXPECT_EQ(all["cx"], 48.0);
  EXPECT_EQ(all["cy"], 32.0);
  // The staged lens's 30 degrees across the picture's height.
  EXPECT_NEAR(double(all["fl_y"]), 32.0 / std::tan(M_PI / 12), 1e-9);
  ASSERT_EQ(all["frames"].size(), 4u);
  for (int i = 0; i < 4; ++i) {
    SCOPED_TRACE(i);
    const json& frame = all["frames"][size_t(i)];
    const std::string stem = "00" + std::to_string(i);
    EXPECT_EQ(frame["file_path"], stem + ".png");
    EXPECT_EQ(frame["depth_file_path"], stem + ".depth.exr");
    EXPECT_EQ(frame["mask_path"], stem + ".object.png");
    const FrameCamera camera(all, frame);
    const ExrPicture depth = read_exr(path("out/" + stem + ".depth.exr"));
    ASSERT_EQ(depth.channels, std::vector<std::string>{"Z"});
    ASSERT_EQ(depth.width, 96);
    const Image object = read_png(path("out/" + stem + ".object.png"));
    // OBJ is +y up: the cube's top face is y = 210. The corner nearest the eye on it.
    glm::dvec3 nearest(0.0);
    double least = std::numeric_limits<double>::infinity();
    for (const double x : {100.0, 110.0})
      for (const double z : {300.0, 310.0})
        if (const double d = glm::length(glm::dvec3(x, 210, z) - camera.eye); d < least) least = d, nearest = {x, 210, z};
    const glm::dvec3 p = camera.project(nearest);
    const int px = int(std::floor(p.x)), py = int(std::floor(p.y));
    ASSERT_TRUE(px >= 0 && px < 96 && py >= 0 && py < 64) << p.x << ", " << p.y;
    EXPECT_EQ(object.at(px, py), 255);
    // That pixel's ray eye + s ray enters the box [lo, hi] at the largest
    // of its entries into the three slabs, and leaves it at the least exit.
    const glm::dvec3 ray = camera.ray(px, py), lo(100, 200, 300), hi(110, 210, 310);
    double s = 0.0, leaves = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a) {
      const double t0 = (lo[a] - camera.eye[a]) / ray[a], t1 = (hi[a] - camera.eye[a]) / ray[a];
      s = std::max(s, std::min(t0, t1)), leaves = std::min(leaves, std::max(t0, t1));
    }
    ASSERT_LT(s, leaves) << "the pixel's ray misses the cube";
    EXPECT_NEAR(depth.values[size_t(py) * 96 + size_t(px)], s, 1e-5 * s);
    EXPECT_NEAR(s, p.z, 0.05 * p.z);  // a pixel from the corner: about its depth
    // The object pass is where the depth is finite.
    for (int y = 0; y < 64; ++y)
      for (int x = 0; x < 96; ++x)
        ASSERT_EQ(object.at(x, y) == 255, std::isfinite(depth.values[size_t(y) * 96 + size_t(x)])) << x << ", " << y;
  }
}

// A sphere of radius 5 at (10, 20, 30) in its file, seen from all round:
// each pixel's depth and normal against the true sphere's, within what its
// facets (48 rings of 96 quads, each pi/48 by at most pi/48) stray from
// it. Pixels near the outline, where a ray grazes the sphere, are left out.
// Orthographic views: transforms.json says so and gives what the picture
// spans instead of a focal length; a corner projected by it lands on the
// model, and the depth pass at that pixel is where its parallel ray (from
// the camera's plane, along its axis) enters the cube, by hand; and
// --cameras draws the same views again.
TEST_F(ViewSet, OrthographicViewsProjectByWhatThePictureSpans) {
  const std::string cube = write_obj("cube.obj", unit_cube(), 10.0, {100, 200, 300});
  const CommandResult r = run("render " + cube + " --views 3 --orthographic --passes depth,object --size 96x64 -o " + path("out"));
  ASSERT_EQ(r.status, 0) << r.err;
  const json all = transforms(path("out"));
  EXPECT_EQ(all["camera_model"], "ORTHOGRAPHIC");
  EXPECT_FALSE(all.contains("fl_x"));
  EXPECT_EQ(all["ortho_height"], all["frames"][0]["ortho_height"]);
  for (int i = 0; i < 3; ++i) {
    SCOPED_TRACE(i);
    const json& frame = all["frames"][size_t(i)];
    // Each view framed as it is: its own span.
    const double span_w = frame["ortho_width"], span_h = frame["ortho_height"];
    EXPECT_NEAR(span_w / span_h, 96.0 / 64.0, 1e-12);
    const std::string stem = "00" + std::to_string(i);
    EXPECT_TRUE(frame["umbra_camera"].contains("orthographic"));
    const glm::dmat3 rotation = FrameCamera(json{{"fl_x", 1}, {"fl_y", 1}, {"cx", 48}, {"cy", 32}}, frame).rotation;
    const glm::dvec3 eye = FrameCamera(json{{"fl_x", 1}, {"fl_y", 1}, {"cx", 48}, {"cy", 32}}, frame).eye;
    const ExrPicture depth = read_exr(path("out/" + stem + ".depth.exr"));
    const Image object = read_png(path("out/" + stem + ".object.png"));
    // The corner nearest the camera's plane; its pixel: u = cx + x w / ortho_width, v = cy - y h / ortho_height.
    glm::dvec3 nearest(0.0), q_nearest(0.0);
    double least = std::numeric_limits<double>::infinity();
    for (const double x : {100.0, 110.0})
      for (const double y : {200.0, 210.0})
        for (const double z : {300.0, 310.0}) {
          const glm::dvec3 q = glm::transpose(rotation) * (glm::dvec3(x, y, z) - eye);
          if (-q.z < least) least = -q.z, nearest = {x, y, z}, q_nearest = q;
        }
    const double u = 48.0 + q_nearest.x * 96.0 / span_w, v = 32.0 - q_nearest.y * 64.0 / span_h;
    const int px = int(std::floor(u)), py = int(std::floor(v));
    ASSERT_TRUE(px >= 0 && px < 96 && py >= 0 && py < 64) << u << ", " << v;
    EXPECT_EQ(object.at(px, py), 255);
    // The pixel's ray: from (its offset on the camera's plane) along -z of the camera.
    const glm::dvec3 origin = eye + rotation * glm::dvec3((px + 0.5 - 48.0) * span_w / 96.0, -(py + 0.5 - 32.0) * span_h / 64.0, 0.0);
    const glm::dvec3 ray = -rotation[2], lo(100, 200, 300), hi(110, 210, 310);
    double s = 0.0, leaves = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a) {
      const double t0 = (lo[a] - origin[a]) / ray[a], t1 = (hi[a] - origin[a]) / ray[a];
      s = std::max(s, std::min(t0, t1)), leaves = std::min(leaves, std::max(t0, t1));
    }
    ASSERT_LT(s, leaves) << "the pixel's ray misses the cube";
    EXPECT_NEAR(depth.values[size_t(py) * 96 + size_t(px)], s, 1e-5 * s);
  }
  const CommandResult again = run("render " + cube + " --cameras " + path("out/transforms.json") + " --passes depth,object -o " + path("again"));
  ASSERT_EQ(again.status, 0) << again.err;
  for (const std::string file : {"000.png", "002.png", "001.depth.exr", "transforms.json"})
    EXPECT_TRUE(read(path("out/" + file)) == read(path("again/" + file))) << file;
}

TEST_F(ViewSet, TheDepthAndNormalsOfASphereAreTheSurfacesWithinItsFacets) {
  const glm::dvec3 centre(10, 20, 30);
  const double radius = 5.0;
  const std::string sphere = write_obj("sphere.obj", uv_sphere(48, 96), radius, centre);
  const CommandResult r =
      run("render " + sphere + " --views 3 --views-on sphere --passes depth,normal,object --size 80x80 -o " + path("out"));
  ASSERT_EQ(r.status, 0) << r.err;
  const json all = transforms(path("out"));
  // The facets' sag: a triangle's plane lies inside the sphere by at most
  // r (1 - cos rho), rho its corners' angle from its centre, at most half
  // its quad's diagonal, (pi / 48) sqrt(2) / 2. Along a ray that meets the
  // surface at an angle whose cosine is at least 1/2, twice that.
  const double sag = radius * (1.0 - std::cos(M_PI / 48 * std::sqrt(0.5))), normal_slack = M_PI / 48;
  for (int i = 0; i < 3; ++i) {
    SCOPED_TRACE(i);
    const std::string stem = "00" + std::to_string(i);
    const FrameCamera camera(all, all["frames"][size_t(i)]);
    const ExrPicture depth = read_exr(path("out/" + stem + ".depth.exr"));
    const ExrPicture normal = read_exr(path("out/" + stem + ".normal.exr"));
    ASSERT_EQ(normal.channels, (std::vector<std::string>{"B", "G", "R"}));  // sorted by name, as EXR keeps them
    int checked = 0;
    for (int y = 0; y < 80; ++y)
      for (int x = 0; x < 80; ++x) {
        const size_t k = size_t(y) * 80 + size_t(x);
        // The ray eye + s ray meets the sphere where |eye + s ray - centre| = radius.
        const glm::dvec3 d = camera.ray(x, y), o = camera.eye - centre;
        const double a = glm::dot(d, d), b = glm::dot(o, d), c = glm::dot(o, o) - radius * radius;
        const double disc = b * b - a * c;
        if (!(disc > 0.0)) {
          EXPECT_FALSE(std::isfinite(depth.values[k]) && disc < -0.1 * a * radius * radius) << "a pixel far off the sphere " << x << ", " << y;
          continue;
        }
        const double s = (-b - std::sqrt(disc)) / a;
        const glm::dvec3 n = glm::normalize(o + s * d);
        const double facing = -glm::dot(n, glm::normalize(d));
        if (facing < 0.5) continue;  // near the outline
        ++checked;
        ASSERT_TRUE(std::isfinite(depth.values[k])) << x << ", " << y;
        EXPECT_NEAR(depth.values[k], s, 2.0 * sag + 1e-5 * s) << x << ", " << y;
        const glm::dvec3 shaded(normal.values[3 * k + 2], normal.values[3 * k + 1], normal.values[3 * k]);  // B, G, R
        EXPECT_NEAR(glm::length(shaded), 1.0, 1e-5);
        EXPECT_LT(std::acos(std::min(1.0, glm::dot(shaded, n))), normal_slack) << x << ", " << y;
      }
    EXPECT_GT(checked, 400);
  }
}

// Views over the sphere look from below too, without a floor, and each
// frames the model alone: centred, filling the frame's width or height to
// within the framing's margin (1.2), where framing the shadow on a floor
// that is not drawn once left the bull small and to one side.
TEST_F(ViewSet, ASphereOfViewsFramesTheModelAlone) {
  const std::string wuson = "/usr/share/assimp/models/OFF/Wuson.off";
  if (!fs::exists(wuson)) GTEST_SKIP() << "needs Debian's assimp-testmodels (build.sh installs it)";
  ASSERT_EQ(run("render " + wuson + " --views 8 --views-on sphere --passes object --size 100x100 -o " + path("out")).status, 0);
  for (int i = 0; i < 8; ++i) {
    SCOPED_TRACE(i);
    const Image object = read_png(path("out/00" + std::to_string(i) + ".object.png"));
    int lo_x = 100, hi_x = -1, lo_y = 100, hi_y = -1;
    for (int y = 0; y < 100; ++y)
      for (int x = 0; x < 100; ++x)
        if (object.at(x, y)) lo_x = std::min(lo_x, x), hi_x = std::max(hi_x, x), lo_y = std::min(lo_y, y), hi_y = std::max(hi_y, y);
    ASSERT_GE(hi_x, 0) << "no model in view";
    EXPECT_GE(std::max(hi_x - lo_x, hi_y - lo_y) + 1, 100 / 1.2 - 3);
    EXPECT_NEAR((lo_x + hi_x) / 2.0, 49.5, 6.0);
    EXPECT_NEAR((lo_y + hi_y) / 2.0, 49.5, 6.0);
  }
}

// Each view's shadow mask is the exact one: the GL's, against shadow rays
// from the same camera, as --mask is tested (mask_comparison.hpp).
TEST_F(ViewSet, EachViewsShadowIsTheExactShadow) {
  const std::string torus = std::string(UMBRA_SOURCE_DIR) + "/scenes/meshes/torus.obj";
  const CommandResult r = run("render " + torus + " --views 3 --passes shadow --size 72x60 -o " + path("out"));
  ASSERT_EQ(r.status, 0) << r.err;
  const json all = transforms(path("out"));
  Scene scene = parse_scene_or_mesh_file(torus);
  for (int i = 0; i < 3; ++i) {
    SCOPED_TRACE(i);
    const json& placed = all["frames"][size_t(i)]["umbra_camera"];
    scene.camera = Camera{{placed["eye"][0], placed["eye"][1], placed["eye"][2]},
                          {placed["target"][0], placed["target"][1], placed["target"][2]},
                          {placed["up"][0], placed["up"][1], placed["up"][2]}, placed["fovy"]};
    RenderSettings settings;
    settings.width = 72, settings.height = 60;
    const MaskComparison m = compare_with_reference(scene, make_render_plan(scene, settings), read_png(path("out/00" + std::to_string(i) + ".shadow.png")), 0);
    EXPECT_EQ(m.unexplained, 0) << m.first_unexplained;
    EXPECT_TRUE(within_boundary_bound(m)) << m.excused_boundary << " of " << m.boundary_pixels;
    EXPECT_GT(m.surface_pixels, 1000);
  }
}

// The views stand where the framing puts them, whatever the floor, the
// background and the passes: a dataset's masks line up with its pictures.
TEST_F(ViewSet, TheFloorTheBackgroundAndThePassesMoveNoCamera) {
  const std::string torus = std::string(UMBRA_SOURCE_DIR) + "/scenes/meshes/torus.obj";
  ASSERT_EQ(run("render " + torus + " --views 3 --size 48x48 -o " + path("plain")).status, 0);
  const json plain = transforms(path("plain"));
  const std::string variants[] = {"--floor none", "--background transparent", "--floor shadow-catcher",
                                  "--passes depth,normal,object,shadow"};
  for (const std::string& options : variants) {
    SCOPED_TRACE(options);
    ASSERT_EQ(run("render " + torus + " --views 3 --size 48x48 " + options + " -o " + path("other")).status, 0);
    const json other = transforms(path("other"));
    for (size_t i = 0; i < 3; ++i) EXPECT_EQ(other["frames"][i]["transform_matrix"], plain["frames"][i]["transform_matrix"]);
  }
  // The passes change no picture either (the rays they share once took the
  // edges' samples away from a picture the GL's larger frame had drawn).
  const std::string wuson = "/usr/share/assimp/models/OFF/Wuson.off";
  if (fs::exists(wuson)) {
    ASSERT_EQ(run("render " + wuson + " --views 2 --size 40x30 -o " + path("w1")).status, 0);
    ASSERT_EQ(run("render " + wuson + " --views 2 --size 40x30 --passes depth,shadow -o " + path("w2")).status, 0);
    for (const std::string file : {"000.png", "001.png"}) EXPECT_TRUE(read(path("w1/" + file)) == read(path("w2/" + file))) << file;
  }
  // And view 0 is the single picture umbra render draws of the file.
  ASSERT_EQ(run("render " + torus + " --size 48x48 -o " + path("single.png")).status, 0);
  EXPECT_TRUE(read(path("single.png")) == read(path("plain/000.png")));
}

// --cameras redraws a run's own views byte for byte from its
// transforms.json; a dataset tool's file, with the poses alone, draws the
// same views but for the rounding of turning its poses back into cameras.
TEST_F(ViewSet, CamerasFromATransformsFileRedrawTheViews) {
  const std::string torus = std::string(UMBRA_SOURCE_DIR) + "/scenes/meshes/torus.obj";
  const std::string passes = " --passes depth,normal,object,shadow";
  ASSERT_EQ(run("render " + torus + " --views 3 --views-on sphere --camera-elevation 50 --size 60x40" + passes + " -o " + path("a")).status, 0);
  // The sphere's views had no floor; the redraw is asked for none.
  const CommandResult again = run("render " + torus + " --cameras " + path("a/transforms.json") + " --floor none" + passes + " -o " + path("b"));
  ASSERT_EQ(again.status, 0) << again.err;
  for (const std::string file : {"000.png", "001.png", "002.png", "001.depth.exr", "002.normal.exr", "002.object.png", "001.shadow.png",
                                 "transforms.json"})
    EXPECT_TRUE(read(path("a/" + file)) == read(path("b/" + file))) << file;
  // Without umbra's own cameras: the poses and the intrinsics alone.
  json poses = transforms(path("a"));
  for (json& frame : poses["frames"]) frame.erase("umbra_camera");
  std::ofstream(path("poses.json")) << poses.dump();
  ASSERT_EQ(run("render " + torus + " --cameras " + path("poses.json") + " --floor none -o " + path("c")).status, 0);
  for (const std::string file : {"000.png", "001.png", "002.png"}) {
    const Image a = read_png(path("a/" + file)), c = read_png(path("c/" + file));
    ASSERT_EQ(c.width, 60);
    ASSERT_EQ(c.height, 40);
    size_t same = 0;
    for (size_t k = 0; k < a.pixels.size(); ++k) same += a.pixels[k] == c.pixels[k];
    EXPECT_GT(same, a.pixels.size() * 99 / 100) << file;
  }
}

TEST_F(ViewSet, ACamerasFileUmbraCannotDrawIsRefusedSayingWhy) {
  const std::string torus = std::string(UMBRA_SOURCE_DIR) + "/scenes/meshes/torus.obj";
  const std::string frame = R"({"transform_matrix": [[1,0,0,0],[0,1,0,0],[0,0,1,5],[0,0,0,1]]})";
  const std::string lens = R"("w": 40, "h": 30, "fl_x": 50, "fl_y": 50, "cx": 20, "cy": 15)";
  const std::pair<std::string, std::string> cases[] = {
      {"{\"w\": 40", "not JSON: "},
      {"[1, 2]", "a transforms.json is an object, with \"frames\""},
      {R"({"h": 30, "fl_x": 50, "fl_y": 50, "cx": 20, "cy": 15, "frames": [)" + frame + "]}", "the file needs \"w\", a finite number"},
      {R"({"w": 40, "h": 30, "fl_x": 50, "fl_y": 60, "cx": 20, "cy": 15, "frames": [)" + frame + "]}",
       "fl_x and fl_y must be one focal length above 0 (umbra draws square pixels)"},
      {R"({"w": 40, "h": 30, "fl_x": 50, "fl_y": 50, "cx": 21, "cy": 15, "frames": [)" + frame + "]}",
       "cx and cy must be the picture's centre, w / 2 and h / 2"},
      {"{" + lens + R"(, "frames": []})", "needs \"frames\", a list of at least one camera"},
      {"{" + lens + R"(, "frames": [{"transform_matrix": [[1,0,0,0],[0,1,0,0],[0,0,1]]}]})",
       "frame 0's transform_matrix needs 4 rows of 4 finite numbers"},
      {"{" + lens + R"(, "frames": [{"transform_matrix": [[1,0,0,0],[0,0,0,0],[0,0,0,5],[0,0,0,1]]}]})",
       "frame 0's transform_matrix has no camera axes"},
      {"{" + lens + R"(, "umbra_turning": "sideways", "frames": [)" + frame + "]}",
       "\"umbra_turning\" is \"model\" or \"light\": the motion that staged the frames"},
      {"{" + lens + R"(, "frames": [{"transform_matrix": [[1,0,0,0],[0,1,0,0],[0,0,1,5],[0,0,0,1]], "light_positions": [[1,2,9],[3,4,9]]}]})",
       "frame 0's \"light_positions\" must list 1 light, as the scene has"},
      {"{" + lens + R"(, "frames": [{"transform_matrix": [[1,0,0,0],[0,1,0,0],[0,0,1,5],[0,0,0,1]], "light_positions": [[1,2]]}]})",
       "frame 0's \"light_positions\" light 1 must be 3 finite numbers"},
  };
  for (const auto& [text, message] : cases) {
    std::ofstream(path("cameras.json")) << text;
    const CommandResult r = run("render " + torus + " --cameras " + path("cameras.json") + " -o " + path("d"));
    EXPECT_EQ(r.status, 1) << text;
    EXPECT_NE(r.err.find(path("cameras.json") + ": " + message), std::string::npos) << text << "\n" << r.err;
    EXPECT_FALSE(fs::exists(path("d/000.png")));
  }
  const CommandResult missing = run("render " + torus + " --cameras " + path("none.json") + " -o " + path("d"));
  EXPECT_EQ(missing.status, 1);
  EXPECT_NE(missing.err.find(path("none.json")), std::string::npos) << missing.err;
  const CommandResult both = run("render " + torus + " --cameras " + path("cameras.json") + " --views 3 -o " + path("d"));
  EXPECT_EQ(both.status, 2);
  EXPECT_NE(both.err.find("--cameras draws the views its file names; --views and --views-on place views of their own"),
            std::string::npos) << both.err;
}

// A folder's models each get their views in OUTDIR/NAME/, in worker
// processes as a folder's pictures are drawn; --json names each one's
// transforms.json, and --skip-existing passes over those newer than the file.
TEST_F(ViewSet, AFoldersModelsEachGetTheirViewsInAFolderOfTheirOwn) {
  fs::create_directories(path("in/sub"));
  fs::copy_file(std::string(UMBRA_SOURCE_DIR) + "/scenes/meshes/torus.obj", path("in/torus.obj"));
  fs::copy_file(std::string(UMBRA_SOURCE_DIR) + "/scenes/meshes/icosphere.obj", path("in/sub/icosphere.obj"));
  const std::string scene = std::string(UMBRA_SOURCE_DIR) + "/scenes/demo.scene";
  const std::string args = "render " + path("in") + " " + scene + " --views 2 --passes object --size 40x40 --json -o " + path("out");
  const CommandResult r = run(args);
  EXPECT_EQ(r.status, 1) << r.err;  // the scene has no views
  std::vector<json> lines;
  std::istringstream out(r.out);
  for (std::string line; std::getline(out, line);) lines.push_back(json::parse(line));
  ASSERT_EQ(lines.size(), 3u) << r.out;
  EXPECT_EQ(lines[0]["path"], path("in/sub/icosphere.obj"));
  EXPECT_EQ(lines[0]["picture"], path("out/sub/icosphere.obj/transforms.json"));
  EXPECT_EQ(lines[0]["status"], "drawn");
  EXPECT_EQ(lines[1]["picture"], path("out/torus.obj/transforms.json"));
  EXPECT_EQ(lines[2]["status"], "failed");
  EXPECT_EQ(lines[2]["error"], scene + ": views are drawn of a mesh file on its own, which umbra stages; this is not one (a scene "
                                       "has its own camera: --turntable turns it)");
  EXPECT_NE(r.err.find("3 files in"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("2 files' views in " + path("out") + ", 1 failed"), std::string::npos) << r.err;
  for (const std::string model : {"sub/icosphere.obj", "torus.obj"}) {
    for (const std::string file : {"000.png", "001.png", "000.object.png", "001.object.png"})
      EXPECT_TRUE(fs::exists(path("out/" + model + "/" + file))) << model << " " << file;
    EXPECT_EQ(transforms(path("out/" + model))["frames"].size(), 2u);
  }
  EXPECT_FALSE(fs::exists(path("out/demo.scene")));
  // A model's views are its single run's.
  ASSERT_EQ(run("render " + path("in/torus.obj") + " --views 2 --passes object --size 40x40 -o " + path("one")).status, 0);
  EXPECT_TRUE(read(path("one/001.png")) == read(path("out/torus.obj/001.png")));
  // A contact sheet of each model's first view; never inside a model's folder of views.
  const CommandResult sheet = run("render " + path("in") + " --views 2 --size 40x40 --skip-existing --sheet " + path("sheet.png") + " -o " + path("out"));
  EXPECT_EQ(sheet.status, 0) << sheet.err;
  EXPECT_NE(sheet.err.find("wrote the contact sheet " + path("sheet.png") + " (2 pictures)"), std::string::npos) << sheet.err;
  EXPECT_GT(read_png(path("sheet.png")).width, 2 * 40);
  const CommandResult inside = run("render " + path("in") + " --views 2 --sheet " + path("out/torus.obj/sheet.png") + " -o " + path("out"));
  EXPECT_EQ(inside.status, 2);
  EXPECT_NE(inside.err.find("--sheet " + path("out/torus.obj/sheet.png") + " is in the folder of the views of \"" + path("in/torus.obj") + "\""),
            std::string::npos) << inside.err;
  const CommandResult again = run("render " + path("in") + " --views 2 --passes object --size 40x40 --json --skip-existing -o " + path("out"));
  EXPECT_EQ(again.status, 0) << again.err;
  EXPECT_EQ(std::count(again.out.begin(), again.out.end(), '\n'), 2);
  EXPECT_EQ(again.out.find("\"drawn\""), std::string::npos) << again.out;
}

// A mesh on standard input takes the staging options and has views as a
// file does (its name once refused --camera-azimuth: "-" is no mesh file's
// name); a scene there has none.
TEST_F(ViewSet, AMeshOnStandardInputTakesTheOptionsAndViewsAFileTakes) {
  const std::string torus = std::string(UMBRA_SOURCE_DIR) + "/scenes/meshes/torus.obj";
  const CommandResult r = run("render - --views 2 --camera-azimuth 10 --size 32x32 -o " + path("piped") + " < " + torus);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("wrote 2 views of standard input (32x32)"), std::string::npos) << r.out;
  ASSERT_EQ(run("render " + torus + " --views 2 --camera-azimuth 10 --size 32x32 -o " + path("named")).status, 0);
  EXPECT_TRUE(read(path("piped/001.png")) == read(path("named/001.png")));
  ASSERT_EQ(run("render - --camera-azimuth 10 --size 32x32 -o " + path("piped.png") + " < " + torus).status, 0);
  ASSERT_EQ(run("render " + torus + " --camera-azimuth 10 --size 32x32 -o " + path("named.png")).status, 0);
  EXPECT_TRUE(read(path("piped.png")) == read(path("named.png")));
  const std::string scene = std::string(UMBRA_SOURCE_DIR) + "/scenes/demo.scene";
  const CommandResult piped_scene = run("render - --views 2 -o " + path("s") + " < " + scene);
  EXPECT_EQ(piped_scene.status, 2);
  EXPECT_NE(piped_scene.err.find("--views is for a mesh file on its own, which umbra stages; standard input holds a scene"),
            std::string::npos) << piped_scene.err;
  EXPECT_FALSE(fs::exists(path("s")));
}

TEST_F(ViewSet, OptionsThatCannotMeanAnythingForViewsAreRefused) {
  const std::string torus = std::string(UMBRA_SOURCE_DIR) + "/scenes/meshes/torus.obj";
  const std::string scene = std::string(UMBRA_SOURCE_DIR) + "/scenes/demo.scene";
  std::ofstream(path("file.txt")) << "x";
  const std::pair<std::string, std::string> cases[] = {
      {"--views 0 -o " + path("d"), "--views expects a whole number from 1 to 100000, got \"0\""},
      {"--passes depth,colour -o " + path("d"),
       "--passes takes depth, normal, object or shadow, separated by commas (colour is always drawn); got \"colour\""},
      {"--passes depth,depth -o " + path("d"), "--passes names depth twice"},
      {"--views-on cube -o " + path("d"), "--views-on takes ring or sphere, got \"cube\""},
      {"--views 3 -o " + path("file.txt"), "-o " + path("file.txt") + " is a file; --views writes each view's files in a folder: name a folder"},
      {"--views 3 -o " + path("v.png"), "-o " + path("v.png") + " names a picture, but --views writes each view's files in a folder"},
      {"--views 3", "no output folder given (-o OUTDIR): --views writes each view's files there"},
      {"--views 3 --eye 1,2,3 -o " + path("d"), "--eye is not for --views (the views stand round the model, where the framing puts them)"},
      {"--views 3 --mask m.png -o " + path("d"), "--mask is not for --views (--passes shadow draws each view's mask)"},
  };
  for (const auto& [options, message] : cases) {
    const CommandResult r = run("render " + torus + " " + options);
    EXPECT_EQ(r.status, 2) << options;
    EXPECT_NE(r.err.find(message), std::string::npos) << options << "\n" << r.err;
  }
  const CommandResult on_scene = run("render " + scene + " --views 3 -o " + path("d"));
  EXPECT_EQ(on_scene.status, 2);
  EXPECT_NE(on_scene.err.find("--views is for a mesh file on its own"), std::string::npos) << on_scene.err;
  EXPECT_FALSE(fs::exists(path("d")));
}

}  // namespace
}  // namespace umbra::test
