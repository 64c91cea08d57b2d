// Table I of the paper: the baseline pipeline with and without an
// amortized broad-phase build, collision queries of the 300 objects of
// scene F (variant a, primitives) against the 7,784-cell octree, then
// against random octrees of 25k, 100k and 300k cells in the same cube, and
// against the 2 cm octree of a Kinect-like frame (room_scene.hpp).
//   FCL default (level 0)       leaves -> fcl::Box (T_{1,1}) -> dynamic
//                               AABB tree, top-down build (T_{1,2})
//   FCL Morton (level 2)        the same, tree_init_level = 2
//   octoprox amortized          OPX_ENGINE_AMORTIZED, refine_steps = 0
//   octoprox amortized refined  refine_steps = 1
//   octoprox direct             no preprocessing
// OctoProx's amortized build happens inside the first query on a fresh
// context, which times its two steps itself (opx_query_get_stats):
// extracting the cells' boxes is T_{1,1}, building the tree T_{1,2}; the
// first query's T_q is its time without them.  One more line per map: the
// tree build in a context kept across frames, as a frame loop uses it.
#include <cmath>
#include <fstream>
#include <iostream>
#include <limits>
#include <stdexcept>

#include "room_scene.hpp"
#include "tables.hpp"
#include "timing.hpp"
#include "variant_setup.hpp"

namespace paper_tables {
namespace {

const char *const kNames[] = {"FCL default (level 0)", "FCL Morton (level 2)", "octoprox amortized",
                              "octoprox amortized refined", "octoprox direct"};
constexpr int kPipelines = 5;
constexpr int kFclDefault = 0, kUnrefined = 2, kRefined = 3;
constexpr uint32_t kFullRefineQueries = 100000;

// One build and one sequence of queries on it.
struct Run {
    double t11 = 0.0, t12 = 0.0;
    std::vector<double> query_ms;
    bool collided = false, consistent = true;
};

struct Row {
    std::string pipeline;
    std::string map;  // "scene F", "random", "room 2 cm"
    size_t cells = 0;
    double t11 = 0.0, t12 = 0.0, first = 0.0, q10 = 0.0, q100 = 0.0;
    double q1000 = std::numeric_limits<double>::quiet_NaN();
    bool collided = false, consistent = true;
    double t1() const { return t11 + t12; }
    double total(int n) const { return t1() + n * q100; }
};

std::unique_ptr<FclManager> manage_at_level(const std::vector<FclObjectPtr> &objects, int level) {
    std::vector<fcl::CollisionObjectd *> pointers;
    pointers.reserve(objects.size());
    for (const FclObjectPtr &object : objects) pointers.push_back(object.get());
    auto manager = std::make_unique<FclManager>();
    manager->tree_init_level = level;  // used by registerObjects on an empty manager
    manager->registerObjects(pointers);
    manager->setup();
    return manager;
}

double sah_ratio(opx_query *query) {
    opx_query_stats stats = OPX_QUERY_STATS_INIT;
    check_opx(opx_query_get_stats(query, &stats), "opx_query_get_stats");
    return stats.sah_ratio;
}

template <class Query>
void time_sequence(Run &run, int queries, Query &&query, const std::function<void(int)> &after = nullptr) {
    for (int i = 0; i < queries; ++i) {
        bool collided = false;
        run.query_ms.push_back(time_once_ms([&] { collided = query(); }));
        if (i == 0) run.collided = collided;
        if (collided != run.collided) run.consistent = false;
        if (after) after(i + 1);
    }
}

double mean_of_first(const std::vector<double> &values, size_t begin, size_t count) {
    double sum = 0.0;
    size_t n = 0;
    for (size_t i = begin; i < values.size() && i < begin + count; ++i, ++n) sum += values[i];
    return n > 0 ? sum / n : 0.0;
}

// The scene's map and robot, shared by the pipelines of one table.
struct Bench {
    const opx_octree *tree;
    const octomap::OcTree *octomap;
    const FclObjectSet *robot;
    const opx_linkset *links;
    int queries;
};

Run run_fcl(const Bench &bench, int level) {
    Run run;
    std::vector<FclObjectPtr> boxes;
    run.t11 = time_once_ms([&] { boxes = boxes_from_octomap(*bench.octomap, Variant::kPrimitives); });
    std::unique_ptr<FclManager> manager;
    run.t12 = time_once_ms([&] { manager = manage_at_level(boxes, level); });
    time_sequence(run, bench.queries, [&] { return fcl_managers_collide(*bench.robot->manager, *manager); });
    return run;
}

// sah: the refined context's SAH ratio after 1, 10, 100, 1000 queries.
Run run_opx(const Bench &bench, int32_t engine, uint32_t refine_steps, std::vector<double> *sah) {
    Run run;
    OpxQueryPtr query = make_query(engine, refine_steps);
    time_sequence(run, bench.queries, [&] { return opx_collides(query.get(), bench.tree, bench.links); },
                  [&](int done) {
                      if (sah != nullptr && (done == 1 || done == 10 || done == 100 || done == 1000))
                          sah->push_back(sah_ratio(query.get()));
                  });
    if (engine == OPX_ENGINE_AMORTIZED && !run.query_ms.empty()) {
        opx_query_stats stats = OPX_QUERY_STATS_INIT;
        if (opx_query_get_stats(query.get(), &stats) == OPX_OK) {
            run.t11 = stats.extract_ms;
            run.t12 = stats.build_ms;
            run.query_ms[0] = std::max(0.0, run.query_ms[0] - run.t11 - run.t12);
        }
    }
    return run;
}

Row summarize(const char *name, size_t cells, const std::vector<Run> &runs) {
    Row row;
    row.pipeline = name;
    row.cells = cells;
    std::vector<double> t11, t12, first, q10, q100, q1000;
    for (const Run &run : runs) {
        t11.push_back(run.t11);
        t12.push_back(run.t12);
        first.push_back(run.query_ms.front());
        q10.push_back(mean_of_first(run.query_ms, 0, 10));
        q100.push_back(mean_of_first(run.query_ms, 0, 100));
        q1000.push_back(mean_of_first(run.query_ms, 0, 1000));
        row.consistent = row.consistent && run.consistent && run.collided == runs.front().collided;
    }
    row.collided = runs.front().collided;
    row.t11 = median(t11), row.t12 = median(t12), row.first = median(first);
    row.q10 = median(q10), row.q100 = median(q100);
    if (runs.front().query_ms.size() >= 1000) row.q1000 = median(q1000);
    return row;
}

std::string cell(double value) { return std::isnan(value) ? "-" : three_significant(value); }

void print_rows(const std::vector<Row> &rows, const std::string &title) {
    std::cout << "\n" << title << "\n";
    std::printf("%-28s %9s %9s %9s %9s %9s %9s %11s %12s  %s\n", "", "T_{1,1}", "T_{1,2}", "T_q 1st",
                "T_q 10", "T_q 100", "T_q 1000", "T_1+10T_q", "T_1+100T_q", "collided");
    for (const Row &r : rows)
        std::printf("%-28s %9s %9s %9s %9s %9s %9s %11s %12s  %s\n", r.pipeline.c_str(), cell(r.t11).c_str(),
                    cell(r.t12).c_str(), cell(r.first).c_str(), cell(r.q10).c_str(), cell(r.q100).c_str(),
                    cell(r.q1000).c_str(), cell(r.total(10)).c_str(), cell(r.total(100)).c_str(),
                    r.consistent ? (r.collided ? "yes" : "no") : "VARIED");
    std::fflush(stdout);
}

// Equation (3): the amortized build wins while N <= (T_{1,2} - T~_{1,2}) / (T~_q - T_q).
void print_break_even(const Row &fcl, const Row &amortized) {
    const double fcl_q = std::isnan(fcl.q1000) ? fcl.q100 : fcl.q1000;
    const double opx_q = std::isnan(amortized.q1000) ? amortized.q100 : amortized.q1000;
    const double denominator = opx_q - fcl_q;
    std::cout << "break-even N (eq. 3, " << fcl.pipeline << " vs " << amortized.pipeline << ", T_q over "
              << (std::isnan(fcl.q1000) ? "100" : "1000") << "): ";
    if (denominator <= 0.0) std::cout << "always";
    else std::cout << three_significant((fcl.t12 - amortized.t12) / denominator)
                   << " (with T_1 instead of T_{1,2}: " << three_significant((fcl.t1() - amortized.t1()) / denominator)
                   << ")";
    std::cout << "\n";
}

// Every contact (max_contacts unlimited): the query visits every colliding
// pair, so its time reflects the tree's quality and not how soon its order
// happens upon a first contact.
bool opx_collides_everywhere(opx_query *query, const opx_octree *tree, const opx_linkset *links) {
    opx_collision_request request = OPX_COLLISION_REQUEST_INIT;
    request.max_contacts = UINT32_MAX;
    opx_collision_result result = OPX_COLLISION_RESULT_INIT;
    check_opx(opx_query_collide(query, tree, links, &request, &result), "opx_query_collide");
    return result.collided != 0;
}

// Refined after 100 queries vs a context refined by 100,000 cheap queries
// first (a far-away tiny sphere: the refinement does not depend on the
// links), interleaved so that load changes hit both alike.  Where the
// objects collide (25k cells and more) a first-contact query takes a few
// microseconds and mostly measures where the traversal happens to meet a
// contact; the ratio that judges the tree is then that of every-contact
// queries, printed beside it.
void refined_vs_full(const Bench &bench, bool objects_collide) {
    OpxQueryPtr after100 = make_query(OPX_ENGINE_AMORTIZED, 1);
    OpxQueryPtr full = make_query(OPX_ENGINE_AMORTIZED, 1);
    for (int i = 0; i < 100; ++i) opx_collides(after100.get(), bench.tree, bench.links);
    SceneObject speck;  // a sphere far from every cell
    speck.radius = 0.01;
    speck.pose.position[0] = speck.pose.position[1] = speck.pose.position[2] = 1000.0;
    OpxLinksetPtr tiny = make_object_linkset({speck}, Variant::kPrimitives);
    const double warmup_ms = time_once_ms([&] {
        for (uint32_t i = 0; i < kFullRefineQueries; ++i) opx_collides(full.get(), bench.tree, tiny.get());
    });
    const std::vector<QueryTiming> t = time_queries_interleaved(
        200, {[&] { return opx_collides(after100.get(), bench.tree, bench.links); },
              [&] { return opx_collides(full.get(), bench.tree, bench.links); }});
    double ratio = t[0].mean_ms / t[1].mean_ms;
    std::cout << "T_q refined after 100 queries: " << three_significant(t[0].mean_ms) << " ms; fully refined ("
              << kFullRefineQueries << " steps first, " << three_significant(warmup_ms)
              << " ms): " << three_significant(t[1].mean_ms) << " ms; SAH " << three_significant(sah_ratio(full.get()))
              << "; ratio " << three_significant(ratio);
    if (objects_collide) {
        const std::vector<QueryTiming> every = time_queries_interleaved(
            100, {[&] { return opx_collides_everywhere(after100.get(), bench.tree, bench.links); },
                  [&] { return opx_collides_everywhere(full.get(), bench.tree, bench.links); }});
        ratio = every[0].mean_ms / every[1].mean_ms;
        std::cout << " (first contact); every contact: " << three_significant(every[0].mean_ms) << " vs "
                  << three_significant(every[1].mean_ms) << " ms, ratio " << three_significant(ratio);
    }
    std::cout << "\n";
}

// T~_{1,2} as a frame loop pays it: one amortized context kept across
// frames, bound in turn to the map and to an identical copy (a new frame to
// the context), so after the first frame its buffers are reused.  The
// table's fresh contexts also pay the page faults of new buffers.
double reused_context_build_ms(const Bench &bench, int rebuilds) {
    const OpxOctreePtr copy = copy_octree(bench.tree);
    const OpxQueryPtr query = make_query(OPX_ENGINE_AMORTIZED, 1);
    std::vector<double> builds;
    uint64_t boxes = 0;
    for (int frame = 0; frame <= rebuilds; ++frame) {
        opx_collides(query.get(), frame % 2 ? copy.get() : bench.tree, bench.links);
        opx_query_stats stats = OPX_QUERY_STATS_INIT;
        check_opx(opx_query_get_stats(query.get(), &stats), "opx_query_get_stats");
        if (frame > 0 && stats.boxes != boxes) throw std::runtime_error("the map's copy has other obstacle cells");
        boxes = stats.boxes;
        if (frame > 0) builds.push_back(stats.build_ms);  // frame 0 allocated the buffers
    }
    return median(builds);
}

// T_1 + 100 T_q of one pipeline over that of the faster FCL pipeline.
void print_total_ratios(const std::vector<Row> &rows) {
    const double fcl_best = std::min(rows[0].total(100), rows[1].total(100));
    for (int p : {kUnrefined, kRefined, 4})
        std::cout << rows[p].pipeline << " T_1+100T_q / faster FCL pipeline's: "
                  << three_significant(rows[p].total(100) / std::max(fcl_best, 1e-9)) << "\n";
}

std::vector<Row> run_size(const Bench &bench, size_t cells, const BenchOptions &options) {
    std::vector<std::vector<Run>> runs(kPipelines);
    std::vector<double> sah_refined, sah_unrefined;
    for (int rep = 0; rep < options.repetitions; ++rep) {
        const bool last = rep + 1 == options.repetitions;
        runs[0].push_back(run_fcl(bench, 0));
        runs[1].push_back(run_fcl(bench, 2));
        runs[2].push_back(run_opx(bench, OPX_ENGINE_AMORTIZED, 0, last ? &sah_unrefined : nullptr));
        runs[3].push_back(run_opx(bench, OPX_ENGINE_AMORTIZED, 1, last ? &sah_refined : nullptr));
        runs[4].push_back(run_opx(bench, OPX_ENGINE_DIRECT, 1, nullptr));
    }
    std::vector<Row> rows;
    for (int p = 0; p < kPipelines; ++p) rows.push_back(summarize(kNames[p], cells, runs[p]));
    print_rows(rows, "Table I, " + std::to_string(cells) + " cells, scene F objects (variant a); ms; T_q means of the first 1/10/100/1000 of " +
                         std::to_string(bench.queries) + " queries, medians of " + std::to_string(options.repetitions) +
                         " fresh builds; octoprox amortized: T_{1,1}, T_{1,2} timed by the context (opx_query_get_stats); T_1+nT_q use T_q 100");
    std::cout << "SAH ratio (vs top-down median split): unrefined " << cell(sah_unrefined.empty() ? NAN : sah_unrefined[0])
              << "; refined after queries";
    const int marks[] = {1, 10, 100, 1000};
    for (size_t i = 0; i < sah_refined.size(); ++i) std::cout << " " << marks[i] << ": " << cell(sah_refined[i]);
    std::cout << "\n";
    print_break_even(rows[kFclDefault], rows[kRefined]);
    const double fcl_t12 = rows[kFclDefault].t12;
    std::cout << "FCL default T_{1,2} / T~_{1,2}: x"
              << three_significant(fcl_t12 / std::max(rows[kRefined].t12, 1e-9)) << " refined, x"
              << three_significant(fcl_t12 / std::max(rows[kUnrefined].t12, 1e-9)) << " unrefined\n";
    const double reused = reused_context_build_ms(bench, options.repetitions);
    std::cout << "T~_{1,2} in one context kept across frames (bound to the map and an identical copy in turn, "
              << "median of " << options.repetitions << " rebuilds): " << cell(reused) << " ms, x"
              << three_significant(fcl_t12 / std::max(reused, 1e-9)) << " faster than FCL default\n";
    refined_vs_full(bench, rows[kRefined].collided);
    print_total_ratios(rows);
    return rows;
}

bool rows_agree(const std::vector<Row> &rows, bool expect_free) {
    bool agree = true;
    for (const Row &r : rows)
        if (!r.consistent || r.collided != rows.front().collided || (expect_free && r.collided)) agree = false;
    std::cout << (agree ? "answers agree" : "MISMATCH: pipelines disagree")
              << (expect_free ? " (scene F: expected no collision)" : "") << "\n";
    return agree;
}

std::string json_number(double value) {
    if (std::isnan(value)) return "null";
    char buffer[48];
    std::snprintf(buffer, sizeof buffer, "%.6g", value);
    return buffer;
}

bool write_rows(const std::string &path, const std::vector<Row> &rows, const std::string &cpu) {
    std::ofstream out(path);
    out << "[\n";
    for (size_t i = 0; i < rows.size(); ++i) {
        const Row &r = rows[i];
        out << "  {\"table\": \"I\", \"pipeline\": \"" << r.pipeline << "\", \"map\": \"" << r.map << "\", \"cells\": " << r.cells
            << ", \"T11_ms\": " << json_number(r.t11) << ", \"T12_ms\": " << json_number(r.t12)
            << ", \"Tq_first_ms\": " << json_number(r.first) << ", \"Tq_10_ms\": " << json_number(r.q10)
            << ", \"Tq_100_ms\": " << json_number(r.q100) << ", \"Tq_1000_ms\": " << json_number(r.q1000)
            << ", \"T1_plus_10Tq_ms\": " << json_number(r.total(10))
            << ", \"T1_plus_100Tq_ms\": " << json_number(r.total(100)) << ", \"collided\": "
            << (r.collided ? "true" : "false") << ", \"cpu\": \"" << cpu << "\"}" << (i + 1 < rows.size() ? "," : "")
            << "\n";
    }
    out << "]\n";
    return static_cast<bool>(out);
}

}  // namespace

int run_table1(const BenchOptions &options, const std::string &cpu) {
    const Scenes scenes = make_scenes();
    const FclObjectSet robot = make_fcl_object_set(scenes.free, Variant::kPrimitives);
    const OpxLinksetPtr links = make_object_linkset(scenes.free, Variant::kPrimitives);
    std::vector<Row> all;
    Bench bench{scenes.maps.opx.get(), scenes.maps.octomap.get(), &robot, links.get(), options.queries};
    std::vector<Row> rows = run_size(bench, scenes.parameters.occupied_cells, options);
    for (Row &row : rows) row.map = "scene F";
    int status = rows_agree(rows, true) ? 0 : 1;
    all.insert(all.end(), rows.begin(), rows.end());
    std::vector<size_t> sizes{25000, 100000};
    if (!options.quick) sizes.push_back(300000);
    for (size_t cells : sizes) {
        SceneParameters parameters;
        parameters.occupied_cells = cells;
        const OccupancyMaps maps = build_occupancy_maps(parameters);
        Bench large{maps.opx.get(), maps.octomap.get(), &robot, links.get(), std::min(options.queries, 100)};
        std::cout << "\n" << cells << " random occupied cells (scene F's objects now may collide: queries stop at the first contact)";
        rows = run_size(large, cells, options);
        for (Row &row : rows) row.map = "random";
        if (!rows_agree(rows, false)) status = 1;
        all.insert(all.end(), rows.begin(), rows.end());
    }
    if (!options.quick) {
        const RoomScene room = make_room_scene(0.02);
        const FclObjectSet room_robot = make_fcl_object_set(room.objects, Variant::kPrimitives);
        const OpxLinksetPtr room_links = make_object_linkset(room.objects, Variant::kPrimitives);
        Bench framed{room.maps.opx.get(), room.maps.octomap.get(), &room_robot, room_links.get(),
                     std::min(options.queries, 100)};
        std::cout << "\nThe 2 cm Kinect-like frame: the generated room (" << room.frame_points
                  << " points, ray-cast) has " << room.maps.occupied
                  << " occupied cells; scene F's 300 objects at a tenth of their size, drawn in the room";
        rows = run_size(framed, room.maps.occupied, options);
        for (Row &row : rows) row.map = "room 2 cm";
        if (!rows_agree(rows, false)) status = 1;
        all.insert(all.end(), rows.begin(), rows.end());
    }
    if (!options.json_path.empty() && !write_rows(options.json_path, all, cpu)) {
        std::cerr << "opx-paper-tables: cannot write " << options.json_path << "\n";
        status = status != 0 ? status : 1;
    }
    return status;
}

}  // namespace paper_tables
