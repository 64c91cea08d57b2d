#!/usr/bin/env bash
# ctest python_wheel_install: the README's install, offline.
#  1. `pip wheel` of this folder with OPX_LIBRARY naming the build tree's
#     library gives a platform wheel carrying liboctoprox and, where the
#     interpreter has its headers (Python.h), the compiled call path
#     octoprox._fastcall, and leaves no build output in this folder;
#  2. the wheel installs with --no-index into a fresh venv
#     (--system-site-packages: numpy from Debian's python3-numpy);
#  3. the README's Python example runs from a directory outside the tree
#     with OPX_LIBRARY, LD_LIBRARY_PATH and PYTHONPATH unset, and imports the
#     venv's package, its bundled library and its compiled call path.
# Usage: check_wheel.sh PYTHON LIBRARY README
set -euo pipefail
python="$1"
library="$2"
readme="$3"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"

if ! "$python" -m pip --version >/dev/null 2>&1; then
  echo "python_wheel_install skipped: $python has no pip (Debian: python3-pip)"
  exit 77
fi
if ! "$python" -c "import venv, ensurepip" >/dev/null 2>&1; then
  echo "python_wheel_install skipped: $python cannot make a venv (Debian: python3-venv)"
  exit 77
fi

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
export PIP_DISABLE_PIP_VERSION_CHECK=1 PIP_NO_INDEX=1

echo "== pip wheel, bundling $library"
OPX_LIBRARY="$library" "$python" -m pip wheel --quiet --no-deps -w "$work/dist" "$here"
wheel="$(ls "$work"/dist/octoprox-*.whl)"
echo "$wheel"
headers="$("$python" -c 'import os, sysconfig; print(int(os.path.exists(os.path.join(sysconfig.get_paths()["include"], "Python.h"))))')"
# Asked of zipfile itself: `zipfile -l | grep -q` fails under pipefail
# when grep exits at the first match and the listing meets a closed pipe.
extension="$("$python" -c 'import sys, zipfile
print(int(any(n.startswith("octoprox/_fastcall.") for n in zipfile.ZipFile(sys.argv[1]).namelist())))' "$wheel")"
if [ "$headers" != "$extension" ]; then
  echo "Python.h present: $headers, octoprox/_fastcall in the wheel: $extension"
  exit 1
fi
for leftover in build dist "*.egg-info"; do
  if compgen -G "$here/$leftover" >/dev/null; then
    echo "the build left $here/$leftover behind"
    exit 1
  fi
done

echo "== a fresh venv, the wheel installed offline"
"$python" -m venv --system-site-packages "$work/venv"
"$work/venv/bin/python" -m pip install --quiet "$wheel"

echo "== the README's Python example, from $work/run"
mkdir "$work/run"
"$python" - "$readme" "$work/run/example.py" <<'EOF'
import re, sys
text = open(sys.argv[1]).read()
blocks = re.findall(r"<!-- example: \S+\.py -->\n```python\n(.*?)```\n", text, re.S)
assert blocks, "README.md has no Python block marked <!-- example: ... -->"
open(sys.argv[2], "w").write(blocks[0])
EOF
cd "$work/run"
run=(env -u OPX_LIBRARY -u LD_LIBRARY_PATH -u PYTHONPATH "$work/venv/bin/python")
"${run[@]}" -c '
import os, sys, octoprox
from octoprox import _calls
package = os.path.dirname(octoprox.__file__)
assert package.startswith(sys.argv[1]), "imported " + package
assert os.path.dirname(octoprox.lib._name) == package, "loaded " + octoprox.lib._name
module = _calls.EXTENSION and _calls.EXTENSION.__file__
if sys.argv[2] == "1":
    assert module and os.path.dirname(module) == package, "compiled call path: %s" % module
print("octoprox", octoprox.__version__, "from", package, "library", octoprox.lib._name,
      "compiled call path", module)
' "$work/venv" "$extension"
out="$("${run[@]}" example.py)"
echo "$out"
grep -q "collided: True" <<<"$out" || { echo "expected \"collided: True\""; exit 1; }
