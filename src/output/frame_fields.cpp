// The fields of one field frame (docs/output-format.md, "/frames/NNNN"): what every frame holds and what the
// /ANIM cards ask for, element by element from the points of the solver state.
#include "frame_fields.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "crumple/elements/shell4.hpp"
#include "crumple/state/element_status.hpp"

namespace crumple {
namespace {

using Stress3 = std::array<double, 3>;  // sxx syy sxy of a shell, in its co-rotational frame

template <class T>
void require_size(const std::vector<T>& v, std::size_t n, const std::string& what) {
  if (v.size() != n) throw std::runtime_error(fmt::format("{} has {} values, the frame needs {}", what, v.size(), n));
}

FrameField field(std::string name, int kind, std::size_t width, std::vector<double> values) {
  FrameField f;
  f.name = std::move(name), f.kind = kind, f.width = width, f.values = std::move(values);
  return f;
}

std::vector<double> interleave(const std::vector<double>& x, const std::vector<double>& y,
                               const std::vector<double>& z, std::size_t n, const std::string& what) {
  for (const auto* v : {&x, &y, &z}) require_size(*v, n, what);
  std::vector<double> out(3 * n);
  for (std::size_t i = 0; i < n; ++i) out[3 * i] = x[i], out[3 * i + 1] = y[i], out[3 * i + 2] = z[i];
  return out;
}

// A per-node result the cycle keeps only when asked for (SolverState::recorded): 3 per node when there.
void add_recorded(FieldSink& out, const char* name, const std::vector<double>& values, std::size_t n) {
  if (values.empty()) return;
  require_size(values, 3 * n, fmt::format("the recorded {}", name));
  out.push_back(field(name, -1, 3, values));
}

void add_nodal_fields(FieldSink& out, const Model& m, const SolverState& s) {
  const std::size_t n = m.nodes.size();
  const NodalState& ns = s.nodes;
  const FrameRequests& want = m.run.anim;
  std::vector<double> x = interleave(ns.x, ns.y, ns.z, n, "nodal coordinates");
  std::vector<double> u = x;
  // The deformed shape: NAME.xdmf makes it the frame's geometry, so that ParaView draws it with no filter.
  out.push_back(field(kFrameCoordinates, -1, 3, std::move(x)));
  for (std::size_t i = 0; i < n; ++i)
    u[3 * i] -= m.nodes.x[i], u[3 * i + 1] -= m.nodes.y[i], u[3 * i + 2] -= m.nodes.z[i];
  out.push_back(field("displacement", -1, 3, std::move(u)));
  out.push_back(field("velocity", -1, 3, interleave(ns.vx, ns.vy, ns.vz, n, "nodal velocities")));
  if (!s.contact.interfaces.empty())  // only decks with contact pay for this field, unless it is asked for
    out.push_back(field("contact_force", -1, 3, interleave(s.contact.fx, s.contact.fy, s.contact.fz, n, "contact forces")));
  else if (want.contact_force)
    out.push_back(field("contact_force", -1, 3, std::vector<double>(3 * n, 0.0)));
  add_recorded(out, "acceleration", s.recorded.acceleration, n);
  add_recorded(out, "internal_force", s.recorded.internal_force, n);
  add_recorded(out, "external_force", s.recorded.external_force, n);
  if (want.angular_velocity)
    out.push_back(field("angular_velocity", -1, 3, interleave(ns.wx, ns.wy, ns.wz, n, "angular velocities")));
  if (want.nodal_mass || want.added_mass) require_size(ns.mass, n, "nodal masses");
  if (want.nodal_mass) out.push_back(field("mass", -1, 1, ns.mass));
  if (want.added_mass) {
    require_size(m.nodal_mass, n, "the model's initial nodal masses");
    std::vector<double> added(n);
    for (std::size_t i = 0; i < n; ++i) added[i] = ns.mass[i] - m.nodal_mass[i];
    out.push_back(field("added_mass", -1, 1, std::move(added)));
  }
}

// The deleted flag (1 for a failed element; an element carried by a rigid body is there, only not computed) and
// VTK's ghost flags that hide it in ParaView, last of the kind's fields.
void add_status_fields(FieldSink& out, ElementKind kind, const std::vector<std::uint8_t>& status) {
  FrameField deleted, ghost;
  deleted.name = "deleted", ghost.name = "vtkGhostType";
  for (FrameField* f : {&deleted, &ghost}) f->kind = static_cast<int>(kind), f->is_bytes = true;
  for (std::uint8_t st : status) {
    deleted.bytes.push_back(element_condition(st) == kElementDeleted ? 1 : 0);
    ghost.bytes.push_back(element_condition(st) == kElementDeleted ? kHiddenCell : 0);
  }
  out.push_back(std::move(deleted));
  out.push_back(std::move(ghost));
}

// The per-element energies and step that ENER, HOURG and DT ask for.
void add_element_scalars(FieldSink& out, const FrameRequests& want, int kind, std::size_t n,
                         const std::vector<double>& internal_energy, const std::vector<double>& mass,
                         const std::vector<double>& hourglass_energy, const std::vector<double>& critical_dt) {
  if (want.energy_density) {
    require_size(internal_energy, n, "element internal energies");
    require_size(mass, n, "element masses");
    std::vector<double> density(n, 0.0);
    for (std::size_t e = 0; e < n; ++e) density[e] = mass[e] > 0.0 ? internal_energy[e] / mass[e] : 0.0;
    out.push_back(field("energy_density", kind, 1, std::move(density)));
  }
  if (want.hourglass_energy) {
    require_size(hourglass_energy, n, "element hourglass energies");
    out.push_back(field("hourglass_energy", kind, 1, hourglass_energy));
  }
  if (want.time_step) {
    require_size(critical_dt, n, "element critical steps");
    out.push_back(field("time_step", kind, 1, critical_dt));
  }
}

// ---- shells ----

// How the points of a shell group's elements lie: `sections` sections (4 for Ishell 12, one per Gauss point,
// else 1) of `per_section` points each, from the lower to the upper surface, weighted by the group's
// through-thickness rule when the state carries it (else the plain mean, no bending from the points).
struct ShellSections {
  std::size_t sections = 1, per_section = 1;
  const double* membrane = nullptr;  // N = t sum w_i sigma_i
  double membrane_sum = 1.0;
  const double* bending = nullptr;   // M = t^2 sum b_i sigma_i
  bool resultant = false;            // N = 0: one membrane point, the bending stress kept per element
};

ShellSections sections_of(const SolverState& state, const ShellState& s, std::size_t g) {
  ShellSections r;
  const auto points = static_cast<std::size_t>(s.points[g]);
  r.per_section = points;
  if (g >= state.shell_groups.size()) return r;
  const ShellGroupParameters& p = state.shell_groups[g];
  r.resultant = p.resultant_plasticity;
  const auto np = static_cast<std::size_t>(p.points);
  if (p.membrane_weight == nullptr || np == 0 || points % np != 0) return r;
  double sum = 0.0;
  for (std::size_t j = 0; j < np; ++j) sum += p.membrane_weight[j];
  if (!(sum > 0.0)) return r;
  r.sections = points / np, r.per_section = np;
  r.membrane = p.membrane_weight, r.membrane_sum = sum, r.bending = p.bending_weight;
  return r;
}

double plane_von_mises(const Stress3& s) {
  return std::sqrt(s[0] * s[0] + s[1] * s[1] - s[0] * s[1] + 3.0 * s[2] * s[2]);
}

struct ShellValues {
  Stress3 membrane{}, bending{}, upper{}, lower{};
  double von_mises = 0.0, plastic_strain = 0.0;
};

// One element's values from its points starting at `first`; `resultant_bending` is the kept 6 M / t^2 of an
// N = 0 element (nullptr for N > 0), whose surfaces are then membrane +- bending.
ShellValues shell_values(const ShellState& s, const ShellSections& r, std::size_t first,
                         const double* resultant_bending) {
  ShellValues v;
  v.plastic_strain = s.eps_p[first];
  const double share = 1.0 / static_cast<double>(r.sections);
  for (std::size_t c = 0; c < r.sections; ++c) {
    const std::size_t base = first + c * r.per_section;
    for (std::size_t j = 0; j < r.per_section; ++j) {
      const std::size_t k = base + j;
      const Stress3 point{s.sxx[k], s.syy[k], s.sxy[k]};
      const double w = r.membrane != nullptr ? r.membrane[j] / r.membrane_sum : 1.0 / static_cast<double>(r.per_section);
      const double b = r.bending != nullptr ? 6.0 * r.bending[j] : 0.0;
      for (int d = 0; d < 3; ++d) v.membrane[d] += share * w * point[d], v.bending[d] += share * b * point[d];
      v.von_mises = std::max(v.von_mises, plane_von_mises(point));
      v.plastic_strain = std::max(v.plastic_strain, static_cast<double>(s.eps_p[k]));
    }
    const std::size_t top = base + r.per_section - 1;
    const Stress3 lower{s.sxx[base], s.syy[base], s.sxy[base]}, upper{s.sxx[top], s.syy[top], s.sxy[top]};
    for (int d = 0; d < 3; ++d) v.lower[d] += share * lower[d], v.upper[d] += share * upper[d];
  }
  if (r.resultant) {
    for (int d = 0; d < 3; ++d) {
      v.bending[d] = resultant_bending != nullptr ? resultant_bending[d] : 0.0;
      v.upper[d] = v.membrane[d] + v.bending[d], v.lower[d] = v.membrane[d] - v.bending[d];
    }
    v.von_mises = std::max(plane_von_mises(v.upper), plane_von_mises(v.lower));
  }
  return v;
}

// The kept bending stress of N = 0 element e (Ishell 12: the mean of its Gauss points), or nullptr.
const double* resultant_bending(const ShellState& s, const SolverState& state, std::size_t g, std::size_t e,
                                std::size_t n, Stress3& scratch) {
  const bool gauss = g < state.shell_groups.size() && state.shell_groups[g].fully_integrated;
  if (gauss && s.gauss_bending.size() == 12 * n) {
    scratch = {};
    for (std::size_t i = 0; i < 4; ++i)
      for (std::size_t d = 0; d < 3; ++d) scratch[d] += 0.25 * s.gauss_bending[12 * e + 3 * i + d];
    return scratch.data();
  }
  return s.bending_stress.size() == 3 * n ? &s.bending_stress[3 * e] : nullptr;
}

void check_shells(const Model& m, ElementKind kind, const ShellState& s, std::size_t n, const char* name) {
  require_size(s.thickness, n, fmt::format("{} thickness", name));
  require_size(s.deleted, n, fmt::format("{} status", name));
  require_size(s.point_offset, m.element_groups.size(), fmt::format("{} point offsets per group", name));
  require_size(s.points, m.element_groups.size(), fmt::format("{} points per group", name));
  for (std::size_t g = 0; g < m.element_groups.size(); ++g) {
    const ElementGroup& group = m.element_groups[g];
    if (group.kind != kind) continue;
    if (s.points[g] < 1) throw std::runtime_error(fmt::format("{} group {} has {} points", name, g, s.points[g]));
    const std::size_t end = s.point_offset[g] + static_cast<std::size_t>(group.end - group.begin) *
                                                    static_cast<std::size_t>(s.points[g]);
    for (const auto* v : {&s.sxx, &s.syy, &s.sxy, &s.eps_p})
      if (v->size() < end)
        throw std::runtime_error(fmt::format("{} point arrays of {} values, group {} needs {}", name, v->size(), g, end));
  }
}

// One stress of each element (a member of ShellValues, in its co-rotational frame) as a symmetric tensor in the
// global axes at the state's node positions, 6 per element.
std::vector<double> global_tensors(const std::vector<ShellValues>& values, Stress3 ShellValues::*member,
                                   const ElementTable& table, const NodalState& nodes) {
  const int per_element = nodes_per_element(table.kind);
  std::vector<double> out(6 * values.size());
  for (std::size_t e = 0; e < values.size(); ++e) {
    Vec3 x[4];
    const std::int32_t* element_nodes = table.nodes_of(e);
    for (int a = 0; a < per_element; ++a) {
      const auto i = static_cast<std::size_t>(element_nodes[a]);
      x[a] = Vec3{nodes.x[i], nodes.y[i], nodes.z[i]};
    }
    const Stress3& s = values[e].*member;
    const double local[3] = {s[0], s[1], s[2]};
    const std::array<double, 6> global = shell_stress_in_global_axes(x, per_element, local);
    std::copy(global.begin(), global.end(), out.begin() + static_cast<std::ptrdiff_t>(6 * e));
  }
  return out;
}

void add_shell_fields(FieldSink& out, const Model& m, const SolverState& state, ElementKind kind) {
  const std::size_t n = m.elements[static_cast<std::size_t>(kind)].size();
  if (n == 0) return;
  const ShellState& s = shell_state(state, kind);
  const std::string name(describe(kind).mesh_group);
  check_shells(m, kind, s, n, name.c_str());
  std::vector<ShellValues> values(n);
  Stress3 scratch{};
  for (std::size_t g = 0; g < m.element_groups.size(); ++g) {
    const ElementGroup& group = m.element_groups[g];
    if (group.kind != kind) continue;
    const ShellSections r = sections_of(state, s, g);
    const auto points = static_cast<std::size_t>(s.points[g]);
    for (std::int32_t e = group.begin; e < group.end; ++e) {
      const auto ue = static_cast<std::size_t>(e);
      const std::size_t first = s.point_offset[g] + static_cast<std::size_t>(e - group.begin) * points;
      values[ue] = shell_values(s, r, first, r.resultant ? resultant_bending(s, state, g, ue, n, scratch) : nullptr);
    }
  }
  const int k = static_cast<int>(kind);
  const FrameRequests& want = m.run.anim;
  const ElementTable& table = m.elements[static_cast<std::size_t>(kind)];
  const auto tensor = [&](Stress3 ShellValues::*member) { return global_tensors(values, member, table, state.nodes); };
  out.push_back(field("stress", k, 6, tensor(&ShellValues::membrane)));
  std::vector<double> eps(n), vm(n), pressure(n);
  for (std::size_t e = 0; e < n; ++e) {
    eps[e] = values[e].plastic_strain, vm[e] = values[e].von_mises;
    pressure[e] = -(values[e].membrane[0] + values[e].membrane[1]) / 3.0;  // plane stress: szz = 0
  }
  out.push_back(field("von_mises", k, 1, std::move(vm)));
  out.push_back(field("plastic_strain", k, 1, std::move(eps)));
  out.push_back(field("thickness", k, 1, s.thickness));
  if (want.pressure) out.push_back(field("pressure", k, 1, std::move(pressure)));
  if (want.bending_stress) out.push_back(field("bending_stress", k, 6, tensor(&ShellValues::bending)));
  if (want.surface_stress) {
    out.push_back(field("stress_upper", k, 6, tensor(&ShellValues::upper)));
    out.push_back(field("stress_lower", k, 6, tensor(&ShellValues::lower)));
  }
  add_element_scalars(out, want, k, n, s.internal_energy, s.mass, s.hourglass_energy, s.critical_dt);
  add_status_fields(out, kind, s.deleted);
}

// ---- bricks ----

void check_bricks(const Model& m, const BrickState& b, std::size_t n) {
  require_size(b.deleted, n, "brick8 status");
  require_size(b.point_offset, m.element_groups.size(), "brick8 point offsets per group");
  require_size(b.points, m.element_groups.size(), "brick8 points per group");
  for (std::size_t g = 0; g < m.element_groups.size(); ++g) {
    const ElementGroup& group = m.element_groups[g];
    if (group.kind != ElementKind::Brick8) continue;
    if (b.points[g] < 1) throw std::runtime_error(fmt::format("brick8 group {} has {} points", g, b.points[g]));
    const std::size_t end = b.point_offset[g] + static_cast<std::size_t>(group.end - group.begin) *
                                                    static_cast<std::size_t>(b.points[g]);
    for (const auto* v : {&b.sxx, &b.syy, &b.szz, &b.sxy, &b.syz, &b.szx, &b.eps_p})
      if (v->size() < end)
        throw std::runtime_error(fmt::format("brick8 point arrays of {} values, group {} needs {}", v->size(), g, end));
  }
}

// sxx syy szz sxy syz szx: the order of VTK's symmetric tensors (and of Radioss' SX SY SZ SXY SYZ SZX).
double von_mises(const double* s) {
  const double a = s[0] - s[1], b = s[1] - s[2], c = s[2] - s[0];
  return std::sqrt(0.5 * (a * a + b * b + c * c) + 3.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]));
}

void add_brick_fields(FieldSink& out, const Model& m, const SolverState& state) {
  const std::size_t n = m.elements[static_cast<std::size_t>(ElementKind::Brick8)].size();
  if (n == 0) return;
  const BrickState& b = state.bricks;
  check_bricks(m, b, n);
  std::vector<double> stress(6 * n, 0.0), eps(n, 0.0);
  for (std::size_t g = 0; g < m.element_groups.size(); ++g) {
    const ElementGroup& group = m.element_groups[g];
    if (group.kind != ElementKind::Brick8) continue;
    const auto points = static_cast<std::size_t>(b.points[g]);
    const double share = 1.0 / static_cast<double>(points);
    for (std::int32_t e = group.begin; e < group.end; ++e) {
      const auto ue = static_cast<std::size_t>(e);
      const std::size_t first = b.point_offset[g] + static_cast<std::size_t>(e - group.begin) * points;
      eps[ue] = b.eps_p[first];
      for (std::size_t k = first; k < first + points; ++k) {
        const std::array<double, 6> point{b.sxx[k], b.syy[k], b.szz[k], b.sxy[k], b.syz[k], b.szx[k]};
        for (std::size_t d = 0; d < 6; ++d) stress[6 * ue + d] += share * point[d];
        eps[ue] = std::max(eps[ue], static_cast<double>(b.eps_p[k]));
      }
    }
  }
  const int k = static_cast<int>(ElementKind::Brick8);
  const FrameRequests& want = m.run.anim;
  std::vector<double> vm(n), pressure(n);
  for (std::size_t e = 0; e < n; ++e) {
    vm[e] = von_mises(&stress[6 * e]);
    pressure[e] = -(stress[6 * e] + stress[6 * e + 1] + stress[6 * e + 2]) / 3.0;
  }
  out.push_back(field("stress", k, 6, std::move(stress)));
  out.push_back(field("von_mises", k, 1, std::move(vm)));
  out.push_back(field("plastic_strain", k, 1, std::move(eps)));
  if (want.pressure) out.push_back(field("pressure", k, 1, std::move(pressure)));
  add_element_scalars(out, want, k, n, b.internal_energy, b.mass, b.hourglass_energy, b.critical_dt);
  add_status_fields(out, ElementKind::Brick8, b.deleted);
}

// Springs (docs/theory/spring.md): per spring, six forces and six elongations, one per degree of freedom: a TYPE4
// spring's axial force (positive in tension) and elongation first, the rest 0; a general spring's forces, moments,
// displacements and rotations in the global axes (SP-9).
void add_spring_fields(FieldSink& out, const Model& m, const SolverState& state) {
  const std::size_t n = m.elements[static_cast<std::size_t>(ElementKind::Spring)].size();
  if (n == 0) return;
  const SpringState& s = state.springs;
  for (const auto* v : {&s.internal_energy, &s.mass, &s.critical_dt}) require_size(*v, n, "spring values");
  for (const auto* v : {&s.force, &s.elongation}) require_size(*v, kSpringDofs * n, "spring values");
  const int k = static_cast<int>(ElementKind::Spring);
  out.push_back(field("spring_force", k, kSpringDofs, s.force));
  out.push_back(field("elongation", k, kSpringDofs, s.elongation));
  add_element_scalars(out, m.run.anim, k, n, s.internal_energy, s.mass, s.hourglass_energy, s.critical_dt);
  add_status_fields(out, ElementKind::Spring, s.deleted);
}

// Trusses (docs/theory/truss.md): per truss, its axial force (positive in tension), stress and plastic strain.
void add_truss_fields(FieldSink& out, const Model& m, const SolverState& state) {
  const std::size_t n = m.elements[static_cast<std::size_t>(ElementKind::Truss)].size();
  if (n == 0) return;
  const TrussState& t = state.trusses;
  for (const auto* v : {&t.internal_energy, &t.mass, &t.critical_dt, &t.force, &t.stress}) require_size(*v, n, "truss values");
  const int k = static_cast<int>(ElementKind::Truss);
  out.push_back(field("axial_force", k, 1, t.force));
  out.push_back(field("axial_stress", k, 1, t.stress));
  out.push_back(field("plastic_strain", k, 1, std::vector<double>(t.eps_p.begin(), t.eps_p.end())));
  add_element_scalars(out, m.run.anim, k, n, t.internal_energy, t.mass, t.hourglass_energy, t.critical_dt);
  add_status_fields(out, ElementKind::Truss, t.deleted);
}

// Beams (docs/theory/beam.md): per beam, its six resultants in its frame (N Vy Vz T My Mz, BM-2) and plastic strain.
void add_beam_fields(FieldSink& out, const Model& m, const SolverState& state) {
  const std::size_t n = m.elements[static_cast<std::size_t>(ElementKind::Beam)].size();
  if (n == 0) return;
  const BeamState& b = state.beams;
  for (const auto* v : {&b.internal_energy, &b.mass, &b.critical_dt}) require_size(*v, n, "beam values");
  require_size(b.resultant, kBeamResultants * n, "beam values");
  const int k = static_cast<int>(ElementKind::Beam);
  out.push_back(field("beam_resultants", k, kBeamResultants, b.resultant));
  out.push_back(field("plastic_strain", k, 1, std::vector<double>(b.eps_p.begin(), b.eps_p.end())));
  add_element_scalars(out, m.run.anim, k, n, b.internal_energy, b.mass, b.hourglass_energy, b.critical_dt);
  add_status_fields(out, ElementKind::Beam, b.deleted);
}

}  // namespace

void frame_fields(const Model& model, const SolverState& state, FieldSink& out) {
  add_nodal_fields(out, model, state);
  add_shell_fields(out, model, state, ElementKind::Shell4);
  add_shell_fields(out, model, state, ElementKind::Shell3);
  add_brick_fields(out, model, state);
  add_spring_fields(out, model, state);
  add_truss_fields(out, model, state);
  add_beam_fields(out, model, state);
}

std::vector<FrameField> frame_fields(const Model& model, const SolverState& state) {
  struct Collect final : FieldSink {
    std::vector<FrameField> fields;
    void push_back(FrameField&& field) override { fields.push_back(std::move(field)); }
  } collect;
  frame_fields(model, state, collect);
  return std::move(collect.fields);
}

}  // namespace crumple
