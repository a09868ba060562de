// Mesh files in and out: every format round-trips exactly, every reader accepts what real files
// contain and refuses malformed input naming the file and line, and writing is atomic.
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <numeric>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "mesh/mesh_writer.hpp"
#include "stitch/mesh/build.hpp"
#include "stitch/mesh/formats.hpp"
#include "stitch/mesh/io.hpp"
#include "stitch/mesh/validate.hpp"
#include "stitch/tess/export.hpp"
#include "temp_folder.hpp"
#include "test_support.hpp"

namespace {

using stitch::Error;
using stitch::HalfedgeMesh;
using stitch::PolygonSoup;
using stitch::Vec3;
using stitch::test::error_of;
using stitch::testing::read_file;
using stitch::testing::TempFolder;

std::string example(const std::string& name) {
  return stitch::test::example_path(name + ".obj");
}

// Little-endian / big-endian bytes of a number, for hand-made binary files.
template <class T>
std::string bytes(T value, bool big_endian = false) {
  std::string out(sizeof(T), '\0');
  std::memcpy(out.data(), &value, sizeof(T));
  if (big_endian != (std::endian::native == std::endian::big)) std::reverse(out.begin(), out.end());
  return out;
}

template <class T>
T from_bytes(const std::string& data, size_t offset) {
  T value;
  std::memcpy(&value, data.data() + offset, sizeof(T));
  return value;  // the test machine is little-endian, as is the format read here
}

// A mesh whose coordinates have no short decimal form, so the round trip must be exact.
PolygonSoup awkward_torus() {
  PolygonSoup soup = stitch::to_polygon_soup(stitch::read_mesh(example("torus")));
  std::mt19937 random(12345);  // fixed seed: reproducible coordinates
  std::uniform_real_distribution<double> noise(-1, 1);
  for (Vec3& p : soup.positions) p += Vec3(noise(random), noise(random), noise(random)) / 3.0;
  soup.positions[0] = Vec3(1e-300, -1.0 / 3.0, 6.02214076e23);
  return soup;
}

class RoundTrip : public ::testing::TestWithParam<std::string> {};

TEST_P(RoundTrip, IsExact) {
  TempFolder folder;
  const PolygonSoup soup = awkward_torus();
  const std::string path = folder.file("mesh" + GetParam());
  stitch::write_polygon_soup(path, soup);
  const PolygonSoup back = stitch::read_polygon_soup(path);
  EXPECT_EQ(back.positions, soup.positions);  // exact: shortest round-trip decimal forms
  EXPECT_EQ(back.faces, soup.faces);
  EXPECT_EQ(back.source, path);
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"mesh" + GetParam()});

  // And through the half-edge mesh: same numbering, same positions.
  const HalfedgeMesh mesh = stitch::build_mesh(soup);
  stitch::write_mesh(path, mesh);
  EXPECT_EQ(stitch::read_mesh(path), mesh);
}

INSTANTIATE_TEST_SUITE_P(Formats, RoundTrip, ::testing::Values(".obj", ".off", ".ply"),
                         [](const auto& info) { return info.param.substr(1); });

TEST(WriteStl, FansPolygonsIntoBinaryTriangles) {
  TempFolder folder;
  PolygonSoup soup = stitch::to_polygon_soup(stitch::read_mesh(example("cube_hole")));
  const std::string path = folder.file("cube_hole.STL");  // extensions are case-insensitive
  stitch::write_polygon_soup(path, soup);
  const std::string data = read_file(path);
  const uint32_t triangles = 4 * 2 + 8;  // 4 quads and one 10-gon
  ASSERT_EQ(data.size(), 84 + 50 * triangles);
  EXPECT_EQ(from_bytes<uint32_t>(data, 80), triangles);
  // The first triangle is (v0, v1, v2) of the first face, with its unit normal.
  const auto& loop = soup.faces[0];
  for (int k = 0; k < 3; ++k)
    for (int c = 0; c < 3; ++c)
      EXPECT_EQ(from_bytes<float>(data, 84 + 12 + 12 * k + 4 * c),
                static_cast<float>(soup.positions[loop[k]][c]));
  const Vec3 n(from_bytes<float>(data, 84), from_bytes<float>(data, 88),
               from_bytes<float>(data, 92));
  EXPECT_NEAR(n.norm(), 1.0, 1e-6);  // float precision
}

TEST(ReadObj, AcceptsWhatRealFilesContain) {
  TempFolder folder;
  const std::string path = folder.write("tags.obj",
                                        "# comment line\r\n"
                                        "mtllib cube.mtl\r\n"
                                        "o cube\r\n"
                                        "v -1 -1 -1\r\n"
                                        "v 1 -1 -1 1.0\r\n"  // optional w
                                        "v -1 1 -1  # trailing comment\r\n"
                                        "v +1 1 -1\r\n"
                                        "v -1 -1 1 0.5 0.5 0.5\r\n"  // vertex colour
                                        "v 1 -1 1\n"
                                        "v -1 1 1\n"
                                        "v 1 1 1\n"
                                        "vt 0 0\nvt 1 0\nvn 0 0 1\nvp 0.5\n"
                                        "g group\nusemtl red\ns off\ns 1\n"
                                        "\n"
                                        "f 1/1 3/2 4/1 2/2\n"
                                        "f 5//1 6//1 8//1 7//1\n"
                                        "f 1/1/1 2/2/1 6/1/1 5/1/1\n"
                                        "f -6 -2 -1 -5\n"  // relative: 3 7 8 4
                                        "f 1 5 7 3\n"
                                        "l 1 2\n"
                                        "f 2 4 8 6\n"
                                        "t corner 1/1/0 0 10.0\n"
                                        "t crease 2/1/0 0 1 10.0\n"
                                        "unknown_statement 1 2 3\n");
  std::vector<std::string> warnings;
  const PolygonSoup soup = stitch::read_polygon_soup(path, &warnings);
  ASSERT_EQ(soup.positions.size(), 8u);
  EXPECT_EQ(soup.positions[3], Vec3(1, 1, -1));
  EXPECT_EQ(
      soup.faces,
      (std::vector<std::vector<int>>{
          {0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}}));
  EXPECT_EQ(soup.vertex_lines, (std::vector<int>{4, 5, 6, 7, 8, 9, 10, 11}));
  EXPECT_EQ(soup.face_lines, (std::vector<int>{21, 22, 23, 24, 25, 27}));
  EXPECT_EQ(soup.source, path);
  // OpenSubdiv's tags are read (vertices counted from 0); tests/test_tags_io.cpp has the rest.
  ASSERT_EQ(soup.corners.size(), 1u);
  EXPECT_EQ(soup.corners[0].vertex, 0);
  EXPECT_EQ(soup.corners[0].line, 28);
  ASSERT_EQ(soup.creases.size(), 1u);
  EXPECT_EQ(soup.creases[0].b, 1);
  EXPECT_EQ(soup.creases[0].sharpness, 10.0);
  // One warning per kind of unsupported statement, none for the silently ignored ones, and one
  // saying that the texture coordinates, which only some faces have, are not used.
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_NE(warnings[0].find("'unknown_statement'"), std::string::npos);
  EXPECT_NE(warnings[1].find("texture coordinates are not used"), std::string::npos);
  EXPECT_TRUE(soup.uvs.empty());
  EXPECT_NO_THROW((void)stitch::build_mesh(soup));
}

TEST(ReadOff, AcceptsCountsOnTheHeaderLineCommentsAndColours) {
  TempFolder folder;
  const std::string path =
      folder.write("tetra.off",
                   "OFF 4 4 6\n"
                   "# a tetrahedron\n"
                   "1 1 1\n1 -1 -1\n\n-1 1 -1\n-1 -1 1 # last\n"
                   "3 0 1 2 255 0 0\n3 0 2 3\n3 0 3 1 0.5 0.5 0.5 1\n3 1 3 2\n");
  const PolygonSoup soup = stitch::read_polygon_soup(path);
  EXPECT_EQ(soup.positions.size(), 4u);
  EXPECT_EQ(soup.faces,
            (std::vector<std::vector<int>>{{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 3, 2}}));
  EXPECT_EQ(soup.face_lines, (std::vector<int>{8, 9, 10, 11}));
  EXPECT_EQ(soup.vertex_lines, (std::vector<int>{3, 4, 6, 7}));

  const std::string split = folder.write("split.off",
                                         "COFF\n4 4 0\n1 1 1 1 0 0 1\n1 -1 -1 1 0 0 1\n"
                                         "-1 1 -1 1 0 0 1\n-1 -1 1 1 0 0 1\n"
                                         "3 0 1 2\n3 0 2 3\n3 0 3 1\n3 1 3 2\n");
  EXPECT_EQ(stitch::read_polygon_soup(split).faces, soup.faces);
}

// The same tetrahedron in every PLY encoding, with properties and elements to skip.
std::string tetra_ply(const std::string& format) {
  const bool ascii = format == "ascii";
  const bool big = format == "binary_big_endian";
  std::string header = "ply\nformat " + format +
                       " 1.0\ncomment made by hand # with a hash\nobj_info nothing\n"
                       "element vertex 4\nproperty float x\nproperty double y\n"
                       "property uchar red\nproperty float z\n"
                       "element face 4\nproperty uchar flags\n"
                       "property list uint uint vertex_index\n"
                       "element edge 1\nproperty list uchar short ends\nend_header\n";
  const float xs[] = {1, 1, -1, -1}, zs[] = {1, -1, -1, 1};
  const double ys[] = {1, -1, 1, -1};
  const std::vector<std::vector<uint32_t>> faces = {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 3, 2}};
  std::string body;
  for (int i = 0; i < 4; ++i)
    body +=
        ascii ? fmt::format("{} {} 7 {}\n", xs[i], ys[i], zs[i])
              : bytes(xs[i], big) + bytes(ys[i], big) + bytes(uint8_t{7}, big) + bytes(zs[i], big);
  for (const auto& face : faces) {
    if (ascii) {
      body += fmt::format("0 {} {}\n", face.size(), fmt::join(face, " "));
      continue;
    }
    body += bytes(uint8_t{0}, big) + bytes(static_cast<uint32_t>(face.size()), big);
    for (uint32_t v : face) body += bytes(v, big);
  }
  body +=
      ascii ? "2 0 1\n" : bytes(uint8_t{2}, big) + bytes(int16_t{0}, big) + bytes(int16_t{1}, big);
  return header + body;
}

class ReadPly : public ::testing::TestWithParam<std::string> {};

TEST_P(ReadPly, ReadsPositionsAndFacesSkippingTheRest) {
  TempFolder folder;
  const std::string path = folder.write("tetra.ply", tetra_ply(GetParam()));
  std::vector<std::string> warnings;
  const PolygonSoup soup = stitch::read_polygon_soup(path, &warnings);
  EXPECT_TRUE(warnings.empty());
  EXPECT_EQ(soup.positions,
            (std::vector<Vec3>{Vec3(1, 1, 1), Vec3(1, -1, -1), Vec3(-1, 1, -1), Vec3(-1, -1, 1)}));
  EXPECT_EQ(soup.faces,
            (std::vector<std::vector<int>>{{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 3, 2}}));
  if (GetParam() == "ascii") {
    EXPECT_EQ(soup.face_lines, (std::vector<int>{20, 21, 22, 23}));
  }
  const HalfedgeMesh mesh = stitch::build_mesh(soup);
  EXPECT_EQ(stitch::topology_stats(mesh).genus, 0);
}

TEST_P(ReadPly, RefusesAHeaderThatDeclaresMoreElementsThanTheFileHolds) {
  TempFolder folder;
  // Without the trailing edge element, so the missing face is at the very end of the file.
  std::string text = tetra_ply(GetParam());
  const std::string edge_header = "element edge 1\nproperty list uchar short ends\n";
  text.erase(text.find(edge_header), edge_header.size());
  text.resize(text.size() - (GetParam() == "ascii" ? 6 : 5));
  text.replace(text.find("element face 4"), 14, "element face 5");
  const std::string path = folder.write("lies.ply", text);
  const std::string message = error_of([&] { (void)stitch::read_polygon_soup(path); });
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_NE(message.find("truncated"), std::string::npos) << message;
  // ASCII names the line; binary names the element.
  EXPECT_NE(message.find(GetParam() == "ascii" ? "line" : "face element 4"), std::string::npos)
      << message;
}

INSTANTIATE_TEST_SUITE_P(Encodings, ReadPly,
                         ::testing::Values("ascii", "binary_little_endian", "binary_big_endian"));

TEST(ReadPly, RefusesOutOfRangeIndicesAndNonFiniteBinaryCoordinates) {
  TempFolder folder;
  std::string text = tetra_ply("binary_little_endian");
  // The last index of the last face (before the edge element) -> 4, one past the end.
  const size_t last_index = text.size() - 5 - 4;
  text.replace(last_index, 4, bytes(uint32_t{4}));
  const std::string bad_index = folder.write("index.ply", text);
  std::string message = error_of([&] { (void)stitch::read_polygon_soup(bad_index); });
  EXPECT_NE(message.find("face element 3"), std::string::npos) << message;
  EXPECT_NE(message.find("refers to vertex 4"), std::string::npos) << message;

  text = tetra_ply("binary_little_endian");
  const size_t first_x = text.find("end_header\n") + 11;
  text.replace(first_x, 4, bytes(std::numeric_limits<float>::infinity()));
  const std::string infinite = folder.write("inf.ply", text);
  message = error_of([&] { (void)stitch::read_polygon_soup(infinite); });
  EXPECT_NE(message.find("vertex element 0"), std::string::npos) << message;
  EXPECT_NE(message.find("not finite"), std::string::npos) << message;
}

// --- malformed input: refused naming the file and the line ------------------------------------

struct Malformed {
  std::string name;  // test name and file name (its extension picks the reader)
  std::string content;
  std::string expected;  // words the message must contain, besides the file name
};

void PrintTo(const Malformed& m, std::ostream* os) {
  *os << m.name;
}

class MalformedInput : public ::testing::TestWithParam<Malformed> {};

// Under --strict (repairing off), so that what the repair would fix is refused too.
TEST_P(MalformedInput, IsRefusedNamingFileAndLine) {
  TempFolder folder;
  const std::string path = folder.write(GetParam().name, GetParam().content);
  stitch::BuildOptions strict;
  strict.repair = false;
  const std::string message = error_of([&] { (void)stitch::read_mesh(path, strict); });
  ASSERT_FALSE(message.empty()) << "accepted";
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_NE(message.find(GetParam().expected), std::string::npos)
      << "expected '" << GetParam().expected << "' in: " << message;
}

const std::string kCubeVertices =
    "v -1 -1 -1\nv 1 -1 -1\nv -1 1 -1\nv 1 1 -1\nv -1 -1 1\nv 1 -1 1\nv -1 1 1\nv 1 1 1\n";
const std::string kCubeFaces = "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n";
const std::string kTetraOff = "OFF\n4 4 0\n1 1 1\n1 -1 -1\n-1 1 -1\n-1 -1 1\n";

std::string random_bytes() {
  std::mt19937 random(2024);  // fixed seed: the same garbage every run
  std::string s(512, '\0');
  for (char& c : s) c = static_cast<char>(random() & 0xff);
  s[0] = 'v';
  s[1] = ' ';
  s[2] = '\x01';  // a control byte on line 1 whatever the seed produces
  return s;
}

INSTANTIATE_TEST_SUITE_P(
    Files, MalformedInput,
    ::testing::Values(
        Malformed{"empty.obj", "", "empty"}, Malformed{"blank.off", "\n  \n", "empty"},
        Malformed{"binary_garbage.obj", random_bytes(), "line 1: not a text file"},
        Malformed{"text_garbage.obj", "hello world\n%%% !!\n", "line 2: unrecognised statement"},
        Malformed{"no_faces.obj", kCubeVertices, "no faces"},
        Malformed{"nan.obj", "v 0 0 0\nv nan 0 0\nv 1 1 1\nf 1 2 3\n", "line 2: coordinate 'nan'"},
        Malformed{"inf.obj", "v 0 0 0\nv 0 -inf 0\nv 1 1 1\nf 1 2 3\n",
                  "line 2: coordinate '-inf' is not finite"},
        Malformed{"huge.off", kTetraOff.substr(0, 16) + "1e999 -1 -1\n",
                  "line 4: number '1e999' is out"},
        Malformed{"word.obj", "v 0 0 zero\n", "line 1: 'zero' is not a number"},
        Malformed{"short_vertex.obj", "v 0 0\n", "line 1: a vertex needs 3 coordinates"},
        Malformed{"index_out_of_range.obj", kCubeVertices + "f 1 2 9\n",
                  "line 9: face refers to vertex 9, but the file has 8 vertices"},
        Malformed{"index_zero.obj", kCubeVertices + "f 0 1 2\n", "line 9: vertex index 0"},
        Malformed{"relative_too_far.obj", "v 0 0 0\nv 1 0 0\nf -1 -2 -3\n",
                  "line 3: relative vertex index -3"},
        Malformed{"bad_entry.obj", kCubeVertices + "f 1/x 2 3\n", "line 9: 'x' is not an integer"},
        Malformed{"repeated_vertex.obj", kCubeVertices + "f 1 3 3 4 2\n" + kCubeFaces.substr(10),
                  "(line 9) repeats vertex 3 (line 3) at consecutive positions"},
        Malformed{"two_vertices.obj", kCubeVertices + "f 1 2\n", "line 9) has 2 vertices"},
        Malformed{"truncated.obj", kCubeVertices + kCubeFaces.substr(0, 55),
                  "line 14) has 2 vertices"},
        Malformed{"flipped.obj", kCubeVertices + "f 2 4 3 1\n" + kCubeFaces.substr(10),
                  "inconsistent orientation"},
        Malformed{"bowtie.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv -1 0 0\nv 0 -1 0\nf 1 2 3\nf 1 4 5\n",
                  "vertex 1 (line 1) is non-manifold: its faces"},
        Malformed{"truncated.off", kTetraOff.substr(0, 32),
                  "line 5: the file ends after 3 of the 4 vertices declared"},
        Malformed{"no_faces.off", kTetraOff, "line 6: the file ends after 0 of the 4 faces"},
        Malformed{"off_index.off", kTetraOff + "3 0 1 4\n",
                  "line 7: face refers to vertex 4 (0-based), but the file has 4 vertices"},
        Malformed{"off_short_face.off", kTetraOff + "4 0 1 2\n",
                  "line 7: face declares 4 vertices but lists 3"},
        Malformed{"not_off.off", "PLY\n", "line 1: not an OFF file"},
        Malformed{"not_ply.ply", "OFF\n", "line 1: not a PLY file"},
        Malformed{"no_end_header.ply", "ply\nformat ascii 1.0\nelement vertex 0\n", "end_header"},
        Malformed{"ply_extra_values.ply",
                  "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                  "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                  "end_header\n0 0 0\n1 0 0\n0 1 0 5\n3 0 1 2\n",
                  "line 12: 1 values more than a 'vertex' element has"},
        Malformed{"ply_index.ply",
                  "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                  "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                  "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 -1\n",
                  "line 13: face refers to vertex -1"},
        Malformed{"unknown.xyz", "solid\n", "extension '.xyz'"},
        Malformed{"stl_loop.stl", "solid t\nfacet normal 0 0 1\nvertex 0 0 0\n",
                  "line 3: 'vertex' outside 'outer loop'"}),
    [](const auto& info) {
      std::string name = info.param.name;
      for (char& c : name)
        if (c == '.') c = '_';
      return name;
    });

// What --strict refuses above is repaired by default, each repair a warning.
TEST(ReadMesh, RepairsByDefault) {
  TempFolder folder;
  const std::map<std::string, std::pair<std::string, std::string>> files{
      {"repeated_vertex.obj",
       {kCubeVertices + "f 1 3 3 4 2\n" + kCubeFaces.substr(10), "removed the repeats in 1 face"}},
      {"truncated.obj",
       {kCubeVertices + kCubeFaces.substr(0, 55),
        "dropped 1 face with fewer than 3 distinct vertices: face 6 (line 14) has 2 vertices"}},
      {"flipped.obj",
       {kCubeVertices + "f 2 4 3 1\n" + kCubeFaces.substr(10),
        "flipped 1 face wound against its neighbours"}},
      {"bowtie.obj",
       {"v 0 0 0\nv 1 0 0\nv 0 1 0\nv -1 0 0\nv 0 -1 0\nf 1 2 3\nf 1 4 5\n",
        "split 1 non-manifold vertex"}}};
  for (const auto& [name, file] : files) {
    stitch::BuildReport report;
    (void)stitch::read_mesh(folder.write(name, file.first), {}, &report);
    ASSERT_FALSE(report.warnings.empty()) << name;
    EXPECT_NE(report.warnings[0].find(file.second), std::string::npos) << report.warnings[0];
  }
  // A file whose faces all go is still refused, saying why.
  const std::string path = folder.write("two_vertices.obj", kCubeVertices + "f 1 2\n");
  const std::string message = error_of([&] { (void)stitch::read_mesh(path); });
  EXPECT_NE(message.find("two_vertices.obj: no faces are left; dropped 1 face"), std::string::npos)
      << message;
}

TEST(ReadMesh, DropsUnusedVerticesWithAWarning) {
  TempFolder folder;
  const std::string path = folder.write("extra.obj", kCubeVertices + "v 5 5 5\n" + kCubeFaces);
  stitch::BuildReport report;
  const HalfedgeMesh mesh = stitch::read_mesh(path, {}, &report);
  EXPECT_EQ(mesh.num_vertices(), 8);
  EXPECT_EQ(report.dropped_vertices, 1);
  ASSERT_EQ(report.warnings.size(), 1u);
  EXPECT_NE(report.warnings[0].find("unused"), std::string::npos);
}

TEST(ReadMesh, RefusesMissingFilesAndFolders) {
  TempFolder folder;
  std::string message = error_of([&] { (void)stitch::read_mesh(folder.file("missing.obj")); });
  EXPECT_NE(message.find("missing.obj: cannot open"), std::string::npos) << message;
  std::filesystem::create_directory(folder.file("folder.obj"));
  message = error_of([&] { (void)stitch::read_mesh(folder.file("folder.obj")); });
  EXPECT_NE(message.find("is a folder"), std::string::npos) << message;
}

TEST(FileExtension, IsLowerCaseWithTheDot) {
  EXPECT_EQ(stitch::file_extension("a/b.c/Mesh.OBJ"), ".obj");
  EXPECT_EQ(stitch::file_extension("a/b.c/mesh"), "");
  EXPECT_EQ(stitch::file_extension("x.tar.PLY"), ".ply");
}

TEST(MeshFileFormat, IsTheExtensionsFormatAmongThoseGiven) {
  using stitch::MeshFileFormat;
  EXPECT_EQ(stitch::mesh_file_format("a/b.c/Mesh.OBJ", stitch::kMeshReadExtensions),
            MeshFileFormat::obj);
  EXPECT_EQ(stitch::mesh_file_format("s.GLTF", stitch::kMeshReadExtensions), MeshFileFormat::gltf);
  EXPECT_EQ(stitch::mesh_file_format("s.stl", stitch::kMeshWriteExtensions), MeshFileFormat::stl);
  // glTF is read, not written as a mesh; no extension and unknown ones are no format.
  EXPECT_FALSE(stitch::mesh_file_format("s.glb", stitch::kMeshWriteExtensions));
  EXPECT_FALSE(stitch::mesh_file_format("surface.dae", stitch::kMeshReadExtensions));
  EXPECT_FALSE(stitch::mesh_file_format("mesh", stitch::kMeshReadExtensions));
}

// --- atomic writing ----------------------------------------------------------------------

TEST(WriteFileAtomically, FailsInAMissingFolderLeavingNothing) {
  TempFolder folder;
  const std::string path = folder.file("missing/cube.obj");
  const std::string message =
      error_of([&] { stitch::write_mesh(path, stitch::read_mesh(example("cube"))); });
  EXPECT_NE(message.find("does not exist"), std::string::npos) << message;
  EXPECT_FALSE(std::filesystem::exists(folder.file("missing")));
  EXPECT_TRUE(folder.entries().empty());
}

TEST(WriteFileAtomically, AFailingWriteLeavesThePreviousFileAndNoTemporary) {
  TempFolder folder;
  const std::string path = folder.write("out.obj", "previous content\n");
  EXPECT_THROW(stitch::write_file_atomically(path,
                                             [](std::ostream& out) {
                                               out << "half of a file";
                                               throw Error("the writer failed");
                                             }),
               Error);
  EXPECT_EQ(read_file(path), "previous content\n");
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"out.obj"});

  // A refused format does not touch the file either.
  EXPECT_THROW(stitch::write_mesh(folder.file("out.xyz"), stitch::read_mesh(example("cube"))),
               Error);
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"out.obj"});

  // A successful write replaces the content and leaves only the target.
  stitch::write_file_atomically(path, [](std::ostream& out) { out << "new content\n"; });
  EXPECT_EQ(read_file(path), "new content\n");
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"out.obj"});
}

TEST(WriteFileAtomically, RefusesToReplaceAFolder) {
  TempFolder folder;
  std::filesystem::create_directory(folder.file("target.obj"));
  EXPECT_THROW(stitch::write_file_atomically(folder.file("target.obj"),
                                             [](std::ostream& out) { out << "x"; }),
               Error);
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"target.obj"});
}

// --- surface export ----------------------------------------------------------------------

// Two quads side by side in the z = 0 plane, normals up.
stitch::TessellatedMesh two_quads() {
  stitch::TessellatedMesh mesh;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 3; ++i) {
      mesh.positions.emplace_back(i, j, 0.1 * i * j);
      mesh.normals.emplace_back(0, 0, 1);
      mesh.uv.emplace_back(0.5 * i, j / 3.0);
      mesh.patch.push_back(i == 2 ? 7 : 3);
      mesh.level.push_back(0);
    }
  mesh.quads = {{0, 1, 4, 3}, {1, 2, 5, 4}};
  return mesh;
}

TEST(WriteSurfaceMesh, WritesEveryFormatReadableBack) {
  TempFolder folder;
  const stitch::TessellatedMesh mesh = two_quads();
  const std::vector<std::vector<int>> quads = {{0, 1, 4, 3}, {1, 2, 5, 4}};
  for (const auto& [format, ext] : {std::pair{stitch::MeshFileFormat::obj, ".obj"},
                                    std::pair{stitch::MeshFileFormat::ply, ".ply"},
                                    std::pair{stitch::MeshFileFormat::off, ".off"}}) {
    const std::string path = folder.file(std::string("surface") + ext);
    stitch::write_surface_mesh(path, format, mesh);
    const PolygonSoup soup = stitch::read_polygon_soup(path);
    EXPECT_EQ(soup.positions, mesh.positions) << ext;
    EXPECT_EQ(soup.faces, quads) << ext;
  }
  const std::string obj = read_file(folder.file("surface.obj"));
  EXPECT_NE(obj.find("\nvn 0 0 1\n"), std::string::npos);
  EXPECT_NE(obj.find("\nf 1//1 2//2 5//5 4//4\n"), std::string::npos);
  // .ply is binary unless asked for text; both hold double positions and normals.
  const std::string ply = read_file(folder.file("surface.ply"));
  EXPECT_NE(ply.find("format binary_little_endian 1.0\n"), std::string::npos);
  stitch::SurfaceFileOptions text;
  text.ascii_ply = true;
  stitch::write_surface_mesh(folder.file("text.ply"), stitch::MeshFileFormat::ply, mesh, text);
  const std::string ascii = read_file(folder.file("text.ply"));
  EXPECT_NE(ascii.find("property double nx\nproperty double ny\nproperty double nz\n"),
            std::string::npos);
  EXPECT_NE(ascii.find("\n1 0 0 0 0 1\n"), std::string::npos);  // sample 1: x y z nx ny nz
  EXPECT_EQ(stitch::read_polygon_soup(folder.file("text.ply")).positions, mesh.positions);

  stitch::write_surface_mesh(folder.file("surface.stl"), stitch::MeshFileFormat::stl, mesh);
  const std::string stl = read_file(folder.file("surface.stl"));
  ASSERT_EQ(stl.size(), 84u + 50u * 4u);  // each quad split into two triangles
  EXPECT_EQ(from_bytes<uint32_t>(stl, 80), 4u);
}

TEST(WriteSurfaceSamplesPly, StoresEveryAttributeInBinary) {
  TempFolder folder;
  const stitch::TessellatedMesh mesh = two_quads();
  const std::string path = folder.file("samples.ply");
  stitch::write_surface_samples_ply(path, mesh);
  // The generic reader understands it (positions and quads) ...
  const PolygonSoup soup = stitch::read_polygon_soup(path);
  EXPECT_EQ(soup.positions, mesh.positions);
  EXPECT_EQ(soup.faces.size(), 2u);
  // ... and every sample's record is 8 doubles and an int, in that order.
  const std::string data = read_file(path);
  const std::string header_end = "end_header\n";
  ASSERT_NE(data.find("format binary_little_endian 1.0\n"), std::string::npos);
  ASSERT_NE(data.find("property double u\nproperty double v\nproperty int patch\n"),
            std::string::npos);
  const size_t body = data.find(header_end) + header_end.size();
  const size_t record = 8 * 8 + 4;
  ASSERT_EQ(data.size(), body + 6 * record + 2 * (1 + 4 * 4));
  for (size_t i = 0; i < 6; ++i) {
    const size_t at = body + i * record;
    EXPECT_EQ(from_bytes<double>(data, at), mesh.positions[i].x());
    EXPECT_EQ(from_bytes<double>(data, at + 40), mesh.normals[i].z());
    EXPECT_EQ(from_bytes<double>(data, at + 48), mesh.uv[i].x());
    EXPECT_EQ(from_bytes<double>(data, at + 56), mesh.uv[i].y());
    EXPECT_EQ(from_bytes<int32_t>(data, at + 64), mesh.patch[i]);
  }
}

TEST(WritePly, BinaryRecordsAreEachValueLittleEndian) {
  TempFolder folder;
  std::vector<Vec3> positions, normals;
  for (int i = 0; i < 300; ++i) {
    const double t = i / 7.0;
    positions.emplace_back(std::cos(t) / 3, std::sin(t) * 1e-300, t * 6.02214076e23);
    normals.emplace_back(std::sin(t), -std::cos(t), 1.0 / (i + 3));
  }
  std::vector<std::vector<int>> faces = {{0, 1, 2}, {3, 4, 5, 6}, {7, 8, 9, 10, 11}, {299, 0, 1}};
  std::vector<int> big(300);  // more than 255 sides: the counts become ints
  std::iota(big.begin(), big.end(), 0);
  for (const bool with_big : {false, true}) {
    if (with_big) faces.push_back(big);
    for (const bool with_normals : {false, true})
      for (const bool single : {false, true}) {
        const auto stream =
            stitch::detail::stream_arrays(positions, with_normals ? &normals : nullptr, faces);
        const std::string path = folder.file("out.ply");
        stitch::detail::write_mesh_file(path, [&](stitch::detail::OutputFile& out) {
          stitch::detail::write_ply(out, stream, stitch::detail::PlyEncoding::binary_little_endian,
                                    single ? stitch::detail::PlyPrecision::single
                                           : stitch::detail::PlyPrecision::double_precision,
                                    "test");
        });
        std::string expected;
        const auto put = [&](const Vec3& p) {
          for (int k = 0; k < 3; ++k)
            expected += single ? bytes(static_cast<float>(p[k])) : bytes(p[k]);
        };
        for (size_t i = 0; i < positions.size(); ++i) {
          put(positions[i]);
          if (with_normals) put(normals[i]);
        }
        for (const auto& face : faces) {
          const auto size = static_cast<std::int32_t>(face.size());
          expected += with_big ? bytes(size) : bytes(static_cast<std::uint8_t>(size));
          for (int v : face) expected += bytes(static_cast<std::int32_t>(v));
        }
        const std::string data = read_file(path);
        const std::string header_end = "end_header\n";
        const size_t body = data.find(header_end);
        ASSERT_NE(body, std::string::npos);
        EXPECT_EQ(data.substr(body + header_end.size()), expected)
            << "normals " << with_normals << ", float " << single << ", int counts " << with_big;
        EXPECT_NE(data.find(with_big ? "property list int int" : "property list uchar int"),
                  std::string::npos);
      }
  }
}

}  // namespace
