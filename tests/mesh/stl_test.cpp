#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>

#include "swarf/core/io.h"
#include "swarf/mesh/generate.h"
#include "swarf/mesh/stl.h"

namespace swarf {
namespace {

namespace fs = std::filesystem;

std::string data(const std::string& name) {
  return std::string(SWARF_TEST_DATA_DIR) + "/mesh/" + name;
}

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

void expect_box(const Box3& b, Vec3 lo, Vec3 hi, double tol) {
  EXPECT_NEAR(b.min.x, lo.x, tol);
  EXPECT_NEAR(b.min.y, lo.y, tol);
  EXPECT_NEAR(b.min.z, lo.z, tol);
  EXPECT_NEAR(b.max.x, hi.x, tol);
  EXPECT_NEAR(b.max.y, hi.y, tol);
  EXPECT_NEAR(b.max.z, hi.z, tol);
}

const char* kTetraAscii = R"(solid tetra
  facet normal 0 0 -1
    outer loop
      vertex 0 0 0
      vertex 0 1 0
      vertex 1 0 0
    endloop
  endfacet
  facet normal 0 -1 0
    outer loop
      vertex 0 0 0
      vertex 1 0 0
      vertex 0 0 1
    endloop
  endfacet
  facet normal -1 0 0
    outer loop
      vertex 0 0 0
      vertex 0 0 1
      vertex 0 1 0
    endloop
  endfacet
  facet normal 1 1 1
    outer loop
      vertex 1 0 0
      vertex 0 1 0
      vertex 0 0 1
    endloop
  endfacet
endsolid tetra
)";

// Facts from tests/data/mesh/SOURCES.md (measured with admesh and an independent count).
TEST(Stl, KirimotoPocketTest) {
  const Result<StlFile> f = read_stl(data("kirimoto_pocket-test.stl"));
  ASSERT_TRUE(f.ok()) << f.status().to_string();
  EXPECT_FALSE(f->binary);
  EXPECT_EQ(f->mesh.size(), 28u);
  EXPECT_TRUE(f->check.closed());
  EXPECT_EQ(f->check.inconsistent_edges, 0u);
  expect_box(bounds(f->mesh), {-50, -50, 0}, {50, 50, 18}, 1e-9);
  // 100 x 100 x 18 block minus a 40 x 40 x 8 pocket.
  EXPECT_NEAR(f->check.volume_mm3, 100.0 * 100 * 18 - 40.0 * 40 * 8, 1e-6);
}

TEST(Stl, OpenscadVicebarIsClosedAscii) {
  const Result<StlFile> f = read_stl(data("openscad_bad-stl-pcbvicebar.stl"));
  ASSERT_TRUE(f.ok()) << f.status().to_string();
  EXPECT_FALSE(f->binary);
  EXPECT_EQ(f->mesh.size(), 260u);
  EXPECT_TRUE(f->check.closed());
  EXPECT_GT(f->check.volume_mm3, 0.0);
  expect_box(bounds(f->mesh), {-54.023, -54.023, 0}, {54.023, 54.023, 6.4}, 1e-3);
}

TEST(Stl, KtoolcavIsBinaryDespiteSolidHeader) {
  const std::string path = data("opencamlib_ktoolcav.stl");
  const Result<std::string> bytes = read_file(path);
  ASSERT_TRUE(bytes.ok());
  ASSERT_EQ(bytes->substr(0, 5), "solid");  // the trap
  const Result<StlFile> f = parse_stl(*bytes, "ktoolcav.stl");
  ASSERT_TRUE(f.ok()) << f.status().to_string();
  EXPECT_TRUE(f->binary);
  EXPECT_EQ(f->mesh.size(), 4090u);
  EXPECT_TRUE(f->check.closed());
  EXPECT_NEAR(std::abs(f->check.volume_mm3), 18.18, 0.01);
  expect_box(bounds(f->mesh), {-2, 0, -1.5}, {2, 1.625, 1.8125}, 1e-6);
}

TEST(Stl, OpencamlibDemoLoadsWithOpenEdgeWarnings) {
  const Result<StlFile> f = read_stl(data("opencamlib_demo.stl"));
  ASSERT_TRUE(f.ok()) << f.status().to_string();
  EXPECT_FALSE(f->binary);
  EXPECT_EQ(f->mesh.size(), 1894u);
  EXPECT_FALSE(f->check.closed());
  EXPECT_EQ(f->check.open_edges, 196u);
  expect_box(bounds(f->mesh), {0, 0, 0}, {10, 10, 2}, 1e-6);
  bool warned = false;
  for (const std::string& w : f->warnings)
    warned |= has(w, "196 open edges");
  EXPECT_TRUE(warned);
}

TEST(Stl, AsciiTetrahedron) {
  const Result<StlFile> f = parse_stl(kTetraAscii, "tetra.stl");
  ASSERT_TRUE(f.ok()) << f.status().to_string();
  EXPECT_EQ(f->mesh.vertices.size(), 4u);
  EXPECT_TRUE(f->check.closed());
  EXPECT_DOUBLE_EQ(f->check.volume_mm3, 1.0 / 6.0);
  EXPECT_TRUE(f->warnings.empty()) << f->warnings.front();
}

TEST(Stl, RoundTripBinaryAndAscii) {
  const fs::path dir = fs::temp_directory_path() / "swarf_stl_roundtrip";
  fs::remove_all(dir);
  // Coordinates exactly representable as float, so that binary round-trips exactly.
  const Mesh m = transformed(make_cylinder({0.5, -2, 1}, 4, 8, 24), 0.0);
  for (bool binary : {true, false}) {
    const std::string path = (dir / (binary ? "b.stl" : "a.stl")).string();
    ASSERT_TRUE(write_stl(path, m, binary).ok());
    const Result<StlFile> f = read_stl(path);
    ASSERT_TRUE(f.ok()) << f.status().to_string();
    EXPECT_EQ(f->binary, binary);
    EXPECT_EQ(f->mesh.size(), m.size());
    EXPECT_EQ(f->mesh.vertices.size(), m.vertices.size());
    EXPECT_TRUE(f->check.closed());
    EXPECT_TRUE(f->warnings.empty());
    const double tol = binary ? 1e-6 : 0.0;  // float vs shortest exact decimal
    for (std::size_t t = 0; t < m.size(); ++t)
      for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(f->mesh.corner(t, k).x, m.corner(t, k).x, tol);
        EXPECT_NEAR(f->mesh.corner(t, k).z, m.corner(t, k).z, tol);
      }
    EXPECT_NEAR(f->check.volume_mm3, check_mesh(m).volume_mm3, 1e-4);
  }
  EXPECT_EQ(stl_binary_bytes(m).size(), 84 + 50 * m.size());
  EXPECT_NE(stl_binary_bytes(m).substr(0, 5), "solid");
  EXPECT_EQ(write_stl((dir / "e.stl").string(), Mesh{}).code(), Error::kBadInput);
  fs::remove_all(dir);
}

// --- rejections: each names the source and the place -------------------------------------

Status parse_error(std::string_view bytes) {
  return parse_stl(bytes, "part.stl").status();
}

TEST(Stl, RejectsTruncatedBinary) {
  const std::string full = stl_binary_bytes(make_box({{0, 0, 0}, {1, 1, 1}}));
  const Status s = parse_error(full.substr(0, full.size() - 7));
  EXPECT_EQ(s.code(), Error::kBadInput);
  EXPECT_TRUE(has(s.message(), "part.stl: truncated binary STL")) << s.message();
  EXPECT_TRUE(has(s.message(), "12 triangles")) << s.message();
  // Extra bytes: the count and the size disagree the other way.
  const Status extra = parse_error(full + std::string(10, '\0'));
  EXPECT_TRUE(has(extra.message(), "extra bytes")) << extra.message();
}

TEST(Stl, RejectsTruncatedBinaryWithSolidHeader) {
  // Like ktoolcav.stl but cut short: must not be mistaken for broken ASCII.
  const Result<std::string> bytes = read_file(data("opencamlib_ktoolcav.stl"));
  ASSERT_TRUE(bytes.ok());
  const Status s = parse_error(std::string_view(*bytes).substr(0, 10000));
  EXPECT_TRUE(has(s.message(), "truncated binary STL: the header counts 4090 triangles"))
      << s.message();
}

TEST(Stl, RejectsBinaryTriangleCountMismatch) {
  std::string bytes = stl_binary_bytes(make_box({{0, 0, 0}, {1, 1, 1}}));
  const std::uint32_t wrong = 13;
  std::memcpy(bytes.data() + 80, &wrong, 4);
  const Status s = parse_error(bytes);
  EXPECT_EQ(s.code(), Error::kBadInput);
  EXPECT_TRUE(has(s.message(), "counts 13 triangles")) << s.message();
}

TEST(Stl, RejectsNonFiniteCoordinates) {
  std::string bytes = stl_binary_bytes(make_box({{0, 0, 0}, {1, 1, 1}}));
  const float nan = std::nanf("");
  std::memcpy(bytes.data() + 84 + 4 * 50 + 12 + 2 * 12 + 4, &nan, 4);  // triangle 5, vertex 3, y
  Status s = parse_error(bytes);
  EXPECT_EQ(s.message(), "part.stl: triangle 5: vertex 3 has a non-finite coordinate (NaN or inf)");

  std::string text = kTetraAscii;
  text.replace(text.find("vertex 0 1 0"), 12, "vertex 0 inf 0");
  s = parse_error(text);
  EXPECT_TRUE(has(s.message(), "part.stl: line 5: triangle 1: non-finite coordinate 'inf'"))
      << s.message();
}

TEST(Stl, RejectsBrokenAsciiWithLineNumbers) {
  std::string text = kTetraAscii;
  text.replace(text.find("vertex 0 0 1"), 6, "vertx");
  Status s = parse_error(text);
  EXPECT_EQ(s.message(), "part.stl: line 13: expected 'vertex', found 'vertx'");

  text = kTetraAscii;
  text.replace(text.find("vertex 1 0 0"), 12, "vertex 1 0 zero");
  s = parse_error(text);
  EXPECT_EQ(s.message(), "part.stl: line 6: expected a number, found 'zero'");

  // Truncated in the middle of a facet.
  s = parse_error(std::string(kTetraAscii).substr(0, 200));
  EXPECT_EQ(s.code(), Error::kBadInput);
  EXPECT_TRUE(has(s.message(), "part.stl: line ")) << s.message();
  EXPECT_TRUE(has(s.message(), "found end of file")) << s.message();

  // Cut after a complete facet: the missing 'endsolid' still shows the truncation.
  const std::string t = kTetraAscii;
  s = parse_error(t.substr(0, t.find("endsolid")));
  EXPECT_TRUE(has(s.message(), "expected 'facet' or 'endsolid', found end of file")) << s.message();
}

TEST(Stl, RejectsEmptyAndGarbage) {
  EXPECT_EQ(parse_error("").message(), "part.stl: empty file");
  EXPECT_EQ(parse_error("solid empty\nendsolid empty\n").message(),
            "part.stl: no triangles (empty mesh)");
  std::string empty_binary(84, '\0');
  EXPECT_EQ(parse_error(empty_binary).message(), "part.stl: no triangles (empty mesh)");
  EXPECT_TRUE(has(parse_error("hello").message(), "not an STL file"))
      << parse_error("hello").message();
  const std::string prose(200, 'x');
  EXPECT_TRUE(has(parse_error(prose).message(), "not an STL file"));
  std::string noise(1000, '\0');
  for (std::size_t i = 0; i < noise.size(); ++i)
    noise[i] = static_cast<char>((i * 7919) % 251);
  EXPECT_EQ(parse_error(noise).code(), Error::kBadInput);
  EXPECT_EQ(read_stl("/nonexistent/part.stl").status().code(), Error::kIo);
}

TEST(Stl, AcceptsUpperCaseKeywordsAndSeveralSolids) {
  std::string upper = kTetraAscii;
  for (char& c : upper)
    c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  const Result<StlFile> f = parse_stl(upper, "upper.stl");
  ASSERT_TRUE(f.ok()) << f.status().to_string();
  EXPECT_EQ(f->mesh.size(), 4u);
  const Result<StlFile> two = parse_stl(std::string(kTetraAscii) + kTetraAscii, "two.stl");
  ASSERT_TRUE(two.ok()) << two.status().to_string();
  EXPECT_EQ(two->mesh.size(), 8u);
  EXPECT_EQ(two->check.non_manifold_edges, 6u);  // every edge now used four times
}

TEST(Stl, WarnsAboutDegenerateTrianglesAndFlippedNormals) {
  std::string text = kTetraAscii;
  text.replace(text.find("facet normal 0 0 -1"), 19, "facet normal 0 0 1");
  // A zero-area facet appended at the end of the solid.
  text.replace(text.find("endsolid"), 0,
               "facet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex 2 0 0\nvertex 1 0 0\n"
               "endloop\nendfacet\n");
  const Result<StlFile> f = parse_stl(text, "w.stl");
  ASSERT_TRUE(f.ok()) << f.status().to_string();
  bool flipped = false, degenerate = false;
  for (const std::string& w : f->warnings) {
    flipped |= has(w, "w.stl: 1 stored normals point against");
    degenerate |= has(w, "w.stl: 1 degenerate");
  }
  EXPECT_TRUE(flipped);
  EXPECT_TRUE(degenerate);
}

}  // namespace
}  // namespace swarf
