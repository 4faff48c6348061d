// BenchResults: see BenchResults.h. The keys are written in the order results.json has always had them.
#include <report/BenchResults.h>

namespace report {

namespace {

Json spreadJson(const BenchSpread& s) {
    return Json{{"median", s.median}, {"min", s.min}, {"max", s.max}, {"p25", s.p25}, {"p75", s.p75}};
}

template <class T, class ToJson>
Json orNull(const std::optional<T>& value, ToJson toJson) {
    return value ? toJson(*value) : Json(nullptr);
}

Json timingJson(const BenchTiming& t) {
    Json passes = Json::array();
    for (const BenchPassTiming& p : t.passes) {
        Json pass{{"name", p.name}, {"gpu_ms", p.gpuMs}, {"cpu_ms", p.cpuMs}, {"draws", p.draws}};
        if (p.work) {
            pass["left_out"] = p.work->leftOut;
            pass["culled"] = p.work->culled;
            pass["triangles"] = p.work->triangles;
            pass["texels_written"] = p.work->texelsWritten;
        }
        passes.push_back(std::move(pass));
    }
    return Json{{"frame_time_ms", spreadJson(t.frameTimeMs)},
                {"gpu_time_ms", orNull(t.gpuTimeMs, spreadJson)},
                {"work", orNull(t.work,
                                [](const BenchFrameWork& w) {
                                    return Json{{"passes_run", w.passesRun},
                                                {"passes_left_out", w.passesLeftOut},
                                                {"draws", w.draws},
                                                {"culled", w.culled},
                                                {"triangles", w.triangles}};
                                })},
                {"passes", passes},
                {"runtime_cpu_ms", orNull(t.runtimeCpuMs, [](const BenchRuntimeCpu& c) {
                     return Json{{"script", c.script},
                                 {"binding", c.binding},
                                 {"preshader", c.preshader},
                                 {"gl", c.gl},
                                 {"overhead", c.overhead}};
                 })}};
}

Json errorJson(const BenchShadowError& e) {
    return Json{{"receiver_pixels", e.receiverPixels},
                {"false_shadow_pixels", e.falseShadowPixels},
                {"false_light_pixels", e.falseLightPixels},
                {"false_shadow_percent", e.falseShadowPercent},
                {"false_light_percent", e.falseLightPercent},
                {"misclassified_percent", e.misclassifiedPercent},
                {"mae", e.mae},
                {"p95_abs_error", e.p95AbsError},
                {"penumbra_pixels", e.penumbraPixels},
                {"penumbra_mae", e.penumbraMae ? Json(*e.penumbraMae) : Json(nullptr)}};
}

Json runJson(const BenchRunRecord& r) {
    Json record{{"run_index", r.runIndex},
                {"effect", r.effect},
                {"effect_name", r.effectName},
                {"peer", r.peer ? Json(*r.peer) : Json(nullptr)},
                {"technique", r.technique},
                {"scene", r.scene},
                {"map_size", r.mapSize},
                {"map_size_honoured", r.mapSizeHonoured},
                {"width", r.width},
                {"height", r.height},
                {"gl_renderer", r.glRenderer}};
    if (r.peerLibraryVersion) record["peer_library_version"] = *r.peerLibraryVersion;
    record["frames"] = r.frames;
    record["warmup_frames"] = r.warmupFrames;
    record["leave_out"] = r.leaveOut;
    record["camera_orbit_degrees_per_frame"] = r.cameraOrbitDegreesPerFrame;
    record["first_frame_ms"] = r.firstFrameMs;
    if (r.setting) {
        Json values = Json::object();
        for (const auto& [name, value] : *r.setting) values[name] = value;
        record["setting"] = values;
    }
    // The steady state keeps the fields' names of schema 1; the full cost sits beside.
    const Json steady = timingJson(r.steady);  // named: items() refers to it while the loop runs
    for (const auto& [key, value] : steady.items()) record[key] = value;
    record["full_cost"] = timingJson(r.fullCost);
    record["aliasing"] = orNull(r.aliasing, [](const BenchAliasing& a) {
        return Json{{"max_texel_footprint_px", a.maxTexelFootprintPx},
                    {"mean_texel_footprint_px", a.meanTexelFootprintPx},
                    {"p95_texel_footprint_px", a.p95TexelFootprintPx},
                    {"pixels", a.pixels}};
    });
    record["ground_truth"] = Json{{"soft", r.truthSoft}, {"samples_per_pixel", r.truthSamplesPerPixel}};
    record["error"] = orNull(r.error, errorJson);
    record["error_image"] = r.errorImage ? Json(*r.errorImage) : Json(nullptr);
    return record;
}

Json configJson(const BenchConfig& c) {
    return Json{{"effects", c.effects},
                {"scenes", c.scenes},
                {"map_sizes", c.mapSizes},
                {"techniques", c.techniques},
                {"set", c.set},
                {"frames", c.frames},
                {"warmup", c.warmup},
                {"width", c.width},
                {"height", c.height},
                {"area_samples", c.areaSamples},
                {"area_radius", c.areaRadius ? Json(*c.areaRadius) : Json(nullptr)},
                {"light_angle_to_view", c.lightAngleToView ? Json(*c.lightAngleToView) : Json(nullptr)},
                {"peers", c.peers},
                {"peer_techniques", c.peerTechniques},
                {"camera_orbit_degrees_per_frame", c.cameraOrbitDegreesPerFrame},
                {"leave_out", c.leaveOut},
                {"time_axis", c.timeAxis},
                {"batching", c.batching}};
}

}  // namespace

Json benchResultsJson(const BenchResults& results) {
    Json truth = Json::array();
    for (const BenchTruthRecord& t : results.groundTruth)
        truth.push_back(Json{{"scene", t.scene},
                             {"soft", t.soft},
                             {"samples_per_pixel", t.samplesPerPixel},
                             {"rays", t.rays},
                             {"normal_offset", t.normalOffset},
                             {"receiver_pixels", t.receiverPixels},
                             {"shadowed_receiver_pixels", t.shadowedReceiverPixels},
                             {"seconds", t.seconds},
                             {"cached", t.cached}});
    Json runs = Json::array();
    for (const BenchRunRecord& run : results.runs) runs.push_back(runJson(run));
    const std::optional<BenchShard>& shard = results.shard;
    return Json{
        {"schema_version", kBenchSchemaVersion},
        {"generator", "shadowfx bench"},
        {"gl_renderer", results.glRenderer},
        {"backend", results.backend},
        {"config", configJson(results.config)},
        {"shard",
         shard ? Json{{"index", shard->index}, {"count", shard->count}, {"runs_total", results.runsTotal}}
               : Json(nullptr)},
        {"ground_truth", truth},
        {"runs", runs}};
}

}  // namespace report
