// Reading mesh files as written, and the exact error for each kind of bad file.
#include <unistd.h>

#include <cctype>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "mesh/io/mesh_format.hpp"
#include "mesh/input_error.hpp"
#include "mesh/io/mapped_file.hpp"
#include "mesh/io/mesh_file.hpp"
#include "tests/mesh/read_error.hpp"

namespace umbra {
namespace {


std::vector<std::vector<uint32_t>> polygons_of(const PolygonSoup& soup) {
  std::vector<std::vector<uint32_t>> out;
  for (size_t f = 0; f < soup.polygon_count(); ++f) out.emplace_back(soup.polygon(f), soup.polygon(f) + soup.corner_count(f));
  return out;
}

const std::vector<std::vector<uint32_t>> kTetrahedronFaces = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};

TEST(MeshFile, ObjKeepsPointsAndFacesWithTheirLines) {
  const PolygonSoup soup = parse_polygon_soup(
      "# a tetrahedron\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv +0 0 1e0\nvn 0 0 1\n"
      "f 1 3 2\nf 1//1 2//1 4//1\nf -4/1 -1/2 -2/3\ng side\nusemtl red\nf 2 3 4\n",
      "t.obj");
  EXPECT_EQ(soup.format, "OBJ");
  ASSERT_EQ(soup.points.size(), 4u);
  EXPECT_EQ(soup.points[3], glm::dvec3(0, 0, 1));
  EXPECT_EQ(soup.point_lines, (std::vector<int>{2, 3, 4, 5}));
  EXPECT_EQ(polygons_of(soup), kTetrahedronFaces);
  EXPECT_EQ(soup.polygon_lines, (std::vector<int>{7, 8, 9, 12}));
}

TEST(MeshFile, OffReadsPolygonsCommentsAndCountsOnTheHeaderLine) {
  const PolygonSoup a = parse_polygon_soup(
      "OFF\n# comment\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2 255 0 0\n3 1 2 3\n", "t.off");
  EXPECT_EQ(polygons_of(a), kTetrahedronFaces);
  EXPECT_EQ(a.polygon_lines, (std::vector<int>{8, 9, 10, 11}));
  const PolygonSoup b = parse_polygon_soup("COFF 4 1 0\n0 0 0 1 1 1 1\n1 0 0 1 1 1 1\n1 1 0 1 1 1 1\n0 1 0 1 1 1 1\n4 0 1 2 3\n", "t.off");
  ASSERT_EQ(b.polygon_count(), 1u);
  EXPECT_EQ(b.corner_count(0), 4u);
}

std::string binary_stl(const std::vector<std::array<glm::vec3, 3>>& triangles) {
  std::string bytes(80, ' ');
  const uint32_t count = uint32_t(triangles.size());
  bytes.append(reinterpret_cast<const char*>(&count), 4);  // little endian on the machines we build for
  for (const auto& t : triangles) {
    const float normal[3] = {0, 0, 0};
    bytes.append(reinterpret_cast<const char*>(normal), 12);
    for (const glm::vec3& p : t) bytes.append(reinterpret_cast<const char*>(&p), 12);
    bytes.append(2, '\0');
  }
  return bytes;
}

TEST(MeshFile, StlAsciiAndBinaryGiveTheSameSoup) {
  const std::string ascii =
      "solid t\n facet normal 0 0 -1\n  outer loop\n   vertex 0 0 0\n   vertex 0 1 0\n   vertex 1 0 0\n  endloop\n endfacet\n"
      " facet normal 0 0 1\n  outer loop\n   vertex 1 0 0\n   vertex 0 1 0\n   vertex 0 0 1\n  endloop\n endfacet\nendsolid t\n";
  const PolygonSoup a = parse_polygon_soup(ascii, "t.stl");
  // A binary file whose header also begins with "solid": the size decides.
  std::string binary = binary_stl({{{{0, 0, 0}, {0, 1, 0}, {1, 0, 0}}}, {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}});
  binary.replace(0, 5, "solid");
  const PolygonSoup b = parse_polygon_soup(binary, "T.STL");
  EXPECT_EQ(a.format, "STL (ascii)");
  EXPECT_EQ(b.format, "STL (binary)");
  EXPECT_EQ(a.points, b.points);
  EXPECT_EQ(polygons_of(a), polygons_of(b));
  EXPECT_EQ(polygons_of(a), (std::vector<std::vector<uint32_t>>{{0, 1, 2}, {3, 4, 5}}));
  EXPECT_EQ(a.polygon_lines, (std::vector<int>{7, 14}));
}

// The tetrahedron as PLY in each encoding, with an extra vertex property and an extra element.
std::string ply(const std::string& format) {
  std::string header = "ply\nformat " + format + " 1.0\ncomment made by a test\nelement vertex 4\nproperty float x\n"
                       "property float y\nproperty double z\nproperty uchar red\nelement face 4\n"
                       "property list uchar int vertex_indices\nelement edge 1\nproperty int v1\nend_header\n";
  if (format == "ascii")
    return header + "0 0 0 1\n1 0 0 1\n0 1 0 1\n0 0 1 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n7\n";
  const bool big = format == "binary_big_endian";
  const auto put = [&](auto value) {
    char raw[sizeof value];
    std::memcpy(raw, &value, sizeof value);
    if (big) std::reverse(raw, raw + sizeof value);
    header.append(raw, sizeof value);
  };
  const float p[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (const auto& v : p) {
    put(v[0]);
    put(v[1]);
    put(double(v[2]));
    put(uint8_t(1));
  }
  for (const auto& f : kTetrahedronFaces) {
    put(uint8_t(3));
    for (uint32_t i : f) put(int32_t(i));
  }
  put(int32_t(7));
  return header;
}

TEST(MeshFile, PlyAsciiLittleAndBigEndianGiveTheSameSoup) {
  for (const std::string format : {"ascii", "binary_little_endian", "binary_big_endian"}) {
    SCOPED_TRACE(format);
    const PolygonSoup soup = parse_polygon_soup(ply(format), "t.ply");
    ASSERT_EQ(soup.points.size(), 4u);
    EXPECT_EQ(soup.points[3], glm::dvec3(0, 0, 1));
    EXPECT_EQ(polygons_of(soup), kTetrahedronFaces);
  }
  EXPECT_EQ(parse_polygon_soup(ply("ascii"), "t.ply").polygon_lines, (std::vector<int>{18, 19, 20, 21}));
}

TEST(MeshFile, PlyHeaderEndsOnlyAtTheLineEndHeader) {
  // A comment that mentions end_header, in ascii and in binary: the header
  // ends at the line that is end_header, give or take spaces and a CR.
  const std::string header =
      "ply\nformat FORMAT 1.0\ncomment written before end_header, by an exporter\nelement vertex 3\n"
      "property float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\n"
      "end_header \r\n";
  std::string ascii = header;
  ascii.replace(ascii.find("FORMAT"), 6, "ascii");
  const PolygonSoup a = parse_polygon_soup(ascii + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "c.ply");
  EXPECT_EQ(a.points.size(), 3u);
  ASSERT_EQ(a.polygon_count(), 1u);
  EXPECT_EQ(a.polygon_line(0), 14);
  std::string binary = header;
  binary.replace(binary.find("FORMAT"), 6, "binary_little_endian");
  const float xyz[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  binary.append(reinterpret_cast<const char*>(xyz), sizeof xyz);
  const int32_t face[3] = {0, 1, 2};
  binary += char(3);
  binary.append(reinterpret_cast<const char*>(face), sizeof face);
  const PolygonSoup b = parse_polygon_soup(binary, "c.ply");
  EXPECT_EQ(b.points, a.points);
  EXPECT_EQ(b.corners, a.corners);
}

// Exporters' quirks: read, with one warning each.
TEST(MeshFile, ExporterQuirksAreReadWithAWarning) {
  // Blender 2.47 names itself in a header line the PLY format does not have;
  // "end_header" with more after it on its line does not end the header.
  const PolygonSoup blender = parse_polygon_soup(
      "ply\nformat ascii 1.0\nCreated by Blender3D 247 - www.blender.org, source file: 'x.blend'\nelement vertex 3\n"
      "property float x\nproperty float y\nproperty float z\nend_header of a sort\nelement face 1\n"
      "property list uchar uint vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
      "blender.ply");
  EXPECT_EQ(blender.polygon_count(), 1u);
  ASSERT_EQ(blender.warnings.size(), 2u);
  EXPECT_EQ(blender.warnings[0].line, 3);
  EXPECT_EQ(blender.warnings[0].message, "unknown PLY header line \"Created\" ignored");
  EXPECT_EQ(blender.warnings[1].line, 8);
  EXPECT_EQ(blender.warnings[1].message, "unknown PLY header line \"end_header\" ignored");

  // A binary STL with a few bytes after its last triangle, whatever its name.
  const std::string stl = binary_stl({{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}}, {{{0, 0, 0}, {0, 1, 0}, {0, 0, 1}}}});
  for (const char* name : {"padded.stl", "padded"}) {
    const PolygonSoup padded = parse_polygon_soup(stl + std::string("\0\0\0\0\0", 5), name);
    EXPECT_EQ(padded.polygon_count(), 2u);
    ASSERT_EQ(padded.warnings.size(), 1u);
    EXPECT_EQ(padded.warnings[0].message, "5 bytes after the last of the 2 triangles ignored");
  }
  EXPECT_TRUE(parse_polygon_soup(stl, "exact.stl").warnings.empty());
}

// Text files as users have them: a UTF-8 byte-order mark before OBJ, OFF or
// STL; ascii STL in upper case (as admesh's example is written); a PLY whose
// lines end in a lone CR; an ascii PLY with nan in a property umbra does not
// use (a normal), which its binary form reads too.
TEST(MeshFile, TextFilesAsUsersHaveThemAreRead) {
  const std::string bom = "\xef\xbb\xbf";
  const std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  const std::string off = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  const std::string stl = "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid t\n";
  for (const std::string& text : {obj, off, stl}) {
    EXPECT_NE(detect_mesh_format(bom + text), "") << text;
    EXPECT_EQ(parse_polygon_soup(bom + text, "bom").polygon_count(), 1u) << text;
  }
  std::string upper = stl;
  for (char& c : upper) c = char(std::toupper(static_cast<unsigned char>(c)));
  EXPECT_EQ(detect_mesh_format(upper), "stl");
  EXPECT_EQ(parse_polygon_soup(upper, "upper.stl").polygon_count(), 1u);

  const std::string ply = "ply\rformat ascii 1.0\relement vertex 3\rproperty float x\rproperty float y\rproperty float z\r"
                          "element face 1\rproperty list uchar int vertex_indices\rend_header\r0 0 0\r1 0 0\r0 1 0\r3 0 1 2\r";
  EXPECT_EQ(parse_polygon_soup(ply, "cr.ply").polygon_count(), 1u);
  const std::string with_normals =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nproperty float nx\n"
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0 nan\n1 0 0 1\n0 1 0 1\n3 0 1 2\n";
  EXPECT_EQ(parse_polygon_soup(with_normals, "nan-normal.ply").polygon_count(), 1u);
  std::string nan_coordinate = with_normals;
  nan_coordinate.replace(nan_coordinate.find("0 0 0 nan"), 9, "nan 0 0 1");
  EXPECT_EQ(test::read_error_of(nan_coordinate, "nan.ply"), "nan.ply:11: vertex 0 has a coordinate that is not a finite number");
}

TEST(MeshFile, BadFilesGetTheirExactLocatedError) {
  EXPECT_EQ(test::read_error_of("v 0 0 0\nf 1 0 1\n", "a.obj"),
            "a.obj:2:5: vertex indices count from 1 (or from -1 backwards); 0 is not an index");
  EXPECT_EQ(test::read_error_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n", "a.obj"),
            "a.obj:4: face 0 refers to vertex 6 (counting from 0), but the file has 3 vertices");
  EXPECT_EQ(test::read_error_of("v 0 nan 0\n", "a.obj"), "a.obj:1:5: the vertex y coordinate is \"nan\", not a finite number");
  EXPECT_EQ(test::read_error_of("v 0 0\n", "a.obj"), "a.obj:1:6: expected a number for the vertex z coordinate, got end of line");
  EXPECT_EQ(test::read_error_of("v 0 0 0\nv 1 0 0\nf 1 2\n", "a.obj"), "a.obj:3: a face needs at least 3 vertices, this one has 2");
  EXPECT_EQ(test::read_error_of("v 0 0 0\nf 1 -3 1\n", "a.obj"),
            "a.obj:2:5: relative vertex index -3 points before the first vertex (only 1 defined so far)");
  EXPECT_EQ(test::read_error_of("OFX\n", "b.off"), "b.off:1:1: expected the header \"OFF\", got \"OFX\"");
  EXPECT_EQ(test::read_error_of("OFF BINARY\n", "b.off"),
            "b.off:1:5: binary OFF is not supported; write the mesh as text OFF, OBJ, PLY or STL");
  EXPECT_EQ(test::read_error_of("OFF\n3 1 0\n0 0 0\n1 0 0\n", "b.off"), "b.off:4: the file ends before vertex 2 of 3");
  EXPECT_EQ(test::read_error_of("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1\n", "b.off"),
            "b.off:6:6: the face has 2 vertex indices, its count says 3");
  EXPECT_EQ(test::read_error_of("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", "b.off"),
            "b.off:6:7: vertex index 3 is out of range: the file has 3 vertices, counted from 0");
  EXPECT_EQ(test::read_error_of("OFF\n-3 1 0\n", "b.off"), "b.off:2:1: the vertex count must not be negative, got -3");
  EXPECT_EQ(test::read_error_of("OFF\n3000 1 0\n", "b.off"), "b.off:2:1: the vertex count 3000 is more than a file of 13 bytes can hold");
  EXPECT_EQ(test::read_error_of("solid x\nfacet\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nendloop\n", "c.stl"),
            "c.stl:6:1: a facet needs at least 3 vertices, this one has 2");
  EXPECT_EQ(test::read_error_of("solid x\nouter loop\nvertex 0 0 0\n", "c.stl"), "c.stl:3: the file ends inside a facet (no \"endloop\")");
  EXPECT_EQ(test::read_error_of(binary_stl({{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}}}).substr(0, 120), "c.stl"),
            "c.stl: not a valid STL file: as binary STL its 1 triangles need 134 bytes but the file has 120, and it "
            "does not begin with \"solid\" as ascii STL does");
  {
    // Records are read on every core; the first bad one is named, whichever
    // thread finds a later one first.
    std::vector<std::array<glm::vec3, 3>> triangles(40000, {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0)});
    triangles[39000][2].z = std::numeric_limits<float>::infinity();
    triangles[20001][1].y = std::numeric_limits<float>::quiet_NaN();
    triangles[20002][0].x = std::numeric_limits<float>::quiet_NaN();
    EXPECT_EQ(test::read_error_of(binary_stl(triangles), "e.stl"),
              "e.stl: triangle 20001 has a vertex coordinate that is not a finite number");
  }
  EXPECT_EQ(test::read_error_of("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n", "d.ply"),
            "d.ply:4: the PLY header has no \"end_header\"");
  EXPECT_EQ(test::read_error_of("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_header\n0\n", "d.ply"),
            "d.ply: the PLY header declares no \"vertex\" element with x, y and z properties");
  EXPECT_EQ(test::read_error_of(ply("binary_little_endian").substr(0, ply("binary_little_endian").size() - 20), "d.ply"),
            "d.ply: the file ends in the middle of a list item");
  EXPECT_EQ(test::read_error_of("ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\nproperty float z\n"
                     "element face 1\nproperty list uchar float vertex_indices\nend_header\n", "d.ply"),
            "d.ply: the face's vertex indices must have an integer type");
  EXPECT_EQ(test::read_error_of("ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\nproperty float z\n"
                                "element face 1\nproperty list uchar int vertex_indices\nend_header\n7.5 0 1 2\n", "d.ply"),
            "d.ply:10:1: expected an integer for the list's length, got \"7.5\"");
  EXPECT_EQ(test::read_error_of("", "e.dae"), "e.dae: the file is empty");
}

TEST(MeshFormat, ContentDecidesTheFormatWhateverTheName) {
  EXPECT_EQ(detect_mesh_format("ply\nformat ascii 1.0\n"), "ply");
  EXPECT_EQ(detect_mesh_format("# made by hand\n\nCOFF\n3 1 0\n"), "off");
  EXPECT_EQ(detect_mesh_format("OFF 3 1 0\n"), "off");
  EXPECT_EQ(detect_mesh_format("solid part\n  facet normal 0 0 1\n"), "stl");
  EXPECT_EQ(detect_mesh_format(binary_stl({{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}}})), "stl");
  EXPECT_EQ(detect_mesh_format("# exporter 1.0\nmtllib a.mtl\no cube\nv 0 0 0\n"), "obj");
  EXPECT_EQ(detect_mesh_format("f 1 2 3\n"), "obj");
  // Not meshes: prose, a binary STL one byte short, a JPEG, UTF-16, JSON that is no glTF.
  EXPECT_EQ(detect_mesh_format("# umbra\nThis is a README.\nv 1 2 3\n"), "");
  EXPECT_EQ(detect_mesh_format(binary_stl({{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}}}).substr(0, 133)), "");
  EXPECT_EQ(detect_mesh_format(std::string("\xff\xd8\xff\xe0\0\x10JFIF", 10)), "");
  EXPECT_EQ(detect_mesh_format(std::string("\xff\xfev\0 \0", 6)), "");
  EXPECT_EQ(detect_mesh_format("{\"name\": \"umbra\", \"version\": \"2.0\"}"), "");

  // Read by content: an OFF named .stl, an STL with no extension.
  EXPECT_EQ(parse_polygon_soup("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "mislabelled.stl").format, "OFF");
  EXPECT_EQ(parse_polygon_soup(binary_stl({{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}}}), "part").polygon_count(), 1u);
}

// Binary files whose bytes 80-83 happen to count about as many 50-byte
// records as follow: a binary STL only when its records are STL's (finite
// numbers, normals of length 0 or 1), not by its size alone. NFF's "v" (a
// viewpoint with no numbers) is not OBJ's.
TEST(MeshFormat, ABinaryFileWithAPlausibleCountIsNoStl) {
  std::string blob(1400, '\0');
  uint32_t state = 12345;
  for (char& c : blob) c = char((state = state * 1103515245u + 12345u) >> 24);
  const uint32_t count = 26;  // 84 + 26 * 50 = 1384: 16 bytes to spare
  std::memcpy(&blob[80], &count, 4);
  EXPECT_EQ(detect_mesh_format(blob), "");
  EXPECT_EQ(test::read_error_of(blob, "scene.bin"), "scene.bin: not a mesh file (" + mesh_format_names() + "): binary data");
  // Named as one of Assimp's formats, it is that format's, whose importer says why it is none.
  EXPECT_EQ(test::read_error_of(blob, "scene.3ds"), "scene.3ds: Assimp's Discreet 3DS Importer cannot read it: Chunk is too large");
  // The same count over real STL records is still an STL with trailing bytes.
  const std::string stl = binary_stl({{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}}, {{{0, 0, 0}, {0, 1, 0}, {0, 0, 1}}}});
  EXPECT_EQ(detect_mesh_format(stl + std::string(16, '\x7f')), "stl");
  EXPECT_EQ(detect_mesh_format("v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 45\nhither 1\nresolution 64 64\n"
                               "f 1.0 0.0 0.0 0.5 0.5 8 0\npp 3\n"),
            "");
  const std::string models = "/usr/share/assimp/models/";
  if (!std::filesystem::exists(models)) GTEST_SKIP() << "needs Debian's assimp-testmodels (build.sh installs it)";
  // Real 3DS and NFF files: none an STL (nor an OBJ), each Assimp's by its name.
  for (const char* name : {"3DS/cube_with_diffuse_texture.3DS", "3DS/cube_with_specular_texture.3DS", "NFF/NFF/cone.nff",
                           "NFF/NFF/WithCamera.nff", "NFF/NFF/hexahedron.nff"}) {
    EXPECT_EQ(detect_mesh_format(MappedFile(models + name).bytes()), "") << name;
    EXPECT_EQ(detect_mesh_format_of_file(models + name), "assimp") << name;
  }
}

TEST(MeshFormat, FilesThatAreNoMeshSayWhatTheyAre) {
  EXPECT_EQ(test::read_error_of("# umbra\nThis is a README.\n", "README.obj"),
            "README.obj: not a mesh file (" + mesh_format_names() + "): text starting with \"#\"");
  EXPECT_EQ(test::read_error_of("Just words\n", "notes"), "notes: not a mesh file (" + mesh_format_names() + "): text starting with \"Just\"");
  EXPECT_EQ(test::read_error_of(std::string("\xff\xfev\0 \0", 6), "u16.obj"), "u16.obj: not a mesh file (" + mesh_format_names() + "): UTF-16 text");
  EXPECT_EQ(test::read_error_of(std::string("\xff\xd8\xff\xe0\0\x10JFIF", 10), "photo.obj"),
            "photo.obj: not a mesh file (" + mesh_format_names() + "): a JPEG image");
  // Empty, or blank lines alone: said so whatever the name, no format's error.
  EXPECT_EQ(test::read_error_of("", "empty.obj"), "empty.obj: the file is empty");
  EXPECT_EQ(test::read_error_of("", "empty.stl"), "empty.stl: the file is empty");
  EXPECT_EQ(test::read_error_of("\n\r\n  \n", "blank.off"), "blank.off: the file holds only blank lines");
}

TEST(MeshFile, MissingFileAndFolderAreReportedByName) {
  try {
    read_polygon_soup("/nonexistent/m.obj");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "/nonexistent/m.obj: cannot open: No such file or directory");
  }
  const std::string folder = ::testing::TempDir() + "folder.obj";
  std::filesystem::create_directories(folder);
  try {
    read_polygon_soup(folder);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), folder + ": is a folder, not a mesh file");
  }
}

// Any bytes give a soup or an InputError: never a crash, a hang or another exception.
// A file cut short while it is mapped: reading past its new end would end
// the process with SIGBUS. Its lost pages read as zeros, the mapping says it
// was cut short, and reading a mesh so says instead of crashing.
TEST(MeshFile, AFileCutShortWhileMappedReadsAsZerosAndSaysSo) {
  const std::string path = testing::TempDir() + "umbra-cut-" + std::to_string(::getpid()) + ".stl";
  std::string stl = binary_stl(std::vector<std::array<glm::vec3, 3>>(40000, {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}}));
  std::ofstream(path, std::ios::binary) << stl;
  {
    const MappedFile file(path);
    EXPECT_FALSE(file.cut_short());
    ASSERT_EQ(::truncate(path.c_str(), 100), 0);
    const std::string_view bytes = file.bytes();
    size_t nonzero = 0;
    for (size_t i = 8192; i < bytes.size(); i += 4096) nonzero += bytes[i] != 0;  // every lost page
    EXPECT_EQ(nonzero, 0u);
    EXPECT_TRUE(file.cut_short());
    EXPECT_EQ(parse_polygon_soup(bytes, path).polygon_count(), 40000u);  // read to the end, zeros and all
  }
  const MappedFile again(path);  // a fresh mapping of the short file is whole
  EXPECT_FALSE(again.cut_short());
  std::remove(path.c_str());
}

TEST(MeshFile, MangledFilesNeverCrashTheReaders) {
  const std::vector<std::pair<std::string, std::string>> seeds = {
      {"m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf -1 -2 -3\n"},
      {"m.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"},
      {"m.stl", "solid a\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n"},
      {"m.ply", ply("ascii")},
      {"n.ply", ply("binary_little_endian")},
      {"o.ply", ply("binary_big_endian")},
      {"b.stl", binary_stl({{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}}})}};
  std::mt19937 random(2026);
  size_t read = 0, refused = 0;
  for (const auto& [path, seed] : seeds) {
    for (int trial = 0; trial < 400; ++trial) {
      std::string bytes = seed;
      const int edits = 1 + int(random() % 4);
      for (int e = 0; e < edits && !bytes.empty(); ++e) {
        const size_t at = random() % bytes.size();
        switch (random() % 4) {
          case 0: bytes[at] = char(random() % 256); break;
          case 1: bytes.erase(at, 1 + random() % 8); break;
          case 2: bytes.insert(at, 1, "0123456789-+.e /\n#"[random() % 18]); break;
          default: bytes.resize(at); break;
        }
      }
      try {
        parse_polygon_soup(bytes, path);
        ++read;
      } catch (const InputError&) {
        ++refused;
      }
    }
  }
  EXPECT_GT(read, 0u);
  EXPECT_GT(refused, 0u);
}

}  // namespace
}  // namespace umbra
