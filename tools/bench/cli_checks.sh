# Shared by the benchmarks' command-line checks (check_*_bench_cli.sh): source it, set `bench`,
# then `expects CODE 'MESSAGE' ARGS...` runs the benchmark with ARGS and fails unless it exits
# with CODE and prints MESSAGE (a grep pattern); its output is left in `out`.
fail() { echo "FAIL: $*"; exit 1; }

expects() {
  local code="$1" message="$2"
  shift 2
  out=$("$bench" "$@" 2>&1)
  local rc=$?
  [ "$rc" -eq "$code" ] || fail "$* exited $rc, expected $code"
  grep -q -- "$message" <<<"$out" || fail "$* did not say '$message': $out"
}
