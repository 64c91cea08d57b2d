// Sweep cases of the queries: each kind, on both engines, as the first
// query of a fresh context and as a later one.  Every attempt has its own
// arm, so a query also meets the link set's lazy work (its tree after
// shapes were added, the mesh placed when first reached).
#include "fault_answers.hpp"
#include "fault_scene.hpp"
#include "sweep_cases.hpp"

#include <string>

namespace fault {
namespace {

constexpr size_t kWaypoints = 6;
constexpr size_t kFirstConfiguration = 2;   // of a used context's earlier query
constexpr size_t kTestedConfiguration = 5;  // of the query under test

// When the query under test runs.
enum class Stage {
    kFresh,    // the first query of a new context
    kUsed,     // after a query of the same kind at another configuration
    kRebound,  // after a query on another map: the amortized engine rebinds
};

const char *stage_name(Stage stage) {
    switch (stage) {
    case Stage::kFresh: return "fresh";
    case Stage::kUsed: return "used";
    case Stage::kRebound: return "after another map";
    }
    return "?";
}

const opx_octree *other_map() {
    static const opx_octree *tree = room_map(0.1, 400, 7);
    return tree;
}

const opx_octree *shared_map() {
    static const opx_octree *tree = room_map(0.1, 600, 3);
    return tree;
}

const std::vector<double> &shared_boxes() {
    static const std::vector<double> boxes = room_boxes(40, 4);
    return boxes;
}

void bind_shared_boxes(opx_query *query) {
    const std::vector<double> &boxes = shared_boxes();
    require_ok(opx_query_bind_boxes(query, boxes.data(), boxes.size() / 6, 0), "opx_query_bind_boxes");
}

// What a failed query must leave alone: the map and the link set.
class QueryAttemptBase : public Attempt {
public:
    explicit QueryAttemptBase(int32_t engine)
        : arm_(arm_with_gripper()), query_(new_query(engine)) {}
    ~QueryAttemptBase() override {
        opx_query_destroy(query_);
        opx_linkset_destroy(arm_);
    }
    void record_state(Record &record) override {
        record_map(record, shared_map());
        record_linkset(record, arm_);
    }
    // The context's accessors after a failed call: any status, no crash.
    void use_after_failure() override {
        opx_query_stats stats = OPX_QUERY_STATS_INIT;
        opx_query_get_stats(query_, &stats);
        opx_contact contact = OPX_CONTACT_INIT;
        opx_query_get_contact(query_, 0, &contact);
        opx_cost_box box = OPX_COST_BOX_INIT;
        opx_query_get_cost_box(query_, 0, &box);
        size_t count = 0;
        opx_query_get_link_distances(query_, nullptr, 0, &count);
    }

protected:
    opx_linkset *arm_;
    opx_query *query_;
};

class QueryAttempt : public QueryAttemptBase {
public:
    QueryAttempt(QueryKind kind, int32_t engine, Stage stage) : QueryAttemptBase(engine), kind_(kind) {
        in_.links = arm_;
        in_.waypoints = kWaypoints;
        if (kind == QueryKind::kCollideBoxes || kind == QueryKind::kDistanceBoxes) bind_shared_boxes(query_);
        if (stage != Stage::kFresh) {
            in_.tree = stage == Stage::kRebound ? other_map() : shared_map();
            arm_pose(arm_, kFirstConfiguration);
            path_ = arm_path(arm_, kFirstConfiguration, kWaypoints);
            in_.path = path_.data();
            require_ok(call_query(kind, query_, in_, out_), "an earlier query");
        }
        in_.tree = shared_map();
        arm_pose(arm_, kTestedConfiguration);
        path_ = arm_path(arm_, kTestedConfiguration, kWaypoints);
        in_.path = path_.data();
    }
    opx_status call() override { return call_query(kind_, query_, in_, out_); }
    void record_answer(Record &record) override { record_query(kind_, record, query_, out_); }

private:
    QueryKind kind_;
    QueryInputs in_;
    QueryOutputs out_;
    std::vector<opx_pose> path_;
};

// Binding the caller's boxes; a used context had other boxes bound and
// queried.  Failed, the context keeps what it had bound.
class BindAttempt : public QueryAttemptBase {
public:
    explicit BindAttempt(bool used) : QueryAttemptBase(OPX_ENGINE_AMORTIZED), boxes_(room_boxes(30, 5)) {
        arm_pose(arm_, kTestedConfiguration);
        if (!used) return;
        bind_shared_boxes(query_);
        QueryInputs in;
        in.links = arm_;
        QueryOutputs out;
        require_ok(call_query(QueryKind::kDistanceBoxes, query_, in, out), "an earlier query");
    }
    opx_status call() override { return opx_query_bind_boxes(query_, boxes_.data(), boxes_.size() / 6, 0); }
    void record_state(Record &record) override {
        QueryAttemptBase::record_state(record);
        record_query_stats(record, query_);
    }
    void record_answer(Record &record) override {
        record_query_stats(record, query_);
        QueryInputs in;
        in.links = arm_;
        QueryOutputs out;
        record.add("distance_boxes status", call_query(QueryKind::kDistanceBoxes, query_, in, out));
        record_query(QueryKind::kDistanceBoxes, record, query_, out);
    }

private:
    std::vector<double> boxes_;
};

// An attempt on a map of its own, read from the shared map's image, so
// that every attempt's call builds the map's obstacle grid.  Failed, the
// call leaves the map as it was; the retry builds the grid.
class OwnMapAttempt : public Attempt {
public:
    OwnMapAttempt() : query_(new_query(OPX_ENGINE_DIRECT)) {
        static const std::vector<unsigned char> image = map_image(shared_map(), OPX_FORMAT_OT);
        require_ok(opx_octree_load_memory(image.data(), image.size(), nullptr, &tree_), "opx_octree_load_memory");
    }
    ~OwnMapAttempt() override {
        opx_query_destroy(query_);
        opx_octree_destroy(tree_);
    }
    void record_state(Record &record) override { record_map(record, tree_); }

protected:
    opx_query *query_;
    opx_octree *tree_ = nullptr;
};

// Signed sphere distances on the attempt's own map, on two threads.
class SphereDistanceAttempt : public OwnMapAttempt {
public:
    SphereDistanceAttempt() {
        Lcg rng(13);
        for (size_t i = 0; i < kSpheres; ++i)
            for (double value : {rng.uniform(-2.0, 2.0), rng.uniform(-2.0, 2.0), rng.uniform(0.0, 2.5),
                                 rng.uniform(0.0, 0.3)})
                rows_.push_back(value);
    }
    opx_status call() override {
        opx_sphere_distance_request request = OPX_SPHERE_DISTANCE_REQUEST_INIT;
        request.max_threads = 2;
        request.max_distance = 0.5;
        return opx_query_distance_spheres(query_, tree_, rows_.data(), kSpheres, 0, &request, distance_, gradient_,
                                          nullptr, kSpheres);
    }
    void record_answer(Record &record) override {
        record.add_bytes("sphere distances", distance_, sizeof distance_);
        record.add_bytes("sphere gradients", gradient_, sizeof gradient_);
    }

private:
    static constexpr size_t kSpheres = 40;
    std::vector<double> rows_;
    double distance_[kSpheres] = {};
    double gradient_[3 * kSpheres] = {};
};

// Spheres against the attempt's own map.
class SpheresAttempt : public OwnMapAttempt {
public:
    SpheresAttempt() {
        Lcg rng(11);
        for (size_t i = 0; i < kSpheres; ++i)
            for (double value : {rng.uniform(-2.0, 2.0), rng.uniform(-2.0, 2.0), rng.uniform(0.0, 2.5),
                                 rng.uniform(0.0, 0.3)})
                rows_.push_back(value);
    }
    opx_status call() override {
        return opx_query_collide_spheres(query_, tree_, rows_.data(), kSpheres, 0, nullptr, collided_, kSpheres);
    }
    void record_answer(Record &record) override {
        for (size_t i = 0; i < kSpheres; ++i) record.add("sphere collided", uint32_t(collided_[i]));
    }

private:
    static constexpr size_t kSpheres = 40;
    std::vector<double> rows_;
    uint8_t collided_[kSpheres] = {};
};

// A batch of the sphere arm on 2 threads against the attempt's own map:
// the first configuration of each worker asks for the obstacle grid,
// which one of them builds.
class SphereBatchAttempt : public OwnMapAttempt {
public:
    SphereBatchAttempt() {
        arm_ = sphere_arm();
        rows_ = sphere_arm_rows(kRows, 13);
    }
    ~SphereBatchAttempt() override { opx_linkset_destroy(arm_); }
    opx_status call() override {
        opx_batch_request request = OPX_BATCH_REQUEST_INIT;
        request.max_threads = 2;
        return opx_query_check_configurations(query_, tree_, arm_, rows_.data(), kRows, kSphereArmJoints, 0,
                                              &kSphereArmBase, 1, 0, &request, collided_, nullptr, kRows);
    }
    void record_answer(Record &record) override {
        for (size_t i = 0; i < kRows; ++i) record.add("configuration collided", uint32_t(collided_[i]));
    }

private:
    static constexpr size_t kRows = 48;
    opx_linkset *arm_ = nullptr;
    std::vector<double> rows_;
    uint8_t collided_[kRows] = {};
};

// A trajectory of the sphere arm on the attempt's own map: its cost and gradient.
class TrajectoryCostAttempt : public OwnMapAttempt {
public:
    TrajectoryCostAttempt() {
        arm_ = sphere_arm();
        rows_ = sphere_arm_rows(kRows, 17);
    }
    ~TrajectoryCostAttempt() override { opx_linkset_destroy(arm_); }
    opx_status call() override {
        opx_trajectory_cost_request request = OPX_TRAJECTORY_COST_REQUEST_INIT;
        request.activation = 0.1;
        return opx_query_trajectory_cost(query_, tree_, arm_, rows_.data(), kRows, kSphereArmJoints, 0,
                                         &kSphereArmBase, &request, &cost_, gradient_, kRows);
    }
    void record_answer(Record &record) override {
        record.add_bytes("trajectory cost", &cost_, sizeof cost_);
        record.add_bytes("trajectory gradient", gradient_, sizeof gradient_);
    }

private:
    static constexpr size_t kRows = 8;
    opx_linkset *arm_ = nullptr;
    std::vector<double> rows_;
    double cost_ = 0.0;
    double gradient_[kRows * kSphereArmJoints] = {};
};

// Certified motions of the sphere arm on 2 threads against the
// attempt's own map: distances per link, advancement, the bracket.
class CertifiedMotionAttempt : public OwnMapAttempt {
public:
    CertifiedMotionAttempt() {
        arm_ = sphere_arm();
        rows_ = sphere_arm_rows(2 * kMotions, 17);
    }
    ~CertifiedMotionAttempt() override { opx_linkset_destroy(arm_); }
    opx_status call() override {
        opx_motion_request request = OPX_MOTION_REQUEST_INIT;
        request.check = OPX_MOTION_CERTIFIED;
        request.max_threads = 2;
        const size_t stride = 2 * kSphereArmJoints * sizeof(double);
        return opx_query_check_motions(query_, tree_, arm_, rows_.data(), rows_.data() + kSphereArmJoints, kMotions,
                                       kSphereArmJoints, stride, &kSphereArmBase, 1, 0, &request, collided_,
                                       fractions_, kMotions);
    }
    void record_answer(Record &record) override {
        for (size_t i = 0; i < kMotions; ++i) {
            record.add("motion collided", uint32_t(collided_[i]));
            record.add("first collision fraction", fractions_[i]);
        }
    }

private:
    static constexpr size_t kMotions = 3;
    opx_linkset *arm_ = nullptr;
    std::vector<double> rows_;
    uint8_t collided_[kMotions] = {};
    double fractions_[kMotions] = {};
};

std::string case_name(const std::string &what, int32_t engine, Stage stage) {
    return what + (engine == OPX_ENGINE_DIRECT ? " direct " : " amortized ") + stage_name(stage);
}

SweepCase query_case(QueryKind kind, int32_t engine, Stage stage) {
    return {case_name(std::string("opx_query_") + query_kind_name(kind), engine, stage),
            [=] { return std::unique_ptr<Attempt>(new QueryAttempt(kind, engine, stage)); }, {}};
}

}  // namespace

std::vector<SweepCase> query_cases() {
    std::vector<SweepCase> cases;
    for (int32_t engine : {OPX_ENGINE_DIRECT, OPX_ENGINE_AMORTIZED})
        for (Stage stage : {Stage::kFresh, Stage::kUsed, Stage::kRebound})
            for (QueryKind kind : {QueryKind::kCollide, QueryKind::kDistance, QueryKind::kPath})
                cases.push_back(query_case(kind, engine, stage));
    for (Stage stage : {Stage::kFresh, Stage::kUsed}) {
        const bool used = stage == Stage::kUsed;
        cases.push_back({case_name("opx_query_bind_boxes", OPX_ENGINE_AMORTIZED, stage),
                         [=] { return std::unique_ptr<Attempt>(new BindAttempt(used)); }, {}});
        for (QueryKind kind : {QueryKind::kCollideBoxes, QueryKind::kDistanceBoxes})
            cases.push_back(query_case(kind, OPX_ENGINE_AMORTIZED, stage));
    }
    cases.push_back({"opx_query_collide_spheres on a new map",
                     [] { return std::unique_ptr<Attempt>(new SpheresAttempt()); }, {}});
    cases.push_back({"opx_query_distance_spheres on a new map",
                     [] { return std::unique_ptr<Attempt>(new SphereDistanceAttempt()); }, {}});
    cases.push_back({"opx_query_trajectory_cost of a sphere arm on a new map",
                     [] { return std::unique_ptr<Attempt>(new TrajectoryCostAttempt()); }, {}});
    cases.push_back({"opx_query_check_configurations of a sphere arm on a new map",
                     [] { return std::unique_ptr<Attempt>(new SphereBatchAttempt()); }, {}});
    cases.push_back({"opx_query_check_motions certified, a sphere arm on a new map",
                     [] { return std::unique_ptr<Attempt>(new CertifiedMotionAttempt()); }, {}});
    return cases;
}

}  // namespace fault
