// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Errors of the pmsum command-line tool, by exit code.

#ifndef CGAL_PMSUM_CLI_ERRORS_H
#define CGAL_PMSUM_CLI_ERRORS_H

#include <stdexcept>

namespace pmsum_cli {

/// An error the user can fix: printed as one line, exit code 1.
struct Error : std::runtime_error { using std::runtime_error::runtime_error; };
/// A command-line mistake: printed with a usage hint, exit code 2.
struct Usage_error : std::runtime_error { using std::runtime_error::runtime_error; };
/// A command that does not exist: the hint is the list of commands, exit code 2.
struct Unknown_command : Usage_error { using Usage_error::Usage_error; };
/// A run refused because it would exhaust the machine (--force overrides): exit code 3.
struct Refused : std::runtime_error { using std::runtime_error::runtime_error; };

} // namespace pmsum_cli

#endif // CGAL_PMSUM_CLI_ERRORS_H
