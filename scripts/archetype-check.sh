#!/usr/bin/env bash
# A project of one's own, made as a new user makes it (issue 33): generates a project from the
# archetype io.rtaware:rtaware-archetype in an empty temporary folder, runs its tests, then runs its
# main (mvn exec:java) until it says it runs, lets it run for a few seconds, sends it SIGINT as Ctrl-C
# does and checks that it printed the summary with a row per task. Nothing in the generated project is
# edited. It needs the project installed first (./mvnw -B -q -DskipTests install), since the generated
# project takes rtaware from the local repository as a user's does; .ci/run calls it after that.
# Maven is the wrapper's. MAVEN_ARGS (read by Maven 3.9) passes options to each Maven run, e.g.
# MAVEN_ARGS=-Dmaven.repo.local=/tmp/m2 to install into and generate from another local repository.
# Exit status: 0 when every step passed; the failing step's status (or 1) otherwise, with its output.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
mvn=("$root/mvnw" -B)
# The project's version: the BOM's own <version> (the BOM does not inherit the parent's).
version="$(sed -n 's|^  <version>\(.*\)</version>$|\1|p' "$root/rtaware-bom/pom.xml")"
archetype_plugin="org.apache.maven.plugins:maven-archetype-plugin:3.4.1"
run_s="${RTAWARE_ARCHETYPE_RUN_S:-3}"

work="$(mktemp -d)"
pid=""
cleanup() {
  if [ -n "$pid" ] && kill -0 "$pid" 2>/dev/null; then kill -KILL -- "-$pid" 2>/dev/null || true; fi
  rm -rf "$work"
}
trap cleanup EXIT

say() { echo "archetype-check: $*" >&2; }

cd "$work"
say "generating com.example:myrobot from io.rtaware:rtaware-archetype:$version"
"${mvn[@]}" -q "$archetype_plugin:generate" -DarchetypeGroupId=io.rtaware -DarchetypeArtifactId=rtaware-archetype \
  -DarchetypeVersion="$version" -DgroupId=com.example -DartifactId=myrobot -DinteractiveMode=false
cd myrobot
if grep -q '<parent>' pom.xml; then
  say "the generated pom has a parent: it must stand alone"; exit 1
fi

say "mvn test in the generated project"
"${mvn[@]}" -q test

# The main in the background, in a process group of its own (job control on), so that SIGINT reaches
# it: a script's background jobs otherwise start with SIGINT ignored, and the JVM then keeps it so.
# perl puts SIGINT back to its default before it starts Maven: a shell cannot, when it was itself
# started with SIGINT ignored (a CI job run in the background of a non-interactive shell), and a JVM
# that starts with SIGINT ignored never runs its shutdown hooks on Ctrl-C.
log="$work/run.log"
say "mvn exec:java in the generated project, SIGINT after it has run ${run_s} s"
set -m
perl -e '$SIG{INT} = "DEFAULT"; exec @ARGV or die "cannot start $ARGV[0]: $!\n"' -- \
  "${mvn[@]}" -q compile exec:java >"$log" 2>&1 &
pid=$!
set +m
for _ in $(seq 1 600); do
  grep -q 'Ctrl-C stops' "$log" && break
  kill -0 "$pid" 2>/dev/null || break
  sleep 0.2
done
if ! grep -q 'Ctrl-C stops' "$log"; then
  say "the controller did not say it runs:"; cat "$log" >&2; exit 1
fi
sleep "$run_s"
kill -INT -- "-$pid"
# A controller that ignores SIGINT would keep the check waiting for ever: it gets a minute.
for _ in $(seq 1 300); do
  kill -0 "$pid" 2>/dev/null || break
  sleep 0.2
done
if kill -0 "$pid" 2>/dev/null; then
  say "the controller did not stop within 60 s of SIGINT:"; cat "$log" >&2; exit 1
fi
status=0
wait "$pid" || status=$?
pid=""
if ! grep -q '^rtaware summary:' "$log" || ! grep -q '^sensor ' "$log" || ! grep -q '^guard ' "$log"; then
  say "no summary with a row per task after SIGINT (exit status $status):"; cat "$log" >&2; exit 1
fi
sed -n '/^rtaware summary:/,$p' "$log" >&2
say "ok: generated, tested, ran and printed its summary on SIGINT (exit status $status)"
