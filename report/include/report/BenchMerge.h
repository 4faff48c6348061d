// BenchMerge: the results document of a whole bench from the results of its shards (`shadowfx bench merge`;
// BenchShard.h says how runs are dealt). The merged document is the one the unsharded command would have
// written, times aside: the same top-level fields, the runs in the unsharded order (by run_index), the
// ground truth of each scene once, and no `shard` mark. Written with BenchReport.h, its report and plot are
// then the unsharded run's as well.
//
// Shards are refused, with the reason, unless they are exactly the N shards of one command: each must be
// marked as a shard, all of the same command (equal `config`) and shard count, run on the same GL renderer
// and backend (times from different machines do not compare), every shard 1..N present once, every run
// index once and in the shard that takes it, and the ground truth of each scene the same in every shard but
// for its time and cache provenance (a shard that measured a different truth scored against another
// reference).
#pragma once

#include <report/BenchReport.h>

#include <optional>
#include <string>
#include <vector>

namespace report {

struct ShardResults {
    std::string origin;  // where it was read from, for messages (its output directory)
    Json results;        // its results.json
};

// The merged document, or nullopt with `error` naming the shard(s) at fault and why.
std::optional<Json> mergeBenchShards(const std::vector<ShardResults>& shards, std::string& error);

}  // namespace report
