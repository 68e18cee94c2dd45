// Mesh files in and out: import any format Assimp reads (STL ASCII/binary, OBJ, PLY, ...) into a
// welded TriMesh in metres, and export a TriMesh as binary STL, ASCII STL or OBJ.
// The length unit of the file is always explicit; millimetres is the CAD default.
// Not validation and not repair: import keeps whatever topology the file has (holes, flipped or
// degenerate faces); check it with mesh_validate.hpp before trusting it.
#pragma once

#include <filesystem>
#include <optional>
#include <string_view>

#include "geometry/mesh.hpp"

namespace gearsim {

// --- Constants of mesh I/O (candidates for geometry/constants.hpp) ------------------------------
namespace constants {
// Weld tolerance on import, in m: 0, i.e. vertices are merged only when their coordinates are
// exactly equal (after node transform and unit scaling, -0 == +0). STL repeats each shared
// vertex as the same float triple in every facet, so an exact weld recovers the topology of any
// correct file; an epsilon weld would hide real gaps (reported instead by validate_mesh) and can
// collapse the thin features of a tooth tip.
inline constexpr double kImportWeldTolerance_m = 0.0;
}  // namespace constants

// Length unit of the coordinates stored in a mesh file.
enum class LengthUnit { Metre, Centimetre, Millimetre, Micrometre, Inch, Foot };

// Metres in one `unit` (e.g. 0.001 for Millimetre, 0.0254 for Inch).
double metres_per(LengthUnit unit);

// Short symbol: "m", "cm", "mm", "um", "in", "ft".
std::string_view symbol(LengthUnit unit);

// The unit with this symbol ("m", "cm", "mm", "um" or "µm", "in", "ft"), or nullopt.
std::optional<LengthUnit> parse_length_unit(std::string_view text);

// Formats export_mesh writes.
enum class MeshFormat { StlBinary, StlAscii, Obj };

// Bytes of a mesh file: a binary STL holds 50 bytes a triangle, so 512 MiB is 1e7 triangles,
// about 100 times the finest gear export of the CAD corpora; more is not a gear's mesh.
constexpr std::size_t kMaxMeshFileBytes = std::size_t{512} << 20;

// Reads every triangle of every mesh in the file's scene, node transforms applied, coordinates
// multiplied by metres_per(unit), vertices welded exactly (see constants::kImportWeldTolerance_m).
// Polygons are triangulated; point and line primitives carry no surface and are dropped.
// `unit` is what one coordinate unit in the file means: STL, OBJ and PLY carry no unit.
// Collada (.dae) files are already scaled to metres by Assimp from their <unit> tag: use Metre.
// Assimp stores coordinates as float32, so imported positions are float32-exact in file units.
// Throws InputError naming the file: missing, empty, unknown format, parse failure (Assimp's
// own message included), or no triangles.
TriMesh import_mesh(const std::filesystem::path& path, LengthUnit unit = LengthUnit::Millimetre);

// Writes the mesh with coordinates divided by metres_per(unit). Deterministic: the same mesh
// gives byte-identical files (no timestamps, locale-independent number formatting).
//  - StlBinary / StlAscii: float32 coordinates (ASCII prints each float32 in its shortest
//    round-trip form), per-facet normal from the winding, no shared vertices (STL has none).
//  - Obj: shared vertices and 1-based faces, each double in its shortest round-trip form.
// Throws InputError naming the path if it cannot be written.
void export_mesh(const TriMesh& mesh, const std::filesystem::path& path, MeshFormat format, LengthUnit unit = LengthUnit::Millimetre);

}  // namespace gearsim
