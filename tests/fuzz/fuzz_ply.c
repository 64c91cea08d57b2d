/*
 * Fuzz target: PLY files (src/clouds ply_read_file), the input being the
 * file.  A cloud that is read must have all its vertices readable and count
 * its finite ones right; a failure must leave the cloud empty with a
 * message.
 */
#include "fuzz_require.h"
#include "fuzz_file.h"

#include "ply_reader.h"


int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    const char *path = fuzz_scratch_file(".ply", data, size);
    ply_cloud cloud;
    char error[256] = "";
    if (ply_read_file(path, &cloud, error, sizeof error) != 0) {
        FUZZ_REQUIRE(cloud.xyz == NULL && cloud.count == 0);
        FUZZ_REQUIRE(error[0] != '\0');
        return 0;
    }
    FUZZ_REQUIRE(cloud.count == 0 || cloud.xyz != NULL);
    FUZZ_REQUIRE(cloud.finite_count == fuzz_count_finite(cloud.xyz, cloud.count));
    ply_free(&cloud);
    return 0;
}
