#include "bench_frame.hpp"

#include "pcd_reader.h"
#include "support/room_frame.h"

#include <cstdio>
#include <stdexcept>
#include <sys/stat.h>

namespace bench {
namespace {

const char *const kRealFrame = "rgbd/frame_20121214T142255.814212_binary.pcd";

bool file_exists(const std::string &path) {
    struct stat info;
    return stat(path.c_str(), &info) == 0;
}

Frame generated_frame(const std::string &why) {
    room_frame room;
    if (room_frame_generate(1, &room) != 0) throw std::runtime_error("out of memory generating the room frame");
    Frame frame;
    frame.xyz.assign(room.xyz, room.xyz + 3 * room.count);
    frame.count = room.count;
    frame.finite_count = room.finite_count;
    frame.width = room.width;
    frame.height = room.height;
    for (int i = 0; i < 3; ++i) frame.position[i] = room.sensor_position[i];
    for (int i = 0; i < 4; ++i) frame.quaternion_xyzw[i] = room.sensor_orientation[i];
    frame.source = "generated room (examples/support/room_frame.c)" + why;
    room_frame_free(&room);
    return frame;
}

// The real frame is in the camera's own frame: identity pose.
Frame real_frame(const std::string &path) {
    pcd_cloud cloud;
    char error[512];
    if (pcd_read_file(path.c_str(), &cloud, error, sizeof error) != 0) throw std::runtime_error(error);
    Frame frame;
    frame.xyz.assign(cloud.xyz, cloud.xyz + 3 * cloud.count);
    frame.count = cloud.count;
    frame.finite_count = cloud.finite_count;
    frame.width = cloud.width;
    frame.height = cloud.height;
    frame.source = "real Kinect frame " + path;
    pcd_free(&cloud);
    return frame;
}

}  // namespace

Frame load_frame(const std::string &data_dir, bool force_generated) {
    if (force_generated) return generated_frame(" (--generated)");
    const std::string path = data_dir + "/" + kRealFrame;
    if (!file_exists(path)) return generated_frame(", because " + path + " is missing");
    return real_frame(path);
}

}  // namespace bench
