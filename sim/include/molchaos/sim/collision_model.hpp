// The physics of a collision for a whole run, fixed at construction: the collision rule, the TC
// model and the velocity shuffle, built once from the Parameters. The elastic relaxation is a run
// with CollisionModel::elastic(); nothing changes the model while a run goes on.
#pragma once

#include "molchaos/sim/collision.hpp"
#include "molchaos/sim/parameters.hpp"

namespace molchaos::sim {

struct CollisionModel {
  ConstantRestitution rule;
  TcModel tc;
  Randomization shuffle = Randomization::none;  // selects the shuffle evaluator, at compile time

  /// The cooling run's model: restitution, TC duration and shuffle of the Parameters.
  static CollisionModel from(const Parameters& p) {
    return {ConstantRestitution{p.restitution}, TcModel{p.tc}, p.randomize};
  }
  /// Elastic collisions, no TC model, no shuffle: the relaxation to equilibrium.
  static CollisionModel elastic() { return {}; }
};

}  // namespace molchaos::sim
