// BenchShard: which runs of a bench one shard measures (`shadowfx bench --shard K/N`), so that a sweep too
// big for one machine runs as N independent jobs of a scheduler a lab already has (a Slurm array, GNU
// parallel) and `bench merge` (BenchMerge.h) joins their outputs.
//
// Every run of a bench command has an index: its place in the unsharded run's order (effect, map size,
// setting, scene, technique, leave-out mode, then the peers' runs). The order follows from the command and
// the compiled effects alone, so every shard of one command numbers the runs alike. Shard K of N takes the
// runs whose index modulo N is K - 1. Dealt round-robin rather than in contiguous blocks: neighbouring runs
// share effect, map size and scene, so their costs go together (a 4096 map, a heavy scene, a slow effect),
// and dealt out in turn every shard gets its share of each costly stretch, so the shards end at about the
// same time. What that costs, every shard needing the ground truth of every scene, `--truth-cache` pays
// once (runtime/TruthCache.h).
#pragma once

#include <cstddef>
#include <optional>
#include <string>

namespace report {

struct BenchShard {
    int index = 1;  // K, 1-based (a Slurm array's SLURM_ARRAY_TASK_ID from 1, GNU parallel's {})
    int count = 1;  // N

    bool takes(size_t runIndex) const { return runIndex % static_cast<size_t>(count) == index - 1u; }
    // How many of `totalRuns` runs this shard takes.
    size_t runsOf(size_t totalRuns) const;
    std::string label() const { return std::to_string(index) + "/" + std::to_string(count); }
};

// "K/N" with 1 <= K <= N; nullopt with `error` saying what is wrong otherwise.
std::optional<BenchShard> parseBenchShard(const std::string& text, std::string& error);

}  // namespace report
