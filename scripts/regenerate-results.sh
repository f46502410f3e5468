#!/usr/bin/env bash
# Re-runs the published experiments on this machine with their conditions recorded, into new
# folders, and regenerates docs/experiment/RESULTS.md from them. Each run waits for a quiet
# machine (at most --quiet-wait, then it is labelled busy: the report judges every claim on the
# quiet runs and again on all runs). Run it on an otherwise idle machine (anything else, even
# reading a source tree, makes runs busy). Durations on the 2-vCPU VM at time scale 10
# (2026-11-28; runs that end stuck take longer): the paper's 5 x 12 runs, independent (about 40 min),
# and 5 x 6 blocked on the world seed (about 20 min), 4 x 3 runs under one CPU (--cpu-limit 1, needs
# root), 2 x 5 x 10 office runs (about 30 min), 9 x 5 office runs at three speeds (13 min), 5 x 10
# corridor runs (9 min), then 8 x 3 + 8 x 3 + 6 x 5 + 9 x 3 sweep runs in the paper's room (40 min).
# Usage: scripts/regenerate-results.sh [OUT]   (default OUT: experiments/published; then copy
# the folders over docs/experiment/ without their runs/ folders and commit them with RESULTS.md).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="${1:-experiments/published}"
cd "$root"
./rtaware experiment --sets paper --runs 12 --quiet-wait 90s --out "$out/paper-profile"
./rtaware experiment --sets paper --runs 6 --design blocked --quiet-wait 90s --out "$out/paper-profile-blocked"
./rtaware experiment --sets docs/experiment/lockup-cpu1/sets.yaml --runs 3 --cpu-limit 1 --quiet-wait 90s --out "$out/lockup-cpu1"
./rtaware experiment --scenario office --sets docs/experiment/office-obstacle/sets.yaml --runs 10 --quiet-wait 90s --out "$out/office-obstacle"
./rtaware experiment --scenario office --sets docs/experiment/office-all/sets.yaml --runs 10 --quiet-wait 90s --out "$out/office-all"
./rtaware experiment --scenario office --sets docs/experiment/office-speed/sets.yaml --runs 5 --quiet-wait 90s --out "$out/office-speed"
./rtaware experiment --scenario corridor --sets docs/experiment/corridor-obstacle/sets.yaml --runs 10 --quiet-wait 90s --out "$out/corridor-obstacle"
./rtaware experiment --sets sweep-obstacle --runs 3 --quiet-wait 90s --out "$out/sweep-obstacle"
./rtaware experiment --sets sweep-all --runs 3 --quiet-wait 90s --out "$out/sweep-all"
./rtaware experiment --sets docs/experiment/sweep-bound-04/sets.yaml --runs 5 --quiet-wait 90s --out "$out/sweep-bound-04"
./rtaware experiment --sets docs/experiment/sweep-speed/sets.yaml --runs 3 --quiet-wait 90s --out "$out/sweep-speed"
./rtaware report --results "$out/RESULTS.md" "$out/paper-profile" "$out/paper-profile-blocked" "$out/lockup-cpu1" "$out/office-obstacle" "$out/office-all" "$out/office-speed" \
  "$out/corridor-obstacle" "$out/sweep-obstacle" "$out/sweep-all" \
  "$out/sweep-bound-04" "$out/sweep-speed"
