// SIGINT and SIGTERM for the commands whose work can be ended in good order: simulate (a
// checkpoint, its outputs), reproduce (figures, tables and report after the cached runs) and
// bench (its table and figures). Two phases.
// Until the command marks the work as under way (under_way()), a signal ends the process at once
// by its default action, after the message given to install(): the parent sees the signal (a
// shell's exit status 128 + signal) as without a handler. From then on the handler only records
// the signal (requested(), which the long steps poll), and the command ends in good order, then
// by end_by_signal() or its own exit status.
#pragma once

#include <atomic>
#include <string>
#include <vector>

namespace molchaos::app::interrupt_signals {

/// Installs the handler for SIGINT and SIGTERM. A signal that was ignored when the command
/// started (nohup, a background job of a shell without job control) stays ignored; SA_RESTART, so
/// that threads see no EINTR. `message`: printed to stderr when a signal ends the process at once.
void install(std::string message = {});
/// Directories a signal that ends the process at once removes when they are empty (rmdir, in the
/// order given): the output folder a command created for files it had not yet written. Call
/// before install().
void remove_if_empty_when_ended_early(std::vector<std::string> directories);
/// Set (by the command, or the code it hands the flag to) once a signal is to be recorded.
std::atomic<bool>& under_way();
/// Set by a recorded signal.
const std::atomic<bool>& requested();
/// The recorded signal, 0 before one.
int signal_number();
/// "SIGINT" or "SIGTERM": the recorded signal's name, for the command's last line.
const char* signal_name();
/// Ends the process by the recorded signal's default action (std::_Exit(128 + signal) should that
/// return).
[[noreturn]] void end_by_signal();

}  // namespace molchaos::app::interrupt_signals
