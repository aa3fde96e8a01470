#!/usr/bin/env bash
# Tests of the pmsum command-line tool: good runs, and bad input that must give a one-line
# error, a non-zero exit code and no output file.
#   cli_test.sh PMSUM_BINARY DATA_DIR
set -u
pmsum=$1
data=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
passed=0
failed=0

ok() { passed=$((passed + 1)); }
ko() { failed=$((failed + 1)); echo "FAILED: $*"; }

# expect_fail CODE PATTERN -- ARGS... : exit code CODE, stderr matches PATTERN, no $work/out.*
expect_fail() {
  local code=$1 pattern=$2
  shift 3
  rm -f "$work"/out.*
  "$pmsum" "$@" > "$work/stdout" 2> "$work/stderr"
  local got=$?
  if [ "$got" != "$code" ]; then ko "exit $got, expected $code: pmsum $*"; cat "$work/stderr"; return; fi
  if ! grep -q -- "$pattern" "$work/stderr"; then ko "stderr lacks '$pattern': pmsum $*"; cat "$work/stderr"; return; fi
  if [ "$(grep -vc "note:" "$work/stderr")" -gt 1 ]; then ko "error is not one line: pmsum $*"; cat "$work/stderr"; return; fi
  if ls "$work"/out.* > /dev/null 2>&1; then ko "output file left behind: pmsum $*"; return; fi
  ok
}

tet="$data/tetrahedron.off"
cube="$work/cube.off"
cat > "$cube" <<'EOF'
OFF
8 6 0
0 0 0
1 0 0
1 1 0
0 1 0
0 0 1
1 0 1
1 1 1
0 1 1
4 0 3 2 1
4 4 5 6 7
4 0 1 5 4
4 1 2 6 5
4 2 3 7 6
4 3 0 4 7
EOF

# --- good runs -------------------------------------------------------------------------
"$pmsum" sum "$cube" "$tet" -d 0.2 -o "$work/ok.xyz" --json "$work/ok.json" 2> "$work/stderr"
if [ $? = 0 ] && grep -q "triangulated 6 non-triangle faces" "$work/stderr" \
   && grep -q "reversed 4 of 4 faces" "$work/stderr"; then ok; else ko "quads + inward tetrahedron"; cat "$work/stderr"; fi
n=$(wc -l < "$work/ok.xyz")
if grep -q "\"output_points\": $n," "$work/ok.json" && [ "$n" -gt 100 ]; then ok; else ko "xyz lines ($n) vs JSON"; fi
for key in '"samples"' '"candidates"' '"cd_queries"' '"normal_filter"' '"cd_filter"' '"total"'; do
  if grep -q "$key" "$work/ok.json"; then ok; else ko "JSON lacks $key"; fi
done
# every xyz line: six numbers, unit normal
if awk 'NF != 6 { bad = 1 } { l = $4*$4 + $5*$5 + $6*$6; if (l < 0.999999 || l > 1.000001) bad = 1 } END { exit bad }' "$work/ok.xyz"; then ok; else ko "xyz format"; fi
# cube [0,1]^3 + tetrahedron of size 1 at the origin: the sum lies in [0,2]^3, and its
# bounding box is exactly [0,2]^3
if awk '{ for (i = 1; i <= 3; ++i) { if ($i < lo[i] || NR == 1) lo[i] = $i; if ($i > hi[i] || NR == 1) hi[i] = $i } }
        END { for (i = 1; i <= 3; ++i) if (lo[i] != 0 || hi[i] != 2) exit 1 }' "$work/ok.xyz"; then ok; else ko "bounding box of cube + tetrahedron"; fi

"$pmsum" sum "$cube" "$tet" -d 0.01 --relative -o "$work/ok.ply" --quiet 2> "$work/stderr"
count=$(head -c 400 "$work/ok.ply" | grep -a "element vertex" | awk '{print $3}')
size=$(stat -c %s "$work/ok.ply")
header=$(head -c 400 "$work/ok.ply" | grep -a -b "end_header" | cut -d: -f1)
if [ -n "$count" ] && [ $((size - header - 11)) = $((count * 48)) ] && [ ! -s "$work/stderr" ]; then ok; else ko "binary PLY size ($size, $count points)"; fi

"$pmsum" sum "$cube" "$tet" -d 0.2 --negate-p --no-normal-filter -o "$work/neg.xyz" --quiet && ok || ko "--negate-p --no-normal-filter"
"$pmsum" sum "$cube" "$tet" -d 0.2 --no-cd-filter -o "$work/nocd.xyz" --quiet && ok || ko "--no-cd-filter"
if [ "$(wc -l < "$work/nocd.xyz")" -ge "$n" ]; then ok; else ko "--no-cd-filter writes every candidate"; fi

# Non-manifold input (two cubes sharing an edge, as one soup) and an open mesh.
cat > "$work/two.off" <<'EOF'
OFF
14 12 0
0 0 0
1 0 0
1 1 0
0 1 0
0 0 1
1 0 1
1 1 1
0 1 1
2 1 0
2 2 0
1 2 0
2 1 1
2 2 1
1 2 1
4 0 3 2 1
4 4 5 6 7
4 0 1 5 4
4 1 2 6 5
4 2 3 7 6
4 3 0 4 7
4 2 10 9 8
4 6 11 12 13
4 2 8 11 6
4 8 9 12 11
4 9 10 13 12
4 10 2 6 13
EOF
"$pmsum" sum "$work/two.off" "$tet" -d 0.2 -o "$work/two.xyz" --quiet && ok || ko "non-manifold blocks"
"$pmsum" sum "$data/open_cube.off" "$data/ellipsoid.off" -d 0.05 --relative -o "$work/open.xyz" --quiet && ok || ko "open cube + ellipsoid"

# --- other commands ----------------------------------------------------------------------
"$pmsum" generate plates -o "$work/plates.off" && "$pmsum" generate cube-small -o "$work/small.off" && ok || ko "generate"
"$pmsum" validate "$work/plates.off" "$work/small.off" -d 0.05 --relative --quiet --json "$work/v.json" > "$work/v.txt"
if [ $? = 0 ] && grep -q "verdict           OK" "$work/v.txt" && grep -q '"void_shells": 1' "$work/v.json" \
   && grep -q '"exactness_failures": 0' "$work/v.json"; then ok; else ko "validate (difficult void)"; cat "$work/v.txt"; fi
"$pmsum" offset "$cube" -r 0.1 -d 0.05 -o "$work/off.xyz" --json "$work/off.json" --quiet && grep -q '"ball_inradius"' "$work/off.json" && ok || ko "offset"
# every offset point is within [inradius, r] of the unit cube
inner=$(grep '"ball_inradius"' "$work/off.json" | tr -dc '0-9.e-')
if awk -v lo="$inner" 'function d(x) { return x < 0 ? -x : (x > 1 ? x - 1 : 0) }
      { e = sqrt(d($1)^2 + d($2)^2 + d($3)^2); if (e < lo - 1e-9 || e > 0.1 + 1e-9) bad = 1 } END { exit bad }' "$work/off.xyz"; then ok; else ko "offset distances"; fi
"$pmsum" offset "$cube" -r 0.1 -d 0.05 --erode -o "$work/ero.xyz" --quiet && [ -s "$work/ero.xyz" ] && ok || ko "erosion"
out=$("$pmsum" pd "$cube" "$cube" -d 0.05 --at 0.1 0 0 --at 3 3 3 --quiet)
if echo "$out" | head -1 | grep -q "overlap 0.9" && echo "$out" | tail -1 | grep -q "free"; then ok; else ko "pd: $out"; fi
printf '0 0 0\n1 0 0\n' > "$work/path.txt"
"$pmsum" sweep "$cube" --path "$work/path.txt" -d 0.1 -o "$work/sweep.xyz" --quiet && ok || ko "sweep"
if awk '{ if ($1 < 0 || $1 > 2 || $2 < 0 || $2 > 1 || $3 < 0 || $3 > 1) bad = 1 } END { exit bad }' "$work/sweep.xyz"; then ok; else ko "sweep bounds"; fi
printf '0 0 0\nnot numbers\n' > "$work/badpath.txt"
expect_fail 1 "expected three numbers" -- sweep "$cube" --path "$work/badpath.txt" -d 0.1 -o "$work/out.xyz"

# plan: the robot (unit cube) out of a pocket under a lid; every vertex printed, start and goal
# at the ends; an unreachable goal (outside a closed room) exits 5; overlapping start exits 1.
"$pmsum" generate pocket -o "$work/pocket.off" && "$pmsum" generate slot-room -o "$work/room.off" && ok || ko "generate pocket"
if "$pmsum" plan "$cube" "$work/pocket.off" --start 0.03125 0.03125 0.03125 --goal 2.875 0.03125 1.8125 -d 0.5 \
     -o "$work/plan.txt" --json "$work/plan.json" --quiet > "$work/plan_stdout"; then ok; else ko "plan"; fi
if [ "$(head -1 "$work/plan.txt")" = "0.03125 0.03125 0.03125" ] && [ "$(tail -1 "$work/plan.txt")" = "2.875 0.03125 1.8125" ] \
   && cmp -s "$work/plan.txt" "$work/plan_stdout"; then ok; else ko "plan path ends"; fi
grep -q '"found": true' "$work/plan.json" && ok || ko "plan json"
expect_fail 5 "no path found" -- plan "$cube" "$work/room.off" --start -1.125 -0.875 0 --goal 5 5 5 -d 0.5 -o "$work/out.txt"
expect_fail 1 "not free"      -- plan "$cube" "$work/pocket.off" --start 0.5 0.5 -0.5 --goal 3 3 3 -d 0.5 -o "$work/out.txt"
expect_fail 2 "three numbers" -- plan "$cube" "$work/pocket.off" --start 0.5 0.5 --goal 3 3 3 -d 0.5
expect_fail 2 "needs -d"      -- plan "$cube" "$work/pocket.off" --start 0 0 0 --goal 3 3 3
expect_fail 2 "three numbers" -- pd "$cube" "$cube" -d 0.1 --at 1 2

# --- bad input --------------------------------------------------------------------------
printf 'OFF\n3 1 0\n0 0 0\n1 0 0\n' > "$work/truncated.off"
printf 'this is not a mesh\n' > "$work/garbage.off"
printf 'OFF\n0 0 0\n' > "$work/empty.off"
printf 'OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\nnan 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n' > "$work/nan.off"
printf 'OFF\n4 2 0\n0 0 0\n1 0 0\n2 0 0\n0 1 1\n3 0 1 3\n3 1 0 2\n' > "$work/degenerate.off"

expect_fail 1 "no such file"  -- sum "$work/missing.off" "$tet" -d 0.1 -o "$work/out.ply"
expect_fail 1 "malformed"     -- sum "$work/garbage.off" "$tet" -d 0.1 -o "$work/out.ply"
expect_fail 1 "P ("            -- sum "$work/truncated.off" "$tet" -d 0.1 -o "$work/out.ply"
expect_fail 1 "no faces"      -- sum "$work/empty.off" "$tet" -d 0.1 -o "$work/out.ply"
expect_fail 1 "Q ("            -- sum "$tet" "$work/nan.off" -d 0.1 -o "$work/out.ply"
expect_fail 1 "degenerate"    -- sum "$tet" "$work/degenerate.off" -d 0.1 -o "$work/out.ply"
expect_fail 1 "unknown format" -- sum "$work/cube.txt" "$tet" -d 0.1 -o "$work/out.ply"
expect_fail 2 "positive"      -- sum "$cube" "$tet" -d 0 -o "$work/out.ply"
expect_fail 2 "positive"      -- sum "$cube" "$tet" -d -1 -o "$work/out.ply"
expect_fail 2 "needs a number" -- sum "$cube" "$tet" -d abc -o "$work/out.ply"
expect_fail 2 ".ply or .xyz"  -- sum "$cube" "$tet" -d 0.1 -o "$work/out.txt"
expect_fail 2 "unknown option" -- sum "$cube" "$tet" -d 0.1 -o "$work/out.ply" --bogus
expect_fail 2 "two meshes"    -- sum "$cube" -d 0.1 -o "$work/out.ply"
expect_fail 2 "unknown command" -- frobnicate
expect_fail 3 "candidate points" -- sum "$data/knot1.off" "$data/elephant.off" -d 0.00002 --relative -o "$work/out.ply"
expect_fail 1 "too small"     -- sum "$cube" "$tet" -d 1e-9 -o "$work/out.ply" --force

echo "cli: $passed passed, $failed failed"
[ "$failed" = 0 ]
