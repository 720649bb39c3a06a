// `umbra volume`: the volumes of a scene as a mesh file that reads back as
// closed, outward surfaces.
#include <gtest/gtest.h>

#include "mesh/check/mesh_check.hpp"
#include "mesh/io/mesh_file.hpp"
#include "tests/tools/command_fixture.hpp"

namespace umbra {
namespace {

using test::CommandResult;
namespace fs = std::filesystem;

class VolumeCommand : public test::CommandTest {};

TEST_F(VolumeCommand, IcosphereVolumeReadsBackAsAClosedOutwardSurface) {
  // The scene without its floor: the icosphere's and the sphere's volumes, apart.
  const std::string scene = write("s.scene", "light 0.2 0.7 1.8\nmesh " + std::string(UMBRA_SOURCE_DIR) +
                                                 "/scenes/meshes/icosphere.obj scale 0.3 translate -0.45 0 -0.3\n"
                                                 "sphere 0.45 0 -0.3 0.3\n");
  const CommandResult r = run("volume " + scene + " -o " + path("v.obj") + " --segments 16");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out.rfind("wrote " + path("v.obj") + ": 2 volume(s), ", 0), 0u) << r.out;
  const std::string obj = read(path("v.obj"));
  EXPECT_NE(obj.find("g mesh_line_2\n"), std::string::npos);
  EXPECT_NE(obj.find("g sphere_line_3\n"), std::string::npos);
  const MeshReport report = check_mesh(read_polygon_soup(path("v.obj")));
  ASSERT_EQ(report.components.size(), 2u);
  for (const ComponentReport& c : report.components) {
    EXPECT_TRUE(c.closed);
    EXPECT_EQ(c.genus, 0);
    EXPECT_EQ(c.outward, true);
  }
  EXPECT_EQ(report.border_edges + report.non_manifold_edges + report.inconsistent_edges, 0u);
}

// A mesh file is staged as umbra render stages it (once "unknown statement
// "OFF""), and only its own volume is written: one closed, outward
// surface, without the floor's.
TEST_F(VolumeCommand, AMeshFileIsStagedAndOnlyItsVolumeWritten) {
  const std::string tet = write("t.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  const CommandResult r = run("volume " + tet + " -o " + path("v.obj") + " --up +z");
  ASSERT_EQ(r.status, 0) << r.err;
  const MeshReport report = check_mesh(read_polygon_soup(path("v.obj")));
  EXPECT_EQ(r.out, "wrote " + path("v.obj") + ": 1 volume(s), " + std::to_string(report.triangles) + " triangles\n");
  EXPECT_NE(read(path("v.obj")).find("g mesh_line_4\n"), std::string::npos);
  ASSERT_EQ(report.components.size(), 1u);
  EXPECT_TRUE(report.components[0].closed);
  EXPECT_EQ(report.components[0].outward, true);
  const std::string jpeg = write("photo.jpg", std::string("\xff\xd8\xff\xe0\0\x10JFIF\0", 11));
  EXPECT_EQ(run("volume " + jpeg + " -o " + path("w.obj")).status, 2);
  const CommandResult up = run("volume " + write("s.scene", "light 0 0 2\nsphere 0 0 0 0.5\n") + " -o " + path("w.obj") + " --up +y");
  EXPECT_EQ(up.status, 2);
  EXPECT_FALSE(fs::exists(path("w.obj")));
}

TEST_F(VolumeCommand, BadLightAndUsageErrors) {
  const std::string scene = write("s.scene", "light 0 0 2\nsphere 0 0 0 0.5\n");
  const CommandResult light = run("volume " + scene + " -o " + path("v.obj") + " --light 2");
  EXPECT_EQ(light.status, 1);
  EXPECT_EQ(light.err, scene + ": --light 2: the scene has 1 light(s)\n");
  EXPECT_FALSE(fs::exists(path("v.obj")));
  const CommandResult none = run("volume " + scene);
  EXPECT_EQ(none.status, 2);
  EXPECT_EQ(none.err, "umbra volume: no output file given (-o OUT.obj)\n(see umbra volume --help)\n");
  const CommandResult far = run("volume " + scene + " -o x.obj --far 0");
  EXPECT_EQ(far.status, 2);
  EXPECT_EQ(far.err, "umbra volume: --far must be positive\n(see umbra volume --help)\n");
  // OBJ text under a picture's name would overwrite the picture with what
  // no image viewer reads.
  const std::string picture = write("keep.png", "a picture");
  const CommandResult png = run("volume " + scene + " -o " + picture);
  EXPECT_EQ(png.status, 2);
  EXPECT_EQ(png.err, "umbra volume: -o " + picture + ": umbra volume writes an OBJ file; name a .obj file\n(see umbra volume --help)\n");
  EXPECT_EQ(read(picture), "a picture");
  EXPECT_EQ(run("volume " + scene + " -o " + path("V.OBJ")).status, 0);
  EXPECT_EQ(run("volume " + scene + " -o /dev/null").status, 0);
}

}  // namespace
}  // namespace umbra
