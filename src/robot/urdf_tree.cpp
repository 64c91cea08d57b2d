#include "robot/urdf_tree.hpp"

#include "base/error.hpp"

namespace octoprox {
namespace {

constexpr uint32_t kNone = UINT32_MAX;

class TreeCheck {
public:
    TreeCheck(const std::vector<std::string> &links, const std::vector<TreeJoint> &joints, const std::string &source)
        : links_(links), joints_(joints), source_(source), parent_joint_(links.size(), kNone) {}

    void run() {
        link_parents();
        const uint32_t root = single_root();
        check_depths(root);
    }

private:
    [[noreturn]] void fail(const std::string &what) const { throw_corrupt(source_ + ": " + what); }
    std::string link(uint32_t l) const { return "link '" + links_[l] + "'"; }
    std::string joint(uint32_t j) const { return "joint '" + joints_[j].name + "'"; }

    void link_parents() {
        for (uint32_t j = 0; j < joints_.size(); ++j) {
            const TreeJoint &tj = joints_[j];
            if (tj.parent == tj.child)
                fail(joint(j) + " has " + link(tj.child) + " as both parent and child: a link cannot be its own ancestor");
            if (parent_joint_[tj.child] != kNone)
                fail(link(tj.child) + " is the child of two joints, '" + joints_[parent_joint_[tj.child]].name +
                     "' and '" + tj.name + "'");
            parent_joint_[tj.child] = j;
        }
    }

    uint32_t single_root() const {
        uint32_t root = kNone;
        for (uint32_t l = 0; l < links_.size(); ++l) {
            if (parent_joint_[l] != kNone) continue;
            if (root != kNone)
                fail("links '" + links_[root] + "' and '" + links_[l] +
                     "' are both roots (the child of no joint); a URDF has one root link");
            root = l;
        }
        if (root == kNone) fail_cycle_above(0);  // every link has a parent: there is a cycle
        return root;
    }

    // Walks up from `start`, which the root does not reach, to the cycle
    // it hangs from, and names the joint that closes it.
    [[noreturn]] void fail_cycle_above(uint32_t start) const {
        std::vector<bool> seen(links_.size(), false);
        uint32_t l = start;
        while (!seen[l]) {
            seen[l] = true;
            l = joints_[parent_joint_[l]].parent;
        }
        fail(joint(parent_joint_[l]) + " closes a cycle: " + link(l) + " is its own ancestor");
    }

    // Breadth first from the root, without recursion.
    void check_depths(uint32_t root) const {
        std::vector<std::vector<uint32_t>> children(links_.size());
        for (uint32_t j = 0; j < joints_.size(); ++j) children[joints_[j].parent].push_back(j);
        std::vector<uint32_t> depth(links_.size(), kNone), queue{root};
        depth[root] = 0;
        for (size_t next = 0; next < queue.size(); ++next) {
            for (uint32_t j : children[queue[next]]) {
                const uint32_t child = joints_[j].child;
                depth[child] = depth[queue[next]] + 1;
                if (depth[child] > kMaxChainDepth)
                    fail(link(child) + " (below " + joint(j) + ") is " + std::to_string(depth[child]) +
                         " joints below the root link; the limit is " + std::to_string(kMaxChainDepth));
                queue.push_back(child);
            }
        }
        for (uint32_t l = 0; l < links_.size(); ++l)
            if (depth[l] == kNone) fail_cycle_above(l);
    }

    const std::vector<std::string> &links_;
    const std::vector<TreeJoint> &joints_;
    const std::string &source_;
    std::vector<uint32_t> parent_joint_;  // per link, kNone for the root
};

}  // namespace

void check_kinematic_tree(const std::vector<std::string> &links, const std::vector<TreeJoint> &joints,
                          const std::string &source) {
    TreeCheck(links, joints, source).run();
}

}  // namespace octoprox
