// Bad input to the renderer is refused with an InputError that names what is wrong: resolution,
// anti-aliasing, an empty scene, bodies without meshes or poses, cameras that cannot project.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <string>

#include "core/errors.hpp"
#include "render/renderer.hpp"
#include "render/shading_mesh.hpp"

namespace gearsim::render {
namespace test_renderer_errors {

// The message of the InputError `f` throws (empty when it throws nothing).
template <class F>
std::string input_error(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

RenderSettings small() {
  RenderSettings s;
  s.width_px = 64;
  s.height_px = 48;
  return s;
}

SceneBody body(const std::string& name, std::shared_ptr<const TriMesh> mesh) {
  SceneBody b;
  b.name = name;
  b.mesh = std::move(mesh);
  return b;
}

Scene one_sphere() {
  Scene s;
  s.bodies.push_back(body("ball", std::make_shared<const TriMesh>(sphere_mesh({0, 0, 0}, 0.01))));
  return s;
}

Camera camera() {
  Camera c;
  c.eye_m = {0, 0, 0.2};
  return c;
}

TEST(RendererErrors, ResolutionMustBePositiveAndBounded) {
  for (auto [w, h] : {std::pair{0, 48}, {64, -1}, {100000, 48}}) {
    RenderSettings s = small();
    s.width_px = w;
    s.height_px = h;
    const std::string m = input_error([&] { Renderer r(s); });
    EXPECT_NE(m.find("resolution " + std::to_string(w)), std::string::npos) << m;
  }
}

TEST(RendererErrors, AntiAliasingOutsideWhatGlOffersIsRefused) {
  RenderSettings s = small();
  s.anti_aliasing = AntiAliasing::Multisample;
  s.msaa_samples = 64;  // llvmpipe offers 4
  EXPECT_NE(input_error([&] { Renderer r(s); }).find("msaa_samples 64"), std::string::npos);
  s.msaa_samples = 1;  // multisampling with one sample is no multisampling
  EXPECT_NE(input_error([&] { Renderer r(s); }).find("msaa_samples must be ≥ 2"), std::string::npos);
}

TEST(RendererErrors, SceneWithoutBodiesIsRefused) {
  Renderer r(small());
  EXPECT_NE(input_error([&] { r.render(Scene{}, camera()); }).find("no bodies"), std::string::npos);
}

TEST(RendererErrors, BodyWithoutMeshIsRefusedByName) {
  Renderer r(small());
  Scene s = one_sphere();
  s.bodies.push_back(body("planet 2", nullptr));
  EXPECT_NE(input_error([&] { r.render(s, camera()); }).find("'planet 2': has no mesh"), std::string::npos);
}

TEST(RendererErrors, MissingOrNonRigidPoseIsRefused) {
  Renderer r(small());
  Scene s = one_sphere();
  s.bodies[0].pose.matrix()(0, 3) = std::numeric_limits<double>::quiet_NaN();  // pose never filled in
  EXPECT_NE(input_error([&] { r.render(s, camera()); }).find("'ball': pose is not finite"), std::string::npos);
  s = one_sphere();
  s.bodies[0].pose.linear() *= 2.0;  // a scale is not a pose
  EXPECT_NE(input_error([&] { r.render(s, camera()); }).find("not a rigid transform"), std::string::npos);
}

TEST(RendererErrors, HighlightOfTheWrongLengthIsRefused) {
  Renderer r(small());
  Scene s = one_sphere();
  s.bodies[0].highlight = std::make_shared<const std::vector<std::uint8_t>>(3, 1);
  EXPECT_NE(input_error([&] { r.render(s, camera()); }).find("expected one per triangle"), std::string::npos);
}

TEST(RendererErrors, CameraThatCannotProjectIsRefused) {
  Renderer r(small());
  Camera c = camera();
  c.eye_m = c.target_m;
  EXPECT_NE(input_error([&] { r.render(one_sphere(), c); }).find("coincides"), std::string::npos);
  c = camera();
  c.up = {0, 0, 1};  // along the view direction
  EXPECT_NE(input_error([&] { r.render(one_sphere(), c); }).find("up"), std::string::npos);
}

TEST(RendererErrors, NegativeArrowScaleIsRefused) {
  Renderer r(small());
  Scene s = one_sphere();
  s.contacts.push_back({{0, 0, 0}, {1, 0, 0}});
  s.arrow_m_per_N = -1e-4;
  EXPECT_NE(input_error([&] { r.render(s, camera()); }).find("arrow_m_per_N"), std::string::npos);
}

}  // namespace test_renderer_errors
}  // namespace gearsim::render
