#include "render/planetary_scene.hpp"

#include <algorithm>
#include <string>

#include "core/errors.hpp"
#include "geometry/extrude.hpp"
#include "geometry/gear_profile.hpp"
#include "render/tooth_highlight.hpp"

namespace gearsim::render {
namespace {

GearSpec coarsened(GearSpec spec, double chordal_deviation_m) {
  spec.chordal_deviation_m = std::max(spec.chordal_deviation_m, chordal_deviation_m);
  return spec;
}

std::shared_ptr<const TriMesh> gear_mesh(const GearSpec& spec) {
  const GearOutline o = make_gear_outline(spec);
  return std::make_shared<const TriMesh>(extrude(o.outline, -0.5 * spec.face_width_m, 0.5 * spec.face_width_m));
}

}  // namespace

PlanetaryMeshes planetary_meshes(const PlanetarySpec& spec, const std::vector<GearSpec>& planet_specs,
                                 const std::vector<HighlightedTooth>& highlighted, double chordal_deviation_m) {
  if (!(chordal_deviation_m > 0)) throw InputError("planetary meshes: chordal_deviation_m must be positive");
  if (spec.planets < 1) throw InputError("planetary meshes: planets must be ≥ 1");
  if (!planet_specs.empty() && static_cast<int>(planet_specs.size()) != spec.planets)
    throw InputError("planetary meshes: " + std::to_string(planet_specs.size()) + " planet specs for " + std::to_string(spec.planets) +
                     " planets");
  for (const HighlightedTooth& h : highlighted)
    if (h.planet < 0 || h.planet >= spec.planets)
      throw InputError("planetary meshes: highlighted planet " + std::to_string(h.planet) + " out of range [0, " +
                       std::to_string(spec.planets) + ")");
  PlanetaryMeshes m;
  const double cd = chordal_deviation_m;
  m.sun = gear_mesh(coarsened(spec.sun, cd));
  m.ring = gear_mesh(coarsened(spec.ring, cd));
  std::shared_ptr<const TriMesh> shared_planet;
  m.planet_highlights.resize(spec.planets);
  for (int k = 0; k < spec.planets; ++k) {
    const GearSpec ps = coarsened(planet_specs.empty() ? spec.planet : planet_specs[k], cd);
    std::vector<int> teeth;
    for (const HighlightedTooth& h : highlighted)
      if (h.planet == k) teeth.push_back(h.tooth);
    if (!teeth.empty()) {
      HighlightedGearMesh hm = gear_mesh_with_highlighted_teeth(ps, teeth);
      m.planets.push_back(std::make_shared<const TriMesh>(std::move(hm.mesh)));
      m.planet_highlights[k] = std::make_shared<const std::vector<std::uint8_t>>(std::move(hm.highlight));
    } else if (planet_specs.empty()) {
      if (!shared_planet) shared_planet = gear_mesh(ps);
      m.planets.push_back(shared_planet);
    } else {
      m.planets.push_back(gear_mesh(ps));
    }
  }
  return m;
}

Scene planetary_scene(const PlanetaryMeshes& meshes, const PlanetaryPose& pose, const PlanetaryPalette& palette) {
  if (pose.planets.size() != meshes.planets.size())
    throw InputError("planetary scene: the pose has " + std::to_string(pose.planets.size()) + " planet poses for " +
                     std::to_string(meshes.planets.size()) + " planet meshes");
  Scene s;
  s.bodies.push_back({"sun", meshes.sun, pose.sun, palette.sun, nullptr, palette.highlight});
  s.bodies.push_back({"ring", meshes.ring, pose.ring, palette.ring, nullptr, palette.highlight});
  for (std::size_t k = 0; k < meshes.planets.size(); ++k) {
    const auto& h = k < meshes.planet_highlights.size() ? meshes.planet_highlights[k] : nullptr;
    s.bodies.push_back({"planet " + std::to_string(k), meshes.planets[k], pose.planets[k], palette.planet, h, palette.highlight});
  }
  return s;
}

}  // namespace gearsim::render
