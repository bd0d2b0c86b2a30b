# Timing for scripts/test.sh (sourced, not run): `phase NAME CMD...` runs one phase and records
# its wall time; `suite PRESET CMD...` runs a ctest command with its output kept in
# build/PRESET/ctest.log, from which the report takes each test's time. The report prints when
# the script exits, passed or failed, so a red or slow run still says where its time went.

timing_start=$(date +%s)
timing_phases=()
# CI's budget for the whole run on its 2-core machine (issue 32).
timing_budget_s=${FLOODLIGHT_TEST_BUDGET_S:-2400}
# A release test slower than this needs a comment saying why (tests/README of the budget).
timing_slow_test_s=30

phase() {
  local name=$1 t0 rc=0
  shift
  t0=$(date +%s)
  "$@" || rc=$?
  timing_phases+=("$name|$(($(date +%s) - t0))|$rc")
  return "$rc"
}

suite() {
  local preset=$1
  shift
  mkdir -p "build/$preset"
  # pipefail (set by the caller) keeps ctest's status through tee.
  "$@" 2>&1 | tee "build/$preset/ctest.log"
}

# "  12/733 Test  #45: Name ....   Passed   3.21 sec" -> "Name 3.21" for every finished test.
timing_test_times() {
  [ -f "$1" ] || return 0
  sed -n 's/^ *[0-9]*\/[0-9]* *Test *#[0-9]*: \([^ ]*\) .* \([0-9.]*\) sec$/\1 \2/p' "$1"
}

timing_report() {
  local rc=$? total entry name secs status
  # The report must never change the run's status: no errexit or pipefail in here (a `head`
  # that closes its pipe early once made a green run exit 141).
  set +e +o pipefail
  total=$(($(date +%s) - timing_start))
  {
    echo
    echo "== timing report ($(nproc) cores, $(date -u +%Y-%m-%dT%H:%MZ), $(git rev-parse --short HEAD 2>/dev/null || echo '?')) =="
    for entry in "${timing_phases[@]}"; do
      IFS='|' read -r name secs status <<<"$entry"
      printf '  %-20s %6d s%s\n' "$name" "$secs" "$([ "$status" = 0 ] || echo "  (failed, exit $status)")"
    done
    printf '  %-20s %6d s (%d min)\n' "total" "$total" "$((total / 60))"
    echo "-- 15 slowest tests (s): release, asan --"
    LC_ALL=C join -a 1 -e - -o 0,1.2,2.2 \
      <(timing_test_times build/release/ctest.log | LC_ALL=C sort -k1,1) \
      <(timing_test_times build/asan/ctest.log | LC_ALL=C sort -k1,1) |
      sort -k2,2 -g -r | awk 'NR <= 15 { printf "  %7s %7s  %s\n", $2, $3, $1 }'
    local slow
    slow=$(timing_test_times build/release/ctest.log | awk -v s="$timing_slow_test_s" '$2 > s' | wc -l)
    [ "$slow" = 0 ] || echo "  $slow release test(s) over ${timing_slow_test_s} s: each needs a comment saying why"
    if [ "$total" -gt "$timing_budget_s" ]; then
      echo "WARNING: the whole run took $((total / 60)) min, over the $((timing_budget_s / 60)) min budget" \
           "(CI: 2 cores, 90 min limit; issue 32)"
    fi
  } | { mkdir -p build; tee build/test-timing.txt; } >&2
  exit "$rc"
}
trap timing_report EXIT
