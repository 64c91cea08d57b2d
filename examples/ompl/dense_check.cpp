#include "dense_check.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace opx_ompl {
namespace {

void require(opx_status status, const char *what) {
    if (status != OPX_OK) throw std::runtime_error(std::string(what) + ": " + opx_last_error());
}

// Every link as the URDF gives it.
void unpad(opx_linkset *robot) {
    uint32_t links = 0;
    require(opx_linkset_get_link_count(robot, &links), "opx_linkset_get_link_count");
    require(opx_linkset_set_padding(robot, 0.0), "opx_linkset_set_padding");
    for (uint32_t l = 0; l < links; ++l) require(opx_linkset_set_link_padding(robot, l, 0.0), "opx_linkset_set_link_padding");
}

struct Checker {
    const CheckScene &scene;
    opx_linkset *robot = nullptr;
    opx_query *query = nullptr;
    std::vector<double> row;

    Checker(const CheckScene &s, bool unpadded) : scene(s), row(s.joint_positions) {
        require(opx_linkset_clone(s.robot, &robot), "opx_linkset_clone");
        if (unpadded) unpad(robot);
        require(opx_query_create(nullptr, &query), "opx_query_create");
        if (s.world != nullptr) require(opx_query_set_world(query, s.world), "opx_query_set_world");
    }
    ~Checker() {
        opx_query_destroy(query);
        opx_linkset_destroy(robot);
    }

    void place(const std::vector<double> &values) {
        for (size_t d = 0; d < values.size(); ++d) row[scene.planned_joints[d]] = values[d];
        require(opx_linkset_set_joint_positions(robot, row.data(), row.size(), &scene.base_pose),
                "opx_linkset_set_joint_positions");
    }

    // Places the copy at `values` (the planned joints) and checks it.
    void check(const std::vector<double> &values, DenseCheckResult &out) {
        place(values);
        opx_collision_request request = OPX_COLLISION_REQUEST_INIT;
        request.max_contacts = 0;
        request.unknown_policy = scene.unknown_policy;
        opx_collision_result hit = OPX_COLLISION_RESULT_INIT;
        require(opx_query_collide(query, scene.map, robot, &request, &hit), "opx_query_collide");
        opx_self_collision_result self = OPX_SELF_COLLISION_RESULT_INIT;
        if (scene.self_collision) {
            opx_self_collision_request self_request = OPX_SELF_COLLISION_REQUEST_INIT;
            self_request.max_contacts = 0;
            require(opx_query_self_collide(query, robot, &self_request, &self), "opx_query_self_collide");
        }
        ++out.configurations;
        out.colliding += hit.collided != 0;
        out.self_colliding += self.collided != 0;
    }
};

const char *link_name(const opx_linkset *robot, uint32_t link) {
    const char *name = "?";
    opx_linkset_get_link_name(robot, link, &name);
    return name;
}

}  // namespace

void explain_collisions(const CheckScene &scene, const std::vector<double> &values, const char *label) {
    Checker checker(scene, false);
    checker.place(values);
    opx_collision_request request = OPX_COLLISION_REQUEST_INIT;
    request.max_contacts = 8;
    opx_collision_result hit = OPX_COLLISION_RESULT_INIT;
    require(opx_query_collide(checker.query, scene.map, checker.robot, &request, &hit), "opx_query_collide");
    for (size_t i = 0; i < hit.contact_count; ++i) {
        opx_contact contact = OPX_CONTACT_INIT;
        require(opx_query_get_contact(checker.query, i, &contact), "opx_query_get_contact");
        std::printf("  %s: link %s touches %s at (%.2f, %.2f, %.2f)\n", label, link_name(checker.robot, contact.link),
                    contact.object >= 0 ? "a world object" : "a map cell", contact.cell_center[0],
                    contact.cell_center[1], contact.cell_center[2]);
    }
    opx_self_collision_request self_request = OPX_SELF_COLLISION_REQUEST_INIT;
    self_request.max_contacts = 8;
    opx_self_collision_result self = OPX_SELF_COLLISION_RESULT_INIT;
    require(opx_query_self_collide(checker.query, checker.robot, &self_request, &self), "opx_query_self_collide");
    for (size_t i = 0; i < self.contact_count; ++i) {
        opx_self_contact contact = OPX_SELF_CONTACT_INIT;
        require(opx_query_get_self_contact(checker.query, i, &contact), "opx_query_get_self_contact");
        std::printf("  %s: links %s and %s touch\n", label, link_name(checker.robot, contact.link_a),
                    link_name(checker.robot, contact.link_b));
    }
}

DenseCheckResult dense_check(const CheckScene &scene, const std::vector<std::vector<double>> &waypoints, double step,
                             bool unpadded) {
    DenseCheckResult out;
    Checker checker(scene, unpadded);
    if (waypoints.empty()) return out;
    checker.check(waypoints.front(), out);
    for (size_t w = 0; w + 1 < waypoints.size(); ++w) {
        const std::vector<double> &a = waypoints[w], &b = waypoints[w + 1];
        double longest = 0.0;
        for (size_t d = 0; d < a.size(); ++d) longest = std::max(longest, std::fabs(b[d] - a[d]));
        const uint64_t steps = std::max<uint64_t>(1, static_cast<uint64_t>(std::ceil(longest / step)));
        std::vector<double> values(a.size());
        for (uint64_t i = 1; i <= steps; ++i) {
            const double t = static_cast<double>(i) / static_cast<double>(steps);
            for (size_t d = 0; d < a.size(); ++d) values[d] = i == steps ? b[d] : a[d] + t * (b[d] - a[d]);
            const uint64_t before = out.colliding + out.self_colliding;
            checker.check(values, out);
            if (out.first_collision_at < 0 && out.colliding + out.self_colliding > before)
                out.first_collision_at = static_cast<double>(w) + t;
        }
    }
    return out;
}

}  // namespace opx_ompl
