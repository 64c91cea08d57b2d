#!/usr/bin/env bash
# Installs the built project into a fresh prefix and builds
# examples/quickstart.c against the INSTALLED tree two ways, as users do:
#   1. a CMake project with find_package(octoprox CONFIG REQUIRED)
#   2. cc quickstart.c $(pkg-config --cflags --libs octoprox)
# then runs both programs against the installed library.
#   install_test.sh CMAKE BUILD_DIR SOURCE_DIR PREFIX LIBDIR C_COMPILER PKG_CONFIG
set -euo pipefail

if [[ $# -ne 7 ]]; then
    echo "usage: $0 CMAKE BUILD_DIR SOURCE_DIR PREFIX LIBDIR C_COMPILER PKG_CONFIG" >&2
    exit 2
fi
cmake=$1 build_dir=$2 source_dir=$3 prefix=$4 libdir=$5 cc=$6 pkg_config=$7
quickstart=$source_dir/examples/quickstart.c
work=$prefix.work

step() { echo; echo "== $*"; }
fail() { echo "FAIL: $*" >&2; exit 1; }

step "install into $prefix"
rm -rf "$prefix" "$work"
mkdir -p "$work"
"$cmake" --install "$build_dir" --prefix "$prefix"
[[ -f $prefix/include/octoprox/octoprox.h ]] || fail "no installed octoprox.h"
ls "$prefix/$libdir"/liboctoprox.so* >/dev/null || fail "no liboctoprox.so in $prefix/$libdir"
[[ -f $prefix/$libdir/pkgconfig/octoprox.pc ]] || fail "no octoprox.pc in $prefix/$libdir/pkgconfig"
[[ -f $prefix/$libdir/cmake/octoprox/octoproxConfig.cmake ]] || fail "no octoproxConfig.cmake"

step "the SONAME is liboctoprox.so.0.MINOR on 0.x, liboctoprox.so.MAJOR from 1.0 on"
version_part() { sed -nE "s/^#define OPX_VERSION_$1 ([0-9]+).*/\1/p" "$source_dir/include/octoprox/common.h"; }
major=$(version_part MAJOR) minor=$(version_part MINOR)
if [[ $major == 0 ]]; then soname=liboctoprox.so.0.$minor; else soname=liboctoprox.so.$major; fi
actual=$(readelf -d "$prefix/$libdir/liboctoprox.so" | sed -nE 's/.*\(SONAME\).*\[(.*)\]/\1/p')
[[ $actual == "$soname" ]] || fail "the SONAME is '$actual', not $soname"
[[ -e $prefix/$libdir/$soname ]] || fail "no $soname in $prefix/$libdir"
echo "SONAME $actual"

# Run a program against the installed library only; check it used it.
run_installed() {
    local program=$1
    local deps
    deps=$(LD_LIBRARY_PATH="$prefix/$libdir" ldd "$program")
    grep -q "liboctoprox.so.* => $prefix/" <<<"$deps" \
        || fail "$program does not load liboctoprox from $prefix:"$'\n'"$deps"
    local output
    output=$(LD_LIBRARY_PATH="$prefix/$libdir" "$program") || fail "$program exited with $?"
    echo "$output"
    grep -q "is occupied" <<<"$output" || fail "$program: the query point is not occupied"
}

step "CMake consumer: find_package(octoprox CONFIG REQUIRED)"
"$cmake" -S "$source_dir/tests/abi/consumer" -B "$work/cmake" \
    -DCMAKE_PREFIX_PATH="$prefix" \
    -DCMAKE_FIND_PACKAGE_NO_PACKAGE_REGISTRY=ON \
    -DCMAKE_C_COMPILER="$cc" \
    -DQUICKSTART_SOURCE="$quickstart"
grep -q "^octoprox_DIR:PATH=$prefix/" "$work/cmake/CMakeCache.txt" \
    || fail "find_package did not find the installed package in $prefix"
"$cmake" --build "$work/cmake"
run_installed "$work/cmake/quickstart"

step "pkg-config consumer: cc quickstart.c \$(pkg-config --cflags --libs octoprox)"
export PKG_CONFIG_PATH=$prefix/$libdir/pkgconfig
flags=$("$pkg_config" --cflags --libs octoprox)
if [[ $flags != *"$prefix"* ]]; then
    # octoprox.pc bakes in CMAKE_INSTALL_PREFIX at configure time, so an
    # install with --prefix elsewhere needs the prefix redefined.
    echo "NOTE: octoprox.pc does not follow 'cmake --install --prefix' ($flags);"
    echo "      redefining prefix=$prefix"
    flags=$("$pkg_config" --define-variable=prefix="$prefix" --cflags --libs octoprox)
fi
echo "flags: $flags"
# shellcheck disable=SC2086 # the flags are words
"$cc" -std=c99 -pedantic -Wall -Wextra -Werror "$quickstart" $flags -o "$work/quickstart-pc"
run_installed "$work/quickstart-pc"

step "the installed octoprox tool runs (RUNPATH \$ORIGIN/../$libdir, no LD_LIBRARY_PATH)"
[[ -x $prefix/bin/octoprox ]] || fail "no $prefix/bin/octoprox"
# Whole outputs, not pipes into grep -q: with pipefail, a writer still
# writing when grep -q has matched and exited dies of SIGPIPE (flaky under load).
grep -q "liboctoprox.so.* => $prefix/" <<<"$(ldd "$prefix/bin/octoprox")" \
    || fail "$prefix/bin/octoprox does not load liboctoprox from $prefix"
grep -q "^octoprox [0-9]" <<<"$("$prefix/bin/octoprox" --version)" || fail "octoprox --version"

step "OK: quickstart builds and runs against the installed octoprox both ways; the tool runs"
