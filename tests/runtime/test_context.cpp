// Contexts: every backend compiled into this build gives an OpenGL 4.5 core context with the D3D clip
// conventions set; Auto picks a headless one; unknown names are rejected. GLFW needs a display and is
// skipped without one.
#include <runtime/GlContext.h>

#include <runtime/GlApi.h>
#include <runtime/GlDebug.h>

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <vector>

namespace test_context {

using namespace runtime;

namespace {

bool hasDisplay() {
    return std::getenv("DISPLAY") != nullptr || std::getenv("WAYLAND_DISPLAY") != nullptr;
}

void expectCore45WithD3dConventions() {
    GLint major = 0, minor = 0, profile = 0, origin = 0, depthMode = 0;
    gl::GetIntegerv(GL_MAJOR_VERSION, &major);
    gl::GetIntegerv(GL_MINOR_VERSION, &minor);
    gl::GetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
    gl::GetIntegerv(GL_CLIP_ORIGIN, &origin);
    gl::GetIntegerv(GL_CLIP_DEPTH_MODE, &depthMode);
    EXPECT_GE(major * 10 + minor, 45);
    EXPECT_NE(profile & GL_CONTEXT_CORE_PROFILE_BIT, 0);
    EXPECT_EQ(origin, GL_UPPER_LEFT);
    EXPECT_EQ(depthMode, GL_ZERO_TO_ONE);
    EXPECT_EQ(gl::GetError(), GLenum(GL_NO_ERROR));
}

}  // namespace

TEST(Context, BackendNamesRoundTrip) {
    for (Backend backend : {Backend::Auto, Backend::OSMesa, Backend::EGL, Backend::GLFW}) {
        auto parsed = parseBackend(backendName(backend));
        ASSERT_TRUE(parsed.has_value()) << backendName(backend);
        EXPECT_EQ(*parsed, backend);
    }
    EXPECT_EQ(parseBackend("OSMesa"), Backend::OSMesa);
    EXPECT_FALSE(parseBackend("vulkan").has_value());
    EXPECT_FALSE(parseBackend("").has_value());
}

TEST(Context, CompiledBackendsListHeadlessFirst) {
    std::vector<Backend> backends = compiledBackends();
    ASSERT_FALSE(backends.empty());
    EXPECT_EQ(backends.front(), Backend::EGL);
    EXPECT_EQ(backends.back(), Backend::GLFW);
}

TEST(Context, EveryCompiledBackendGivesCore45) {
    for (Backend backend : compiledBackends()) {
        if (backend == Backend::GLFW && !hasDisplay()) continue;
        SCOPED_TRACE(std::string(backendName(backend)));
        ContextOptions options;
        options.backend = backend;
        std::string error;
        auto context = createContext(options, error);
        ASSERT_NE(context, nullptr) << error;
        EXPECT_TRUE(error.empty());
        EXPECT_EQ(context->backend(), backend);
        std::string renderer = context->renderer();
        EXPECT_NE(renderer.find(" | 4."), std::string::npos) << renderer;
        EXPECT_NE(renderer.find("Core Profile"), std::string::npos) << renderer;
        expectCore45WithD3dConventions();
    }
}

TEST(Context, AutoGivesAHeadlessContext) {
    std::string error;
    auto context = createContext(ContextOptions{}, error);
    ASSERT_NE(context, nullptr) << error;
    EXPECT_NE(context->backend(), Backend::GLFW);
    EXPECT_NE(context->backend(), Backend::Auto);
    expectCore45WithD3dConventions();
}

TEST(Context, SwitchingBetweenBackendsKeepsWorking) {
    std::vector<std::unique_ptr<GlContext>> contexts;
    for (Backend backend : compiledBackends()) {
        if (backend == Backend::GLFW) continue;
        ContextOptions options;
        options.backend = backend;
        std::string error;
        contexts.push_back(createContext(options, error));
        ASSERT_NE(contexts.back(), nullptr) << error;
    }
    for (auto& context : contexts) {
        context->makeCurrent();
        SCOPED_TRACE(std::string(backendName(context->backend())));
        expectCore45WithD3dConventions();
        GLuint texture = 0;
        gl::GenTextures(1, &texture);
        EXPECT_NE(texture, 0u);
        gl::DeleteTextures(1, &texture);
    }
}

TEST(Context, GlfwWithoutDisplayFailsWithAReason) {
    if (hasDisplay()) GTEST_SKIP() << "a display is available";
    ContextOptions options;
    options.backend = Backend::GLFW;
    std::string error;
    auto context = createContext(options, error);
    EXPECT_EQ(context, nullptr);
    EXPECT_NE(error.find("glfw:"), std::string::npos) << error;
}

TEST(Context, DebugContextRoutesMessagesToTheSink) {
    std::vector<std::string> messages;
    setDebugSink([&](std::string message) { messages.push_back(std::move(message)); });
    ContextOptions options;
    options.debug = true;
    std::string error;
    auto context = createContext(options, error);
    ASSERT_NE(context, nullptr) << error;
    gl::Enable(GLenum(0x1234));  // GL_INVALID_ENUM
    EXPECT_EQ(gl::GetError(), GLenum(GL_INVALID_ENUM));
    EXPECT_FALSE(messages.empty());
    EXPECT_TRUE(checkGlErrors("nothing", __FILE__, __LINE__));
    gl::Enable(GLenum(0x1234));
    messages.clear();
    EXPECT_FALSE(checkGlErrors("gl::Enable(0x1234)", "file.cpp", 7));
    ASSERT_FALSE(messages.empty());
    EXPECT_NE(messages.back().find("file.cpp:7: gl::Enable(0x1234): GL_INVALID_ENUM"), std::string::npos)
        << messages.back();
    setDebugSink(nullptr);
}
}  // namespace test_context
