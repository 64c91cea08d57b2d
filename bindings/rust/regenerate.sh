#!/usr/bin/env bash
# Regenerates octoprox-sys/src/bindings.rs from include/octoprox/octoprox.h
# with Debian's bindgen CLI.  With an argument, writes there instead (the
# ctest drift check writes to a temporary file and diffs it).
#
# rustfmt is not used: its output changes between versions, and the file
# must be byte-identical wherever it is regenerated.  Instead each item is
# put on its own line by a fixed sed rule, so diffs stay readable: a
# top-level item's doc comment on the line before it.  bindgen keeps the
# '<' of a trailing doc comment (`/**< ... */` after a field); the last
# rule drops it.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
include_dir="$here/../../include"
out="${1:-$here/octoprox-sys/src/bindings.rs}"
bindgen="${BINDGEN:-/usr/bin/bindgen}"
command -v "$bindgen" >/dev/null || bindgen=bindgen

"$bindgen" "$include_dir/octoprox/octoprox.h" \
    --no-rustfmt-bindings --size_t-is-usize --with-derive-partialeq \
    --default-macro-constant-type signed \
    --allowlist-function 'opx_.*' --allowlist-type 'opx_.*' --allowlist-var 'OPX_.*' \
    -- -I"$include_dir" |
  sed -e 's/ \(pub const \|pub type \|extern "C" \|# \[repr\|# \[test\]\|fn test_field\)/\n\1/g' \
      -e 's/\([;}]\) \(# \[doc = \)/\1\n\2/g' \
      -e 's/# \[doc = "< */# [doc = " /g' >"$out"
echo >>"$out" # a final newline
