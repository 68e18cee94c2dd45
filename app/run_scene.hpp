// What a rendered frame of a run shows: a render mesh per scenario body (generated gears
// extruded from their outlines with the teeth that carry errors highlighted, CAD meshes as
// imported; shapeless bodies such as a carrier are not drawn) posed by a PoseReplay, and the
// camera presets for any gear train. Not the renderer.
#pragma once

#include <Eigen/Geometry>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/run_dir.hpp"
#include "input/gear_train.hpp"
#include "physics/scenario.hpp"
#include "render/camera.hpp"
#include "render/scene.hpp"

namespace gearsim::app {

struct RunMeshes {
  std::vector<render::SceneBody> bodies;  // one per drawn body, in scenario order
  std::vector<int> body_index;  // scenario body of each
};

// InputError naming the body when a mesh file cannot be read.
RunMeshes run_meshes(const physics::Scenario& s);

// The scene at one set of poses (scenario order, PoseReplay::poses), with overlay lines.
render::Scene run_scene(const RunMeshes& m, const std::vector<Eigen::Isometry3d>& poses, const std::vector<std::string>& overlay);

// Cameras: "overview" (along −z), "tilted" (30° toward −y), "sun_mesh" and "ring_mesh" (close-ups,
// 6 mm tall, on the pitch point of the faulty planet — the first planet whose gear carries an
// error, else planet 0 — with the sun and with the ring; a pair's "sun_mesh" is its mesh).
// `train`: the run's (camera_train), for the close-ups. InputError naming the preset when it is
// unknown or the train has no ring.
render::Camera run_camera(const std::string& preset, const physics::Scenario& s, const std::optional<input::GearTrain>& train,
                          const render::Scene& scene, const std::vector<Eigen::Isometry3d>& poses, double aspect);

// The run's gear train when `preset` is a close-up that needs it, else nothing: found once per
// render, not per frame.
std::optional<input::GearTrain> camera_train(const std::string& preset, const RunDir& run);

}  // namespace gearsim::app
