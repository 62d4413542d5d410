#include "crumple/elements/critical_step.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "crumple/core/geometry.hpp"
#include "crumple/elements/beam.hpp"
#include "crumple/elements/spring.hpp"
#include "crumple/elements/truss.hpp"

namespace crumple {

double initial_element_time_step(const Model& model, ElementKind kind, std::size_t element) {
  const ElementTable& table = model.elements[static_cast<int>(kind)];
  const Part& part = model.parts[static_cast<std::size_t>(table.part[element])];
  const Property& property = model.properties[static_cast<std::size_t>(part.property)];
  // Springs carry their law in the property (mat_ID 0): only the shells' and the bricks' cases read a material.
  const auto material = [&]() -> const Material& { return model.materials[static_cast<std::size_t>(part.material)]; };
  const std::int32_t* n = table.nodes_of(element);
  const Nodes& x = model.nodes;
  switch (kind) {
    case ElementKind::Shell4:
    case ElementKind::Shell3: {
      const Material& mat = material();
      // T-1a's speed (the plate's for QBAT); the length of T-1 (QBAT, triangles), T-1b (Ishell 1 to 4) or T-1d
      // (QEPH); the factor of T-1c for the formulation's damping.
      const auto q = static_cast<std::size_t>(part.property);
      const ResolvedFormulation& f = model.formulations[q];
      const bool triangle = kind == ElementKind::Shell3;
      const double speed = shell_step_wave_speed(mat.young, mat.poisson, mat.density,
                                                 shell_step_at_plate_speed(mat.law, !triangle && f.ishell == 12));
      const Vec3 a = x.position(n[0]), b = x.position(n[1]), c = x.position(n[2]);
      const double length = triangle           ? geometry::triangle_characteristic_length(a, b, c)
                            : f.ishell == 24 ? geometry::qeph_length(a, b, c, x.position(n[3]))
                            : f.ishell == 12 ? geometry::quad_characteristic_length(a, b, c, x.position(n[3]))
                                             : geometry::belytschko_tsay_length(a, b, c, x.position(n[3]));
      return length * damped_step_factor(shell_damping(triangle, model.properties[q].shell, f).step) / speed;
    }
    case ElementKind::Brick8: {
      // eq. B-12 at rest: the linear bulk viscosity's speed qb c lowers the step, L / (qb c + sqrt((qb c)^2 + c^2))
      const Material& mat = material();
      const double qb = model.properties[static_cast<std::size_t>(part.property)].solid.qb_or_default();
      const double speed = std::sqrt((mat.bulk_modulus() + 4.0 / 3.0 * mat.shear_modulus()) / mat.density) *
                           (qb + std::sqrt(1.0 + qb * qb));
      std::array<Vec3, 8> p;
      for (int a = 0; a < 8; ++a) p[static_cast<std::size_t>(a)] = x.position(n[a]);
      if (fully_integrated_brick(model.formulations[static_cast<std::size_t>(part.property)].isolid) &&
          geometry::repeats_a_node(n)) {  // B-12a
        double px[8], py[8], pz[8];
        for (std::size_t a = 0; a < 8; ++a) px[a] = p[a].x, py[a] = p[a].y, pz[a] = p[a].z;
        return geometry::full_integration_length(px, py, pz, geometry::smallest_point_jacobian(px, py, pz)) / speed;
      }
      return geometry::brick_characteristic_length(p) / speed;
    }
    case ElementKind::Spring:
      return spring_critical_step(spring_parameters(property.spring, model.functions), norm(x.position(n[1]) - x.position(n[0])));
    case ElementKind::Truss:
      return truss_critical_step(truss_parameters(material(), property.truss, model.functions),
                                 norm(x.position(n[1]) - x.position(n[0])));
    case ElementKind::Beam:
      return beam_critical_step(beam_parameters(material(), property.beam, model.functions),
                                norm(x.position(n[1]) - x.position(n[0])));
  }
  return 0.0;
}

NodalStiffnessFactor nodal_stiffness_factor(ElementKind kind, int ishell, double poisson) {
  const double plate = 1.0 / (1.0 - poisson * poisson);  // A11 / E
  switch (kind) {
    case ElementKind::Brick8: return {0.25, 0.25};             // 2 (m_e / 8) / dt_e^2
    case ElementKind::Spring: return {1.0, 1.0};               // K at each node: M / dt_e^2 (eq. SP-4a)
    case ElementKind::Truss: return {1.0, 1.0};                // E A / L at each node (eq. TR-6)
    case ElementKind::Beam: return {1.0, 1.0};                 // E A / L at each node, as a truss (BM-8)
    case ElementKind::Shell3: return {0.6561 * plate, plate};  // 0.6561 V A11 / L^2; V A11 / L^2
    case ElementKind::Shell4:
      if (ishell == 24) return {0.5 * plate, 0.5 * plate};               // (1/2) V A11 / L^2, QEPH
      if (ishell == 12) return {2.0 / 3.0, 0.0, NodalLength::QbatAsQeph};  // (2/3) V A11 / L^2 on its step; T-2b
      return {0.405, 0.0, NodalLength::BelytschkoTsay};  // Ishell 1 to 4: 0.81 (1/2) V E / L^2; T-2a
  }
  return {};
}

double mass_scaling_nodal_length(NodalLength length, const ShellSection& section, const Vec3& p1, const Vec3& p2,
                                 const Vec3& p3, const Vec3& p4) {
  // T-2b: the QEPH's length, sqrt(15/16) and the damping factor of QBAT's own dn (measured: dn 0.001 to 0.1)
  if (length == NodalLength::QbatAsQeph)
    return std::sqrt(15.0 / 16.0) * damped_step_factor(qbat_numerical_damping(section)) *
           geometry::qeph_length(p1, p2, p3, p4);
  return geometry::belytschko_tsay_nodal_length(p1, p2, p3, p4);  // T-2a
}

double initial_element_nodal_step(const Model& model, ElementKind kind, std::size_t element) {
  const ElementTable& table = model.elements[static_cast<int>(kind)];
  const Part& part = model.parts[static_cast<std::size_t>(table.part[element])];
  const double poisson = part.material >= 0 ? model.materials[static_cast<std::size_t>(part.material)].poisson : 0.0;
  const NodalStiffnessFactor f =
      nodal_stiffness_factor(kind, model.formulations[static_cast<std::size_t>(part.property)].ishell, poisson);
  const double n = nodes_per_element(kind);
  // T-2a, T-2b: sqrt(2 (rho V / 4) / ((1/2) V A11 / L^2)) = L sqrt(rho / A11)
  if (f.mass_scaling_length != NodalLength::CriticalStep) {
    const Material& mat = model.materials[static_cast<std::size_t>(part.material)];
    const std::int32_t* c = table.nodes_of(element);
    const Nodes& x = model.nodes;
    return mass_scaling_nodal_length(f.mass_scaling_length, model.properties[static_cast<std::size_t>(part.property)].shell,
                                     x.position(c[0]), x.position(c[1]), x.position(c[2]), x.position(c[3])) /
           shell_step_wave_speed(mat.young, mat.poisson, mat.density, true);
  }
  return initial_element_time_step(model, kind, element) * std::sqrt(2.0 / (n * f.mass_scaling));
}

ControllingElement smallest_element_time_step(const Model& model) {
  ControllingElement best;
  double smallest = std::numeric_limits<double>::infinity();
  for (const ElementGroup& g : model.element_groups)
    for (std::int32_t e = g.begin; e < g.end; ++e) {
      const double dt = initial_element_time_step(model, g.kind, static_cast<std::size_t>(e));
      if (dt < smallest) {
        smallest = dt;
        const ElementTable& table = model.elements[static_cast<int>(g.kind)];
        best = {dt, g.kind, table.user_id[static_cast<std::size_t>(e)],
                model.parts[static_cast<std::size_t>(g.part)].user_id};
      }
    }
  return best;
}

}  // namespace crumple
