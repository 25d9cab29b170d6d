// Umbrella header of molchaos::sim.
#pragma once

#include "molchaos/sim/csv.hpp"
#include "molchaos/sim/parameters.hpp"
#include "molchaos/sim/result.hpp"
#include "molchaos/sim/run.hpp"
