# Sourced by the tool's shell tests (cli_test.sh, mpi_test.sh), called as
#   TEST.sh PMSUM_BINARY DATA_DIR
# Sets pmsum, data and a scratch directory work (removed at exit); ok and ko count the checks,
# summary NAME prints them and fails if one failed.
set -u
pmsum=$1
data=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
passed=0
failed=0
ok() { passed=$((passed + 1)); }
ko() { failed=$((failed + 1)); echo "FAILED: $*"; }
summary() {
  echo "$1: $passed passed, $failed failed"
  [ "$failed" = 0 ]
}
