// A CAD gear mesh in its gear frame: the prism recovered from the triangles, turned so that its
// extrusion runs along +z of the mesh's own dominant axis (a gear modelled about −z is mirrored
// into +z, so the tooth angles read as in the CAD tool), the gear recognised from the outline,
// and the frame centred on the gear's axis wherever the CAD tool put it. Not a body: physics
// builds one from this.
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <optional>
#include <string>

#include "core/result.hpp"
#include "geometry/convex_decomposition.hpp"
#include "geometry/gear_recognition.hpp"
#include "geometry/mesh.hpp"
#include "geometry/mesh_io.hpp"
#include "geometry/prism.hpp"

namespace gearsim {

// An axis found closer than this to the mesh's origin line is taken as on it (the frame is not
// moved, so a gear modelled about its axis keeps its coordinates bit for bit), m.
inline constexpr double kAxisOnOriginTolerance_m = 0.1e-6;

struct MeshGear {
  Outline2 outline;  // the prism's outline in the gear frame (axis at the origin), m
  double face_width_m = 0;  // m
  Eigen::Matrix3d rotation;  // columns: the gear frame's x, y, z in mesh coordinates
  Eigen::Vector3d origin_m;  // the gear frame's origin in mesh coordinates (mid face width), m
  Result<RecognisedGear> recognition = Refusal{"not recognised yet"};  // the outline as a gear (about the gear frame's origin)
  // Where the axis was found in the cap plane, relative to the mesh's origin line, m; the frame
  // was moved there when larger than kAxisOnOriginTolerance_m.
  Eigen::Vector2d axis_offset_m = Eigen::Vector2d::Zero();

  // A mesh vertex in the gear frame.
  Eigen::Vector3d to_gear(const Eigen::Vector3d& p_mesh) const { return rotation.transpose() * (p_mesh - origin_m); }
};

MeshGear mesh_gear(const Prism& prism);

// How far, in m, a CAD mesh's vertex may lie off its two cap planes and still count as a prism:
// STL stores float32 (~3 nm at 50 mm, 15 nm past 128 mm) and CAD exports carry coordinate noise
// (±0.5 µm per coordinate is 1 µm between two vertices); 2 µm, the default flank-table departure
// (contact.max_flank_departure_m): a mesh rougher than that could not be simulated anyway.
inline constexpr double kCadPrismTolerance_m = 2e-6;

// A mesh file read (import_mesh), checked to be a valid solid (throws InputError naming the
// file otherwise) and, when it is a prism, brought into its gear frame.
struct MeshGearFile {
  TriMesh mesh;  // as read, mesh coordinates, m
  Result<Prism> prism = Refusal{"no mesh read"};  // the prism within kCadPrismTolerance_m, or why not
  std::optional<MeshGear> gear;  // that prism in its gear frame
};
MeshGearFile read_mesh_gear(const std::filesystem::path& path, LengthUnit unit);

// A given tooth 0 may lie this fraction of a pitch off the recognised tooth centre line: a
// rounded angle passes, a half-pitch error (sector boundaries through the teeth) does not.
inline constexpr double kTooth0Tolerance = 0.02;

// A tooth layout (from a scenario) checked against the recognised gear: passes when it agrees
// (same count, tooth 0 within kTooth0Tolerance of a pitch of some tooth's centre line), else
// refused with what the mesh shows.
Check check_layout(const RecognisedGear& g, const ToothLayout& given);

// Modules a gear mesh may have, m: a fine-pitch watch gear to a mill gear. Outside, the mesh's
// unit is almost certainly wrong (a mm file read as m makes a 1 mm module 1 m).
inline constexpr double kMinPlausibleModule_m = 0.05e-3;
inline constexpr double kMaxPlausibleModule_m = 100e-3;

// Passes when the recognised module is plausible in `unit`, else refused saying which unit would
// make it so.
Check check_unit(const RecognisedGear& g, LengthUnit unit);

}  // namespace gearsim
