#include "python/py_render.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl/filesystem.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>

#include "app/render_run.hpp"
#include "app/run_dir.hpp"
#include "core/errors.hpp"
#include "input/input_limits.hpp"

namespace gearsim::python {
namespace {

// The CLI's bound on --msaa.
constexpr int kMaxMsaa = 16;

py::array_t<std::uint8_t> render_frame(const std::filesystem::path& run_dir, double t_s, const std::string& camera, int width_px,
                                       int height_px, int msaa) {
  if (camera != "overview" && camera != "tilted" && camera != "sun_mesh" && camera != "ring_mesh")
    throw InputError("camera: '" + camera + "' is none of overview, tilted, sun_mesh, ring_mesh");
  input::require_within("t_s", t_s, input::limits::kRunTime_s);
  input::require_within("width_px", width_px, input::limits::kFrameSize_px);
  input::require_within("height_px", height_px, input::limits::kFrameSize_px);
  if (msaa < 0 || msaa == 1 || msaa > kMaxMsaa)
    throw InputError("msaa: " + std::to_string(msaa) + " samples; expected 0 (edge anti-aliasing) or 2 to 16");
  physics::RenderDef def;
  def.camera = camera;
  def.width_px = width_px;
  def.height_px = height_px;
  def.msaa = msaa;
  render::Image image;
  {
    py::gil_scoped_release released;
    image = app::render_run_frame(app::open_run_dir(run_dir), def, t_s);
  }
  py::array_t<std::uint8_t> a(
      {static_cast<py::ssize_t>(image.height_px), static_cast<py::ssize_t>(image.width_px), static_cast<py::ssize_t>(3)});
  std::memcpy(a.mutable_data(), image.rgb.data(), image.rgb.size());
  return a;
}

constexpr const char* kRenderFrameDoc = R"(One frame of a run folder at simulated time t_s (s), as `gearsim render DIR` draws it.

Returns an H×W×3 numpy uint8 array (sRGB, rows from the top): the bodies posed from the run's
state.csv at t_s (angles interpolated linearly), drawn off-screen (OSMesa) with the overlay line,
the camera, the size and the anti-aliasing of the CLI — the PNG frame `gearsim render DIR --from
t_s --camera … --width … --height …` writes first, pixel for pixel. camera: overview, tilted,
sun_mesh or ring_mesh; width_px, height_px: 16 to 4096 px; msaa: 0 (edge anti-aliasing) or 2 to
16 samples. gearsim.InputError when DIR is not a run folder, t_s lies outside the logged span
(the message gives it) or an argument is out of range. The GIL is released while it draws.)";

}  // namespace

void bind_render(py::module_& m) {
  const physics::RenderDef d;
  m.def("render_frame", &render_frame, py::arg("run_dir"), py::arg("t_s"), py::arg("camera") = d.camera, py::arg("width_px") = d.width_px,
        py::arg("height_px") = d.height_px, py::arg("msaa") = d.msaa, kRenderFrameDoc);
}

}  // namespace gearsim::python
