#!/usr/bin/env python3
# Copyright (c) 2026 CGAL_pmsum contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Hostile-input corpus of the pmsum command-line tool.

Generates malformed inputs for every reader (OFF, OBJ, PLY ASCII and binary, STL ASCII and
binary) and hostile option values, each with its expected exit code, runs `pmsum sum` on each
and fails on any: wrong exit code or message class, crash (killed by a signal or exit >= 128),
hang (> 30 s), peak RSS over 2 GiB (address space capped at 4 GiB), output or temporary file
left behind after a failure, input file changed on disk.

    make_corpus.py PMSUM [--keep DIR] [--list] [--no-as-limit]
    make_corpus.py --seeds DIR

--keep DIR keeps the inputs and the work files in DIR. --no-as-limit leaves the address
space uncapped (AddressSanitizer reserves terabytes of it: the sanitized tests pass it; their
peak RSS is still checked). --seeds DIR writes each input file, without running anything, as a
seed of the readers' fuzzer (test/fuzz/fuzz_readers.cpp): one byte naming the format ('0' OFF,
'1' PLY, '2' STL, '3' OBJ), then the file.
"""

import collections
import hashlib
import os
import re
import resource
import signal
import struct
import subprocess
import sys
import tempfile
import time

TIMEOUT = 30
RSS_LIMIT_KB = 2 * 1024 * 1024
AS_LIMIT = 4 << 30

# message class of each exit code (first line of stderr that is not a note)
CLASSES = {
    0: re.compile(r"points written"),
    1: re.compile(r"^pmsum: error: "),
    2: re.compile(r"^pmsum: .*\(see pmsum "),
    3: re.compile(r"^pmsum: refused"),
}

# ----- valid models ----------------------------------------------------------------------
TET = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
TET_F = [(0, 2, 1), (0, 1, 3), (1, 2, 3), (0, 3, 2)]
CUBE = [(i & 1, (i >> 1) & 1, (i >> 2) & 1) for i in range(8)]
CUBE_F = []
for a, b, c, d in [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]:
    CUBE_F += [(a, b, c), (a, c, d)]


def num(x):
    return repr(float(x)) if not isinstance(x, str) else x


def off(points, faces, header=None, counts=None, tail=""):
    counts = counts if counts is not None else "%d %d 0" % (len(points), len(faces))
    s = (header if header is not None else "OFF") + "\n" + counts + "\n"
    s += "".join(" ".join(num(c) for c in p) + "\n" for p in points)
    s += "".join(" ".join(str(x) for x in [len(f)] + list(f)) + "\n" for f in faces)
    return s + tail


def obj(points, faces, base=1):
    s = "".join("v " + " ".join(num(c) for c in p) + "\n" for p in points)
    return s + "".join("f " + " ".join(str(i + base) if isinstance(i, int) else i for i in f) + "\n" for f in faces)


def ply_ascii(points, faces, count_type="uchar", index_type="int", nv=None, nf=None, extra_header="", tail=""):
    h = "ply\nformat ascii 1.0\n%selement vertex %s\nproperty float x\nproperty float y\nproperty float z\n" \
        "element face %s\nproperty list %s %s vertex_indices\nend_header\n" % (
            extra_header, len(points) if nv is None else nv, len(faces) if nf is None else nf, count_type, index_type)
    s = "".join(" ".join(num(c) for c in p) + "\n" for p in points)
    s += "".join(" ".join(str(x) for x in [len(f)] + list(f)) + "\n" for f in faces)
    return (h + s + tail).encode()


def ply_binary(points, faces, endian="<", count_type="uchar", index_type="int", nv=None, nf=None, tail=b"",
               counts=None, coord_type="float"):
    fmt = "binary_little_endian" if endian == "<" else "binary_big_endian"
    h = ("ply\nformat %s 1.0\nelement vertex %s\nproperty %s x\nproperty %s y\nproperty %s z\n"
         "element face %s\nproperty list %s %s vertex_indices\nend_header\n" % (
             fmt, len(points) if nv is None else nv, coord_type, coord_type, coord_type,
             len(faces) if nf is None else nf, count_type, index_type)).encode()
    ct = {"uchar": "B", "uint": "I", "int": "i", "ushort": "H"}[count_type]
    it = {"int": "i", "uint": "I", "uchar": "B", "short": "h"}[index_type]
    cf = {"float": "f", "double": "d"}[coord_type]
    b = b"".join(struct.pack(endian + "3" + cf, *p) for p in points)
    for k, f in enumerate(faces):
        n = len(f) if counts is None or counts[k] is None else counts[k]
        b += struct.pack(endian + ct, n) + struct.pack(endian + "%d" % len(f) + it, *f)
    return h + b + tail


def stl_binary(points, faces, declared=None, tail=b"", header=b"binary"):
    body = b""
    for f in faces:
        body += struct.pack("<3f", 0, 0, 0) + b"".join(struct.pack("<3f", *points[i]) for i in f) + b"\0\0"
    n = len(faces) if declared is None else declared
    return header.ljust(80, b" ")[:80] + struct.pack("<I", n) + body + tail


def stl_ascii(points, faces, name="cube", end=True):
    s = "solid %s\n" % name
    for f in faces:
        s += " facet normal 0 0 0\n  outer loop\n"
        s += "".join("   vertex %s %s %s\n" % tuple(num(c) for c in points[i]) for i in f)
        s += "  endloop\n endfacet\n"
    return s + ("endsolid %s\n" % name if end else "")


def boxes(parts):
    P, F = [], []
    for lo, hi, inward in parts:
        o = len(P)
        P += [(hi[0] if i & 1 else lo[0], hi[1] if i & 2 else lo[1], hi[2] if i & 4 else lo[2]) for i in range(8)]
        for a, b, c in CUBE_F:
            F.append((o + a, o + c, o + b) if inward else (o + a, o + b, o + c))
    return P, F


def shared(points, faces):
    """The same mesh with equal points merged (parts that touch share their vertices there)."""
    index, P = {}, []
    for p in points:
        if p not in index:
            index[p] = len(P)
            P.append(p)
    return P, [tuple(index[points[v]] for v in f) for f in faces]


# ----- the corpus ------------------------------------------------------------------------
def corpus():
    """(name, extension, content as str or bytes, expected exit code, extra arguments)."""
    C = []

    def add(name, ext, content, code, args=()):
        C.append((name, ext, content, code, list(args)))

    # OFF: header
    add("off_empty", "off", "", 1)
    add("off_only_comments", "off", "# nothing\n# here\n", 1)
    add("off_no_keyword", "off", "8 12 0\n" + off(CUBE, CUBE_F).split("\n", 2)[2], 1)
    add("off_wrong_keyword", "off", off(CUBE, CUBE_F, header="OFX"), 1)
    add("off_lowercase", "off", off(CUBE, CUBE_F, header="off"), 1)
    add("off_4off", "off", off(CUBE, CUBE_F, header="4OFF"), 1)
    add("off_noff_dim", "off", off(CUBE, CUBE_F, header="nOFF"), 1)
    add("off_binary", "off", "OFF BINARY\n" + "\0" * 40, 1)
    add("off_counts_missing", "off", "OFF\n", 1)
    add("off_counts_one", "off", "OFF\n8\n", 1)
    add("off_counts_negative_v", "off", off(CUBE, CUBE_F, counts="-8 12 0"), 1)
    add("off_counts_negative_f", "off", off(CUBE, CUBE_F, counts="8 -12 0"), 1)
    add("off_counts_text", "off", off(CUBE, CUBE_F, counts="eight twelve 0"), 1)
    add("off_counts_float", "off", off(CUBE, CUBE_F, counts="8.0 12 0"), 1)
    add("off_counts_hex", "off", off(CUBE, CUBE_F, counts="0x8 12 0"), 1)
    add("off_counts_edges_text", "off", off(CUBE, CUBE_F, counts="8 12 x"), 1)
    for nv, nf in [(4e8, 12), (8, 4e8), (2**31, 12), (8, 2**32), (2**63, 1), (10**19, 1), (10**25, 1), (4e8, 4e8)]:
        add("off_counts_huge_%g_%g" % (nv, nf), "off", off(CUBE, CUBE_F, counts="%d %d 0" % (nv, nf)), 1)
    add("off_counts_more_vertices", "off", off(CUBE, CUBE_F, counts="9 12 0"), 1)
    add("off_counts_fewer_vertices", "off", off(CUBE, CUBE_F, counts="7 12 0"), 1)
    add("off_counts_more_faces", "off", off(CUBE, CUBE_F, counts="8 13 0"), 1)
    add("off_counts_fewer_faces", "off", off(CUBE, CUBE_F, counts="8 4 0"), 1)
    add("off_counts_zero_faces", "off", off(CUBE, [], counts="8 0 0"), 1)
    add("off_counts_same_line", "off", "OFF 8 12 0\n" + off(CUBE, CUBE_F).split("\n", 2)[2], 0)
    add("off_crlf", "off", off(CUBE, CUBE_F).replace("\n", "\r\n"), 0)
    add("off_comments_everywhere", "off", off(CUBE, CUBE_F).replace("\n", " # c\n"), 0)
    add("off_trailing_comment", "off", off(CUBE, CUBE_F, tail="# end\n\n\n"), 0)
    add("off_trailing_data", "off", off(CUBE, CUBE_F, tail="3 0 1 2\n"), 1)
    add("off_trailing_garbage", "off", off(CUBE, CUBE_F, tail="garbage\n"), 1)
    add("off_trailing_nul", "off", off(CUBE, CUBE_F, tail="\0\0\0\n"), 1)
    add("off_coff_colors", "off", off([p + (0.5, 0.5, 0.5, 1) for p in CUBE], CUBE_F, header="COFF"), 0)
    add("off_face_colors", "off", off(CUBE, CUBE_F).replace("\n3 ", "\n3 ").rstrip("\n").replace(
        "\n3 4 5 7", "\n3 4 5 7 255 0 0") + "\n", 0)
    # OFF: vertices
    bad_vertices = {
        "two_coords": "0 0", "text": "a b c", "nan": "nan 0 0", "inf": "inf 0 0", "minus_inf": "0 -inf 0",
        "overflow": "1e400 0 0", "hexfloat": "0x1p-3 0 0", "empty_token": "0 0 ,", "comma": "0,0,0",
        "denormal": "4.9e-324 0 0", "huge": "1e308 1e308 1e308",
    }
    for k, v in bad_vertices.items():
        lines = off(CUBE, CUBE_F).split("\n")
        lines[2] = v
        code = {"hexfloat": 0, "denormal": 0, "huge": 3}.get(k, 1)
        add("off_vertex_" + k, "off", "\n".join(lines), code)
    # OFF: faces
    def cube_with_face(face_line, k=5):
        lines = off(CUBE, CUBE_F).split("\n")
        lines[2 + 8 + k] = face_line
        return "\n".join(lines)
    for k, line in {
        "n0": "0", "n1": "1 0", "n2": "2 0 1", "n_huge": "2000000000 0 1 2", "n_2e19": "20000000000000000000 0 1 2",
        "n_negative": "-3 0 1 2", "n_text": "x 0 1 2", "n_float": "3.0 0 1 2", "n_short": "4 0 1 2",
        "index_8": "3 0 1 8", "index_big": "3 0 1 4294967296", "index_2e19": "3 0 1 99999999999999999999",
        "index_negative": "3 0 1 -1", "index_float": "3 0 1 2.5", "index_text": "3 0 1 two",
        "repeated": "3 0 0 1", "all_same": "3 1 1 1", "empty": "",
    }.items():
        add("off_face_" + k, "off", cube_with_face(line), 1)
    add("off_face_quad_ok", "off", off(CUBE, [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2),
                                             (1, 3, 7, 5)]), 0)
    # a repeated vertex closing a polygon, a duplicated face: not a mesh, repaired (CGAL's PMP)
    add("off_face_pentagon_repeat", "off", off(CUBE, [(0, 2, 3, 1, 0)] + CUBE_F[2:]), 0)
    # a hexagon that crosses itself in its plane: CGAL 5.5's triangulate_faces made an endless
    # face cycle of it (a hang; found by the readers' fuzzer); a planar star pentagon
    add("off_face_not_simple_hexagon", "off", off([(1, 1, 1), (3, 3, 1), (3, 1, 1), (2, 2, 0), (0, 2, 2), (2, 2, 2)],
                                                  [(0, 1, 2, 3, 4, 5)]), 1)
    add("off_face_star_pentagon", "off", off([(0, 0, 0), (2, 0, 0), (0, 1, 0), (2, 1, 0), (1, 3, 0)],
                                             [(0, 1, 2, 3, 4)]), 1)
    # a quad whose plane overflows double: SIGFPE in GMP (the readers' fuzzer)
    add("off_face_quad_1e308", "off", off([(0, 0, 0), (1e308, 0, 0), (1e308, 1e308, 0), (0, 1e308, 0)],
                                          [(0, 1, 2, 3)]), 1)
    # two crossing cubes, closed: CGAL 5.5's orient_to_bound_a_volume looped for ever in its ray
    # casts (the readers' fuzzer, verbatim)
    # an OBJ whose repaired soup has a pentagon with two corners on one point of the plane of its
    # normal: CGAL 5.5's triangulate_faces inserted a constraint from a vertex to itself (UBSan;
    # the readers' fuzzer, verbatim)
    add("obj_pentagon_corners_meet_in_projection", "obj", b'v 0.0 0.0 0.0\x8av 1.0 0.0 0.0\nv 1.0 0.0 0.0\nv 0.0 1.0 0.0\nv 1.0 1.1 6/1/10.0\nv 0.0 0.0 1.0\nv 1.0 0.0 1.0\nv 0.0 1.0 1.0\nv 1.0 1.0 1.0\nf 1/1/1 3/1/1 4/1/1\nf 1/1/1 4/1/1 2/1/1\nf 5/1/1 6/1/1 8/1/1\nf 5/1/1 8/1/1 7/1/\xcf\xf5\x99\xe31/1/1 2/1/1 6/1/1\nf 1/1/1 6/1/1 5/1/1\nf 3/1/1 7/1/1 8/1/1\nf 3/1/1 8/1/1 4/1/1\nf 1/1/1 5/1/1 7/1/1\nf 1/1/1 5/1/1 6/1/1 8/1/1\nf 5/1/1 8/1/1 7/1/1\nf 1/1/1 2/1/1 6/1/1\xff\xff\xff\xff/1/1 6/1/1 5/1/1e308/1/1 7/1/1 8/1/1\nf 3/1/1 8/1/1vertex  4/1/1 6/1/1\nvt 0 0\nvn 0 0.0 0.0\nv 0.0 1.0 0.0\nv 1.0 1.0 0.0\nv 0.0 0.0 1.0\nv 1.0 0.0 1.0\nv 0.0 1.0 1.0\nv 1.0 1.0 1.0\nf 1/1/1 3/1/1 4/1/1\nf 1/1/1 4/1/1 2/1/1\nf 5/1/1 6/1/1 8/1/1\nf 5/1/1 8/1/1 7/1/1\nf 1/1/1 2/1/1 6/1/1\nf 1/1/1 6/1/1 5/1/1\nf 3/1/1 7/1/1 8/1/1\nf 3/1/1 8/1/1 4/1/1\nf 1/1/1 5/1/1 7/1/1\nf 1/1/1 7/1/1 3/1/1\nf 2/1/1 4/1/1 8/1/1\nf 2/1/1 8/1/1 6/1/1\nvt 0 0\nvn 0 0 1\n', 1)
    add("off_crossing_cubes_orient_loop", "off", (
        'OFF\n16 24 0\n0.0 0.0 0.0\n1.0 0.0 0.00\n.0 1.5 0.0\n1.0 1.0 0.0\n'
        '0.0 0.0 1.0\n0.0 0.0 1.0\n1.0 1.0 1.0\n1.0 1.0 1.0\n0.0 0.0 0.0\n'
        '1.0 0.0 0.0\n0.0 1.0 0.0\n1.0 1.0 0.0\n0.0 0.0 1.0\n1.0 0.0 1.0\n'
        '0.0 0.0 1.0\n1.0 1.0 1.0\n3 0 2 3\n3 0 3 1\n3 4 5 7\n3 4 7 6\n3 0 1 5\n'
        '3 0 5 4\n3 2 6 7\n3 2 7 3\n3 0 4 6\n3 0 6 2\n3 1 3 7\n3 1 7 5\n3 8 10 11\n'
        '3 8 11 9\n3 12 13 15\n3 12 15 14\n3 8 9 13\n3 8 13 12\n3 10 14 15\n'
        '3 10 15 11\n3 8 12 14\n3 8 14 10\n3 9 11 15\n3 9 15 13\n'), 1)
    add("off_45_bytes_2e9", "off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2000000000 0 1 2\n", 1)
    add("off_header_4e8_faces", "off", "OFF\n3 400000000 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", 1)
    add("off_truncated_vertices", "off", "OFF\n8 12 0\n0 0 0\n1 0 0\n", 1)
    add("off_truncated_faces", "off", off(CUBE, CUBE_F[:5], counts="8 12 0"), 1)
    add("off_nul_bytes", "off", "OFF\n\0\0\0\0\n", 1)
    add("off_random_bytes", "off", bytes(range(256)) * 4, 1)
    add("off_long_line", "off", "OFF\n" + "1 " * 500000 + "\n", 1)
    # OFF: geometry
    add("off_degenerate_triangle", "off", off(TET + [(2, 0, 0)], TET_F + [(0, 1, 4)]), 1)
    add("off_all_collinear", "off", off([(0, 0, 0), (1, 0, 0), (2, 0, 0)], [(0, 1, 2)]), 1)
    add("off_open_ok", "off", off(CUBE, CUBE_F[2:]), 0)
    add("off_inward_ok", "off", off(CUBE, [(a, c, b) for a, b, c in CUBE_F]), 0)
    add("off_duplicate_face", "off", off(CUBE, CUBE_F + [CUBE_F[0]]), 0)
    add("off_opposite_face", "off", off(CUBE, CUBE_F + [(CUBE_F[0][0], CUBE_F[0][2], CUBE_F[0][1])]), 0)
    add("off_overlapping_cubes", "off", off(*boxes([((0, 0, 0), (2, 2, 2), 0), ((1, 1, 1), (3, 3, 3), 0)])), 1)
    add("off_nested_void_ok", "off", off(*boxes([((0, 0, 0), (4, 4, 4), 0), ((1, 1, 1), (3, 3, 3), 1)])), 0)
    add("off_touching_ok", "off", off(*boxes([((0, 0, 0), (1, 1, 1), 0), ((1, 0, 0), (2, 1, 1), 0)])), 0)
    add("off_edge_touching_ok", "off", off(*boxes([((0, 0, 0), (1, 1, 1), 0), ((1, 1, 0), (2, 2, 1), 0)])), 0)
    add("off_same_cube_twice", "off", off(*boxes([((0, 0, 0), (1, 1, 1), 0), ((0, 0, 0), (1, 1, 1), 0)])), 1)
    # the same, sharing the vertices where they touch (edges with four faces)
    add("off_edge_touching_shared_ok", "off", off(*shared(*boxes([((0, 0, 0), (1, 1, 1), 0), ((1, 1, 0), (2, 2, 1), 0)]))), 0)
    add("off_face_touching_shared_ok", "off", off(*shared(*boxes([((0, 0, 0), (1, 1, 1), 0), ((1, 0, 0), (2, 1, 1), 0)]))), 0)
    # (CGAL's soup repair merges the repeated faces: the union, one cube, is summed)
    add("off_same_cube_twice_shared_ok", "off", off(*shared(*boxes([((0, 0, 0), (1, 1, 1), 0), ((0, 0, 0), (1, 1, 1), 0)]))), 0)
    add("off_overlapping_cubes_shared_edge", "off",
        off(*shared(*boxes([((0, 0, 0), (2, 2, 2), 0), ((0, 0, 0), (2, 3, 3), 0)]))), 1)
    si = list(CUBE)
    si[7] = (0.25, 0.5, -1)
    add("off_self_intersecting", "off", off(si, CUBE_F), 1)
    add("off_isolated_vertex_ok", "off", off(CUBE + [(5, 5, 5)], CUBE_F), 0)
    add("off_not_double", "off", off([(0.1, 0.2, 0.3)] + CUBE[1:], CUBE_F), 0)

    # OBJ
    add("obj_ok", "obj", obj(CUBE, CUBE_F), 0)
    add("obj_empty", "obj", "", 1)
    add("obj_no_faces", "obj", "".join("v %d %d %d\n" % p for p in CUBE), 1)
    add("obj_index_zero", "obj", obj(CUBE, CUBE_F, base=0), 1)
    add("obj_index_high", "obj", obj(CUBE, CUBE_F[:-1] + [(0, 1, 8)]), 1)
    add("obj_index_huge", "obj", obj(CUBE, CUBE_F[:-1] + [(0, 1, "4294967297")]), 1)
    add("obj_index_negative_ok", "obj", obj(CUBE, [tuple(str(i - 8) for i in f) for f in CUBE_F], base=0), 0)
    add("obj_index_negative_far", "obj", obj(CUBE, CUBE_F[:-1] + [(0, 1, "-100")]), 1)
    add("obj_two_vertices", "obj", obj(CUBE, CUBE_F[:-1] + [(0, 1)]), 1)
    add("obj_repeated", "obj", obj(CUBE, CUBE_F[:-1] + [(0, 1, 1)]), 1)
    add("obj_slashes_ok", "obj", obj(CUBE, [tuple("%d/%d/%d" % (i + 1, 1, 1) for i in f) for f in CUBE_F])
        + "vt 0 0\nvn 0 0 1\n", 0)
    add("obj_vertex_two_coords", "obj", "v 0 0\n" + obj(CUBE[1:], CUBE_F), 1)
    add("obj_vertex_nan", "obj", "v nan 0 0\n" + obj(CUBE[1:], [tuple(i + 1 for i in f) for f in CUBE_F]), 1)
    add("obj_vertex_text", "obj", "v a b c\n" + obj(CUBE, CUBE_F), 1)
    add("obj_face_text", "obj", obj(CUBE, CUBE_F) + "f a b c\n", 1)
    add("obj_random_bytes", "obj", bytes(range(256)) * 4, 1)
    add("obj_overlapping", "obj", obj(*boxes([((0, 0, 0), (2, 2, 2), 0), ((1, 1, 1), (3, 3, 3), 0)])), 1)

    # PLY ASCII
    add("plya_ok", "ply", ply_ascii(CUBE, CUBE_F), 0)
    add("plya_no_magic", "ply", ply_ascii(CUBE, CUBE_F)[4:], 1)
    add("plya_no_end_header", "ply", ply_ascii(CUBE, CUBE_F).replace(b"end_header", b"end_headr"), 1)
    add("plya_unknown_format", "ply", ply_ascii(CUBE, CUBE_F).replace(b"ascii", b"utf8"), 1)
    add("plya_unknown_type", "ply", ply_ascii(CUBE, CUBE_F).replace(b"property float x", b"property quad x"), 1)
    add("plya_no_x", "ply", ply_ascii(CUBE, CUBE_F).replace(b"property float x", b"property float w"), 1)
    add("plya_no_indices", "ply", ply_ascii(CUBE, CUBE_F).replace(b"vertex_indices", b"corners"), 1)
    add("plya_list_float_count", "ply", ply_ascii(CUBE, CUBE_F, count_type="float"), 1)
    add("plya_count_negative", "ply", ply_ascii(CUBE, CUBE_F, nf="-12"), 1)
    add("plya_count_text", "ply", ply_ascii(CUBE, CUBE_F, nv="eight"), 1)
    for nv, nf in [(8, 4e8), (4e8, 12), (8, 2**40), (10**19, 12), (10**30, 12)]:
        add("plya_count_huge_%g_%g" % (nv, nf), "ply", ply_ascii(CUBE, CUBE_F, nv="%d" % nv, nf="%d" % nf), 1)
    add("plya_more_faces", "ply", ply_ascii(CUBE, CUBE_F, nf=13), 1)
    add("plya_fewer_faces", "ply", ply_ascii(CUBE, CUBE_F, nf=4), 1)
    add("plya_index_high", "ply", ply_ascii(CUBE, CUBE_F[:-1] + [(0, 1, 8)]), 1)
    add("plya_index_negative", "ply", ply_ascii(CUBE, CUBE_F[:-1] + [(0, 1, -1)]), 1)
    add("plya_index_float", "ply", ply_ascii(CUBE, CUBE_F[:-1] + [(0, 1, 2.5)]), 1)
    add("plya_list_huge", "ply", ply_ascii(CUBE, CUBE_F).replace(b"\n3 1 3 7", b"\n2000000000 1 3 7"), 1)
    # a list count that overflows an integer type (UBSan in the error message; the readers' fuzzer)
    add("plya_list_1e308", "ply", ply_ascii(CUBE, CUBE_F).replace(b"\n3 1 3 7", b"\n1e308 1 3 7"), 1)
    add("plya_list_nan", "ply", ply_ascii(CUBE, CUBE_F).replace(b"\n3 1 3 7", b"\nnan 1 3 7"), 1)
    add("plya_list_two", "ply", ply_ascii(CUBE, CUBE_F[:-1] + [(0, 1)]), 1)
    add("plya_vertex_text", "ply", ply_ascii(CUBE, CUBE_F).replace(b"end_header\n0.0", b"end_header\nzero"), 1)
    add("plya_vertex_nan", "ply", ply_ascii(CUBE, CUBE_F).replace(b"end_header\n0.0", b"end_header\nnan"), 1)
    add("plya_comments_ok", "ply", ply_ascii(CUBE, CUBE_F, extra_header="comment hello\nobj_info x\n"), 0)
    add("plya_extra_element_ok", "ply", ply_ascii(CUBE, CUBE_F).replace(
        b"end_header\n", b"element edge 1\nproperty int a\nproperty int b\nend_header\n") + b"0 1\n", 0)
    add("plya_trailing_data", "ply", ply_ascii(CUBE, CUBE_F, tail="1 2 3\n"), 1)

    # PLY binary
    for e, name in (("<", "le"), (">", "be")):
        add("plyb_%s_ok" % name, "ply", ply_binary(CUBE, CUBE_F, endian=e), 0)
        add("plyb_%s_index_high" % name, "ply", ply_binary(CUBE, CUBE_F[:-1] + [(0, 1, 1000)], endian=e), 1)
        add("plyb_%s_index_negative" % name, "ply", ply_binary(CUBE, CUBE_F[:-1] + [(0, 1, -7)], endian=e), 1)
        add("plyb_%s_truncated" % name, "ply", ply_binary(CUBE, CUBE_F, endian=e)[:-7], 1)
    add("plyb_double_ok", "ply", ply_binary(CUBE, CUBE_F, coord_type="double"), 0)
    add("plyb_uint_count_ok", "ply", ply_binary(CUBE, CUBE_F, count_type="uint"), 0)
    add("plyb_uint_index_ok", "ply", ply_binary(CUBE, CUBE_F, index_type="uint"), 0)
    add("plyb_uchar_index_ok", "ply", ply_binary(CUBE, CUBE_F, index_type="uchar"), 0)
    add("plyb_list_2e9", "ply", ply_binary(CUBE, CUBE_F, count_type="uint", counts=[None] * 11 + [2000000000]), 1)
    add("plyb_list_4e9", "ply", ply_binary(CUBE, CUBE_F, count_type="uint", counts=[None] * 11 + [4000000000]), 1)
    add("plyb_list_negative", "ply", ply_binary(CUBE, CUBE_F, count_type="int", counts=[None] * 11 + [-3]), 1)
    add("plyb_list_zero", "ply", ply_binary(CUBE, CUBE_F[:-1] + [()]), 1)
    add("plyb_list_255", "ply", ply_binary(CUBE, CUBE_F, counts=[None] * 11 + [255]), 1)
    add("plyb_list_short", "ply", ply_binary(CUBE, CUBE_F, counts=[None] * 11 + [2]), 1)
    add("plyb_count_4e8", "ply", ply_binary(CUBE, CUBE_F, nf=400000000), 1)
    add("plyb_count_2e19", "ply", ply_binary(CUBE, CUBE_F, nv="20000000000000000000"), 1)
    add("plyb_count_more", "ply", ply_binary(CUBE, CUBE_F, nf=13), 1)
    add("plyb_count_fewer", "ply", ply_binary(CUBE, CUBE_F, nf=11), 1)
    add("plyb_trailing", "ply", ply_binary(CUBE, CUBE_F, tail=b"\0" * 13), 1)
    add("plyb_nan", "ply", ply_binary([(float("nan"), 0, 0)] + CUBE[1:], CUBE_F), 1)
    add("plyb_inf", "ply", ply_binary([(float("inf"), 0, 0)] + CUBE[1:], CUBE_F), 1)
    add("plyb_header_only", "ply", ply_binary(CUBE, CUBE_F).split(b"end_header\n")[0] + b"end_header\n", 1)
    add("plyb_no_newline_after_header", "ply", ply_binary(CUBE, CUBE_F).split(b"end_header\n")[0] + b"end_header", 1)
    add("plyb_overlapping", "ply", ply_binary(*boxes([((0, 0, 0), (2, 2, 2), 0), ((1, 1, 1), (3, 3, 3), 0)])), 1)

    # STL binary
    add("stlb_ok", "stl", stl_binary(CUBE, CUBE_F), 0)
    add("stlb_solid_header_ok", "stl", stl_binary(CUBE, CUBE_F, header=b"solid but binary"), 0)
    add("stlb_space_header_ok", "stl", stl_binary(CUBE, CUBE_F, header=b"   "), 0)
    for k, d in {"fewer": 3, "more": 13, "zero": 0, "huge": 10**9, "max": 2**32 - 1}.items():
        add("stlb_declared_" + k, "stl", stl_binary(CUBE, CUBE_F, declared=d), 1)
    add("stlb_trailing", "stl", stl_binary(CUBE, CUBE_F, tail=b"x"), 1)
    add("stlb_truncated", "stl", stl_binary(CUBE, CUBE_F)[:-1], 1)
    add("stlb_short", "stl", b"\0" * 83, 1)
    add("stlb_header_only", "stl", stl_binary(CUBE, []), 1)
    add("stlb_nan", "stl", stl_binary([(float("nan"), 0, 0)] + CUBE[1:], CUBE_F), 1)
    add("stlb_degenerate", "stl", stl_binary(CUBE, CUBE_F[:-1] + [(0, 1, 1)]), 1)
    add("stlb_open_ok", "stl", stl_binary(CUBE, CUBE_F[2:]), 0)

    # STL ASCII
    add("stla_ok", "stl", stl_ascii(CUBE, CUBE_F), 0)
    add("stla_no_endsolid", "stl", stl_ascii(CUBE, CUBE_F, end=False), 1)
    add("stla_text_coordinate", "stl", stl_ascii(CUBE, CUBE_F).replace("vertex 0.0 0.0 0.0", "vertex a b c", 1), 1)
    add("stla_two_coordinates", "stl", stl_ascii(CUBE, CUBE_F).replace("vertex 0.0 0.0 0.0", "vertex 0 0", 1), 1)
    add("stla_nan", "stl", stl_ascii(CUBE, CUBE_F).replace("vertex 0.0 0.0 0.0", "vertex nan 0 0", 1), 1)
    add("stla_missing_vertex", "stl", stl_ascii(CUBE, CUBE_F).replace("   vertex 0.0 0.0 0.0\n", "", 1), 1)
    add("stla_empty_solid", "stl", "solid x\nendsolid x\n", 1)
    add("stla_only_solid", "stl", "solid", 1)
    add("stla_random_after_solid", "stl", b"solid " + bytes(range(256)) * 3, 1)

    # Option values (on valid inputs written by the runner: cube.off, tet.off).
    def opt(name, args, code):
        C.append(("opt_" + name, None, None, code, args))
    for d, code in [("0", 2), ("-1", 2), ("nan", 2), ("inf", 2), ("-inf", 2), ("1e-300", 3), ("1e-12", 3),
                    ("1e308", 0), ("1e", 2), ("", 2), ("0x10", 0), ("1,5", 2), (" 1", 0), ("5e-324", 3)]:
        opt("d_" + d.replace(" ", "_"), ["-d", d], code)
    for t, code in [("0", 2), ("-1", 2), ("1.5", 2), ("abc", 2), ("1e9", 2), ("1", 0), ("1025", 2)]:
        opt("threads_" + t, ["-d", "0.5", "--threads", t], code)
    for s, code in [("0", 2), ("-1", 2), ("nan", 2), ("inf", 2), ("1e308", 3), ("1e-300", 0), ("1e300", 3)]:
        opt("scale_q_" + s, ["-d", "0.5", "--scale-q", s], code)
    for lv, code in [("0.4", 2), ("1,0.4", 2), ("abc", 2), ("", 2), ("2,,1", 2), ("0.6,0.8", 2), ("0.8,0.6", 0),
                     ("nan", 2), ("inf,1", 2)]:
        opt("levels_" + lv.replace(",", "_"), ["-d", "0.5", "--levels", lv], code)
    opt("relative_tiny", ["-d", "1e-9", "--relative"], 3)
    opt("relative_huge", ["-d", "1e9", "--relative"], 0)
    opt("missing_d_value", ["-d"], 2)
    opt("unknown_option", ["-d", "0.5", "--frobnicate"], 2)
    opt("output_directory", ["-d", "0.5", "-o", "DIR/"], 2)
    opt("output_missing_dir", ["-d", "0.5", "-o", "DIR/missing/out.ply"], 1)
    opt("output_is_input", ["-d", "0.5", "-o", "INPUT"], 2)
    opt("json_is_input", ["-d", "0.5", "--json", "INPUT"], 2)
    opt("json_missing_dir", ["-d", "0.5", "--json", "DIR/missing/x.json"], 1)
    opt("json_is_output", ["-d", "0.5", "--json", "DIR/out.xyz", "-o", "DIR/out.xyz"], 2)
    opt("json_dev_null", ["-d", "0.5", "--json", "/dev/null"], 1)
    opt("output_long_name", ["-d", "0.5", "-o", "DIR/" + "a" * 246 + ".xyz"], 0)
    opt("output_too_long_name", ["-d", "0.5", "-o", "DIR/" + "a" * 300 + ".xyz"], 1)
    return C


# Every command shares the readers and the input checks: each refused file is also given to
# the other commands (as their first mesh), which must refuse it the same way.
COMMANDS = {
    "offset": lambda f, o: ["offset", f, "-r", "0.25", "-d", "0.5", "-o", o],
    "erode": lambda f, o: ["offset", f, "--erode", "-r", "0.1", "-d", "0.5", "-o", o],
    "sweep": lambda f, o: ["sweep", f, "--path", "PATH", "-d", "0.5", "-o", o],
    "pd": lambda f, o: ["pd", f, "TET", "-d", "0.5", "--at", "0.2", "0.2", "0.2"],
    "plan": lambda f, o: ["plan", f, "TET", "-d", "0.5", "--start", "-5", "0", "0", "--goal", "5", "0", "0"],
    "validate": lambda f, o: ["validate", f, "TET", "-d", "0.5"],
}


def command_cases():
    """Options and side files of the other commands: (name, arguments, expected exit code).
    CUBE, TET, PATH (a valid 3-point polyline), DIR and OUT are replaced by the runner."""
    C = []

    def add(name, args, code):
        C.append(("cmd_" + name, args, code))
    off_ = ["offset", "CUBE", "-d", "0.5", "-o", "OUT"]
    for r, code in [("0", 2), ("-1", 2), ("nan", 2), ("inf", 2), ("1e308", 3), ("abc", 2), ("0.25", 0)]:
        add("offset_r_" + r, off_ + ["-r", r], code)
    for e, code in [("0", 2), ("1", 2), ("nan", 2), ("-0.1", 2), ("1e-300", 3), ("0.5", 0)]:
        add("offset_sphere_error_" + e, off_ + ["-r", "0.25", "--sphere-error", e], code)
    add("offset_cube", off_ + ["-r", "0.25", "--cube"], 0)
    add("erode_too_deep", off_ + ["-r", "5", "--erode"], 0)
    add("erode_open_mesh", ["offset", "DIR/open.off", "--erode", "-r", "0.1", "-d", "0.5", "-o", "OUT"], 1)
    add("offset_no_mesh", ["offset", "-r", "0.25", "-d", "0.5", "-o", "OUT"], 2)
    sw = ["sweep", "CUBE", "-d", "0.5", "-o", "OUT", "--path"]
    for name, text, code in [("ok", "0 0 0\n1 0 0\n1 1 0\n", 0), ("empty", "", 1), ("one_point", "0 0 0\n", 1),
                             ("repeated_point", "0 0 0\n0 0 0\n1 0 0\n", 1), ("nan", "0 0 0\nnan 0 0\n", 1),
                             ("inf", "0 0 0\ninf 0 0\n", 1), ("two_numbers", "0 0 0\n1 0\n", 1),
                             ("garbage", "\x00\xff garbage\n", 1), ("huge", "0 0 0\n1e308 0 0\n", 3),
                             ("comma", "0,0,0\n1,0,0\n", 1), ("extra_number", "0 0 0 1\n1 0 0\n", 1)]:
        add("sweep_path_" + name, sw + ["DIR/path_%s.txt" % name, "WRITE:" + text], code)
    add("sweep_path_missing", sw + ["DIR/missing.txt"], 1)
    add("sweep_path_directory", sw + ["DIR"], 1)
    pd = ["pd", "CUBE", "TET", "-d", "0.5"]
    for name, at, code in [("overlap", ["0.2", "0.2", "0.2"], 0), ("free", ["9", "9", "9"], 0),
                           ("nan", ["nan", "0", "0"], 2), ("two_values", ["1", "2"], 2), ("text", ["a", "b", "c"], 2),
                           ("huge", ["1e308", "0", "0"], 0), ("inf", ["inf", "0", "0"], 2)]:
        add("pd_at_" + name, pd + ["--at"] + at, code)
    add("pd_no_at", pd, 2)
    pl = ["plan", "CUBE", "TET", "-d", "0.5"]
    for name, extra, code in [("ok", ["--start", "-5", "0", "0", "--goal", "5", "0", "0"], 0),
                              ("start_overlaps", ["--start", "0.2", "0.2", "0.2", "--goal", "5", "0", "0"], 1),
                              ("nan_goal", ["--start", "-5", "0", "0", "--goal", "nan", "0", "0"], 2),
                              ("no_goal", ["--start", "-5", "0", "0"], 2),
                              ("two_starts", ["--start", "-5", "0", "0", "--start", "-6", "0", "0", "--goal", "5", "0", "0"], 2),
                              ("k_zero", ["--start", "-5", "0", "0", "--goal", "5", "0", "0", "-k", "0"], 2),
                              ("k_huge", ["--start", "-5", "0", "0", "--goal", "5", "0", "0", "-k", "1e12"], 2)]:
        add("plan_" + name, pl + extra, code)
    va = ["validate", "CUBE", "TET", "-d", "0.5"]
    add("validate_ok", va, 0)
    for name, content, code in [("empty", "", 1), ("garbage", "garbage\n", 1), ("binary", "\x00" * 64, 1),
                                ("truncated", "TRUNCATED", 1), ("header_only", "Selective Nef Complex\n", 1)]:
        add("validate_exact_" + name, va + ["--exact", "DIR/ref_%s.nef3" % name, "WRITE:" + content], code)
    add("validate_exact_missing", va + ["--exact", "DIR/missing.nef3"], 1)
    add("validate_save_exact_missing_dir", va + ["--save-exact", "DIR/missing/x.nef3"], 1)
    return C


def run(pmsum, args, cwd, as_limit=True):
    """(exit code or -signal, stdout, stderr, seconds, peak RSS in kB, timed out)."""
    def limits():
        if as_limit:
            resource.setrlimit(resource.RLIMIT_AS, (AS_LIMIT, AS_LIMIT))
    start = time.monotonic()
    with tempfile.TemporaryFile() as out, tempfile.TemporaryFile() as err:
        p = subprocess.Popen([pmsum] + args, stdout=out, stderr=err, cwd=cwd, preexec_fn=limits)
        timed_out = False
        while True:
            pid, status, usage = os.wait4(p.pid, os.WNOHANG)
            if pid == p.pid:
                break
            if time.monotonic() - start > TIMEOUT:
                p.kill()
                timed_out = True
                pid, status, usage = os.wait4(p.pid, 0)
                break
            time.sleep(0.01)
        code = os.waitstatus_to_exitcode(status)
        out.seek(0)
        err.seek(0)
        return code, out.read().decode(errors="replace"), err.read().decode(errors="replace"), \
            time.monotonic() - start, usage.ru_maxrss, timed_out


def digest(path):
    with open(path, "rb") as f:
        return hashlib.sha256(f.read()).hexdigest()


FUZZ_FORMAT = {"off": b"0", "ply": b"1", "stl": b"2", "obj": b"3"}


def write_seeds(directory):
    os.makedirs(directory, exist_ok=True)
    files = [("cube", "off", off(CUBE, CUBE_F)), ("tet", "off", off(TET, TET_F))]
    files += [(name, ext, content) for name, ext, content, _, _ in corpus() if ext is not None]
    for name, ext, content in files:
        with open(os.path.join(directory, name), "wb") as f:
            f.write(FUZZ_FORMAT[ext] + (content if isinstance(content, bytes) else content.encode()))
    print("%d seeds written to %s" % (len(files), directory))
    return 0


def check(pmsum, args, code, inputs, out_dir, work, as_limit=True):
    """Runs one case; (outcome, problems, stderr)."""
    before = {p: digest(p) for p in inputs if os.path.isfile(p)}
    got, stdout, stderr, seconds, rss, timed_out = run(pmsum, args, work, as_limit)
    outcome = ("hung" if timed_out else "crashed" if got < 0 or got >= 128 else
               "accepted" if got == 0 else "refused (exit %d)" % got)
    problems = []
    if timed_out:
        problems.append("hang (> %d s)" % TIMEOUT)
    elif got < 0 or got >= 128:
        problems.append("crash (exit %d)" % got)
    elif got != code:
        problems.append("exit %d, expected %d" % (got, code))
    lines = [l for l in stderr.splitlines() if "note:" not in l]
    if not timed_out and got in CLASSES and got == code and got != 0:
        if not lines or not CLASSES[got].search(lines[0]):
            problems.append("message class: %r" % (lines[:1],))
        elif len(lines) != 1:
            problems.append("error is not one line: %r" % lines)
    if rss > RSS_LIMIT_KB:
        problems.append("peak RSS %d MiB" % (rss // 1024))
    left = [f for f in os.listdir(out_dir) if got != 0 or f.startswith(".pmsum-")]
    left += [f for f in os.listdir(work) if f.startswith(".pmsum-")]
    if left:
        problems.append("files left behind: %s" % left[:3])
    for p, h in before.items():
        if os.path.exists(p) and digest(p) != h:
            problems.append("input changed: %s" % os.path.basename(p))
    return outcome, problems, stderr


def clear(out_dir):
    for f in os.listdir(out_dir):
        os.remove(os.path.join(out_dir, f))


def main():
    if len(sys.argv) < 2:
        print(__doc__)
        return 2
    if sys.argv[1] == "--seeds":
        return write_seeds(sys.argv[2])
    pmsum = os.path.abspath(sys.argv[1])
    as_limit = "--no-as-limit" not in sys.argv
    cases = corpus()
    if "--list" in sys.argv:
        for name, ext, _, code, _ in cases:
            print(code, name)
        for name, _, code in command_cases():
            print(code, name)
        return 0
    keep = sys.argv[sys.argv.index("--keep") + 1] if "--keep" in sys.argv else None
    work = keep or tempfile.mkdtemp(prefix="pmsum-corpus-")
    os.makedirs(work, exist_ok=True)
    cube, tet, path = (os.path.join(work, n) for n in ("cube.off", "tet.off", "path.txt"))
    for name, text in [(cube, off(CUBE, CUBE_F)), (tet, off(TET, TET_F)), (path, "0 0 0\n1 0 0\n1 1 0\n"),
                       (os.path.join(work, "open.off"), off(CUBE, CUBE_F[2:]))]:
        with open(name, "w") as f:
            f.write(text)
    out_dir = os.path.join(work, "out")
    os.makedirs(out_dir, exist_ok=True)
    out = os.path.join(out_dir, "out.xyz")
    results = collections.Counter()
    outcomes = collections.Counter()

    def record(label, outcome, problems, stderr):
        outcomes[outcome] += 1
        results["failed" if problems else "passed"] += 1
        if problems:
            print("FAILED %s: %s" % (label, "; ".join(problems)))
            for l in stderr.splitlines()[-3:]:
                print("    " + l[:200])
        clear(out_dir)

    def output_bytes():
        with open(out, "rb") as f:
            return f.read()

    # 1. hostile files (as P of sum), and option values of sum
    for name, ext, content, code, extra in cases:
        if ext is not None:
            file = os.path.join(work, name + "." + ext)
            with open(file, "wb") as f:
                f.write(content if isinstance(content, bytes) else content.encode())
            args = ["sum", file, tet, "-d", "0.5", "-o", out]
        else:
            file = cube
            extra = [a.replace("DIR", out_dir).replace("INPUT", cube) for a in extra]
            if "-o" not in extra:
                extra += ["-o", out]
            if extra[:1] == ["-d"] and len(extra) == 1:
                extra = ["-o", out, "-d"]
            args = ["sum", cube, tet] + extra
        outcome, problems, stderr = check(pmsum, args, code, [file, cube, tet], out_dir, work, as_limit)
        # valid inputs: one thread and three give the same bytes
        if ext is not None and code == 0 and not problems:
            first = output_bytes()
            for threads in ("1", "3"):
                clear(out_dir)
                o2, p2, _ = check(pmsum, args + ["--threads", threads], 0, [file], out_dir, work, as_limit)
                problems += p2
                if not p2 and output_bytes() != first:
                    problems.append("--threads %s: output differs" % threads)
            results["thread checks"] += 1
        record(name, outcome, problems, stderr)

    # 2. every refused file through the other commands
    for name, ext, content, code, extra in cases:
        if ext is None or code != 1:
            continue
        file = os.path.join(work, name + "." + ext)
        for command, make in COMMANDS.items():
            args = [a.replace("PATH", path).replace("TET", tet) for a in make(file, out)]
            record("%s (%s)" % (name, command), *check(pmsum, args, code, [file, tet, path], out_dir, work, as_limit))

    # 3. options and side files of the other commands
    truncated = None
    for name, args, code in command_cases():
        args = [a.replace("CUBE", cube).replace("TET", tet).replace("DIR", work).replace("OUT", out) for a in args]
        if any(a.startswith("WRITE:") for a in args):
            i = next(i for i, a in enumerate(args) if a.startswith("WRITE:"))
            text = args.pop(i)[len("WRITE:"):]
            if text == "TRUNCATED":
                if truncated is None:
                    ref = os.path.join(work, "ref.nef3")
                    run(pmsum, ["validate", cube, tet, "-d", "0.5", "--save-exact", ref], work, as_limit)
                    with open(ref, "rb") as f:
                        data = f.read()
                    truncated = data[: len(data) // 2]
                    os.remove(ref)
                content = truncated
            else:
                content = text.encode("latin-1")
            with open(args[i - 1], "wb") as f:
                f.write(content)
        record(name, *check(pmsum, args, code, [cube, tet, path], out_dir, work, as_limit))

    os.rmdir(out_dir)
    if not keep:
        for f in os.listdir(work):
            os.remove(os.path.join(work, f))
        os.rmdir(work)
    print("outcomes: " + ", ".join("%s %d" % kv for kv in sorted(outcomes.items())))
    print("valid inputs with 1 = 2 = 3 threads checked: %d" % results["thread checks"])
    print("corpus: %d passed, %d failed" % (results["passed"], results["failed"]))
    return 0 if results["failed"] == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
