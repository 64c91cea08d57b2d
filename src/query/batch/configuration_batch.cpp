#include "query/batch/configuration_batch.hpp"

#include "query/batch/batch_split.hpp"

namespace octoprox {

void check_configurations(BatchWorkers &workers, const Obstacles &obstacles, const LinkSet &links,
                          const JointTree &joints, const JointRows &rows, const BasePoses &bases,
                          const ConfigurationSettings &settings, const ConfigurationOutputs &out) {
    const size_t tasks = task_count(settings.threads, rows.count);
    workers.prepare(tasks, links, joints, obstacles.world);
    split_items(tasks, rows.count, [&](size_t task, size_t begin, size_t end) {
        BatchWorker &worker = workers[task];
        for (size_t row = begin; row < end; ++row) {
            const ConfigurationAnswer answer = worker.check(obstacles.tree, rows, bases, row, settings);
            out.collided[row] = answer.collided ? 1 : 0;
            if (settings.distance) out.distances[row] = answer.distance;
        }
    });
}

}  // namespace octoprox
