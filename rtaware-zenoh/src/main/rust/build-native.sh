#!/usr/bin/env bash
# Builds the JNI library of rtaware-zenoh with cargo and copies it to $1/<os>-<arch>/, where
# io.rtaware.zenoh.ZenohLibrary finds it on the class path. Without cargo (or with a Rust older
# than the zenoh crate needs) it says so in one line and succeeds: everything but the ROS 2
# features builds and runs without Rust. The cargo target folder lives outside the clone
# (RTAWARE_CARGO_TARGET_DIR, default: the user's cache folder) so that rebuilds reuse it.
set -euo pipefail
out="$1"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
min_rust="1.75"

if ! command -v cargo >/dev/null 2>&1; then
  echo "rtaware-zenoh: no cargo on the PATH: the native Zenoh layer is skipped (ROS 2 features off; install Rust >= $min_rust and rebuild to enable them)"
  exit 0
fi
rust_version="$(rustc --version 2>/dev/null | awk '{print $2}')"
if [ "$(printf '%s\n%s\n' "$min_rust" "$rust_version" | sort -V | head -1)" != "$min_rust" ]; then
  echo "rtaware-zenoh: rustc $rust_version is older than $min_rust: the native Zenoh layer is skipped (ROS 2 features off; install Rust >= $min_rust and rebuild to enable them)"
  exit 0
fi

case "$(uname -s)-$(uname -m)" in
  Linux-x86_64) platform="linux-x86_64"; lib="librtaware_zenoh.so" ;;
  Linux-aarch64) platform="linux-aarch64"; lib="librtaware_zenoh.so" ;;
  Darwin-x86_64) platform="macos-x86_64"; lib="librtaware_zenoh.dylib" ;;
  Darwin-arm64) platform="macos-aarch64"; lib="librtaware_zenoh.dylib" ;;
  *) echo "rtaware-zenoh: no native build for $(uname -s)-$(uname -m): the native Zenoh layer is skipped"; exit 0 ;;
esac

export CARGO_TARGET_DIR="${RTAWARE_CARGO_TARGET_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/rtaware/cargo-target}"
mkdir -p "$CARGO_TARGET_DIR" "$out/$platform"
cargo build --release --locked --quiet --manifest-path "$here/Cargo.toml"
cp "$CARGO_TARGET_DIR/release/$lib" "$out/$platform/$lib.tmp"
mv "$out/$platform/$lib.tmp" "$out/$platform/$lib"
