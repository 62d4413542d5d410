#pragma once
// The snapshot of a run at a cycle boundary: everything a resumed run needs to go on exactly as the run it
// continues (docs/theory/time-loop.md, "Restart"). A continued run (NAME_0002.rad) carries the SolverState in
// memory; a restart file holds the same state, field by field, with the monitor's marks beside it.
//
// visit_state() names every field of the state that a cycle changes or that a restart must give back. Everything
// else (parameters, element groups, rules through the thickness, the interfaces' segments) is rebuilt from the
// deck by initial_state(), so a restart reads the deck again and then overwrites these fields.
#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "crumple/solver/solver_state.hpp"

namespace crumple {

// The monitor's state at the snapshot: the next output times of the engine deck being run and the counts the
// listing keeps, so that a resumed run writes its frames and history rows at the same times and repeats no
// warning.
struct ResumeMarks {
  int engine_deck = 1;  // 1 for NAME_0001.rad, 2 for NAME_0002.rad, ...
  double next_frame = std::numeric_limits<double>::infinity();    // [T]
  double next_history = std::numeric_limits<double>::infinity();  // [T]
  long long last_frame_cycle = std::numeric_limits<long long>::min() / 2;  // the run's cycle of its last frame
  long long deleted_below_minimum_step = 0;
  long long switched_to_small_strain = 0;
  long long deleted_inverted = 0;
  bool hourglass_warned = false;
  bool energy_error_warned = false;
  bool step_drop_warned = false;
};

namespace snapshot_detail {

template <class V>
void visit_nodes(V& v, const std::string& at, NodalState& n) {
  for (auto [name, field] : {std::pair{"x", &n.x}, {"y", &n.y}, {"z", &n.z}, {"vx", &n.vx}, {"vy", &n.vy},
                             {"vz", &n.vz}, {"wx", &n.wx}, {"wy", &n.wy}, {"wz", &n.wz}, {"fx", &n.fx},
                             {"fy", &n.fy}, {"fz", &n.fz}, {"mx", &n.mx}, {"my", &n.my}, {"mz", &n.mz},
                             {"mass", &n.mass}, {"inertia", &n.inertia}})
    v(at + name, *field);
}

template <class V>
void visit_shells(V& v, const std::string& at, ShellState& s) {
  for (auto [name, field] : {std::pair{"sxx", &s.sxx}, {"syy", &s.syy}, {"sxy", &s.sxy}, {"eps_p", &s.eps_p},
                             {"eps_rate", &s.eps_rate}, {"hardening_term", &s.hardening_term}})
    v(at + name, *field);  // point_real
  for (auto [name, field] :
       {std::pair{"qx", &s.qx}, {"qy", &s.qy}, {"thickness", &s.thickness},
        {"bending_stress", &s.bending_stress}, {"hourglass", &s.hourglass}, {"internal_energy", &s.internal_energy},
        {"critical_dt", &s.critical_dt}, {"initial_length", &s.initial_length}, {"initial_shape", &s.initial_shape},
        {"gauss_shear", &s.gauss_shear}, {"gauss_bending", &s.gauss_bending}, {"mass", &s.mass},
        {"hourglass_energy", &s.hourglass_energy}})
    v(at + name, *field);
  v(at + "viscous", s.viscous);  // float
  if (!s.section_work.empty()) v(at + "section_work", s.section_work);  // only when /TH/SECTIO asks WORK
  v(at + "small_strain", s.small_strain);
  v(at + "deleted", s.deleted);
}

template <class V>
void visit_bricks(V& v, const std::string& at, BrickState& b) {
  for (auto [name, field] : {std::pair{"sxx", &b.sxx}, {"syy", &b.syy}, {"szz", &b.szz}, {"sxy", &b.sxy},
                             {"syz", &b.syz}, {"szx", &b.szx}, {"eps_p", &b.eps_p}, {"eps_rate", &b.eps_rate}})
    v(at + name, *field);  // point_real
  for (auto [name, field] :
       {std::pair{"volume0", &b.volume0},
        {"hourglass", &b.hourglass}, {"internal_energy", &b.internal_energy},
        {"hourglass_energy", &b.hourglass_energy}, {"critical_dt", &b.critical_dt}, {"mass", &b.mass},
        {"reference_shape", &b.reference_shape}, {"reference_frame", &b.reference_frame}})
    v(at + name, *field);
  if (!b.section_work.empty()) v(at + "section_work", b.section_work);
  v(at + "small_strain", b.small_strain);
  v(at + "deleted", b.deleted);
}

template <class V>
void visit_springs(V& v, const std::string& at, SpringState& sp) {
  for (auto [name, field] :
       {std::pair{"length0", &sp.length0}, {"rest_offset", &sp.rest_offset}, {"frame_y", &sp.frame_y},
        {"elongation", &sp.elongation}, {"force", &sp.force},
        {"elastic_force", &sp.elastic_force}, {"plastic_a", &sp.plastic_a}, {"plastic_b", &sp.plastic_b},
        {"radial_law", &sp.radial_law}, {"law_energy", &sp.law_energy}, {"joint", &sp.joint}, {"joint_frame", &sp.joint_frame}, {"internal_energy", &sp.internal_energy}, {"hourglass_energy", &sp.hourglass_energy},
        {"critical_dt", &sp.critical_dt}, {"mass", &sp.mass}})
    v(at + name, *field);
  if (!sp.section_work.empty()) v(at + "section_work", sp.section_work);
  v(at + "deleted", sp.deleted);
}

template <class V>
void visit_trusses(V& v, const std::string& at, TrussState& t) {
  for (auto [name, field] :
       {std::pair{"length0", &t.length0}, {"length", &t.length}, {"area", &t.area}, {"stress", &t.stress},
        {"force", &t.force}, {"off", &t.off}, {"internal_energy", &t.internal_energy}, {"hourglass_energy", &t.hourglass_energy},
        {"critical_dt", &t.critical_dt}, {"mass", &t.mass}})
    v(at + name, *field);
  v(at + "eps_p", t.eps_p);  // point_real, one point per truss
  if (!t.section_work.empty()) v(at + "section_work", t.section_work);
  v(at + "deleted", t.deleted);
}

template <class V>
void visit_beams(V& v, const std::string& at, BeamState& b) {
  for (auto [name, field] :
       {std::pair{"length0", &b.length0}, {"length", &b.length}, {"area", &b.area}, {"frame_y", &b.frame_y},
        {"resultant", &b.resultant}, {"off", &b.off}, {"internal_energy", &b.internal_energy},
        {"hourglass_energy", &b.hourglass_energy}, {"critical_dt", &b.critical_dt}, {"mass", &b.mass}})
    v(at + name, *field);
  v(at + "eps_p", b.eps_p);  // point_real, one point per beam
  if (!b.section_work.empty()) v(at + "section_work", b.section_work);
  v(at + "deleted", b.deleted);
}

template <class V>
void visit_body(V& v, const std::string& at, RigidBodyState& b) {
  v(at + "rx", b.rx), v(at + "ry", b.ry), v(at + "rz", b.rz);
  v(at + "mass", b.mass);
  v(at + "inertia_body", b.inertia_body), v(at + "rotation", b.rotation);
  v(at + "velocity", b.velocity), v(at + "momentum_angular", b.momentum_angular), v(at + "omega", b.omega);
  v(at + "active", b.active);
}

template <class V>
void visit_wall(V& v, const std::string& at, RigidWallState& w) {
  v(at + "tied", w.tied), v(at + "active", w.active);

  v(at + "force", w.force), v(at + "velocity", w.velocity), v(at + "origin", w.origin);
}

// What an interface changes while it runs: its node and segment switches, the sorted pairs with their friction
// history, the sort's clock and the forces of the last pass (their work is taken with the next velocities).
template <class V>
void visit_interface(V& v, const std::string& at, ContactInterface& c, InterfaceResult& r) {
  v(at + "node_active", c.node_active), v(at + "node_impacted", c.node_impacted);
  v(at + "segment_active", c.segment_active);
  v(at + "gap_reduction", c.gap_reduction), v(at + "gap_clearance", c.gap_clearance);
  v(at + "node_element_stiffness", c.node_element_stiffness);
  v(at + "candidate_node", c.candidate_node), v(at + "candidate_segment", c.candidate_segment);
  v(at + "friction_x", c.friction_x), v(at + "friction_y", c.friction_y), v(at + "friction_z", c.friction_z);
  v(at + "friction_mu", c.friction_mu), v(at + "friction_mu_pass", c.friction_mu_pass);
  v(at + "passes", c.passes), v(at + "sorts", c.sorts), v(at + "motion", c.motion), v(at + "margin", c.margin);
  v(at + "applied_node", c.applied_node);
  v(at + "applied_x", c.applied_x), v(at + "applied_y", c.applied_y), v(at + "applied_z", c.applied_z);
  v(at + "result/normal_force", r.normal_force), v(at + "result/tangential_force", r.tangential_force);
  for (auto [name, field] :
       {std::pair{"elastic_energy", &r.elastic_energy}, {"damping_work", &r.damping_work},
        {"friction_work", &r.friction_work}, {"absorbed", &r.absorbed}, {"dt", &r.dt}, {"added_mass", &r.added_mass},
        {"added_mass_energy", &r.added_mass_energy}, {"max_penetration_ratio", &r.max_penetration_ratio}})
    v(at + "result/" + name, *field);
  v(at + "result/active_nodes", r.active_nodes), v(at + "result/dt_node", r.dt_node);
  v(at + "result/released", r.released);
}

// The /TH integrals (accelerometers, nodal rotations): only those the deck asks for exist, so a restart file of a
// deck without them has none, as before they existed.
template <class V>
void visit_histories(V& v, HistoryIntegrals& h) {
  for (auto [name, field] : {std::pair{"accel_filtered", &h.accel_filtered}, {"accel_velocity", &h.accel_velocity},
                             {"accel_memory", &h.accel_memory}, {"rotation", &h.rotation}})
    if (!field->empty()) v(std::string("histories/") + name, *field);
}

}  // namespace snapshot_detail

// Calls v(name, field) for every field of the snapshot: std::vector<T>, std::array<T, N> and scalars (double,
// int32, int, long long, bool); the integration points' state is std::vector<point_real> (float in the mixed
// build). Names are paths ("nodes/vx", "bodies/0/omega").
template <class V>
void visit_state(V& v, SolverState& s, ResumeMarks& marks) {
  using namespace snapshot_detail;
  v("time", s.time), v("dt", s.dt), v("cycle", s.cycle), v("cycles_done", s.cycles_done);
  v("mass_initial", s.mass_initial), v("mass_added", s.mass_added);
  EnergyBalanceState& e = s.energy;
  for (auto [name, field] :
       {std::pair{"internal", &e.internal}, {"hourglass", &e.hourglass},
        {"kinetic_translational", &e.kinetic_translational}, {"kinetic_rotational", &e.kinetic_rotational},
        {"external_work", &e.external_work}, {"contact", &e.contact}, {"initial_kinetic", &e.initial_kinetic},
        {"external_work_at_start", &e.external_work_at_start}})
    v(std::string("energy/") + name, *field);
  v("marks/engine_deck", marks.engine_deck), v("marks/next_frame", marks.next_frame);
  v("marks/next_history", marks.next_history), v("marks/last_frame_cycle", marks.last_frame_cycle);
  v("marks/deleted_below_minimum_step", marks.deleted_below_minimum_step);
  v("marks/switched_to_small_strain", marks.switched_to_small_strain);
  v("marks/deleted_inverted", marks.deleted_inverted);
  v("marks/hourglass_warned", marks.hourglass_warned);
  v("marks/energy_error_warned", marks.energy_error_warned);
  v("marks/step_drop_warned", marks.step_drop_warned);
  visit_nodes(v, "nodes/", s.nodes);
  v("fixed", s.fixed), v("rigid_owner", s.rigid_owner), v("nodal_stiffness", s.nodal_stiffness);
  visit_shells(v, "shells4/", s.shells);
  visit_shells(v, "shells3/", s.shells3);
  visit_bricks(v, "bricks/", s.bricks);
  visit_springs(v, "springs/", s.springs);
  visit_trusses(v, "trusses/", s.trusses);
  visit_beams(v, "beams/", s.beams);
  v("damping/alpha", s.damping.alpha), v("damping/beta", s.damping.beta);
  if (s.damping.stiffness()) v("damping/element_force_before", s.damping.element_force_before);
  for (std::size_t k = 0; k < s.bodies.size(); ++k) visit_body(v, "bodies/" + std::to_string(k) + "/", s.bodies[k]);
  for (std::size_t k = 0; k < s.walls.size(); ++k) visit_wall(v, "walls/" + std::to_string(k) + "/", s.walls[k]);
  for (std::size_t k = 0; k < s.contact.interfaces.size(); ++k)
    visit_interface(v, "interfaces/" + std::to_string(k) + "/", s.contact.interfaces[k], s.contact.results[k]);
  v("contact/fx", s.contact.fx), v("contact/fy", s.contact.fy), v("contact/fz", s.contact.fz);
  v("contact/touched", s.contact.touched);
  visit_histories(v, s.histories);
  // Selective mass scaling (sized at the start when the deck has it): what the last cycle leaves for the next.
  SelectiveMassState& sm = s.selective_mass;
  if (!sm.node_added.empty()) {
    v("selective_mass/node_added", sm.node_added), v("selective_mass/started", sm.started);
    v("selective_mass/shells4", sm.element_added[0]), v("selective_mass/shells3", sm.element_added[1]);
    v("selective_mass/bricks", sm.element_added[2]);
    v("selective_mass/solves", sm.solves), v("selective_mass/iterations", sm.iterations);
    v("selective_mass/max_iterations", sm.max_iterations);
    v("selective_mass/x", sm.x), v("selective_mass/warm", sm.warm);  // the next solve's first guess
  }
}

}  // namespace crumple
