// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Default options of AddressSanitizer and UBSan, linked into every program of the sanitizer
// build (PMSUM_SANITIZE=ON): a report aborts the program (SIGABRT, never an exit code a test
// could expect, such as pmsum's 1), leaks included. ASAN_OPTIONS and UBSAN_OPTIONS still
// override them.

extern "C" __attribute__((used, visibility("default"))) const char* __asan_default_options()
{
  return "abort_on_error=1:halt_on_error=1:detect_leaks=1";
}

extern "C" __attribute__((used, visibility("default"))) const char* __ubsan_default_options()
{
  return "abort_on_error=1:halt_on_error=1:print_stacktrace=1";
}
