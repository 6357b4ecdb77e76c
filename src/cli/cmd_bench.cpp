#include "cli/commands.hpp"

namespace asos::cli {

CLI::App* addBenchCommand(CLI::App& app) {
    CLI::App* bench = app.add_subcommand("bench", "Benchmarks: programs that print figures");
    bench->require_subcommand(1);
    return bench;
}

}  // namespace asos::cli
