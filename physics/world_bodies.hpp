// Building Bullet rigid bodies from body definitions: generated gears and CAD meshes become
// compounds of their exact convex pieces with mass properties from the mesh; gears also get the
// flank tables tooth contact uses; a body's planar pose. Internal to physics/ (model.cpp).
#pragma once

#include <btBulletDynamicsCommon.h>

#include <cmath>
#include <memory>
#include <optional>
#include <vector>

#include "contact/flank_table.hpp"
#include "contact/tooth_contact.hpp"
#include "physics/scenario.hpp"
#include "physics/world.hpp"

namespace gearsim::physics {

inline btVector3 bt(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }
inline Eigen::Vector3d eig(const btVector3& v) { return {v.x(), v.y(), v.z()}; }

struct BuiltBody {
  std::string name;
  std::unique_ptr<btCollisionShape> shape;
  std::vector<std::unique_ptr<btCollisionShape>> children;
  std::unique_ptr<btRigidBody> rigid;
  // The gear (or mesh) frame expressed in the centre-of-mass principal frame Bullet simulates.
  btTransform com_from_gear = btTransform::getIdentity();
  bool fixed = false;
  double mass_kg = 0;
  double inertia_axis_kg_m2 = 0;  // about the gear axis
  // Gears only.
  std::shared_ptr<const contact::FlankTable> flanks;  // shared by bodies of the same gear
  double face_width_m = 0;
  double contact_radius_m = 0;  // base radius (generated) or mid-tooth radius (meshes), for damping
  // Flanks generated from a gear spec (smooth to the outline's nm), not read from a CAD mesh: only
  // between two such gears does verify.continued_search let a continued contact stand alone. A
  // faceted mesh's flanks (MCAD's STL) give a contact's depth profile several maxima ~20 µm apart:
  // there the deeper of the continued and the searched maximum stands (docs/tooth-contact.md,
  // "Continuation").
  bool flanks_from_spec = false;
};

BuiltBody build_body(const BodyDef& def, const ContactDef& contact);

// How far the two gears' faces overlap along a's axis at their initial poses, m (≤ 0: they lie
// side by side, in different planes): the face width their mesh has.
double axial_overlap_m(const BuiltBody& a, const BuiltBody& b);

// Can the two gears' toothed zones reach each other (at their initial poses)? Only gears whose
// faces overlap along the axis do: gears in different planes never mesh, however close their
// axes. Throws InputError when they could but their axes are not parallel.
bool gears_can_mesh(const BuiltBody& a, const BuiltBody& b);

// Whether a pair macro chose the centre distance of gears a and b (no centre_distance_m given).
bool centre_distance_derived(const std::vector<PairTableDef>& tables, const std::string& a, const std::string& b);

// Refuses (InputError naming the pair, teeth, radii and depth) two gears whose bodies lie inside
// each other, or whose teeth overlap by more than World::kStartOverlapLimit_m at their poses or
// anywhere over a mesh period turned at the ideal ratio (mesh_cycle_overlap: interference).
// `derived_distance`: the pair macro chose the centre distance (zero backlash); the message says so.
void require_clear_mesh(const BuiltBody& a, const contact::PlanarPose& pose_a, const BuiltBody& b, const contact::PlanarPose& pose_b,
                        bool derived_distance);

// Damping of one tooth-pair contact, N·s/m: a fraction ζ of critical for stiffness k (N/m) on
// the pair's reduced mass m_eq (kg): c = 2ζ√(k·m_eq).
double contact_damping_N_s_per_m(double stiffness_N_per_m, double reduced_mass_kg, double damping_ratio);

// Tooth-pair stiffness and damping of a meshing pair (the constant stiffness per face width).
GearPairInfo pair_contact(const BuiltBody& a, const BuiltBody& b, const ContactDef& contact);

// Gear-frame pose projected on the common plane (the gear axes must be parallel to world z): its
// angle from the gear frame's x axis, and that axis normalised in the plane as the angle's cosine
// and sine (the same rotation to rounding, without libm's sincos of an angle that grows with
// every turn).
inline contact::PlanarPose planar_pose(const BuiltBody& b) {
  const btTransform t = b.rigid->getWorldTransform() * b.com_from_gear;
  const btVector3 x = t.getBasis().getColumn(0);
  contact::PlanarPose p{{t.getOrigin().x(), t.getOrigin().y()}, std::atan2(x.y(), x.x())};
  const double length = std::sqrt(x.x() * x.x() + x.y() * x.y());
  p.cos_angle = x.x() / length;
  p.sin_angle = x.y() / length;
  p.rotation_of_rad = p.angle_rad;
  return p;
}

}  // namespace gearsim::physics
