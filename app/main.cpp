// gearsim: one binary, many subcommands. Exit codes (app/exit_codes.hpp): 0 done; 2 bad input,
// with a message that names the file, key, option or value at fault; 3 an internal error (a bug); 4 a run
// that diverged (left its physical bounds), its logs kept up to that step; 5 a sweep some of whose cases
// did not complete (each recorded in its case.json).
#include <exception>
#include <iostream>

#include "app/commands.hpp"
#include "app/exit_codes.hpp"
#include "core/errors.hpp"

int main(int argc, char** argv) {
  CLI::App app{
      "gearsim: planetary gearbox dynamics with manufacturing errors.\n"
      "SI units at every interface unless an option says otherwise.\n"
      "Exit codes: 0 done, 2 bad input (file or command line), 3 internal error (a bug), 4 a run diverged (non-physical;\n"
      "summary.json says where; logs kept up to that step), 5 a sweep with some cases not completed (each recorded),\n130/143 a run stopped by SIGINT/SIGTERM\n"
      "(summary.json status interrupted; logs kept up to that step)."};
  app.require_subcommand(1);
  gearsim::app::register_tolerance(app);
  gearsim::app::register_gears(app);
  gearsim::app::register_inspect(app);
  gearsim::app::register_run(app);
  gearsim::app::register_analyze(app);
  gearsim::app::register_report(app);
  gearsim::app::register_render(app);
  gearsim::app::register_fe_te(app);
  gearsim::app::register_modes(app);
  gearsim::app::register_sweep(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // CLI11 prints the help or the error; a bad command line is bad input (not CLI11's 105–109).
    return app.exit(e) == 0 ? gearsim::app::kExitOk : gearsim::app::kExitInputError;
  } catch (const gearsim::app::RunStopped& e) {
    std::cerr << "gearsim: " << e.what() << "\n";
    return e.code();
  } catch (const gearsim::InputError& e) {
    std::cerr << "gearsim: error: " << e.what() << "\n";
    return gearsim::app::kExitInputError;
  } catch (const gearsim::InternalError& e) {
    std::cerr << "gearsim: internal error (please report): " << e.what() << "\n";
    return gearsim::app::kExitInternalError;
  } catch (const std::exception& e) {
    std::cerr << "gearsim: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
