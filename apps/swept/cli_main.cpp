#include "cli_main.h"

#include "commands.h"

#include <exception>
#include <iostream>

namespace swept::cli {

int run_cli(CLI::App& app, int argc, char** argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return app.exit(e);
    std::cerr << "swept: error: " << e.what() << " (see --help)\n";
    return 1;
  } catch (const ExitCode& e) {
    return e.code;
  } catch (const std::exception& e) {
    std::cerr << "swept: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

}  // namespace swept::cli
