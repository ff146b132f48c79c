#pragma once

#include <array>
#include <cmath>

namespace vesicle_iga
{
  /**
   * A number with its derivatives with respect to N independent inputs
   * (forward-mode automatic differentiation on the stack, no allocation):
   * what PointwiseTerm uses to get the exact Jacobian of a term from its
   * residual formula (spec 4.9 allows automatic differentiation at the
   * quadrature-point level).
   */
  template <int N>
  struct Dual
  {
    double                v = 0;
    std::array<double, N> d{};

    Dual() = default;
    Dual(const double value)
      : v(value)
    {}
    /// The independent input number i with value x.
    static Dual
    input(const double x, const unsigned int i)
    {
      Dual r(x);
      r.d[i] = 1;
      return r;
    }

    Dual &
    operator+=(const Dual &b)
    {
      v += b.v;
      for (int i = 0; i < N; ++i)
        d[i] += b.d[i];
      return *this;
    }
    Dual &
    operator-=(const Dual &b)
    {
      v -= b.v;
      for (int i = 0; i < N; ++i)
        d[i] -= b.d[i];
      return *this;
    }
    Dual &
    operator*=(const Dual &b)
    {
      for (int i = 0; i < N; ++i)
        d[i] = d[i] * b.v + v * b.d[i];
      v *= b.v;
      return *this;
    }
    Dual &
    operator*=(const double b)
    {
      for (int i = 0; i < N; ++i)
        d[i] *= b;
      v *= b;
      return *this;
    }
  };

  template <int N>
  inline Dual<N>
  operator+(Dual<N> a, const Dual<N> &b)
  {
    return a += b;
  }
  template <int N>
  inline Dual<N>
  operator-(Dual<N> a, const Dual<N> &b)
  {
    return a -= b;
  }
  template <int N>
  inline Dual<N>
  operator-(Dual<N> a)
  {
    return a *= -1.;
  }
  template <int N>
  inline Dual<N>
  operator*(Dual<N> a, const Dual<N> &b)
  {
    return a *= b;
  }
  template <int N>
  inline Dual<N>
  operator*(Dual<N> a, const double b)
  {
    return a *= b;
  }
  template <int N>
  inline Dual<N>
  operator*(const double b, Dual<N> a)
  {
    return a *= b;
  }
  template <int N>
  inline Dual<N>
  operator+(Dual<N> a, const double b)
  {
    a.v += b;
    return a;
  }
  template <int N>
  inline Dual<N>
  operator+(const double b, Dual<N> a)
  {
    a.v += b;
    return a;
  }
  template <int N>
  inline Dual<N>
  operator-(Dual<N> a, const double b)
  {
    a.v -= b;
    return a;
  }
  template <int N>
  inline Dual<N>
  operator-(const double b, const Dual<N> &a)
  {
    return -a + b;
  }
  template <int N>
  inline Dual<N>
  operator/(const Dual<N> &a, const Dual<N> &b)
  {
    Dual<N>      r;
    const double inv = 1. / b.v;
    r.v              = a.v * inv;
    for (int i = 0; i < N; ++i)
      r.d[i] = (a.d[i] - r.v * b.d[i]) * inv;
    return r;
  }
  template <int N>
  inline Dual<N>
  operator/(Dual<N> a, const double b)
  {
    return a *= 1. / b;
  }
  template <int N>
  inline Dual<N>
  operator/(const double a, const Dual<N> &b)
  {
    return Dual<N>(a) / b;
  }

  /// f(a) with f'(a.v) given: the chain rule.
  template <int N>
  inline Dual<N>
  chain(const Dual<N> &a, const double value, const double derivative)
  {
    Dual<N> r(value);
    for (int i = 0; i < N; ++i)
      r.d[i] = derivative * a.d[i];
    return r;
  }
  template <int N>
  inline Dual<N>
  sqrt(const Dual<N> &a)
  {
    const double s = std::sqrt(a.v);
    return chain(a, s, 0.5 / s);
  }
  template <int N>
  inline Dual<N>
  exp(const Dual<N> &a)
  {
    const double e = std::exp(a.v);
    return chain(a, e, e);
  }
  template <int N>
  inline Dual<N>
  log(const Dual<N> &a)
  {
    return chain(a, std::log(a.v), 1. / a.v);
  }

  /// The value of a plain number or of a Dual.
  inline double
  value_of(const double a)
  {
    return a;
  }
  template <int N>
  inline double
  value_of(const Dual<N> &a)
  {
    return a.v;
  }
} // namespace vesicle_iga
