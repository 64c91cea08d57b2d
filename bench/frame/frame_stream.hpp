// The streams of frames opx-frame-bench feeds to every pipeline:
//   real  the shared RGB-D frame (bench::load_frame), seen from the PR2's
//         head camera as in opx-demo --real and Table IV (robot root at the
//         map origin);
//   room  the generated room at 307,200 points (examples/support), seen
//         from the room's own camera; the PR2 stands in the room facing
//         the table (see kRoomBase in frame_stream.cpp).
// Frame k of a stream is the same cloud from a sensor pose moved a little
// (a few mm and mrad, seeded): a robot's camera is never quite still.
#pragma once

#include <cstdint>
#include <string>

#include <octoprox/octoprox.h>

#include "bench_frame.hpp"

namespace frame_bench {

struct Stream {
    std::string name;                      // "real" or "room"
    bench::Frame frame;                    // the cloud; its pose is set per frame
    opx_pose nominal_sensor = OPX_POSE_IDENTITY;  // map frame
    opx_pose robot_base = OPX_POSE_IDENTITY;      // the PR2's root link, map frame
    uint64_t seed = 0;                     // of the sensor motions
};

// The real frame under data_dir (which must hold it); `camera` is the PR2
// head camera's pose with the robot's root at the origin.
Stream make_real_stream(const std::string &data_dir, const opx_pose &camera);

// The generated room (no data needed).
Stream make_room_stream();

// Sets stream.frame's sensor pose to frame `index`'s: the nominal pose
// moved by up to +-kShift metres along each axis and turned by up to
// +-kTurn radians about each of its own axes (uniform, seeded by the
// stream and the index, so every run sees the same motions).
void move_sensor_to_frame(Stream &stream, int index);

// The largest motion, for the report.
extern const double kShift, kTurn;

}  // namespace frame_bench
