#include "forms/fluid_element_jacobian.hpp"

#include <algorithm>

namespace fsi::forms {
namespace {
/// d/dx of rounded_ramp(x, w): 0 below -w/2, 1 above w/2, linear in between.
double rounded_ramp_slope(double x, double w) {
  if (x <= -0.5 * w) return 0.0;
  if (x >= 0.5 * w) return 1.0;
  return (x + 0.5 * w) / w;
}
}  // namespace

void fluid_element_jacobian(const ElementInput& in, const FsiCoefficients& c,
                            const std::array<double, kMaxLocal>& x, ElementMatrix& k) {
  const fe::SubElement& e = *in.element;
  const int n = e.vertices;
  const int nl = 5 * n;
  for (int l = 0; l < nl; ++l) std::fill(k[l].begin(), k[l].begin() + nl, 0.0);
  const double inv_k = 1.0 / c.k_s;
  const double mu_f = c.rho_f * c.nu_f;

  for (int q = 0; q < in.num_qp; ++q) {
    const fe::QuadraturePoint& qp = in.qp[q];
    const OldValues& old = in.old[q];
    const double w = qp.weight;
    double v[2] = {0.0, 0.0}, p = 0.0, G[2][2] = {{0.0, 0.0}, {0.0, 0.0}};
    for (int a = 0; a < n; ++a) {
      const double N = qp.value[a], dx = qp.grad[a].x(), dy = qp.grad[a].y();
      for (int i = 0; i < 2; ++i) {
        const double va = x[5 * a + i];
        v[i] += N * va;
        G[i][0] += dx * va;
        G[i][1] += dy * va;
      }
      p += N * x[5 * a + 4];
    }
    const double wc[2] = {v[0] - old.tx, v[1] - old.ty};
    // d div / d p: the cavitation floor's ramp(p_cav - p) / mu_f enters with a minus sign.
    const double dp_div = c.cavitation_p_pa != 0.0
                              ? rounded_ramp_slope(c.cavitation_p_pa - p, c.cavitation_smoothing_pa) / mu_f
                              : 0.0;
    for (int a = 0; a < n; ++a) {
      const double Na = qp.value[a];
      const double ga[2] = {qp.grad[a].x(), qp.grad[a].y()};
      const bool extension_row = !in.u_row_solid[a];
      for (int b = 0; b < n; ++b) {
        const double Nb = qp.value[b];
        const double gb[2] = {qp.grad[b].x(), qp.grad[b].y()};
        const double lap = ga[0] * gb[0] + ga[1] * gb[1];
        // rho_f ((v_i - v_old_i) / k + wc . grad v_i): d/d v_kb = rho_f (delta_ik (N_b / k +
        // wc . grad N_b) + N_b G_ik); tested with N_a.
        const double transport = c.rho_f * (Nb * inv_k + wc[0] * gb[0] + wc[1] * gb[1]) * Na;
        for (int i = 0; i < 2; ++i) {
          double* row = k[5 * a + i].data() + 5 * b;
          for (int kk = 0; kk < 2; ++kk) {
            // mu_f (G + G^T) : grad phi: d/d v_kb = mu_f (delta_ik grad N_a . grad N_b + d_i N_b d_k N_a).
            double value = c.rho_f * Nb * G[i][kk] * Na + mu_f * gb[i] * ga[kk];
            if (i == kk) value += transport + mu_f * lap;
            row[kk] += w * value;
          }
          row[4] -= w * Nb * ga[i];  // - p div phi
          if (extension_row) k[5 * a + 2 + i][5 * b + 2 + i] += w * c.extension_u * lap;
        }
        double* prow = k[5 * a + 4].data() + 5 * b;
        prow[0] += w * Na * gb[0];
        prow[1] += w * Na * gb[1];
        prow[4] += w * Na * Nb * dp_div;
      }
    }
  }
}

}  // namespace fsi::forms
