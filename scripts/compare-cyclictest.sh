#!/usr/bin/env bash
# Issue 16, goal 5: rtaware's release lateness against cyclictest's wake-up latency at the same
# period and SCHED_FIFO priority, in alternating rounds (cyclictest, then rtaware, ROUNDS times)
# so both see the same machine noise; prints p50, p99 and p99.9 of each and the ratios.
# Needs root (or CAP_SYS_NICE) for SCHED_FIFO and cyclictest from rt-tests
# (Debian: apt-get install rt-tests); without cyclictest it says so and exits 0.
#
# Usage: scripts/compare-cyclictest.sh [PERIOD_US=1000] [SECONDS_PER_ROUND=5] [ROUNDS=4] [PRIORITY=80]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
period_us="${1:-1000}"
round_s="${2:-5}"
rounds="${3:-4}"
prio="${4:-80}"

if ! command -v cyclictest >/dev/null 2>&1; then
  echo "compare-cyclictest: cyclictest is not installed (Debian: apt-get install rt-tests); skipping"
  exit 0
fi
if ! command -v python3 >/dev/null 2>&1; then
  echo "compare-cyclictest: python3 is needed to merge the histograms; skipping"
  exit 0
fi

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
for ((r = 1; r <= rounds; r++)); do
  echo "compare-cyclictest: round $r/$rounds: cyclictest" >&2
  cyclictest -m -q -t 1 -p "$prio" -i "$period_us" -D "$round_s" -h 20000 --histfile="$work/ct-$r.hist" >/dev/null
  echo "compare-cyclictest: round $r/$rounds: rtaware" >&2
  # One task, no work, --realtime: SCHED_FIFO at --rt-priority and 1 ns timer slack, as cyclictest.
  "$root/rtaware" bench --tasks 1 --period "${period_us}us" --work 0 --duration "${round_s}s" --realtime \
    --rt-priority "$prio" --quiet --lateness-histogram "$work/rt-$r.hist" >/dev/null
done

python3 - "$work" "$rounds" "$period_us" "$prio" "$round_s" <<'PY'
import sys, glob, os
work, rounds, period_us, prio, round_s = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4], sys.argv[5]

def load(pattern):
    # cyclictest -h: "<us> <count>" lines (comments start with #); rtaware: the same format.
    hist = {}
    for f in glob.glob(os.path.join(work, pattern)):
        for line in open(f):
            parts = line.split()
            if len(parts) < 2 or line.startswith("#") or not parts[0].isdigit():
                continue
            us, n = int(parts[0]), int(parts[1])
            hist[us] = hist.get(us, 0) + n
    return hist

def pct(hist, p):
    total = sum(hist.values())
    if total == 0:
        return float("nan")
    need = total * p / 100.0
    seen = 0
    for us in sorted(hist):
        seen += hist[us]
        if seen >= need:
            return us
    return max(hist)

ct, rt = load("ct-*.hist"), load("rt-*.hist")
print(f"cyclictest vs rtaware: period {period_us} us, SCHED_FIFO {prio}, {rounds} alternating rounds of {round_s} s each")
print(f"{'':12s} {'samples':>9s} {'p50':>7s} {'p99':>7s} {'p99.9':>7s}  (us, 1 us buckets)")
for name, h in (("cyclictest", ct), ("rtaware", rt)):
    print(f"{name:12s} {sum(h.values()):9d} {pct(h,50):7} {pct(h,99):7} {pct(h,99.9):7}")
for p, limit in ((50, 1.5), (99, 1.5), (99.9, 2.0)):
    c, r = pct(ct, p), pct(rt, p)
    ratio = r / c if c else float("inf")
    verdict = "PASS" if ratio <= limit else "MISS"
    print(f"{verdict} goal: rtaware p{p:g} / cyclictest p{p:g} <= {limit}: {ratio:.2f} ({r} / {c} us)")
PY
