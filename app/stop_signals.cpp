#include "app/stop_signals.hpp"

#include <csignal>

#include "app/exit_codes.hpp"

namespace gearsim::app {
namespace {

volatile std::sig_atomic_t g_stop_signal = 0;
void on_stop_signal(int sig) { g_stop_signal = sig; }

}  // namespace

int stop_signal() { return static_cast<int>(g_stop_signal); }

std::string signal_name(int sig) { return sig == SIGTERM ? "SIGTERM" : "SIGINT"; }

StopSignals::StopSignals() {
  g_stop_signal = 0;
  old_int_ = std::signal(SIGINT, on_stop_signal);
  old_term_ = std::signal(SIGTERM, on_stop_signal);
}

StopSignals::~StopSignals() {
  std::signal(SIGINT, old_int_);
  std::signal(SIGTERM, old_term_);
}

void throw_if_render_stopped(const RenderResult& r, const std::filesystem::path& dir) {
  if (!r.stopped_by) return;
  throw RunStopped(r.stopped_by == SIGTERM ? kExitSigterm : kExitSigint,
                   "interrupted by " + signal_name(r.stopped_by) + " while rendering, after " + std::to_string(r.frames_drawn) + " of " +
                       std::to_string(r.frames) + " frames: no video written (" + r.video.filename().string() +
                       "); the PNG frames drawn stay in " + (dir / "frames").string());
}

}  // namespace gearsim::app
