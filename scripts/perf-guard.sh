#!/usr/bin/env bash
# The performance guard (issue 36): is this checkout's scheduling measurably slower than the
# baseline's? Builds the jar of the baseline commit named in .ci/perf-baseline (first word) in a
# temporary worktree, then runs both jars one after the other, in alternating pairs, on the same
# machine: the pooled executor draining 10 000 in-phase tasks at 10 ms with no work, and the
# thread-per-task executor with 100 tasks at 10 ms. A change is judged slower when, for one
# executor, every pair has this checkout worse than the baseline in the median task's p99
# lateness AND the median of those ratios exceeds RTAWARE_PERF_RATIO (default 1.5), or every
# pair has more missed releases by over 1 point of the releases. The judgement is made only
# when the machine was quiet for every run of this checkout (rtaware's own verdict, in each
# report's conditions): on a busy machine the figures are printed and nothing fails.
#
# Exit status: 0 not slower (or not judged: busy machine, baseline not in this clone, no build);
# 1 slower on a quiet machine. Usage: scripts/perf-guard.sh [PAIRS] (default 5).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

pairs="${1:-5}"
ratio_limit="${RTAWARE_PERF_RATIO:-1.5}"
baseline="$(awk 'NF && $1 !~ /^#/ {print $1; exit}' .ci/perf-baseline)"
say() { echo "perf-guard: $*" >&2; }

if ! git cat-file -e "$baseline^{commit}" 2>/dev/null; then
  say "baseline commit $baseline is not in this clone (shallow?): not judged"
  exit 0
fi
current_jar="rtaware-app/target/rtaware.jar"
if [ ! -f "$current_jar" ]; then
  say "no $current_jar: build first (./mvnw -B -q -pl rtaware-app -am package -DskipTests)"
  exit 0
fi

work="$(mktemp -d)"
cleanup() {
  git worktree remove --force "$work/baseline" >/dev/null 2>&1 || true
  rm -rf "$work"
}
trap cleanup EXIT

say "building the baseline $baseline ($(git log -1 --format='%cs %s' "$baseline" | cut -c1-80))"
git worktree add -q --detach "$work/baseline" "$baseline"
# The baseline's native layer is not needed to schedule tasks: built without Rust.
if ! (cd "$work/baseline" && RTAWARE_NO_RUST=1 ./mvnw -B -q -pl rtaware-app -am package -DskipTests \
      -Dmaven.javadoc.skip=true -Dmaven.source.skip=true > "$work/baseline-build.log" 2>&1); then
  say "the baseline does not build here (last lines below): not judged"
  tail -5 "$work/baseline-build.log" >&2
  exit 0
fi
cp "$work/baseline/rtaware-app/target/rtaware.jar" "$work/baseline.jar"
cp "$current_jar" "$work/current.jar"

run() { # jar report executor-args...: through the launcher, for its JVM options
  local jar="$1" out="$2" status=0
  shift 2
  RTAWARE_JAR="$jar" ./rtaware bench "$@" --period 10ms --work 0 --duration 10s --quiet --json "$out" \
    >/dev/null 2>&1 || status=$?
  [ "$status" -eq 0 ] || say "a run of $(basename "$jar") ended with status $status ($*)"
}

for i in $(seq 1 "$pairs"); do
  for kind in pooled threaded; do
    if [ "$kind" = pooled ]; then args=(--executor pooled --tasks 10000); else args=(--tasks 100); fi
    # Alternate which jar goes first, so that neither always runs on a machine the other warmed.
    if [ $((i % 2)) -eq 1 ]; then order="baseline current"; else order="current baseline"; fi
    for who in $order; do
      run "$work/$who.jar" "$work/$kind-$who-$i.json" "${args[@]}"
    done
  done
  say "pair $i of $pairs done"
done

python3 - "$work" "$pairs" "$ratio_limit" <<'PY'
import json, os, statistics, sys

work, pairs, ratio_limit = sys.argv[1], int(sys.argv[2]), float(sys.argv[3])

def figures(path):
    if not os.path.exists(path):
        return None
    with open(path) as f:
        report = json.load(f)
    p99 = [t["lateness_us"]["p99"] for t in report["tasks"] if t.get("lateness_us")]
    releases = sum(t.get("releases", 0) for t in report["tasks"])
    misses = sum(t.get("misses", 0) for t in report["tasks"])
    machine = (report.get("conditions") or {}).get("machine", "unknown")
    return {"p99_us": statistics.median(p99) if p99 else float("nan"),
            "miss_pct": 100.0 * misses / releases if releases else float("nan"), "machine": machine}

slower = []
quiet = True
for kind in ("pooled", "threaded"):
    rows = []
    for i in range(1, pairs + 1):
        b = figures(f"{work}/{kind}-baseline-{i}.json")
        c = figures(f"{work}/{kind}-current-{i}.json")
        if b is None or c is None:
            print(f"perf-guard: {kind} pair {i}: a run wrote no report; not judged", file=sys.stderr)
            quiet = False
            continue
        quiet &= c["machine"] == "quiet"
        rows.append((b, c))
        print(f"perf-guard: {kind:8} pair {i}: baseline p99 {b['p99_us']:9.1f} us, misses {b['miss_pct']:6.2f} % | "
              f"this {c['p99_us']:9.1f} us, misses {c['miss_pct']:6.2f} % (machine {c['machine']})", file=sys.stderr)
    if len(rows) < pairs:
        continue
    ratios = [c["p99_us"] / b["p99_us"] for b, c in rows if b["p99_us"] > 0]
    worse_p99 = len(ratios) == pairs and all(r > 1 for r in ratios) and statistics.median(ratios) > ratio_limit
    worse_misses = all(c["miss_pct"] > b["miss_pct"] + 1.0 for b, c in rows)
    median_ratio = statistics.median(ratios) if ratios else float("nan")
    print(f"perf-guard: {kind}: median p99 ratio this/baseline {median_ratio:.2f} (limit {ratio_limit}); "
          f"misses worse in every pair: {worse_misses}", file=sys.stderr)
    if worse_p99 or worse_misses:
        slower.append(kind)

if not quiet:
    print("perf-guard: the machine was not quiet for every run of this checkout: figures above, not judged",
          file=sys.stderr)
    sys.exit(0)
if slower:
    print(f"perf-guard: SLOWER than the baseline on a quiet machine: {', '.join(slower)}", file=sys.stderr)
    sys.exit(1)
print("perf-guard: not slower than the baseline", file=sys.stderr)
PY
