// Local build: sweeps run on the local thread pool.
#include "sweep_runner.hpp"

namespace molchaos::app {

validation::SweepRunner default_sweep_runner() { return {}; }

}  // namespace molchaos::app
