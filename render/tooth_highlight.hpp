// A gear mesh whose chosen teeth are whole sets of triangles, for highlighting (the faulty tooth).
// The mesh is the extruded outline (GearBody::mesh's vertices and side walls); only the caps are
// re-triangulated so that no cap triangle straddles a tooth's boundary: from where one gap
// mid-line crosses the outline (on the root circle) to where the other does — straight for an
// external tooth (the 64 µm circular segment under that chord, z = 36, counts as tooth), through
// one extra point outside the root circle for an internal one (whose tooth crosses the chord).
// Not a new geometry: no vertex is moved, the solid and its volume are unchanged.
#pragma once

#include <cstdint>
#include <vector>

#include "geometry/gear_spec.hpp"
#include "geometry/mesh.hpp"

namespace gearsim::render {

struct HighlightedGearMesh {
  TriMesh mesh;  // body frame, m: axis +z, faces at ±b/2
  std::vector<std::uint8_t> highlight;  // one per triangle: 1 = in a chosen tooth
};

// Throws InputError for a tooth index outside [0, z) (naming the gear) or an invalid spec.
HighlightedGearMesh gear_mesh_with_highlighted_teeth(const GearSpec& spec, const std::vector<int>& teeth);

}  // namespace gearsim::render
