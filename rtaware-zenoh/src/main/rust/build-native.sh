#!/usr/bin/env bash
# Builds the JNI library of rtaware-zenoh with cargo and copies it to $1/<os>-<arch>/, where
# io.rtaware.zenoh.ZenohLibrary finds it on the class path. Without cargo (or with a Rust older
# than the zenoh crate needs) it prints a WARNING block saying what is off and how to enable it,
# and succeeds: everything but the ROS 2 features builds and runs without Rust. With
# RTAWARE_REQUIRE_NATIVE=1 a skip fails the build instead. The cargo target folder lives outside
# the clone (RTAWARE_CARGO_TARGET_DIR, default: the user's cache folder) so that rebuilds reuse it.
#
# build-native.sh --test runs the layer's Rust tests instead (cargo test, release profile, so it
# reuses the dependencies the build compiled), skipping with the same WARNING block without cargo;
# rtaware-zenoh's pom runs it in Maven's test phase.
set -euo pipefail
out="$1"
what="is NOT built"
[ "$out" = "--test" ] && what="is NOT built and its Rust tests do NOT run"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
min_rust="1.75"

# Prints the reason in a block Maven's output cannot hide (stderr, shown also under -q), then
# succeeds, or fails when the native layer is required.
skip() {
  {
    echo "[WARNING] ========================================================================"
    echo "[WARNING] rtaware-zenoh: the native Zenoh layer $what: $1"
    echo "[WARNING] OFF: everything ROS 2 (run/sim --ros2, the ROS 2 exporter); ROS 2 tests skip."
    echo "[WARNING] To enable: install Rust >= $min_rust with cargo on the PATH (https://rustup.rs),"
    echo "[WARNING] then rebuild (./mvnw -B -DskipTests package)."
    echo "[WARNING] Set RTAWARE_REQUIRE_NATIVE=1 to make this a build failure."
    echo "[WARNING] ========================================================================"
  } >&2
  if [ "${RTAWARE_REQUIRE_NATIVE:-0}" = "1" ]; then
    echo "[ERROR] rtaware-zenoh: RTAWARE_REQUIRE_NATIVE=1 and the native Zenoh layer cannot be built" >&2
    exit 1
  fi
  exit 0
}

if ! command -v cargo >/dev/null 2>&1; then
  skip "no cargo on the PATH"
fi
rust_version="$(rustc --version 2>/dev/null | awk '{print $2}')"
if [ "$(printf '%s\n%s\n' "$min_rust" "$rust_version" | sort -V | head -1)" != "$min_rust" ]; then
  skip "rustc ${rust_version:-(none)} is older than $min_rust"
fi

case "$(uname -s)-$(uname -m)" in
  Linux-x86_64) platform="linux-x86_64"; lib="librtaware_zenoh.so" ;;
  Linux-aarch64) platform="linux-aarch64"; lib="librtaware_zenoh.so" ;;
  Darwin-x86_64) platform="macos-x86_64"; lib="librtaware_zenoh.dylib" ;;
  Darwin-arm64) platform="macos-aarch64"; lib="librtaware_zenoh.dylib" ;;
  *) skip "no native build for $(uname -s)-$(uname -m)" ;;
esac

# The ROS 2 DDS bridge (cargo feature dds, issue 29) builds Eclipse Cyclone DDS from source: it needs
# cmake and libclang (bindgen). Without them the layer is built without the bridge (--dds then says
# so), with the same kind of WARNING block; RTAWARE_REQUIRE_DDS=1 makes that a failure.
features=()
dds_missing=""
command -v cmake >/dev/null 2>&1 || dds_missing="no cmake on the PATH"
# The library list is read whole before it is searched: 'ldconfig -p | grep -q' under pipefail fails
# whenever grep stops at the first match before ldconfig has written its last line (SIGPIPE).
shared_libraries="$(ldconfig -p 2>/dev/null || true)"
if [ -z "$dds_missing" ] && [ -z "${LIBCLANG_PATH:-}" ] && ! grep -q 'libclang[-.0-9]*\.so' <<<"$shared_libraries"; then
  dds_missing="no libclang (install libclang-dev, or set LIBCLANG_PATH)"
fi
if [ -z "$dds_missing" ]; then
  features=(--features dds)
else
  {
    echo "[WARNING] ========================================================================"
    echo "[WARNING] rtaware-zenoh: the ROS 2 DDS bridge is NOT built: $dds_missing"
    echo "[WARNING] OFF: --dds (run, sim, bench --export); the DDS tests skip."
    echo "[WARNING] To enable: install cmake and libclang-dev, then rebuild."
    echo "[WARNING] ========================================================================"
  } >&2
  if [ "${RTAWARE_REQUIRE_DDS:-0}" = "1" ]; then
    echo "[ERROR] rtaware-zenoh: RTAWARE_REQUIRE_DDS=1 and the ROS 2 DDS bridge cannot be built" >&2
    exit 1
  fi
fi

export CARGO_TARGET_DIR="${RTAWARE_CARGO_TARGET_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/rtaware/cargo-target}"
if [ "$out" = "--test" ]; then
  mkdir -p "$CARGO_TARGET_DIR"
  exec cargo test --release --locked --quiet "${features[@]}" --manifest-path "$here/Cargo.toml"
fi
mkdir -p "$CARGO_TARGET_DIR" "$out/$platform"
cargo build --release --locked --quiet "${features[@]}" --manifest-path "$here/Cargo.toml"
# The library, and with the bridge its executable (rtaware-dds-bridge, a process of its own: src/bridge/main.rs).
# A bridge left from an earlier build with it is removed: Java takes its presence for the bridge being built.
artifacts=("$lib")
if [ ${#features[@]} -gt 0 ]; then
  artifacts+=(rtaware-dds-bridge)
else
  rm -f "$out/$platform/rtaware-dds-bridge"
fi
for artifact in "${artifacts[@]}"; do
  cp "$CARGO_TARGET_DIR/release/$artifact" "$out/$platform/$artifact.tmp"
  mv "$out/$platform/$artifact.tmp" "$out/$platform/$artifact"
done
