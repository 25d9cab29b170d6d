// Parameters of one simulation run: an immutable value, validated once at the edge (CLI or caller)
// and carried back out in every result file. Units: sigma = m = k_B = 1, initial temperature T0
// = 1.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace molchaos::sim {

/// What happens to the velocities of a colliding pair right after the collision.
///  none : nothing (the plain inelastic gas).
///  paper: the paper's shuffle (Sec. 4, Fig. 3): the pair swaps velocities with two random
///  particles,
///         the assignment fixed by the pair separating along e.
///  flux : like paper, but the donor pair is drawn with weight |(v_k - v_l).e| (the collision
///  flux),
///         which keeps an elastic gas in equilibrium (see shuffle.hpp for the derivation).
enum class Randomization { none, paper, flux };

/// How the cooling gas is simulated.
///  edmd: event-driven molecular dynamics of hard disks/spheres (positions and velocities).
///  dsmc: direct simulation Monte Carlo of the homogeneous Enskog–Boltzmann equation (velocities
///        only, molecular chaos by construction; see dsmc.hpp).
enum class Method { edmd, dsmc };

std::string_view to_string(Randomization mode);
std::optional<Randomization> parse_randomization(std::string_view text);

/// Whether `method` can run the randomization `mode`: EDMD every mode, DSMC only none (a shuffle
/// only permutes velocities, which leaves the DSMC state unchanged).
bool method_runs_mode(Method method, Randomization mode);

/// Whether `method` relaxes the gas before t = 0: EDMD does (elastic collisions take the lattice
/// start to a homogeneous fluid); DSMC does not, it starts from the homogeneous Maxwellian state,
/// which elastic collisions leave as it is, so its relax_collisions_per_particle is 0 (the table's
/// default is made for EDMD: default_relaxation_for_method below).
bool method_relaxes(Method method);

struct Parameters {
  int dimension = 2;
  std::int64_t particles = 5000;
  double density = 0.05;     // n = N sigma^d / V, in (0, close packing)
  double restitution = 1.0;  // (0, 1]
  Randomization randomize = Randomization::none;
  std::uint64_t seed = 1;
  double t_end = 1000.0;                        // physical time of the cooling run
  double relax_collisions_per_particle = 20.0;  // elastic equilibration before t = 0
  double tc = 0.0;                              // TC model duration (Luding & McNamara); 0 = off
  int samples_per_decade = 20;
  double t_first_sample = 0.01;  // log-spaced time grid (plus t = 0 and t_end)
  bool contact_statistics = false;
  std::vector<double> snapshot_times;
  std::uint64_t max_collisions = 0;  // 0 = unlimited
  double min_temperature = 0.0;      // stop when T/T0 falls below (0 = never)
  Method method = Method::edmd;
};

/// Densest allowed reduced density n = N sigma^d / V (close packing) for dimension d.
double close_packing_density(int dimension);

/// Side of the periodic box, L = (N / n)^(1/d).
double box_side(const Parameters& p);

/// Throws std::invalid_argument("<field>: value X is outside the allowed range ...") for the first
/// field out of range.
void validate(const Parameters& p);

/// The relaxation of a run whose relax_collisions_per_particle was not given: the table's default
/// (EDMD's) kept for a method that relaxes, 0 for one that does not. Every front end applies it.
void default_relaxation_for_method(Parameters& p);

}  // namespace molchaos::sim
