#pragma once
// Physical hourglass stabilisation of the one-point 4-node shell, Ishell 24 (docs/theory/shell4.md, "Physical
// stabilisation", eqs. S-10 to S-14). Plain functions over one element's local data, used by the shell kernel.
namespace crumple::shell_hourglass {

// H_ij = integral over the element of h_,i h_,j with h = xi eta the bilinear mode (eq. S-10), from the Jacobian at
// the centre: H = (A / 3) (grad xi grad xi^T + grad eta grad eta^T), exact for parallelograms.
// lx, ly: local node coordinates (counter-clockwise, nodes at xi, eta = (-1,-1), (1,-1), (1,1), (-1,1)).
// Returns H_xx, H_yy, H_xy [-].
struct ShapeTensor {
  double xx, yy, xy;
};
inline ShapeTensor shape_tensor(const double lx[4], const double ly[4], double area) {
  // Jacobian d(x, y)/d(xi, eta) at the centre.
  const double x_xi = 0.25 * (-lx[0] + lx[1] + lx[2] - lx[3]), x_eta = 0.25 * (-lx[0] - lx[1] + lx[2] + lx[3]);
  const double y_xi = 0.25 * (-ly[0] + ly[1] + ly[2] - ly[3]), y_eta = 0.25 * (-ly[0] - ly[1] + ly[2] + ly[3]);
  const double det = x_xi * y_eta - x_eta * y_xi;
  // Rows of the inverse Jacobian: grad xi = (y_eta, -x_eta) / det, grad eta = (-y_xi, x_xi) / det.
  const double xi_x = y_eta / det, xi_y = -x_eta / det, eta_x = -y_xi / det, eta_y = x_xi / det;
  const double c = area / 3.0;
  return {c * (xi_x * xi_x + eta_x * eta_x), c * (xi_y * xi_y + eta_y * eta_y), c * (xi_x * xi_y + eta_x * eta_y)};
}

// Moments of the hourglass vector against the quadratic fields x^2, y^2, x y at the nodes (eq. S-13).
struct QuadraticMoments {
  double xx, yy, xy;
};
inline QuadraticMoments quadratic_moments(const double gamma[4], const double lx[4], const double ly[4]) {
  QuadraticMoments g{0.0, 0.0, 0.0};
  for (int a = 0; a < 4; ++a) {
    g.xx += gamma[a] * lx[a] * lx[a];
    g.yy += gamma[a] * ly[a] * ly[a];
    g.xy += gamma[a] * lx[a] * ly[a];
  }
  return g;
}

// Coefficients of the nodal rotations in the transverse-shear hourglass rate (eq. S-13):
// q_s = sum_a gamma_a vz_a + sum_a (cx_a tx_a + cy_a ty_a), removing the bilinear part of w that the rotations'
// linear (Kirchhoff) field explains, so that twisting and bending a thin plate leave the shear mode at rest.
inline void shear_rotation_coefficients(const QuadraticMoments& g, const double b1[4], const double b2[4], double cx[4],
                                        double cy[4]) {
  for (int a = 0; a < 4; ++a) {
    cx[a] = -0.5 * (g.yy * b2[a] + g.xy * b1[a]);
    cy[a] = 0.5 * (g.xx * b1[a] + g.xy * b2[a]);
  }
}

}  // namespace crumple::shell_hourglass
