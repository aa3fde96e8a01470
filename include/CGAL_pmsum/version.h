// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The package's version (CMakeLists.txt reads it from here: one place).

#ifndef CGAL_PMSUM_VERSION_H
#define CGAL_PMSUM_VERSION_H

/// \ingroup PkgPointMinkowskiSumSupport
/// The major version of the package (0.x: a minor version may break the API).
#define CGAL_PMSUM_VERSION_MAJOR 0
/// \ingroup PkgPointMinkowskiSumSupport
/// The minor version of the package.
#define CGAL_PMSUM_VERSION_MINOR 1
/// \ingroup PkgPointMinkowskiSumSupport
/// The patch version of the package.
#define CGAL_PMSUM_VERSION_PATCH 0
/// \ingroup PkgPointMinkowskiSumSupport
/// The version of the package as a string, "MAJOR.MINOR.PATCH".
#define CGAL_PMSUM_VERSION "0.1.0"
/// \ingroup PkgPointMinkowskiSumSupport
/// The version of the package as a number, MAJOR * 10000 + MINOR * 100 + PATCH, for `#if`.
#define CGAL_PMSUM_VERSION_NR 100

#endif // CGAL_PMSUM_VERSION_H
