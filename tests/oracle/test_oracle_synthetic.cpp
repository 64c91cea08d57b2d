// The paper's synthetic scene (the cube [-20, 20]^3 at 0.2 m with 7,784
// occupied leaves from random single hits) against random robots of all six
// shape kinds placed anywhere in the cube: yes/no answers and contact sets
// against the brute-force oracle.
#include "oracle_engine.hpp"
#include "oracle_scenes.hpp"

#include <cstdio>

using namespace oracle;

int main() {
    elapsed_seconds();
    const uint64_t seed = env_number("OPX_ORACLE_SEED", 7784);
    const int robots = int(env_number("OPX_ORACLE_ROBOTS", 50));
    std::printf("oracle_synthetic: seed %llu, %d robots x 1000 states\n", (unsigned long long)seed, robots);
    Rng rng(seed);
    std::unique_ptr<Scene> scene = synthetic_scene(rng);
    scene->label += " (seed " + std::to_string(seed) + ")";
    std::printf("synthetic scene: %zu leaves, built in %.1f s\n", scene->leaves.size(), elapsed_seconds());
    Checker checker("oracle_synthetic");
    opx_query *query = nullptr;
    if (oracle_create_query(&query) != OPX_OK) return 1;
    Campaign campaign;
    campaign.robot.min_links = 2, campaign.robot.max_links = 8;
    campaign.robot.min_scale = 0.3, campaign.robot.max_scale = 3.0;
    campaign.robots = robots, campaign.states = 1000;
    campaign.low = scene->low, campaign.high = scene->high;
    run_campaign(rng, *scene, campaign, query, checker);
    opx_query_destroy(query);
    return checker.finish(elapsed_seconds());
}
