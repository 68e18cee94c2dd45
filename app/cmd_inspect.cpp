// PLACEHOLDER during development: replaced by the real subcommand before any commit.
#include "app/commands.hpp"
#include "geometry/errors.hpp"
namespace gearsim::app {
void register_inspect(CLI::App& app) {
  auto* sub = app.add_subcommand("inspect", "(not built yet)");
  sub->callback([] { throw InputError("inspect: not built yet"); });
}
}  // namespace gearsim::app
