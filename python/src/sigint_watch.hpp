// Ctrl-C during a simulate() run of the Python module (module.cpp). Python's own SIGINT handler
// only notes the signal, and the interpreter runs the Python handler (KeyboardInterrupt) when it
// next executes Python code: after the run, which may take hours. While a run started from the main
// thread goes on, a handler in front of Python's also asks the run to stop
// (CheckpointOptions::interrupt): it stops at its next sample time or progress pause (at most 2^20
// events, the relaxation's included; while the initial state is built, within 2^16 particles),
// writes its checkpoint if it has a path and the relaxation is done (a half-relaxed state has
// none), and KeyboardInterrupt is raised. Signals with other Python
// handlers (a SIGINT or SIGTERM handler of the caller's, an alarm) are run at the sample times and
// progress pauses, and stop the run when they raise.
#pragma once

#include <atomic>

namespace molchaos::python {

/// Set by Ctrl-C while a SigintWatch is in place, and by a Python handler that raised; the run
/// polls it (CheckpointOptions::interrupt).
std::atomic<bool>& interrupt_requested();

/// Whether the caller is Python's main thread (the only one that runs signal handlers). Needs the
/// GIL.
bool in_main_thread();

/// Puts a handler in front of Python's SIGINT handler for its lifetime, which also sets
/// interrupt_requested(): in the main thread, and only where SIGINT raises KeyboardInterrupt (not
/// where it is ignored, left to the system's default or given to a handler of the caller's).
/// Clears interrupt_requested() first. Needs the GIL.
class SigintWatch {
 public:
  SigintWatch();
  ~SigintWatch();
  SigintWatch(const SigintWatch&) = delete;
  SigintWatch& operator=(const SigintWatch&) = delete;

 private:
  bool installed_ = false;
};

}  // namespace molchaos::python
