// The /TH datasets of NAME.h5 and their values (include/crumple/output/history_channels.hpp); what each variable
// is: docs/output-format.md, "/history/th". Runs at history output times only.
#include "crumple/output/history_channels.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

#include "crumple/elements/shell4.hpp"
#include "crumple/core/geometry.hpp"
#include "crumple/model/cut_sections.hpp"
#include "crumple/model/history_variables.hpp"
#include "crumple/model/mass.hpp"
#include "crumple/state/element_status.hpp"

namespace crumple {
namespace {


constexpr double kUnknown = std::numeric_limits<double>::quiet_NaN();

// ---- What one object gives, and the variables read from it.
template <class Values>
struct Evaluator {
  std::string_view name;
  double (*get)(const Values&);
};
template <class Values, Vec3 Values::*Member, int C>
double component(const Values& v) {
  return (v.*Member)[C];
}
template <class Values, double Values::*Member>
double scalar(const Values& v) {
  return v.*Member;
}

struct NodeValues {
  Vec3 d, v, a, vr, ar, x, reaction, reaction_moment, dr;
};
using N = NodeValues;
constexpr Evaluator<N> kNode[] = {
    {"DX", component<N, &N::d, 0>},  {"DY", component<N, &N::d, 1>},  {"DZ", component<N, &N::d, 2>},
    {"VX", component<N, &N::v, 0>},  {"VY", component<N, &N::v, 1>},  {"VZ", component<N, &N::v, 2>},
    {"AX", component<N, &N::a, 0>},  {"AY", component<N, &N::a, 1>},  {"AZ", component<N, &N::a, 2>},
    {"VRX", component<N, &N::vr, 0>}, {"VRY", component<N, &N::vr, 1>}, {"VRZ", component<N, &N::vr, 2>},
    {"ARX", component<N, &N::ar, 0>}, {"ARY", component<N, &N::ar, 1>}, {"ARZ", component<N, &N::ar, 2>},
    {"X", component<N, &N::x, 0>},   {"Y", component<N, &N::x, 1>},   {"Z", component<N, &N::x, 2>},
    {"REACX", component<N, &N::reaction, 0>}, {"REACY", component<N, &N::reaction, 1>},
    {"REACZ", component<N, &N::reaction, 2>}, {"REACXX", component<N, &N::reaction_moment, 0>},
    {"REACYY", component<N, &N::reaction_moment, 1>}, {"REACZZ", component<N, &N::reaction_moment, 2>},
    {"DRX", component<N, &N::dr, 0>}, {"DRY", component<N, &N::dr, 1>}, {"DRZ", component<N, &N::dr, 2>}};

struct PartValues {
  double ie = 0.0, ke = 0.0, he = 0.0, rke = 0.0, mass = 0.0;
  Vec3 momentum{}, cg{};
};
using P = PartValues;
constexpr Evaluator<P> kPart[] = {
    {"IE", scalar<P, &P::ie>},   {"KE", scalar<P, &P::ke>},   {"XMOM", component<P, &P::momentum, 0>},
    {"YMOM", component<P, &P::momentum, 1>}, {"ZMOM", component<P, &P::momentum, 2>}, {"MASS", scalar<P, &P::mass>},
    {"HE", scalar<P, &P::he>},   {"XCG", component<P, &P::cg, 0>}, {"YCG", component<P, &P::cg, 1>},
    {"ZCG", component<P, &P::cg, 2>}, {"RKE", scalar<P, &P::rke>}};

struct ShellHistoryValues {
  Vec3 n, m;
  double q1, q2, off, thickness, eps_lower, eps_upper, eps_rate;
};
using S = ShellHistoryValues;
constexpr Evaluator<S> kShell[] = {
    {"F1", component<S, &S::n, 0>}, {"F2", component<S, &S::n, 1>}, {"F12", component<S, &S::n, 2>},
    {"Q1", scalar<S, &S::q1>},      {"Q2", scalar<S, &S::q2>},      {"M1", component<S, &S::m, 0>},
    {"M2", component<S, &S::m, 1>}, {"M12", component<S, &S::m, 2>}, {"OFF", scalar<S, &S::off>},
    {"THIC", scalar<S, &S::thickness>}, {"EMIN", scalar<S, &S::eps_lower>}, {"EMAX", scalar<S, &S::eps_upper>},
    {"EPSD", scalar<S, &S::eps_rate>}};

struct BrickValues {
  std::array<double, 6> s;  // xx yy zz xy yz zx
  double off, ie, density, volume, plastic_strain;
};
using B = BrickValues;
template <int C>
double brick_stress(const B& b) {
  return b.s[C];
}
constexpr Evaluator<B> kBrick[] = {
    {"OFF", scalar<B, &B::off>}, {"SX", brick_stress<0>}, {"SY", brick_stress<1>}, {"SZ", brick_stress<2>},
    {"SXY", brick_stress<3>},    {"SYZ", brick_stress<4>}, {"SXZ", brick_stress<5>}, {"IE", scalar<B, &B::ie>},
    {"DENS", scalar<B, &B::density>}, {"VOL", scalar<B, &B::volume>}, {"PLAS", scalar<B, &B::plastic_strain>}};

struct SpringValues {  // TYPE4: X along its nodes (FX and LX only); TYPE8: the global axes
  Vec3 f, m, l, r;
  double off, ie, length;
};
using SP = SpringValues;
constexpr Evaluator<SP> kSpring[] = {
    {"OFF", scalar<SP, &SP::off>},        {"FX", component<SP, &SP::f, 0>}, {"FY", component<SP, &SP::f, 1>},
    {"FZ", component<SP, &SP::f, 2>},     {"MX", component<SP, &SP::m, 0>}, {"MY", component<SP, &SP::m, 1>},
    {"MZ", component<SP, &SP::m, 2>},     {"LX", component<SP, &SP::l, 0>}, {"LY", component<SP, &SP::l, 1>},
    {"LZ", component<SP, &SP::l, 2>},     {"RX", component<SP, &SP::r, 0>}, {"RY", component<SP, &SP::r, 1>},
    {"RZ", component<SP, &SP::r, 2>},     {"IE", scalar<SP, &SP::ie>},      {"LENGTH", scalar<SP, &SP::length>}};

struct TrussValues {
  double off, force, ie, area, length0, plastic_strain;
};
using TR = TrussValues;
constexpr Evaluator<TR> kTruss[] = {{"OFF", scalar<TR, &TR::off>}, {"F", scalar<TR, &TR::force>},
                                    {"IE", scalar<TR, &TR::ie>},   {"A", scalar<TR, &TR::area>},
                                    {"L", scalar<TR, &TR::length0>}, {"PLAS", scalar<TR, &TR::plastic_strain>}};

struct BeamValues {
  std::array<double, kBeamResultants> r;  // N Vy Vz T My Mz: F1 F2 F3 M1 M2 M3
  double off, ie;
};
using BM = BeamValues;
template <int C>
double beam_resultant(const BM& b) {
  return b.r[C];
}
constexpr Evaluator<BM> kBeam[] = {{"OFF", scalar<BM, &BM::off>}, {"F1", beam_resultant<0>}, {"F2", beam_resultant<1>},
                                   {"F3", beam_resultant<2>},      {"M1", beam_resultant<3>}, {"M2", beam_resultant<4>},
                                   {"M3", beam_resultant<5>},      {"IE", scalar<BM, &BM::ie>}};

struct ForceValues {  // interfaces and rigid walls: normal and tangential force, interface energies
  Vec3 fn, ft;
  double elastic = 0.0, friction = 0.0, damping = 0.0;
  Vec3 pair_normal_abs{}, pair_force_abs{};  // interfaces: sums over the pairs of |fn n_k| and |f_k|
  double pair_normal_norm = 0.0, pair_force_norm = 0.0;
};
using F = ForceValues;
constexpr Evaluator<F> kForces[] = {
    {"FNX", component<F, &F::fn, 0>}, {"FNY", component<F, &F::fn, 1>}, {"FNZ", component<F, &F::fn, 2>},
    {"FTX", component<F, &F::ft, 0>}, {"FTY", component<F, &F::ft, 1>}, {"FTZ", component<F, &F::ft, 2>},
    {"CE_ELAST", scalar<F, &F::elastic>}, {"CE_FRIC", scalar<F, &F::friction>}, {"CE_DAMP", scalar<F, &F::damping>},
    {"|FNX|", component<F, &F::pair_normal_abs, 0>}, {"|FNY|", component<F, &F::pair_normal_abs, 1>},
    {"|FNZ|", component<F, &F::pair_normal_abs, 2>}, {"||FN||", scalar<F, &F::pair_normal_norm>},
    {"|FX|", component<F, &F::pair_force_abs, 0>},    {"|FY|", component<F, &F::pair_force_abs, 1>},
    {"|FZ|", component<F, &F::pair_force_abs, 2>},    {"||F||", scalar<F, &F::pair_force_norm>}};

struct BodyValues {
  Vec3 f, m, r;
};
using R = BodyValues;
constexpr Evaluator<R> kBody[] = {
    {"FX", component<R, &R::f, 0>}, {"FY", component<R, &R::f, 1>}, {"FZ", component<R, &R::f, 2>},
    {"MX", component<R, &R::m, 0>}, {"MY", component<R, &R::m, 1>}, {"MZ", component<R, &R::m, 2>},
    {"RX", component<R, &R::r, 0>}, {"RY", component<R, &R::r, 1>}, {"RZ", component<R, &R::r, 2>}};

struct AccelerometerValues {
  Vec3 a, w;  // filtered acceleration [L/T^2], integral of the raw acceleration [L/T]
};
using A = AccelerometerValues;
constexpr Evaluator<A> kAccelerometer[] = {
    {"AX", component<A, &A::a, 0>}, {"AY", component<A, &A::a, 1>}, {"AZ", component<A, &A::a, 2>},
    {"WX", component<A, &A::w, 0>}, {"WY", component<A, &A::w, 1>}, {"WZ", component<A, &A::w, 2>}};

struct SectionValues {  // docs/output-format.md, "SECTIO"
  Vec3 fn, ft;            // normal and tangential parts of the resultant force, global axes
  Vec3 f_local, m_local;  // the resultant force and moment on the axes of the section's frame (eqs. SEC-3, SEC-4)
  Vec3 m;                 // the resultant moment about the reference point, global axes
  Vec3 center;            // the reference point
  double work = 0.0;
};
using C = SectionValues;
constexpr Evaluator<C> kSection[] = {
    {"FNX", component<C, &C::fn, 0>},      {"FNY", component<C, &C::fn, 1>},      {"FNZ", component<C, &C::fn, 2>},
    {"FTX", component<C, &C::ft, 0>},      {"FTY", component<C, &C::ft, 1>},      {"FTZ", component<C, &C::ft, 2>},
    {"M1", component<C, &C::m_local, 0>},  {"M2", component<C, &C::m_local, 1>},  {"M3", component<C, &C::m_local, 2>},
    {"WORK", scalar<C, &C::work>},         {"MX", component<C, &C::m, 0>},         {"MY", component<C, &C::m, 1>},
    {"MZ", component<C, &C::m, 2>},        {"F1", component<C, &C::f_local, 0>},  {"F2", component<C, &C::f_local, 1>},
    {"F3", component<C, &C::f_local, 2>},  {"CX", component<C, &C::center, 0>},   {"CY", component<C, &C::center, 1>},
    {"CZ", component<C, &C::center, 2>}};

// The evaluator of `name` for a kind of object, or -1 when Crumple computes no such variable.
template <class Values, std::size_t Count>
int find(const Evaluator<Values> (&table)[Count], std::string_view name) {
  for (std::size_t i = 0; i < Count; ++i)
    if (table[i].name == name) return static_cast<int>(i);
  return -1;
}

int evaluator_of(HistoryObject object, std::string_view name) {
  switch (object) {
    case HistoryObject::Node: return find(kNode, name);
    case HistoryObject::Part:
    case HistoryObject::Subset: return find(kPart, name);
    case HistoryObject::Shell:
    case HistoryObject::Sh3n: return find(kShell, name);
    case HistoryObject::Brick: return find(kBrick, name);
    case HistoryObject::Spring: return find(kSpring, name);
    case HistoryObject::Truss: return find(kTruss, name);
    case HistoryObject::Beam: return find(kBeam, name);
    case HistoryObject::Interface:
    case HistoryObject::RigidWall: return find(kForces, name);
    case HistoryObject::RigidBody: return find(kBody, name);
    case HistoryObject::Accelerometer: return find(kAccelerometer, name);
    case HistoryObject::Section: return find(kSection, name);
  }
  return -1;
}

template <class Values, std::size_t Count>
void append(const Evaluator<Values> (&table)[Count], const Values& values, const std::vector<int>& getters,
            std::vector<double>& row) {
  for (int g : getters) row.push_back(table[static_cast<std::size_t>(g)].get(values));
}

// ---- Object titles.
std::string object_title(const Model& m, const TimeHistoryRequest& th, std::size_t k) {
  const auto at = static_cast<std::size_t>(th.objects[k]);
  switch (th.object) {
    case HistoryObject::Part: return m.parts[at].title;
    case HistoryObject::Subset: return m.subsets[at].title;
    case HistoryObject::RigidWall: return m.rigid_walls[at].title;
    case HistoryObject::RigidBody: return m.rigid_bodies[at].title;
    case HistoryObject::Interface:  // TYPE7 ones first, then TYPE2 (resolve_output.cpp)
      return at < m.type7_interfaces.size() ? m.type7_interfaces[at].title
                                            : m.type2_interfaces[at - m.type7_interfaces.size()].title;
    case HistoryObject::Section: return m.sections[at].title;
    case HistoryObject::Accelerometer: return m.accelerometers[at].title;
    case HistoryObject::Node: {
      // A node's curves in a skew say so in their title: the components are along the skew's axes (SK-4).
      const std::string name = k < th.object_names.size() ? th.object_names[k] : std::string();
      const std::int64_t skew = k < th.object_skew_ids.size() ? th.object_skew_ids[k] : 0;
      return skew == 0 ? name : fmt::format("{}{}in skew {}", name, name.empty() ? "" : ", ", skew);
    }
    default: return k < th.object_names.size() ? th.object_names[k] : std::string();
  }
}

// ---- Node values.
Vec3 of(const std::vector<double>& x, const std::vector<double>& y, const std::vector<double>& z, std::size_t k) {
  return {x[k], y[k], z[k]};
}

Vec3 of(const std::vector<double>& xyz, std::size_t first) { return {xyz[first], xyz[first + 1], xyz[first + 2]}; }

// The change of a velocity over the step, times `scale` / dt: NaN when the update is not known.
Vec3 rate_of_change(const Vec3& now, const std::array<const std::vector<double>*, 6>& then, std::size_t first,
                  std::size_t k, double scale, double dt) {
  Vec3 out;
  for (std::size_t c = 0; c < 3; ++c) out[c] = dt > 0.0 ? scale * (now[c] - (*then[first + c])[k]) / dt : kUnknown;
  return out;
}

// The integral of node k's angular velocity (solver/node_rotations.hpp): NaN for a node the cycle does not keep it
// for (no request asked DRX, DRY or DRZ of it).
Vec3 node_rotation(const HistoryIntegrals& h, std::size_t k) {
  const auto at = std::lower_bound(h.rotation_nodes.begin(), h.rotation_nodes.end(), static_cast<std::int32_t>(k));
  const bool kept = at != h.rotation_nodes.end() && *at == static_cast<std::int32_t>(k) &&
                    h.rotation.size() == 3 * h.rotation_nodes.size();
  if (!kept)
    return {kUnknown, kUnknown, kUnknown};
  return of(h.rotation, 3 * static_cast<std::size_t>(at - h.rotation_nodes.begin()));
}

NodeValues node_values(const Model& m, const SolverState& s, const VelocityChange& change, std::size_t k) {
  const NodalState& n = s.nodes;
  NodeValues out;
  out.x = of(n.x, n.y, n.z, k);
  out.d = {out.x[0] - m.nodes.x[k], out.x[1] - m.nodes.y[k], out.x[2] - m.nodes.z[k]};
  out.v = of(n.vx, n.vy, n.vz, k);
  out.vr = of(n.wx, n.wy, n.wz, k);
  const double dt = change.known() ? change.dt : 0.0;
  out.a = rate_of_change(out.v, change.before, 0, k, 1.0, dt);
  out.ar = rate_of_change(out.vr, change.before, 3, k, 1.0, dt);
  // The reaction of the kinematic conditions: the impulse they gave the node over the step. A rigid body's nodes
  // move with their body, whose driven motion is not split into nodal reactions.
  const std::int32_t owner = k < s.rigid_owner.size() ? s.rigid_owner[k] : -1;
  const bool in_body = owner >= 0 && s.bodies[static_cast<std::size_t>(owner)].active;
  const double reaction_dt = in_body ? 0.0 : dt;
  out.reaction = rate_of_change(out.v, change.free, 0, k, n.mass[k], reaction_dt);
  out.reaction_moment = rate_of_change(out.vr, change.free, 3, k, n.inertia[k], reaction_dt);
  out.dr = node_rotation(s.histories, k);
  return out;
}

// A node's vectors written in a skew: their components along its axes at the current positions; a position too,
// with no origin taken off (eq. SK-4, as the reference writes them).
NodeValues in_skew(NodeValues values, const SolverState& s, std::int32_t skew) {
  if (skew < 0) return values;
  const SkewAxes& axes = s.skew_axes[static_cast<std::size_t>(skew)];
  for (Vec3* v : {&values.d, &values.v, &values.a, &values.vr, &values.ar, &values.x, &values.reaction,
                  &values.reaction_moment, &values.dr})
    *v = to_skew(axes, *v);
  return values;
}

// ---- Element values.
ShellHistoryValues shell_values(const Model& m, const SolverState& s, ElementKind kind, std::size_t group,
                                std::int32_t e) {
  const ShellState& state = shell_state(s, kind);
  const ShellElementOutput o = shell_element_output(s.shell_groups[group], state, m.element_groups[group], e);
  const auto ue = static_cast<std::size_t>(e);
  return {{o.n[0], o.n[1], o.n[2]}, {o.m[0], o.m[1], o.m[2]}, o.q[0], o.q[1],
          element_condition(state.deleted[ue]) == kElementDeleted ? 0.0 : 1.0, state.thickness[ue], o.plastic_strain_lower,
          o.plastic_strain_upper, o.strain_rate};
}

BrickValues brick_values(const Model& m, const SolverState& s, std::size_t group, std::int32_t e) {
  const BrickState& b = s.bricks;
  const auto ue = static_cast<std::size_t>(e);
  const auto np = static_cast<std::size_t>(b.points[group]);
  const std::size_t first = b.point_offset[group] + static_cast<std::size_t>(e - m.element_groups[group].begin) * np;
  BrickValues out{};
  const std::vector<point_real>* components[6] = {&b.sxx, &b.syy, &b.szz, &b.sxy, &b.syz, &b.szx};
  for (std::size_t k = 0; k < np; ++k) {  // the element's stress: the mean of its points
    for (std::size_t c = 0; c < 6; ++c) out.s[c] += (*components[c])[first + k] / static_cast<double>(np);
    out.plastic_strain += b.eps_p[first + k] / static_cast<double>(np);
  }
  const std::int32_t* nodes = m.elements[static_cast<int>(ElementKind::Brick8)].nodes_of(ue);
  out.volume = geometry::brick_volume(s.nodes.x, s.nodes.y, s.nodes.z, nodes);
  out.density = s.brick_groups[group].density * b.volume0[ue] / out.volume;
  out.ie = b.internal_energy[ue];
  out.off = element_condition(b.deleted[ue]) == kElementDeleted ? 0.0 : 1.0;
  return out;
}

// FX: the axial force, positive in tension; LX: the elongation (docs/theory/spring.md, SP-1, SP-2); a general
// spring's forces, moments, displacements and rotations in the global axes (SP-9).
SpringValues spring_values(const SolverState& s, bool general, std::int32_t e) {
  const SpringState& sp = s.springs;
  const auto ue = static_cast<std::size_t>(e);
  const double* f = &sp.force[kSpringDofs * ue];
  const double* l = &sp.elongation[kSpringDofs * ue];
  SpringValues out{};
  out.f = {f[0], f[1], f[2]}, out.m = {f[3], f[4], f[5]};
  out.l = {l[0], l[1], l[2]}, out.r = {l[3], l[4], l[5]};
  out.ie = sp.internal_energy[ue];
  const double* rest = &sp.rest_offset[3 * ue];
  out.length = general ? norm(Vec3{rest[0] + l[0], rest[1] + l[1], rest[2] + l[2]}) : sp.length0[ue] + l[0];
  out.off = element_condition(sp.deleted[ue]) == kElementDeleted ? 0.0 : 1.0;
  return out;
}

// F: the axial force off A sigma, positive in tension (docs/theory/truss.md, TR-4); OFF the failed truss's factor
// (TR-7), 0 once deleted and while a gap is open (TR-5, measured).
TrussValues truss_values(const SolverState& s, std::size_t g, std::int32_t e) {
  const TrussState& t = s.trusses;
  const auto ue = static_cast<std::size_t>(e);
  const bool on = element_condition(t.deleted[ue]) != kElementDeleted &&
                  truss_acts(s.truss_groups[g], t.length0[ue], t.length[ue]);
  return {on ? t.off[ue] : 0.0, t.force[ue], t.internal_energy[ue], t.area[ue], t.length0[ue], static_cast<double>(t.eps_p[ue])};
}

// F1 F2 F3 M1 M2 M3: the resultants in the beam's frame (docs/theory/beam.md, BM-2).
BeamValues beam_values(const SolverState& s, std::int32_t e) {
  const BeamState& b = s.beams;
  const auto ue = static_cast<std::size_t>(e);
  BeamValues out{};
  std::copy_n(&b.resultant[kBeamResultants * ue], kBeamResultants, out.r.begin());
  out.off = element_condition(b.deleted[ue]) == kElementDeleted ? 0.0 : 1.0;
  out.ie = b.internal_energy[ue];
  return out;
}

// ---- Walls, interfaces, bodies.
ForceValues wall_values(const RigidWallState& w) {
  ForceValues out;
  out.fn = w.normal_force;
  for (std::size_t c = 0; c < 3; ++c) out.ft[c] = w.force[c] - w.normal_force[c];
  return out;
}

ForceValues interface_values(const InterfaceResult& r) {
  return {r.normal_force,    r.tangential_force, r.elastic_energy,   r.friction_work,  r.damping_work,
          r.pair_normal_abs, r.pair_force_abs,   r.pair_normal_norm, r.pair_force_norm};
}

// A tied interface passes forces only: the TYPE7 energies and the pair sums are 0 (TI-6).
ForceValues tied_interface_values(const TiedInterfaceState& t) {
  ForceValues out;
  out.fn = t.normal_force, out.ft = t.tangential_force;
  return out;
}

// The rotation vector (axis times angle) of a rotation matrix, row-major.
Vec3 rotation_vector(const std::array<double, 9>& r) {
  const double c = std::clamp(0.5 * (r[0] + r[4] + r[8] - 1.0), -1.0, 1.0);
  const double angle = std::acos(c);
  const Vec3 skew{r[7] - r[5], r[2] - r[6], r[3] - r[1]};  // 2 sin(angle) axis
  const double sine = 0.5 * std::sqrt(skew[0] * skew[0] + skew[1] * skew[1] + skew[2] * skew[2]);
  if (angle < 1e-6) return {0.5 * skew[0], 0.5 * skew[1], 0.5 * skew[2]};
  if (sine > 1e-6) return {angle * skew[0] / (2.0 * sine), angle * skew[1] / (2.0 * sine), angle * skew[2] / (2.0 * sine)};
  // Near a half turn: the axis from the symmetric part, R = 2 a a^T - I, signed by its largest component.
  Vec3 axis{};
  for (std::size_t i = 0; i < 3; ++i) axis[i] = std::sqrt(std::max(0.0, 0.5 * (r[4 * i] + 1.0)));
  const std::size_t big = axis.x >= axis.y && axis.x >= axis.z ? 0 : axis.y >= axis.z ? 1 : 2;
  for (std::size_t i = 0; i < 3; ++i)
    if (i != big) axis[i] = 0.5 * (r[3 * big + i] + r[3 * i + big]) / (2.0 * axis[big]);
  return {angle * axis[0], angle * axis[1], angle * axis[2]};
}

BodyValues body_values(const SolverState& s, const RigidBodyState& b) {
  const NodalState& n = s.nodes;
  const auto k = static_cast<std::size_t>(b.main_node);
  return {of(n.fx, n.fy, n.fz, k), of(n.mx, n.my, n.mz, k), rotation_vector(b.rotation)};
}

// What the cycle integrated for accelerometer `k` (solver/accelerometers.hpp).
AccelerometerValues accelerometer_values(const HistoryIntegrals& h, std::size_t k) {
  if (3 * k + 2 >= h.accel_filtered.size() || 3 * k + 2 >= h.accel_velocity.size())
    throw std::runtime_error(fmt::format("history: the solver state has no values for accelerometer {}", k));
  return {of(h.accel_filtered, 3 * k), of(h.accel_velocity, 3 * k)};
}

// ---- Cut sections (docs/output-format.md, "SECTIO").
const ElementRecords& records_of(const SolverState& s, ElementKind kind) { return element_state(s, kind).records; }

const std::vector<double>& section_work_of(const SolverState& s, ElementKind kind) {
  return element_state(s, kind).section_work;
}

SectionValues section_values(const Model& m, const SolverState& s, const Section& section,
                             const std::vector<SectionTerm>& terms) {
  const NodalState& n = s.nodes;
  auto at = [&n](std::int32_t k) { return of(n.x, n.y, n.z, static_cast<std::size_t>(k)); };
  // The frame of N1 N2 N3 at the row's positions (eq. SEC-2): e1 along N1N2, e3 normal to the plane N1N2N3.
  const Vec3 x1 = at(section.nodes[0]), x2 = at(section.nodes[1]), x3 = at(section.nodes[2]);
  const Vec3 e1 = unit(x2 - x1), e3 = unit(cross(e1, x3 - x1)), e2 = cross(e3, e1);
  // The reference point O (Iframe, eq. SEC-5).
  Vec3 o{0.0, 0.0, 0.0};
  const int point = section.iframe % 10;
  const std::vector<std::int32_t>* cut =
      section.node_group >= 0 ? &m.node_groups[static_cast<std::size_t>(section.node_group)].nodes : nullptr;
  if (point == 0) {
    o = x1;
  } else if (point == 1 || point == 2) {
    Vec3 sum{0.0, 0.0, 0.0};
    double weight = 0.0;
    for (std::int32_t k : cut != nullptr ? *cut : std::vector<std::int32_t>{}) {
      const double w = point == 1 ? 1.0 : n.mass[static_cast<std::size_t>(k)];
      sum = sum + scaled(at(k), w), weight += w;
    }
    o = weight > 0.0 ? scaled(sum, 1.0 / weight) : Vec3{kUnknown, kUnknown, kUnknown};
  }
  // The resultants over the terms in model order (eq. SEC-1).
  Vec3 f{0.0, 0.0, 0.0}, moment{0.0, 0.0, 0.0};
  double work = 0.0;
  for (const SectionTerm& t : terms) {
    const ElementRecords& r = records_of(s, t.kind);
    const auto ue = static_cast<std::size_t>(t.element);
    if (!r.covers(ue))
      throw std::runtime_error(fmt::format("history: the solver state has no loads recorded for /SECT/{}",
                                           section.user_id));
    const double* load = r.load_at(ue, t.slot);
    const Vec3 force{load[0], load[1], load[2]};
    const Vec3 couple = r.values_per_node == 6 ? Vec3{load[3], load[4], load[5]} : Vec3{0.0, 0.0, 0.0};
    f = f + force;
    moment = moment + couple + cross(at(t.node) - o, force);
    const std::vector<double>& w = section_work_of(s, t.kind);
    const std::size_t slot = ue * static_cast<std::size_t>(nodes_per_element(t.kind)) + static_cast<std::size_t>(t.slot);
    work += w.empty() ? kUnknown : w[slot];
  }
  SectionValues out;
  const double normal = dot(f, e3);
  out.fn = scaled(e3, normal);
  out.ft = f - out.fn;
  const bool global = section.iframe >= 10;
  const Vec3 axes[3] = {global ? Vec3{1.0, 0.0, 0.0} : e1, global ? Vec3{0.0, 1.0, 0.0} : e2,
                        global ? Vec3{0.0, 0.0, 1.0} : e3};
  for (std::size_t c = 0; c < 3; ++c) out.f_local[c] = dot(f, axes[c]), out.m_local[c] = dot(moment, axes[c]);
  out.m = moment;
  out.center = o;
  out.work = work;
  return out;
}

}  // namespace

// ---- Parts: sums over the nodes and the elements.
struct HistoryChannels::PartSums {
  std::vector<double> ie, he, ke, rke, mass;
  std::vector<Vec3> momentum, first_moment;  // sum m v, sum m x
  explicit PartSums(std::size_t parts)
      : ie(parts), he(parts), ke(parts), rke(parts), mass(parts), momentum(parts), first_moment(parts) {}
  PartValues of(const std::vector<std::int32_t>& parts) const {
    PartValues out;
    Vec3 moment{};
    for (std::int32_t p : parts) {
      const auto up = static_cast<std::size_t>(p);
      out.ie += ie[up], out.he += he[up], out.ke += ke[up], out.rke += rke[up], out.mass += mass[up];
      for (std::size_t c = 0; c < 3; ++c) out.momentum[c] += momentum[up][c], moment[c] += first_moment[up][c];
    }
    for (std::size_t c = 0; c < 3; ++c) out.cg[c] = out.mass > 0.0 ? moment[c] / out.mass : kUnknown;
    return out;
  }
};

HistoryChannels::HistoryChannels(const Model& model) : model_(model) {
  for (const TimeHistoryRequest& th : model.histories) add_request(th);
  for (int kind = 0; kind < kElementKinds; ++kind)
    element_group_[static_cast<std::size_t>(kind)].assign(model.elements[static_cast<std::size_t>(kind)].size(), -1);
  for (std::size_t g = 0; g < model.element_groups.size(); ++g) {
    const ElementGroup& group = model.element_groups[g];
    for (std::int32_t e = group.begin; e < group.end; ++e)
      element_group_[static_cast<std::size_t>(group.kind)][static_cast<std::size_t>(e)] = static_cast<std::int32_t>(g);
  }
  split_nodes_by_part();  // the run's part table needs it too
  if (needs_parts_) gather_subsets();
}

void HistoryChannels::add_request(const TimeHistoryRequest& th) {
  Request request{th.object, th.objects, {}, th.object_skews};
  HistoryDataset d;
  d.kind = std::string(history_kind(th.object).name);
  d.keyword = th.keyword, d.id = th.user_id, d.title = th.title;
  d.name = fmt::format("{}_{}", d.kind, th.user_id);
  const auto same = static_cast<std::size_t>(std::count_if(
      datasets_.begin(), datasets_.end(), [&](const HistoryDataset& o) { return o.kind == d.kind && o.id == d.id; }));
  if (same > 0) d.name += fmt::format("_{}", same + 1);
  std::vector<const HistoryVariable*> written;
  for (const HistoryVariable* v : select_history_variables(th.object, th.variables).variables) {
    if (!v->written) continue;
    const int getter = evaluator_of(th.object, v->name);
    if (getter < 0) throw std::logic_error(fmt::format("{}: no evaluator for the written variable {}", th.keyword, v->name));
    request.getters.push_back(getter), written.push_back(v);
  }
  if (written.empty() || th.objects.empty()) return;
  if (th.object == HistoryObject::Section) {
    section_terms_.resize(model_.sections.size());
    for (std::int32_t k : th.objects)
      section_terms_[static_cast<std::size_t>(k)] = section_terms(model_, model_.sections[static_cast<std::size_t>(k)]);
  }
  for (std::size_t k = 0; k < th.objects.size(); ++k)
    for (const HistoryVariable* v : written)
      d.columns.push_back({th.object_ids[k], object_title(model_, th, k), std::string(v->name), std::string(v->unit),
                           si_factor(v->dimension, model_.units.work),
                           fmt::format("{}/{}/{}", d.name, th.object_ids[k], v->name)});
  needs_parts_ = needs_parts_ || th.object == HistoryObject::Part || th.object == HistoryObject::Subset;
  datasets_.push_back(std::move(d));
  requests_.push_back(std::move(request));
}

// A node's mass, momentum and kinetic energy belong to the parts of the elements that use it, each in proportion to
// the lumped mass the element gives the node (its mass over its node count).
void HistoryChannels::split_nodes_by_part() {
  const Model& m = model_;
  struct Lumped {
    std::int32_t node, part;
    double mass;
  };
  std::vector<Lumped> lumped;  // one per element and node, then sorted by node and part
  for (const ElementGroup& g : m.element_groups) {
    const ElementTable& table = m.elements[static_cast<std::size_t>(g.kind)];
    const int count = nodes_per_element(g.kind);
    for (std::int32_t e = g.begin; e < g.end; ++e) {
      const double share = element_mass(m, g.kind, static_cast<std::size_t>(e)) / count;
      const std::int32_t* nodes = table.nodes_of(static_cast<std::size_t>(e));
      for (int a = 0; a < count; ++a) lumped.push_back({nodes[a], g.part, share});
    }
  }
  std::sort(lumped.begin(), lumped.end(),
            [](const Lumped& a, const Lumped& b) { return a.node != b.node ? a.node < b.node : a.part < b.part; });
  node_share_offset_.assign(m.nodes.size() + 1, 0);
  for (std::size_t i = 0, node = 0; node < m.nodes.size(); ++node) {
    const std::size_t first = node_share_.size();
    double total = 0.0;
    for (; i < lumped.size() && lumped[i].node == static_cast<std::int32_t>(node); ++i) {
      total += lumped[i].mass;
      if (node_share_.size() > first && node_share_.back().first == lumped[i].part) node_share_.back().second += lumped[i].mass;
      else node_share_.emplace_back(lumped[i].part, lumped[i].mass);
    }
    const double parts = static_cast<double>(node_share_.size() - first);
    for (std::size_t k = first; k < node_share_.size(); ++k)  // a node of massless elements only: equal shares
      node_share_[k].second = total > 0.0 ? node_share_[k].second / total : 1.0 / parts;
    node_share_offset_[node + 1] = node_share_.size();
  }
}

// A subset holds the parts that name it and, recursively, its child subsets' parts; each part once.
void HistoryChannels::gather_subsets() {
  const Model& m = model_;
  subset_parts_.assign(m.subsets.size(), {});
  for (std::size_t s = 0; s < m.subsets.size(); ++s) {
    std::vector<std::int64_t> pending{m.subsets[s].user_id}, seen;
    while (!pending.empty()) {
      const std::int64_t id = pending.back();
      pending.pop_back();
      if (std::find(seen.begin(), seen.end(), id) != seen.end()) continue;  // a cycle of subsets
      seen.push_back(id);
      for (std::size_t p = 0; p < m.parts.size(); ++p)
        if (m.parts[p].subset_id == id) subset_parts_[s].push_back(static_cast<std::int32_t>(p));
      if (const auto at = m.index.subsets.find(id); at != m.index.subsets.end())
        for (std::int64_t child : m.subsets[static_cast<std::size_t>(at->second)].children) pending.push_back(child);
    }
    std::sort(subset_parts_[s].begin(), subset_parts_[s].end());
    subset_parts_[s].erase(std::unique(subset_parts_[s].begin(), subset_parts_[s].end()), subset_parts_[s].end());
  }
}

HistoryChannels::PartSums HistoryChannels::part_sums(const SolverState& s) const {
  PartSums sums(model_.parts.size());
  const NodalState& n = s.nodes;
  for (std::size_t k = 0; k < n.size(); ++k) {
    const Vec3 v = of(n.vx, n.vy, n.vz, k), w = of(n.wx, n.wy, n.wz, k), x = of(n.x, n.y, n.z, k);
    const double ke = 0.5 * n.mass[k] * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    const double rke = 0.5 * n.inertia[k] * (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
    for (std::size_t i = node_share_offset_[k]; i < node_share_offset_[k + 1]; ++i) {
      const auto [part, share] = node_share_[i];
      const auto p = static_cast<std::size_t>(part);
      const double mass = share * n.mass[k];
      sums.mass[p] += mass, sums.ke[p] += share * ke, sums.rke[p] += share * rke;
      for (std::size_t c = 0; c < 3; ++c) sums.momentum[p][c] += mass * v[c], sums.first_moment[p][c] += mass * x[c];
    }
  }
  for (std::size_t kind = 0; kind < static_cast<std::size_t>(kElementKinds); ++kind) {
    const ElementTable& table = model_.elements[kind];
    const ElementKindState& state = element_state(s, table.kind);
    for (std::size_t e = 0; e < table.size(); ++e) {
      const auto p = static_cast<std::size_t>(table.part[e]);
      sums.ie[p] += state.internal_energy[e], sums.he[p] += state.hourglass_energy[e];
    }
  }
  return sums;
}

std::vector<PartResult> HistoryChannels::part_results(const SolverState& s) const {
  const PartSums sums = part_sums(s);
  std::vector<PartResult> out;
  for (std::size_t p = 0; p < model_.parts.size(); ++p)
    out.push_back({model_.parts[p].user_id, model_.parts[p].title, sums.mass[p], sums.ie[p], sums.ke[p] + sums.rke[p],
                   sums.he[p]});
  return out;
}

void HistoryChannels::evaluate(const SolverState& s, const VelocityChange& change,
                               std::vector<std::vector<double>>& values) const {
  values.resize(requests_.size());
  std::optional<PartSums> parts;
  if (needs_parts_) parts.emplace(part_sums(s));
  for (std::size_t r = 0; r < requests_.size(); ++r) {
    values[r].clear();
    evaluate(requests_[r], s, change, parts ? &*parts : nullptr, values[r]);
  }
}

void HistoryChannels::evaluate(const Request& r, const SolverState& s, const VelocityChange& change,
                               const PartSums* parts, std::vector<double>& row) const {
  const Model& m = model_;
  for (std::size_t i = 0; i < r.objects.size(); ++i) {
    const std::int32_t object = r.objects[i];
    const auto o = static_cast<std::size_t>(object);
    switch (r.object) {
      case HistoryObject::Node: {
        const std::int32_t skew = r.skews.empty() ? -1 : r.skews[i];
        append(kNode, in_skew(node_values(m, s, change, o), s, skew), r.getters, row);
        break;
      }
      case HistoryObject::Part: append(kPart, parts->of({object}), r.getters, row); break;
      case HistoryObject::Subset: append(kPart, parts->of(subset_parts_[o]), r.getters, row); break;
      case HistoryObject::Shell:
      case HistoryObject::Sh3n: {
        const ElementKind kind = r.object == HistoryObject::Shell ? ElementKind::Shell4 : ElementKind::Shell3;
        const auto g = static_cast<std::size_t>(element_group_[static_cast<std::size_t>(kind)][o]);
        append(kShell, shell_values(m, s, kind, g, object), r.getters, row);
        break;
      }
      case HistoryObject::Brick: {
        const auto g = static_cast<std::size_t>(element_group_[static_cast<std::size_t>(ElementKind::Brick8)][o]);
        append(kBrick, brick_values(m, s, g, object), r.getters, row);
        break;
      }
      case HistoryObject::Spring: {
        const auto g = static_cast<std::size_t>(element_group_[static_cast<std::size_t>(ElementKind::Spring)][o]);
        append(kSpring, spring_values(s, s.spring_groups[g].frame == SpringFrame::Global, object), r.getters, row);
        break;
      }
      case HistoryObject::Truss: {
        const auto g = static_cast<std::size_t>(element_group_[static_cast<std::size_t>(ElementKind::Truss)][o]);
        append(kTruss, truss_values(s, g, object), r.getters, row);
        break;
      }
      case HistoryObject::Beam: append(kBeam, beam_values(s, object), r.getters, row); break;
      case HistoryObject::Interface: {
        const std::size_t contacts = m.type7_interfaces.size();
        const ForceValues values = o < contacts ? interface_values(s.contact.results[o])
                                                : tied_interface_values(s.ties.interfaces[o - contacts]);
        append(kForces, values, r.getters, row);
        break;
      }
      case HistoryObject::RigidWall: append(kForces, wall_values(s.walls[o]), r.getters, row); break;
      case HistoryObject::RigidBody: append(kBody, body_values(s, s.bodies[o]), r.getters, row); break;
      case HistoryObject::Accelerometer:
        append(kAccelerometer, accelerometer_values(s.histories, o), r.getters, row);
        break;
      case HistoryObject::Section:
        append(kSection, section_values(m, s, m.sections[o], section_terms_[o]), r.getters, row);
        break;
    }
  }
}

}  // namespace crumple
