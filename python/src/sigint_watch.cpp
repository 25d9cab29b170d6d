// Ctrl-C during a simulate() run (sigint_watch.hpp).
#include "sigint_watch.hpp"

#include <pybind11/pybind11.h>
#include <signal.h>

namespace py = pybind11;

namespace molchaos::python {
namespace {

std::atomic<bool> g_interrupt_requested{false};
struct sigaction g_python_sigint {};

void on_sigint(int signal) {
  g_interrupt_requested.store(true);
  g_python_sigint.sa_handler(signal);  // Python's: notes the signal for the interpreter
}

}  // namespace

std::atomic<bool>& interrupt_requested() { return g_interrupt_requested; }

bool in_main_thread() {
  const py::module_ threading = py::module_::import("threading");
  const py::object main_ident = threading.attr("main_thread")().attr("ident");
  return main_ident.equal(threading.attr("get_ident")());
}

SigintWatch::SigintWatch() {
  g_interrupt_requested.store(false);
  if (!in_main_thread()) return;
  const py::module_ signal_module = py::module_::import("signal");
  if (!signal_module.attr("getsignal")(SIGINT).is(signal_module.attr("default_int_handler")))
    return;
  struct sigaction current {};
  if (sigaction(SIGINT, nullptr, &current) != 0) return;
  if ((current.sa_flags & SA_SIGINFO) != 0 || current.sa_handler == SIG_DFL ||
      current.sa_handler == SIG_IGN)
    return;
  g_python_sigint = current;
  struct sigaction ours = current;
  ours.sa_handler = on_sigint;
  installed_ = sigaction(SIGINT, &ours, nullptr) == 0;
}

SigintWatch::~SigintWatch() {
  if (installed_) sigaction(SIGINT, &g_python_sigint, nullptr);
}

}  // namespace molchaos::python
