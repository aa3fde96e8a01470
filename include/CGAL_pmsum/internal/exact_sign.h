// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Exact signs of small polynomial expressions in double coordinates.
//
// Every geometric decision of CGAL_pmsum is the sign of a polynomial whose inputs are
// mesh coordinates (exact doubles) and small integers (lattice numerators and
// denominators of the samples). `filtered_sign` evaluates such an expression first with
// interval arithmetic and, only when the interval contains zero, again with CGAL::Mpzf,
// which adds and multiplies doubles and integers without rounding.

#ifndef CGAL_PMSUM_INTERNAL_EXACT_SIGN_H
#define CGAL_PMSUM_INTERNAL_EXACT_SIGN_H

#include <CGAL/Interval_nt.h>
#include <CGAL/Mpzf.h>
#include <CGAL/enum.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <vector>

namespace CGAL {
namespace Pmsum {
namespace internal {

using Interval = CGAL::Interval_nt<false>;
using Exact_nt = CGAL::Mpzf;

template <class NT> using Vec3 = std::array<NT, 3>;

template <class NT>
inline Vec3<NT> operator-(const Vec3<NT>& a, const Vec3<NT>& b)
{ return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

template <class NT>
inline Vec3<NT> operator+(const Vec3<NT>& a, const Vec3<NT>& b)
{ return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }

template <class NT>
inline Vec3<NT> cross(const Vec3<NT>& a, const Vec3<NT>& b)
{ return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }

template <class NT>
inline NT dot(const Vec3<NT>& a, const Vec3<NT>& b)
{ return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

template <class NT>
inline Vec3<NT> scaled(const Vec3<NT>& a, const NT& s)
{ return {a[0] * s, a[1] * s, a[2] * s}; }

/// Converts a double triple to the number type NT (exactly: doubles are exact in both
/// Interval_nt and Mpzf).
template <class NT>
inline Vec3<NT> to_nt(const std::array<double, 3>& p)
{ return {NT(p[0]), NT(p[1]), NT(p[2])}; }

/// (b - a) x (c - a) in NT: the normal of triangle abc (not normalized), on the side from
/// which a, b, c turn counterclockwise.
template <class NT>
inline Vec3<NT> triangle_normal(const std::array<double, 3>& a, const std::array<double, 3>& b,
                                const std::array<double, 3>& c)
{
  const Vec3<NT> A = to_nt<NT>(a);
  return cross(to_nt<NT>(b) - A, to_nt<NT>(c) - A);
}

/// Converts an integer exactly. Callers keep |i| < 2^53 (lattice denominators are capped at
/// 2^20, so products of two of them are far below), hence the conversion to double is exact.
template <class NT>
inline NT int_nt(std::int64_t i) { return NT(static_cast<long>(i)); }
template <>
inline Interval int_nt<Interval>(std::int64_t i) { return Interval(static_cast<double>(i)) ; }

/// Are all coordinates of these points integer multiples of one power of two 2^e, below
/// 2^15 2^e in absolute value (as in most CAD models: few significant bits), with
/// |e| <= 300? Then, in units of powers of 2^e, every step of the orientation determinant of
/// four of them is an integer below 2^53 (differences below 2^16, cross products below
/// 2^33, the determinant below 3 2^49), and so is every step of its gradient for shifts in
/// {-1, 0, 1} (below 6 2^33); and 2^3e neither underflows nor overflows: their evaluation in
/// double arithmetic is exact.
inline bool on_small_grid(std::initializer_list<const std::vector<std::array<double, 3>>*> point_sets)
{
  int low = std::numeric_limits<int>::max(); // exponent of the grid
  double largest = 0;
  for (const auto* points : point_sets)
    for (const auto& p : *points)
      for (double x : p) {
        if (x == 0) continue;
        if (!std::isfinite(x)) return false;
        int exponent;
        const double m = std::frexp(std::abs(x), &exponent); // |x| = m 2^exponent, m in [1/2, 1)
        std::uint64_t mantissa = static_cast<std::uint64_t>(std::ldexp(m, 53));
        int lowest = exponent - 53;
        while ((mantissa & 1) == 0) { mantissa >>= 1; ++lowest; }
        low = (std::min)(low, lowest);
        largest = (std::max)(largest, std::abs(x));
      }
  return largest == 0 || (low >= -300 && low <= 300 && largest < std::ldexp(1.0, low + 15));
}

/// Sign of `f(NT{})`, where `f` is a generic callable computing a polynomial expression in
/// the number type it is called with, from its interval evaluation if that decides, else
/// from `exact()`, which returns the exact sign.
template <class F, class E>
CGAL::Sign filtered_sign(const F& f, const E& exact)
{
  {
    CGAL::Protect_FPU_rounding<true> guard;
    const Interval r = f(Interval());
    if (r.inf() > 0) return CGAL::POSITIVE;
    if (r.sup() < 0) return CGAL::NEGATIVE;
    if (r.inf() == 0 && r.sup() == 0) return CGAL::ZERO;
  }
  return exact();
}

/// The same, with f evaluated in Exact_nt where intervals do not decide. The result is exact.
template <class F>
CGAL::Sign filtered_sign(const F& f)
{ return filtered_sign(f, [&] { return CGAL::sign(f(Exact_nt())); }); }

} // namespace internal
} // namespace Pmsum
} // namespace CGAL

#endif // CGAL_PMSUM_INTERNAL_EXACT_SIGN_H
