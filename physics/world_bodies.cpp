#include "physics/world_bodies.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "contact/flank_table_store.hpp"
#include "core/errors.hpp"
#include "geometry/gear_body.hpp"
#include "geometry/mass_properties.hpp"
#include "geometry/mesh_gear.hpp"
#include "geometry/mesh_validate.hpp"
#include "geometry/prism.hpp"

namespace gearsim::physics {
namespace {

// Collision margin of the convex pieces, m. Gears never touch through Bullet's narrowphase
// (tooth contact does that), so this only matters against other bodies; Bullet's default
// (0.04) is sized for metre-scale boxes.
constexpr double kPieceMargin_m = 10e-6;

// Flank-table radial samples: 4096 over a tooth height of 2.25 modules is ~0.5 µm per sample at
// m = 1 mm; the cubic through the outline's vertices carries the accuracy, this the resolution.
constexpr int kFlankSamples = 4096;

btTransform to_bt(const Pose& p) {
  btTransform t;
  t.setOrigin(btVector3(p.position_m.x(), p.position_m.y(), p.position_m.z()));
  t.setRotation(btQuaternion(p.orientation.x(), p.orientation.y(), p.orientation.z(), p.orientation.w()));
  return t;
}

// Gear frame → principal centre-of-mass frame.
btTransform com_frame(const MassProperties& m) {
  btMatrix3x3 basis;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) basis[r][c] = m.principal_axes(r, c);
  return btTransform(basis, btVector3(m.centre_of_mass_m.x(), m.centre_of_mass_m.y(), m.centre_of_mass_m.z()));
}

// The layout the tooth contact uses: the scenario's (filled from the mesh when it gave none),
// refused when the mesh is not a recognised gear, shows other teeth, or has an implausible size.
ToothLayout checked_layout(const MeshGear& mg, const MeshSource& src, const std::string& who) {
  if (!mg.recognition) throw InputError(who + ": not recognised as a spur gear: " + mg.recognition.reason());
  const RecognisedGear& g = *mg.recognition;
  if (const Check u = check_unit(g, src.unit); !u) throw InputError(who + ": " + u.reason());
  if (const Check m = check_layout(g, *src.teeth); !m) throw InputError(who + ": " + m.reason());
  return *src.teeth;
}

void add_pieces(BuiltBody& b, const ConvexPieces3& pieces, const btTransform& com_from_shape) {
  auto compound = std::make_unique<btCompoundShape>(true, static_cast<int>(pieces.pieces.size()));
  for (const ConvexPiece3& piece : pieces.pieces) {
    auto hull = std::make_unique<btConvexHullShape>();
    for (const Eigen::Vector3d& p : piece.points_m) hull->addPoint(btVector3(p.x(), p.y(), p.z()), false);
    hull->recalcLocalAabb();
    hull->setMargin(kPieceMargin_m);
    compound->addChildShape(com_from_shape, hull.get());
    b.children.push_back(std::move(hull));
  }
  b.shape = std::move(compound);
}

// Refuses a flank table that does not describe the outline it came from.
void require_faithful(const contact::FlankTable& t, const std::string& who, const ContactDef& contact) {
  const contact::FlankTable::Departure& d = t.departure();
  if (d.departure_m <= contact.max_flank_departure_m) return;
  std::ostringstream msg;
  msg << who << ": its flank table departs " << d.departure_m * 1e6 << " um from the mesh outline at tooth " << d.tooth << ", "
      << (d.flank == Flank::Ccw ? "Ccw" : "Cw") << " flank, r = " << d.r_m * 1e3 << " mm (limit " << contact.max_flank_departure_m * 1e6
      << " um, contact.max_flank_departure_m; outline resolution " << t.knot_resolution_m() * 1e6
      << " um): the outline's vertices there do not lie on a smooth flank (a corner, a tooth layout that does not "
         "match the mesh, or coordinates too coarse for the tooth size)";
  throw InputError(msg.str());
}

// The shape, mass and flank table of a generated gear (its errors included).
void gear_shape(const BodyDef& def, const ContactDef& contact, const std::string& who, BuiltBody& b, std::optional<MassProperties>& mass,
                ConvexPieces3& pieces) {
  GearSpec spec = *def.gear;
  if (spec.helix_angle_rad != 0)
    throw InputError(who + ": a helical gear (β = " + std::to_string(std::abs(spec.helix_angle_rad) * 180 / 3.14159265358979323846) +
                     "°): helical gears are read, tabled and exported (gearsim gears), not yet simulated: the contact along their "
                     "face is not in the model");
  spec.chordal_deviation_m = contact.chordal_deviation_m;
  const double density = def.density_kg_m3.value_or(0);
  GEARSIM_CHECK(def.mass_kg || density > 0, who + ": density_kg_m3 or mass_kg (input/ refuses a scenario without)");
  GearBody g = make_gear_body(spec, def.mass_kg ? 1.0 : density);
  if (def.mass_kg) g.mass = mass_properties(g.mesh, *def.mass_kg / g.mass.volume_m3);
  mass = g.mass;
  pieces = std::move(g.pieces);
  const bool internal = spec.kind == GearKind::Internal;
  b.flanks = contact::shared_flank_table(internal ? g.outline.outline.holes.front() : g.outline.outline.outer,
                                         ToothLayout{spec.teeth, spec.tooth0_angle_rad}, internal, kFlankSamples);
  require_faithful(*b.flanks, who, contact);
  b.flanks_from_spec = true;
  b.face_width_m = spec.face_width_m;
  b.contact_radius_m = g.outline.dims.base_radius_m;
}

// The shape, mass and (for a toothed mesh) flank table of a CAD mesh body, in its gear frame.
void mesh_shape(const BodyDef& def, const ContactDef& contact, const std::string& who, BuiltBody& b, std::optional<MassProperties>& mass,
                ConvexPieces3& pieces) {
  const MeshGearFile f = read_mesh_gear(def.mesh->path, def.mesh->unit);
  const TriMesh& mesh = f.mesh;
  double density = def.density_kg_m3.value_or(0);
  const MassProperties unit = mass_properties(mesh, 1.0);
  if (def.mass_kg) density = *def.mass_kg / unit.volume_m3;
  GEARSIM_CHECK(density > 0, who + ": density_kg_m3 or mass_kg (input/ refuses a scenario without)");
  if (def.mesh->teeth) {
    const std::string file = def.mesh->path.string();
    if (!f.gear)
      throw InputError(who + ": " + file + " has teeth but is not a prism (" + f.prism.reason() +
                       "); tooth contact needs a spur-gear extrusion");
    const MeshGear& mg = *f.gear;
    const ToothLayout layout = checked_layout(mg, *def.mesh, who + " (" + file + ")");
    const RecognisedGear& rg = *mg.recognition;
    DecompositionOptions opt;
    opt.tooth_layout = layout;
    const double half = 0.5 * mg.face_width_m;
    pieces = extrude_pieces(decompose(mg.outline, opt), PrismFrame{}, -half, half);  // gear frame
    const Polygon2& loop = rg.loop < 0 ? mg.outline.outer : mg.outline.holes[static_cast<std::size_t>(rg.loop)];
    b.flanks = contact::shared_flank_table(loop, layout, rg.internal, kFlankSamples);
    require_faithful(*b.flanks, who + " (" + file + ")", contact);
    b.face_width_m = mg.face_width_m;
    b.contact_radius_m = 0.5 * (b.flanks->r_min_m() + b.flanks->r_max_m());
    TriMesh in_gear = mesh;
    for (Eigen::Vector3d& v : in_gear.vertices) v = mg.to_gear(v);
    mass = mass_properties(in_gear, density);
  } else {
    // A toothless mesh body: its own coordinates are its frame.
    mass = mass_properties(mesh, density);
    if (f.prism)
      pieces = extrude_pieces(decompose(f.prism->outline), *f.prism);
    else
      throw InputError(who + ": " + def.mesh->path.string() + " is not a prism (" + f.prism.reason() +
                       "); only prismatic meshes are simulated so far");
  }
}

}  // namespace

BuiltBody build_body(const BodyDef& def, const ContactDef& contact) {
  BuiltBody b;
  b.name = def.name;
  b.fixed = def.fixed;
  const std::string who = "body '" + def.name + "'";
  std::optional<MassProperties> mass;
  ConvexPieces3 pieces;
  GEARSIM_CHECK(!(def.gear && def.mesh), who + ": one shape, a gear or a mesh (input/ refuses a scenario with both)");
  if (def.gear) {
    gear_shape(def, contact, who, b, mass, pieces);
  } else if (def.mesh) {
    mesh_shape(def, contact, who, b, mass, pieces);
  } else {
    GEARSIM_CHECK(def.mass_kg && def.principal_inertia_kg_m2,
                  who + ": a shapeless body's mass_kg and principal_inertia_kg_m2 (input/ refuses one without)");
    MassProperties m;
    m.mass_kg = *def.mass_kg;
    m.principal_moments_kg_m2 = *def.principal_inertia_kg_m2;
    mass = m;
  }
  if ((def.gear || def.mesh) && def.principal_inertia_kg_m2) {
    // Given moments replace the shape's (about its centre of mass, in the body's own axes).
    GEARSIM_CHECK(def.mass_kg.has_value(), who + ": principal_inertia_kg_m2 on a shaped body with mass_kg (input/ refuses it without)");
    mass->principal_moments_kg_m2 = *def.principal_inertia_kg_m2;
    mass->principal_axes = Eigen::Matrix3d::Identity();
    mass->inertia_com_kg_m2 = def.principal_inertia_kg_m2->asDiagonal();
  }
  b.mass_kg = mass->mass_kg;
  const btTransform com_in_gear = com_frame(*mass);
  b.com_from_gear = com_in_gear.inverse();
  if (!pieces.pieces.empty())
    add_pieces(b, pieces, b.com_from_gear);
  else
    b.shape = std::make_unique<btEmptyShape>();
  const Eigen::Vector3d& I = mass->principal_moments_kg_m2;
  // Inertia about the gear axis (z of the gear frame) from the principal tensor.
  Eigen::Matrix3d tensor = mass->principal_axes * I.asDiagonal() * mass->principal_axes.transpose();
  b.inertia_axis_kg_m2 = def.gear || (def.mesh && def.mesh->teeth) ? tensor(2, 2) : I.z();
  const double m = b.fixed ? 0.0 : b.mass_kg;
  btRigidBody::btRigidBodyConstructionInfo ci(m, nullptr, b.shape.get(), b.fixed ? btVector3(0, 0, 0) : btVector3(I.x(), I.y(), I.z()));
  b.rigid = std::make_unique<btRigidBody>(ci);
  b.rigid->setWorldTransform(to_bt(def.pose) * com_in_gear);
  b.rigid->setActivationState(DISABLE_DEACTIVATION);
  b.rigid->setDamping(0, 0);
  return b;
}

namespace {

// Where gear b's frame lies from gear a's: along a's axis and across it (in a's plane), m.
struct AxialOffset {
  double along_m = 0, across_m = 0;
};
AxialOffset offset_of(const BuiltBody& a, const BuiltBody& b) {
  const btTransform ta = a.rigid->getWorldTransform() * a.com_from_gear;
  const btTransform tb = b.rigid->getWorldTransform() * b.com_from_gear;
  const btVector3 axis = ta.getBasis().getColumn(2), sep = tb.getOrigin() - ta.getOrigin();
  const double along = sep.dot(axis);
  return {along, (sep - along * axis).length()};
}

}  // namespace

double axial_overlap_m(const BuiltBody& a, const BuiltBody& b) {
  // Each gear frame sits at mid face width: the faces span ±w/2 about it along the axis.
  const double along = offset_of(a, b).along_m;
  return std::min(0.5 * a.face_width_m, along + 0.5 * b.face_width_m) - std::max(-0.5 * a.face_width_m, along - 0.5 * b.face_width_m);
}

bool gears_can_mesh(const BuiltBody& a, const BuiltBody& b) {
  // Gears mesh in a plane: their faces must overlap along the axis (gears of two stages side by
  // side on one shaft line do not touch however close their axes are), and their toothed
  // zones must reach each other across it.
  if (!(axial_overlap_m(a, b) > 0)) return false;
  const double d = offset_of(a, b).across_m;
  const contact::FlankTable &fa = *a.flanks, &fb = *b.flanks;
  bool reach;
  if (!fa.internal() && !fb.internal())
    reach = d < fa.r_max_m() + fb.r_max_m();
  else {
    const contact::FlankTable& ext = fa.internal() ? fb : fa;
    const contact::FlankTable& ring = fa.internal() ? fa : fb;
    reach = d + ext.r_max_m() > ring.r_min_m() && d < ring.r_max_m();
  }
  if (!reach) return false;
  const btVector3 za = (a.rigid->getWorldTransform() * a.com_from_gear).getBasis().getColumn(2);
  const btVector3 zb = (b.rigid->getWorldTransform() * b.com_from_gear).getBasis().getColumn(2);
  if (std::abs(za.dot(zb)) < 1 - 1e-9)
    throw InputError("gears '" + a.name + "' and '" + b.name +
                     "' overlap but their axes are not parallel: tooth contact "
                     "supports spur gears on parallel axes");
  return true;
}

// Positions per mesh period at which a pair's overlap is checked before a run (a tip's path
// across the mate's fillet spans tens of them at this spacing).
constexpr int kMeshCycleSteps = 256;

bool centre_distance_derived(const std::vector<PairTableDef>& tables, const std::string& a, const std::string& b) {
  for (const PairTableDef& t : tables)
    if (t.centre_distance_derived && ((t.driver == a && t.driven == b) || (t.driver == b && t.driven == a))) return true;
  return false;
}

void require_clear_mesh(const BuiltBody& a, const contact::PlanarPose& pose_a, const BuiltBody& b, const contact::PlanarPose& pose_b,
                        bool derived_distance) {
  // Bodies inside each other (a wrong unit, a centre distance for other gears): beyond what
  // tooth contact can see, so refused on the radii alone.
  const double d = (pose_b.centre_m - pose_a.centre_m).norm();
  const contact::FlankTable &fa = *a.flanks, &fb = *b.flanks;
  const bool ring = fb.internal();
  if (ring ? d + fa.r_max_m() > fb.r_max_m() : d < fa.r_min_m() + fb.r_min_m()) {
    std::ostringstream msg;
    msg << "scenario: gears '" << a.name << "' and '" << b.name << "' share a plane (their faces overlap by " << axial_overlap_m(a, b) * 1e3
        << " mm along the axis) and are " << std::round(d * 1e9) * 1e-6 << " mm apart, but "
        << (ring ? "the external gear's tip circle (" + std::to_string(fa.r_max_m() * 1e3) + " mm) crosses the ring's root circle (" +
                       std::to_string(fb.r_max_m() * 1e3) + " mm)"
                 : "their root circles (" + std::to_string(fa.r_min_m() * 1e3) + " and " + std::to_string(fb.r_min_m() * 1e3) +
                       " mm) overlap: one body lies inside the other")
        << ". Check the centre distance, the meshes' unit and the gears' positions along the axis (gears in different planes do not mesh)";
    throw InputError(msg.str());
  }
  const contact::MeshCycleOverlap o = contact::mesh_cycle_overlap(*a.flanks, pose_a, *b.flanks, pose_b, kMeshCycleSteps);
  if (o.deepest.depth_m > World::kStartOverlapLimit_m) {
    const contact::ToothContact& c = o.deepest;
    std::ostringstream msg;
    msg << "scenario: gears '" << a.name << "' and '" << b.name << "' overlap "
        << (o.turn_a_rad == 0 ? "at t = 0" : "over their mesh cycle") << ": tooth " << c.tooth_a << " of '" << a.name << "' is "
        << c.depth_m * 1e6 << " um deep in tooth " << c.tooth_b << " of '" << b.name << "'";
    if (o.turn_a_rad != 0) msg << " after '" << a.name << "' turns " << o.turn_a_rad * 180 / std::numbers::pi << " deg at the ideal ratio";
    msg << ", at r = " << o.radius_a_m * 1e3 << " mm on '" << a.name << "' (teeth " << a.flanks->r_min_m() * 1e3 << "–"
        << a.flanks->r_max_m() * 1e3 << " mm) and r = " << o.radius_b_m * 1e3 << " mm on '" << b.name << "' (teeth "
        << b.flanks->r_min_m() * 1e3 << "–" << b.flanks->r_max_m() * 1e3 << " mm); limit " << World::kStartOverlapLimit_m * 1e6
        << " um. The centre distance (" << d * 1e3
        << " mm) is too small for these gears, a tip cuts into the mate's "
           "fillet (interference), or a tooth layout (teeth, tooth0_deg) does not match the mesh";
    if (derived_distance)
      msg << ". That distance is the pair's zero-backlash one (no centre_distance_m given): gears that clear each "
             "other only with backlash need their centre_distance_m";
    throw InputError(msg.str());
  }
}

double contact_damping_N_s_per_m(double k, double m_eq, double zeta) { return 2 * zeta * std::sqrt(k * m_eq); }

GearPairInfo pair_contact(const BuiltBody& a, const BuiltBody& b, const ContactDef& c) {
  GearPairInfo info;
  info.body_a = a.name;
  info.body_b = b.name;
  info.face_width_m = axial_overlap_m(a, b);  // both faces' width where they share a plane
  info.stiffness_N_per_m = c.stiffness_N_per_m_per_m * info.face_width_m;
  // Effective mass along the line of action from the rotational inertias (J/r²); a fixed gear
  // contributes none. Planet translation on its carrier is neglected here.
  auto inv_mass = [](const BuiltBody& g) { return g.fixed ? 0.0 : g.contact_radius_m * g.contact_radius_m / g.inertia_axis_kg_m2; };
  const double m_eq = 1.0 / (inv_mass(a) + inv_mass(b));
  info.reduced_mass_kg = m_eq;
  info.damping_N_s_per_m = contact_damping_N_s_per_m(info.stiffness_N_per_m, m_eq, c.damping_ratio);
  return info;
}

}  // namespace gearsim::physics
