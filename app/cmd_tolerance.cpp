// PLACEHOLDER during development: replaced by the real subcommand before any commit.
#include "app/commands.hpp"
#include "geometry/errors.hpp"
namespace gearsim::app {
void register_tolerance(CLI::App& app) {
  auto* sub = app.add_subcommand("tolerance", "(not built yet)");
  sub->callback([] { throw InputError("tolerance: not built yet"); });
}
}  // namespace gearsim::app
