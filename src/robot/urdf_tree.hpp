// A URDF's kinematic tree, checked on names before urdfdom builds it:
// urdfdom links its links and joints by shared_ptr both ways, so a cycle
// leaks them; it reports what it rejects on stderr only; and it walks the
// tree by recursion, one stack frame per level.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace octoprox {

// Deeper chains are rejected: urdfdom's recursion then needs under 100 KB
// of stack (a thread's stack may be that small); robots are far shallower.
constexpr size_t kMaxChainDepth = 1000;

struct TreeJoint {
    std::string name;
    uint32_t parent = 0, child = 0;  // link indices
};

// Throws ApiError(OPX_ERROR_CORRUPT) prefixed with `source`, naming the
// joint or links at fault, when a joint's parent is its child, a link is
// the child of two joints, there is not exactly one root link (the child
// of no joint), a link is its own ancestor, or a link lies more than
// kMaxChainDepth joints below the root.
void check_kinematic_tree(const std::vector<std::string> &links, const std::vector<TreeJoint> &joints,
                          const std::string &source);

}  // namespace octoprox
