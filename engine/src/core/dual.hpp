#pragma once
/// \file dual.hpp
/// Forward-mode automatic differentiation with a fixed number of derivatives.
///
/// The element residuals are written once, templated on the scalar; evaluated with
/// Dual<N> (N = local unknowns of one sub-element, at most 4 nodes x 5 fields = 20)
/// they give the exact element Jacobian, row by row, with no hand derivation to get
/// wrong. tests/unit/fsi_jacobian_test.cpp checks it against finite differences. Fluid
/// sub-elements off the open boundary, the bulk of the mesh, use a hand-derived Jacobian
/// checked against this one (forms/fluid_element_jacobian.hpp): it costs far less.
#include <array>
#include <cmath>

namespace fsi {

template <int N>
struct Dual {
  double v = 0.0;
  std::array<double, N> d{};

  Dual() = default;
  Dual(double value) : v(value) {}  // NOLINT: constants promote implicitly
  static Dual variable(double value, int index) {
    Dual x(value);
    x.d[index] = 1.0;
    return x;
  }

  Dual& operator+=(const Dual& o) {
    v += o.v;
    for (int i = 0; i < N; ++i) d[i] += o.d[i];
    return *this;
  }
  Dual& operator-=(const Dual& o) {
    v -= o.v;
    for (int i = 0; i < N; ++i) d[i] -= o.d[i];
    return *this;
  }
  Dual& operator*=(const Dual& o) {
    for (int i = 0; i < N; ++i) d[i] = d[i] * o.v + v * o.d[i];
    v *= o.v;
    return *this;
  }
  Dual& operator*=(double s) {
    v *= s;
    for (int i = 0; i < N; ++i) d[i] *= s;
    return *this;
  }
  Dual& operator/=(const Dual& o) {
    const double inv = 1.0 / o.v;
    for (int i = 0; i < N; ++i) d[i] = (d[i] - v * inv * o.d[i]) * inv;
    v *= inv;
    return *this;
  }
};

template <int N> Dual<N> operator-(Dual<N> a) { a *= -1.0; return a; }
template <int N> Dual<N> operator+(Dual<N> a, const Dual<N>& b) { return a += b; }
template <int N> Dual<N> operator-(Dual<N> a, const Dual<N>& b) { return a -= b; }
template <int N> Dual<N> operator*(Dual<N> a, const Dual<N>& b) { return a *= b; }
template <int N> Dual<N> operator/(Dual<N> a, const Dual<N>& b) { return a /= b; }
template <int N> Dual<N> operator+(Dual<N> a, double b) { a.v += b; return a; }
template <int N> Dual<N> operator+(double b, Dual<N> a) { a.v += b; return a; }
template <int N> Dual<N> operator-(Dual<N> a, double b) { a.v -= b; return a; }
template <int N> Dual<N> operator-(double b, const Dual<N>& a) { return Dual<N>(b) - a; }
template <int N> Dual<N> operator*(Dual<N> a, double b) { return a *= b; }
template <int N> Dual<N> operator*(double b, Dual<N> a) { return a *= b; }
template <int N> Dual<N> operator/(Dual<N> a, double b) { return a *= 1.0 / b; }
template <int N> Dual<N> operator/(double b, const Dual<N>& a) { return Dual<N>(b) / a; }

inline double value_of(double x) { return x; }
template <int N> double value_of(const Dual<N>& x) { return x.v; }

}  // namespace fsi
