#include "certified_rows.hpp"

#include "timing.hpp"

namespace batch_bench {
namespace {

using paper_tables::check_opx;

constexpr double kVampResolution = 1.0 / 32.0, kPrrtcResolution = 1.0 / 16.0;  // rad

opx_motion_request motion_request(const Workload &work, uint32_t threads, bool certified, double resolution) {
    opx_motion_request request = OPX_MOTION_REQUEST_INIT;
    request.check = certified ? OPX_MOTION_CERTIFIED : OPX_MOTION_SAMPLED;
    request.resolution = resolution;
    request.self_collision = work.self_collision ? 1 : 0;
    request.max_threads = threads;
    return request;
}

void check_all(opx_query *query, const Workload &work, const std::vector<double> &goals, size_t count,
               const opx_motion_request &request, std::vector<uint8_t> &collided) {
    collided.resize(count);
    check_opx(opx_query_check_motions(query, work.scene.tree.get(), work.robot.links.get(), work.set.rows.data(),
                                      goals.data(), count, work.set.joints, 0, &work.set.base, 1, 0, &request,
                                      collided.data(), nullptr, count),
              "opx_query_check_motions");
}

// Configurations a check measures per motion, by single calls (untimed).
double configurations_per_motion(const Workload &work, const std::vector<double> &goals, size_t count,
                                 const opx_motion_request &request) {
    const paper_tables::OpxQueryPtr query = paper_tables::make_direct_query();
    uint64_t checked = 0;
    for (size_t m = 0; m < count; ++m) {
        opx_motion_result result = OPX_MOTION_RESULT_INIT;
        check_opx(opx_query_check_motion(query.get(), work.scene.tree.get(), work.robot.links.get(), work.set.row(m),
                                         goals.data() + m * work.set.joints, work.set.joints, &work.set.base,
                                         &request, &result),
                  "opx_query_check_motion");
        checked += result.configurations_checked;
    }
    return double(checked) / double(count);
}

size_t missed(const std::vector<uint8_t> &sampled, const std::vector<uint8_t> &certified) {
    size_t n = 0;
    for (size_t m = 0; m < sampled.size(); ++m) n += !sampled[m] && certified[m];
    return n;
}

}  // namespace

CertifiedTiming time_certified_motions(const Workload &work, const std::vector<double> &goals, size_t count,
                                       uint32_t threads) {
    const paper_tables::OpxQueryPtr certified_query = paper_tables::make_direct_query(),
                                    sampled_query = paper_tables::make_direct_query();
    const opx_motion_request certified = motion_request(work, threads, true, kVampResolution),
                             sampled = motion_request(work, threads, false, kVampResolution),
                             coarse = motion_request(work, threads, false, kPrrtcResolution);
    std::vector<uint8_t> by_certified, by_sampled, by_coarse;
    check_all(certified_query.get(), work, goals, count, certified, by_certified);
    check_all(sampled_query.get(), work, goals, count, sampled, by_sampled);
    check_all(sampled_query.get(), work, goals, count, coarse, by_coarse);
    std::vector<double> certified_ms, sampled_ms;
    std::vector<uint8_t> scratch;
    for (int r = 0; r < work.rounds; ++r) {  // interleaved, the order alternating
        auto run_certified = [&] { check_all(certified_query.get(), work, goals, count, certified, scratch); };
        auto run_sampled = [&] { check_all(sampled_query.get(), work, goals, count, sampled, scratch); };
        if (r % 2 == 0) certified_ms.push_back(paper_tables::time_once_ms(run_certified));
        sampled_ms.push_back(paper_tables::time_once_ms(run_sampled));
        if (r % 2 == 1) certified_ms.push_back(paper_tables::time_once_ms(run_certified));
    }
    CertifiedTiming t;
    t.motions = count;
    t.certified_us = 1000.0 * paper_tables::median(certified_ms) / double(count);
    t.sampled_us = 1000.0 * paper_tables::median(sampled_ms) / double(count);
    t.certified_measured = configurations_per_motion(work, goals, count, certified);
    t.sampled_checked = configurations_per_motion(work, goals, count, sampled);
    for (size_t m = 0; m < count; ++m) {
        t.certified_collided += by_certified[m], t.sampled_collided += by_sampled[m];
        t.unsound += (by_sampled[m] || by_coarse[m]) && !by_certified[m];
    }
    t.missed_32 = missed(by_sampled, by_certified), t.missed_16 = missed(by_coarse, by_certified);
    return t;
}

}  // namespace batch_bench
