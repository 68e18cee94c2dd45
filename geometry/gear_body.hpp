// GearBody: one generated gear carried through the whole geometry pipeline, spec → outline →
// watertight prism mesh → exact convex pieces (with tooth indices) → mass properties.
// What the physics and the renderer consume. Not a Bullet object.
#pragma once

#include "geometry/convex_decomposition.hpp"
#include "geometry/gear_profile.hpp"
#include "geometry/gear_spec.hpp"
#include "geometry/mass_properties.hpp"
#include "geometry/mesh.hpp"

namespace gearsim {

struct GearBody {
  GearSpec spec;
  GearOutline outline;
  TriMesh mesh;  // body frame: gear axis +z, mid-plane z = 0, faces from −b/2 to +b/2
  ConvexDecomposition decomposition;
  ConvexPieces3 pieces;  // in the body frame, each with its tooth index
  MassProperties mass;
};

GearBody make_gear_body(const GearSpec& spec, double density_kg_m3);

// The tooth layout of a spec, for the sector cut of the decomposition.
ToothLayout tooth_layout(const GearSpec& spec);

}  // namespace gearsim
