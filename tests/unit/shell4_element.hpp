#pragma once
// Test support for the 4-node shell kernels: one element driven by prescribed nodal velocities over one step from a
// stress-free state, so that its nodal forces are its tangent stiffness times the increment; eigenvalues of small
// symmetric matrices; rigid motions.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "crumple/elements/shell4.hpp"
#include "crumple/materials/hardening.hpp"

namespace crumple::test {
inline constexpr double kE = 2.0e11, kNu = 0.3, kRho = 7800.0;

// One 4-node element, elastic, N = 0 (resultants) or 1..10 points through the thickness.
struct Element {
  ElementTable table;
  ElementGroup group{ElementKind::Shell4, 0, 0, 0, 0, 1};
  NodalState nodes;
  ShellState state;
  ShellGroupParameters p;
  Material material;
  std::vector<Function> functions;
  double zeta[11], wn[11], wb[11];

  Element(const std::array<std::array<double, 3>, 4>& x, double thickness, int n_points) {
    table.kind = ElementKind::Shell4;
    table.user_id = {1};
    table.part = {0};
    table.connectivity = {0, 1, 2, 3};
    nodes.resize(4);
    for (std::size_t k = 0; k < 4; ++k) nodes.x[k] = x[k][0], nodes.y[k] = x[k][1], nodes.z[k] = x[k][2];
    material.law = MaterialLaw::Elastic, material.young = kE, material.poisson = kNu, material.density = kRho;
    p.hardening = materials::Hardening::of(material, functions);
    p.young = kE, p.poisson = kNu, p.density = kRho;
    p.fully_integrated = true;
    p.numerical_damping = 0.0;  // stiffness alone
    p.resultant_plasticity = n_points == 0;
    p.points = std::max(n_points, 1);
    through_thickness_rule(p.points, zeta, wn, wb);
    p.zeta = zeta, p.membrane_weight = wn, p.bending_weight = wb;
    state.resize_elements(1, thickness);
    state.resize_points(4 * static_cast<std::size_t>(p.points));
    state.gauss_shear.assign(8, 0.0);
    state.gauss_bending.assign(12, 0.0);
    state.initial_shape.assign(8, 0.0);
  }
  // The one-point kernel instead, with the hourglass treatment of Ishell 1, 2 or 3 (defaults of setup_shells).
  void one_point(int ishell) {
    p.fully_integrated = false;
    p.orthogonal_hourglass = ishell != 2;
    p.elastoplastic_hourglass = ishell == 3;
    p.hm = p.hf = ishell == 3 ? 0.1 : 0.01;
    p.hr = 0.01;
    state.resize_points(static_cast<std::size_t>(p.points));
    state.bending_stress.assign(3, 0.0);
  }
  // Nodal forces and moments (24 values, node by node: f then m) for the 24 velocities u over dt, from rest.
  std::array<double, 24> response(const std::array<double, 24>& u, double dt) {
    Element copy = *this;
    for (std::size_t k = 0; k < 4; ++k) {
      copy.nodes.vx[k] = u[6 * k], copy.nodes.vy[k] = u[6 * k + 1], copy.nodes.vz[k] = u[6 * k + 2];
      copy.nodes.wx[k] = u[6 * k + 3], copy.nodes.wy[k] = u[6 * k + 4], copy.nodes.wz[k] = u[6 * k + 5];
    }
    copy.p.zeta = copy.zeta, copy.p.membrane_weight = copy.wn, copy.p.bending_weight = copy.wb;
    last = shell4_forces(copy.table, copy.group, copy.p, copy.nodes, copy.state, dt);
    std::array<double, 24> f{};
    for (std::size_t k = 0; k < 4; ++k) {
      f[6 * k] = -copy.nodes.fx[k], f[6 * k + 1] = -copy.nodes.fy[k], f[6 * k + 2] = -copy.nodes.fz[k];
      f[6 * k + 3] = -copy.nodes.mx[k], f[6 * k + 4] = -copy.nodes.my[k], f[6 * k + 5] = -copy.nodes.mz[k];
    }
    return f;
  }
  // Tangent stiffness K (column j: forces for a unit increment of dof j).
  std::vector<double> stiffness() {
    std::vector<double> k(24 * 24);
    for (std::size_t j = 0; j < 24; ++j) {
      std::array<double, 24> u{};
      u[j] = 1.0;
      const auto f = response(u, 1.0);
      for (std::size_t i = 0; i < 24; ++i) k[24 * i + j] = f[i];
    }
    return k;
  }
  GroupStepResult last;
};

// Symmetric Jacobi eigenvalues of an n x n matrix (row-major), ascending.
inline std::vector<double> eigenvalues(std::vector<double> a, std::size_t n) {
  for (int sweep = 0; sweep < 100; ++sweep) {
    double off = 0.0;
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j) off += a[n * i + j] * a[n * i + j];
    if (off < 1e-30) break;
    for (std::size_t p = 0; p < n; ++p)
      for (std::size_t q = p + 1; q < n; ++q) {
        if (std::abs(a[n * p + q]) < 1e-300) continue;
        const double theta = 0.5 * (a[n * q + q] - a[n * p + p]) / a[n * p + q];
        const double t = (theta >= 0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
        const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
        for (std::size_t k = 0; k < n; ++k) {
          const double akp = a[n * k + p], akq = a[n * k + q];
          a[n * k + p] = c * akp - s * akq, a[n * k + q] = s * akp + c * akq;
        }
        for (std::size_t k = 0; k < n; ++k) {
          const double apk = a[n * p + k], aqk = a[n * q + k];
          a[n * p + k] = c * apk - s * aqk, a[n * q + k] = s * apk + c * aqk;
        }
      }
  }
  std::vector<double> d(n);
  for (std::size_t i = 0; i < n; ++i) d[i] = a[n * i + i];
  std::sort(d.begin(), d.end());
  return d;
}

inline const std::array<std::array<double, 3>, 4> kDistorted{{{0.0, 0.0, 0.0}, {0.24, 0.02, 0.0}, {0.2, 0.15, 0.0}, {-0.03, 0.11, 0.0}}};
// A warped element: the corners alternately 6 mm above and below the mean plane.
inline const std::array<std::array<double, 3>, 4> kWarped{{{0.0, 0.0, 0.006}, {0.24, 0.02, -0.006}, {0.2, 0.15, 0.006}, {-0.03, 0.11, -0.006}}};

inline std::array<double, 24> rigid_motion(const Element& el, const double (&v0)[3], const double (&w)[3]) {
  std::array<double, 24> u{};
  for (std::size_t k = 0; k < 4; ++k) {
    const double r[3] = {el.nodes.x[k], el.nodes.y[k], el.nodes.z[k]};
    u[6 * k] = v0[0] + w[1] * r[2] - w[2] * r[1];
    u[6 * k + 1] = v0[1] + w[2] * r[0] - w[0] * r[2];
    u[6 * k + 2] = v0[2] + w[0] * r[1] - w[1] * r[0];
    u[6 * k + 3] = w[0], u[6 * k + 4] = w[1], u[6 * k + 5] = w[2];
  }
  return u;
}


}  // namespace crumple::test
