#!/usr/bin/env bash
# Runs the readers' fuzzer (test/fuzz/fuzz_readers.cpp) from the hostile-input corpus's seeds
# and prints its executions and coverage; fails on a finding (crash, sanitizer report, timeout
# of one input, RSS over 2 GiB, unexpected exception), whose input is left in WORK/.
#
#   test/fuzz/run_fuzzer.sh [SECONDS] [--fuzzer PATH] [--work DIR] [--seed N] [--no-results]
#
# SECONDS defaults to 1200. The fuzzer is built by the sanitizer build (PMSUM_SANITIZE=ON,
# clang: `scripts/quickstart.sh test` makes build-san/); PATH defaults to
# build-san/test/fuzz_readers. WORK (default build-san/fuzz) receives the inputs the run
# found new and any crashing input. Unless --no-results (CTest's 60 s run), the figures are
# written to benchmark/results/fuzz_readers.md.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
seconds=1200
fuzzer=$root/build-san/test/fuzz_readers
work=$root/build-san/fuzz
seed=1
results=$root/benchmark/results/fuzz_readers.md
while [ $# -gt 0 ]; do
  case "$1" in
    --fuzzer) fuzzer=$2; shift 2 ;;
    --work) work=$2; shift 2 ;;
    --seed) seed=$2; shift 2 ;;
    --no-results) results=""; shift ;;
    [0-9]*) seconds=$1; shift ;;
    *) echo "usage: run_fuzzer.sh [SECONDS] [--fuzzer PATH] [--work DIR] [--seed N] [--no-results]" >&2; exit 2 ;;
  esac
done
[ -x "$fuzzer" ] || { echo "run_fuzzer.sh: no fuzzer at $fuzzer (build with -DPMSUM_SANITIZE=ON and clang)" >&2; exit 2; }

rm -rf "$work"
mkdir -p "$work/seeds" "$work/new" "$work/artifacts"
python3 "$root/test/corpus/make_corpus.py" --seeds "$work/seeds" > /dev/null
nseeds=$(ls "$work/seeds" | wc -l)

# -max_len: the corpus's files are at most a few kB but one (a 1 MB line), which is cut.
options=(-seed="$seed" -max_total_time="$seconds" -rss_limit_mb=2048 -malloc_limit_mb=2048 -timeout=30
         -max_len=16384 -dict="$root/test/fuzz/readers.dict" -print_final_stats=1
         -artifact_prefix="$work/artifacts/")
echo "run_fuzzer.sh: $fuzzer ${options[*]} ($nseeds seeds)"
commit=$(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo '?')
start=$(date +%s)
set +e
"$fuzzer" "${options[@]}" "$work/new" "$work/seeds" > "$work/log" 2>&1
code=$?
set -e
elapsed=$(( $(date +%s) - start ))

# libFuzzer's last status line ("#N DONE cov: C ft: F corp: ...") and its final stats (printed
# twice after a crash)
last=$(grep -E '^#[0-9]+' "$work/log" | tail -1 || true)
cov=$(sed -nE 's/.* cov: ([0-9]+).*/\1/p' <<< "$last")
ft=$(sed -nE 's/.* ft: ([0-9]+).*/\1/p' <<< "$last")
corp=$(sed -nE 's/.* corp: ([0-9]+\/[0-9]+[a-zA-Z]*).*/\1/p' <<< "$last")
execs=$(sed -nE 's/^stat::number_of_executed_units: ([0-9]+)/\1/p' "$work/log" | tail -1)
rate=$(sed -nE 's/^stat::average_exec_per_sec: +([0-9]+)/\1/p' "$work/log" | tail -1)
newunits=$(sed -nE 's/^stat::new_units_added: +([0-9]+)/\1/p' "$work/log" | tail -1)
rss=$(sed -nE 's/^stat::peak_rss_mb: +([0-9]+)/\1/p' "$work/log" | tail -1)
artifacts=$(ls "$work/artifacts" | wc -l)
echo "executions: ${execs:-?} in ${elapsed} s (${rate:-?}/s); cov: ${cov:-?} ft: ${ft:-?} corpus: ${corp:-?}" \
     "(new units: ${newunits:-?}); peak RSS ${rss:-?} MB; findings: $artifacts; exit $code"

if [ -n "$results" ]; then
  mkdir -p "$(dirname "$results")"
  {
    echo "# Readers' fuzzer: one run"
    echo
    echo "\`test/fuzz/run_fuzzer.sh $seconds\`, $(date -u +%Y-%m-%d), commit $commit, seed $seed," \
         "$(nproc) cores shared with other work, clang $(clang++ -dumpversion 2>/dev/null || echo '?')," \
         "-fsanitize=fuzzer,address,undefined -O1. Target: test/fuzz/fuzz_readers.cpp (readers of" \
         "src/cli_input.h, mesh_from_soup, the library's make_mesh_data with the solid checks)."
    echo
    echo "| figure | value |"
    echo "|---|---|"
    echo "| seconds | $elapsed |"
    echo "| seeds (make_corpus.py --seeds) | $nseeds |"
    echo "| executions (stat::number_of_executed_units) | ${execs:-?} |"
    echo "| executions per second | ${rate:-?} |"
    echo "| coverage: cov (edges) / ft (features) | ${cov:-?} / ${ft:-?} |"
    echo "| corpus at the end (inputs/bytes) | ${corp:-?} |"
    echo "| new inputs found | ${newunits:-?} |"
    echo "| peak RSS (MB) | ${rss:-?} |"
    echo "| findings (crash, leak, timeout, OOM, unexpected exception) | $artifacts |"
    echo "| libFuzzer's exit code | $code |"
    echo
    echo "libFuzzer's options: \`${options[*]}\`."
  } > "$results"
  echo "run_fuzzer.sh: figures written to $results"
fi
if [ "$code" != 0 ] || [ "$artifacts" != 0 ]; then
  echo "run_fuzzer.sh: FINDING: libFuzzer exit $code, inputs in $work/artifacts:" >&2
  ls "$work/artifacts" >&2
  grep -E -A30 'ERROR|runtime error|unexpected exception|SUMMARY|==ERROR' "$work/log" | head -60 >&2
  exit 1
fi
