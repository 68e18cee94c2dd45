// The planar outline of a spur gear with its manufacturing errors, tessellated within the spec's
// chordal deviation. External gears: rack-generated involute flanks with the exact trochoidal
// root fillet (the envelope of the cutter's tip radius). Internal gears: involute flanks with a
// circular root fillet tangent to flank and root circle (a stated approximation of the fillet a
// pinion-type cutter leaves). Not a mesh: extrude.hpp makes one.
#pragma once

#include <Eigen/Core>

#include "geometry/gear_dimensions.hpp"
#include "geometry/gear_spec.hpp"
#include "geometry/outline.hpp"

namespace gearsim {

struct GearOutline {
  GearDimensions dims;
  // External: outer = toothed loop, holes = {bore} when bore_diameter_m > 0.
  // Internal: outer = rim circle, holes = {toothed loop}.
  Outline2 outline;
};

GearOutline make_gear_outline(const GearSpec& spec);

// The exact (untessellated) point of the involute of one flank of one tooth at a radius between
// the form and tip circles, errors included: what the tessellated outline approximates.
Eigen::Vector2d flank_point(const GearSpec& spec, const GearDimensions& dims, int tooth, Flank flank, double radius_m);

// Unit normal of that flank at that radius, pointing out of the tooth material.
Eigen::Vector2d flank_normal(const GearSpec& spec, const GearDimensions& dims, int tooth, Flank flank, double radius_m);

}  // namespace gearsim
