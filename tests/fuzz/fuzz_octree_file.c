/*
 * Fuzz target: OctoMap .bt and .ot files as bytes in memory
 * (opx_octree_load_memory reads both, by their first line).  The input is
 * the file as it is, so any real map is a seed.  A map that loads is then
 * read every way (fuzz_tree.h).
 */
#include "fuzz_check.h"
#include "fuzz_tree.h"

#include <stdint.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    opx_octree *tree = (opx_octree *)&tree; /* must be reset to NULL on failure */
    const opx_status status = FUZZ_CALL(opx_octree_load_memory, data, size, NULL, &tree);
    fuzz_check_loaded(status, tree);
    return 0;
}
