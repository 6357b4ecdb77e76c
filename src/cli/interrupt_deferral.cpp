#include "cli/interrupt_deferral.hpp"

#include <csignal>
#include <cstddef>
#include <iterator>
#include <cstdlib>

namespace asos::cli {
namespace {

constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};

// A signal handler can only set a flag of static storage: this is the one
// piece of global state, written by the handler and read by the class.
volatile std::sig_atomic_t gCaught = 0;
struct sigaction gPrevious[std::size(kSignals)];

extern "C" void remember(int signal) { gCaught = signal; }

}  // namespace

InterruptDeferral::InterruptDeferral() {
    gCaught = 0;
    struct sigaction action {};
    action.sa_handler = remember;
    sigemptyset(&action.sa_mask);
    for (std::size_t i = 0; i < std::size(kSignals); ++i) {
        sigaction(kSignals[i], nullptr, &gPrevious[i]);
        // An ignored signal (nohup's SIGHUP) stays ignored.
        if (gPrevious[i].sa_handler != SIG_IGN) sigaction(kSignals[i], &action, nullptr);
    }
}

InterruptDeferral::~InterruptDeferral() {
    for (std::size_t i = 0; i < std::size(kSignals); ++i) sigaction(kSignals[i], &gPrevious[i], nullptr);
}

int InterruptDeferral::caught() const { return gCaught; }

void InterruptDeferral::endByCaughtSignal() {
    const int signal = gCaught;
    for (std::size_t i = 0; i < std::size(kSignals); ++i) sigaction(kSignals[i], &gPrevious[i], nullptr);
    std::raise(signal);
    std::_Exit(128 + signal);  // a previous handler of the caller's own returned: end all the same
}

}  // namespace asos::cli
