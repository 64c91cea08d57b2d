/*
 * Fuzz target: PCD files (src/clouds pcd_read_file), the input being the
 * file.  A cloud that is read must hold width * height points, all of them
 * readable, and count its finite ones right; a failure must leave the cloud
 * empty with a message.
 */
#include "fuzz_require.h"
#include "fuzz_file.h"

#include "pcd_reader.h"


int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    const char *path = fuzz_scratch_file(".pcd", data, size);
    pcd_cloud cloud;
    char error[256] = "";
    if (pcd_read_file(path, &cloud, error, sizeof error) != 0) {
        FUZZ_REQUIRE(cloud.xyz == NULL && cloud.count == 0);
        FUZZ_REQUIRE(error[0] != '\0');
        return 0;
    }
    FUZZ_REQUIRE(cloud.count == (size_t)cloud.width * cloud.height);
    FUZZ_REQUIRE(cloud.count == 0 || cloud.xyz != NULL);
    FUZZ_REQUIRE(cloud.finite_count == fuzz_count_finite(cloud.xyz, cloud.count));
    pcd_free(&cloud);
    return 0;
}
