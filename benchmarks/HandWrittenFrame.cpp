// HandWrittenFrame: see HandWrittenFrame.h.
//
// [SECTION] Uniform blocks  which member holds what, written the way SPIRV-Cross laid the block out
// [SECTION] Uniform ring    a persistently mapped buffer per pass, a region per frame in flight
// [SECTION] Set-up          programs, meshes, targets, samplers, the BVH (once)
// [SECTION] Frame           light fit, culled lists, three passes
#include "HandWrittenFrame.h"

#include <runtime/GlApi.h>
#include <runtime/IntersectionBody.h>
#include <runtime/LightParameterization.h>

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cstring>
#include <optional>

namespace shadowfx::baseline {

// [SECTION] Uniform blocks

// What a block member holds. Constants are written into the block's template once; per-frame members
// into the template once a frame; per-object members per draw.
enum class Source {
    Constant,
    ViewInverse,
    LightView,
    LightProjection,
    LightColor,
    Ambient,
    LightViewProjection,  // the scene pass's compile argument mul(LightView, LightProjection)
    World,
    WorldInverseTranspose,
    WorldViewProjection,
    ObjectColor,
    WorldLightViewProjection,  // the shadow pass's compile argument mul(World, mul(LightView,
                               // LightProjection))
};

bool perObject(Source source) {
    return source >= Source::World;
}

struct HandWrittenFrame::Member {
    Source source = Source::Constant;
    uint32_t offset = 0;
    uint32_t matrixStride = 0;
    bool hlslColumnsContiguous = true;
};

struct HandWrittenFrame::Block {
    int binding = -1;
    uint32_t size = 0;
    std::vector<uint8_t> base;  // constants and per-frame values
    std::vector<Member> perFrame, perDraw;
};

struct HandWrittenFrame::Pass {
    uint32_t program = 0;
    std::vector<Block> blocks;   // the vertex stage's, then the fragment stage's (when it has one)
    std::vector<uint32_t> vaos;  // per mesh
    std::vector<std::pair<int, glm::vec4>> defaults;  // attributes a mesh may lack: (location, value)
    std::vector<std::pair<int, bool>> samplers;       // (unit, true = the shadow map, false = the noise)
    // Every draw's blocks go straight into a persistently mapped buffer with a region per frame in
    // flight; a fence per region says when the GPU no longer reads what it held.
    static constexpr int kRegions = 3;
    uint32_t buffer = 0;
    uint8_t* mapped = nullptr;
    size_t regionSize = 0;
    std::array<GLsync, kRegions> fences{};
    int region = 0;
};

struct HandWrittenFrame::FrameValues {
    glm::mat4 view{1.0f}, projection{1.0f}, viewInverse{1.0f};
    glm::mat4 lightView{1.0f}, lightProjection{1.0f}, lightViewProjection{1.0f};
    glm::vec3 lightColor{1.0f}, ambient{0.0f};
};

namespace {

using FrameValues = HandWrittenFrame::FrameValues;

void writeMatrix(uint8_t* block, const HandWrittenFrame::Member& member, const glm::mat4& m) {
    // A glm::mat4 holding a D3DX matrix has its HLSL row r in m[r] (fx/Value.h).
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) {
            const size_t at = member.hlslColumnsContiguous ? member.offset + c * member.matrixStride + r * 4
                                                           : member.offset + r * member.matrixStride + c * 4;
            std::memcpy(block + at, &m[r][c], 4);
        }
}

void writeVector(uint8_t* block, const HandWrittenFrame::Member& member, const glm::vec3& v) {
    std::memcpy(block + member.offset, &v.x, 12);
}

void writeFrameMember(uint8_t* block, const HandWrittenFrame::Member& member, const FrameValues& frame) {
    switch (member.source) {
        case Source::ViewInverse:
            return writeMatrix(block, member, frame.viewInverse);
        case Source::LightView:
            return writeMatrix(block, member, frame.lightView);
        case Source::LightProjection:
            return writeMatrix(block, member, frame.lightProjection);
        case Source::LightViewProjection:
            return writeMatrix(block, member, frame.lightViewProjection);
        case Source::LightColor:
            return writeVector(block, member, frame.lightColor);
        case Source::Ambient:
            return writeVector(block, member, frame.ambient);
        default:
            return;
    }
}

// The matrices are composed in the order the runtime composes them (SemanticBinder, preshaders), so that
// both frames round alike.
void writeObjectMember(uint8_t* block, const HandWrittenFrame::Member& member, const FrameValues& frame,
                       const runtime::SceneObject& object) {
    switch (member.source) {
        case Source::World:
            return writeMatrix(block, member, object.world);
        case Source::WorldInverseTranspose:
            return writeMatrix(block, member, glm::transpose(glm::inverse(object.world)));
        case Source::WorldViewProjection:
            return writeMatrix(block, member, frame.projection * frame.view * object.world);
        case Source::WorldLightViewProjection:
            return writeMatrix(block, member, frame.lightViewProjection * object.world);
        case Source::ObjectColor:
            return writeVector(block, member, object.color);
        default:
            return;
    }
}

// A constant member: the parameter's initial value (bools as 32-bit uints, as glslang stores them).
bool writeConstant(std::vector<uint8_t>& block, const fx::UniformBinding& binding, const fx::Value& value) {
    const fx::TypeDesc& type = binding.type;
    if (type.shape == fx::Shape::Matrix || !type.arrayDims.empty()) return false;
    const int count = type.shape == fx::Shape::Scalar ? 1 : type.cols;
    for (int i = 0; i < count; ++i) {
        const float component = static_cast<size_t>(i) < value.data.size() ? value.data[i] : 0.0f;
        uint8_t* at = block.data() + binding.offset + 4 * i;
        if (type.base == fx::BaseType::Bool) {
            const uint32_t bits = component != 0.0f ? 1u : 0u;
            std::memcpy(at, &bits, 4);
        } else if (type.base == fx::BaseType::Int) {
            const int32_t bits = static_cast<int32_t>(component);
            std::memcpy(at, &bits, 4);
        } else {
            std::memcpy(at, &component, 4);
        }
    }
    return true;
}

std::optional<Source> parameterSource(const std::string& name) {
    static const std::map<std::string, Source> kSources = {
        {"WorldMatrix", Source::World},
        {"WorldITMatrix", Source::WorldInverseTranspose},
        {"WorldViewProjectionMatrix", Source::WorldViewProjection},
        {"ViewIMatrix", Source::ViewInverse},
        {"LightViewMatrix", Source::LightView},
        {"LightProjectionMatrix", Source::LightProjection},
        {"LightColor", Source::LightColor},
        {"AmbientLightColor", Source::Ambient},
        {"SurfaceColor", Source::ObjectColor},
    };
    auto it = kSources.find(name);
    if (it != kSources.end()) return it->second;
    return std::nullopt;
}

uint32_t compile(GLenum kind, const std::string& source, std::string& error) {
    const uint32_t shader = gl::CreateShader(kind);
    const char* text = source.c_str();
    gl::ShaderSource(shader, 1, &text, nullptr);
    gl::CompileShader(shader);
    GLint ok = GL_FALSE;
    gl::GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[2048] = {};
        gl::GetShaderInfoLog(shader, sizeof log, nullptr, log);
        error = std::string("shader does not compile: ") + log;
        gl::DeleteShader(shader);
        return 0;
    }
    return shader;
}

uint32_t link(const fx::CompiledPass& pass, std::string& error) {
    const uint32_t vs = compile(GL_VERTEX_SHADER, pass.vertex.glsl, error);
    const uint32_t fs = vs ? compile(GL_FRAGMENT_SHADER, pass.fragment.glsl, error) : 0;
    if (!fs) {
        if (vs) gl::DeleteShader(vs);
        return 0;
    }
    const uint32_t program = gl::CreateProgram();
    gl::AttachShader(program, vs);
    gl::AttachShader(program, fs);
    gl::LinkProgram(program);
    gl::DeleteShader(vs);
    gl::DeleteShader(fs);
    GLint ok = GL_FALSE;
    gl::GetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok) {
        char log[2048] = {};
        gl::GetProgramInfoLog(program, sizeof log, nullptr, log);
        error = "pass " + pass.name + " does not link: " + log;
        gl::DeleteProgram(program);
        return 0;
    }
    return program;
}

uint32_t texture2D(GLenum format, int width, int height) {
    uint32_t texture = 0;
    gl::GenTextures(1, &texture);
    gl::BindTexture(GL_TEXTURE_2D, texture);
    gl::TexStorage2D(GL_TEXTURE_2D, 1, format, width, height);
    gl::TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl::TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    return texture;
}

uint32_t sampler(GLenum filter, GLenum wrap) {
    uint32_t id = 0;
    gl::GenSamplers(1, &id);
    gl::SamplerParameteri(id, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(filter));
    gl::SamplerParameteri(id, GL_TEXTURE_MAG_FILTER, static_cast<GLint>(filter));
    gl::SamplerParameteri(id, GL_TEXTURE_WRAP_S, static_cast<GLint>(wrap));
    gl::SamplerParameteri(id, GL_TEXTURE_WRAP_T, static_cast<GLint>(wrap));
    return id;
}

const fx::CompiledPass* findPass(const fx::CompiledTechnique& technique, const std::string& name) {
    for (const fx::CompiledPass& pass : technique.passes)
        if (pass.name == name) return &pass;
    return nullptr;
}

std::optional<size_t> findParameter(const fx::CompiledEffect& effect, const std::string& name) {
    for (size_t i = 0; i < effect.parameters.size(); ++i)
        if (effect.parameters[i].name == name) return i;
    return std::nullopt;
}

}  // namespace

namespace {

// [SECTION] Uniform ring

void releaseRing(HandWrittenFrame::Pass& pass) {
    for (GLsync& fence : pass.fences) {
        if (fence) gl::DeleteSync(fence);
        fence = nullptr;
    }
    if (!pass.buffer) return;
    gl::BindBuffer(GL_UNIFORM_BUFFER, pass.buffer);
    gl::UnmapBuffer(GL_UNIFORM_BUFFER);
    gl::DeleteBuffers(1, &pass.buffer);
    pass.buffer = 0;
    pass.mapped = nullptr;
}

// Makes each region hold at least `bytes` (with room to grow: reallocated rarely, after a glFinish).
void reserveRing(HandWrittenFrame::Pass& pass, size_t bytes) {
    if (bytes <= pass.regionSize && pass.mapped) return;
    gl::Finish();
    releaseRing(pass);
    pass.regionSize = std::max<size_t>(bytes + bytes / 2, 64 * 1024);
    const GLbitfield flags = GL_MAP_WRITE_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;
    const auto capacity = static_cast<GLsizeiptr>(pass.regionSize * HandWrittenFrame::Pass::kRegions);
    gl::GenBuffers(1, &pass.buffer);
    gl::BindBuffer(GL_UNIFORM_BUFFER, pass.buffer);
    gl::BufferStorage(GL_UNIFORM_BUFFER, capacity, nullptr, flags);
    pass.mapped = static_cast<uint8_t*>(gl::MapBufferRange(GL_UNIFORM_BUFFER, 0, capacity, flags));
    pass.region = 0;
}

}  // namespace

// [SECTION] Set-up

std::unique_ptr<HandWrittenFrame> HandWrittenFrame::create(const fx::CompiledEffect& effect,
                                                           const runtime::Scene& scene, int width, int height,
                                                           std::string& error) {
    std::unique_ptr<HandWrittenFrame> frame(new HandWrittenFrame());
    frame->mWidth = width;
    frame->mHeight = height;
    if (!frame->setUp(effect, scene, error)) return nullptr;
    return frame;
}

bool HandWrittenFrame::setUp(const fx::CompiledEffect& effect, const runtime::Scene& scene,
                             std::string& error) {
    const fx::CompiledTechnique* technique = effect.findTechnique("main");
    const fx::CompiledPass* shadow = technique ? findPass(*technique, "RenderShadowMap") : nullptr;
    const fx::CompiledPass* lit = technique ? findPass(*technique, "RenderScene") : nullptr;
    if (!shadow || !lit || scene.lights.empty()) {
        error = "needs the thesis effect's technique main (RenderShadowMap, RenderScene) and a lit scene";
        return false;
    }
    const auto initial = [&](const std::string& name) -> std::vector<float> {
        const std::optional<size_t> index = findParameter(effect, name);
        return index ? effect.initialValues[*index].data : std::vector<float>{};
    };
    mShadowClear = initial("ShadowClearColor");
    mFrameClear = initial("ClearColor");
    const std::vector<float> clearDepth = initial("ClearDepth");
    const std::vector<float> mapSize = initial("SHADOW_SIZE");
    if (mShadowClear.size() < 4 || mFrameClear.size() < 4 || clearDepth.empty() || mapSize.empty()) {
        error = "the thesis effect's ShadowClearColor, ClearColor, ClearDepth or SHADOW_SIZE is missing";
        return false;
    }
    mClearDepth = clearDepth[0];
    mMapSize = static_cast<int>(mapSize[0]);
    if (shadow->filterReachTexels > 0.0f) mPadTexels = shadow->filterReachTexels;
    GLint alignment = 256;
    gl::GetIntegerv(GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT, &alignment);
    mUniformAlignment = std::max(alignment, 16);

    // Objects and meshes: one set of buffers per distinct mesh, one BVH over the objects' world boxes.
    std::vector<runtime::Aabb> boxes;
    std::vector<bool> present;
    for (const runtime::SceneObject& object : scene.objects) {
        if (!object.mesh || object.mesh->positions.empty()) continue;
        mObjects.push_back(&object);
        boxes.push_back(
            runtime::transformBox({object.mesh->boundsMin(), object.mesh->boundsMax()}, object.world));
        present.push_back(true);
        if (auto known = mMeshIndex.find(object.mesh.get()); known != mMeshIndex.end()) {
            mObjectMesh.push_back(known->second);
            continue;
        }
        mObjectMesh.push_back(mMeshes.size());
        const runtime::Mesh& mesh = *object.mesh;
        MeshBuffers buffers;
        const auto upload = [](GLenum target, const void* data, size_t bytes) {
            uint32_t buffer = 0;
            gl::GenBuffers(1, &buffer);
            gl::BindBuffer(target, buffer);
            gl::BufferData(target, static_cast<GLsizeiptr>(bytes), data, GL_STATIC_DRAW);
            return buffer;
        };
        const size_t n = mesh.positions.size();
        buffers.positions = upload(GL_ARRAY_BUFFER, mesh.positions.data(), n * sizeof(glm::vec3));
        if (mesh.normals.size() == n)
            buffers.normals = upload(GL_ARRAY_BUFFER, mesh.normals.data(), n * sizeof(glm::vec3));
        if (mesh.texcoords.size() == n)
            buffers.texcoords = upload(GL_ARRAY_BUFFER, mesh.texcoords.data(), n * sizeof(glm::vec2));
        buffers.indices = upload(GL_ELEMENT_ARRAY_BUFFER, mesh.indices.data(), mesh.indices.size() * 4);
        buffers.indexCount = static_cast<int>(mesh.indices.size());
        mMeshIndex.emplace(object.mesh.get(), mMeshes.size());
        mMeshes.push_back(buffers);
    }
    mBvh = runtime::InstanceBvh(std::move(boxes), present);
    mBounds = scene.bounds();

    // Passes: the compiled GLSL, block layouts from reflection, a VAO per mesh for the pass's inputs.
    const auto makePass = [&](const fx::CompiledPass& compiled, bool isShadow) -> std::unique_ptr<Pass> {
        auto pass = std::make_unique<Pass>();
        pass->program = link(compiled, error);
        if (!pass->program) return nullptr;
        for (const fx::StageProgram* stage : {&compiled.vertex, &compiled.fragment}) {
            for (const fx::SamplerBinding& binding : stage->samplers) {
                const std::string& name = effect.parameters[binding.samplerParameter].name;
                if (name != "ShadowMapSampler" && name != "NoiseSampler") {
                    error =
                        "pass " + compiled.name + " samples " + name + ", which the baseline does not bind";
                    return nullptr;
                }
                pass->samplers.emplace_back(binding.unit, name == "ShadowMapSampler");
            }
            if (stage->uniformBlockName.empty()) continue;
            Block block;
            block.binding = stage->uniformBlockBinding;
            block.size = stage->uniformBlockSize;
            block.base.assign(block.size, 0);
            for (const fx::UniformBinding& binding : stage->uniforms) {
                if (!binding.active) continue;
                Member member{Source::Constant, binding.offset, binding.matrixStride,
                              binding.hlslColumnsContiguous};
                if (binding.source == fx::UniformBinding::Source::CompileArgument) {
                    if (binding.index != 0) {
                        error =
                            "pass " + compiled.name + " has more compile arguments than the baseline knows";
                        return nullptr;
                    }
                    member.source = isShadow ? Source::WorldLightViewProjection : Source::LightViewProjection;
                } else if (const std::optional<Source> source =
                               parameterSource(effect.parameters[binding.index].name)) {
                    member.source = *source;
                } else if (!effect.parameters[binding.index].semantic.empty() ||
                           !writeConstant(block.base, binding, effect.initialValues[binding.index])) {
                    error =
                        "the baseline does not know what " + effect.parameters[binding.index].name + " holds";
                    return nullptr;
                }
                if (member.source == Source::Constant) continue;
                (perObject(member.source) ? block.perDraw : block.perFrame).push_back(member);
            }
            pass->blocks.push_back(std::move(block));
        }
        for (const MeshBuffers& mesh : mMeshes) {
            uint32_t vao = 0;
            gl::GenVertexArrays(1, &vao);
            gl::BindVertexArray(vao);
            for (const fx::VertexInput& input : compiled.vertex.inputs) {
                uint32_t buffer = 0;
                int components = 3;
                glm::vec4 fallback(0.0f);
                using fx::VertexStream;
                if (input.stream.stream == VertexStream::Position) {
                    buffer = mesh.positions;
                    fallback = glm::vec4(0, 0, 0, 1);
                } else if (input.stream.stream == VertexStream::Normal) {
                    buffer = mesh.normals;
                    fallback = glm::vec4(0, 1, 0, 0);
                } else if (input.stream.stream == VertexStream::Texcoord && input.stream.index == 0) {
                    buffer = mesh.texcoords;
                    components = 2;
                } else {
                    error = "pass " + compiled.name + " reads " + input.semantic +
                            ", which the baseline does not feed";
                    return nullptr;
                }
                if (buffer == 0) {
                    pass->defaults.emplace_back(input.location, fallback);
                    continue;
                }
                gl::BindBuffer(GL_ARRAY_BUFFER, buffer);
                gl::EnableVertexAttribArray(static_cast<GLuint>(input.location));
                gl::VertexAttribPointer(static_cast<GLuint>(input.location), components, GL_FLOAT, GL_FALSE,
                                        0, nullptr);
            }
            gl::BindBuffer(GL_ELEMENT_ARRAY_BUFFER, mesh.indices);
            pass->vaos.push_back(vao);
        }
        gl::BindVertexArray(0);
        return pass;
    };
    mShadowPass = makePass(*shadow, true);
    if (!mShadowPass) return false;
    mScenePass = makePass(*lit, false);
    if (!mScenePass) return false;

    // Targets: the R32F map; the frame's RGBA8 colour and D24S8 depth (as the runtime's frame targets).
    mShadowMap = texture2D(GL_R32F, mMapSize, mMapSize);
    mFrameColor = texture2D(GL_RGBA8, mWidth, mHeight);
    mFrameDepth = texture2D(GL_DEPTH24_STENCIL8, mWidth, mHeight);
    mNoise = texture2D(GL_RGBA8, 1, 1);  // JITTER is off: the lookup's result is never used
    gl::GenFramebuffers(1, &mShadowFbo);
    gl::BindFramebuffer(GL_FRAMEBUFFER, mShadowFbo);
    gl::FramebufferTexture(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, mShadowMap, 0);
    const bool shadowComplete = gl::CheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
    gl::GenFramebuffers(1, &mFrameFbo);
    gl::BindFramebuffer(GL_FRAMEBUFFER, mFrameFbo);
    gl::FramebufferTexture(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, mFrameColor, 0);
    gl::FramebufferTexture(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, mFrameDepth, 0);
    const bool frameComplete = gl::CheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
    gl::BindFramebuffer(GL_FRAMEBUFFER, 0);
    if (!shadowComplete || !frameComplete) {
        error = "incomplete framebuffer";
        return false;
    }
    mPointClamp = sampler(GL_NEAREST, GL_CLAMP_TO_EDGE);
    mLinearWrap = sampler(GL_LINEAR, GL_REPEAT);
    return gl::GetError() == GL_NO_ERROR || (error = "GL error during set-up", false);
}

HandWrittenFrame::~HandWrittenFrame() {
    for (Pass* pass : {mShadowPass.get(), mScenePass.get()}) {
        if (!pass) continue;
        gl::DeleteProgram(pass->program);
        gl::DeleteVertexArrays(static_cast<GLsizei>(pass->vaos.size()), pass->vaos.data());
        releaseRing(*pass);
    }
    for (const MeshBuffers& mesh : mMeshes) {
        const uint32_t buffers[] = {mesh.positions, mesh.normals, mesh.texcoords, mesh.indices};
        gl::DeleteBuffers(4, buffers);
    }
    const uint32_t textures[] = {mShadowMap, mFrameColor, mFrameDepth, mNoise};
    gl::DeleteTextures(4, textures);
    const uint32_t framebuffers[] = {mShadowFbo, mFrameFbo};
    gl::DeleteFramebuffers(2, framebuffers);
    const uint32_t samplers[] = {mPointClamp, mLinearWrap};
    gl::DeleteSamplers(2, samplers);
}

// [SECTION] Frame

void HandWrittenFrame::render(const runtime::Scene& scene) {
    const runtime::Light& light = scene.lights[0];
    const float aspect = static_cast<float>(mWidth) / static_cast<float>(mHeight);
    FrameValues frame;
    frame.view = scene.camera.view();
    frame.projection = scene.camera.projection(aspect);
    frame.viewInverse = glm::inverse(frame.view);
    const runtime::LightFit fit =
        runtime::fitLight(runtime::LightParameterization::Uniform, scene, mBounds, aspect, light);
    frame.lightView = fit.view;
    frame.lightProjection = fit.projection;
    frame.lightViewProjection = fit.projection * fit.view;
    frame.lightColor = light.color;
    frame.ambient = scene.ambient;

    // Culled lists: the camera's frustum, and the casters whose shadow can reach what the camera sees.
    const glm::mat4 cameraViewProjection = frame.projection * frame.view;
    const runtime::Aabb& root = mBvh.rootBox();
    runtime::ReceiverRegion region = runtime::receiverRegion(
        runtime::intersectionBodyPoints(cameraViewProjection, {root.min, root.max}),
        frame.lightViewProjection, glm::vec2(static_cast<float>(mMapSize)), mPadTexels);
    region.castersBehindLightPlaneCastNothing = fit.shinesIntoPositiveW;
    mCasters.clear();
    mBvh.query(
        [&](const runtime::Aabb& box) {
            return runtime::casterReaches(region, frame.lightViewProjection, box);
        },
        mCasters);
    const runtime::ConvexVolume frustum = runtime::frustumPlanes(cameraViewProjection);
    mVisible.clear();
    mBvh.query([&](const runtime::Aabb& box) { return runtime::overlapVolume(frustum, box); }, mVisible);

    for (Pass* pass : {mShadowPass.get(), mScenePass.get()})
        for (Block& block : pass->blocks)
            for (const Member& member : block.perFrame) writeFrameMember(block.base.data(), member, frame);

    // ClearShadowMap and RenderShadowMap: no depth buffer, BlendOp=min keeps the nearest occluder.
    gl::BindFramebuffer(GL_FRAMEBUFFER, mShadowFbo);
    gl::Viewport(0, 0, mMapSize, mMapSize);
    gl::ClearColor(mShadowClear[0], mShadowClear[1], mShadowClear[2], mShadowClear[3]);
    gl::Clear(GL_COLOR_BUFFER_BIT);
    gl::Disable(GL_DEPTH_TEST);
    gl::DepthMask(GL_FALSE);
    gl::Disable(GL_CULL_FACE);
    gl::Enable(GL_BLEND);
    gl::BlendFunc(GL_ONE, GL_ONE);
    gl::BlendEquation(GL_MIN);
    drawPass(*mShadowPass, mCasters, frame);
    mShadowDraws = static_cast<int>(mCasters.size());

    // RenderScene: clear, depth test, back faces (D3D's counter-clockwise ones) culled.
    gl::BindFramebuffer(GL_FRAMEBUFFER, mFrameFbo);
    gl::Viewport(0, 0, mWidth, mHeight);
    gl::ClearColor(mFrameClear[0], mFrameClear[1], mFrameClear[2], mFrameClear[3]);
    gl::ClearDepth(mClearDepth);
    gl::DepthMask(GL_TRUE);
    gl::Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl::Disable(GL_BLEND);
    gl::BlendEquation(GL_FUNC_ADD);
    gl::Enable(GL_DEPTH_TEST);
    gl::DepthFunc(GL_LEQUAL);
    gl::Enable(GL_CULL_FACE);
    gl::FrontFace(GL_CW);
    gl::CullFace(GL_BACK);
    drawPass(*mScenePass, mVisible, frame);
    mSceneDraws = static_cast<int>(mVisible.size());
    gl::BindVertexArray(0);
}

// Every draw's blocks are written into this frame's region of the pass's ring; each draw binds its ranges.
void HandWrittenFrame::drawPass(Pass& pass, const std::vector<uint32_t>& objects, const FrameValues& frame) {
    std::vector<size_t> stride(pass.blocks.size()), start(pass.blocks.size());
    size_t total = 0;
    for (size_t b = 0; b < pass.blocks.size(); ++b) {
        const size_t align = static_cast<size_t>(mUniformAlignment);
        stride[b] = (pass.blocks[b].size + align - 1) / align * align;
        start[b] = total;
        total += stride[b] * objects.size();
    }
    reserveRing(pass, total);
    GLsync& fence = pass.fences[static_cast<size_t>(pass.region)];
    if (fence) {
        while (gl::ClientWaitSync(fence, GL_SYNC_FLUSH_COMMANDS_BIT, 1'000'000'000) == GL_TIMEOUT_EXPIRED) {
        }
        gl::DeleteSync(fence);
        fence = nullptr;
    }
    const size_t base = static_cast<size_t>(pass.region) * pass.regionSize;
    for (size_t i = 0; i < objects.size(); ++i) {
        const runtime::SceneObject& object = *mObjects[objects[i]];
        for (size_t b = 0; b < pass.blocks.size(); ++b) {
            const Block& block = pass.blocks[b];
            uint8_t* data = pass.mapped + base + start[b] + i * stride[b];
            std::memcpy(data, block.base.data(), block.size);
            for (const Member& member : block.perDraw) writeObjectMember(data, member, frame, object);
        }
    }
    gl::UseProgram(pass.program);
    for (const auto& [unit, isShadowMap] : pass.samplers) {
        gl::ActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
        gl::BindTexture(GL_TEXTURE_2D, isShadowMap ? mShadowMap : mNoise);
        gl::BindSampler(static_cast<GLuint>(unit), isShadowMap ? mPointClamp : mLinearWrap);
    }
    for (const auto& [location, value] : pass.defaults)
        gl::VertexAttrib4fv(static_cast<GLuint>(location), &value.x);
    for (size_t i = 0; i < objects.size(); ++i) {
        for (size_t b = 0; b < pass.blocks.size(); ++b)
            gl::BindBufferRange(GL_UNIFORM_BUFFER, static_cast<GLuint>(pass.blocks[b].binding), pass.buffer,
                                static_cast<GLintptr>(base + start[b] + i * stride[b]), pass.blocks[b].size);
        const size_t mesh = mObjectMesh[objects[i]];
        gl::BindVertexArray(pass.vaos[mesh]);
        gl::DrawElements(GL_TRIANGLES, mMeshes[mesh].indexCount, GL_UNSIGNED_INT, nullptr);
    }
    fence = gl::FenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
    pass.region = (pass.region + 1) % Pass::kRegions;
}

runtime::FrameImage HandWrittenFrame::readFrame() const {
    runtime::FrameImage image;
    image.width = mWidth;
    image.height = mHeight;
    image.rgba.resize(static_cast<size_t>(mWidth) * static_cast<size_t>(mHeight) * 4);
    gl::BindFramebuffer(GL_READ_FRAMEBUFFER, mFrameFbo);
    gl::ReadBuffer(GL_COLOR_ATTACHMENT0);
    gl::PixelStorei(GL_PACK_ALIGNMENT, 1);
    gl::ReadPixels(0, 0, mWidth, mHeight, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
    gl::BindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    return image;
}

}  // namespace shadowfx::baseline
