// The frame the ingest benchmark inserts: the real Kinect frame of the
// shared data when present, else the synthetic room of examples/support.
#pragma once

#include <string>
#include <vector>

namespace bench {

struct Frame {
    std::vector<float> xyz;  // packed x y z, sensor (optical) frame, NaN kept
    size_t count = 0;
    size_t finite_count = 0;
    unsigned width = 0, height = 0;
    double position[3] = {0, 0, 0};           // sensor pose in the map frame
    double quaternion_xyzw[4] = {0, 0, 0, 1};
    std::string source;                       // for the report
};

// The real frame under data_dir, or the generated room when force_generated
// is set or the file is missing (source then says why).
Frame load_frame(const std::string &data_dir, bool force_generated);

}  // namespace bench
