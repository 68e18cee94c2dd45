#include "geometry/mesh_io.hpp"

#include <Eigen/Geometry>
#include <array>
#include <assimp/DefaultIOSystem.h>
#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <bit>
#include <charconv>
#include <fstream>
#include <limits>
#include <string>
#include <unordered_map>

#include "core/errors.hpp"
#include "core/input_file.hpp"
#include "core/output_file.hpp"

namespace gearsim {
namespace {

// "<path>: ", the start of every message about a file.
std::string where(const std::filesystem::path& path) { return path.string() + ": "; }

// Assimp's file access with the bounded reader's checks on every file it opens to read: a file
// refused (a FIFO, a device, an oversized file) is one Assimp cannot open, and the first refusal
// is kept for the error when the import then fails.
class BoundedIoSystem : public Assimp::DefaultIOSystem {
 public:
  Assimp::IOStream* Open(const char* file, const char* mode) override {
    if (mode && mode[0] == 'r') try {
        check_input_file(file, kMaxMeshFileBytes, "a mesh file");
      } catch (const InputError& e) {
        if (refusal.empty()) refusal = e.what();
        return nullptr;
      }
    return Assimp::DefaultIOSystem::Open(file, mode);
  }
  // Assimp's own Exists() opens the file (fopen), which blocks on a FIFO: a regular file only.
  bool Exists(const char* file) const override {
    std::error_code ec;
    return std::filesystem::is_regular_file(file, ec);
  }
  std::string refusal;
};

// --- Units ------------------------------------------------------------------------------------

struct UnitInfo {
  LengthUnit unit;
  double metres;
  std::string_view symbol;
};

// Inch and foot are exact by definition (1959 international yard).
constexpr std::array<UnitInfo, 6> kUnits{{{LengthUnit::Metre, 1.0, "m"},
                                          {LengthUnit::Centimetre, 0.01, "cm"},
                                          {LengthUnit::Millimetre, 0.001, "mm"},
                                          {LengthUnit::Micrometre, 1e-6, "um"},
                                          {LengthUnit::Inch, 0.0254, "in"},
                                          {LengthUnit::Foot, 0.3048, "ft"}}};

const UnitInfo& unit_info(LengthUnit unit) {
  for (const UnitInfo& u : kUnits) {
    if (u.unit == unit) return u;
  }
  GEARSIM_CHECK(false, "unknown LengthUnit " + std::to_string(static_cast<int>(unit)));
  return kUnits[0];
}

// --- Import -----------------------------------------------------------------------------------

static_assert(constants::kImportWeldTolerance_m == 0.0, "the Welder below merges exactly equal positions only");

// Bit pattern of a position; +0.0 is added first so that -0 and +0 weld.
using WeldKey = std::array<std::uint64_t, 3>;

struct WeldKeyHash {
  std::size_t operator()(const WeldKey& k) const noexcept {
    std::uint64_t h = 0xcbf29ce484222325ULL;  // FNV-1a offset basis
    for (std::uint64_t w : k) h = (h ^ w) * 0x100000001b3ULL;
    return static_cast<std::size_t>(h);
  }
};

// Appends each distinct position once; vertices come in order of first use, so the result does
// not depend on hashing.
class Welder {
 public:
  explicit Welder(TriMesh& mesh) : mesh_(mesh) {}

  std::uint32_t add(const Eigen::Vector3d& p) {
    const WeldKey key{std::bit_cast<std::uint64_t>(p.x() + 0.0), std::bit_cast<std::uint64_t>(p.y() + 0.0),
                      std::bit_cast<std::uint64_t>(p.z() + 0.0)};
    const auto next = static_cast<std::uint32_t>(mesh_.vertices.size());
    const auto [it, inserted] = index_.try_emplace(key, next);
    if (inserted) mesh_.vertices.push_back(p);
    return it->second;
  }

 private:
  TriMesh& mesh_;
  std::unordered_map<WeldKey, std::uint32_t, WeldKeyHash> index_;
};

Eigen::Matrix4d to_eigen(const aiMatrix4x4& m) {
  Eigen::Matrix4d e;
  e << m.a1, m.a2, m.a3, m.a4, m.b1, m.b2, m.b3, m.b4, m.c1, m.c2, m.c3, m.c4, m.d1, m.d2, m.d3, m.d4;
  return e;
}

// Appends the triangles of `node` and its children, in metres, to `out`.
void collect(const aiScene& scene, const aiNode& node, const Eigen::Matrix4d& parent, double metres_per_unit, Welder& welder,
             TriMesh& out) {
  const Eigen::Matrix4d world = parent * to_eigen(node.mTransformation);
  const Eigen::Matrix3d linear = world.topLeftCorner<3, 3>();
  const Eigen::Vector3d offset = world.topRightCorner<3, 1>();
  // A mirroring transform turns counter-clockwise into clockwise: swap two corners back.
  const bool mirrored = linear.determinant() < 0.0;
  constexpr std::uint32_t kUnwelded = std::numeric_limits<std::uint32_t>::max();

  for (unsigned k = 0; k < node.mNumMeshes; ++k) {
    const aiMesh& mesh = *scene.mMeshes[node.mMeshes[k]];
    // SortByPType leaves one primitive type per mesh: skip point and line meshes.
    if ((mesh.mPrimitiveTypes & aiPrimitiveType_TRIANGLE) == 0) continue;
    std::vector<std::uint32_t> welded(mesh.mNumVertices, kUnwelded);
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      GEARSIM_CHECK(face.mNumIndices == 3, "Assimp returned a non-triangle after Triangulate");
      std::array<std::uint32_t, 3> tri{};
      for (int c = 0; c < 3; ++c) {
        const unsigned v = face.mIndices[c];
        if (welded[v] == kUnwelded) {
          const aiVector3D& q = mesh.mVertices[v];
          const Eigen::Vector3d p_file(q.x, q.y, q.z);
          welded[v] = welder.add(metres_per_unit * (linear * p_file + offset));
        }
        tri[c] = welded[v];
      }
      if (mirrored) std::swap(tri[1], tri[2]);
      out.triangles.push_back(tri);
    }
  }
  for (unsigned c = 0; c < node.mNumChildren; ++c) {
    collect(scene, *node.mChildren[c], world, metres_per_unit, welder, out);
  }
}

// --- Export -----------------------------------------------------------------------------------

void put_u16(std::string& s, std::uint16_t v) {
  for (int i = 0; i < 2; ++i) s.push_back(static_cast<char>((v >> (8 * i)) & 0xFFu));
}

void put_u32(std::string& s, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) s.push_back(static_cast<char>((v >> (8 * i)) & 0xFFu));
}

// Little-endian IEEE float32, as binary STL stores every number.
void put_f32(std::string& s, float v) { put_u32(s, std::bit_cast<std::uint32_t>(v)); }

// Shortest text that reads back to the same float/double; locale-independent.
template <typename Real>
void put_number(std::string& s, Real v) {
  char buf[32];
  const auto result = std::to_chars(buf, buf + sizeof buf, v);
  s.append(buf, result.ptr);
}

// Corners of face f in file units, rounded to float32 (what STL stores).
std::array<Eigen::Vector3f, 3> stl_corners(const TriMesh& mesh, std::size_t f, double unit_m) {
  std::array<Eigen::Vector3f, 3> c;
  for (int k = 0; k < 3; ++k) c[k] = (mesh.vertices[mesh.triangles[f][k]] / unit_m).cast<float>();
  return c;
}

// Unit normal from the winding, or zero for a degenerate facet.
Eigen::Vector3f facet_normal(const std::array<Eigen::Vector3f, 3>& c) {
  const Eigen::Vector3d a = c[0].cast<double>(), b = c[1].cast<double>(), d = c[2].cast<double>();
  const Eigen::Vector3d n = (b - a).cross(d - a);
  const double length = n.norm();
  return length > 0.0 ? Eigen::Vector3f((n / length).cast<float>()) : Eigen::Vector3f::Zero();
}

std::string stl_binary(const TriMesh& mesh, LengthUnit unit) {
  const std::size_t n = mesh.triangles.size();
  GEARSIM_CHECK(n <= std::numeric_limits<std::uint32_t>::max(), "too many triangles for STL");
  std::string s;
  s.reserve(84 + 50 * n);
  // 80-byte header; must not start with "solid" or readers take the file for ASCII.
  std::string header = "gearsim binary STL, unit: " + std::string(symbol(unit));
  header.resize(80, '\0');
  s += header;
  put_u32(s, static_cast<std::uint32_t>(n));
  for (std::size_t f = 0; f < n; ++f) {
    const auto c = stl_corners(mesh, f, metres_per(unit));
    const Eigen::Vector3f normal = facet_normal(c);
    for (int i = 0; i < 3; ++i) put_f32(s, normal[i]);
    for (const Eigen::Vector3f& p : c) {
      for (int i = 0; i < 3; ++i) put_f32(s, p[i]);
    }
    put_u16(s, 0);  // attribute byte count
  }
  return s;
}

void put_xyz(std::string& s, const char* prefix, const auto& p) {
  s += prefix;
  for (int i = 0; i < 3; ++i) {
    s += ' ';
    put_number(s, p[i]);
  }
  s += '\n';
}

std::string stl_ascii(const TriMesh& mesh, LengthUnit unit) {
  const std::string name = "gearsim-" + std::string(symbol(unit));
  std::string s = "solid " + name + "\n";
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const auto c = stl_corners(mesh, f, metres_per(unit));
    put_xyz(s, "  facet normal", facet_normal(c));
    s += "    outer loop\n";
    for (const Eigen::Vector3f& p : c) put_xyz(s, "      vertex", p);
    s += "    endloop\n  endfacet\n";
  }
  s += "endsolid " + name + "\n";
  return s;
}

std::string obj(const TriMesh& mesh, LengthUnit unit) {
  std::string s = "# gearsim OBJ, unit: " + std::string(symbol(unit)) + "\n";
  for (const Eigen::Vector3d& p : mesh.vertices) {
    put_xyz(s, "v", Eigen::Vector3d(p / metres_per(unit)));
  }
  for (const auto& t : mesh.triangles) {
    s += 'f';
    for (std::uint32_t v : t) {
      s += ' ';
      put_number(s, v + 1);  // OBJ indices are 1-based
    }
    s += '\n';
  }
  return s;
}

}  // namespace

double metres_per(LengthUnit unit) { return unit_info(unit).metres; }

std::string_view symbol(LengthUnit unit) { return unit_info(unit).symbol; }

std::optional<LengthUnit> parse_length_unit(std::string_view text) {
  for (const UnitInfo& u : kUnits) {
    if (text == u.symbol) return u.unit;
  }
  if (text == "\u00b5m" || text == "\u03bcm") return LengthUnit::Micrometre;  // micro sign, mu
  return std::nullopt;
}

TriMesh import_mesh(const std::filesystem::path& path, LengthUnit unit) {
  std::error_code ec;
  if (!std::filesystem::exists(std::filesystem::symlink_status(path, ec))) throw InputError(where(path) + "file not found");
  // The file and every file it refers to (an OBJ's materials, a glTF's buffers) through the
  // bounded reader's checks: a FIFO, a device, a folder, a link loop or an oversized file is
  // refused naming it, before Assimp opens it.
  if (check_input_file(path, kMaxMeshFileBytes, "a mesh file") == 0)
    throw InputError(where(path) + "file is empty, expected a mesh (e.g. STL, OBJ, PLY)");
  Assimp::Importer importer;
  auto* io = new BoundedIoSystem();  // owned by the importer
  importer.SetIOHandler(io);
  const unsigned flags = aiProcess_Triangulate | aiProcess_SortByPType | aiProcess_ValidateDataStructure;
  const aiScene* scene = importer.ReadFile(path.string(), flags);
  // A refused file the mesh needed: its reason (one it could do without, e.g. an OBJ's missing
  // or FIFO material library, was skipped as Assimp skips a file it cannot open).
  if (scene == nullptr && !io->refusal.empty()) throw InputError(io->refusal);
  if (scene == nullptr) {
    const std::string ext = path.extension().string();
    const std::string assimp = importer.GetErrorString();
    // Assimp tries the extension, then sniffs the content: only when both fail is the format
    // unknown (a .txt holding a broken OBJ is a parse failure).
    if (assimp.find("No suitable reader") != std::string::npos) {
      throw InputError(where(path) + "unknown mesh format '" + (ext.empty() ? "(none)" : ext) + "' (Assimp: " + assimp +
                       "); expected a format Assimp reads, e.g. .stl, " + ".obj, .ply");
    }
    throw InputError(where(path) + "cannot parse mesh (Assimp: " + assimp + ")");
  }

  TriMesh mesh;
  Welder welder(mesh);
  if (scene->mRootNode != nullptr) {
    collect(*scene, *scene->mRootNode, Eigen::Matrix4d::Identity(), metres_per(unit), welder, mesh);
  }
  if (mesh.triangles.empty()) throw InputError(where(path) + "contains no triangles");
  return mesh;
}

void export_mesh(const TriMesh& mesh, const std::filesystem::path& path, MeshFormat format, LengthUnit unit) {
  for (const auto& t : mesh.triangles) {
    for (std::uint32_t v : t) GEARSIM_CHECK(v < mesh.vertices.size(), "vertex index out of range");
  }
  const std::string bytes = format == MeshFormat::StlBinary  ? stl_binary(mesh, unit)
                            : format == MeshFormat::StlAscii ? stl_ascii(mesh, unit)
                                                             : obj(mesh, unit);
  write_output_file(path, bytes);
}

}  // namespace gearsim
