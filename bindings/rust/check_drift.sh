#!/usr/bin/env bash
# ctest rust_sys_drift: regenerates the bindings into a temporary file and
# fails when they differ from the committed octoprox-sys/src/bindings.rs
# (run bindings/rust/regenerate.sh and commit after changing a header).
# Usage: check_drift.sh BINDGEN WORK_DIR
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
mkdir -p "$2"
fresh="$2/bindings.rs.fresh"
BINDGEN="$1" "$here/regenerate.sh" "$fresh"
if ! diff -u "$here/octoprox-sys/src/bindings.rs" "$fresh"; then
  echo "rust_sys_drift: octoprox-sys/src/bindings.rs is out of date: run bindings/rust/regenerate.sh"
  exit 1
fi
echo "rust_sys_drift: bindings.rs matches the headers ($(grep -c 'pub fn opx_' "$fresh") functions)"
