// build/molchaos: the command-line front end. It parses, validates and dispatches; the physics
// lives in the libraries (theory/, sim/, validation/, figures/).
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <iostream>
#include <iterator>
#include <new>
#include <string>
#include <vector>

#include "cli_support.hpp"
#include "commands.hpp"
#include "config_file.hpp"
#include "molchaos/sim/checkpoint.hpp"
#include "molchaos/sim/run.hpp"
#include "molchaos/version.hpp"
#include "repeated_options.hpp"
#ifdef MOLCHAOS_HAVE_MPI
#include "molchaos/mpi/session.hpp"
#endif

namespace {

// CLI11 messages can span lines; a usage error must be exactly one line. A value echoed from a
// file can hold control bytes (a NUL would cut the message short, an escape sequence would drive
// the terminal): they are written as \xNN.
std::string one_line(const std::string& text) {
  std::string line;
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '\n' || c == '\t')
      line += ' ';
    else if (byte < 0x20 || byte == 0x7f)
      line += fmt::format("\\x{:02x}", byte);
    else
      line += c;
  }
  while (!line.empty() && line.back() == ' ') line.pop_back();
  return line;
}

// Standard output is the only copy of some results (theory's tables, a sweep without --out), and
// a failed write there (a full disk, a closed descriptor) only sets the stream's error state: the
// last flush and that state say whether everything arrived. Returns the exit status.
int finish_standard_output() {
  std::cout.flush();
  errno = 0;
  const bool flushed = std::fflush(stdout) == 0;
  const int error = errno;
  if (flushed && std::cout.good() && !std::ferror(stdout)) return 0;
  std::fprintf(stderr, "molchaos: failed: cannot write standard output%s%s\n",
               error != 0 ? ": " : "", error != 0 ? std::strerror(error) : "");
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  // A write beyond the file-size limit (ulimit -f) fails with EFBIG, which the writers report and
  // clean up after, as after a full disk; by default the signal would kill the process and leave
  // the temporaries of its outputs behind. (Python ignores it too.)
  std::signal(SIGXFSZ, SIG_IGN);
#ifdef MOLCHAOS_HAVE_MPI
  // Under mpirun/srun every rank runs main(). Rank 0 parses and runs the command; the others only
  // compute the runs rank 0 hands out, until the session on rank 0 goes out of scope (on every
  // return path, usage errors included) and releases them. Without a launcher: no MPI at all.
  // MOLCHAOS_MPI=0 under a launcher of several processes would have each of them run the whole
  // command and write the same files at once.
  if (!molchaos::mpi::launched_by_mpi() && molchaos::mpi::launched_processes() > 1) {
    const char* rank = std::getenv("OMPI_COMM_WORLD_RANK");
    if (rank == nullptr) rank = std::getenv("PMI_RANK");
    if (rank == nullptr || std::strcmp(rank, "0") == 0)  // said once, by the first process
      std::fprintf(
          stderr,
          "molchaos: error: MOLCHAOS_MPI=0 in one of %d processes that a launcher started: "
          "each would run the whole command and write the same files; start one process "
          "(mpirun -np 1), or leave MOLCHAOS_MPI unset to spread the runs over all %d\n",
          molchaos::mpi::launched_processes(), molchaos::mpi::launched_processes());
    return 2;
  }
  molchaos::mpi::Session mpi_session(argc, argv);
  if (mpi_session.is_worker()) return mpi_session.serve();
#endif
  CLI::App app{"molchaos: kinetic theory and event-driven simulation of granular gases"};
  app.require_subcommand(1);
  app.set_version_flag("--version", molchaos::k_version);
  molchaos::app::add_theory_command(app);
  molchaos::app::add_sweep_command(app);
  molchaos::app::add_reproduce_command(app);
  molchaos::app::add_bench_command(app);
  molchaos::app::add_simulate_command(app);
  molchaos::app::refuse_repeated_options(app);

  // A first word that is neither a flag nor a subcommand: name it and list the choices.
  if (argc > 1 && argv[1][0] != '-') {
    std::string names;
    bool known = false;
    for (const CLI::App* sub : app.get_subcommands({})) {
      known = known || sub->get_name() == argv[1];
      names += (names.empty() ? "" : ", ") + sub->get_name();
    }
    if (!known) {
      std::fprintf(stderr, "molchaos: error: unknown subcommand '%s'; allowed: %s\n", argv[1],
                   names.c_str());
      return 2;
    }
  }

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ExtrasError&) {
    // CLI11's message lists the words in reverse order; remaining() has them in the order typed,
    // the command's first, then those after a "--" (on the top level's list, the "--" with them).
    const std::vector<CLI::App*> parsed = app.get_subcommands();
    const CLI::App* command = parsed.empty() ? &app : parsed.front();
    std::vector<std::string> typed = command->remaining();
    if (command != &app) std::ranges::copy(app.remaining(), std::back_inserter(typed));
    std::string words;
    std::size_t count = 0;
    for (const std::string& word : typed)
      if (word != "--") words += (count++ == 0 ? "'" : ", '") + word + "'";
    std::fprintf(stderr, "molchaos: error: %s: unexpected argument%s %s (see molchaos %s--help)\n",
                 command->get_name().empty() ? "molchaos" : command->get_name().c_str(),
                 count == 1 ? "" : "s", one_line(words).c_str(),
                 command == &app ? "" : (command->get_name() + " ").c_str());
    return 2;
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "molchaos: error: %s\n", one_line(e.what()).c_str());
    return 2;
  } catch (const molchaos::app::Interrupted& e) {
    // The results printed so far first, so that a log of both streams ends with this line (and
    // below; standard output to a file is buffered).
    std::cout.flush();
    std::fprintf(stderr, "molchaos: %s\n", e.what());
    return molchaos::app::k_exit_interrupted;
  } catch (const molchaos::app::UsageError& e) {
    // A refused value the user did not type names the file it came from.
    const std::string what = e.what();
    const std::string file = molchaos::app::config_file_that_set(what.substr(0, what.find(": ")));
    const char* given_by = molchaos::sim::is_checkpoint_file(file) ? "--restart" : "--config";
    std::fprintf(
        stderr, "molchaos: error: %s%s\n", one_line(what).c_str(),
        file.empty() ? "" : fmt::format(" (the value is from {} {})", given_by, file).c_str());
    return 2;
  } catch (const std::bad_alloc&) {
    std::cout.flush();
    std::fprintf(stderr, "molchaos: failed: %s (or fewer threads, in a sweep)\n",
                 molchaos::sim::k_out_of_memory_message);
    return 1;
  } catch (const std::exception& e) {
    std::cout.flush();
    std::fprintf(stderr, "molchaos: failed: %s\n", one_line(e.what()).c_str());
    return 1;
  }
  return finish_standard_output();
}
