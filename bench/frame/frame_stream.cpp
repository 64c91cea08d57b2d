#include "frame_stream.hpp"

#include <cmath>

#include "rng.hpp"

extern "C" {
#include "shape_mesh.h"
}

namespace frame_bench {

const double kShift = 0.003;  // m
const double kTurn = 0.003;   // rad

namespace {

// The PR2 in the generated room: 1.45 m from the camera (x = -0.9), facing
// the table (x from 1.2 m, top at 0.73 m) so that its reaching arms come
// over the table's near edge.  Its wheels are 5.5 cm above the floor: the
// floor's cells (up to 5 cm high at the coarsest resolution) would
// otherwise touch the casters in every configuration, and every query
// would stop at that first contact.
const opx_pose kRoomBase = {{0.55, 0.0, 0.055}, {0.0, 0.0, 0.0, 1.0}};

opx_pose frame_pose(const bench::Frame &frame) {
    opx_pose pose = OPX_POSE_IDENTITY;
    for (int i = 0; i < 3; ++i) pose.position[i] = frame.position[i];
    for (int i = 0; i < 4; ++i) pose.orientation[i] = frame.quaternion_xyzw[i];
    return pose;
}

// A rotation by the small rotation vector r (radians) as a unit quaternion.
opx_pose small_motion(const double shift[3], const double r[3]) {
    opx_pose motion = OPX_POSE_IDENTITY;
    const double angle = std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
    const double s = angle > 0.0 ? std::sin(0.5 * angle) / angle : 0.5;
    for (int i = 0; i < 3; ++i) {
        motion.position[i] = shift[i];
        motion.orientation[i] = s * r[i];
    }
    motion.orientation[3] = std::cos(0.5 * angle);
    return motion;
}

}  // namespace

Stream make_real_stream(const std::string &data_dir, const opx_pose &camera) {
    Stream stream;
    stream.name = "real";
    stream.frame = bench::load_frame(data_dir, false);
    stream.nominal_sensor = camera;
    stream.seed = 0x5EA1F7A3u;
    return stream;
}

Stream make_room_stream() {
    Stream stream;
    stream.name = "room";
    stream.frame = bench::load_frame("", true);
    stream.nominal_sensor = frame_pose(stream.frame);
    stream.robot_base = kRoomBase;
    stream.seed = 0x500F7A3u;
    return stream;
}

void move_sensor_to_frame(Stream &stream, int index) {
    paper_tables::Rng rng(stream.seed + static_cast<uint64_t>(index));
    double shift[3], turn[3];
    for (double &v : shift) v = rng.uniform(-kShift, kShift);
    for (double &v : turn) v = rng.uniform(-kTurn, kTurn);
    const opx_pose motion = small_motion(shift, turn);
    opx_pose moved = OPX_POSE_IDENTITY;
    pose_compose(&stream.nominal_sensor, &motion, &moved);  // the motion is in the sensor's own frame
    for (int i = 0; i < 3; ++i) stream.frame.position[i] = moved.position[i];
    for (int i = 0; i < 4; ++i) stream.frame.quaternion_xyzw[i] = moved.orientation[i];
}

}  // namespace frame_bench
