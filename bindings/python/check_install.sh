#!/usr/bin/env bash
# ctest python_pip_install: `pip install bindings/python` works offline with
# the given interpreter and its setuptools (no build isolation, no index),
# and the installed package imports and answers.  Installs into WORK/target,
# from a copy of the sources so the build leaves nothing in the tree.
# Usage: check_install.sh PYTHON WORK
set -euo pipefail
python="$1"
work="$2"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
if ! "$python" -m pip --version >/dev/null 2>&1; then
  echo "python_pip_install skipped: $python has no pip (scripts/setup installs python3-pip)"
  exit 77
fi
rm -rf "$work"
mkdir -p "$work/src"
cp -r "$here/pyproject.toml" "$here/README.md" "$here/octoprox" "$work/src/"
"$python" -m pip install --quiet --no-build-isolation --no-deps --no-index \
  --target "$work/target" "$work/src"
cd "$work"
PYTHONPATH="$work/target" "$python" -c '
import octoprox, os, sys
assert octoprox.__file__.startswith(sys.argv[1]), octoprox.__file__
print("installed octoprox", octoprox.__version__, "library", octoprox.version())
' "$work/target"
