// The ground-truth cache (runtime/TruthCache.h), without GL: a G-buffer made by hand over a plane, a box
// casting a shadow onto it. Its key must change with every input of the truth and with nothing else; an
// entry read back must be the truth that was cast; and a stale, truncated, corrupted or foreign entry must
// be rejected with its reason and cast again (the file then repaired), never used.
#include "ScratchDirectory.h"

#include <runtime/GroundTruth.h>
#include <runtime/ShadowMeasurement.h>
#include <runtime/TruthCache.h>

#include <glm/gtc/matrix_transform.hpp>

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

namespace shadowfx::test::test_truth_cache {
namespace {

constexpr int kWidth = 24;
constexpr int kHeight = 16;

runtime::Scene boxOverPlane() {
    runtime::Scene scene;
    scene.name = "box-over-plane";
    runtime::SceneObject plane;
    plane.name = "plane";
    plane.mesh = std::make_shared<runtime::Mesh>(runtime::makePlane(12.0f, 12.0f));
    plane.castsShadow = false;
    scene.objects.push_back(plane);
    runtime::SceneObject box;
    box.name = "box";
    box.mesh = std::make_shared<runtime::Mesh>(runtime::makeBox(glm::vec3(2.0f)));
    box.world = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 2.0f, 0.0f));
    scene.objects.push_back(box);
    runtime::Light light;
    light.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.1f));
    scene.lights.push_back(light);
    return scene;
}

// The plane seen from straight above: pixel (x, y) at x in [-6, 6), z in [-4, 4), facing up; the first
// column is background.
runtime::GBuffer planeGBuffer() {
    runtime::GBuffer g;
    g.width = kWidth;
    g.height = kHeight;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            g.position.emplace_back(-6.0f + 12.0f * (x + 0.5f) / kWidth, 0.0f,
                                    -4.0f + 8.0f * (y + 0.5f) / kHeight);
            g.normal.emplace_back(0.0f, 1.0f, 0.0f);
            g.objectId.push_back(x == 0 ? 0u : 1u);
        }
    }
    return g;
}

class TruthCacheTest : public ::testing::Test {
protected:
    runtime::Scene scene = boxOverPlane();
    runtime::GBuffer gbuffer = planeGBuffer();
    runtime::GroundTruthOptions options;
    ScratchDirectory scratch{"truth_cache"};
    runtime::TruthCache cache{scratch / "cache"};

    uint64_t key() const { return runtime::truthKey(scene, scene.lights[0], gbuffer, options); }
    runtime::GroundTruth cast() const {
        return runtime::ShadowRayCaster(scene).compute(gbuffer, scene.lights[0], options);
    }
    runtime::GroundTruth viaCache(bool& cached, std::string& note) const {
        return runtime::castOrReadTruth(scene, scene.lights[0], gbuffer, options, &cache, cached, note);
    }
    std::string entryBytes() const {
        std::ifstream in(cache.entryPath(key()), std::ios::binary);
        return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    void writeEntry(const std::string& bytes) const {
        std::ofstream(cache.entryPath(key()), std::ios::binary | std::ios::trunc) << bytes;
    }
};

TEST_F(TruthCacheTest, TheSceneCastsAShadowOnSomePixelsOnly) {
    // Else a cache that returned a constant truth could pass the tests below.
    const runtime::GroundTruth truth = cast();
    int shadowed = 0, lit = 0;
    for (float v : truth.visibility) {
        shadowed += v == 0.0f ? 1 : 0;
        lit += v == 1.0f ? 1 : 0;
    }
    EXPECT_GT(shadowed, 4);
    EXPECT_GT(lit, 4);
}

TEST_F(TruthCacheTest, KeyChangesWithEveryInputOfTheTruthAndNothingElse) {
    const uint64_t base = key();
    EXPECT_EQ(base, key());
    const auto changed = [&](auto edit) {
        runtime::Scene keptScene = scene;
        runtime::GBuffer keptGBuffer = gbuffer;
        runtime::GroundTruthOptions keptOptions = options;
        edit();
        const uint64_t k = key();
        scene = keptScene;
        gbuffer = keptGBuffer;
        options = keptOptions;
        return k != base;
    };
    EXPECT_TRUE(changed([&] { scene.objects[1].world[3][0] += 0.01f; })) << "a caster moved";
    EXPECT_TRUE(changed([&] {
        auto mesh = std::make_shared<runtime::Mesh>(*scene.objects[1].mesh);
        mesh->positions[0].y += 0.01f;
        scene.objects[1].mesh = mesh;
    })) << "a caster's mesh (its file) changed";
    EXPECT_TRUE(changed([&] { scene.objects[0].castsShadow = true; })) << "the plane now casts";
    EXPECT_TRUE(changed([&] { scene.lights[0].direction.x += 0.01f; }));
    EXPECT_TRUE(changed([&] { scene.lights[0].areaRadius = 0.5f; }));
    EXPECT_TRUE(changed([&] { scene.lights[0].type = runtime::Light::Type::Point; }));
    EXPECT_TRUE(changed([&] {
        scene.explicitBounds = runtime::Bounds{glm::vec3(-20.0f), glm::vec3(20.0f)};
    })) << "the rays' offset scales with the bounds";
    EXPECT_TRUE(changed([&] { gbuffer.position[30].y += 1e-6f; }))
        << "the camera or rasterizer moved a pixel";
    EXPECT_TRUE(changed([&] { gbuffer.objectId[30] = 0; }));
    EXPECT_TRUE(changed([&] {
        gbuffer.width = kHeight;
        gbuffer.height = kWidth;
    })) << "the resolution";
    EXPECT_TRUE(changed([&] { options.areaSamples = 64; }));
    EXPECT_TRUE(changed([&] { options.normalOffset *= 2.0f; }));
    // What the rays do not see: names, colours, the camera (through the G-buffer only), the thread count.
    EXPECT_FALSE(changed([&] { scene.name = "renamed"; }));
    EXPECT_FALSE(changed([&] { scene.objects[1].color = glm::vec3(1.0f, 0.0f, 0.0f); }));
    EXPECT_FALSE(changed([&] { scene.camera.position.x += 1.0f; }));
    EXPECT_FALSE(changed([&] { options.threads = 3; }));
}

TEST_F(TruthCacheTest, AStoredTruthIsReadBackAsCast) {
    bool cached = true;
    std::string note;
    const runtime::GroundTruth first = viaCache(cached, note);
    EXPECT_FALSE(cached) << "an empty cache casts";
    EXPECT_TRUE(note.empty()) << note;
    EXPECT_TRUE(std::filesystem::exists(cache.entryPath(key())));

    const runtime::GroundTruth second = viaCache(cached, note);
    EXPECT_TRUE(cached);
    EXPECT_TRUE(note.empty()) << note;
    const runtime::GroundTruth fresh = cast();
    EXPECT_EQ(second.visibility, fresh.visibility);
    EXPECT_EQ(first.visibility, fresh.visibility);
    EXPECT_EQ(second.width, kWidth);
    EXPECT_EQ(second.height, kHeight);
    EXPECT_EQ(second.raysCast, fresh.raysCast);
    EXPECT_EQ(second.samplesPerPixel, fresh.samplesPerPixel);
    EXPECT_EQ(second.soft, fresh.soft);
}

TEST_F(TruthCacheTest, BadEntriesAreRejectedWithTheirReasonAndCastAgain) {
    std::string storeError;
    ASSERT_TRUE(cache.store(key(), cast(), storeError)) << storeError;
    const std::string good = entryBytes();
    const runtime::GroundTruth fresh = cast();
    // Offsets of the header (TruthCache.cpp): magic 0, format 8, truth version 12, key 16, width 24.
    struct Damage {
        const char* what;
        std::string bytes;
        const char* reason;
    };
    std::string flippedPixel = good;
    flippedPixel[good.size() - 8 - 4 * 40 + 3] ^= 0x40;  // a pixel's float, not the checksum
    std::string staleVersion = good;
    staleVersion[12] ^= 0x01;
    std::string otherKey = good;
    otherKey[16] ^= 0x01;
    std::string otherWidth = good;
    otherWidth[24] ^= 0x01;
    const std::vector<Damage> damages{
        {"a flipped bit", flippedPixel, "checksum mismatch (corrupted)"},
        {"a truncated file", good.substr(0, good.size() - 100), "does not match its header (truncated?)"},
        {"an older truth version", staleVersion, "stale entry"},
        {"another key's entry", otherKey, "holds the truth of another key"},
        {"another size", otherWidth, "truth where 24x16 was asked for"},
        {"a foreign file", std::string(200, 'x'), "not a ground-truth cache entry"},
        {"an empty file", "", "not a ground-truth cache entry"},
    };
    for (const Damage& damage : damages) {
        writeEntry(damage.bytes);
        const runtime::TruthCache::Lookup lookup = cache.load(key(), kWidth, kHeight);
        EXPECT_FALSE(lookup.truth) << damage.what << " was used";
        EXPECT_NE(lookup.rejected.find(damage.reason), std::string::npos)
            << damage.what << ": " << lookup.rejected;

        bool cached = true;
        std::string note;
        const runtime::GroundTruth truth = viaCache(cached, note);
        EXPECT_FALSE(cached) << damage.what;
        EXPECT_NE(note.find(damage.reason), std::string::npos) << damage.what << ": " << note;
        EXPECT_NE(note.find("cast again"), std::string::npos) << note;
        EXPECT_EQ(truth.visibility, fresh.visibility) << damage.what;
        EXPECT_EQ(entryBytes(), good) << damage.what << ": the entry is written again, whole";
    }
}

}  // namespace
}  // namespace shadowfx::test::test_truth_cache
