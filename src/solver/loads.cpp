// External forces (/CLOAD, /GRAV) and kinematic conditions (/BCS, /IMPVEL, /IMPDISP) (docs/theory/loads.md).
#include "solver/internal.hpp"

namespace crumple::solver {
namespace {

double curve(const Model& m, std::int32_t function, double scale_x, double scale_y, double t) {
  return load_curve(m, function, scale_x, scale_y, t);
}

std::vector<double>* translation(NodalState& n, Dof dof) {
  switch (dof) {
    case Dof::X: return &n.vx;
    case Dof::Y: return &n.vy;
    case Dof::Z: return &n.vz;
    case Dof::XX: return &n.wx;
    case Dof::YY: return &n.wy;
    case Dof::ZZ: return &n.wz;
  }
  return &n.vx;
}

std::vector<double>* force(NodalState& n, Dof dof) {
  switch (dof) {
    case Dof::X: return &n.fx;
    case Dof::Y: return &n.fy;
    case Dof::Z: return &n.fz;
    case Dof::XX: return &n.mx;
    case Dof::YY: return &n.my;
    case Dof::ZZ: return &n.mz;
  }
  return &n.fx;
}

// Calls add(dof, node, value) for every /CLOAD and /GRAV force at time t, load by load in deck order.
template <class Add>
void for_each_external_force(const Model& m, const NodalState& n, double t, Add add) {
  for (const ImposedMotion& im : m.imposed) {
    if (im.kind != ImposedKind::Force || t < im.t_start || t > im.t_stop) continue;
    const double value = curve(m, im.function, im.scale_x, im.scale_y, t);
    for (std::int32_t node : m.node_groups[static_cast<std::size_t>(im.node_group)].nodes)
      add(im.dof, static_cast<std::size_t>(node), value);
  }
  for (const Gravity& g : m.gravity) {
    const double acceleration = curve(m, g.function, g.scale_x, g.scale_y, t);
    for_each_load_node(m, g.node_group, [&](std::int32_t node) {
      add(g.dof, static_cast<std::size_t>(node), n.mass[static_cast<std::size_t>(node)] * acceleration);
    });
  }
}

}  // namespace

void add_external_forces(const Model& m, SolverState& s, double t) {
  for_each_external_force(m, s.nodes, t,
                          [&](Dof dof, std::size_t node, double value) { (*force(s.nodes, dof))[node] += value; });
}

void record_external_forces(const Model& m, SolverState& s, double t) {
  std::vector<double>& out = s.recorded.external_force;
  std::fill(out.begin(), out.end(), 0.0);
  for_each_external_force(m, s.nodes, t, [&](Dof dof, std::size_t node, double value) {
    const auto d = static_cast<std::size_t>(dof);
    if (d < 3) out[3 * node + d] += value;  // forces only; moments have no field
  });
}

void impose_kinematics(const Model& m, SolverState& s, double t, double dt_next) {
  NodalState& n = s.nodes;
  for_each_local_node(s.domain, n.size(), [&](std::size_t k) {
    const std::uint8_t mask = s.fixed[k];
    if (mask == 0) return;
    if (mask & 1u) n.vx[k] = 0.0;
    if (mask & 2u) n.vy[k] = 0.0;
    if (mask & 4u) n.vz[k] = 0.0;
    if (mask & 8u) n.wx[k] = 0.0;
    if (mask & 16u) n.wy[k] = 0.0;
    if (mask & 32u) n.wz[k] = 0.0;
  });
  const double t_half = t + 0.5 * dt_next;
  for (const ImposedMotion& im : m.imposed) {
    if (im.kind == ImposedKind::Force) continue;
    auto& v = *translation(n, im.dof);
    const auto& nodes = m.node_groups[static_cast<std::size_t>(im.node_group)].nodes;
    if (im.kind == ImposedKind::Velocity) {
      if (t_half < im.t_start || t_half > im.t_stop) continue;
      const double value = curve(m, im.function, im.scale_x, im.scale_y, t_half);
      for (std::int32_t node : nodes) v[static_cast<std::size_t>(node)] = value;
    } else {
      // Imposed displacement: the velocity that brings the node to u(t + dt) during the step.
      if (t + dt_next < im.t_start || t > im.t_stop || dt_next <= 0.0) continue;
      const double target = curve(m, im.function, im.scale_x, im.scale_y, t + dt_next);
      const std::vector<double>* x = im.dof == Dof::X ? &n.x : im.dof == Dof::Y ? &n.y : &n.z;
      const std::vector<double>* x0 = im.dof == Dof::X ? &s.x0 : im.dof == Dof::Y ? &s.y0 : &s.z0;
      if (im.dof == Dof::XX || im.dof == Dof::YY || im.dof == Dof::ZZ) continue;  // rotations: rejected by reader
      for (std::int32_t node : nodes) {
        const auto k = static_cast<std::size_t>(node);
        v[k] = (target - ((*x)[k] - (*x0)[k])) / dt_next;
      }
    }
  }
}

std::optional<double> imposed_velocity(const Model& m, const SolverState& s, const ImposedMotion& im, std::size_t k,
                                       double t, double dt_next) {
  if (im.kind == ImposedKind::Velocity) {
    const double t_half = t + 0.5 * dt_next;
    if (t_half < im.t_start || t_half > im.t_stop) return std::nullopt;
    return curve(m, im.function, im.scale_x, im.scale_y, t_half);
  }
  if (im.kind != ImposedKind::Displacement || is_rotation(im.dof)) return std::nullopt;
  if (t + dt_next < im.t_start || t > im.t_stop || dt_next <= 0.0) return std::nullopt;
  const double target = curve(m, im.function, im.scale_x, im.scale_y, t + dt_next);
  const NodalState& n = s.nodes;
  const std::vector<double>* x = im.dof == Dof::X ? &n.x : im.dof == Dof::Y ? &n.y : &n.z;
  const std::vector<double>* x0 = im.dof == Dof::X ? &s.x0 : im.dof == Dof::Y ? &s.y0 : &s.z0;
  return (target - ((*x)[k] - (*x0)[k])) / dt_next;
}

}  // namespace crumple::solver
