// `penumbra`: the headless renderer (render, devices, compare, bench, study).
#include <cstdio>
#include <map>

#include "commands.h"
#include "penumbra/util/error.h"
#include "penumbra/util/log.h"

int main(int argc, char** argv) {
  using namespace penumbra;
  CLI::App app{"Penumbra: a cross-API hardware ray-tracing renderer"};
  app.require_subcommand(1);
  std::map<CLI::App*, app::Command> commands;
  auto add = [&](app::Command (*factory)(CLI::App&)) {
    const size_t before = app.get_subcommands({}).size();
    app::Command run = factory(app);
    commands[app.get_subcommands({})[before]] = std::move(run);
  };
  add(&app::addRenderCommand);
  add(&app::addDevicesCommand);
  add(&app::addCompareCommand);
  add(&app::addBenchCommand);
  add(&app::addStudyCommand);
  add(&app::addMergeCommand);
  add(&app::addFarmCommand);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // One line: what was wrong with the command line.
    std::fprintf(stderr, "error: %s (see --help)\n", e.what());
    return 2;
  }
  try {
    for (auto& [sub, run] : commands)
      if (sub->parsed()) return run();
  } catch (const Error& e) {
    log::error("{}", e.what());
    return 1;
  } catch (const std::exception& e) {
    log::error("internal error: {}", e.what());
    return 1;
  }
  return 1;
}
