// gearsim: one binary, many subcommands. Exit codes (app/exit_codes.hpp): 0 done; 2 bad input,
// with a message that names the file, key, option or value at fault; 3 an internal error (a bug); 4 a run
// that diverged (left its physical bounds), its logs kept up to that step; 5 a sweep some of whose cases
// did not complete (each recorded in its case.json); 6 an output that could not be written (the message names
// the file and the reason; nothing half-written is left in its place); 7 another gearsim command writing into
// the same output folder; 8 a program or library gearsim drives (CalculiX, OSMesa, FFmpeg) failed.
#include <hdf5.h>

#include <exception>
#include <iostream>

#include "app/commands.hpp"
#include "app/exit_codes.hpp"
#include "core/errors.hpp"
#include "core/folder_lock.hpp"
#include "render/render_error.hpp"

int main(int argc, char** argv) {
  // No HDF5 clean-up at exit: every file the commands write is closed (or, when its writes
  // failed, closed and removed) before they end, and HDF5's exit handler would try again to flush
  // a file whose writes failed, and crash on a full disk.
  H5dont_atexit();
  CLI::App app{
      "gearsim: planetary gearbox dynamics with manufacturing errors.\n"
      "SI units at every interface unless an option says otherwise.\n"
      "Exit codes: 0 done, 2 bad input (file or command line), 3 internal error (a bug), 4 a run diverged (non-physical;\n"
      "summary.json says where; logs kept up to that step), 5 a sweep with some cases not completed (each recorded),\n"
      "6 an output could not be written (disk full, no permission: the file and the reason named; nothing half-written\n"
      "left in its place), 7 another gearsim command is writing into the output folder (the holder named),\n"
      "8 a program or library gearsim drives failed (CalculiX, OSMesa, FFmpeg: named, and what was kept),\n"
      "9 a run completed (its logs valid) but its analysis was refused (the message says why),\n"
      "130/143 a run stopped by SIGINT/SIGTERM (summary.json status interrupted; logs kept up to that step)."};
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
  } catch (const gearsim::OutputError& e) {
    std::cerr << "gearsim: cannot write: " << e.what() << "\n";
    return gearsim::app::kExitOutputError;
  } catch (const gearsim::render::RenderError& e) {
    std::cerr << "gearsim: error: " << e.what() << "\n";
    return gearsim::app::kExitToolFailed;
  } catch (const gearsim::FolderBusy& e) {
    std::cerr << "gearsim: error: " << e.what() << "\n";
    return gearsim::app::kExitFolderBusy;
  } catch (const gearsim::InputError& e) {
    std::cerr << "gearsim: error: " << e.what() << "\n";
    return gearsim::app::kExitInputError;
  } catch (const gearsim::InternalError& e) {
    std::cerr << "gearsim: internal error (please report): " << e.what() << "\n";
    return gearsim::app::kExitInternalError;
  } catch (const std::exception& e) {
    // Any other exception is one the code did not expect here: a bug, whatever its message.
    std::cerr << "gearsim: internal error (please report): " << e.what() << "\n";
    return gearsim::app::kExitInternalError;
  }
  return 0;
}
