# Debian packages through CPack (`cpack -G DEB` in the build tree, or the
# `package` target): `liboctoprox`, the library under its SONAME, and
# `liboctoprox-dev`, what a build against it needs (headers, the unversioned
# link, pkg-config file, CMake package) and the `octoprox` tool.  The
# install components of src/ and tools/ decide which file goes where.
#
# Dependencies on Debian's libraries come from dpkg-shlibdeps (dpkg-dev),
# so they name the versions of the machine that built the packages; build
# them on the release they are meant for.  The prefix is /usr: the library
# lands in /usr/lib, on the loader's path, and `ldconfig` runs on install
# through the shlibs file's trigger.

# cpack and the install target copy what is built and build nothing: in a
# tree with the tests and benchmarks, "all" is most of the build, and the
# packages need the library and the tool alone.  Build first (cmake --build).
set(CMAKE_SKIP_INSTALL_ALL_DEPENDENCY ON)

set(CPACK_GENERATOR "DEB")
set(CPACK_PACKAGE_NAME "liboctoprox")
set(CPACK_PACKAGE_VENDOR "OctoProx")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_PACKAGING_INSTALL_PREFIX "/usr")
set(OPX_PACKAGE_CONTACT "OctoProx maintainers" CACHE STRING
  "The Maintainer field of the Debian packages (Name <email>)")
set(CPACK_PACKAGE_CONTACT "${OPX_PACKAGE_CONTACT}")

set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_COMPONENTS_ALL runtime dev)
set(CPACK_COMPONENT_DEV_DEPENDS runtime)
set(CPACK_DEBIAN_ENABLE_COMPONENT_DEPENDS ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)

set(CPACK_DEBIAN_RUNTIME_PACKAGE_NAME "liboctoprox")
set(CPACK_DEBIAN_RUNTIME_PACKAGE_SECTION "libs")
set(CPACK_COMPONENT_RUNTIME_DESCRIPTION
  "${PROJECT_DESCRIPTION}\n The shared library liboctoprox (a C ABI).")
set(CPACK_DEBIAN_DEV_PACKAGE_NAME "liboctoprox-dev")
set(CPACK_DEBIAN_DEV_PACKAGE_SECTION "libdevel")
set(CPACK_COMPONENT_DEV_DESCRIPTION
  "${PROJECT_DESCRIPTION}\n Headers, pkg-config file and CMake package of liboctoprox, and the\n octoprox command-line tool.")

set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# A shlibs file, so that packages linking liboctoprox get their dependency
# on it from dpkg-shlibdeps too.
set(CPACK_DEBIAN_PACKAGE_GENERATE_SHLIBS ON)
set(CPACK_DEBIAN_PACKAGE_GENERATE_SHLIBS_POLICY ">=")
# The tool needs liboctoprox, which no installed package declares yet:
# dpkg-shlibdeps finds it in the build tree and skips it (the dev package
# depends on liboctoprox of the same version instead).
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS_PRIVATE_DIRS "${PROJECT_BINARY_DIR}/src")

include(CPack)
