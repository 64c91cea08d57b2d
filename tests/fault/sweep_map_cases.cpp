// Sweep cases that make or change maps and link sets.
#include "fault_answers.hpp"
#include "fault_scene.hpp"
#include "sweep_cases.hpp"

#include <cstring>
#include <string>

namespace fault {
namespace {

constexpr double kResolution = 0.1;
constexpr size_t kMapPoints = 300;
constexpr size_t kFramePoints = 60;
constexpr size_t kLargeFramePoints = 700;   // the node pool grows several times

// The small map every case starts from, as a .ot image.
const std::vector<unsigned char> &base_image() {
    static const std::vector<unsigned char> image = [] {
        opx_octree *tree = room_map(kResolution, kMapPoints, 1);
        std::vector<unsigned char> bytes = map_image(tree, OPX_FORMAT_OT);
        opx_octree_destroy(tree);
        return bytes;
    }();
    return image;
}

opx_octree *load_base_map() {
    const opx_octree_options options = map_options(kResolution);
    opx_octree *tree = nullptr;
    require_ok(opx_octree_load_memory(base_image().data(), base_image().size(), &options, &tree),
               "opx_octree_load_memory");
    return tree;
}

// A call that makes a new map: failed, it leaves *out NULL.
class LoadAttempt : public Attempt {
public:
    ~LoadAttempt() override { opx_octree_destroy(tree_); }
    void record_state(Record &record) override { record.add("out is NULL", static_cast<uint64_t>(tree_ == nullptr)); }
    void record_answer(Record &record) override { record_map(record, tree_); }
    bool makes_object() const override { return true; }

protected:
    opx_octree *tree_ = nullptr;
};

class LoadImage : public LoadAttempt {
public:
    explicit LoadImage(int32_t format) : image_(map_image_of_base(format)) {}
    opx_status call() override {
        const opx_octree_options options = map_options(kResolution);
        return opx_octree_load_memory(image_.data(), image_.size(), &options, &tree_);
    }

private:
    static std::vector<unsigned char> map_image_of_base(int32_t format) {
        opx_octree *tree = load_base_map();
        std::vector<unsigned char> image = map_image(tree, format);
        opx_octree_destroy(tree);
        return image;
    }
    std::vector<unsigned char> image_;
};

// A message's data is the file's body: what follows the line "data".
class LoadMessage : public LoadAttempt {
public:
    explicit LoadMessage(int32_t binary) : binary_(binary) {
        opx_octree *tree = load_base_map();
        const std::vector<unsigned char> image = map_image(tree, binary ? OPX_FORMAT_BT : OPX_FORMAT_OT);
        opx_octree_destroy(tree);
        const std::string text(image.begin(), image.end());
        body_ = text.substr(text.find("\ndata\n") + 6);
    }
    opx_status call() override {
        const opx_octree_options options = map_options(kResolution);
        return opx_octree_load_message(body_.data(), body_.size(), binary_, kResolution, &options, &tree_);
    }

private:
    int32_t binary_;
    std::string body_;
};

class InsertFrame : public Attempt {
public:
    InsertFrame(int32_t mode, size_t points)
        : tree_(load_base_map()), mode_(mode), points_(points), cloud_(room_cloud(points, 2)) {}
    ~InsertFrame() override { opx_octree_destroy(tree_); }
    opx_status call() override {
        const opx_insert_options options = sensor_insert_options(mode_);
        return opx_octree_insert_points(tree_, cloud_.data(), points_, 0, OPX_SCALAR_FLOAT32, &options,
                                        &report_);
    }
    void record_state(Record &record) override { record_map(record, tree_); }
    void record_answer(Record &record) override {
        record_map(record, tree_);
        record.add("points_used", report_.points_used);
        record.add("cells_hit", report_.cells_hit);
        record.add("cells_missed", report_.cells_missed);
    }

private:
    opx_octree *tree_;
    int32_t mode_;
    size_t points_;
    std::vector<float> cloud_;
    opx_insert_report report_ = OPX_INSERT_REPORT_INIT;
};

// The arm (with its gripper's capsule, hull and mesh) filtered out of a
// frame, its volume cleared: a failure while the robot's solids, bins or
// cells are made leaves the map as it was.
class InsertFiltered : public Attempt {
public:
    InsertFiltered() : tree_(load_base_map()), arm_(arm_with_gripper()), cloud_(room_cloud(kFramePoints, 2)) {
        arm_pose(arm_, 3);
    }
    ~InsertFiltered() override {
        opx_octree_destroy(tree_);
        opx_linkset_destroy(arm_);
    }
    opx_status call() override {
        opx_insert_options options = sensor_insert_options(OPX_INSERT_RAYCAST);
        options.robot = arm_;
        options.robot_padding = 0.03;
        options.clear_robot_volume = 1;
        return opx_octree_insert_points(tree_, cloud_.data(), kFramePoints, 0, OPX_SCALAR_FLOAT32, &options,
                                        &report_);
    }
    void record_state(Record &record) override { record_map(record, tree_); }
    void record_answer(Record &record) override {
        record_map(record, tree_);
        record.add("points_used", report_.points_used);
        record.add("points_on_robot", report_.points_on_robot);
        record.add("points_shadowed", report_.points_shadowed);
        record.add("cells_cleared", report_.cells_cleared);
    }

private:
    opx_octree *tree_;
    opx_linkset *arm_;
    std::vector<float> cloud_;
    opx_insert_report report_ = OPX_INSERT_REPORT_INIT;
};

// A 16 x 12 depth frame in millimetres (every seventh pixel without a
// return) through a pinhole camera at the sensor's pose: a failure while
// its points are made, or while they go in, leaves the map as it was.
class InsertDepthImage : public Attempt {
public:
    InsertDepthImage() : tree_(load_base_map()), depth_(kDepthWidth * kDepthHeight) {
        for (size_t i = 0; i < depth_.size(); ++i)
            depth_[i] = i % 7 == 0 ? 0 : static_cast<uint16_t>(1500 + 13 * (i % 40));
    }
    ~InsertDepthImage() override { opx_octree_destroy(tree_); }
    opx_status call() override {
        const opx_insert_options options = sensor_insert_options(OPX_INSERT_RAYCAST);
        opx_depth_image image = OPX_DEPTH_IMAGE_INIT;
        image.data = depth_.data();
        image.width = kDepthWidth;
        image.height = kDepthHeight;
        opx_camera_intrinsics camera = OPX_CAMERA_INTRINSICS_INIT;
        camera.fx = camera.fy = 10.0;
        camera.cx = 7.5;
        camera.cy = 5.5;
        return opx_octree_insert_depth_image(tree_, &image, &camera, &options, &report_);
    }
    void record_state(Record &record) override { record_map(record, tree_); }
    void record_answer(Record &record) override {
        record_map(record, tree_);
        record.add("points_used", report_.points_used);
        record.add("pixels_no_return", report_.pixels_no_return);
        record.add("cells_hit", report_.cells_hit);
        record.add("cells_missed", report_.cells_missed);
    }

private:
    static constexpr size_t kDepthWidth = 16, kDepthHeight = 12;
    opx_octree *tree_;
    std::vector<uint16_t> depth_;
    opx_insert_report report_ = OPX_INSERT_REPORT_INIT;
};

// Clearing, decay and cropping: the blocks a clear takes (pruned leaves
// split along the box, free space made) and a crop's fresh slabs come
// first, so a failure leaves the map as it was.
enum class EditKind { kBoxToFree, kBoxToUnknown, kShapesToFree, kDecay, kCrop, kBoundedInsert };

class EditMap : public Attempt {
public:
    explicit EditMap(EditKind kind) : tree_(load_base_map()), kind_(kind), cloud_(room_cloud(kFramePoints, 3)) {}
    ~EditMap() override { opx_octree_destroy(tree_); }
    opx_status call() override {
        const double lo[3] = {-0.73, -0.41, 0.05}, hi[3] = {0.66, 0.92, 1.33};
        switch (kind_) {
        case EditKind::kBoxToFree: return opx_octree_clear_region(tree_, lo, hi, OPX_CELL_FREE);
        case EditKind::kBoxToUnknown: return opx_octree_clear_region(tree_, lo, hi, OPX_CELL_UNKNOWN);
        case EditKind::kShapesToFree: {
            opx_shape shapes[2] = {OPX_SHAPE_INIT, OPX_SHAPE_INIT};
            shapes[0].kind = OPX_SHAPE_SPHERE;
            shapes[0].radius = 0.45;
            shapes[1].kind = OPX_SHAPE_BOX;
            shapes[1].size[0] = shapes[1].size[1] = shapes[1].size[2] = 0.6;
            shapes[1].pose.position[2] = 0.7;
            opx_pose pose = OPX_POSE_IDENTITY;
            pose.position[0] = 0.3;
            return opx_octree_clear_shapes(tree_, shapes, 2, &pose, OPX_CELL_FREE);
        }
        case EditKind::kDecay: return opx_octree_decay(tree_, 0.5);
        case EditKind::kCrop: return opx_octree_crop(tree_, lo, hi);
        case EditKind::kBoundedInsert: {
            opx_insert_options options = sensor_insert_options(OPX_INSERT_RAYCAST);
            options.use_bounds = 1;
            for (int axis = 0; axis < 3; ++axis) options.bounds_min[axis] = lo[axis], options.bounds_max[axis] = hi[axis];
            return opx_octree_insert_points(tree_, cloud_.data(), kFramePoints, 0, OPX_SCALAR_FLOAT32, &options,
                                            nullptr);
        }
        }
        return OPX_ERROR_INTERNAL;
    }
    void record_state(Record &record) override { record_map(record, tree_); }
    void record_answer(Record &record) override { record_map(record, tree_); }

private:
    opx_octree *tree_;
    EditKind kind_;
    std::vector<float> cloud_;
};

class SaveImage : public Attempt {
public:
    explicit SaveImage(int32_t format) : tree_(load_base_map()), format_(format), buffer_(1 << 20) {}
    ~SaveImage() override { opx_octree_destroy(tree_); }
    opx_status call() override { return opx_octree_save_memory(tree_, format_, buffer_.data(), buffer_.size(), &size_); }
    void record_state(Record &record) override { record_map(record, tree_); }
    void record_answer(Record &record) override { record.add_bytes("image", buffer_.data(), size_); }

private:
    opx_octree *tree_;
    int32_t format_;
    std::vector<unsigned char> buffer_;
    size_t size_ = 0;
};

class LoadUrdf : public Attempt {
public:
    ~LoadUrdf() override { opx_linkset_destroy(links_); }
    opx_status call() override { return opx_linkset_load_urdf_string(kArmUrdf, nullptr, &links_); }
    void record_state(Record &record) override { record.add("out is NULL", static_cast<uint64_t>(links_ == nullptr)); }
    void record_answer(Record &record) override { record_linkset(record, links_); }
    bool makes_object() const override { return true; }

private:
    opx_linkset *links_ = nullptr;
};

// Adds the gripper's mesh again, to another link of a posed arm.
class AddMesh : public Attempt {
public:
    AddMesh() : arm_(arm_with_gripper()) {
        arm_pose(arm_, 3);
        require_ok(opx_linkset_get_shape(arm_, 6, 2, &mesh_), "opx_linkset_get_shape");
        vertices_.assign(mesh_.vertices, mesh_.vertices + 3 * mesh_.vertex_count);
        indices_.assign(mesh_.indices, mesh_.indices + 3 * mesh_.triangle_count);
        mesh_.vertices = vertices_.data();
        mesh_.indices = indices_.data();
    }
    ~AddMesh() override { opx_linkset_destroy(arm_); }
    opx_status call() override { return opx_linkset_add_shape(arm_, 2, &mesh_, nullptr); }
    void record_state(Record &record) override { record_linkset(record, arm_); }
    void record_answer(Record &record) override { record_linkset(record, arm_); }

private:
    opx_linkset *arm_;
    opx_shape mesh_ = OPX_SHAPE_INIT;
    std::vector<double> vertices_;
    std::vector<uint32_t> indices_;
};

class CloneArm : public Attempt {
public:
    CloneArm() : arm_(arm_with_gripper()) { arm_pose(arm_, 4); }
    ~CloneArm() override { opx_linkset_destroy(arm_), opx_linkset_destroy(clone_); }
    opx_status call() override { return opx_linkset_clone(arm_, &clone_); }
    void record_state(Record &record) override {
        record_linkset(record, arm_);
        record.add("out is NULL", static_cast<uint64_t>(clone_ == nullptr));
    }
    void record_answer(Record &record) override { record_linkset(record, clone_); }
    bool makes_object() const override { return true; }

private:
    opx_linkset *arm_;
    opx_linkset *clone_ = nullptr;
};

template <class T, class... Args>
SweepCase make_case(const char *name, std::vector<KnownFault> known, Args... args) {
    return SweepCase{name, [=] { return std::unique_ptr<Attempt>(new T(args...)); }, known};
}

// Faults the sweep finds in these calls (see KnownFault).
const KnownFault kUrdfdomNumbers{"status", "urdfdom", "urdfdom reads numbers through a stream that swallows "
                                                      "std::bad_alloc and then rejects the URDF"};
const KnownFault kTinyXmlLeak{"leak", "", "TinyXML 2.6 leaks the node it was parsing when an allocation throws"};

}  // namespace

std::vector<SweepCase> map_and_robot_cases() {
    return {
        make_case<LoadImage>("opx_octree_load_memory .bt", {}, OPX_FORMAT_BT),
        make_case<LoadImage>("opx_octree_load_memory .ot", {}, OPX_FORMAT_OT),
        make_case<LoadMessage>("opx_octree_load_message binary", {}, 1),
        make_case<LoadMessage>("opx_octree_load_message full", {}, 0),
        make_case<InsertFrame>("opx_octree_insert_points ray-cast", {},
                               OPX_INSERT_RAYCAST, kFramePoints),
        make_case<InsertFrame>("opx_octree_insert_points endpoints", {},
                               OPX_INSERT_ENDPOINTS, kFramePoints),
        make_case<InsertFrame>("opx_octree_insert_points ray-cast, large frame",
                               {}, OPX_INSERT_RAYCAST, kLargeFramePoints),
        make_case<InsertFrame>("opx_octree_insert_points endpoints, large frame",
                               {}, OPX_INSERT_ENDPOINTS, kLargeFramePoints),
        make_case<InsertDepthImage>("opx_octree_insert_depth_image", {}),
        make_case<InsertFiltered>("opx_octree_insert_points self-filtered", {}),
        make_case<EditMap>("opx_octree_clear_region to free", {}, EditKind::kBoxToFree),
        make_case<EditMap>("opx_octree_clear_region to unknown", {}, EditKind::kBoxToUnknown),
        make_case<EditMap>("opx_octree_clear_shapes to free", {}, EditKind::kShapesToFree),
        make_case<EditMap>("opx_octree_decay", {}, EditKind::kDecay),
        make_case<EditMap>("opx_octree_crop", {}, EditKind::kCrop),
        make_case<EditMap>("opx_octree_insert_points with bounds", {}, EditKind::kBoundedInsert),
        make_case<SaveImage>("opx_octree_save_memory .bt", {}, OPX_FORMAT_BT),
        make_case<SaveImage>("opx_octree_save_memory .ot", {}, OPX_FORMAT_OT),
        make_case<LoadUrdf>("opx_linkset_load_urdf_string", {kUrdfdomNumbers, kTinyXmlLeak}),
        make_case<AddMesh>("opx_linkset_add_shape mesh", {}),
        make_case<CloneArm>("opx_linkset_clone", {}),
    };
}

}  // namespace fault
