// The ground truth's cost per pixel (runtime/GroundTruth.h): Embree shadow rays from a synthetic G-buffer
// of the built-in scenes' ground plane, hard (1 ray a pixel) and soft (N light samples a pixel). No GL:
// the G-buffer is the plane y = 0 sampled on a grid, so the figure is the ray caster's alone.
//
//   build/benchmarks/bench_ground_truth [--benchmark_filter=Soft]
// items_per_second is pixels per second.
#include <runtime/BuiltinScenes.h>
#include <runtime/GroundTruth.h>
#include <runtime/Scene.h>

#include <benchmark/benchmark.h>

namespace {

runtime::GBuffer planeGBuffer(const runtime::Scene& scene, int size) {
    runtime::GBuffer gbuffer;
    gbuffer.width = gbuffer.height = size;
    const runtime::Bounds bounds = scene.bounds();
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            const float u = (x + 0.5f) / size, v = (y + 0.5f) / size;
            gbuffer.position.emplace_back(bounds.min.x + u * (bounds.max.x - bounds.min.x), 0.0f,
                                          bounds.min.z + v * (bounds.max.z - bounds.min.z));
            gbuffer.normal.emplace_back(0.0f, 1.0f, 0.0f);
            gbuffer.objectId.push_back(1);
        }
    }
    return gbuffer;
}

void groundTruth(benchmark::State& state, const char* sceneName, float areaRadius) {
    std::optional<runtime::Scene> scene = runtime::makeBuiltinScene(sceneName);
    if (!scene || scene->lights.empty()) {
        state.SkipWithError("scene not available");
        return;
    }
    runtime::Light light = scene->lights[0];
    light.areaRadius = areaRadius;
    const runtime::ShadowRayCaster caster(*scene);
    const runtime::GBuffer gbuffer = planeGBuffer(*scene, static_cast<int>(state.range(0)));
    runtime::GroundTruthOptions options;
    options.areaSamples = 64;
    options.threads = 1;  // per-core cost; the bench uses every core
    uint64_t rays = 0;
    for (auto _ : state) {
        runtime::GroundTruth truth = caster.compute(gbuffer, light, options);
        rays += truth.raysCast;
        benchmark::DoNotOptimize(truth.visibility.data());
    }
    state.SetItemsProcessed(static_cast<int64_t>(state.iterations()) *
                            static_cast<int64_t>(gbuffer.pixelCount()));
    state.counters["rays_per_pixel"] =
        static_cast<double>(rays) / static_cast<double>(state.iterations() * gbuffer.pixelCount());
}

void buildBvh(benchmark::State& state, const char* sceneName) {
    std::optional<runtime::Scene> scene = runtime::makeBuiltinScene(sceneName);
    if (!scene) {
        state.SkipWithError("scene not available");
        return;
    }
    for (auto _ : state) {
        runtime::ShadowRayCaster caster(*scene);
        benchmark::DoNotOptimize(&caster);
    }
    state.counters["triangles"] = static_cast<double>(scene->triangleCount());
}

}  // namespace

BENCHMARK_CAPTURE(groundTruth, HardBoxes, "boxes", 0.0f)->Arg(128)->Arg(256)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(groundTruth, HardTeapot, "teapot", 0.0f)->Arg(128)->Arg(256)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(groundTruth, Soft64Boxes, "boxes", 0.5f)->Arg(64)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(buildBvh, Teapot, "teapot")->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
