#pragma once
// The energy balance of a run (docs/theory/energy.md): the energies the listing prints and the balance's error.

namespace crumple {

struct EnergyBalanceState {
  double internal = 0.0;          // element internal energy (stress work)
  double hourglass = 0.0;         // hourglass energy
  double kinetic_translational = 0.0;
  double kinetic_rotational = 0.0;
  double external_work = 0.0;     // work of loads and of kinematic conditions (rigid walls, imposed motion)
  double contact = 0.0;
  // E_0: the energy at the start of the engine deck being run: the initial kinetic energy for the first one, the
  // whole energy (internal, kinetic, hourglass, contact) where a continued run takes over.
  double initial_kinetic = 0.0;
  double external_work_at_start = 0.0;  // W_ext when the engine deck started (0 for the first one)
  // (E_int + E_kin + E_hg + E_contact - E_0 - dW_ext) / (E_0 + dW_ext) in percent with dW_ext the work since the
  // engine deck started (docs/theory/energy.md)
  double error_percent() const;
};

}  // namespace crumple
