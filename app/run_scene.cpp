#include "app/run_scene.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "app/run_analysis.hpp"
#include "input/gear_train.hpp"
#include "core/errors.hpp"
#include "geometry/mesh_io.hpp"
#include "render/tooth_highlight.hpp"

namespace gearsim::app {
namespace {

// Palette: sun/driver brass, planets steel blue, ring grey, other bodies light grey.
constexpr render::Rgb kInternal{150, 154, 162}, kExternal{96, 150, 206}, kInput{214, 160, 62};
// The "mesh" close-up: view height at the pitch point, m (three teeth of module 1 mm).
constexpr double kMeshViewHeight_m = 6e-3;
constexpr double kTilt_rad = 30.0 * std::numbers::pi / 180;

}  // namespace

RunMeshes run_meshes(const physics::Scenario& s) {
  RunMeshes m;
  std::string input;
  if (!s.motors.empty())
    for (const physics::JointDef& j : s.joints)
      if (j.name == s.motors.front().joint) input = j.body;
  for (std::size_t b = 0; b < s.bodies.size(); ++b) {
    const physics::BodyDef& def = s.bodies[b];
    render::SceneBody body;
    body.name = def.name;
    if (def.gear) {
      // The teeth that carry an error, highlighted.
      std::vector<int> faulty;
      for (const FlankOffset& e : def.gear->errors.flank_offsets) faulty.push_back(e.tooth);
      render::HighlightedGearMesh g = render::gear_mesh_with_highlighted_teeth(*def.gear, faulty);
      body.mesh = std::make_shared<const TriMesh>(std::move(g.mesh));
      if (!faulty.empty()) body.highlight = std::make_shared<const std::vector<std::uint8_t>>(std::move(g.highlight));
      body.colour = def.gear->kind == GearKind::Internal ? kInternal : kExternal;
    } else if (def.mesh) {
      try {
        body.mesh = std::make_shared<const TriMesh>(import_mesh(def.mesh->path, def.mesh->unit));
      } catch (const InputError& e) {
        throw InputError("body '" + def.name + "': " + e.what());
      }
      body.colour = kExternal;
    } else {
      continue;  // shapeless (a carrier arm): nothing to draw
    }
    if (def.name == input) body.colour = kInput;
    m.bodies.push_back(std::move(body));
    m.body_index.push_back(static_cast<int>(b));
  }
  return m;
}

render::Scene run_scene(const RunMeshes& m, const std::vector<Eigen::Isometry3d>& poses, const std::vector<std::string>& overlay) {
  render::Scene scene;
  scene.bodies = m.bodies;
  for (std::size_t k = 0; k < scene.bodies.size(); ++k) scene.bodies[k].pose = poses.at(static_cast<std::size_t>(m.body_index[k]));
  scene.overlay_lines = overlay;
  return scene;
}

std::optional<input::GearTrain> camera_train(const std::string& preset, const RunDir& run) {
  if (preset != "sun_mesh" && preset != "ring_mesh") return std::nullopt;
  return run_gear_train(run);
}

render::Camera run_camera(const std::string& preset, const physics::Scenario& s, const std::optional<input::GearTrain>& train,
                          const render::Scene& scene, const std::vector<Eigen::Isometry3d>& poses, double aspect) {
  if (preset == "overview") return render::overview_camera(render::scene_bounds(scene), aspect);
  if (preset == "tilted") return render::overview_camera(render::scene_bounds(scene), aspect, kTilt_rad);
  if (preset == "sun_mesh" || preset == "ring_mesh") {
    // The train's first planetary stage, else its first stage.
    GEARSIM_CHECK(train.has_value(), "run_camera: the close-up '" + preset + "' needs the run's train (camera_train)");
    const input::TrainStage& t = train->first_planetary() ? *train->first_planetary() : train->stages.front();
    // The faulty planet (the first whose gear carries an error), planet 0 without one.
    std::string planet = t.planetary ? t.planets.front() : t.driven;
    for (const physics::BodyDef& b : s.bodies)
      if (b.gear && !b.gear->errors.flank_offsets.empty() && std::find(t.planets.begin(), t.planets.end(), b.name) != t.planets.end()) {
        planet = b.name;
        break;
      }
    const bool ring = preset == "ring_mesh";
    if (ring && !t.planetary) throw InputError("--camera ring_mesh: the scenario has no ring gear");
    const std::string a = ring ? planet : (t.planetary ? t.sun : t.driver), b = ring ? t.ring : planet;
    Eigen::Vector3d ca = Eigen::Vector3d::Zero(), cb = Eigen::Vector3d::Zero();
    for (std::size_t k = 0; k < s.bodies.size(); ++k) {
      if (s.bodies[k].name == a) ca = poses[k].translation();
      if (s.bodies[k].name == b) cb = poses[k].translation();
    }
    // External pair: the pitch point divides the centre distance as z_a : z_b. Planet in ring:
    // it lies beyond the planet, a pitch radius from its centre away from the ring's centre.
    Eigen::Vector3d pitch;
    if (ring) {
      const Eigen::Vector3d out = (ca - cb).normalized();
      pitch = ca + out * (t.planet_teeth * (ca - cb).norm() / double(t.ring_teeth - t.planet_teeth));
    } else {
      const int za = t.planetary ? t.sun_teeth : t.driver_teeth, zb = t.planetary ? t.planet_teeth : t.driven_teeth;
      pitch = ca + (cb - ca) * za / double(za + zb);
    }
    pitch.z() = render::scene_bounds(scene).max_m.z();  // on the gears' front face
    render::Camera cam = render::closeup_camera(pitch, Eigen::Vector3d(0, 0, -1), kMeshViewHeight_m);
    // The line of centres upright in the image (the sun, or the planet, below), so the mesh holds
    // still on screen while the carrier turns.
    const Eigen::Vector3d up = (cb - ca).normalized();
    if (up.allFinite() && up.head<2>().norm() > 0.5) cam.up = ring ? Eigen::Vector3d(-up) : up;
    return cam;
  }
  throw InputError("--camera '" + preset + "': expected overview, tilted, sun_mesh or ring_mesh");
}

}  // namespace gearsim::app
