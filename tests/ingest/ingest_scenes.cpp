#include "ingest_scenes.hpp"

#include <algorithm>
#include <cmath>

namespace ingest {

Frame random_frame(std::mt19937 &rng, float spread, size_t count, bool outside) {
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    Frame frame;
    frame.origin = octomap::point3d(0.3f * unit(rng), 0.3f * unit(rng), 0.3f * unit(rng));
    for (size_t i = 0; i < count; ++i) {
        const float reach = (i % 10 == 0) ? 4.0f * spread : spread;
        frame.points.emplace_back(reach * unit(rng), reach * unit(rng), reach * unit(rng));
    }
    if (outside) {
        frame.points.emplace_back(1e5f, 0.0f, 0.0f);
        frame.points.emplace_back(0.0f, -3e4f, 1.0f);
    }
    return frame;
}

namespace {

// Where a ray from inside the room first meets a wall, the floor, the
// ceiling or the top of a table.
float room_hit(const octomap::point3d &o, const octomap::point3d &d) {
    const float lo[3] = {-3.0f, -3.0f, 0.0f}, hi[3] = {3.0f, 3.0f, 2.5f};
    float t = 1e9f;
    for (int a = 0; a < 3; ++a) {
        if (d(a) > 0) t = std::min(t, (hi[a] - o(a)) / d(a));
        if (d(a) < 0) t = std::min(t, (lo[a] - o(a)) / d(a));
    }
    if (d(2) < 0) {  // a table top at 0.75 m over [0.5, 1.7] x [-0.6, 0.6]
        const float tt = (0.75f - o(2)) / d(2);
        const float x = o(0) + tt * d(0), y = o(1) + tt * d(1);
        if (tt > 0 && x > 0.5f && x < 1.7f && y > -0.6f && y < 0.6f) t = std::min(t, tt);
    }
    return t;
}

}  // namespace

Frame room_frame(const octomap::point3d &origin, float yaw) {
    Frame frame;
    frame.origin = origin;
    const float fx = 525.0f, cx = 319.5f, cy = 239.5f;
    for (int v = 0; v < 480; ++v)
        for (int u = 0; u < 640; ++u) {
            // Camera looking along +x (rotated by yaw), image y down.
            const float right = (u - cx) / fx, down = (v - cy) / fx;
            const float c = std::cos(yaw), s = std::sin(yaw);
            octomap::point3d d(c - s * -right, s + c * -right, -down);
            d.normalize();
            frame.points.push_back(origin + d * room_hit(origin, d));
        }
    return frame;
}

namespace {

// An origin where ties are likeliest: a cell corner, a face, a centre
// (which 0, 1, 2), or off the grid (3); r is the resolution.
octomap::point3d tie_origin(float r, int which) {
    const octomap::point3d origins[4] = {octomap::point3d(0.0f, 0.0f, 0.0f), octomap::point3d(0.5f * r, 0.0f, 0.0f),
                                         octomap::point3d(0.5f * r, 0.5f * r, 0.5f * r),
                                         octomap::point3d(0.3f * r, -0.7f * r, 0.1f * r)};
    return origins[which];
}

}  // namespace

Frame tie_frame(double resolution, int variant) {
    const float r = static_cast<float>(resolution);
    Frame frame;
    frame.origin = tie_origin(r, variant % 3);
    for (int i = -12; i <= 12; ++i)
        for (int j = -12; j <= 12; ++j) {
            const float a = i * r, b = j * r;
            frame.points.emplace_back(a, b, 9.0f * r);          // face points on a plane ahead
            frame.points.emplace_back(9.0f * r, a, b);
            frame.points.emplace_back(a, -9.0f * r, 0.5f * b);  // edges
            frame.points.emplace_back(a + 0.5f * r, b, -7.0f * r);
        }
    for (int k = 1; k <= 20; ++k) {
        const float s = k * r;
        for (int sx = -1; sx <= 1; ++sx)
            for (int sy = -1; sy <= 1; ++sy)
                for (int sz = -1; sz <= 1; ++sz)  // the axes and the diagonals
                    frame.points.push_back(frame.origin + octomap::point3d(sx * s, sy * s, sz * s));
    }
    return frame;
}

Frame dense_frame(double resolution, int variant) {
    const float r = static_cast<float>(resolution);
    Frame frame;
    frame.origin = tie_origin(r, variant % 4);
    // Row after row, a quarter cell apart: every fourth point of a row and
    // every fourth row lie on cell faces, so the cells hold points on their
    // faces, edges and corners.
    const float step = 0.25f * r;
    for (int row = -48; row <= 48; ++row)
        for (int column = -48; column <= 48; ++column) {
            const float x = column * step, y = row * step;
            frame.points.emplace_back(x, y, 9.0f * r);                        // a wall on cell faces
            frame.points.emplace_back(x, y, 6.0f * r + 0.5f * x - 0.25f * y);  // a slanted one
            frame.points.emplace_back(-7.0f * r, y, x);                       // one across x
        }
    return frame;
}

}  // namespace ingest
