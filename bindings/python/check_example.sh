#!/usr/bin/env bash
# ctest python_example_check_robot: examples/check_robot.py on the shared
# data (the geb079 map and the PR2 URDF) answers as expected:
#  - at the origin, unseen space free: collision-free (exit 0);
#  - far outside the mapped floor with unseen space an obstacle: it
#    collides (exit 1), wheels included.
# Exit 77 (skipped) passes through when the data is absent.
# Usage: check_example.sh PYTHON
set -uo pipefail
python="$1"
example="$(dirname "${BASH_SOURCE[0]}")/examples/check_robot.py"

out="$("$python" "$example" --joint torso_lift_joint=0.1)"
status=$?
echo "$out"
[ "$status" -eq 77 ] && exit 77
[ "$status" -eq 0 ] && grep -q "collided: False" <<<"$out" || { echo "expected no collision"; exit 1; }

out="$("$python" "$example" --at 100 100 100 --unknown-occupied)"
status=$?
echo "$out"
[ "$status" -eq 1 ] && grep -q "collided: True" <<<"$out" && grep -q "wheel" <<<"$out" ||
  { echo "expected a collision with unseen space"; exit 1; }
