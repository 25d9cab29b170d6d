// An option that takes one value, given twice ("--seed 1 --seed 2"), is a usage error naming the
// option: which value was meant cannot be guessed, and CLI11's own words ("At Most 1 required but
// received 2") name no remedy. So is a flag given twice, which may carry a value of its own
// ("--contacts=true --contacts=false"). Set up once for every subcommand in main().
#pragma once

#include <CLI/CLI.hpp>

namespace molchaos::app {

/// Whether `op` takes exactly one value (not a flag, not a list).
bool takes_one_value(const CLI::Option& op);
/// Whether `op` is a flag (no value, or true/false after '=').
bool is_flag(const CLI::Option& op);

/// Makes every one-value option and flag of app's subcommands refuse a repeat on the command line with
/// UsageError("--seed", "given twice; give it once"), checked when parsing is complete and before
/// any subcommand runs.
void refuse_repeated_options(CLI::App& app);

}  // namespace molchaos::app
