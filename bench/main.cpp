#include "benchmarks.hpp"

int main(int argc, char** argv) {
    using namespace asos::bench;
    CLI::App app{"asos-bench: benchmarks of asos, programs that print figures", "asos-bench"};
    app.require_subcommand(1);
    CommandResult result;

    // Benchmarks register here, one line each.
    addParseBenchmark(app, result);
    addBvhBenchmark(app, result);
    addIntersectBenchmark(app, result);
    addRenderBenchmark(app, result);
    addLightsBenchmark(app, result);
    addAccuracyBenchmark(app, result);
    addStabilityBenchmark(app, result);
    addEpsBenchmark(app, result);
    addScaleBenchmark(app, result);

    return asos::cli::runProgram(app, argc, argv, result);
}
