// BenchReport: see BenchReport.h.
#include <report/BenchReport.h>
#include <report/ErrorTimePlot.h>
#include <report/NumberFormat.h>

#include <fstream>
#include <map>
#include <ostream>
#include <utility>
#include <vector>

namespace report {

std::string techniqueLabel(const Json& run) {
    std::string label = run["technique"].get<std::string>();
    if (!run.contains("setting")) return label;
    std::string values;
    for (const auto& [name, value] : run["setting"].items())
        values += (values.empty() ? "" : ", ") + name + "=" + value.get<std::string>();
    return label + " (" + values + ")";
}

namespace {

// error_vs_time.svg (ErrorTimePlot.h). Returns a note for the report: why there is no plot, or "".
// `fullCost`: the x axis is the full cost (every pass drawn), else the steady state.
std::string plotErrorVsTime(const std::filesystem::path& outDir, const Json& runs, bool fullCost) {
    std::vector<PlotPoint> points;
    for (const Json& run : runs) {
        if (!run["error"].is_object()) continue;
        const Json& time = fullCost ? run["full_cost"]["frame_time_ms"] : run["frame_time_ms"];
        points.push_back(PlotPoint{time["median"].get<double>(),
                                   run["error"]["misclassified_percent"].get<double>(),
                                   run["effect_name"].get<std::string>() + "/" + techniqueLabel(run) + " " +
                                       std::to_string(run["map_size"].get<int>()),
                                   run["scene"].get<std::string>()});
    }
    if (points.empty()) return "no run exposes its shadow term (SHADOWFX_VISIBILITY): nothing to plot";
    std::string error;
    if (!writeErrorTimePlot((outDir / "error_vs_time.svg").string(), points,
                            fullCost ? "full cost: every pass drawn" : "steady state: unchanged maps reused",
                            error))
        return error + ": no plot";
    return "";
}

// Per scene and map size, the most exact shadowfx run and the most exact run of each peer, and the ratio of
// their median frame times (shadowfx ÷ peer): nothing when no peer ran.
void writeSideBySide(std::ostream& md, const Json& runs) {
    struct Best {
        const Json* run = nullptr;
        void offer(const Json& candidate) {
            if (!candidate["error"].is_object()) return;
            if (!run || candidate["error"]["misclassified_percent"].get<double>() <
                            (*run)["error"]["misclassified_percent"].get<double>())
                run = &candidate;
        }
    };
    // (scene, map size) -> best shadowfx run, and best run per peer
    std::map<std::pair<std::string, int>, std::pair<Best, std::map<std::string, Best>>> best;
    bool anyPeer = false;
    for (const Json& run : runs) {
        auto& entry = best[{run["scene"].get<std::string>(), run["map_size"].get<int>()}];
        if (run["peer"].is_string()) {
            anyPeer = true;
            entry.second[run["effect"].get<std::string>()].offer(run);
        } else {
            entry.first.offer(run);
        }
    }
    if (!anyPeer) return;
    const auto describe = [](const Json& run) {
        return run["effect_name"].get<std::string>() + "/" + techniqueLabel(run) + " " +
               report::formatFixed(run["error"]["misclassified_percent"].get<double>(), 3) + " % in " +
               report::formatFixed(run["full_cost"]["frame_time_ms"]["median"].get<double>(), 2) + " ms";
    };
    md << "\n## Side by side with the peers\n\n"
          "The most exact run of each side (least misclassified %) per scene and map size; ratio = median "
          "full-cost frame time (every map redrawn each frame, as the peers do) of shadowfx's ÷ the "
          "peer's.\n\n"
          "| scene | map | shadowfx | peer | frame-time ratio |\n|---|---:|---|---|---:|\n";
    for (const auto& [key, entry] : best) {
        for (const auto& [peer, peerBest] : entry.second) {
            if (!peerBest.run) continue;
            md << "| " << key.first << " | " << key.second << " | "
               << (entry.first.run ? describe(*entry.first.run) : std::string("–")) << " | "
               << describe(*peerBest.run) << " | ";
            if (entry.first.run)
                md << report::formatFixed(
                    (*entry.first.run)["full_cost"]["frame_time_ms"]["median"].get<double>() /
                        (*peerBest.run)["full_cost"]["frame_time_ms"]["median"].get<double>(),
                    2);
            md << " |\n";
        }
    }
}

void writeReport(const std::filesystem::path& path, const Json& results, const std::string& plotNote) {
    std::ofstream md(path);
    md << "# shadowfx bench\n\n";
    if (results.contains("shard") && results["shard"].is_object()) {
        const Json& shard = results["shard"];
        md << "Shard " << shard["index"].get<int>() << " of " << shard["count"].get<int>() << ": "
           << results["runs"].size() << " of the command's " << shard["runs_total"].get<size_t>()
           << " runs (`shadowfx bench merge` joins the shards; docs/sharding.md).  \n";
    }
    md << "GL renderer: `" << results["gl_renderer"].get<std::string>() << "`  \n";
    md << "Frames: " << results["config"]["warmup"].get<int>() << " warm-up, then "
       << results["config"]["frames"].get<int>() << " timed; frame " << results["config"]["width"].get<int>()
       << "x" << results["config"]["height"].get<int>() << "."
       << (results["config"]["camera_orbit_degrees_per_frame"].get<double>() != 0.0
               ? " The camera orbits " +
                     report::formatFixed(results["config"]["camera_orbit_degrees_per_frame"].get<double>(),
                                         2) +
                     " degrees a frame (view-dependent maps redrawn every frame); errors at the scene's "
                     "camera."
               : std::string())
       << "  \n";
    md << "Errors are over receiver pixels (covered, N·L > 0) against the Embree ray-cast ground truth; "
          "misclassified = false shadow + false light. Texel footprint: screen pixels covered by one "
          "shadow-map "
          "texel along its longest direction (Lloyd et al.), > 1 is undersampling.\n\n";
    const bool fullAxis = results["config"]["time_axis"] == "full";
    md << "Time: **full cost** = every pass drawn each frame, leave-out's reuse of unchanged shadow maps off "
          "(what a moving light or moving objects cost: compare techniques by this); **steady** = the same "
          "frames with that reuse (a static light and scene: with leave-out on, `main`-like techniques "
          "then pay for the scene pass alone; a technique that blurs its map every frame pays the full cost, "
          "docs/scoring.md, \"Full cost and steady state\"). The plot's axis is the "
       << (fullAxis ? "full cost" : "steady-state time (`--time steady`)") << ".\n\n";
    if (plotNote.empty()) {
        md << "![error against frame time](error_vs_time.svg)\n\n";
    } else {
        md << "_" << plotNote << "_\n\n";
    }
    md << "## Runs\n\n";
    md << "| scene | effect | technique | map | misclassified % | false shadow % | false light % | MAE | p95 "
          "| penumbra MAE | "
          "full ms (median [min–max]) | steady ms | full GPU ms | full runtime CPU ms | texel footprint max "
          "/ "
          "p95 / mean | errors |\n";
    md << "|---|---|---|---:|---:|---:|---:|---:|---:|---:|---|---:|---:|---:|---|---|\n";
    for (const Json& run : results["runs"]) {
        const Json& full = run["full_cost"];
        const Json& frame = full["frame_time_ms"];
        md << "| " << run["scene"].get<std::string>() << " | " << run["effect_name"].get<std::string>()
           << " | " << techniqueLabel(run) << " | " << run["map_size"].get<int>() << " | ";
        if (run["error"].is_object()) {
            const Json& e = run["error"];
            md << report::formatFixed(e["misclassified_percent"].get<double>(), 3) << " | "
               << report::formatFixed(e["false_shadow_percent"].get<double>(), 3) << " | "
               << report::formatFixed(e["false_light_percent"].get<double>(), 3) << " | "
               << report::formatFixed(e["mae"].get<double>(), 4) << " | "
               << report::formatFixed(e["p95_abs_error"].get<double>(), 3) << " | "
               << (e["penumbra_mae"].is_number() ? report::formatFixed(e["penumbra_mae"].get<double>(), 4)
                                                 : std::string("–"))
               << " | ";
        } else {
            md << "n/a | n/a | n/a | n/a | n/a | n/a | ";
        }
        md << report::formatFixed(frame["median"].get<double>(), 2) << " ["
           << report::formatFixed(frame["min"].get<double>(), 2) << "–"
           << report::formatFixed(frame["max"].get<double>(), 2) << "] | "
           << report::formatFixed(run["frame_time_ms"]["median"].get<double>(), 2) << " | ";
        // A peer's row has frame times and errors only: its passes are the peer library's own.
        if (run["peer"].is_string()) {
            md << "– | – | – | ";
        } else {
            md << report::formatFixed(full["gpu_time_ms"]["median"].get<double>(), 2) << " | "
               << report::formatFixed(full["runtime_cpu_ms"]["overhead"].get<double>(), 3) << " | "
               << report::formatFixed(run["aliasing"]["max_texel_footprint_px"].get<double>(), 2) << " / "
               << report::formatFixed(run["aliasing"]["p95_texel_footprint_px"].get<double>(), 2) << " / "
               << report::formatFixed(run["aliasing"]["mean_texel_footprint_px"].get<double>(), 2) << " | ";
        }
        if (run["error_image"].is_string()) md << "[png](" << run["error_image"].get<std::string>() << ")";
        md << " |\n";
    }
    writeSideBySide(md, results["runs"]);
    md << "\n## Passes (full cost, median per frame)\n\n";
    md << "| scene | effect | technique | map | pass | GPU ms | CPU ms | draws "
          "|\n|---|---|---|---:|---|---:|---:|---:|\n";
    for (const Json& run : results["runs"]) {
        for (const Json& pass : run["full_cost"]["passes"]) {
            md << "| " << run["scene"].get<std::string>() << " | " << run["effect_name"].get<std::string>()
               << " | " << techniqueLabel(run) << " | " << run["map_size"].get<int>() << " | "
               << pass["name"].get<std::string>() << " | "
               << report::formatFixed(pass["gpu_ms"].get<double>(), 3) << " | "
               << report::formatFixed(pass["cpu_ms"].get<double>(), 3) << " | " << pass["draws"].get<int>()
               << " |\n";
        }
    }
    md << "\n## Leave-out\n\n"
          "Work of one steady-state frame (counted in an extra frame): passes run / left out (dead or "
          "cached), draws, objects culled, triangles; full ms = the full cost's median. First frame = the "
          "first warm-up frame (nothing "
          "cached). "
          "`speed-up` = median frame time without leave-out / with, where both were run.\n\n";
    md << "| scene | effect | technique | map | leave-out | full ms | steady ms | first frame ms | passes "
          "run "
          "/ "
          "left out | draws | culled | triangles | speed-up |\n"
          "|---|---|---|---:|---|---:|---:|---:|---|---:|---:|---:|---:|\n";
    for (const Json& run : results["runs"]) {
        if (run["peer"].is_string()) continue;
        const Json& work = run["work"];
        std::string speedUp;
        if (run["leave_out"].get<bool>()) {
            for (const Json& other : results["runs"]) {
                if (other["peer"].is_string() || other["leave_out"].get<bool>() ||
                    other["scene"] != run["scene"] || other["effect"] != run["effect"] ||
                    techniqueLabel(other) != techniqueLabel(run) || other["map_size"] != run["map_size"])
                    continue;
                speedUp = report::formatFixed(other["frame_time_ms"]["median"].get<double>() /
                                                  run["frame_time_ms"]["median"].get<double>(),
                                              2) +
                          "x";
            }
        }
        md << "| " << run["scene"].get<std::string>() << " | " << run["effect_name"].get<std::string>()
           << " | " << techniqueLabel(run) << " | " << run["map_size"].get<int>() << " | "
           << (run["leave_out"].get<bool>() ? "on" : "off") << " | "
           << report::formatFixed(run["full_cost"]["frame_time_ms"]["median"].get<double>(), 2) << " | "
           << report::formatFixed(run["frame_time_ms"]["median"].get<double>(), 2) << " | "
           << report::formatFixed(run["first_frame_ms"].get<double>(), 2) << " | "
           << work["passes_run"].get<int>() << " / " << work["passes_left_out"].get<int>() << " | "
           << work["draws"].get<int>() << " | " << work["culled"].get<int>() << " | "
           << work["triangles"].get<uint64_t>() << " | " << speedUp << " |\n";
    }
    md << "\n## Runtime CPU time (full cost, median per frame, ms)\n\n"
          "Script = interpreting the SAS scripts and the rest of the frame executor; binding = semantics and "
          "uniforms; preshader = pass arguments and state expressions; GL = inside the driver's draw/clear "
          "calls.\n\n";
    md << "| scene | effect | technique | map | script | binding | preshader | overhead (sum) | GL |\n"
          "|---|---|---|---:|---:|---:|---:|---:|---:|\n";
    for (const Json& run : results["runs"]) {
        if (run["peer"].is_string()) continue;
        const Json& c = run["full_cost"]["runtime_cpu_ms"];
        md << "| " << run["scene"].get<std::string>() << " | " << run["effect_name"].get<std::string>()
           << " | " << techniqueLabel(run) << " | " << run["map_size"].get<int>() << " | "
           << report::formatFixed(c["script"].get<double>(), 3) << " | "
           << report::formatFixed(c["binding"].get<double>(), 3) << " | "
           << report::formatFixed(c["preshader"].get<double>(), 3) << " | "
           << report::formatFixed(c["overhead"].get<double>(), 3) << " | "
           << report::formatFixed(c["gl"].get<double>(), 3) << " |\n";
    }
    md << "\n## Ground truth\n\n| scene | lights samples / pixel | soft | rays | seconds "
          "|\n|---|---:|---|---:|---:|\n";
    for (const Json& truth : results["ground_truth"]) {
        md << "| " << truth["scene"].get<std::string>() << " | " << truth["samples_per_pixel"].get<int>()
           << " | " << (truth["soft"].get<bool>() ? "yes" : "no") << " | " << truth["rays"].get<uint64_t>()
           << " | " << report::formatFixed(truth["seconds"].get<double>(), 2) << " |\n";
    }
}

}  // namespace

bool writeBenchOutputs(const std::filesystem::path& outDir, const Json& results, std::string& plotNote,
                       std::string& error) {
    {
        std::ofstream out(outDir / "results.json");
        out << results.dump(2) << "\n";
        if (!out) {
            error = "cannot write " + (outDir / "results.json").string();
            return false;
        }
    }
    plotNote = plotErrorVsTime(outDir, results["runs"], results["config"]["time_axis"] == "full");
    writeReport(outDir / "report.md", results, plotNote);
    return true;
}

}  // namespace report
