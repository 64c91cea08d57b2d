/*
 * Fuzz target: the data of a ROS octomap_msgs/Octomap message
 * (opx_octree_load_message).  Input layout:
 *   byte 0      bit 0: binary (a .bt body) or full (a .ot body);
 *               bit 1: options with free_threshold 0.3 (an uncertain band)
 *   bytes 1-8   the message's resolution, a little-endian double as it is
 *               (so denormals, NaN and infinities are reachable)
 *   the rest    the message's data
 */
#include "fuzz_check.h"
#include "fuzz_input.h"
#include "fuzz_tree.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    fuzz_input in = {data, size};
    const uint8_t flags = take_u8(&in);
    const double resolution = take_raw_double(&in);
    opx_octree_options options = OPX_OCTREE_OPTIONS_INIT;
    options.free_threshold = 0.3;
    opx_octree *tree = (opx_octree *)&tree; /* must be reset to NULL on failure */
    const opx_status status = FUZZ_CALL(opx_octree_load_message, in.data, in.size, flags & 1, resolution,
                                        (flags & 2) ? &options : NULL, &tree);
    fuzz_check_loaded(status, tree);
    return 0;
}
