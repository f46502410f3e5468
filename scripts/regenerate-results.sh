#!/usr/bin/env bash
# Re-runs the published experiments on this machine with their conditions recorded, into new
# folders, and regenerates docs/experiment/RESULTS.md from them. Each run waits for a quiet
# machine (rtaware experiment's default; at most --quiet-wait, then it is labelled busy
# and left out of the report). Run it on an otherwise idle machine (anything else, even reading a
# source tree, makes runs busy): 5 x 12 paper runs (about 30 min on the 2-vCPU VM), 2 x 5 x 10 office
# runs (about 30 min), 9 x 5 office runs at three speeds (13 min), 5 x 10 corridor runs (9 min), then
# 8 x 3 + 8 x 3 + 6 x 5 + 9 x 3 sweep runs in the paper's room (40 min) at time scale 10 (2026-11-26).
# Usage: scripts/regenerate-results.sh [OUT]   (default OUT: experiments/published; then copy
# the folders over docs/experiment/ and commit them with RESULTS.md, keeping the runs' folders).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="${1:-experiments/published}"
cd "$root"
./rtaware experiment --sets paper --runs 12 --out "$out/paper-profile"
./rtaware experiment --scenario office --sets docs/experiment/office-obstacle/sets.yaml --runs 10 --out "$out/office-obstacle"
./rtaware experiment --scenario office --sets docs/experiment/office-all/sets.yaml --runs 10 --out "$out/office-all"
./rtaware experiment --scenario office --sets docs/experiment/office-speed/sets.yaml --runs 5 --out "$out/office-speed"
./rtaware experiment --scenario corridor --sets docs/experiment/corridor-obstacle/sets.yaml --runs 10 --out "$out/corridor-obstacle"
./rtaware experiment --sets sweep-obstacle --runs 3 --out "$out/sweep-obstacle"
./rtaware experiment --sets sweep-all --runs 3 --out "$out/sweep-all"
./rtaware experiment --sets docs/experiment/sweep-bound-04/sets.yaml --runs 5 --out "$out/sweep-bound-04"
./rtaware experiment --sets docs/experiment/sweep-speed/sets.yaml --runs 3 --out "$out/sweep-speed"
./rtaware report --results "$out/RESULTS.md" "$out/paper-profile" "$out/office-obstacle" "$out/office-all" "$out/office-speed" \
  "$out/corridor-obstacle" "$out/sweep-obstacle" "$out/sweep-all" \
  "$out/sweep-bound-04" "$out/sweep-speed"
