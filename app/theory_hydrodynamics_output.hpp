// The hydrodynamic block of `molchaos theory`: the critical box size of the homogeneous cooling
// state and the growth of the largest shear mode of a box of N particles (theory/hydrodynamics),
// as the report computes them (theory_report.hpp).
#pragma once

#include <CLI/CLI.hpp>
#include <memory>
#include <string>

#include "molchaos/theory/theory_report.hpp"

namespace molchaos::app {

/// Adds --particles and --growth to the theory command.
std::shared_ptr<theory::BoxInputs> add_hydrodynamics_options(CLI::App& cmd);

/// The hydrodynamics of the report r as text lines.
std::string hydrodynamics_text(const theory::ReportInputs& in, const theory::TheoryReport& r);

}  // namespace molchaos::app
