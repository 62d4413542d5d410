// Fully integrated 4-node Batoz shell, Ishell 12 (docs/theory/shell4.md, "QBAT", eqs. ): the bilinear
// surface of the element seen in its co-rotational frame (warp included), 2 x 2 Gauss points each with its own
// tangent frame, membrane and bending strains at the points, the in-plane shear strain at the centre only, the
// transverse shear strains interpolated from the mid-side tying points of Batoz and Dhatt's Q4gamma. No hourglass
// control: the element has no zero-energy mode.
#include <algorithm>
#include <cmath>

#include "crumple/elements/shell4.hpp"
#include "shell4_section.hpp"

namespace crumple {
namespace {


constexpr double kNodeXi[4] = {-1.0, 1.0, 1.0, -1.0};
constexpr double kNodeEta[4] = {-1.0, -1.0, 1.0, 1.0};
constexpr double kGaussAbscissa = 0.57735026918962576451;  // 1 / sqrt(3)
constexpr double kGaussXi[4] = {-kGaussAbscissa, kGaussAbscissa, kGaussAbscissa, -kGaussAbscissa};
constexpr double kGaussEta[4] = {-kGaussAbscissa, -kGaussAbscissa, kGaussAbscissa, kGaussAbscissa};

// Tangents of the bilinear surface x(xi, eta) = sum N_I x_I (eq. Q-1): d x / d xi on the line eta, d x / d eta on
// the line xi.
Vec3 tangent_xi(const Vec3 (&x)[4], double eta) {
  Vec3 a{0.0, 0.0, 0.0};
  for (int i = 0; i < 4; ++i) a = a + scaled(x[i], 0.25 * kNodeXi[i] * (1.0 + kNodeEta[i] * eta));
  return a;
}
Vec3 tangent_eta(const Vec3 (&x)[4], double xi) {
  Vec3 a{0.0, 0.0, 0.0};
  for (int i = 0; i < 4; ++i) a = a + scaled(x[i], 0.25 * kNodeEta[i] * (1.0 + kNodeXi[i] * xi));
  return a;
}

// A Gauss point's tangent frame (r3 the surface normal, r1 the element's e1 projected on the tangent plane) and
// its gradient operator (eq. Q-2); all vectors in element-frame components.
struct GaussPoint {
  Vec3 r1, r2, r3;
  double x_xi, x_eta, y_xi, y_eta;  // Jacobian d(x, y) / d(xi, eta) in the point's frame
  double det;                       // surface area per unit xi eta [L^2]
  double dndx[4], dndy[4];          // shape function derivatives [1/L]
};

// False when the surface Jacobian at the point is not positive: the element is inverted there.
bool gauss_point(const Vec3 (&x)[4], double xi, double eta, GaussPoint& g) {
  const Vec3 a = tangent_xi(x, eta), b = tangent_eta(x, xi);
  const Vec3 normal = cross(a, b);
  if (!(normal.z > 0.0)) return false;
  g.r3 = unit(normal);
  g.r1 = unit(Vec3{1.0, 0.0, 0.0} - scaled(g.r3, g.r3.x));
  g.r2 = cross(g.r3, g.r1);
  g.x_xi = dot(a, g.r1), g.y_xi = dot(a, g.r2), g.x_eta = dot(b, g.r1), g.y_eta = dot(b, g.r2);
  g.det = g.x_xi * g.y_eta - g.x_eta * g.y_xi;
  if (!(g.det > 0.0)) return false;
  for (int i = 0; i < 4; ++i) {
    const double n_xi = 0.25 * kNodeXi[i] * (1.0 + kNodeEta[i] * eta);
    const double n_eta = 0.25 * kNodeEta[i] * (1.0 + kNodeXi[i] * xi);
    g.dndx[i] = (g.y_eta * n_xi - g.y_xi * n_eta) / g.det;
    g.dndy[i] = (g.x_xi * n_eta - g.x_eta * n_xi) / g.det;
  }
  return true;
}

// Tying points of the transverse shear (eq. Q-5), the mid-sides A (nodes 1-2, eta = -1), B (2-3, xi = 1),
// C (4-3, eta = 1) and D (1-4, xi = -1). With the tangent t = (x_j - x_i) / 2 of the side from node i to node j
// and the director interpolated there, d = (n_i + n_j) / 2, the covariant shear rate is the rate of t . d:
//   gamma = d . (v_j - v_i) / 2 + t . (w_i x n_i + w_j x n_j) / 2.
constexpr int kTyingFrom[4] = {0, 1, 3, 0}, kTyingTo[4] = {1, 2, 2, 3};
struct TyingPoint {
  Vec3 director;         // (n_i + n_j) / 2
  Vec3 lever_i, lever_j;  // n_i x t and n_j x t: the rotations' share, w . (n x t) = t . (w x n)
};

// The element in its co-rotational frame: node positions from the centroid (z is the warp), velocities, angular
// velocities and nodal directors (the unit normals of the element's bilinear surface at its nodes, eq. Q-1), all
// in element-frame components.
struct LocalElement {
  shell_section::Frame frame;
  Vec3 x[4], v[4], w[4], n[4];
};

// Gathers the element; with small strain (Ismstr 1, 3, or Ismstr 2 after the switch) the reference shape
// replaces the current one, flat as it was stored (eqs. S-15, S-16).
bool local_element(const ElementTable& table, std::size_t e, const NodalState& nodes, ShellState& state,
                   bool small_strain, LocalElement& l) {
  const std::int32_t* n = table.nodes_of(e);
  Vec3 x[4], v[4], w[4];
  for (int a = 0; a < 4; ++a) {
    const auto k = static_cast<std::size_t>(n[a]);
    x[a] = {nodes.x[k], nodes.y[k], nodes.z[k]};
    v[a] = {nodes.vx[k], nodes.vy[k], nodes.vz[k]};
    w[a] = {nodes.wx[k], nodes.wy[k], nodes.wz[k]};
  }
  if (!shell_section::corotational_frame<4>(x, l.frame)) return false;
  const shell_section::Frame& f = l.frame;
  for (int a = 0; a < 4; ++a) {
    const Vec3 r = x[a] - f.centre;
    l.x[a] = {dot(r, f.e1), dot(r, f.e2), dot(r, f.e3)};
    l.v[a] = {dot(v[a], f.e1), dot(v[a], f.e2), dot(v[a], f.e3)};
    l.w[a] = {dot(w[a], f.e1), dot(w[a], f.e2), dot(w[a], f.e3)};
  }
  if (small_strain) {
    double* shape = &state.initial_shape[8 * e];
    if (state.initial_length[e] == 0.0)
      for (int a = 0; a < 4; ++a) shape[a] = l.x[a].x, shape[4 + a] = l.x[a].y;
    for (int a = 0; a < 4; ++a) l.x[a] = {shape[a], shape[4 + a], 0.0};
  }
  for (int a = 0; a < 4; ++a) {
    const Vec3 normal = cross(tangent_xi(l.x, kNodeEta[a]), tangent_eta(l.x, kNodeXi[a]));
    if (!(normal.z > 0.0)) return false;
    l.n[a] = unit(normal);
  }
  return true;
}

void tying_points(const LocalElement& l, TyingPoint (&tying)[4]) {
  for (int k = 0; k < 4; ++k) {
    const int i = kTyingFrom[k], j = kTyingTo[k];
    const Vec3 tangent = scaled(l.x[j] - l.x[i], 0.5);
    tying[k].director = scaled(l.n[i] + l.n[j], 0.5);
    tying[k].lever_i = cross(l.n[i], tangent);
    tying[k].lever_j = cross(l.n[j], tangent);
  }
}

// Plane-stress elastic stiffness times a strain (xx, yy, gxy), per unit of the section stiffness [stress].
struct Elastic {
  double c, nu;  // E / (1 - nu^2), nu
  void apply(const double (&d)[3], double (&s)[3]) const {
    s[0] = c * (d[0] + nu * d[1]), s[1] = c * (d[1] + nu * d[0]), s[2] = c * 0.5 * (1.0 - nu) * d[2];
  }
};

// Generalised nodal forces and moments of one element in its frame, accumulated over the Gauss points.
struct NodalLoads {
  Vec3 f[4] = {}, m[4] = {};
  double in_plane_shear = 0.0;  // sum over the points of det N_xy: the work conjugate of the centre shear rate
  double tying[4] = {};         // work conjugates of the four tying shear rates (eq. Q-7)
};

// Gradients at a Gauss point of the velocity, the director d = sum N_I n_I and its rate sum N_I (w_I x n_I).
struct PointGradients {
  Vec3 v_x, v_y, d_x, d_y, rate_x, rate_y;
};
PointGradients point_gradients(const LocalElement& l, const GaussPoint& g) {
  PointGradients q{};
  for (int a = 0; a < 4; ++a) {
    const Vec3 rate = cross(l.w[a], l.n[a]);
    q.v_x = q.v_x + scaled(l.v[a], g.dndx[a]), q.v_y = q.v_y + scaled(l.v[a], g.dndy[a]);
    q.d_x = q.d_x + scaled(l.n[a], g.dndx[a]), q.d_y = q.d_y + scaled(l.n[a], g.dndy[a]);
    q.rate_x = q.rate_x + scaled(rate, g.dndx[a]), q.rate_y = q.rate_y + scaled(rate, g.dndy[a]);
  }
  return q;
}

// Membrane strain rates (eq. Q-3; gxy is the centre's) and curvature rates, the rates of x_,a . d_,b (eq. Q-4).
shell_section::StrainRates point_rates(const GaussPoint& g, const PointGradients& q, double centre_shear) {
  return {dot(q.v_x, g.r1),
          dot(q.v_y, g.r2),
          centre_shear,
          dot(g.r1, q.rate_x) + dot(q.v_x, q.d_x),
          dot(g.r2, q.rate_y) + dot(q.v_y, q.d_y),
          dot(g.r1, q.rate_y) + dot(g.r2, q.rate_x) + dot(q.v_x, q.d_y) + dot(q.v_y, q.d_x)};
}

// Adds a Gauss point's membrane, bending and shear resultants to the nodal loads (eq. Q-7), `det` its weight:
// the derivatives of its power det (N : d + M : kappa + Q . gamma) with respect to the nodal velocities.
void add_point_loads(const LocalElement& l, const GaussPoint& g, const PointGradients& q, int point,
                     const double (&n)[3], const double (&m)[3], double qx, double qy, NodalLoads& loads) {
  // Director gradients paired with the moments, for the velocity part of the curvature rate.
  const Vec3 mx = scaled(q.d_x, m[0]) + scaled(q.d_y, m[2]), my = scaled(q.d_y, m[1]) + scaled(q.d_x, m[2]);
  for (int a = 0; a < 4; ++a) {
    const double nx = g.dndx[a], ny = g.dndy[a];
    loads.f[a] = loads.f[a] + scaled(g.r1, g.det * nx * n[0]) + scaled(g.r2, g.det * ny * n[1]) +
                 scaled(mx, g.det * nx) + scaled(my, g.det * ny);
    // d kappa / d w_I: r_b . (w_I x n_I) N_I,a = w_I . (n_I x r_b) N_I,a.
    const Vec3 along_x = scaled(g.r1, nx * m[0] + ny * m[2]), along_y = scaled(g.r2, ny * m[1] + nx * m[2]);
    loads.m[a] = loads.m[a] + scaled(cross(l.n[a], along_x + along_y), g.det);
  }
  loads.in_plane_shear += g.det * n[2];
  // det (Qx gxz + Qy gyz) = q_xi gamma_xi + q_eta gamma_eta, then spread on the tying points (eq. Q-6).
  const double q_xi = g.y_eta * qx - g.x_eta * qy, q_eta = g.x_xi * qy - g.y_xi * qx;
  const double xi = kGaussXi[point], eta = kGaussEta[point];
  loads.tying[0] += 0.5 * (1.0 - eta) * q_xi;
  loads.tying[2] += 0.5 * (1.0 + eta) * q_xi;
  loads.tying[3] += 0.5 * (1.0 - xi) * q_eta;
  loads.tying[1] += 0.5 * (1.0 + xi) * q_eta;
}

// Centre shear (B1, B2 of eq. S-2) and tying loads to the nodes, then everything to global, subtracted (and kept in
// `record`, 6 values per node, when the run records element loads).
void apply_loads(const LocalElement& l, const double (&b1)[4], const double (&b2)[4], const TyingPoint (&tying)[4],
                 NodalLoads& loads, const std::int32_t* n, NodalState& nodes, double* record) {
  for (int a = 0; a < 4; ++a) {
    loads.f[a].x += loads.in_plane_shear * b2[a];
    loads.f[a].y += loads.in_plane_shear * b1[a];
  }
  for (int k = 0; k < 4; ++k) {
    const double half = 0.5 * loads.tying[k];
    const int i = kTyingFrom[k], j = kTyingTo[k];
    loads.f[j] = loads.f[j] + scaled(tying[k].director, half);
    loads.f[i] = loads.f[i] - scaled(tying[k].director, half);
    loads.m[i] = loads.m[i] + scaled(tying[k].lever_i, half);
    loads.m[j] = loads.m[j] + scaled(tying[k].lever_j, half);
  }
  const shell_section::Frame& f = l.frame;
  for (int a = 0; a < 4; ++a) {
    const Vec3 force = scaled(f.e1, loads.f[a].x) + scaled(f.e2, loads.f[a].y) + scaled(f.e3, loads.f[a].z);
    const Vec3 moment = scaled(f.e1, loads.m[a].x) + scaled(f.e2, loads.m[a].y) + scaled(f.e3, loads.m[a].z);
    subtract_internal(nodes, static_cast<std::size_t>(n[a]), force, moment);
    if (record != nullptr) record_load(record + 6 * a, force, moment);
  }
}

}  // namespace

GroupStepResult shell4_qbat_forces(const ElementTable& table, const ElementGroup& group, const ShellGroupParameters& p,
                                   NodalState& nodes, ShellState& state, double dt) {
  GroupStepResult result;
  const double E = p.young, nu = p.poisson, G = E / (2.0 * (1.0 + nu));
  const double wave_speed = shell_step_wave_speed(E, nu, p.density, true);  // plate wave speed
  const materials::PlaneStressElastic elastic{E, nu};
  const Elastic viscous{E / (1.0 - nu * nu), nu};
  const int np = p.points;

  const bool recording = state.records.on(group.begin);
  for (std::int32_t e = group.begin; e < group.end; ++e) {
    const auto ue = static_cast<std::size_t>(e);
    // What one of this domain's elements hands the nodes if it computes nothing this cycle.
    if (recording && !(state.deleted[ue] & kElementElsewhere)) state.records.clear(ue);
    if (state.deleted[ue]) continue;
    const bool small_strain = p.small_strain || state.small_strain[ue] != 0;
    LocalElement l;
    if (!local_element(table, ue, nodes, state, small_strain, l)) {
      delete_inverted_shell(state, result, e);
      continue;
    }
    // Centre gradient of the projection (eq. S-2): the in-plane shear rate and the critical step (T-1).
    double lx[4], ly[4];
    for (int a = 0; a < 4; ++a) lx[a] = l.x[a].x, ly[a] = l.x[a].y;
    const double area = shell_section::local_area<4>(lx, ly);
    GaussPoint g[4];
    bool valid = area > 0.0;
    for (int i = 0; i < 4 && valid; ++i) valid = gauss_point(l.x, kGaussXi[i], kGaussEta[i], g[i]);
    if (!valid) {
      delete_inverted_shell(state, result, e);
      continue;
    }
    double b1[4], b2[4], centre_shear = 0.0;
    for (int a = 0; a < 4; ++a) {
      const int next = (a + 1) % 4, previous = (a + 3) % 4;
      b1[a] = (ly[next] - ly[previous]) * 0.5 / area;
      b2[a] = (lx[previous] - lx[next]) * 0.5 / area;
      centre_shear += b2[a] * l.v[a].x + b1[a] * l.v[a].y;
    }
    double length = shell_section::characteristic_length<4>(lx, ly, area);
    if (small_strain) {
      if (state.initial_length[ue] == 0.0) state.initial_length[ue] = length;
      length = state.initial_length[ue];
    }
    const double step = length / wave_speed;

    // Covariant transverse shear rates at the tying points (eq. Q-5).
    TyingPoint tying[4];
    tying_points(l, tying);
    double gamma[4];
    for (int k = 0; k < 4; ++k) {
      const int i = kTyingFrom[k], j = kTyingTo[k];
      gamma[k] = 0.5 * (dot(tying[k].director, l.v[j] - l.v[i]) + dot(l.w[i], tying[k].lever_i) +
                        dot(l.w[j], tying[k].lever_j));
    }

    const double t = state.thickness[ue];
    const double shear_stiffness = p.shear_factor * G * t;
    // Viscous fraction dn of the elastic response over the element's transit time (eq. Q-8).
    const double damping = p.numerical_damping * step;
    NodalLoads loads;
    double work = 0.0, thickness_strain = 0.0, weight = 0.0;
    bool failed = false;
    for (int i = 0; i < 4; ++i) {
      const PointGradients gradients = point_gradients(l, g[i]);
      const shell_section::StrainRates s = point_rates(g[i], gradients, centre_shear);
      const std::size_t first =
          p.first_point + (static_cast<std::size_t>(e - group.begin) * 4 + static_cast<std::size_t>(i)) * static_cast<std::size_t>(np);
      double* bending = p.resultant_plasticity ? &state.gauss_bending[12 * ue + 3 * static_cast<std::size_t>(i)] : nullptr;
      const shell_section::Update u = shell_section::update(p, elastic, state, first, bending, t, s, dt);
      // Transverse shear at the point from the tying rates (eq. Q-6), elastic.
      const double xi = kGaussXi[i], eta = kGaussEta[i];
      const double gamma_xi = 0.5 * (1.0 - eta) * gamma[0] + 0.5 * (1.0 + eta) * gamma[2];
      const double gamma_eta = 0.5 * (1.0 - xi) * gamma[3] + 0.5 * (1.0 + xi) * gamma[1];
      const double gxz = (g[i].y_eta * gamma_xi - g[i].y_xi * gamma_eta) / g[i].det;
      const double gyz = (g[i].x_xi * gamma_eta - g[i].x_eta * gamma_xi) / g[i].det;
      double* q = &state.gauss_shear[8 * ue + 2 * static_cast<std::size_t>(i)];
      const double old_qx = q[0], old_qy = q[1];
      q[0] += shear_stiffness * gxz * dt;
      q[1] += shear_stiffness * gyz * dt;
      double vn[3], vm[3];
      viscous.apply({s.dxx, s.dyy, s.gxy}, vn);
      viscous.apply({s.kxx, s.kyy, s.kxy}, vm);
      double n[3], m[3];
      for (int c = 0; c < 3; ++c) {
        vn[c] *= damping * t, vm[c] *= damping * t * t * t / 12.0;
        n[c] = u.n[c] + vn[c], m[c] = u.m[c] + vm[c];
      }
      const double viscous_work = dt * (vn[0] * s.dxx + vn[1] * s.dyy + vn[2] * s.gxy + vm[0] * s.kxx +
                                        vm[1] * s.kyy + vm[2] * s.kxy);
      work += g[i].det * (shell_section::work(u, s, dt) + viscous_work +
                          0.5 * dt * ((old_qx + q[0]) * gxz + (old_qy + q[1]) * gyz));
      add_point_loads(l, g[i], gradients, i, n, m, q[0], q[1], loads);
      thickness_strain += g[i].det * u.thickness_strain;
      weight += g[i].det;
      failed = failed || u.failed;
      if (!std::isfinite(u.n[0] + u.n[1] + u.n[2] + u.m[0] + u.m[1] + u.m[2] + q[0] + q[1])) result.non_finite = e;
    }
    if (p.thickness_update && dt > 0.0) state.thickness[ue] = t * std::exp(thickness_strain / weight);
    apply_loads(l, b1, b2, tying, loads, table.nodes_of(ue), nodes, recording ? state.records.load_at(ue, 0) : nullptr);
    if (!std::isfinite(work)) result.non_finite = e;
    state.internal_energy[ue] += work;
    result.internal_energy += work;
    close_element(state, result, e, step, failed);
  }
  return result;
}

}  // namespace crumple
