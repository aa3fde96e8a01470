// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// libFuzzer target over the pmsum tool's mesh readers and the library's input checks: the
// readers of src/cli_input.h on in-memory text (parse_soup, then mesh_from_soup: repair,
// triangulation, orientation), then the library's input stage (make_mesh_data: the
// descriptors, orientation around edges, degenerate faces, the solid checks).
//
// Input: one byte choosing the format (its value mod 4: 0 OFF, 1 PLY, 2 STL, 3 OBJ; bit 2:
// the mesh is treated as a surface), then the file's contents. The seeds written by
// `test/corpus/make_corpus.py --seeds DIR` start with '0'..'3'.
//
// A refusal (pmsum_cli::Error, CGAL::Pmsum::Invalid_input or Too_large) is a clean outcome;
// any other exception, a crash, a sanitizer report, a timeout or a memory blow-up is a
// finding. Built with clang -fsanitize=fuzzer,address,undefined (PMSUM_SANITIZE=ON);
// test/fuzz/run_fuzzer.sh runs it.

#include "cli_input.h"

#include <CGAL_pmsum/exceptions.h>
#include <CGAL_pmsum/internal/mesh_data.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if (size < 1) return 0;
  static const char* const formats[] = {"off", "ply", "stl", "obj"};
  const std::string ext = formats[data[0] % 4];
  const bool as_surface = (data[0] >> 2) & 1;
  const std::string_view text(reinterpret_cast<const char*>(data + 1), size - 1);
  namespace in = CGAL::Pmsum::internal;
  try {
    const pmsum_cli::Mesh m = pmsum_cli::mesh_from_soup(pmsum_cli::parse_soup(text, ext, "P"), "P", true);
    in::Mesh_descriptors<pmsum_cli::Mesh> desc;
    in::make_mesh_data(m, get(CGAL::vertex_point, m), false, as_surface, "P", desc);
  } catch (const pmsum_cli::Error&) {
  } catch (const CGAL::Pmsum::Invalid_input&) {
  } catch (const CGAL::Pmsum::Too_large&) {
  } catch (const std::exception& e) {
    // What pmsum would print as "error: ..." without having decided it: a finding.
    std::fprintf(stderr, "fuzz_readers: unexpected exception (%s format): %s\n", ext.c_str(), e.what());
    std::abort();
  }
  return 0;
}
