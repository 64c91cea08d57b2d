/*
 * Where package://NAME/... mesh URIs are looked up, in order (the first
 * existing file wins, so explicit entries win):
 *   1. the --package-dir entries as given ("DIR" or "NAME=DIR");
 *   2. each folder of $ROS_PACKAGE_PATH (colon-separated): a package
 *      folder itself or a folder of packages; a package.xml in it or in
 *      one of its subfolders maps its <name> to that folder, so a package
 *      folder named otherwise than its package is found too;
 *   3. PREFIX/share for each PREFIX of $AMENT_PREFIX_PATH (ROS 2 installs
 *      keep PREFIX/share/NAME).
 * See opx_urdf_options.package_dirs (include/octoprox/robot.h) for how an
 * entry resolves a URI.
 */
#ifndef OPX_TOOLS_PACKAGE_PATHS_H
#define OPX_TOOLS_PACKAGE_PATHS_H

#include <stddef.h>

typedef struct package_paths {
    char **entries; /* count entries for opx_urdf_options.package_dirs */
    size_t count;
    size_t capacity;
} package_paths;

/* Builds the list from the explicit entries and the environment; 0, or
 * -1 out of memory (*out then empty). */
int package_paths_build(const char *const *explicit_entries, size_t explicit_count, package_paths *out);
void package_paths_free(package_paths *paths);

#endif /* OPX_TOOLS_PACKAGE_PATHS_H */
