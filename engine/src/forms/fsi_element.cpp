#include "forms/fsi_element.hpp"

#include <cmath>

namespace fsi::forms {

template <class S>
void element_residual(const ElementInput& in, const FsiCoefficients& c,
                      const std::array<S, kMaxLocal>& x, std::array<S, kMaxLocal>& r) {
  const fe::SubElement& e = *in.element;
  const int n = e.vertices;
  for (auto& ri : r) ri = S(0.0);
  const double inv_k = 1.0 / c.k_s;
  const bool solid = e.phase == Phase::solid;
  const double mu_f = c.rho_f * c.nu_f;
  const double stab = c.alpha * std::pow(in.h_patch_m, c.s);

  for (int q = 0; q < in.num_qp; ++q) {
    const fe::QuadraturePoint& qp = in.qp[q];
    const OldValues& old = in.old[q];
    const double w = qp.weight;
    // Values and gradients at the point: v, u, p, G = grad v, H = grad u (G[i][j] = d v_i / d x_j).
    S v[2] = {0.0, 0.0}, u[2] = {0.0, 0.0}, p = 0.0;
    S G[2][2] = {{0.0, 0.0}, {0.0, 0.0}}, H[2][2] = {{0.0, 0.0}, {0.0, 0.0}}, gp[2] = {0.0, 0.0};
    for (int a = 0; a < n; ++a) {
      const double N = qp.value[a], dx = qp.grad[a].x(), dy = qp.grad[a].y();
      for (int i = 0; i < 2; ++i) {
        const S& va = x[5 * a + i];
        const S& ua = x[5 * a + 2 + i];
        v[i] += N * va;
        u[i] += N * ua;
        G[i][0] += dx * va;
        G[i][1] += dy * va;
        H[i][0] += dx * ua;
        H[i][1] += dy * ua;
      }
      p += N * x[5 * a + 4];
      gp[0] += dx * x[5 * a + 4];
      gp[1] += dy * x[5 * a + 4];
    }
    const S wc[2] = {v[0] - old.tx, v[1] - old.ty};  // convective velocity v - d_t T
    const double v_old[2] = {old.vx, old.vy}, u_old[2] = {old.ux, old.uy};

    if (!solid) {
      S acc[2], sigma[2][2];
      for (int i = 0; i < 2; ++i) {
        acc[i] = c.rho_f * ((v[i] - v_old[i]) * inv_k + wc[0] * G[i][0] + wc[1] * G[i][1]);  // (1), (2)
        for (int j = 0; j < 2; ++j) sigma[i][j] = mu_f * (G[i][j] + G[j][i]);              // (3)
        sigma[i][i] -= p;
      }
      S div = G[0][0] + G[1][1];  // (6)
      // Cavitation floor: below p_cav the fluid may expand at a rate set by the deficit,
      // which keeps p from falling far below p_cav (a vapour-pressure-like limit).
      if (c.cavitation_p_pa != 0.0)
        div -= rounded_ramp(c.cavitation_p_pa - p, c.cavitation_smoothing_pa) / mu_f;
      for (int a = 0; a < n; ++a) {
        const double N = qp.value[a], dx = qp.grad[a].x(), dy = qp.grad[a].y();
        for (int i = 0; i < 2; ++i) r[5 * a + i] += w * (acc[i] * N + sigma[i][0] * dx + sigma[i][1] * dy);  // (1)-(3)
        if (!in.u_row_solid[a])
          for (int i = 0; i < 2; ++i)
            r[5 * a + 2 + i] += (w * c.extension_u) * (H[i][0] * dx + H[i][1] * dy);  // (7)
        r[5 * a + 4] += (w * N) * div;                                                // (6)
      }
    } else {
      // F = I - grad u (the inverse of the Lagrangian deformation gradient).
      const S F00 = 1.0 - H[0][0], F01 = -H[0][1], F10 = -H[1][0], F11 = 1.0 - H[1][1];
      const S J = F00 * F11 - F01 * F10;
      const S Fi00 = F11 / J, Fi01 = -F01 / J, Fi10 = -F10 / J, Fi11 = F00 / J;  // F^-1
      // C^-1-type product F^-T F^-1 (symmetric), then Green-Lagrange E.
      const S B00 = Fi00 * Fi00 + Fi10 * Fi10, B01 = Fi00 * Fi01 + Fi10 * Fi11;
      const S B11 = Fi01 * Fi01 + Fi11 * Fi11;
      const S E00 = 0.5 * (B00 - 1.0), E01 = 0.5 * B01, E11 = 0.5 * (B11 - 1.0);
      const S trE = E00 + E11;
      const S S00 = 2.0 * c.mu_s * E00 + c.lambda_s * trE, S01 = 2.0 * c.mu_s * E01;
      const S S11 = 2.0 * c.mu_s * E11 + c.lambda_s * trE;
      // sigma = J F^-1 S F^-T  (10)
      const S A00 = Fi00 * S00 + Fi01 * S01, A01 = Fi00 * S01 + Fi01 * S11;
      const S A10 = Fi10 * S00 + Fi11 * S01, A11 = Fi10 * S01 + Fi11 * S11;
      S sigma[2][2];
      sigma[0][0] = J * (A00 * Fi00 + A01 * Fi01);
      sigma[0][1] = J * (A00 * Fi10 + A01 * Fi11);
      sigma[1][0] = J * (A10 * Fi00 + A11 * Fi01);
      sigma[1][1] = J * (A10 * Fi10 + A11 * Fi11);
      const S rho = c.rho_s0 * J;
      const double g[2] = {c.gx, c.gy};
      S acc[2], du[2];
      for (int i = 0; i < 2; ++i) {
        // Weight rho g, less the displaced fluid's rho_f g with buoyancy (Scenario::buoyancy).
        acc[i] = rho * ((v[i] - v_old[i]) * inv_k + wc[0] * G[i][0] + wc[1] * G[i][1] - g[i]) + c.rho_buoyancy * g[i];  // (8), (9)
        du[i] = (u[i] - u_old[i]) * inv_k + wc[0] * H[i][0] + wc[1] * H[i][1] - v[i];  // (11)
      }
      for (int a = 0; a < n; ++a) {
        const double N = qp.value[a], dx = qp.grad[a].x(), dy = qp.grad[a].y();
        for (int i = 0; i < 2; ++i) {
          r[5 * a + i] += w * (acc[i] * N + sigma[i][0] * dx + sigma[i][1] * dy);  // (8)-(10)
          if (in.u_row_released[a])
            r[5 * a + 2 + i] += (w * c.extension_u) * (H[i][0] * dx + H[i][1] * dy);  // (7)
          else
            r[5 * a + 2 + i] += w * (du[i] * N - stab * (G[i][0] * dx + G[i][1] * dy));  // (11), (12)
        }
        if (!in.p_row_fluid[a]) r[5 * a + 4] += (w * c.extension_p) * (gp[0] * dx + gp[1] * dy);  // (13)
      }
    }
  }

  // Do-nothing correction on open boundaries: (4) - <rho_f nu_f grad v^T n, phi>; and where
  // fluid flows in, the backflow term (5) - <beta rho_f / 2 (v.n)_- v, phi>. Tested with v
  // it adds beta rho_f / 2 |v.n_-| |v|^2 >= 0, which cancels the kinetic energy the
  // convective term lets in through the boundary (it is rho_f / 2 (v.n) |v|^2 there).
  if (!solid)
    for (int s = 0; s < in.num_open_sides; ++s) {
      const OpenBoundarySide& side = in.open_sides[s];
      for (int q = 0; q < 2; ++q) {
        const fe::ShapeValues& sv = side.shape[q];
        S G[2][2] = {{0.0, 0.0}, {0.0, 0.0}}, vb[2] = {0.0, 0.0};
        for (int a = 0; a < n; ++a)
          for (int i = 0; i < 2; ++i) {
            G[i][0] += sv.grad[a].x() * x[5 * a + i];
            G[i][1] += sv.grad[a].y() * x[5 * a + i];
            vb[i] += sv.value[a] * x[5 * a + i];
          }
        // (grad v^T n)_i = sum_j G[j][i] n_j  (4)
        S t[2] = {mu_f * (G[0][0] * side.nx + G[1][0] * side.ny),
                  mu_f * (G[0][1] * side.nx + G[1][1] * side.ny)};
        const S vn = vb[0] * side.nx + vb[1] * side.ny;
        if (c.backflow_beta > 0.0 && value_of(vn) < 0.0)
          for (int i = 0; i < 2; ++i) t[i] += (0.5 * c.backflow_beta * c.rho_f) * vn * vb[i];  // (5)
        for (int a = 0; a < n; ++a)
          for (int i = 0; i < 2; ++i) r[5 * a + i] -= (side.weight[q] * sv.value[a]) * t[i];
      }
    }
}

template void element_residual<double>(const ElementInput&, const FsiCoefficients&,
                                       const std::array<double, kMaxLocal>&,
                                       std::array<double, kMaxLocal>&);
template void element_residual<Jet>(const ElementInput&, const FsiCoefficients&,
                                    const std::array<Jet, kMaxLocal>&, std::array<Jet, kMaxLocal>&);

}  // namespace fsi::forms
