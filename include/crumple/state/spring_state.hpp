#pragma once
// State owned by the spring kernels (docs/theory/spring.md): per spring, its rest, its frame, its step, and per
// degree of freedom its elongation, its force and its hardening.
#include <cstddef>
#include <vector>

#include "crumple/model/properties.hpp"
#include "crumple/state/element_kind_state.hpp"

namespace crumple {

struct SpringState : ElementKindState {  // no integration points: points and eps_p stay empty
  // Per element (index in the Spring ElementTable).
  std::vector<double> length0;         // length at t = 0, moved by an Isflag 2 switch (SP-24, SP-24b) [L]
  std::vector<double> rest_offset;     // 3 per spring: x2 - x1 at t = 0, the general spring's rest (SP-9), moved by an
                                       // Isflag 2 switch (SP-24b) [L]
  std::vector<double> frame_y;         // 3 per spring: a beam-type spring's Y axis, turning with it (SP-15)
  std::vector<double> step_stiffness;  // the stiffness of its step, which it gives each node in the nodal steps [F/L]
  std::vector<double> nodal_step;      // its step: its nodes' masses held by every spring on them (SP-19) [T]
  // Set up once, not per element (neither exchanged nor in the restart): per node (kNodeHeldValues), the stiffness
  // and damping of translation and rotation that every spring on it hands it (SpringStepStiffness, 4 values), then
  // the mass and inertia they hold, the node's own (a tied node's stays its own, TI-3); per spring, its own share of
  // the stiffnesses at rest (4 values). A beam-type spring's share changes with its length (SP-18).
  static constexpr std::size_t kNodeHeldValues = 6;
  std::vector<double> node_held, own_held;
  // kSpringDofs per spring, one per degree of freedom (a /PROP/TYPE4 spring: the first only; /PROP/TYPE8: X, Y, Z,
  // XX, YY, ZZ in the global axes; /PROP/TYPE13: tension, shear Y and Z, torsion, bending Y and Z in its frame):
  std::vector<double> elongation;  // delta = l - l0 (TYPE4), or the relative displacement or rotation, positive in
                                   // tension [L] or [rad] (eq. SP-1, SP-9, SP-16)
  std::vector<double> force;       // force, positive in tension: K delta + C d(delta)/dt [F] or [F L] (eq. SP-2)
  std::vector<double> elastic_force;  // the spring's part of it, without the dashpot [F]
  // Hardening: H 1 and 6, the hardening displacement x (SP-6, SP-12) and 0; H 2, the plastic elongations of the
  // tension and of the compression side (SP-7); H 5, each side's largest elongation (SP-11) [L].
  std::vector<double> plastic_a, plastic_b;
  // TYPE25 (SP-20): the radial shear's and bending's laws, each its own history of the magnitude (elongation,
  // force, elastic force, hardening a and b), kRadialValues per spring; the slots above keep their components.
  static constexpr std::size_t kRadialValues = 10;
  std::vector<double> radial_law;
  // kSpringDofs per spring: the work done on each law so far, its dashpot's included, which Ifail2's energy criterion
  // reads (SP-5b) [E].
  std::vector<double> law_energy;
  // /PROP/TYPE45, kJointValues per spring (SP-25): the blocking stiffness of the translations [F/L] and of the
  // rotations [F L/rad], their dampings [F T/L], [F L T/rad], and the joint's step [T], from the bodies it joins at
  // each engine deck's first step (0 before the run's first: its offset is 0 then). In the restart: a resumed run
  // keeps them (taken anew, the bodies' arms would differ in their last digits from the run it resumes).
  static constexpr std::size_t kJointValues = 5;
  std::vector<double> joint;
  // /PROP/TYPE45, 9 per spring: the joint's frame, its X, Y and Z axes (global components), turned each step by the
  // mean of its two nodes' rotation increments (SP-25); the global axes at t = 0.
  std::vector<double> joint_frame;

  void resize_elements(std::size_t n) {
    resize_common(n);
    for (auto* v : {&length0, &step_stiffness, &nodal_step}) v->assign(n, 0.0);
    rest_offset.assign(3 * n, 0.0), frame_y.assign(3 * n, 0.0), radial_law.assign(kRadialValues * n, 0.0);
    joint.assign(kJointValues * n, 0.0);
    joint_frame.assign(9 * n, 0.0);
    for (std::size_t e = 0; e < n; ++e) {
      joint[kJointValues * e + 4] = 1e30;  // no step before the first
      joint_frame[9 * e] = joint_frame[9 * e + 4] = joint_frame[9 * e + 8] = 1.0;
    }
    for (auto* v : {&elongation, &force, &elastic_force, &plastic_a, &plastic_b, &law_energy})
      v->assign(kSpringDofs * n, 0.0);
  }
};

}  // namespace crumple
