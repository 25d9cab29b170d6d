#include "interrupt_signals.hpp"

#include <signal.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <utility>

namespace molchaos::app::interrupt_signals {
namespace {

std::atomic<bool> g_under_way{false};
std::atomic<bool> g_requested{false};
volatile std::sig_atomic_t g_signal = 0;
std::string g_message;  // set before the handler is installed, not changed after
std::vector<std::string> g_empty_directories;  // the same
static_assert(std::atomic<bool>::is_always_lock_free, "set from a signal handler");

extern "C" void on_signal(int signal) {
  if (!g_under_way.load()) {
    // write(), rmdir(), signal() and raise() are async-signal-safe.
    if (!g_message.empty()) {
      [[maybe_unused]] const ssize_t written =
          ::write(STDERR_FILENO, g_message.data(), g_message.size());
    }
    for (const std::string& directory : g_empty_directories) ::rmdir(directory.c_str());
    std::signal(signal, SIG_DFL);
    std::raise(signal);
    return;
  }
  g_signal = signal;
  g_requested.store(true);
}

}  // namespace

void remove_if_empty_when_ended_early(std::vector<std::string> directories) {
  g_empty_directories = std::move(directories);
}

void install(std::string message) {
  g_message = std::move(message);
  for (const int signal : {SIGINT, SIGTERM}) {
    struct sigaction before {};
    sigaction(signal, nullptr, &before);
    if (before.sa_handler == SIG_IGN) continue;
    struct sigaction action {};
    action.sa_handler = on_signal;
    action.sa_flags = SA_RESTART;
    sigemptyset(&action.sa_mask);
    sigaction(signal, &action, nullptr);
  }
}

std::atomic<bool>& under_way() { return g_under_way; }
const std::atomic<bool>& requested() { return g_requested; }
int signal_number() { return g_signal; }
const char* signal_name() { return g_signal == SIGINT ? "SIGINT" : "SIGTERM"; }

void end_by_signal() {
  const int signal = g_signal;
  std::signal(signal, SIG_DFL);
  std::raise(signal);
  std::_Exit(128 + signal);
}

}  // namespace molchaos::app::interrupt_signals
