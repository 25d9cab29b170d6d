// The run parameters of an H5MD trajectory read back (the attributes of /parameters that
// write_h5md_file stores), so that a run repeats itself from its trajectory file.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace molchaos::io {

/// The parameter table's rows found in /parameters, in table order, each as (name, text values)
/// in the text form of a result CSV's header (sim::format_value: shortest round-trip decimals,
/// true/false, choice names; a list gives one text per element). Rows the file lacks are left
/// out. Throws std::runtime_error naming the file and the attribute when the file cannot be read,
/// has no /parameters group, or stores an attribute of another type than its row's.
std::vector<std::pair<std::string, std::vector<std::string>>> read_h5md_parameters(
    const std::string& path);

}  // namespace molchaos::io
