// One-value options given more than once: refused by name (repeated_options.hpp).
#include "repeated_options.hpp"

#include <string>

#include "cli_support.hpp"

namespace molchaos::app {

bool takes_one_value(const CLI::Option& op) {
  return op.get_expected_min() > 0 && op.get_items_expected_max() == 1;
}

bool is_flag(const CLI::Option& op) {
  return op.get_expected_min() == 0 && op.get_items_expected_max() <= 1;
}

void refuse_repeated_options(CLI::App& app) {
  // CLI11 throws at the second value before anything can name it; taking the last value lets
  // parsing finish so that the check below sees the count and says what to do.
  for (CLI::App* sub : app.get_subcommands({}))
    for (CLI::Option* op : sub->get_options())
      if (takes_one_value(*op)) op->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  app.parse_complete_callback([&app] {
    for (const CLI::App* sub : app.get_subcommands())  // the one given
      for (const CLI::Option* op : sub->get_options()) {
        const std::size_t given = op->count();
        if (!(takes_one_value(*op) || is_flag(*op)) || given < 2) continue;
        const std::string times = given == 2 ? "twice" : std::to_string(given) + " times";
        throw UsageError(op->get_name(), "given " + times + "; give it once");
      }
  });
}

}  // namespace molchaos::app
