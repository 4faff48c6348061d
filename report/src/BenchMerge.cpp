// BenchMerge: see BenchMerge.h.
#include <report/BenchMerge.h>
#include <report/BenchShard.h>

#include <initializer_list>

namespace report {

namespace {

// A ground-truth entry without what may differ between shards that measured the same truth: how long it
// took and whether it came from the truth cache.
Json withoutProvenance(Json truth) {
    if (truth.is_object()) {
        truth.erase("seconds");
        truth.erase("cached");
    }
    return truth;
}

// The fields of a results document that merging and the report writer read (the schema's required ones,
// docs/results.schema.json, and the run index): the first one `results` lacks, as a path, or "".
std::string missingField(const Json& results) {
    const auto lacks = [](const Json& object, std::initializer_list<const char*> keys) -> std::string {
        if (!object.is_object()) return "(the object itself)";
        for (const char* key : keys)
            if (!object.contains(key)) return key;
        return "";
    };
    if (std::string key = lacks(results, {"gl_renderer", "backend", "config", "ground_truth", "runs"});
        !key.empty())
        return key;
    if (std::string key = lacks(results["config"], {"frames", "warmup", "width", "height",
                                                    "camera_orbit_degrees_per_frame", "time_axis"});
        !key.empty())
        return "config." + key;
    if (!results["ground_truth"].is_array()) return "ground_truth (an array)";
    for (const Json& truth : results["ground_truth"])
        if (std::string key = lacks(truth, {"scene", "soft", "samples_per_pixel", "rays", "receiver_pixels"});
            !key.empty())
            return "ground_truth[]." + key;
    if (!results["runs"].is_array()) return "runs (an array)";
    for (const Json& run : results["runs"])
        if (std::string key = lacks(run, {"run_index", "effect", "effect_name", "peer", "technique", "scene",
                                          "map_size", "frame_time_ms", "passes", "error", "error_image",
                                          "leave_out", "first_frame_ms", "work", "full_cost", "aliasing"});
            !key.empty())
            return "runs[]." + key;
    return "";
}

// The top-level keys in which `a` and `b` differ, comma-separated.
std::string differingKeys(const Json& a, const Json& b) {
    std::string keys;
    for (const auto& [key, value] : a.items())
        if (!b.contains(key) || b[key] != value) keys += (keys.empty() ? "" : ", ") + key;
    for (const auto& [key, value] : b.items())
        if (!a.contains(key)) keys += (keys.empty() ? "" : ", ") + key;
    return keys;
}

// The shard mark of `shard`'s results, checked for form.
std::optional<BenchShard> shardOf(const ShardResults& shard, size_t& runsTotal, std::string& error) {
    const Json& results = shard.results;
    if (!results.is_object() || results.value("generator", "") != "shadowfx bench" ||
        results.value("schema_version", 0) != kBenchSchemaVersion) {
        error = shard.origin + ": not the results.json of shadowfx bench (schema version " +
                std::to_string(kBenchSchemaVersion) + ")";
        return std::nullopt;
    }
    if (const std::string field = missingField(results); !field.empty()) {
        error =
            shard.origin + ": results.json has no " + field + " (not written by this shadowfx, or edited)";
        return std::nullopt;
    }
    const Json& mark = results.contains("shard") ? results["shard"] : Json();
    if (!mark.is_object() || !mark.contains("index") || !mark.contains("count") ||
        !mark.contains("runs_total") || !mark["index"].is_number_integer() ||
        !mark["count"].is_number_integer() || !mark["runs_total"].is_number_integer()) {
        error = shard.origin + ": not a shard (run without --shard K/N): nothing to merge it with";
        return std::nullopt;
    }
    BenchShard parsed{mark["index"].get<int>(), mark["count"].get<int>()};
    if (parsed.count < 1 || parsed.index < 1 || parsed.index > parsed.count) {
        error = shard.origin + ": shard " + parsed.label() + " is not a shard K/N with 1 <= K <= N";
        return std::nullopt;
    }
    runsTotal = mark["runs_total"].get<size_t>();
    return parsed;
}

}  // namespace

std::optional<Json> mergeBenchShards(const std::vector<ShardResults>& shards, std::string& error) {
    if (shards.empty()) {
        error = "no shards to merge";
        return std::nullopt;
    }
    // Each shard's mark; all of one command, one count, one machine kind.
    std::vector<BenchShard> marks;
    size_t runsTotal = 0;
    for (const ShardResults& shard : shards) {
        size_t total = 0;
        const std::optional<BenchShard> mark = shardOf(shard, total, error);
        if (!mark) return std::nullopt;
        const ShardResults& first = shards.front();
        if (marks.empty()) {
            runsTotal = total;
        } else {
            if (shard.results["config"] != first.results["config"]) {
                error = shard.origin + " and " + first.origin +
                        " are shards of different bench commands (their config differs in: " +
                        differingKeys(shard.results["config"], first.results["config"]) + ")";
                return std::nullopt;
            }
            if (mark->count != marks.front().count || total != runsTotal) {
                error = shard.origin + " is shard " + mark->label() + " of " + std::to_string(total) +
                        " runs, " + first.origin + " shard " + marks.front().label() + " of " +
                        std::to_string(runsTotal) + ": not one split of one command";
                return std::nullopt;
            }
            for (const char* key : {"gl_renderer", "backend"}) {
                if (shard.results[key] != first.results[key]) {
                    error = shard.origin + " ran on " + shard.results[key].dump() + ", " + first.origin +
                            " on " + first.results[key].dump() + " (" + key +
                            "): times from different machines do not compare";
                    return std::nullopt;
                }
            }
        }
        marks.push_back(*mark);
    }

    // Every shard 1..N exactly once.
    const int count = marks.front().count;
    std::vector<int> holder(static_cast<size_t>(count) + 1, -1);
    for (size_t s = 0; s < shards.size(); ++s) {
        int& seen = holder[static_cast<size_t>(marks[s].index)];
        if (seen >= 0) {
            error = "shard " + marks[s].label() +
                    " given twice: " + shards[static_cast<size_t>(seen)].origin + " and " + shards[s].origin;
            return std::nullopt;
        }
        seen = static_cast<int>(s);
    }
    std::string missing;
    for (int k = 1; k <= count; ++k)
        if (holder[static_cast<size_t>(k)] < 0)
            missing += (missing.empty() ? "" : ", ") + BenchShard{k, count}.label();
    if (!missing.empty()) {
        error = "missing shard" + std::string(missing.find(',') != std::string::npos ? "s " : " ") + missing +
                " (of " + std::to_string(count) + ")";
        return std::nullopt;
    }

    // Every run index once, in the shard that takes it.
    std::vector<const Json*> runs(runsTotal, nullptr);
    for (size_t s = 0; s < shards.size(); ++s) {
        const Json& shardRuns = shards[s].results["runs"];
        if (shardRuns.size() != marks[s].runsOf(runsTotal)) {
            error = shards[s].origin + ": shard " + marks[s].label() + " holds " +
                    std::to_string(shardRuns.size()) + " runs, its share of " + std::to_string(runsTotal) +
                    " is " + std::to_string(marks[s].runsOf(runsTotal)) +
                    " (an interrupted or edited shard?)";
            return std::nullopt;
        }
        for (const Json& run : shardRuns) {
            if (!run["run_index"].is_number_unsigned() || run["run_index"].get<size_t>() >= runsTotal ||
                !marks[s].takes(run["run_index"].get<size_t>())) {
                error = shards[s].origin + ": a run whose run_index " + run["run_index"].dump() + " shard " +
                        marks[s].label() + " does not take";
                return std::nullopt;
            }
            const Json*& slot = runs[run["run_index"].get<size_t>()];
            if (slot) {
                error = shards[s].origin + ": run " + run["run_index"].dump() + " twice";
                return std::nullopt;
            }
            slot = &run;
        }
    }

    // The ground truth of each scene, the same wherever it was measured. From shard 1, as the unsharded run
    // would list it.
    const ShardResults& shardOne = shards[static_cast<size_t>(holder[1])];
    const Json& firstTruths = shardOne.results["ground_truth"];
    for (size_t s = 0; s < shards.size(); ++s) {
        const Json& truths = shards[s].results["ground_truth"];
        if (truths.size() != firstTruths.size()) {
            error = shards[s].origin + ": ground truth of " + std::to_string(truths.size()) + " scenes, " +
                    shardOne.origin + " of " + std::to_string(firstTruths.size());
            return std::nullopt;
        }
        for (size_t i = 0; i < truths.size(); ++i) {
            if (withoutProvenance(truths[i]) != withoutProvenance(firstTruths[i])) {
                error = shards[s].origin + " and " + shardOne.origin +
                        " measured different ground truths of scene " +
                        (truths[i]["scene"].is_string() ? truths[i]["scene"].get<std::string>()
                                                        : truths[i]["scene"].dump()) +
                        " (differing in: " +
                        differingKeys(withoutProvenance(truths[i]), withoutProvenance(firstTruths[i])) + ")";
                return std::nullopt;
            }
        }
    }

    Json merged = shardOne.results;
    merged["shard"] = nullptr;
    Json joined = Json::array();
    for (const Json* run : runs) joined.push_back(*run);
    merged["runs"] = std::move(joined);
    return merged;
}

}  // namespace report
