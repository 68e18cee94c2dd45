// A planetary set as a Scene: meshes for sun, ring and each planet (a planet may have its own spec,
// e.g. the faulty one, and highlighted teeth), placed by a PlanetaryPose, with a default palette.
// Not a pose source (planetary_pose.hpp, later run logs) and not a camera.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "geometry/gear_spec.hpp"
#include "geometry/mesh.hpp"
#include "geometry/planetary.hpp"
#include "render/constants.hpp"
#include "render/planetary_pose.hpp"
#include "render/scene.hpp"

namespace gearsim::render {

struct PlanetaryMeshes {
  std::shared_ptr<const TriMesh> sun, ring;
  std::vector<std::shared_ptr<const TriMesh>> planets;  // one per planet
  // Per planet: null, or one entry per triangle of that planet's mesh (non-zero = highlighted).
  std::vector<std::shared_ptr<const std::vector<std::uint8_t>>> planet_highlights;
};

struct PlanetaryPalette {
  Rgb sun{214, 160, 62};  // brass
  Rgb planet{96, 150, 206};  // steel blue
  Rgb ring{150, 154, 162};  // grey steel
  Rgb highlight{235, 45, 35};  // the faulty tooth
};

struct HighlightedTooth {
  int planet = 0;
  int tooth = 0;
};

// Outlines extruded over each face width (mid-plane z = 0), tessellated at the coarser of each
// spec's chordal deviation and chordal_deviation_m (drawing needs less than physics); a planet with highlighted teeth gets
// its own mesh (tooth_highlight.hpp), the others share one per spec. planet_specs: empty (every planet is
// spec.planet) or one per planet (same tooth count and centre distance, e.g. the faulty planet).
// Throws InputError for a wrong planet_specs count or a highlighted planet/tooth out of range.
PlanetaryMeshes planetary_meshes(const PlanetarySpec& spec, const std::vector<GearSpec>& planet_specs = {},
                                 const std::vector<HighlightedTooth>& highlighted = {},
                                 double chordal_deviation_m = constants::kRenderChordalDeviation_m);

// Bodies named "sun", "ring", "planet 0" … Throws InputError when the pose's planet count differs
// from the meshes' (a pose for another set, or no poses at all).
Scene planetary_scene(const PlanetaryMeshes& meshes, const PlanetaryPose& pose, const PlanetaryPalette& palette = {});

}  // namespace gearsim::render
