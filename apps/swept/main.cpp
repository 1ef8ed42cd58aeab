// swept: can this part be taken out, and how?
#include "cli_main.h"
#include "commands.h"
#include "tools_path.h"
#include "swept/io/cad_reader.h"

#include <string>
#include <string_view>

int main(int argc, char** argv) {
  // `swept scene` and `swept bench` are swept-tools' (tools_main.cpp): this program does not
  // link OpenCASCADE's modelling libraries or FCL, and starts in a fraction of the time.
  if (argc > 1 && (std::string_view(argv[1]) == "scene" || std::string_view(argv[1]) == "bench"))
    return swept::cli::exec_tools(argv);
  CLI::App app{
      "swept: collision and distance queries on rigid triangle meshes with RSS trees,\n"
      "and certified, deterministic 6-DOF assembly/disassembly path planning."};
  app.require_subcommand(1);
  // The version, which CAD reader module (STEP, IGES, OCCT .brep) this swept loads and which
  // swept-tools it runs: an install or a moved prefix can be checked with it (swept/io/cad_reader.h,
  // tools_path.h).
  app.set_version_flag("--version", [] {
    const swept::CadReaderStatus cad = swept::cad_reader_status();
    std::string text = "swept 0.1.0\nCAD reader (STEP, IGES, OCCT .brep): ";
    text += cad.path.empty() ? "none: " + cad.error : cad.path.string();
    const swept::cli::ToolsLookup tools = swept::cli::find_tools();
    text += "\nscenes and benchmarks (swept scene, swept bench): ";
    return text + (tools.path.empty() ? "none: tried " + tools.tried : tools.path.string());
  });
  swept::cli::add_bvh_command(app);
  swept::cli::add_plan_command(app);
  swept::cli::add_check_command(app);
  swept::cli::add_view_command(app);
  // Listed here for --help; run by swept-tools (above).
  app.add_subcommand("scene", "Generate a built-in CAD-like scene, a planner benchmark problem or an assembly "
                              "(`swept scene --help`)");
  swept::cli::add_mesh_stats_command(app);
  app.add_subcommand("bench", "Benchmarks against peer libraries: queries, paper (`swept bench --help`)");
  swept::cli::add_disassemble_command(app);
  return swept::cli::run_cli(app, argc, argv);
}
