#pragma once
// While the output files are written, SIGINT, SIGTERM and SIGHUP are caught
// rather than ending the process at once: the files are all staged beside
// their targets, and a signal that came meanwhile means none is put in place
// (the staged ones are removed) before the process ends by that signal, as
// it would have (a shell sees 130 for SIGINT). Outside this window the
// signals keep their default action: a render stopped by Ctrl-C ends at once,
// and no output file exists yet to be left half-written.
namespace asos::cli {

class InterruptDeferral {
public:
    InterruptDeferral();   // catches the signals from here on
    ~InterruptDeferral();  // restores their previous actions
    InterruptDeferral(const InterruptDeferral&) = delete;
    InterruptDeferral& operator=(const InterruptDeferral&) = delete;

    // The signal caught since construction, 0 if none.
    int caught() const;

    // Restores the previous actions and sends the caught signal again, so
    // that the process ends as that signal ends it.
    [[noreturn]] void endByCaughtSignal();
};

}  // namespace asos::cli
