#!/usr/bin/env bash
# The shared library exports exactly the committed list of functions, and
# the list matches the OPX_API declarations of the public headers.  A change
# to the ABI must be deliberate: update exported_symbols.txt with it.
#   check_symbols.sh NM LIBRARY EXPECTED_LIST INCLUDE_DIR
set -euo pipefail

if [[ $# -ne 4 ]]; then
    echo "usage: $0 NM LIBRARY EXPECTED_LIST INCLUDE_DIR" >&2
    exit 2
fi
nm_tool=$1 library=$2 expected=$3 include_dir=$4
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# Defined dynamic text symbols (T), version suffixes (@@V) removed.  Every
# T symbol is listed, not only opx_*: a leaked C++ symbol must show up too.
"$nm_tool" -D --defined-only "$library" \
    | awk '$2 == "T" { sub(/@.*/, "", $3); print $3 }' \
    | LC_ALL=C sort -u >"$work/exported"

# Function names declared with OPX_API in the public headers: drop the
# preprocessor lines, split at ';', take the name before the first '('.
grep -hv '^[[:space:]]*#' "$include_dir"/octoprox/*.h \
    | tr '\n' ' ' | tr ';' '\n' \
    | grep 'OPX_API' \
    | sed -E 's/.*OPX_API[^(]*[^A-Za-z0-9_](opx_[a-z0-9_]+)[[:space:]]*\(.*/\1/' \
    | LC_ALL=C sort -u >"$work/declared"

status=0
if ! LC_ALL=C sort -c "$expected" 2>/dev/null; then
    echo "FAIL: $expected is not sorted (LC_ALL=C sort)"
    status=1
fi
if ! diff -u "$expected" "$work/exported" >"$work/diff_exported"; then
    echo "FAIL: symbols exported by $library differ from $expected"
    echo "      (- committed list, + exported):"
    cat "$work/diff_exported"
    status=1
fi
if ! diff -u "$expected" "$work/declared" >"$work/diff_declared"; then
    echo "FAIL: functions declared OPX_API in $include_dir/octoprox differ from $expected"
    echo "      (- committed list, + declared):"
    cat "$work/diff_declared"
    status=1
fi
if [[ $status -eq 0 ]]; then
    echo "OK: $(wc -l <"$expected") exported functions match the list and the headers"
fi
exit $status
