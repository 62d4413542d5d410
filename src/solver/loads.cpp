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

// Calls add(dof, node, value) for a load `value` along `dof` of the skew `skew` (-1: the global axes): in a skew,
// the load's three global components (eq. SK-6).
template <class Add>
void add_along(const SolverState& s, Dof dof, std::int32_t skew, std::size_t node, double value, Add& add) {
  if (skew < 0) return add(dof, node, value);
  const Vec3 e = s.skew_axes[static_cast<std::size_t>(skew)].axis[dof_axis(dof)];
  const int first = is_rotation(dof) ? 3 : 0;
  for (std::size_t c = 0; c < 3; ++c) add(static_cast<Dof>(first + static_cast<int>(c)), node, value * e[c]);
}

// Calls add(dof, node, value) for every /CLOAD and /GRAV force at time t, load by load in deck order.
template <class Add>
void for_each_external_force(const Model& m, const SolverState& s, double t, Add add) {
  const NodalState& n = s.nodes;
  for (const ImposedMotion& im : m.imposed) {
    if (im.kind != ImposedKind::Force || t < im.t_start || t > im.t_stop || !im.sensor.holds(t)) continue;
    const double value = curve(m, im.function, im.scale_x, im.scale_y, im.sensor.clock(t));
    for (std::int32_t node : m.node_groups[static_cast<std::size_t>(im.node_group)].nodes)
      add_along(s, im.dof, im.skew, static_cast<std::size_t>(node), value, add);
  }
  for (const Gravity& g : m.gravity) {
    if (!g.sensor.holds(t)) continue;
    const double acceleration = curve(m, g.function, g.scale_x, g.scale_y, g.sensor.clock(t));
    for_each_load_node(m, g.node_group, [&](std::int32_t node) {
      const auto k = static_cast<std::size_t>(node);
      add_along(s, g.dof, g.skew, k, n.mass[k] * acceleration, add);
    });
  }
}

// The velocity a node's /IMPDISP asks along the unit axis e: the one that brings its displacement along e to
// `target` over the step (with e a global axis, the displacement's component).
double velocity_to_displacement(const SolverState& s, std::size_t k, Vec3 e, double target, double dt_next) {
  const NodalState& n = s.nodes;
  const Vec3 u{n.x[k] - s.x0[k], n.y[k] - s.y0[k], n.z[k] - s.z0[k]};
  return (target - dot(u, e)) / dt_next;
}

Vec3 node_vector(const std::vector<double>& x, const std::vector<double>& y, const std::vector<double>& z,
                 std::size_t k) {
  return {x[k], y[k], z[k]};
}

void set_node_vector(std::vector<double>& x, std::vector<double>& y, std::vector<double>& z, std::size_t k, Vec3 v) {
  x[k] = v.x, y[k] = v.y, z[k] = v.z;
}

// /BCS in a skew: the velocity's components along the fixed axes of the skew set to zero (eq. SK-5).
void fix_in_skews(const Model& m, SolverState& s) {
  NodalState& n = s.nodes;
  for (const BoundaryCondition& bc : m.boundary_conditions) {
    if (bc.skew < 0) continue;
    const SkewAxes& a = s.skew_axes[static_cast<std::size_t>(bc.skew)];
    for (std::int32_t node : m.node_groups[static_cast<std::size_t>(bc.node_group)].nodes) {
      const auto k = static_cast<std::size_t>(node);
      Vec3 v = node_vector(n.vx, n.vy, n.vz, k), w = node_vector(n.wx, n.wy, n.wz, k);
      for (std::size_t d = 0; d < 3; ++d) {
        if (bc.fixed_translation[d]) v = with_component(v, a.axis[d], 0.0);
        if (bc.fixed_rotation[d]) w = with_component(w, a.axis[d], 0.0);
      }
      set_node_vector(n.vx, n.vy, n.vz, k, v), set_node_vector(n.wx, n.wy, n.wz, k, w);
    }
  }
}

}  // namespace

void add_external_forces(const Model& m, SolverState& s, double t) {
  for_each_external_force(m, s, t,
                          [&](Dof dof, std::size_t node, double value) { (*force(s.nodes, dof))[node] += value; });
}

void record_external_forces(const Model& m, SolverState& s, double t) {
  std::vector<double>& out = s.recorded.external_force;
  std::fill(out.begin(), out.end(), 0.0);
  for_each_external_force(m, s, t, [&](Dof dof, std::size_t node, double value) {
    const auto d = static_cast<std::size_t>(dof);
    if (d < 3) out[3 * node + d] += value;  // forces only; moments have no field
  });
}

void add_load_work(const Model& m, const SolverState& s, const std::array<std::vector<double>, 6>& before, double t,
                   double dt_average, ExactSum& work) {
  const NodalState& n = s.nodes;
  const std::vector<double>* now[6] = {&n.vx, &n.vy, &n.vz, &n.wx, &n.wy, &n.wz};
  for_each_external_force(m, s, t, [&](Dof dof, std::size_t k, double value) {
    const auto d = static_cast<std::size_t>(dof);
    if (s.domain.owns(k)) work.add(value * (0.5 * ((*now[d])[k] + before[d][k])) * dt_average);
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
  fix_in_skews(m, s);
  for (const ImposedMotion& im : m.imposed) {
    if (im.kind == ImposedKind::Force) continue;
    // An imposed velocity is the card's one value (its function at the mid-step), taken once; a displacement's
    // depends on each node's displacement so far.
    const bool velocity = im.kind == ImposedKind::Velocity;
    const std::optional<double> card_value = velocity ? imposed_velocity(m, s, im, 0, t, dt_next) : std::nullopt;
    if (velocity && !card_value) continue;
    for (std::int32_t node : m.node_groups[static_cast<std::size_t>(im.node_group)].nodes) {
      const auto k = static_cast<std::size_t>(node);
      const std::optional<double> value = velocity ? card_value : imposed_velocity(m, s, im, k, t, dt_next);
      if (!value) continue;
      if (im.skew < 0) {
        (*translation(n, im.dof))[k] = *value;
        continue;
      }
      // In a skew: the component along the skew's axis (eq. SK-5).
      const Vec3 e = s.skew_axes[static_cast<std::size_t>(im.skew)].axis[dof_axis(im.dof)];
      if (is_rotation(im.dof))
        set_node_vector(n.wx, n.wy, n.wz, k, with_component(node_vector(n.wx, n.wy, n.wz, k), e, *value));
      else
        set_node_vector(n.vx, n.vy, n.vz, k, with_component(node_vector(n.vx, n.vy, n.vz, k), e, *value));
    }
  }
  for (const FinalGeometry& g : m.final_geometries)
    for (std::size_t i = 0; i < g.nodes.size(); ++i)
      if (const auto v = final_geometry_velocity(m, s, g, i, t, dt_next))
        set_node_vector(n.vx, n.vy, n.vz, static_cast<std::size_t>(g.nodes[i]), *v);
}

std::optional<Vec3> final_geometry_velocity(const Model& m, const SolverState& s, const FinalGeometry& g, std::size_t i,
                                            double t, double dt_next) {
  const double t_next = t + dt_next;
  if (t_next < g.t_start || t > g.t_stop || dt_next <= 0.0 || !g.sensor.holds_during(t, t_next)) return std::nullopt;
  const double share = load_curve(m, g.function, g.scale_x, 1.0, g.sensor.clock(t_next));
  const auto k = static_cast<std::size_t>(g.nodes[i]);
  const NodalState& n = s.nodes;
  const Vec3 u{n.x[k] - s.x0[k], n.y[k] - s.y0[k], n.z[k] - s.z0[k]};
  return scaled(scaled(g.displacements[i], share) - u, 1.0 / dt_next);
}

std::optional<double> imposed_velocity(const Model& m, const SolverState& s, const ImposedMotion& im, std::size_t k,
                                       double t, double dt_next) {
  if (im.kind == ImposedKind::Velocity) {
    const double t_half = t + 0.5 * dt_next;
    if (t_half < im.t_start || t_half > im.t_stop || !im.sensor.holds(t_half)) return std::nullopt;
    return curve(m, im.function, im.scale_x, im.scale_y, im.sensor.clock(t_half));
  }
  if (im.kind != ImposedKind::Displacement || is_rotation(im.dof)) return std::nullopt;
  const double t_next = t + dt_next;
  if (t_next < im.t_start || t > im.t_stop || dt_next <= 0.0 || !im.sensor.holds_during(t, t_next)) return std::nullopt;
  const double target = curve(m, im.function, im.scale_x, im.scale_y, im.sensor.clock(t_next));
  Vec3 e{};
  if (im.skew < 0) e[static_cast<std::size_t>(dof_axis(im.dof))] = 1.0;
  else e = s.skew_axes[static_cast<std::size_t>(im.skew)].axis[dof_axis(im.dof)];
  return velocity_to_displacement(s, k, e, target, dt_next);
}

}  // namespace crumple::solver
