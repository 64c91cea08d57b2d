#!/usr/bin/env bash
# The product's files speak of the product alone: no "session N", no
# "issue N" and no goals as verdicts or aims ("goal: yes", "goal met",
# "the speed goal") in docs/, README.md, src/, include/, bench/ or tools/;
# a motion's start and goal are the product's own words.  A peer's own issue numbers named as such stay allowed ("FCL
# issue #NNN", "OctoMap issue #NNN", "fcl#NNN", "octomap#NNN").
#   check_product_words.sh SOURCE_DIR
# Exit 0 when nothing is found, 1 with the offending lines printed, 2 on
# bad usage.
set -u

if [ $# -ne 1 ] || [ ! -d "$1" ]; then
    echo "check_product_words.sh: usage: check_product_words.sh SOURCE_DIR (got: ${1:-nothing})" >&2
    exit 2
fi
cd "$1" || exit 2

words='session [0-9]|issue [0-9]|\bgoals? *:|\bgoals? (met|not met|reached|missed|yes|no)\b|\b(our|speed|performance|the [a-z]+ ?) goals?\b'
peers='(fcl|octomap|libccd|eigen|assimp) issue|(fcl|octomap|libccd)#[0-9]'

paths=()
for path in docs README.md src include bench tools; do
    [ -e "$path" ] && paths+=("$path")
done
if [ ${#paths[@]} -eq 0 ]; then
    echo "check_product_words.sh: none of docs README.md src include bench tools in $PWD" >&2
    exit 2
fi

# -I skips binary files (the plots); grep exits 1 when nothing matches.
found=$(grep -rniIE "$words" "${paths[@]}" | grep -viE "$peers")
if [ -n "$found" ]; then
    echo "Words that belong in commit messages, not in the product's files:" >&2
    echo "$found" >&2
    exit 1
fi
echo "no session/issue/goal wording in ${paths[*]}"
