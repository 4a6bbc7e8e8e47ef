#!/usr/bin/env bash
# Long fuzzing runs (at least 30 CPU-minutes per target for a parser change): builds the
# targets as fuzz/run.sh does, then runs each for the given seconds with its dictionary on a
# persistent working corpus (seeded from fuzz/corpus/<target>, kept between runs in the build
# folder), and prints per target: executions, coverage (cov: edges, ft: features), corpus
# size and findings (crash/leak/timeout/oom artifacts).
# Usage: fuzz/run-long.sh [seconds per target, default 1800] [build folder, default build-fuzz]
#        [targets..., default all]
# New interesting inputs stay in BUILD/long-corpus-<target>; minimise and copy the useful ones
# into fuzz/corpus/<target>/ by hand. Exits non-zero when any target has a finding.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
seconds="${1:-1800}"
out="${2:-$(dirname "$here")/build-fuzz}"
shift $(( $# > 2 ? 2 : $# ))
targets="${*:-obj off ply stl inr inr_gz binvox points}"
HMIRA_FUZZ_ONLY_BUILD=1 bash "$here/run.sh" 0 "$out" > "$out.build.log" 2>&1 || { cat "$out.build.log" >&2; exit 1; }
status=0
declare -A cpu_used
printf '%-8s %8s %12s %8s %8s %8s %s\n' target cpu_s execs cov ft corpus findings
for t in $targets; do
  work="$out/long-corpus-$t"
  mkdir -p "$work" "$out/long-artifacts-$t"
  cp -n "$here/corpus/$t/"* "$work/" 2>/dev/null || true
  log="$out/long-$t.log"
  # The budget is CPU time, not wall time, so a busy machine does not shorten the run: the
  # fuzzer is stopped with SIGINT (it then prints its final stats) once it has used $seconds.
  "$out/fuzz_$t" -seed="${HMIRA_FUZZ_SEED:-0}" -max_total_time=$((seconds * 20)) -max_len=65536 -rss_limit_mb=2048 -timeout=10 \
    -dict="$here/dict/$t.dict" -artifact_prefix="$out/long-artifacts-$t/" -print_final_stats=1 "$work" > "$log" 2>&1 &
  pid=$!
  cpu=0
  tick=$(getconf CLK_TCK)
  while kill -0 "$pid" 2>/dev/null; do
    cpu=$(awk -v t="$tick" '{print int(($14 + $15) / t)}' "/proc/$pid/stat" 2>/dev/null || echo 0)
    if [ "$cpu" -ge "$seconds" ]; then kill -INT "$pid" 2>/dev/null || true; break; fi
    sleep 5
  done
  wait "$pid" || true
  cpu_used[$t]=$cpu
  execs="$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)"
  last="$(grep -E '^#[0-9]+' "$log" | tail -1)"
  cov="$(echo "$last" | sed -n 's/.*cov: \([0-9]*\).*/\1/p')"
  ft="$(echo "$last" | sed -n 's/.*ft: \([0-9]*\).*/\1/p')"
  corp="$(echo "$last" | sed -n 's/.*corp: \([0-9]*\).*/\1/p')"
  findings="$(find "$out/long-artifacts-$t" -type f | wc -l)"
  printf '%-8s %8s %12s %8s %8s %8s %s\n' "$t" "${cpu_used[$t]}" "${execs:-?}" "${cov:-?}" "${ft:-?}" "${corp:-?}" "$findings"
  if [ "$findings" -ne 0 ]; then
    status=1
    echo "  findings in $out/long-artifacts-$t/ (log $log):" >&2
    grep -m 3 -E "ERROR|runtime error|property violated" "$log" | sed 's/^/  /' >&2 || true
  fi
done
exit $status
