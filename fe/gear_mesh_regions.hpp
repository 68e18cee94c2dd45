// Which tooth, and which part of it, each edge of a gear mesh's toothed loop belongs to: the
// bookkeeping an FE deck needs to put contact surfaces and loads on chosen teeth and flanks.
// Not a mesher (gear_mesher.hpp) and not a contact search.
#pragma once

#include <vector>

#include "geometry/gear_dimensions.hpp"
#include "geometry/gear_spec.hpp"
#include "fe/quad_mesh.hpp"

namespace gearsim::fe {

// One toothed-loop edge, classified by its midpoint.
struct ToothedEdgeTag {
  // Tooth k whose centre line (polar angle tooth0_angle_rad + k·2π/z) is nearest, 0..z−1.
  int tooth = 0;
  // Side of that centre line: Ccw when the midpoint's polar angle is larger.
  Flank side = Flank::Ccw;
  // On the involute flank: the midpoint radius lies strictly between the form and tip circles
  // (the tip land, along the tip circle, is not flank; fillets and roots are not).
  bool on_flank = false;
};

// Tags parallel to mesh.toothed_edges. `spec` supplies z and tooth0_angle_rad; `dims` the form
// and tip radii (gear_dimensions(spec)). Eccentricity is ignored (polar angles about the origin).
std::vector<ToothedEdgeTag> tag_toothed_edges(const QuadMesh2& mesh, const GearSpec& spec, const GearDimensions& dims);

// The toothed edges on the given teeth; only flank edges when flanks_only, and only one side's
// flank when side is given.
struct ToothEdgeSelection {
  std::vector<int> teeth;
  bool flanks_only = true;
  bool one_side = false;
  Flank side = Flank::Ccw;  // used when one_side
};
std::vector<QuadEdge> select_tooth_edges(const QuadMesh2& mesh, const std::vector<ToothedEdgeTag>& tags, const ToothEdgeSelection& which);

// The quads that own the toothed-loop edges of one tooth's root on one side of its centre line:
// the fillet and root land between the form circle and the root circle (not flank, not tip
// land). Their stresses are the tooth-root (bending) stresses on that side. Sorted, unique.
// `kind` says on which side of the form circle the root lies (inside for external gears).
std::vector<int> root_elements(const QuadMesh2& mesh, const std::vector<ToothedEdgeTag>& tags, const GearDimensions& dims, GearKind kind,
                               int tooth, Flank side);

}  // namespace gearsim::fe
