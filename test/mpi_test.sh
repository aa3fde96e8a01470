#!/usr/bin/env bash
# mpirun -np 2 pmsum ... against one process (the tool built with -DCGAL_PMSUM_WITH_MPI=ON):
# the same output files byte for byte and the same JSON counts; a bad input ends every rank
# with one error line and no output file.
#   mpi_test.sh PMSUM_BINARY DATA_DIR
. "$(dirname "$0")/script_common.sh"

# Two ranks on any machine (--oversubscribe), also as root (as CI runs); a hung rank is a failure.
launcher=(mpirun --oversubscribe -np 2)
[ "$(id -u)" = 0 ] && launcher+=(--allow-run-as-root)
two() { timeout 600 "${launcher[@]}" "$pmsum" "$@"; }

# The JSON summary without what may differ: seconds, the output's name, the ranks' shares.
counts() {
  /usr/bin/env python3 - "$1" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
def strip(x):
    if isinstance(x, dict):
        return {k: strip(v) for k, v in x.items() if k not in ("seconds", "output", "ranks", "processes")}
    return x
print(json.dumps(strip(j), sort_keys=True))
PY
}

# same_run NAME ARGS... : pmsum ARGS -o OUT.EXT --json J, once alone and once on two ranks
same_run() {
  local name=$1 ext=$2
  shift 2
  "$pmsum" "$@" -o "$work/one.$ext" --json "$work/one.json" --quiet || { ko "$name: one process failed"; return; }
  two "$@" -o "$work/two.$ext" --json "$work/two.json" --quiet > "$work/out" 2>&1 || { ko "$name: two ranks failed"; cat "$work/out"; return; }
  if ! cmp -s "$work/one.$ext" "$work/two.$ext"; then ko "$name: the output differs"; return; fi
  if [ "$(counts "$work/one.json")" != "$(counts "$work/two.json")" ]; then
    ko "$name: the JSON counts differ"; diff <(counts "$work/one.json") <(counts "$work/two.json"); return
  fi
  # each rank's share is reported (sum's summary), and every candidate was decided once (the
  # pieces cut every feature pair into one or more)
  if ! /usr/bin/env python3 -c "
import json, sys
j = json.load(open('$work/two.json'))
if 'feature_pairs' not in j: sys.exit(0)
r = j['ranks']
sys.exit(0 if j['processes'] == 2 and len(r) == 2 and sum(x['pieces'] for x in r) >= j['feature_pairs']
         and sum(x['candidates'] for x in r) == j['candidates'] and all(x['pieces'] > 0 for x in r) else 1)"; then
    ko "$name: the ranks' shares are missing or do not add up"; return
  fi
  ok
}

"$pmsum" generate l-shape -o "$work/l-shape.off" && "$pmsum" generate cube -o "$work/cube.off"
"$pmsum" generate tunnel -o "$work/tunnel.off" && "$pmsum" generate tunnel-cube-rotated -o "$work/tunnel-cube.off"
same_run "knot1 + tetrahedron/32, PLY" ply sum "$data/knot1.off" "$data/tetrahedron.off" --scale-q 0.03125 -d 0.01 --relative --threads 1
same_run "l-shape + cube, XYZ" xyz sum "$work/l-shape.off" "$work/cube.off" -d 0.02 --relative
same_run "narrow tunnel (trim points), PLY" ply sum "$work/tunnel.off" "$work/tunnel-cube.off" -d 0.03 --relative
same_run "offset of the octahedron" ply offset "$data/octahedron.off" -r 0.1 -d 0.05 --relative

# Coarse to fine (--levels): every level's file too (the decisions reused travel with the ranks).
levels=(sum "$work/l-shape.off" "$work/cube.off" -d 0.02 --relative --levels 0.05 --quiet)
"$pmsum" "${levels[@]}" -o "$work/lv1.ply" && two "${levels[@]}" -o "$work/lv2.ply" > "$work/out" 2>&1
if [ $? != 0 ]; then ko "levels: a run failed"; cat "$work/out"
elif ! cmp -s "$work/lv1.level0.ply" "$work/lv2.level0.ply" || ! cmp -s "$work/lv1.ply" "$work/lv2.ply"; then ko "levels: a level differs"
else ok; fi

# Bad input: every rank ends, with one error line (rank 0's), exit code 1, no output file.
printf 'OFF\n3 1 0\n0 0 0\n1 0 0\n' > "$work/broken.off"
rm -f "$work"/bad.*
two sum "$work/broken.off" "$data/tetrahedron.off" -d 0.1 -o "$work/bad.ply" > "$work/stdout" 2> "$work/stderr"
code=$?
if [ "$code" = 124 ]; then ko "bad input: the ranks hung"
elif [ "$code" = 0 ]; then ko "bad input: exit code 0"
elif [ "$(grep -o 'pmsum: error' "$work/stderr" | wc -l)" != 1 ]; then ko "bad input: not one error line"; cat "$work/stderr"
elif ls "$work"/bad.* "$work"/.pmsum-* > /dev/null 2>&1; then ko "bad input: output file left behind"
else ok; fi

# Commands that do not share their work are refused under mpirun, with one line.
two pd "$data/octahedron.off" "$data/tetrahedron.off" -d 0.1 --at 0 0 0 > "$work/stdout" 2> "$work/stderr"
if [ $? = 0 ] || [ "$(grep -o 'pmsum: under mpirun' "$work/stderr" | wc -l)" != 1 ]; then ko "pd under mpirun is not refused with one line"; cat "$work/stderr"; else ok; fi

summary mpi_test
