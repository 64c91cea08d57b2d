#include "fcl_check.hpp"

#include <cstdint>

#include <fcl/narrowphase/collision.h>

namespace batch_bench {
namespace {

struct SelfState {
    const std::vector<char> *allowed;
    size_t links;
    fcl::CollisionRequestd request;
    bool done = false;
};

uint32_t link_of(const fcl::CollisionObjectd *object) {
    return static_cast<uint32_t>(reinterpret_cast<uintptr_t>(object->getUserData()));
}

// Stops (returns true) at the first contact of an allowed pair.
bool first_allowed_contact(fcl::CollisionObjectd *a, fcl::CollisionObjectd *b, void *data) {
    auto *state = static_cast<SelfState *>(data);
    if (state->done) return true;
    const uint32_t la = link_of(a), lb = link_of(b);
    if (!(*state->allowed)[la * state->links + lb]) return false;
    fcl::CollisionResultd result;
    fcl::collide(a, b, state->request, result);
    state->done = result.isCollision();
    return state->done;
}

}  // namespace

FclCheck::FclCheck(Robot &robot, fcl::CollisionObjectd &octree) : robot_(*robot.fcl), octree_(octree) {
    uint32_t links = 0;
    paper_tables::check_opx(opx_linkset_get_link_count(robot.links.get(), &links), "opx_linkset_get_link_count");
    links_ = links;
    allowed_.assign(links_ * links_, 1);
    for (size_t l = 0; l < links_; ++l) allowed_[l * links_ + l] = 0;
    for (const auto &pair : robot.disabled)
        allowed_[pair.first * links_ + pair.second] = allowed_[pair.second * links_ + pair.first] = 0;
    for (size_t i = 0; i < robot_.object_count(); ++i)
        robot_.object(i).setUserData(reinterpret_cast<void *>(static_cast<uintptr_t>(robot_.object_link(i))));
}

bool FclCheck::world_collides() { return paper_tables::fcl_octree_collides(robot_.manager(), octree_); }

bool FclCheck::self_collides() {
    SelfState state{&allowed_, links_, {}, false};
    robot_.manager().collide(&state, first_allowed_contact);
    return state.done;
}

}  // namespace batch_bench
