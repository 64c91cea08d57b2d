// Many configurations of one robot against one map (opx_query_check_
// configurations): each row's joint vector is posed by FK on a worker's
// own copy of the link set and checked, the rows split over threads.
#pragma once

#include "query/batch/batch_worker.hpp"

namespace octoprox {

// Answers every row of `rows` into `out`.  `links`, `joints` and the
// obstacles are the caller's, read-only.
void check_configurations(BatchWorkers &workers, const Obstacles &obstacles, const LinkSet &links,
                          const JointTree &joints, const JointRows &rows, const BasePoses &bases,
                          const ConfigurationSettings &settings, const ConfigurationOutputs &out);

}  // namespace octoprox
