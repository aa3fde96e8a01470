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

#include <array>
#include <cstdint>

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

/// Converts an integer exactly. Callers keep |i| < 2^53 (lattice denominators are capped at
/// 2^20, so products of two of them are far below), hence the conversion to double is exact.
template <class NT>
inline NT int_nt(std::int64_t i) { return NT(static_cast<long>(i)); }
template <>
inline Interval int_nt<Interval>(std::int64_t i) { return Interval(static_cast<double>(i)) ; }

/// Sign of `f(NT{})`, where `f` is a generic callable computing a polynomial expression in
/// the number type it is called with. The result is exact.
template <class F>
CGAL::Sign filtered_sign(const F& f)
{
  {
    CGAL::Protect_FPU_rounding<true> guard;
    const Interval r = f(Interval());
    if (r.inf() > 0) return CGAL::POSITIVE;
    if (r.sup() < 0) return CGAL::NEGATIVE;
    if (r.inf() == 0 && r.sup() == 0) return CGAL::ZERO;
  }
  return CGAL::sign(f(Exact_nt()));
}

} // namespace internal
} // namespace Pmsum
} // namespace CGAL

#endif // CGAL_PMSUM_INTERNAL_EXACT_SIGN_H
