// gearsim: one binary, many subcommands. Bad input ends with exit code 2 and a message that names
// the file, key or value at fault; an internal error (a bug) with exit code 3.
#include <exception>
#include <iostream>

#include "app/commands.hpp"
#include "geometry/errors.hpp"

int main(int argc, char** argv) {
  CLI::App app{
      "gearsim: planetary gearbox dynamics with manufacturing errors.\n"
      "SI units at every interface unless an option says otherwise."};
  app.require_subcommand(1);
  gearsim::app::register_tolerance(app);
  gearsim::app::register_gears(app);
  gearsim::app::register_inspect(app);
  gearsim::app::register_run(app);
  gearsim::app::register_analyze(app);
  gearsim::app::register_report(app);
  gearsim::app::register_render(app);
  gearsim::app::register_fe_te(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const gearsim::InputError& e) {
    std::cerr << "gearsim: error: " << e.what() << "\n";
    return 2;
  } catch (const gearsim::InternalError& e) {
    std::cerr << "gearsim: internal error (please report): " << e.what() << "\n";
    return 3;
  } catch (const std::exception& e) {
    std::cerr << "gearsim: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
