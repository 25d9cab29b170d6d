// One function per subcommand of build/molchaos; each adds its flags and its run callback.
#pragma once

#include <CLI/CLI.hpp>

namespace molchaos::app {

void add_theory_command(CLI::App& app);
void add_sweep_command(CLI::App& app);
void add_reproduce_command(CLI::App& app);
void add_bench_command(CLI::App& app);
void add_simulate_command(CLI::App& app);

}  // namespace molchaos::app
