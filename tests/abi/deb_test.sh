#!/usr/bin/env bash
# Builds the Debian packages with cpack in the build tree, extracts them
# (dpkg-deb -x, no root) into a fresh root and builds the README's C
# example against that root two ways, as users of the packages do:
#   1. a CMake project with find_package(octoprox CONFIG REQUIRED)
#   2. cc example.c $(pkg-config --cflags --libs octoprox)
# then runs both, and the packaged `octoprox` tool.
#   deb_test.sh CMAKE CPACK BUILD_DIR SOURCE_DIR WORK C_COMPILER PKG_CONFIG
set -euo pipefail

if [[ $# -ne 7 ]]; then
    echo "usage: $0 CMAKE CPACK BUILD_DIR SOURCE_DIR WORK C_COMPILER PKG_CONFIG" >&2
    exit 2
fi
cmake=$1 cpack=$2 build_dir=$3 source_dir=$4 work=$5 cc=$6 pkg_config=$7

step() { echo; echo "== $*"; }
fail() { echo "FAIL: $*" >&2; exit 1; }

for tool in dpkg-deb dpkg-shlibdeps; do
    command -v "$tool" >/dev/null || { echo "deb_packages skipped: no $tool (Debian's dpkg-dev)"; exit 77; }
done

rm -rf "$work"
mkdir -p "$work/packages" "$work/root" "$work/example"

step "the library and the tool are built"
"$cmake" --build "$build_dir" --target octoprox octoprox_cli

step "cpack -G DEB"
"$cpack" -G DEB --config "$build_dir/CPackConfig.cmake" -B "$work/packages" >"$work/cpack.log" 2>&1 \
    || { cat "$work/cpack.log"; fail "cpack failed"; }
lib_deb=$(ls "$work"/packages/liboctoprox_*.deb) || fail "no liboctoprox_*.deb"
dev_deb=$(ls "$work"/packages/liboctoprox-dev_*.deb) || fail "no liboctoprox-dev_*.deb"

version_part() { sed -nE "s/^#define OPX_VERSION_$1 ([0-9]+).*/\1/p" "$source_dir/include/octoprox/common.h"; }
major=$(version_part MAJOR) minor=$(version_part MINOR) patch=$(version_part PATCH)
version=$major.$minor.$patch
if [[ $major == 0 ]]; then soname=liboctoprox.so.0.$minor; else soname=liboctoprox.so.$major; fi

step "contents and control fields"
for deb in "$lib_deb" "$dev_deb"; do
    echo "-- $(basename "$deb")"
    dpkg-deb -f "$deb" Package Version Section Depends
    dpkg-deb -c "$deb" | awk '{$1 = $2 = $3 = $4 = $5 = ""; print "  " $0}'
done
lib_files=$(dpkg-deb -c "$lib_deb")
dev_files=$(dpkg-deb -c "$dev_deb")
grep -qE "\./usr/lib/$soname( -> |\$)" <<<"$lib_files" || fail "liboctoprox has no /usr/lib/$soname"
grep -q "include/" <<<"$lib_files" && fail "liboctoprox carries headers"
for file in /usr/include/octoprox/octoprox.h /usr/lib/pkgconfig/octoprox.pc \
            /usr/lib/cmake/octoprox/octoproxConfig.cmake /usr/bin/octoprox "/usr/lib/liboctoprox.so -> "; do
    grep -qF ".$file" <<<"$dev_files" || fail "liboctoprox-dev has no $file"
done
[[ $(dpkg-deb -f "$lib_deb" Version) == "$version" ]] || fail "liboctoprox's version is not $version"
lib_depends=$(dpkg-deb -f "$lib_deb" Depends)
# dpkg-shlibdeps computed them: the C++ runtime and OctoMap at least.
grep -q "libstdc++6" <<<"$lib_depends" || fail "liboctoprox does not depend on libstdc++6: $lib_depends"
grep -q "liboctomap" <<<"$lib_depends" || fail "liboctoprox does not depend on liboctomap: $lib_depends"
grep -qF "liboctoprox (= $version)" <<<"$(dpkg-deb -f "$dev_deb" Depends)" \
    || fail "liboctoprox-dev does not depend on liboctoprox (= $version)"
grep -q "^liboctoprox " <<<"$(dpkg-deb --ctrl-tarfile "$lib_deb" | tar -xO ./shlibs)" \
    || fail "liboctoprox has no shlibs file"

step "dpkg-deb -x into $work/root"
root=$work/root
dpkg-deb -x "$lib_deb" "$root"
dpkg-deb -x "$dev_deb" "$root"
libdir=$root/usr/lib

# The README's first C block that has a main().
example=$work/example/readme.c
awk '/^```c$/ {inside = 1; block = ""; next}
     inside && /^```$/ {inside = 0; if (block ~ /int main/) {printf "%s", block; exit}; next}
     inside {block = block $0 "\n"}' "$source_dir/README.md" >"$example"
[[ -s $example ]] || fail "no C example with main() in README.md"

# Run a program against the extracted library only; check it used it.
run_packaged() {
    local program=$1 deps output
    deps=$(LD_LIBRARY_PATH="$libdir" ldd "$program")
    grep -q "$soname => $libdir/" <<<"$deps" \
        || fail "$program does not load $soname from $libdir:"$'\n'"$deps"
    output=$(LD_LIBRARY_PATH="$libdir" "$program") || fail "$program exited with $?"
    echo "$output"
    grep -q "^class 3, p = " <<<"$output" || fail "$program: the probe is not occupied"
}

step "CMake: find_package(octoprox CONFIG REQUIRED) in $root/usr"
"$cmake" -S "$source_dir/tests/abi/consumer" -B "$work/example/cmake" \
    -DCMAKE_PREFIX_PATH="$root/usr" \
    -DCMAKE_FIND_PACKAGE_NO_PACKAGE_REGISTRY=ON \
    -DCMAKE_C_COMPILER="$cc" \
    -DQUICKSTART_SOURCE="$example" >"$work/example/cmake.log" \
    || { cat "$work/example/cmake.log"; fail "configure"; }
grep -q "^octoprox_DIR:PATH=$libdir/cmake/octoprox" "$work/example/cmake/CMakeCache.txt" \
    || fail "find_package did not find the package in $root"
"$cmake" --build "$work/example/cmake"
run_packaged "$work/example/cmake/quickstart"

step "pkg-config: cc readme.c \$(pkg-config --cflags --libs octoprox)"
flags=$(PKG_CONFIG_PATH=$libdir/pkgconfig PKG_CONFIG_LIBDIR=$libdir/pkgconfig "$pkg_config" --cflags --libs octoprox)
echo "flags: $flags"
[[ $flags == *"-I$root/"* ]] || fail "pkg-config does not point into $root: $flags"
# shellcheck disable=SC2086 # the flags are words
"$cc" -std=c99 -pedantic -Wall -Wextra -Werror "$example" $flags -o "$work/example/readme-pc"
run_packaged "$work/example/readme-pc"

step "the packaged tool runs against the packaged library (RUNPATH, no LD_LIBRARY_PATH)"
grep -q "$soname => $root/usr/" <<<"$(ldd "$root/usr/bin/octoprox")" \
    || fail "$root/usr/bin/octoprox does not load $soname from $libdir"
grep -q "^octoprox $version" <<<"$("$root/usr/bin/octoprox" --version)" || fail "octoprox --version"

step "OK: the packages build, and the README's example builds and runs against them both ways"
