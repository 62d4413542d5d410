// 8-node bricks (docs/theory/brick8.md): exact volume, patch tests on distorted meshes, rigid motions,
// hourglass resistance, bending of the physically stabilised element, uniaxial tension against Johnson-Cook,
// the critical step, and end to end: a wave in a brick bar through run_simulation, a negative volume.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <vector>

#include "crumple/deck/reader.hpp"
#include "crumple/elements/brick8.hpp"
#include "crumple/materials/solid_update.hpp"
#include "crumple/core/geometry.hpp"
#include "crumple/output/run.hpp"
#include "crumple/solver/solver_state.hpp"
#include "deck_files.hpp"

// Its own namespace: the test programs are built in unity batches (cmake/Unity.cmake).
namespace test_brick8 {

using namespace crumple;
using test::I;
using test::R;

namespace {

using Point = std::array<double, 3>;
using Matrix = std::array<std::array<double, 3>, 3>;
using Connectivity = std::array<int, 8>;

constexpr double kE = 210e9, kNu = 0.3, kRho = 7800.0;
// The formulations that pass the patch test on distorted elements (Isolid 2 does on parallelepipeds only).
constexpr int kIsolids[] = {1, 12, 14, 17, 18, 24};

Material elastic_material(double young = kE, double nu = kNu) {
  Material m;
  m.law = MaterialLaw::Elastic;
  m.density = kRho, m.young = young, m.poisson = nu;
  return m;
}

Material johnson_cook_material(double a, double b, double n) {
  Material m = elastic_material();
  m.law = MaterialLaw::JohnsonCook;
  m.johnson_cook.a = a, m.johnson_cook.b = b, m.johnson_cook.n = n;
  return m;
}

double volume_of(const double* x, const double* y, const double* z) {
  double bx[8], by[8], bz[8];
  return geometry::brick_volume_gradient(x, y, z, bx, by, bz);
}

// A group of bricks with its own nodes and state, driven directly through brick8_forces.
class Bricks {
 public:
  Bricks(const std::vector<Point>& coordinates, const std::vector<Connectivity>& elements, int isolid,
         const Material& material)
      : material_(material) {
    nodes.resize(coordinates.size());
    for (std::size_t k = 0; k < coordinates.size(); ++k)
      nodes.x[k] = coordinates[k][0], nodes.y[k] = coordinates[k][1], nodes.z[k] = coordinates[k][2];
    for (std::size_t e = 0; e < elements.size(); ++e) {
      table.user_id.push_back(static_cast<std::int64_t>(e + 1));
      table.part.push_back(0);
      for (int a : elements[e]) table.connectivity.push_back(a);
    }
    const auto n = elements.size();
    group = {ElementKind::Brick8, 0, 0, 0, 0, static_cast<std::int32_t>(n)};
    p.hardening = materials::Hardening::of(material_, functions_);
    p.young = material_.young, p.poisson = material_.poisson, p.density = material_.density;
    brick8_configure(isolid, isolid == 17 ? 1 : 3, p);  // the default Icpre
    const std::size_t points = n * static_cast<std::size_t>(p.points);
    state.resize_points(points);
    state.resize_elements(n);
    for (std::size_t e = 0; e < n; ++e) state.volume0[e] = volume(e);
  }
  Bricks(const Bricks&) = delete;
  Bricks& operator=(const Bricks&) = delete;

  double volume(std::size_t e) const {
    double x[8], y[8], z[8];
    coordinates_of(e, x, y, z);
    return volume_of(x, y, z);
  }
  void coordinates_of(std::size_t e, double* x, double* y, double* z) const {
    const std::int32_t* c = table.nodes_of(e);
    for (int a = 0; a < 8; ++a) {
      const auto k = static_cast<std::size_t>(c[a]);
      x[a] = nodes.x[k], y[a] = nodes.y[k], z[a] = nodes.z[k];
    }
  }
  Point position(std::size_t k) const { return {nodes.x[k], nodes.y[k], nodes.z[k]}; }
  Point force(std::size_t k) const { return {nodes.fx[k], nodes.fy[k], nodes.fz[k]}; }
  std::array<double, 6> stress(std::size_t point) const {
    return {state.sxx[point], state.syy[point], state.szz[point], state.sxy[point], state.syz[point],
            state.szx[point]};
  }
  void set_velocity(std::size_t k, const Point& v) { nodes.vx[k] = v[0], nodes.vy[k] = v[1], nodes.vz[k] = v[2]; }
  // x^n = x^(n-1) + dt v, then the kernel over that step (the order of the time loop).
  GroupStepResult advance(double dt) {
    for (std::size_t k = 0; k < nodes.size(); ++k) {
      nodes.x[k] += dt * nodes.vx[k];
      nodes.y[k] += dt * nodes.vy[k];
      nodes.z[k] += dt * nodes.vz[k];
    }
    return forces(dt);
  }
  GroupStepResult forces(double dt) {
    nodes.clear_forces();
    return brick8_forces(table, group, p, nodes, state, dt);
  }

  ElementTable table = empty_element_tables()[static_cast<std::size_t>(ElementKind::Brick8)];
  ElementGroup group{};
  NodalState nodes;
  BrickState state;
  BrickGroupParameters p;

 private:
  Material material_;
  std::vector<Function> functions_;
};

// Unit-cube corners in brick order (node k + 4 above node k).
constexpr Point kCorners[8] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};

std::vector<Point> box(double lx, double ly, double lz) {
  std::vector<Point> p;
  for (const Point& c : kCorners) p.push_back({lx * (c[0] - 0.5), ly * (c[1] - 0.5), lz * (c[2] - 0.5)});
  return p;
}

// One strongly distorted brick (no two faces parallel).
std::vector<Point> distorted_brick() {
  return {{0.0, 0.0, 0.0},  {1.2, 0.1, -0.1}, {1.0, 0.9, 0.2},  {-0.1, 1.1, 0.05},
          {0.1, -0.2, 1.0}, {1.1, 0.05, 1.3}, {1.3, 1.2, 0.9},  {0.05, 0.8, 1.1}};
}

// The distorted seven-element patch of MacNeal and Harder (1985): a unit cube with an inner brick whose corners
// are at irregular places; six bricks join the inner brick's faces to the cube's faces.
struct Patch {
  std::vector<Point> nodes;
  std::vector<Connectivity> elements;
  std::vector<std::size_t> interior;
};
Patch macneal_harder_patch() {
  Patch p;
  for (const Point& c : kCorners) p.nodes.push_back(c);
  p.nodes.insert(p.nodes.end(), {{0.249, 0.342, 0.192}, {0.826, 0.288, 0.288}, {0.850, 0.649, 0.263},
                                 {0.273, 0.750, 0.230}, {0.320, 0.186, 0.643}, {0.677, 0.305, 0.683},
                                 {0.788, 0.693, 0.644}, {0.165, 0.745, 0.702}});
  p.elements.push_back({8, 9, 10, 11, 12, 13, 14, 15});
  constexpr int faces[6][4] = {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  for (const auto& f : faces) {
    Connectivity c{f[0], f[1], f[2], f[3], f[0] + 8, f[1] + 8, f[2] + 8, f[3] + 8};
    double x[8], y[8], z[8];
    for (int a = 0; a < 8; ++a) {
      const Point& q = p.nodes[static_cast<std::size_t>(c[static_cast<std::size_t>(a)])];
      x[a] = q[0], y[a] = q[1], z[a] = q[2];
    }
    if (volume_of(x, y, z) < 0.0) c = {f[0] + 8, f[1] + 8, f[2] + 8, f[3] + 8, f[0], f[1], f[2], f[3]};
    p.elements.push_back(c);
  }
  for (std::size_t k = 8; k < 16; ++k) p.interior.push_back(k);
  return p;
}

// A 2 x 2 x 2 block of the unit cube with every node moved by up to `amplitude` / 2 (deterministic
// pseudo-random; 0 gives the regular block of cubes).
Patch perturbed_block(double amplitude = 0.2) {
  Patch p;
  unsigned state = 12345u;
  auto jitter = [&]() {
    state = state * 1103515245u + 12345u;
    return amplitude * (static_cast<double>((state >> 8) & 0xffffu) / 65535.0 - 0.5);
  };
  auto id = [](int i, int j, int k) { return i + 3 * j + 9 * k; };
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) p.nodes.push_back({0.5 * i + jitter(), 0.5 * j + jitter(), 0.5 * k + jitter()});
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i)
        p.elements.push_back({id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k), id(i, j, k + 1),
                              id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)});
  p.interior.push_back(static_cast<std::size_t>(id(1, 1, 1)));
  return p;
}

Point mul(const Matrix& m, const Point& x) {
  return {m[0][0] * x[0] + m[0][1] * x[1] + m[0][2] * x[2], m[1][0] * x[0] + m[1][1] * x[1] + m[1][2] * x[2],
          m[2][0] * x[0] + m[2][1] * x[1] + m[2][2] * x[2]};
}
double norm(const Point& p) { return std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]); }

Matrix rotation(Point u, double t) {
  const double n = norm(u);
  for (double& v : u) v /= n;
  const double c = std::cos(t), s = std::sin(t), k = 1.0 - c;
  return {{{c + u[0] * u[0] * k, u[0] * u[1] * k - u[2] * s, u[0] * u[2] * k + u[1] * s},
           {u[1] * u[0] * k + u[2] * s, c + u[1] * u[1] * k, u[1] * u[2] * k - u[0] * s},
           {u[2] * u[0] * k - u[1] * s, u[2] * u[1] * k + u[0] * s, c + u[2] * u[2] * k}}};
}

Matrix inverse(const Matrix& b) {
  const double det = b[0][0] * (b[1][1] * b[2][2] - b[1][2] * b[2][1]) -
                     b[0][1] * (b[1][0] * b[2][2] - b[1][2] * b[2][0]) +
                     b[0][2] * (b[1][0] * b[2][1] - b[1][1] * b[2][0]);
  Matrix inv{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const auto i1 = static_cast<std::size_t>((j + 1) % 3), i2 = static_cast<std::size_t>((j + 2) % 3);
      const auto j1 = static_cast<std::size_t>((i + 1) % 3), j2 = static_cast<std::size_t>((i + 2) % 3);
      inv[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = (b[i1][j1] * b[i2][j2] - b[i1][j2] * b[i2][j1]) / det;
    }
  return inv;
}

// ---------------------------------------------------------------------------------------------------------------
// Geometry

TEST(Brick8, VolumeAndItsGradientAreExact) {
  // A cube, a box, and the distorted brick against a 2x2x2 Gauss integration of det J (exact for a trilinear map).
  double x[8], y[8], z[8];
  const auto fill = [&](const std::vector<Point>& p) {
    for (std::size_t a = 0; a < 8; ++a) x[a] = p[a][0], y[a] = p[a][1], z[a] = p[a][2];
  };
  fill(box(2.0, 3.0, 0.5));
  EXPECT_NEAR(volume_of(x, y, z), 3.0, 1e-14);
  fill(distorted_brick());
  double gauss = 0.0;
  const double g = 1.0 / std::sqrt(3.0);
  for (const Point& c : kCorners) {
    const double r = g * (2 * c[0] - 1), s = g * (2 * c[1] - 1), t = g * (2 * c[2] - 1);
    double j[3][3] = {};
    for (std::size_t a = 0; a < 8; ++a) {
      const double sr = 2 * kCorners[a][0] - 1, ss = 2 * kCorners[a][1] - 1, st = 2 * kCorners[a][2] - 1;
      const double d[3] = {0.125 * sr * (1 + ss * s) * (1 + st * t), 0.125 * ss * (1 + sr * r) * (1 + st * t),
                           0.125 * st * (1 + sr * r) * (1 + ss * s)};
      for (int k = 0; k < 3; ++k) j[0][k] += x[a] * d[k], j[1][k] += y[a] * d[k], j[2][k] += z[a] * d[k];
    }
    gauss += j[0][0] * (j[1][1] * j[2][2] - j[1][2] * j[2][1]) - j[0][1] * (j[1][0] * j[2][2] - j[1][2] * j[2][0]) +
             j[0][2] * (j[1][0] * j[2][1] - j[1][1] * j[2][0]);
  }
  double bx[8], by[8], bz[8];
  const double volume = geometry::brick_volume_gradient(x, y, z, bx, by, bz);
  EXPECT_NEAR(volume, gauss, 1e-14);
  // V is linear in each coordinate of each node: a central difference is exact up to round-off.
  for (std::size_t a = 0; a < 8; ++a) {
    const double h = 1e-3;
    double* coordinate[3] = {&x[a], &y[a], &z[a]};
    const double gradient[3] = {bx[a], by[a], bz[a]};
    for (int k = 0; k < 3; ++k) {
      const double keep = *coordinate[k];
      *coordinate[k] = keep + h;
      const double plus = volume_of(x, y, z);
      *coordinate[k] = keep - h;
      const double minus = volume_of(x, y, z);
      *coordinate[k] = keep;
      EXPECT_NEAR((plus - minus) / (2 * h), gradient[k], 1e-11) << "node " << a << " direction " << k;
    }
  }
}

// ---------------------------------------------------------------------------------------------------------------
// Patch tests: a linear displacement field gives the same strain and stress in every element and point, and no
// force at the interior nodes.

void check_patch(const Patch& patch, int isolid) {
  Bricks b(patch.nodes, patch.elements, isolid, elastic_material());
  const Matrix A = {{{1.0e-3, 2.0e-4, -3.0e-4}, {5.0e-4, -2.0e-3, 1.0e-4}, {-1.0e-4, 3.0e-4, 1.5e-3}}};
  const double dt = 1e-6;
  // Step 1: x -> (I + A) x over dt. On the mid-step geometry (I + A/2) X the velocity A X / dt has the gradient
  // L = A (I + A/2)^-1 / dt, exactly.
  for (std::size_t k = 0; k < b.nodes.size(); ++k) {
    const Point v = mul(A, b.position(k));
    b.set_velocity(k, {v[0] / dt, v[1] / dt, v[2] / dt});
  }
  Matrix half = A;
  for (std::size_t i = 0; i < 3; ++i) {
    for (auto& v : half[i]) v *= 0.5;
    half[i][i] += 1.0;
  }
  const Matrix h_inv = inverse(half);
  Matrix L{};  // times dt
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j)
      for (std::size_t k = 0; k < 3; ++k) L[i][j] += A[i][k] * h_inv[k][j];
  const double e[6] = {L[0][0], L[1][1], L[2][2], L[0][1] + L[1][0], L[1][2] + L[2][1], L[2][0] + L[0][2]};
  const double lambda = kE * kNu / ((1 + kNu) * (1 - 2 * kNu)), mu = kE / (2 * (1 + kNu));
  const double tr = e[0] + e[1] + e[2];
  const double expected[6] = {lambda * tr + 2 * mu * e[0], lambda * tr + 2 * mu * e[1], lambda * tr + 2 * mu * e[2],
                              mu * e[3], mu * e[4], mu * e[5]};
  double scale = 0.0;
  for (double s : expected) scale = std::max(scale, std::abs(s));

  const GroupStepResult r = b.advance(dt);
  EXPECT_EQ(r.inverted, -1);
  const std::size_t points = patch.elements.size() * static_cast<std::size_t>(b.p.points);
  for (std::size_t ip = 0; ip < points; ++ip) {
    const auto s = b.stress(ip);
    for (std::size_t k = 0; k < 6; ++k)
      EXPECT_NEAR(s[k], expected[k], 1e-10 * scale) << "Isolid " << isolid << " point " << ip << " component " << k;
  }
  double largest = 0.0;
  for (std::size_t k = 0; k < b.nodes.size(); ++k) largest = std::max(largest, norm(b.force(k)));
  ASSERT_GT(largest, 0.0);
  for (std::size_t k : patch.interior)
    EXPECT_LT(norm(b.force(k)), 1e-10 * largest) << "Isolid " << isolid << " interior node " << k;

  // Two more increments of the same homogeneous deformation (the stress now rotates and accumulates): still
  // uniform, still no interior force.
  for (int step = 0; step < 2; ++step) {
    for (std::size_t k = 0; k < b.nodes.size(); ++k) {
      const Point v = mul(A, b.position(k));
      b.set_velocity(k, {v[0] / dt, v[1] / dt, v[2] / dt});
    }
    b.advance(dt);
  }
  const auto first = b.stress(0);
  for (std::size_t ip = 1; ip < points; ++ip) {
    const auto s = b.stress(ip);
    for (std::size_t k = 0; k < 6; ++k) EXPECT_NEAR(s[k], first[k], 1e-10 * 3 * scale) << "Isolid " << isolid;
  }
  largest = 0.0;
  for (std::size_t k = 0; k < b.nodes.size(); ++k) largest = std::max(largest, norm(b.force(k)));
  for (std::size_t k : patch.interior) EXPECT_LT(norm(b.force(k)), 1e-10 * largest) << "Isolid " << isolid;
}

TEST(Brick8, PatchTestSingleDistortedBrick) {
  Patch single;
  single.nodes = distorted_brick();
  single.elements = {{0, 1, 2, 3, 4, 5, 6, 7}};
  for (int isolid : kIsolids) check_patch(single, isolid);
}

TEST(Brick8, PatchTestMacNealHarderSevenElements) {
  const Patch patch = macneal_harder_patch();
  for (int isolid : kIsolids) check_patch(patch, isolid);
}

TEST(Brick8, PatchTestRegularBlockOfIsolid2) {
  // Isolid 2's hourglass base vectors are orthogonal to linear fields only on parallelepipeds (eq. B-6a).
  check_patch(perturbed_block(0.0), 2);
}

TEST(Brick8, PatchTestPerturbedBlock) {
  const Patch patch = perturbed_block();
  for (int isolid : kIsolids) check_patch(patch, isolid);
}

// ---------------------------------------------------------------------------------------------------------------
// Degenerate bricks: prisms 1 2 3 3 5 6 7 7 and tetrahedra 1 2 3 3 4 4 4 4 written with repeated nodes

Connectivity tetrahedron(const std::vector<Point>& nodes, int a, int b, int c, int d) {
  Connectivity t{a, b, c, c, d, d, d, d};
  double x[8], y[8], z[8];
  for (std::size_t k = 0; k < 8; ++k) {
    const Point& q = nodes[static_cast<std::size_t>(t[k])];
    x[k] = q[0], y[k] = q[1], z[k] = q[2];
  }
  if (volume_of(x, y, z) < 0.0) t = {b, a, c, c, d, d, d, d};
  return t;
}

// The perturbed block with every brick split into two prisms (through its 1-3 / 5-7 diagonal plane) or six
// tetrahedra around its 1-7 diagonal (the same diagonal direction everywhere: a conforming mesh).
Patch degenerate_block(bool tetrahedra) {
  const Patch block = perturbed_block();
  Patch p;
  p.nodes = block.nodes, p.interior = block.interior;
  for (const Connectivity& h : block.elements) {
    if (!tetrahedra) {
      p.elements.push_back({h[0], h[1], h[2], h[2], h[4], h[5], h[6], h[6]});
      p.elements.push_back({h[0], h[2], h[3], h[3], h[4], h[6], h[7], h[7]});
      continue;
    }
    constexpr int ring[7] = {1, 2, 3, 7, 4, 5, 1};
    for (int k = 0; k < 6; ++k) p.elements.push_back(tetrahedron(p.nodes, h[0], h[ring[k]], h[ring[k + 1]], h[6]));
  }
  return p;
}

TEST(Brick8, DegenerateVolumesAreExact) {
  // Tetrahedron: |det(b - a, c - a, d - a)| / 6. Oblique prism with a triangular base: base area times height.
  const std::vector<Point> tet = {{0.1, 0.2, -0.1}, {1.3, 0.1, 0.2}, {0.2, 0.9, 0.1}, {0.3, 0.4, 1.2}};
  double x[8], y[8], z[8];
  const Connectivity t = tetrahedron(tet, 0, 1, 2, 3);
  for (std::size_t k = 0; k < 8; ++k) {
    const Point& q = tet[static_cast<std::size_t>(t[k])];
    x[k] = q[0], y[k] = q[1], z[k] = q[2];
  }
  Point e[3];
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j) e[i][j] = tet[i + 1][j] - tet[0][j];
  const double det = e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) - e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
                     e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
  EXPECT_NEAR(volume_of(x, y, z), std::abs(det) / 6.0, 1e-14);
  const Point base[3] = {{0.0, 0.0, 0.0}, {2.0, 0.0, 0.0}, {0.5, 1.5, 0.0}}, shift{0.3, -0.2, 0.7};
  const int prism[8] = {0, 1, 2, 2, 3, 4, 5, 5};
  for (std::size_t k = 0; k < 8; ++k) {
    const int n = prism[k];
    const Point& q = base[n % 3];
    const double top = n >= 3 ? 1.0 : 0.0;
    x[k] = q[0] + top * shift[0], y[k] = q[1] + top * shift[1], z[k] = q[2] + top * shift[2];
  }
  EXPECT_NEAR(volume_of(x, y, z), 0.5 * 2.0 * 1.5 * 0.7, 1e-14);
}

TEST(Brick8, PatchTestDegeneratePrismsAndTetrahedra) {
  for (bool tetrahedra : {false, true}) {
    const Patch patch = degenerate_block(tetrahedra);
    for (int isolid : kIsolids) check_patch(patch, isolid);
  }
}

TEST(Brick8, DegenerateTetrahedronHasNoHourglassForce) {
  // A tetrahedron is a linear element: every nodal velocity field is linear, so the orthogonalised hourglass rates
  // vanish and Isolid 1's viscous forces and Isolid 24's stabilisation stay zero for any motion.
  const std::vector<Point> tet = {{0.1, 0.2, -0.1}, {1.3, 0.1, 0.2}, {0.2, 0.9, 0.1}, {0.3, 0.4, 1.2}};
  for (int isolid : {1, 24}) {
    Bricks b(tet, {tetrahedron(tet, 0, 1, 2, 3)}, isolid, elastic_material());
    const Point v[4] = {{1.0, -2.0, 0.5}, {-0.3, 0.8, 1.1}, {0.2, 0.1, -0.9}, {0.7, -0.4, 0.3}};
    for (std::size_t k = 0; k < 4; ++k) b.set_velocity(k, v[k]);
    const GroupStepResult r = b.advance(1e-7);
    ASSERT_GT(r.internal_energy, 0.0);
    double stored = 0.0;  // Isolid 24's generalized hourglass stresses [F]
    for (int k = 0; k < 12; ++k) stored = std::max(stored, std::abs(b.state.hourglass[static_cast<std::size_t>(k)]));
    EXPECT_LT(std::abs(r.hourglass_energy), 1e-12 * r.internal_energy) << isolid;
    EXPECT_LT(stored, 1e-12 * kE * 1e-6) << isolid;  // a strain of 1e-6 on a unit area
  }
}

// ---------------------------------------------------------------------------------------------------------------
// Small strain (Ismstr, eq. B-14)

// Stretches a unit cube (nu = 0) along x to 1 + total in `steps` equal increments; returns s_xx.
double stretched_stress(bool small_strain, double total, int steps) {
  std::vector<Point> corners(kCorners, kCorners + 8);
  Bricks b(corners, {{0, 1, 2, 3, 4, 5, 6, 7}}, 1, elastic_material(kE, 0.0));
  if (small_strain) brick8_switch_to_small_strain(b.table, 0, b.nodes, b.state);
  const double dt = 1e-6, rate = total / steps / dt;
  for (int step = 0; step < steps; ++step) {
    for (std::size_t k = 0; k < 8; ++k) b.set_velocity(k, {rate * kCorners[k][0], 0.0, 0.0});
    b.advance(dt);
  }
  return b.stress(0)[0];
}

TEST(Brick8, SmallStrainComputesEngineeringStrainOnTheReferenceShape) {
  // 10 % stretch: on the frozen reference shape the strain increments add up to the engineering strain 0.1;
  // on the current geometry (large strain) to the logarithmic strain ln 1.1 (eq. B-14).
  EXPECT_NEAR(stretched_stress(true, 0.1, 200), kE * 0.1, 1e-9 * kE);
  EXPECT_NEAR(stretched_stress(false, 0.1, 200), kE * std::log(1.1), 1e-5 * kE);
}

TEST(Brick8, SwitchToSmallStrainFreezesTheStepAndStaysObjective) {
  // A cube crushed to half its height (no bulk viscosity, so that the step is the geometric one): with large
  // strain its critical step L / c falls to 0.5 / sqrt(0.5) of the initial one (L halves, the density doubles);
  // it stays at the value of the switch once brick8_switch_to_small_strain has frozen the shape. A rigid rotation
  // after the switch rotates the stress and changes nothing else (the frozen shape turns with the element frame
  // and the frame's rigid turn is taken out of the velocities).
  for (bool switched : {false, true}) {
    std::vector<Point> corners(kCorners, kCorners + 8);
    Bricks b(corners, {{0, 1, 2, 3, 4, 5, 6, 7}}, 1, elastic_material(kE, 0.0));
    b.p.qa = b.p.qb = 0.0;
    const double dt = 1e-6;
    b.forces(0.0);
    const double initial_step = b.state.critical_dt[0];
    if (switched) brick8_switch_to_small_strain(b.table, 0, b.nodes, b.state);
    EXPECT_EQ(b.state.small_strain[0], switched ? 1 : 0);
    for (int step = 0; step < 100; ++step) {
      for (std::size_t k = 0; k < 8; ++k) b.set_velocity(k, {0.0, 0.0, -0.005 * kCorners[k][2] / dt});
      b.advance(dt);
    }
    const double ratio = b.state.critical_dt[0] / initial_step;
    if (switched)
      EXPECT_NEAR(ratio, 1.0, 1e-12);
    else
      EXPECT_NEAR(ratio, 0.5 / std::sqrt(0.5), 1e-6);
    if (!switched) continue;
    const auto before = b.stress(0);
    const Matrix rot = rotation({0.2, 1.0, -0.4}, 0.3);
    for (std::size_t k = 0; k < 8; ++k) {
      const Point x = b.position(k), y = mul(rot, x);
      b.set_velocity(k, {(y[0] - x[0]) / dt, (y[1] - x[1]) / dt, (y[2] - x[2]) / dt});
    }
    b.advance(dt);
    const auto after = b.stress(0);
    // s_zz alone before; after: R s R^T, so the trace and the z-z projection on the rotated axis are kept.
    EXPECT_NEAR(after[0] + after[1] + after[2], before[2], 1e-9 * std::abs(before[2]));
    const Point axis = mul(rot, {0.0, 0.0, 1.0});
    const double projected = after[0] * axis[0] * axis[0] + after[1] * axis[1] * axis[1] + after[2] * axis[2] * axis[2] +
                             2.0 * (after[3] * axis[0] * axis[1] + after[4] * axis[1] * axis[2] + after[5] * axis[2] * axis[0]);
    EXPECT_NEAR(projected, before[2], 1e-9 * std::abs(before[2]));
    EXPECT_LT(before[2], 0.0);
  }
}

// ---------------------------------------------------------------------------------------------------------------
// Rigid motions

TEST(Brick8, RigidTranslationAndRotationGiveNoForce) {
  const double reference_force = kE * 1e-3 * 1.0;  // a strain of 1e-3 on a unit face
  for (int isolid : kIsolids) {
    Bricks b(distorted_brick(), {{0, 1, 2, 3, 4, 5, 6, 7}}, isolid, elastic_material());
    const double dt = 1e-4;  // rotation speed 4000 rad/s below: the round-off of the velocities stays small
    for (std::size_t k = 0; k < 8; ++k) b.set_velocity(k, {30.0, -20.0, 10.0});
    b.advance(dt);
    for (std::size_t k = 0; k < 8; ++k) EXPECT_LT(norm(b.force(k)), 1e-12 * reference_force) << isolid;
    // Finite rotation increments of 0.4 rad about a skew axis: v = (R x - x) / dt.
    const Matrix rot = rotation({1.0, 2.0, -0.5}, 0.4);
    for (int step = 0; step < 3; ++step) {
      for (std::size_t k = 0; k < 8; ++k) {
        const Point x = b.position(k), y = mul(rot, x);
        b.set_velocity(k, {(y[0] - x[0]) / dt, (y[1] - x[1]) / dt, (y[2] - x[2]) / dt});
      }
      const GroupStepResult r = b.advance(dt);
      for (std::size_t k = 0; k < 8; ++k) EXPECT_LT(norm(b.force(k)), 1e-12 * reference_force) << isolid;
      EXPECT_LT(std::abs(r.internal_energy), 1e-20 * reference_force);
      EXPECT_LT(std::abs(r.hourglass_energy), 1e-20 * reference_force);
    }
  }
}

TEST(Brick8, RigidRotationRotatesStressAndForces) {
  // Load the element (stress and, for Isolid 24, hourglass stresses), then rotate it rigidly by 0.5 rad in one
  // step: the stress must become R s R^T and every nodal force R f (objectivity, eq. B-3 and SU-2).
  for (int isolid : kIsolids) {
    Bricks b(distorted_brick(), {{0, 1, 2, 3, 4, 5, 6, 7}}, isolid, elastic_material());
    const double dt = 1e-6;
    const Matrix A = {{{1.0e-3, 2.0e-4, 0.0}, {-1.0e-4, -5.0e-4, 3.0e-4}, {2.0e-4, 0.0, 8.0e-4}}};
    constexpr double hourglass[8] = {1, -1, 1, -1, -1, 1, -1, 1};
    for (std::size_t k = 0; k < 8; ++k) {
      const Point v = mul(A, b.position(k));
      b.set_velocity(k, {v[0] / dt, v[1] / dt + 2e-4 * hourglass[k] / dt, v[2] / dt});
    }
    b.advance(dt);
    for (std::size_t k = 0; k < 8; ++k) b.set_velocity(k, {0.0, 0.0, 0.0});
    b.forces(0.0);  // forces of the loaded state, nothing updated
    std::vector<Point> before;
    for (std::size_t k = 0; k < 8; ++k) before.push_back(b.force(k));
    std::vector<std::array<double, 6>> stress_before;
    for (std::size_t ip = 0; ip < static_cast<std::size_t>(b.p.points); ++ip) stress_before.push_back(b.stress(ip));

    const Matrix rot = rotation({0.3, -1.0, 0.7}, 0.5);
    for (std::size_t k = 0; k < 8; ++k) {
      const Point x = b.position(k), y = mul(rot, x);
      b.set_velocity(k, {(y[0] - x[0]) / dt, (y[1] - x[1]) / dt, (y[2] - x[2]) / dt});
    }
    b.advance(dt);
    double largest = 0.0;
    for (const Point& f : before) largest = std::max(largest, norm(f));
    ASSERT_GT(largest, 0.0);
    for (std::size_t k = 0; k < 8; ++k) {
      const Point expected = mul(rot, before[k]), f = b.force(k);
      for (std::size_t i = 0; i < 3; ++i) EXPECT_NEAR(f[i], expected[i], 1e-10 * largest) << isolid << " node " << k;
    }
    for (std::size_t ip = 0; ip < stress_before.size(); ++ip) {
      const auto& s = stress_before[ip];
      const Matrix S = {{{s[0], s[3], s[5]}, {s[3], s[1], s[4]}, {s[5], s[4], s[2]}}};
      Matrix RS{}, RSR{};
      for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j)
          for (std::size_t k = 0; k < 3; ++k) RS[i][j] += rot[i][k] * S[k][j];
      for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j)
          for (std::size_t k = 0; k < 3; ++k) RSR[i][j] += RS[i][k] * rot[j][k];
      const auto now = b.stress(ip);
      const double scale = std::abs(materials::von_mises(s.data())) + std::abs(s[0] + s[1] + s[2]);
      EXPECT_NEAR(now[0], RSR[0][0], 1e-10 * scale);
      EXPECT_NEAR(now[1], RSR[1][1], 1e-10 * scale);
      EXPECT_NEAR(now[2], RSR[2][2], 1e-10 * scale);
      EXPECT_NEAR(now[3], RSR[0][1], 1e-10 * scale);
      EXPECT_NEAR(now[4], RSR[1][2], 1e-10 * scale);
      EXPECT_NEAR(now[5], RSR[2][0], 1e-10 * scale);
    }
  }
}

// ---------------------------------------------------------------------------------------------------------------
// Hourglass modes

constexpr double kHourglass[4][8] = {{1, 1, -1, -1, -1, -1, 1, 1},
                                     {1, -1, -1, 1, -1, 1, 1, -1},
                                     {1, -1, 1, -1, 1, -1, 1, -1},
                                     {-1, 1, -1, 1, 1, -1, 1, -1}};

TEST(Brick8, ViscousHourglassOfIsolid1) {
  // A cube of side 0.01 with the velocity h_alpha in direction i: the one-point strain is zero, the force on
  // node I is -Q gamma_I with Q = h rho c V^(2/3) / 4 q, q = gamma . v = 8 (eq. B-5, B-6).
  const double side = 0.01, dt = 1e-9;
  const double c = std::sqrt(kE * (1 - kNu) / ((1 + kNu) * (1 - 2 * kNu)) / kRho);
  const double coefficient = 0.25 * 0.1 * kRho * c * side * side;
  for (int mode = 0; mode < 4; ++mode)
    for (std::size_t dir = 0; dir < 3; ++dir) {
      Bricks b(box(side, side, side), {{0, 1, 2, 3, 4, 5, 6, 7}}, 1, elastic_material());
      b.p.hourglass = 0.1;
      for (std::size_t k = 0; k < 8; ++k) {
        Point v{0, 0, 0};
        v[dir] = kHourglass[mode][k];
        b.set_velocity(k, v);
      }
      const GroupStepResult r = b.advance(dt);
      double power = 0.0;
      for (std::size_t k = 0; k < 8; ++k) {
        const Point f = b.force(k);
        EXPECT_NEAR(f[dir], -8.0 * coefficient * kHourglass[mode][k], 1e-6 * 8.0 * coefficient);
        power += f[dir] * kHourglass[mode][k];
      }
      EXPECT_LT(power, 0.0);  // resists the motion
      EXPECT_NEAR(r.hourglass_energy, 64.0 * coefficient * dt, 1e-6 * 64.0 * coefficient * dt);
    }
}

TEST(Brick8, PlainViscousHourglassOfIsolid2) {
  // Isolid 2 (Hallquist): the hourglass rates are h . v with the base vectors themselves (eq. B-6a). On a
  // parallelepiped h is orthogonal to every linear field, as gamma is, and Isolid 2 gives Isolid 1's forces; on a
  // distorted brick a linear velocity field (here a rigid rotation rate) has h . v != 0 and meets viscous forces
  // that Isolid 1's orthogonalised gamma does not produce.
  const double dt = 1e-4, reference_force = kE * 1e-3 * 1.0;  // as in RigidTranslationAndRotationGiveNoForce
  const Matrix rot = rotation({1.0, 2.0, -0.5}, 0.01);            // 100 rad/s
  for (bool distorted : {false, true}) {
    double largest[2] = {};
    for (int which = 0; which < 2; ++which) {
      Bricks b(distorted ? distorted_brick() : box(1.0, 2.0, 0.5), {{0, 1, 2, 3, 4, 5, 6, 7}}, which == 0 ? 1 : 2,
               elastic_material());
      for (std::size_t k = 0; k < 8; ++k) {
        const Point x = b.position(k), y = mul(rot, x);
        b.set_velocity(k, {(y[0] - x[0]) / dt, (y[1] - x[1]) / dt, (y[2] - x[2]) / dt});
      }
      b.advance(dt);
      for (std::size_t k = 0; k < 8; ++k) largest[which] = std::max(largest[which], norm(b.force(k)));
    }
    EXPECT_LT(largest[0], 1e-12 * reference_force);
    if (distorted)
      EXPECT_GT(largest[1], 1e-3 * reference_force);
    else
      EXPECT_LT(largest[1], 1e-12 * reference_force);
  }
  // Pure hourglass velocity on a cube: gamma = h there, so Isolid 2's force equals Isolid 1's.
  for (int mode = 0; mode < 4; ++mode) {
    Point f[2];
    for (int which = 0; which < 2; ++which) {
      Bricks b(box(0.01, 0.01, 0.01), {{0, 1, 2, 3, 4, 5, 6, 7}}, which == 0 ? 1 : 2, elastic_material());
      for (std::size_t k = 0; k < 8; ++k) b.set_velocity(k, {kHourglass[mode][k], 0.0, 0.0});
      b.forces(1e-9);
      f[which] = b.force(0);
    }
    EXPECT_NEAR(f[1][0], f[0][0], 1e-12 * std::abs(f[0][0])) << "mode " << mode;
    EXPECT_LT(f[0][0] * kHourglass[mode][0], 0.0);
  }
}

TEST(Brick8, HourglassModesAreResistedByTheStiffFormulations) {
  // An hourglass displacement of amplitude d: the nodal forces oppose it (f . u < 0) and the element stores
  // energy. For Isolid 24 and a cube of half-width a the twisting-type mode (mode k along axis k) stores
  // (V/3) G d^2 / a^2 (eq. B-9).
  const double side = 0.01, a = 0.5 * side, dt = 1e-6, d = 1e-7;
  const double G = kE / (2 * (1 + kNu)), V = side * side * side;
  for (int isolid : {24, 12, 14, 17, 18})
    for (int mode = 0; mode < 4; ++mode)
      for (std::size_t dir = 0; dir < 3; ++dir) {
        Bricks b(box(side, side, side), {{0, 1, 2, 3, 4, 5, 6, 7}}, isolid, elastic_material());
        for (std::size_t k = 0; k < 8; ++k) {
          Point v{0, 0, 0};
          v[dir] = d * kHourglass[mode][k] / dt;
          b.set_velocity(k, v);
        }
        const GroupStepResult r = b.advance(dt);
        double work = 0.0;
        for (std::size_t k = 0; k < 8; ++k) work += b.force(k)[dir] * d * kHourglass[mode][k];
        EXPECT_LT(work, 0.0) << "Isolid " << isolid << " mode " << mode << " direction " << dir;
        const double stored = r.internal_energy + r.hourglass_energy;
        EXPECT_GT(stored, 0.0);
        // Linear spring: energy = -f . u / 2 (the stress work is taken on the mid-step geometry: O(d / side)).
        EXPECT_NEAR(-0.5 * work, stored, 1e-4 * stored);
        if (isolid == 24 && mode < 3 && static_cast<std::size_t>(mode) == dir) {
          // Elastic strain energy of the assumed-strain field: internal energy, no hourglass (dissipated) energy.
          EXPECT_NEAR(r.internal_energy, V / 3.0 * G * d * d / (a * a), 1e-6 * r.internal_energy);
          EXPECT_EQ(r.hourglass_energy, 0.0);
        }
      }
}

TEST(Brick8, StabilisedAndAssumedShearBricksBendWithoutShearLocking) {
  // One thin brick (1 x 1 x 0.1, nu = 0) bent by u_x = k x z, in any orientation (the element frame of eq. B-8).
  // The one-point strain is zero and the assumed-strain stabilisation of Isolid 24 (eq. B-9) stores exactly the
  // Euler-Bernoulli energy E I k^2 L / 2, as internal energy. Isolid 14's assumed shears (eq. B-10a) remove the
  // parasitic shear G (k x)^2 and store the same energy; the plain 2x2x2 element keeps it and is about 50 times
  // stiffer here.
  const double young = 2e11, curvature = 1e-4, dt = 1e-6;
  const double beam = 0.5 * young * (1.0 * 0.1 * 0.1 * 0.1 / 12.0) * curvature * curvature * 1.0;
  const Matrix identity = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  for (const Matrix& orientation : {identity, rotation({1.0, 2.0, 3.0}, 0.7)}) {
    double energy[3];
    for (int variant = 0; variant < 3; ++variant) {
      std::vector<Point> corners;
      for (const Point& x : box(1.0, 1.0, 0.1)) corners.push_back(mul(orientation, x));
      Bricks b(corners, {{0, 1, 2, 3, 4, 5, 6, 7}}, variant == 0 ? 24 : 14, elastic_material(young, 0.0));
      b.p.assumed_shear = variant == 1;
      for (std::size_t k = 0; k < 8; ++k) {
        Point local{};  // R^T x
        const Point g = b.position(k);
        for (std::size_t i = 0; i < 3; ++i)
          local[i] = orientation[0][i] * g[0] + orientation[1][i] * g[1] + orientation[2][i] * g[2];
        const Point u = mul(orientation, {curvature * local[0] * local[2], 0.0, 0.0});
        b.set_velocity(k, {u[0] / dt, u[1] / dt, u[2] / dt});
      }
      const GroupStepResult r = b.advance(dt);
      EXPECT_EQ(r.hourglass_energy, 0.0);
      energy[variant] = r.internal_energy;
    }
    EXPECT_NEAR(energy[0], beam, 1e-6 * beam);
    EXPECT_NEAR(energy[1], beam, 1e-6 * beam);
    EXPECT_GT(energy[2], 10.0 * beam);
  }
}

// Energy of the bending field u_x = k x z on a unit cube, shear modulus fixed, for Poisson ratio nu.
double cube_bending_energy(int isolid, bool constant_pressure, double nu) {
  const double shear = 8e10, curvature = 1e-4, dt = 1e-6;
  Bricks b(box(1.0, 1.0, 1.0), {{0, 1, 2, 3, 4, 5, 6, 7}}, isolid, elastic_material(2 * shear * (1 + nu), nu));
  b.p.constant_pressure = constant_pressure;
  for (std::size_t k = 0; k < 8; ++k) {
    const Point x = b.position(k);
    b.set_velocity(k, {curvature * x[0] * x[2] / dt, 0.0, 0.0});
  }
  const GroupStepResult r = b.advance(dt);
  return r.internal_energy + r.hourglass_energy;
}

TEST(Brick8, ConstantPressureRemovesVolumetricLocking) {
  // nu from 0.3 to 0.4999 multiplies the bulk modulus by 800. With Icpre 1 (constant pressure: deviatoric
  // stabilisation for Isolid 24, eq. B-9a; mean dilatation for Isolid 14, eq. B-10) the bending energy changes by
  // less than a factor 2. With Icpre 3 the hourglass strains (24) or the Gauss-point dilatations (14) meet the
  // bulk modulus and the energy grows by more than 100.
  for (int isolid : {24, 14, 17, 18}) {
    const double free_0 = cube_bending_energy(isolid, true, 0.3), free_1 = cube_bending_energy(isolid, true, 0.4999);
    EXPECT_GT(free_0, 0.0);
    EXPECT_LT(free_1, 2.0 * free_0) << "Isolid " << isolid;
    const double locked_0 = cube_bending_energy(isolid, false, 0.3);
    const double locked_1 = cube_bending_energy(isolid, false, 0.4999);
    EXPECT_GT(locked_1, 100.0 * locked_0) << "Isolid " << isolid;
  }
}

// ---------------------------------------------------------------------------------------------------------------
// Uniaxial tension of one element against Johnson-Cook

TEST(Brick8, UniaxialTensionFollowsJohnsonCook) {
  // A unit cube pulled along x at a constant true strain rate with its lateral faces free: the lateral velocity
  // is found every increment by a secant iteration on s_yy = 0. Then s_xx must follow
  // sigma_y = a + b eps_p^n with eps_p = ln(L / L0) - s_xx / E (0.5 %).
  const double a = 250e6, b_hard = 600e6, n_hard = 0.35;
  for (int isolid : kIsolids) {
    std::vector<Point> corners(kCorners, kCorners + 8);
    Bricks b(corners, {{0, 1, 2, 3, 4, 5, 6, 7}}, isolid, johnson_cook_material(a, b_hard, n_hard));
    const double dt = 1e-5, rate = 100.0;  // 1e-3 true strain per increment
    const auto hardening = b.p.hardening;
    double lateral = -kNu * rate;
    double worst = 0.0;
    for (int step = 0; step < 300; ++step) {
      const NodalState start = b.nodes;
      const BrickState saved = b.state;
      auto attempt = [&](double lateral_rate) {
        b.nodes = start;
        b.state = saved;
        for (std::size_t k = 0; k < 8; ++k) {
          const Point x = b.position(k);
          b.set_velocity(k, {rate * x[0], lateral_rate * x[1], lateral_rate * x[2]});
        }
        b.advance(dt);
        return b.state.syy[0];
      };
      double x0 = lateral, f0 = attempt(x0);
      double x1 = lateral * 0.999 - 1e-3 * rate, f1 = attempt(x1);
      for (int it = 0; it < 30 && std::abs(f1) > 1e-3 && f1 != f0; ++it) {
        const double x2 = x1 - f1 * (x1 - x0) / (f1 - f0);
        x0 = x1, f0 = f1;
        x1 = x2, f1 = attempt(x1);
      }
      lateral = x1;
      const std::size_t points = static_cast<std::size_t>(b.p.points);
      for (std::size_t ip = 0; ip < points; ++ip) {
        ASSERT_LT(std::abs(b.state.syy[ip]), 1.0) << isolid;
        ASSERT_LT(std::abs(b.state.szz[ip]), 1.0) << isolid;
      }
      const double length = b.nodes.x[1] - b.nodes.x[0];
      const double sxx = b.state.sxx[0];
      const double eps_p = std::log(length) - sxx / kE;
      if (eps_p > 1e-3) {
        const double jc = hardening.yield(eps_p, 0.0);
        worst = std::max(worst, std::abs(sxx - jc) / jc);
      }
    }
    EXPECT_LT(worst, 0.005) << "Isolid " << isolid;
    EXPECT_GT(b.nodes.x[1] - b.nodes.x[0], 1.3);
  }
}

// ---------------------------------------------------------------------------------------------------------------
// Critical step, inversion

TEST(Brick8, CriticalStepIsLengthOverDilatationalSpeed) {
  const double lx = 0.02, ly = 0.01, lz = 0.005;
  const double c = std::sqrt(kE * (1 - kNu) / ((1 + kNu) * (1 - 2 * kNu)) / kRho);
  for (int isolid : kIsolids) {
    Bricks b(box(lx, ly, lz), {{0, 1, 2, 3, 4, 5, 6, 7}}, isolid, elastic_material());
    GroupStepResult r = b.forces(0.0);
    // L = V / largest face = lz; at rest the linear bulk viscosity's speed Q = qb c bounds the step too, as in the
    // reference (eq. B-12): L / (Q + sqrt(Q^2 + c^2)) = L / c / (qb + sqrt(1 + qb^2)).
    const double at_rest = lz / c / (0.05 + std::sqrt(1.0 + 0.05 * 0.05));
    EXPECT_NEAR(r.min_dt, at_rest, 1e-12 * at_rest);
    EXPECT_EQ(r.controlling, 0);
    // Uniform compression at rate d: Q = qb c + qa^2 L |d|, step L / (Q + sqrt(Q^2 + c^2)) (eq. B-12).
    const double rate = -200.0, dt = 1e-9;
    for (std::size_t k = 0; k < 8; ++k) {
      const Point x = b.position(k);
      b.set_velocity(k, {rate * x[0], rate * x[1], rate * x[2]});
    }
    r = b.advance(dt);
    double x[8], y[8], z[8];
    b.coordinates_of(0, x, y, z);
    const double volume = volume_of(x, y, z);
    const double rho = kRho * lx * ly * lz / volume;
    const double c_now = std::sqrt(kE * (1 - kNu) / ((1 + kNu) * (1 - 2 * kNu)) / rho);
    const double length = volume / (x[1] - x[0]) / (y[3] - y[0]);
    // v = d x^(n-1) seen on the mid-step geometry x^(n-1) (1 + d dt / 2): a rate d / (1 + d dt / 2) per direction.
    const double dv = 3.0 * rate / (1.0 + 0.5 * rate * dt);
    const double Q = 0.05 * c_now + 1.1 * 1.1 * length * std::abs(dv);
    EXPECT_NEAR(r.min_dt, length / (Q + std::sqrt(Q * Q + c_now * c_now)), 1e-9 * r.min_dt) << isolid;
  }
}

// Highest natural frequency of a free mesh with its lumped mass (rho V / 8 per element node), from the stiffness
// probed column by column through the kernel (a displacement d e_j over a long step, so that velocities and the
// viscosities are negligible) and a power iteration on M^-1/2 K M^-1/2.
double highest_frequency(const Patch& mesh, int isolid, double nu) {
  const double d = 1e-9, dt = 1.0;
  const std::size_t n = 3 * mesh.nodes.size();
  std::vector<double> k(n * n, 0.0), mass(mesh.nodes.size(), 0.0);
  {
    Bricks b(mesh.nodes, mesh.elements, isolid, elastic_material(kE, nu));
    for (std::size_t e = 0; e < mesh.elements.size(); ++e)
      for (int a : mesh.elements[e]) mass[static_cast<std::size_t>(a)] += kRho * b.volume(e) / 8.0;
  }
  for (std::size_t j = 0; j < n; ++j) {
    Bricks b(mesh.nodes, mesh.elements, isolid, elastic_material(kE, nu));
    Point v{0, 0, 0};
    v[j % 3] = d / dt;
    b.set_velocity(j / 3, v);
    b.advance(dt);
    for (std::size_t i = 0; i < n; ++i) k[i * n + j] = -b.force(i / 3)[i % 3] / d;
  }
  std::vector<double> a(n * n);  // symmetric part of M^-1/2 K M^-1/2
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j)
      a[i * n + j] = 0.5 * (k[i * n + j] + k[j * n + i]) / std::sqrt(mass[i / 3] * mass[j / 3]);
  std::vector<double> x(n), y(n);
  for (std::size_t i = 0; i < n; ++i) x[i] = 1.0 + 0.1 * static_cast<double>(i % 7) - 0.05 * static_cast<double>(i % 3);
  double lambda = 0.0;
  for (int it = 0; it < 2000; ++it) {
    double norm2 = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      double sum = 0.0;
      for (std::size_t j = 0; j < n; ++j) sum += a[i * n + j] * x[j];
      y[i] = sum;
      norm2 += sum * sum;
    }
    lambda = std::sqrt(norm2);
    for (std::size_t i = 0; i < n; ++i) x[i] = y[i] / lambda;
  }
  return std::sqrt(lambda);
}

// A regular block of nx x ny x nz bricks of size hx x hy x hz.
Patch block(int nx, int ny, int nz, double hx, double hy, double hz) {
  Patch p;
  auto id = [&](int i, int j, int k) { return i + (nx + 1) * (j + (ny + 1) * k); };
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) p.nodes.push_back({hx * i, hy * j, hz * k});
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        p.elements.push_back({id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k), id(i, j, k + 1),
                              id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)});
  return p;
}

TEST(Brick8, CriticalStepAgainstTheStabilityLimit) {
  // The central difference scheme is stable for dt <= 2 / omega_max. The estimate L / c (eq. B-12) is exact for
  // nu = 0 on regular meshes and below the limit on distorted ones. For nu > 0 the uniform dilatation of an element
  // whose nodes are free to follow it (a single element, the corners of a free block) runs faster than the
  // dilatational wave: at most by sqrt(3K / (lambda + 2G)) = sqrt((1 + nu) / (1 - nu)), the single cube's factor
  // (the element eigenvalue bound). brick8.md, "Critical step", discusses what that means for the scale factor.
  std::vector<Patch> meshes;
  Patch single;
  single.elements = {{0, 1, 2, 3, 4, 5, 6, 7}};
  for (const auto& shape : {box(1.0, 1.0, 1.0), box(1.0, 1.0, 0.1), box(1.0, 0.1, 0.1), distorted_brick()}) {
    single.nodes = shape;
    meshes.push_back(single);
  }
  meshes.push_back(block(2, 2, 2, 1.0, 1.0, 1.0));
  meshes.push_back(perturbed_block());
  meshes.push_back(macneal_harder_patch());
  for (double nu : {0.0, 0.3, 0.49})
    for (std::size_t m = 0; m < meshes.size(); ++m) {
      Bricks b(meshes[m].nodes, meshes[m].elements, 24, elastic_material(kE, nu));
      // L / c: the step at rest is L / c / (qb + sqrt(1 + qb^2)), the linear bulk viscosity's share (eq. B-12).
      const double estimate = b.forces(0.0).min_dt * (0.05 + std::sqrt(1.0 + 0.05 * 0.05));
      const double limit = 2.0 / highest_frequency(meshes[m], 24, nu);
      const double breathing = std::sqrt((1.0 + nu) / (1.0 - nu));
      EXPECT_LE(estimate, limit * breathing * (1.0 + 1e-5)) << "nu " << nu << " mesh " << m;
      if (nu == 0.0) {
        EXPECT_LE(estimate, limit * (1.0 + 1e-5)) << "mesh " << m;
      }
      if (m == 0) {  // the single cube reaches the bound
        EXPECT_NEAR(estimate / limit, breathing, 1e-5 * breathing);
      }
      if (m == 4 && nu <= 0.3) {  // a free 2 x 2 x 2 block: the default scale 0.9 holds
        EXPECT_LT(0.9 * estimate, limit);
      }
    }
}

// The corner element of a cube mapped onto a ball by shells (r = max(|u|, |v|, |w|) onto the sphere of radius r):
// seven of its eight nodes lie on the outer sphere, so the element is flat-ish and its hourglass vectors are long.
std::vector<Point> ball_corner_brick() {
  auto on_ball = [](double u, double v, double w) -> Point {
    const double r = std::max({u, v, w}), a = u / r, b = v / r, c = w / r;
    return {r * a * std::sqrt(1.0 - b * b / 2.0 - c * c / 2.0 + b * b * c * c / 3.0),
            r * b * std::sqrt(1.0 - c * c / 2.0 - a * a / 2.0 + c * c * a * a / 3.0),
            r * c * std::sqrt(1.0 - a * a / 2.0 - b * b / 2.0 + a * a * b * b / 3.0)};
  };
  std::vector<Point> p;
  const double h = 1.0 / 16.0;
  for (const Point& c : kCorners) p.push_back(on_ball(1.0 - h + h * c[0], 1.0 - h + h * c[1], 1.0 - h + h * c[2]));
  return p;
}

TEST(Brick8, CriticalStepHoldsTheViscousDampersStable) {
  // Isolid 1's hourglass forces are a damper F = -C v on modes without stiffness. Central differences integrate a
  // damper on a mass stably only for dt <= 2 / lambda_max(M^-1 C) (eq. B-13). C is probed column by column with a
  // velocity over a vanishing step (so that no strain accumulates), without bulk viscosity (whose linear part B-12
  // covers in compression). A cube is far from the bound; on the flat corner element of a mapped ball, L / c alone
  // (eq. B-12) overshoots it by 8 % (a 16^3 ball blew up in hourglass modes once its contact let go).
  for (const auto& shape : {box(1.0, 1.0, 1.0), ball_corner_brick()}) {
    Bricks probe(shape, {{0, 1, 2, 3, 4, 5, 6, 7}}, 1, elastic_material());
    const double estimate = probe.forces(0.0).min_dt;
    const double mass = kRho * probe.volume(0) / 8.0, dt = 1e-14, v = 1e-3;
    constexpr std::size_t n = 24;
    std::vector<double> damping(n * n);
    for (std::size_t j = 0; j < n; ++j) {
      Bricks b(shape, {{0, 1, 2, 3, 4, 5, 6, 7}}, 1, elastic_material());
      b.p.qb = 0.0;
      Point velocity{0, 0, 0};
      velocity[j % 3] = v;
      b.set_velocity(j / 3, velocity);
      b.advance(dt);
      for (std::size_t i = 0; i < n; ++i) damping[i * n + j] = -b.force(i / 3)[i % 3] / v / mass;
    }
    std::vector<double> x(n, 1.0), y(n);
    for (std::size_t i = 0; i < n; ++i) x[i] += 0.1 * static_cast<double>(i % 5);
    double lambda = 0.0;
    for (int it = 0; it < 3000; ++it) {
      double norm2 = 0.0;
      for (std::size_t i = 0; i < n; ++i) {
        double sum = 0.0;
        for (std::size_t j = 0; j < n; ++j) sum += 0.5 * (damping[i * n + j] + damping[j * n + i]) * x[j];
        y[i] = sum, norm2 += sum * sum;
      }
      lambda = std::sqrt(norm2);
      for (std::size_t i = 0; i < n; ++i) x[i] = y[i] / lambda;
    }
    EXPECT_LE(estimate, 2.0 / lambda) << "lambda " << lambda;
  }
}

TEST(Brick8, InvertedElementIsReported) {
  for (int isolid : kIsolids) {
    std::vector<Point> p = box(1.0, 1.0, 1.0);
    Bricks b(p, {{0, 1, 2, 3, 4, 5, 6, 7}}, isolid, elastic_material());
    for (std::size_t k = 4; k < 8; ++k) b.nodes.z[k] -= 1.5;  // top face below the bottom face
    EXPECT_EQ(b.forces(0.0).inverted, 0) << isolid;
  }
}

TEST(Brick8, NonFiniteForcesAreReported) {
  for (int isolid : kIsolids) {
    Bricks b(box(1.0, 1.0, 1.0), {{0, 1, 2, 3, 4, 5, 6, 7}}, isolid, elastic_material());
    b.state.sxx[0] = std::nan("");
    EXPECT_EQ(b.forces(0.0).non_finite, 0) << isolid;
  }
}

// ---------------------------------------------------------------------------------------------------------------
// End to end through the deck reader and run_simulation

// Bar of n x 1 x 1 bricks of side h along x; node (i, j, k) has id 1 + 4 i + j + 2 k. Part 1, /PROP/SOLID 1 with
// `isolid`, /MAT/ELAST 1. Nodes at x = 0 in group 10, at x = L in group 20.
std::string bar_starter(int n, double h, int isolid, double young, double nu, const std::string& extra) {
  std::string s = test::begin_card("WAVE") + "/NODE\n";
  for (int i = 0; i <= n; ++i)
    for (int k = 0; k < 2; ++k)
      for (int j = 0; j < 2; ++j) s += I(1 + 4 * i + j + 2 * k) + R(h * i) + R(h * j) + R(h * k) + "\n";
  s += "/BRICK/1\n";
  auto id = [](int i, int j, int k) { return 1 + 4 * i + j + 2 * k; };
  for (int i = 0; i < n; ++i)  // (y, z, x) is right-handed: nodes 1-4 on the face x_i, 5-8 on x_(i+1)
    s += I(i + 1) + I(id(i, 0, 0)) + I(id(i, 1, 0)) + I(id(i, 1, 1)) + I(id(i, 0, 1)) + I(id(i + 1, 0, 0)) +
         I(id(i + 1, 1, 0)) + I(id(i + 1, 1, 1)) + I(id(i + 1, 0, 1)) + "\n";
  s += "/PART/1\nbar\n" + I(1) + I(1) + "\n";
  s += "/PROP/SOLID/1\nsolid\n" + I(isolid) + I(isolid == 18 ? 4 : 0) + I(0) + I(isolid == 18 ? 3 : 0) + "\n" + R(0.0) + R(0.0) + R(0.0) +
       "\n";  // Isolid 18 needs its Ismstr and Icpre given
  s += "/MAT/ELAST/1\nsteel\n" + R(kRho) + "\n" + R(young) + R(nu) + "\n";
  s += "/GRNOD/NODE/10\nleft\n" + I(id(0, 0, 0)) + I(id(0, 1, 0)) + I(id(0, 0, 1)) + I(id(0, 1, 1)) + "\n";
  s += "/GRNOD/NODE/20\nright\n" + I(id(n, 0, 0)) + I(id(n, 1, 0)) + I(id(n, 0, 1)) + I(id(n, 1, 1)) + "\n";
  return s + extra + "/END\n";
}

// A unit cube of 7800 kg/m^3 written as one prism 1 2 3 3 5 6 7 7 (corners 1 2 3 | 5 6 7, half the cube) and three
// tetrahedra 1 2 3 3 4 4 4 4 filling the other half (1 3 4 | 5 7 8): (1 3 4 5), (3 4 5 7), (4 8 5 7). The reader
// accepts them. One-point bricks integrate a tetrahedron over 8 det J(0), 3/4 of its volume, as the reference (eq.
// B-2b, its starter listing's mass); the prism over all of it; fully integrated bricks integrate all of every shape.
TEST(Brick8, DegenerateBricksReadWithTheReferenceMass) {
  for (int isolid : {1, 14}) {
    std::string s = test::begin_card("DEGEN") + "/NODE\n";
    for (int k = 0; k < 8; ++k) s += I(k + 1) + R(kCorners[k][0]) + R(kCorners[k][1]) + R(kCorners[k][2]) + "\n";
    s += "/BRICK/1\n" + I(1) + I(1) + I(2) + I(3) + I(3) + I(5) + I(6) + I(7) + I(7) + "\n";
    s += I(2) + I(1) + I(3) + I(4) + I(4) + I(5) + I(5) + I(5) + I(5) + "\n";
    s += I(3) + I(3) + I(4) + I(5) + I(5) + I(7) + I(7) + I(7) + I(7) + "\n";
    s += I(4) + I(4) + I(8) + I(5) + I(5) + I(7) + I(7) + I(7) + I(7) + "\n";
    s += "/PART/1\ncube\n" + I(1) + I(1) + "\n/PROP/SOLID/1\nsolid\n" + I(isolid) + "\n" + R(0.0) + R(0.0) + R(0.0) + "\n";
    s += "/MAT/ELAST/1\nsteel\n" + R(kRho) + "\n" + R(kE) + R(kNu) + "\n/END\n";
    test::TempDir dir;
    const Model m = read_deck(dir.write("DEGEN_0000.rad", s)).model;
    ASSERT_EQ(m.elements[static_cast<int>(ElementKind::Brick8)].size(), 4u);
    const double tetra = isolid == 1 ? 0.75 : 1.0;  // the share of a tetrahedron's volume the element integrates
    EXPECT_NEAR(m.element_mass, kRho * (0.5 + 0.5 * tetra), 1e-12 * kRho) << "Isolid " << isolid;
    double nodal = 0.0;
    for (double v : m.nodal_mass) nodal += v;
    EXPECT_NEAR(nodal, m.element_mass, 1e-12 * kRho);
    // Each connectivity slot carries 1/8 of its element's mass (as the reference lumps degenerate bricks): node 5
    // holds 4/8 of the tetrahedron having it four times.
    EXPECT_NEAR(m.nodal_mass[static_cast<std::size_t>(m.index.nodes.at(5))],
                kRho * (0.5 / 8.0 + tetra * (1.0 / 6.0) * (4.0 / 8.0 + 2.0 / 8.0 + 2.0 / 8.0)), 1e-12 * kRho);
  }
}

std::string bar_engine(double end_time, double history) {
  std::ostringstream e;
  e.precision(10);
  e << "/RUN/WAVE/1\n" << end_time << "\n/TFILE\n" << history << "\n/ANIM/DT\n0 1\n/PRINT/-1000\n/DT\n0.9 0\n";
  return e.str();
}

TEST(Brick8, WaveCrossesABarAtTheDilatationalSpeed) {
  // A 150 x 1 x 1 bar of 10 mm bricks (L = 1.5 m), E = 210 GPa, rho = 7800, nu = 0: c = sqrt(E / rho). The left end
  // gets the velocity pulse v0 sin^2(pi t / Tp) for t < Tp (then it is free); the pulse reflects at the free right
  // end, where the velocity doubles. The right end's velocity is the incident pulse delayed by L / c (and doubled),
  // so the centroid of its history is at L / c + Tp / 2. The run stops at L / c + 1.5 Tp, when the reflected pulse
  // travels back through the bar and has not reached the left end yet.
  //
  // Energy: with velocities at half steps the balance carries an error of order (omega dt)^2 / 4 for a wave of
  // frequency omega (kinetic energy of v^(n+1/2) against strain energy at x^n); Tp = 150 us is 90 steps, so the
  // error stays far below 0.1 % (a 20 us pulse, 12 steps, shows 1.8 %).
  const int n = 150;
  const double h = 0.01, young = 210e9, length = n * h;
  const double c = std::sqrt(young / kRho), arrival = length / c;
  const double pulse = 150e-6, v0 = 1.0, pi = 3.14159265358979323846;
  std::string funct = "/FUNCT/1\nsine squared\n";
  for (int k = 0; k <= 60; ++k) {
    const double t = pulse * k / 60.0, s = std::sin(pi * t / pulse);
    funct += R(t) + R(s * s) + "\n";
  }
  funct += R(1.0) + R(0.0) + "\n";
  const std::string impvel = "/IMPVEL/1\npulse\n" + I(1) + "         X" + I(0) + I(0) + I(10) + I(0) + I(0) + "\n" +
                             R(1.0) + R(v0) + R(0.0) + R(pulse) + "\n";
  for (int isolid : kIsolids) {
    test::TempDir dir;
    dir.write("WAVE_0001.rad", bar_engine(arrival + 1.5 * pulse, 1e-9));  // history (observer) every cycle
    const auto starter = dir.write("WAVE_0000.rad", bar_starter(n, h, isolid, young, 0.0, funct + impvel));
    const Model model = read_deck(starter).model;
    const auto& right = model.node_groups[static_cast<std::size_t>(model.index.node_groups.at(20))].nodes;
    std::vector<double> times, speeds;  // time t^(n+1) and right-end velocity v^(n+1/2)
    SimulationOptions options;
    options.output_directory = dir.path();
    options.write_results = false;
    options.on_history_row = [&](const SolverState& s) {
      double v = 0.0;
      for (std::int32_t node : right) v += s.nodes.vx[static_cast<std::size_t>(node)];
      times.push_back(s.time);
      speeds.push_back(v / static_cast<double>(right.size()));
    };
    std::ostringstream console;
    const RunSummary summary = run_simulation(model, options, console);
    ASSERT_EQ(summary.status, RunStatus::Normal) << summary.message;
    ASSERT_GT(times.size(), 200u);
    // v^(n+1/2) holds over [t^n, t^(n+1)]: its centroid contribution sits at the middle of the step.
    double moment = 0.0, area = 0.0, peak = 0.0;
    for (std::size_t k = 1; k < times.size(); ++k) {
      const double dt = times[k] - times[k - 1];
      moment += (times[k] - 0.5 * dt) * speeds[k] * dt;
      area += speeds[k] * dt;
      peak = std::max(peak, speeds[k]);
    }
    const double measured = moment / area - 0.5 * pulse;
    EXPECT_NEAR(measured, arrival, 0.02 * arrival) << "Isolid " << isolid;
    EXPECT_NEAR(peak, 2.0 * v0, 0.05 * v0) << "Isolid " << isolid;  // free end: the velocity doubles
    // Work of the imposed velocity: rho c A int v^2 dt = rho c A v0^2 3 Tp / 8 (A = h^2).
    const double injected = kRho * c * h * h * v0 * v0 * 3.0 * pulse / 8.0;
    EXPECT_NEAR(summary.energy.external_work, injected, 0.01 * injected) << "Isolid " << isolid;
    EXPECT_LT(std::abs(summary.energy.error_percent), 0.1) << "Isolid " << isolid;
    std::cout << "[ Isolid " << isolid << " ] arrival " << measured << " s, L/c " << arrival << " s, peak " << peak
              << " m/s, energy error " << summary.energy.error_percent << " %, " << summary.cycles << " cycles\n";
  }
}

TEST(Brick8, NegativeVolumeStopsTheRun) {
  // Two bricks clamped at the right end, the left face driven into them at 2000 m/s: an element inverts within a
  // few microseconds.
  const std::string funct = "/FUNCT/1\nconstant\n" + R(0.0) + R(1.0) + "\n" + R(1.0) + R(1.0) + "\n";
  const std::string impvel = "/IMPVEL/1\ncrush\n" + I(1) + "         X" + I(0) + I(0) + I(10) + I(0) + I(0) + "\n" +
                             R(1.0) + R(2000.0) + R(0.0) + R(0.0) + "\n";
  const std::string clamp = "/BCS/1\nclamp\n   111 000" + I(0) + I(20) + "\n";
  for (int isolid : kIsolids) {
    test::TempDir dir;
    dir.write("WAVE_0001.rad", bar_engine(1e-3, 1e-3));
    const auto starter = dir.write("WAVE_0000.rad", bar_starter(2, 0.01, isolid, 210e9, 0.3, funct + impvel + clamp));
    const Model model = read_deck(starter).model;
    std::ostringstream console;
    SimulationOptions options;
    options.output_directory = dir.path();
    options.write_results = false;
    const RunSummary summary = run_simulation(model, options, console);
    EXPECT_EQ(summary.status, RunStatus::Error) << "Isolid " << isolid;
    EXPECT_NE(summary.message.find("BRICK "), std::string::npos) << summary.message;
    EXPECT_NE(summary.message.find("of part 1 "), std::string::npos) << summary.message;
    EXPECT_NE(summary.message.find("negative volume"), std::string::npos) << summary.message;
  }
}

}  // namespace

// Isolid 18 takes its Icpre from the law, as the reference resolves it: 2 (the plasticity-following share, eq. B-9c)
// with a plastic law, 3 with an elastic one; Isolid 14 keeps a given 2.
TEST(Brick8, Isolid18ResolvesIcpreFromTheLaw) {
  auto icpre_of = [](int isolid, int icpre, const std::string& material) {
    std::string s = test::begin_card("ICPRE") + "/NODE\n";
    for (int k = 0; k < 8; ++k) s += I(k + 1) + R(kCorners[k][0]) + R(kCorners[k][1]) + R(kCorners[k][2]) + "\n";
    s += "/BRICK/1\n" + I(1) + I(1) + I(2) + I(3) + I(4) + I(5) + I(6) + I(7) + I(8) + "\n";
    s += "/PART/1\ncube\n" + I(1) + I(1) + "\n/PROP/SOLID/1\nsolid\n" + I(isolid) + I(0) + I(0) + I(icpre) + "\n" +
         R(0.0) + R(0.0) + R(0.0) + "\n" + material + "/END\n";
    test::TempDir dir;
    const Model m = read_deck(dir.write("ICPRE_0000.rad", s)).model;
    return m.formulations.at(0).icpre;
  };
  const std::string elastic = "/MAT/ELAST/1\nsteel\n" + R(kRho) + "\n" + R(kE) + R(kNu) + "\n";
  const std::string plastic =
      "/MAT/PLAS_JOHNS/1\nsteel\n" + R(kRho) + "\n" + R(kE) + R(kNu) + "\n" + R(3e8) + R(5e8) + R(0.3) + "\n";
  EXPECT_EQ(icpre_of(18, 0, plastic), 2);
  EXPECT_EQ(icpre_of(18, 0, elastic), 3);
  EXPECT_EQ(icpre_of(14, 2, plastic), 2);
  EXPECT_EQ(icpre_of(14, 0, plastic), 3);
}

}  // namespace test_brick8
