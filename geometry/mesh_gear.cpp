#include "geometry/mesh_gear.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "geometry/mesh_validate.hpp"

namespace gearsim {

MeshGear mesh_gear(const Prism& prism) {
  MeshGear g;
  // Gear frame: z along the extrusion, oriented to the mesh's own positive direction (+z for a
  // gear modelled about z) so that tooth angles given in mesh coordinates read the same; x along
  // the prism's x.
  Eigen::Vector3d gx = prism.frame.x, gy = prism.frame.y, gz = gx.cross(gy);
  g.outline = prism.outline;
  int dominant = 0;
  gz.cwiseAbs().maxCoeff(&dominant);
  if (gz[dominant] < 0) {
    // Mirror: flip y and z; the outline's v coordinates flip and its loops reverse.
    gy = -gy;
    gz = -gz;
    auto mirror = [](Polygon2& poly) {
      for (Eigen::Vector2d& v : poly.points) v.y() = -v.y();
      std::reverse(poly.points.begin(), poly.points.end());
    };
    mirror(g.outline.outer);
    for (Polygon2& h : g.outline.holes) mirror(h);
  }
  g.rotation.col(0) = gx;
  g.rotation.col(1) = gy;
  g.rotation.col(2) = gz;
  g.face_width_m = prism.height_m;
  g.origin_m = prism.frame.origin_m + 0.5 * prism.height_m * prism.frame.z;
  g.recognition = recognise_gear(g.outline);
  if (g.recognition) {
    g.axis_offset_m = g.recognition->axis_m;
    if (g.axis_offset_m.norm() > kAxisOnOriginTolerance_m) {
      g.outline = recentred(g.outline, g.axis_offset_m);
      g.origin_m += g.axis_offset_m.x() * gx + g.axis_offset_m.y() * gy;
      g.recognition->axis_m = Eigen::Vector2d::Zero();  // radii and angles were about the axis already
    }
  }
  return g;
}

MeshGearFile read_mesh_gear(const std::filesystem::path& path, LengthUnit unit) {
  MeshGearFile f;
  f.mesh = import_mesh(path, unit);
  require_valid_solid(validate_mesh(f.mesh), path.string());
  f.prism = recover_prism(f.mesh, kCadPrismTolerance_m);
  if (f.prism) f.gear = mesh_gear(*f.prism);
  return f;
}

Check check_layout(const RecognisedGear& g, const ToothLayout& given) {
  constexpr double kDeg = 180 / std::numbers::pi;
  std::ostringstream m;
  if (given.teeth != g.teeth) {
    m << given.teeth << " teeth given, the mesh shows " << g.teeth << " (tooth 0 at " << g.tooth0_angle_rad * kDeg << " deg)";
    return Refusal{m.str()};
  }
  const double pitch = 2 * std::numbers::pi / g.teeth;
  const double off = std::remainder(given.tooth0_angle_rad - g.tooth0_angle_rad, pitch);
  if (std::abs(off) <= kTooth0Tolerance * pitch) return {};
  m << "tooth 0 given at " << given.tooth0_angle_rad * kDeg << " deg lies " << std::abs(off) / pitch * 100
    << " % of a pitch from the nearest tooth centre line of the mesh (tooth 0 at " << g.tooth0_angle_rad * kDeg << " deg, pitch "
    << pitch * kDeg << " deg; limit " << kTooth0Tolerance * 100 << " %)";
  return Refusal{m.str()};
}

Check check_unit(const RecognisedGear& g, LengthUnit unit) {
  const double m = g.module_m;
  if (m >= kMinPlausibleModule_m && m <= kMaxPlausibleModule_m) return {};
  std::ostringstream msg;
  // Off the plausible range no standard module matches, so m is the tooth depth / 2.25: "about".
  const char* about = g.standard ? "" : "about ";
  msg << "read as " << symbol(unit) << ", its module is " << about << m * 1e3 << " mm" << (g.standard ? "" : " (tooth depth / 2.25)")
      << " (plausible: " << kMinPlausibleModule_m * 1e3 << " to " << kMaxPlausibleModule_m * 1e3 << " mm): is the unit right?";
  const double file_module = m / metres_per(unit);  // in file units
  for (LengthUnit u :
       {LengthUnit::Millimetre, LengthUnit::Inch, LengthUnit::Metre, LengthUnit::Centimetre, LengthUnit::Micrometre, LengthUnit::Foot}) {
    const double mu = file_module * metres_per(u);
    if (u != unit && mu >= 0.2e-3 && mu <= 50e-3) {
      msg << " (read as " << symbol(u) << " it would be " << about << mu * 1e3 << " mm)";
      break;
    }
  }
  return Refusal{msg.str()};
}

}  // namespace gearsim
