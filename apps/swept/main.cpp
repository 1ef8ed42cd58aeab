// swept: can this part be taken out, and how?
#include "commands.h"
#include "swept/io/cad_reader.h"

#include <exception>
#include <iostream>
#include <string>

int main(int argc, char** argv) {
  CLI::App app{
      "swept: collision and distance queries on rigid triangle meshes with RSS trees,\n"
      "and certified, deterministic 6-DOF assembly/disassembly path planning."};
  app.require_subcommand(1);
  // The version, and which CAD reader module (STEP, IGES, OCCT .brep) this swept loads: an
  // install or a moved prefix can be checked with it (swept/io/cad_reader.h).
  app.set_version_flag("--version", [] {
    const swept::CadReaderStatus cad = swept::cad_reader_status();
    std::string text = "swept 0.1.0\nCAD reader (STEP, IGES, OCCT .brep): ";
    if (!cad.path.empty()) return text + cad.path.string();
    return text + "none: " + cad.error;
  });
  swept::cli::add_bvh_command(app);
  swept::cli::add_plan_command(app);
  swept::cli::add_check_command(app);
  swept::cli::add_view_command(app);
  swept::cli::add_scene_command(app);
  swept::cli::add_mesh_stats_command(app);
  swept::cli::add_bench_queries_command(app);
  swept::cli::add_bench_paper_command(app);
  swept::cli::add_disassemble_command(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version end here with code 0. Any other command-line error (a missing file,
    // an unknown option, a value out of range) is bad input: one line and exit code 1, not
    // CLI11's own codes (105, 106, ...).
    if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return app.exit(e);
    std::cerr << "swept: error: " << e.what() << " (see --help)\n";
    return 1;
  } catch (const swept::cli::ExitCode& e) {
    return e.code;
  } catch (const std::exception& e) {
    std::cerr << "swept: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
