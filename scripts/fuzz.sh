#!/usr/bin/env bash
# Runs every fuzz test of the project as a coverage-guided fuzzer (Jazzer, JAZZER_FUZZ=1) for the
# time its @FuzzTest(maxDuration) gives, one Maven run each (Jazzer fuzzes one test per JVM).
# Without JAZZER_FUZZ the same tests replay their corpus as plain regression tests in
# `./mvnw verify`. A finding fails the run and is written into the test's corpus folder
# (src/test/resources/<package>/<Class>Inputs/<method>/crash-*): fix the bug, rename the file for
# what it shows, and commit it, so that it stays a regression test.
# Usage: scripts/fuzz.sh [module:Class ...]   (default: all of them)
# RTAWARE_FUZZ_UNTIL (Unix seconds), when set, is a time budget: a test that would not end by then
# (its 20 s of fuzzing plus Maven's start-up, counted as 60 s) is skipped and said so, never cut short.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

tests=("$@")
if [ "${#tests[@]}" -eq 0 ]; then
  tests=(
    rtaware-record:McapReaderFuzzTest
    rtaware-ros2msg:CdrDecodersFuzzTest
    rtaware-player:PlayerStreamFuzzTest
    rtaware-sim:ScenarioFuzzTest
    rtaware-sim:MapFuzzTest
    rtaware-experiment:ExperimentFilesFuzzTest
    rtaware-app:AnalyzeFuzzTest
  )
fi

corpus_root="${XDG_CACHE_HOME:-$HOME/.cache}/rtaware/fuzz-corpus"
failed=()
skipped=()
for t in "${tests[@]}"; do
  module="${t%%:*}"
  class="${t##*:}"
  if [ -n "${RTAWARE_FUZZ_UNTIL:-}" ] && [ "$(( $(date +%s) + 60 ))" -gt "$RTAWARE_FUZZ_UNTIL" ]; then
    skipped+=("$class")
    continue
  fi
  echo "fuzz: $class ($module)" >&2
  # The corpus the fuzzer grows is kept outside the clone, so later runs start from it.
  mkdir -p "$corpus_root/$class"
  rm -rf "$module/.cifuzz-corpus"
  mkdir -p "$module/.cifuzz-corpus"
  ln -sfn "$corpus_root/$class" "$module/.cifuzz-corpus/$(find "$module/src/test/java" -name "$class.java" | sed 's|.*/src/test/java/||; s|\.java$||; s|/|.|g')"
  touch "$corpus_root/$class.log.start"
  if ! JAZZER_FUZZ=1 ./mvnw -B -q -o -pl "$module" -am test -Dtest="$class" -Dsurefire.failIfNoSpecifiedTests=false \
      >"$corpus_root/$class.log" 2>&1; then
    echo "fuzz: $class FOUND A PROBLEM (log: $corpus_root/$class.log):" >&2
    grep -E "FuzzTestFinding|Caused by|Test unit written" "$corpus_root/$class.log" | head -5 >&2 || true
    # The input, so that it survives a CI log: base64 -d it into the test's corpus folder.
    find "$module/src/test/resources" -name 'crash-*' -newer "$corpus_root/$class.log.start" 2>/dev/null \
      | while read -r crash; do echo "fuzz: input $crash (base64): $(base64 -w0 "$crash")" >&2; done
    failed+=("$class")
  else
    grep -E "^Done [0-9]+ runs" "$corpus_root/$class.log" | tail -1 | sed "s/^/fuzz: $class: /" >&2 || true
  fi
  rm -rf "$module/.cifuzz-corpus"
done
if [ "${#skipped[@]}" -gt 0 ]; then
  echo "fuzz: not fuzzed, the time budget (RTAWARE_FUZZ_UNTIL) being spent: ${skipped[*]}" >&2
fi
if [ "${#failed[@]}" -gt 0 ]; then
  echo "fuzz: findings in ${failed[*]}" >&2
  exit 1
fi
