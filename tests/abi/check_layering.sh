#!/usr/bin/env bash
# The library's lower layers stay below the query engines and the C ABI:
# no file in src/base, src/clouds, src/geometry, src/robot, src/octree,
# src/broadphase, src/narrowphase, src/world or src/self_filter includes a header of
# src/query or src/capi.
#   check_layering.sh SOURCE_DIR
# Exit 0 when none does, 1 with the offending include lines printed, 2 on
# bad usage.
set -u

if [ $# -ne 1 ] || [ ! -d "$1/src" ]; then
    echo "check_layering.sh: usage: check_layering.sh SOURCE_DIR (a directory holding src/; got: ${1:-nothing})" >&2
    exit 2
fi
cd "$1/src" || exit 2

folders=()
for folder in base clouds geometry robot octree broadphase narrowphase world self_filter; do
    [ -d "$folder" ] && folders+=("$folder")
done
if [ ${#folders[@]} -eq 0 ]; then
    echo "check_layering.sh: none of base clouds geometry robot octree broadphase narrowphase world in $PWD" >&2
    exit 2
fi

# An include whose path has a query/ or capi/ part: "query/x.hpp",
# <capi/x.hpp>, "../query/x.hpp".  grep exits 1 when nothing matches.
upward='^[[:space:]]*#[[:space:]]*include[[:space:]]*["<]([^">]*/)?(query|capi)/'
found=$(grep -rnE "$upward" "${folders[@]}")
if [ -n "$found" ]; then
    echo "Lower layers including the query engines or the C ABI (src/$(IFS=,; echo "{${folders[*]}}")):" >&2
    echo "$found" >&2
    exit 1
fi
(IFS=,; echo "no query/ or capi/ includes in src/{${folders[*]}}")
