// Mesh import/export: round trips through STL (binary, ASCII) and OBJ, units, welding, scene
// merging with node transforms, determinism, and the InputError of each bad file.
// Every file is generated into a fresh temp directory.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

#include "core/errors.hpp"
#include "geometry/mass_properties.hpp"
#include "geometry/mesh_io.hpp"

namespace gearsim {
namespace test_mesh_io {

namespace fs = std::filesystem;

// A hexagonal prism (a gear blank stand-in) of radius 23.7 mm, height 8.3 mm, off the origin.
TriMesh hex_prism() {
  constexpr int n = 6;
  const Eigen::Vector3d centre(5.1e-3, -3.2e-3, 12.9e-3);
  TriMesh m;
  for (double z : {0.0, 8.3e-3}) {
    for (int i = 0; i < n; ++i) {
      const double a = 2.0 * std::numbers::pi * i / n + 0.1;
      m.vertices.push_back(centre + Eigen::Vector3d(23.7e-3 * std::cos(a), 23.7e-3 * std::sin(a), z));
    }
  }
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t j = (i + 1) % n;
    m.triangles.push_back({i, j, n + j});
    m.triangles.push_back({i, n + j, n + i});
  }
  for (std::uint32_t i = 1; i + 1 < n; ++i) {
    m.triangles.push_back({0, i + 1, i});  // bottom, seen from -z
    m.triangles.push_back({n, n + i, n + i + 1});  // top
  }
  return m;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The message of the InputError `f` throws, or a failure.
template <typename F>
std::string input_error(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected an InputError";
  return "";
}

#define EXPECT_CONTAINS(text, part) EXPECT_NE(std::string(text).find(part), std::string::npos) << "in: " << (text)

// Same triangles over the same vertices, matched by nearest position within tol_m.
void expect_same_mesh(const TriMesh& expected, const TriMesh& actual, double tol_m) {
  ASSERT_EQ(actual.vertices.size(), expected.vertices.size());
  ASSERT_EQ(actual.triangles.size(), expected.triangles.size());
  std::vector<std::uint32_t> to_expected;
  for (const Eigen::Vector3d& p : actual.vertices) {
    std::uint32_t best = 0;
    for (std::uint32_t j = 1; j < expected.vertices.size(); ++j) {
      if ((expected.vertices[j] - p).norm() < (expected.vertices[best] - p).norm()) best = j;
    }
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(p[k], expected.vertices[best][k], tol_m);
    to_expected.push_back(best);
  }
  // Triangles compared as sets, each rotated to start at its smallest index (winding kept).
  auto canonical = [](std::array<std::uint32_t, 3> t) {
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    return t;
  };
  std::vector<std::array<std::uint32_t, 3>> a, b;
  for (const auto& t : expected.triangles) a.push_back(canonical(t));
  for (const auto& t : actual.triangles) {
    b.push_back(canonical({to_expected[t[0]], to_expected[t[1]], to_expected[t[2]]}));
  }
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  EXPECT_EQ(a, b);
}

// STL and Assimp store float32: one rounding of each coordinate (in mm) is at most half an ulp,
// 2^-24 relative; 2^-23 of the largest coordinate also covers the double unit conversions.
double float32_tolerance_m(const TriMesh& m) {
  double largest = 0.0;
  for (const auto& p : m.vertices) largest = std::max(largest, p.cwiseAbs().maxCoeff());
  return largest * std::ldexp(1.0, -23);
}

class MeshIo : public ::testing::Test {
 protected:
  void SetUp() override {
    const std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    dir_ = fs::temp_directory_path() / ("gearsim_mesh_io_" + test + "_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  fs::path file(const std::string& name, const std::string& contents) const {
    std::ofstream(dir_ / name, std::ios::binary) << contents;
    return dir_ / name;
  }
  // glTF: one outward tetrahedron (unit legs, volume 1/6) used by two nodes, one translated by
  // +10 along x, one mirrored in x.
  fs::path two_node_tetrahedra() const {
    const std::uint16_t index[12] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
    const float position[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    std::string bin(reinterpret_cast<const char*>(index), sizeof index);
    bin.append(reinterpret_cast<const char*>(position), sizeof position);
    file("tet.bin", bin);
    return file("tet.gltf", R"({"asset": {"version": "2.0"}, "scene": 0,
      "scenes": [{"nodes": [0, 1]}],
      "nodes": [{"mesh": 0, "translation": [10, 0, 0]}, {"mesh": 0, "scale": [-1, 1, 1]}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 1}, "indices": 0}]}],
      "buffers": [{"uri": "tet.bin", "byteLength": 72}],
      "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 24, "target": 34963},
                      {"buffer": 0, "byteOffset": 24, "byteLength": 48, "target": 34962}],
      "accessors": [
        {"bufferView": 0, "componentType": 5123, "count": 12, "type": "SCALAR"},
        {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC3",
         "max": [1, 1, 1], "min": [0, 0, 0]}]})");
  }
  fs::path dir_;
};

TEST_F(MeshIo, StlBinaryRoundTripKeepsTrianglesAndVerticesToFloat32) {
  const TriMesh m = hex_prism();
  export_mesh(m, dir_ / "p.stl", MeshFormat::StlBinary);
  expect_same_mesh(m, import_mesh(dir_ / "p.stl"), float32_tolerance_m(m));
}

TEST_F(MeshIo, StlAsciiRoundTripKeepsTrianglesAndVerticesToFloat32) {
  const TriMesh m = hex_prism();
  export_mesh(m, dir_ / "p.stl", MeshFormat::StlAscii);
  expect_same_mesh(m, import_mesh(dir_ / "p.stl"), float32_tolerance_m(m));
}

TEST_F(MeshIo, ObjRoundTripKeepsTrianglesAndVerticesToFloat32) {
  // OBJ holds the full double, but Assimp reads it into float32.
  const TriMesh m = hex_prism();
  export_mesh(m, dir_ / "p.obj", MeshFormat::Obj);
  expect_same_mesh(m, import_mesh(dir_ / "p.obj"), float32_tolerance_m(m));
}

TEST_F(MeshIo, AnObjsMaterialLibraryThatIsMissingOrAFifoIsSkippedNotWaitedOn) {
  // The geometry is all a gear needs: a material library Assimp cannot open is skipped (a FIFO
  // under its name is refused by the bounded reader's checks, so the import does not block).
  const std::string obj =
      "mtllib gone.mtl\nmtllib pipe.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
      "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
  ASSERT_EQ(::mkfifo((dir_ / "pipe.mtl").c_str(), 0600), 0);
  const TriMesh m = import_mesh(file("tet.obj", obj), LengthUnit::Metre);
  EXPECT_EQ(m.triangles.size(), 4u);
}

TEST_F(MeshIo, AMeshThatIsAFifoIsRefusedByKindNotWaitedOn) {
  ASSERT_EQ(::mkfifo((dir_ / "gear.stl").c_str(), 0600), 0);
  const std::string msg = input_error([&] { import_mesh(dir_ / "gear.stl"); });
  EXPECT_CONTAINS(msg, "gear.stl: expected a mesh file (a regular file), got a FIFO");
}

TEST_F(MeshIo, AsciiPlyCubeImportsAsAClosedTenMillimetreCube) {
  // A 10 mm cube as an ASCII PLY with quads: Assimp triangulates to 12 faces over 8 vertices.
  const fs::path p = file("cube.ply",
                          "ply\nformat ascii 1.0\nelement vertex 8\nproperty float x\nproperty float y\n"
                          "property float z\nelement face 6\nproperty list uchar int vertex_indices\nend_header\n"
                          "0 0 0\n10 0 0\n10 10 0\n0 10 0\n0 0 10\n10 0 10\n10 10 10\n0 10 10\n"
                          "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n");
  const TriMesh m = import_mesh(p, LengthUnit::Millimetre);
  EXPECT_EQ(m.triangles.size(), 12u);
  EXPECT_EQ(m.vertices.size(), 8u);
  // Outward winding and the volume of a 10 mm cube: 1e-6 m³ (float32-exact coordinates).
  EXPECT_NEAR(signed_volume_m3(m), 1e-6, 1e-18);
}

TEST_F(MeshIo, StlCornersWeldIntoSharedVertices) {
  // 20 facets store 60 corners; the prism has 12 distinct vertices.
  export_mesh(hex_prism(), dir_ / "p.stl", MeshFormat::StlBinary);
  const TriMesh m = import_mesh(dir_ / "p.stl");
  EXPECT_EQ(m.triangles.size(), 20u);
  EXPECT_EQ(m.vertices.size(), 12u);
}

TEST_F(MeshIo, MillimetreFileImportsInMetres) {
  const fs::path p = file("tri.stl",
                          "solid t\nfacet normal 0 0 1\nouter loop\nvertex 10 0 0\n"
                          "vertex 0 20 0\nvertex 0 0 30\nendloop\nendfacet\nendsolid t\n");
  const TriMesh m = import_mesh(p, LengthUnit::Millimetre);
  ASSERT_EQ(m.vertices.size(), 3u);
  // 10, 20, 30 are exact in float32; the only rounding is the double product with 0.001.
  EXPECT_NEAR(m.vertices[0].x(), 0.010, 1e-17);
  EXPECT_NEAR(m.vertices[1].y(), 0.020, 1e-17);
  EXPECT_NEAR(m.vertices[2].z(), 0.030, 1e-17);
}

TEST_F(MeshIo, ExportUnitAndImportUnitCancel) {
  const TriMesh m = hex_prism();
  for (LengthUnit unit : {LengthUnit::Metre, LengthUnit::Millimetre, LengthUnit::Inch}) {
    export_mesh(m, dir_ / "p.obj", MeshFormat::Obj, unit);
    expect_same_mesh(m, import_mesh(dir_ / "p.obj", unit), float32_tolerance_m(m));
  }
}

TEST_F(MeshIo, WrongUnitScalesByTheUnitRatio) {
  export_mesh(hex_prism(), dir_ / "p.stl", MeshFormat::StlBinary, LengthUnit::Millimetre);
  const TriMesh as_mm = import_mesh(dir_ / "p.stl", LengthUnit::Millimetre);
  const TriMesh as_m = import_mesh(dir_ / "p.stl", LengthUnit::Metre);
  // Same float32 numbers, multiplied by 0.001 or by 1: a factor 1000 to double rounding.
  EXPECT_NEAR(as_m.vertices[3].y(), 1000.0 * as_mm.vertices[3].y(), 1e-12);
}

TEST_F(MeshIo, LengthUnitSymbolsParseBack) {
  for (LengthUnit u :
       {LengthUnit::Metre, LengthUnit::Centimetre, LengthUnit::Millimetre, LengthUnit::Micrometre, LengthUnit::Inch, LengthUnit::Foot}) {
    EXPECT_EQ(parse_length_unit(symbol(u)), u);
  }
  EXPECT_EQ(parse_length_unit("\u00b5m"), LengthUnit::Micrometre);
  EXPECT_EQ(parse_length_unit("furlong"), std::nullopt);
  EXPECT_EQ(metres_per(LengthUnit::Inch), 0.0254);
}

TEST_F(MeshIo, ExportIsByteIdenticalForIdenticalMeshes) {
  for (MeshFormat f : {MeshFormat::StlBinary, MeshFormat::StlAscii, MeshFormat::Obj}) {
    export_mesh(hex_prism(), dir_ / "a", f);
    export_mesh(hex_prism(), dir_ / "b", f);
    EXPECT_EQ(slurp(dir_ / "a"), slurp(dir_ / "b"));
  }
}

TEST_F(MeshIo, BinaryStlHasTheSizeTheFormatPrescribes) {
  // 80-byte header, uint32 count, 50 bytes per facet.
  export_mesh(hex_prism(), dir_ / "p.stl", MeshFormat::StlBinary);
  EXPECT_EQ(fs::file_size(dir_ / "p.stl"), 84u + 50u * 20u);
}

TEST_F(MeshIo, SceneMeshesMergeWithTheirNodeTransforms) {
  const TriMesh m = import_mesh(two_node_tetrahedra());
  EXPECT_EQ(m.triangles.size(), 8u);
  EXPECT_EQ(m.vertices.size(), 8u);  // no shared positions between the two copies
  const auto [lo, hi] = std::minmax_element(m.vertices.begin(), m.vertices.end(),
                                            [](const Eigen::Vector3d& a, const Eigen::Vector3d& b) { return a.x() < b.x(); });
  EXPECT_DOUBLE_EQ(lo->x(), -0.001);  // the mirrored copy
  EXPECT_DOUBLE_EQ(hi->x(), 0.011);  // the translated copy
}

TEST_F(MeshIo, MirroringNodeKeepsOutwardWinding) {
  // Both copies outward: 2 × (1/6) mm³, not 0; 1e-12 relative covers the double sums.
  EXPECT_NEAR(signed_volume_m3(import_mesh(two_node_tetrahedra())), 2.0 / 6.0 * 1e-9, 1e-12 * 1e-9);
}

TEST_F(MeshIo, ImportKeepsAnOpenMeshForValidationToJudge) {
  // Assimp does not reject an open STL (one lone facet): import must hand it on intact.
  const fs::path p = file("open.stl",
                          "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n"
                          "vertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid t\n");
  EXPECT_EQ(import_mesh(p).triangles.size(), 1u);
}

TEST_F(MeshIo, MissingFileNamesTheFile) {
  const std::string msg = input_error([&] { import_mesh(dir_ / "gear.stl"); });
  EXPECT_CONTAINS(msg, "gear.stl: file not found");
}

TEST_F(MeshIo, EmptyFileNamesTheFile) {
  const fs::path p = file("gear.stl", "");
  EXPECT_CONTAINS(input_error([&] { import_mesh(p); }), "gear.stl: file is empty");
}

TEST_F(MeshIo, UnknownFormatNamesTheFileAndQuotesAssimp) {
  const fs::path p = file("gear.xyz", "this is not a mesh\n1 2 3\n");
  const std::string msg = input_error([&] { import_mesh(p); });
  EXPECT_CONTAINS(msg, "gear.xyz: unknown mesh format '.xyz'");
  EXPECT_CONTAINS(msg, "Assimp: No suitable reader found");
}

TEST_F(MeshIo, BrokenKnownFormatUnderAnUnknownExtensionIsAParseError) {
  // Assimp recognises the OBJ by its content; the face's vertex 9 does not exist.
  const fs::path p = file("gear.txt", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n");
  EXPECT_CONTAINS(input_error([&] { import_mesh(p); }), "gear.txt: cannot parse mesh (Assimp: ");
}

TEST_F(MeshIo, TruncatedBinaryStlIsAParseError) {
  export_mesh(hex_prism(), dir_ / "p.stl", MeshFormat::StlBinary);
  const std::string whole = slurp(dir_ / "p.stl");
  const fs::path p = file("gear.stl", whole.substr(0, whole.size() - 30));
  const std::string msg = input_error([&] { import_mesh(p); });
  EXPECT_CONTAINS(msg, "gear.stl: cannot parse mesh (Assimp: ");
}

TEST_F(MeshIo, MalformedAsciiStlIsAParseError) {
  // Assimp 5.2 leaks ~2.4 kB when its ASCII STL parser throws; under GEARSIM_SANITIZE,
  // LeakSanitizer needs "leak:libassimp.so" suppressed for this test.
  const fs::path p = file("gear.stl", "solid t\nfacet normal 0 0 1\nouter loop\nvertex 1 2\n");
  EXPECT_CONTAINS(input_error([&] { import_mesh(p); }), "gear.stl: cannot parse mesh (Assimp: ");
}

TEST_F(MeshIo, FileOfLinesOnlyHasNoTriangles) {
  const fs::path p = file("gear.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nl 1 2 3\n");
  EXPECT_CONTAINS(input_error([&] { import_mesh(p); }), "gear.obj: contains no triangles");
}

TEST_F(MeshIo, UnwritablePathNamesThePath) {
  // An output that cannot be written is an OutputError (core/output_file.hpp), with the reason.
  const fs::path p = dir_ / "no_such_dir" / "gear.stl";
  try {
    export_mesh(hex_prism(), p, MeshFormat::StlBinary);
    FAIL() << "wrote " << p;
  } catch (const OutputError& e) {
    EXPECT_CONTAINS(std::string(e.what()), p.string() + ": cannot create: No such file or directory");
  }
}

}  // namespace test_mesh_io
}  // namespace gearsim
