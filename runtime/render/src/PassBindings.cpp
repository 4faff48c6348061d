// PassBindings: see PassBindings.h.
#include "PassBindings.h"

#include <runtime/GlApi.h>

#include <algorithm>
#include <array>

namespace runtime {

namespace {

// The texture parameter a sampler binding samples: a D3D10 pair's own texture (sampled through the
// sampler's states), else the sampler's; none for a bare sampler.
std::optional<size_t> sampledTexture(const EffectResources& resources, const fx::SamplerBinding& binding) {
    if (binding.textureParameter) return binding.textureParameter;
    const fx::SamplerDesc* desc = resources.effect().findSampler(binding.samplerParameter);
    return desc ? desc->texture : std::nullopt;
}

void bindStageTextures(EffectResources& resources, const fx::StageProgram& stage,
                       const RenderTargets& drawing, const GpuTexture* hostPicture) {
    for (const fx::SamplerBinding& binding : stage.samplers) {
        const std::optional<size_t> textureParameter = sampledTexture(resources, binding);
        gl::ActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(binding.unit));
        // A bare sampler's texture is the application's under the sampler's own index (EffectVariable).
        const size_t given = textureParameter.value_or(binding.samplerParameter);
        if (binding.hostPicture && hostPicture && !resources.textures->givenByApplication(given)) {
            gl::BindTexture(hostPicture->target(), hostPicture->id());
            resources.samplers.bind(binding);
            continue;
        }
        const EffectTextures::ApplicationTexture* application = resources.textures->applicationTexture(given);
        const GpuTexture* texture = nullptr;
        if (textureParameter) {
            // A view of a read-write texture (`string ViewOf`) samples the image's texture.
            texture = resources.storage->image(resources.storage->viewedResource(*textureParameter));
            if (!texture) texture = resources.textures->find(*textureParameter);
        }
        const bool rendering = std::any_of(drawing.colors.begin(), drawing.colors.end(),
                                           [texture](const auto& color) { return color.texture == texture; });
        // Not while the pass renders into it (the chain would be built before the draw that changes it).
        if (texture && !rendering) resources.textures->refreshMipChain(*texture);
        const GpuBuffer* buffer =
            textureParameter ? resources.storage->buffer(resources.storage->viewedResource(*textureParameter))
                             : nullptr;
        if (application) {
            gl::BindTexture(application->target, application->name);
        } else if (texture) {
            gl::BindTexture(texture->target(), texture->id());
        } else if (buffer && buffer->texture()) {
            gl::BindTexture(GL_TEXTURE_BUFFER, buffer->texture());  // Buffer<T>
        } else if (!textureParameter && !binding.depthCompare) {
            // A sampler that no texture is given to: what its application would have bound, white.
            const GpuTexture& neutral = resources.textures->neutralFor(
                resources.effect().parameters[binding.samplerParameter].type.base);
            gl::BindTexture(neutral.target(), neutral.id());
        } else {
            gl::BindTexture(GL_TEXTURE_2D, 0);
        }
        resources.samplers.bind(binding);
    }
}

std::array<const fx::StageProgram*, 6> stagesOf(const fx::CompiledPass& pass) {
    return {&pass.vertex, &pass.hull, &pass.domain, &pass.geometry, &pass.fragment, &pass.compute};
}

// Every stage's sampled textures (the host's picture for the samplers that read it where the application
// gave them nothing, else an application's GL texture where it set one, else the effect's texture or
// Buffer<T>, else none) and sampler objects. A mipmapped render target written since its chain was
// built gets its chain first, unless `drawing` renders into it.
void bindPassTextures(EffectResources& resources, const fx::CompiledPass& pass, const RenderTargets& drawing,
                      const GpuTexture* hostPicture) {
    for (const fx::StageProgram* stage : stagesOf(pass))
        bindStageTextures(resources, *stage, drawing, hostPicture);
}

// The buffers behind the pass's StructuredBuffer and ByteAddressBuffer blocks, and the counters of its
// append, consume and counted buffers, at the binding points their blocks are declared at.
void bindPassStorageBuffers(EffectResources& resources, const fx::CompiledPass& pass) {
    for (const fx::StageProgram* stage : stagesOf(pass))
        for (const fx::StorageBufferBinding& b : stage->storageBuffers) {
            const size_t resource = resources.storage->viewedResource(b.parameter);
            if (const GpuBuffer* buffer = resources.storage->buffer(resource))
                gl::BindBufferBase(GL_SHADER_STORAGE_BUFFER, static_cast<GLuint>(b.binding), buffer->id());
            const GpuBuffer* counter = b.counterBinding >= 0 ? resources.storage->counter(resource) : nullptr;
            if (counter)
                gl::BindBufferBase(GL_SHADER_STORAGE_BUFFER, static_cast<GLuint>(b.counterBinding),
                                   counter->id());
        }
}

// The textures behind the pass's images (RWTexture1D/2D/3D/2DArray, all layers) and the buffer textures
// behind its RWBuffers on their image units (fx::ImageBinding::unit, declared in the GLSL), read-write.
void bindPassImages(EffectResources& resources, const fx::CompiledPass& pass) {
    for (const fx::StageProgram* stage : stagesOf(pass))
        for (const fx::ImageBinding& binding : stage->images) {
            const GpuTexture* image = resources.storage->image(binding.parameter);
            const GpuBuffer* buffer = resources.storage->buffer(binding.parameter);
            const auto unit = static_cast<GLuint>(binding.unit);
            if (image) {
                // A 3D texture's slices and an array's elements are all the image's (image3D,
                // image2DArray).
                const GLenum target = image->target();
                const GLboolean layered = target == GL_TEXTURE_3D || target == GL_TEXTURE_2D_ARRAY;
                gl::BindImageTexture(unit, image->id(), 0, layered, 0, GL_READ_WRITE,
                                     image->glFormat().internalFormat);
            } else if (buffer && buffer->texture()) {  // RWBuffer<T>
                gl::BindImageTexture(unit, buffer->texture(), 0, GL_FALSE, 0, GL_READ_WRITE,
                                     buffer->texelFormat());
            }
        }
}

}  // namespace

bool bindPassTargets(EffectResources& resources, const RenderTargets& targets, FramebufferFault& fault) {
    return resources.textures->bindTargets(targets, fault);
}

bool bindPass(EffectResources& resources, size_t technique, size_t pass, const PassBinding& binding,
              fx::DiagnosticSink& diagnostics, FramebufferFault& fault) {
    const fx::CompiledPass& compiled = resources.effect().techniques[technique].passes[pass];
    GpuProgram* program = binding.program ? binding.program : resources.programs->program(technique, pass);
    const RenderTargets none;
    const RenderTargets& drawing = binding.framebuffer ? *binding.framebuffer : none;
    // A compute program (a compute pass's, or the dispatch of a pass that also draws) binds no target and
    // no state; the graphics program of a pass that also dispatches binds both.
    if (!program || !program->isCompute()) {
        if (binding.framebuffer && !bindPassTargets(resources, drawing, fault)) return false;
        if (binding.viewport)
            gl::Viewport(binding.viewport->x, binding.viewport->y, binding.viewport->z, binding.viewport->w);
        applyRenderStates(binding.states
                              ? *binding.states
                              : resources.programs->preshaders(technique, pass)
                                    .states(resources.values.all(), resources.values.stamps(), diagnostics),
                          binding.depthBits);
    }
    if (!program || !program->hasShaders()) return true;
    bindPassTextures(resources, compiled, drawing, binding.hostPicture);
    bindPassStorageBuffers(resources, compiled);
    bindPassImages(resources, compiled);
    program->bind();
    return true;
}

void evaluatePassArguments(EffectResources& resources, size_t technique, size_t pass,
                           const std::vector<bool>* which, std::vector<fx::Value>& arguments,
                           fx::DiagnosticSink& diagnostics) {
    resources.programs->preshaders(technique, pass)
        .arguments(resources.values.all(), resources.values.stamps(), which, arguments, diagnostics);
}

void uploadPassValues(EffectResources& resources, GpuProgram& program,
                      const std::vector<fx::Value>& arguments) {
    program.upload(resources.values.all(), arguments, *resources.uniformRing);
}

void commitPassValues(EffectResources& resources, size_t technique, size_t pass,
                      std::vector<fx::Value>& arguments, fx::DiagnosticSink& diagnostics) {
    GpuProgram* program = resources.programs->program(technique, pass);
    if (!program || !program->hasShaders()) return;
    evaluatePassArguments(resources, technique, pass, nullptr, arguments, diagnostics);
    uploadPassValues(resources, *program, arguments);
}

bool readsHostPicture(const EffectResources& resources, const fx::CompiledPass& pass) {
    for (const fx::SamplerBinding& binding : pass.fragment.samplers) {
        if (!binding.hostPicture) continue;
        const std::optional<size_t> texture = sampledTexture(resources, binding);
        // A bare sampler's texture is the application's under the sampler's own index (EffectVariable).
        if (!resources.textures->givenByApplication(texture.value_or(binding.samplerParameter))) return true;
    }
    return false;
}

int depthBiasBits(const GpuTexture* texture) {
    return texture ? std::clamp(texture->glFormat().depthBits, 16, 24) : 24;
}

GlStateMask passStateMask(const fx::CompiledPass& pass) {
    GlStateMask mask;
    mask.renderStates = true;  // every state, set or not (RenderStateApplier.h)
    if (pass.vertex.glsl.empty() && pass.compute.glsl.empty()) return mask;
    mask.program = true;
    for (const fx::StageProgram* stage : stagesOf(pass)) {
        GlStateMask stageMask;
        for (const fx::SamplerBinding& binding : stage->samplers)
            stageMask.textureUnits.push_back(binding.unit);
        if (stage->uniformBlockSize > 0 && stage->uniformBlockBinding >= 0)
            stageMask.uniformBuffers.push_back(stage->uniformBlockBinding);
        mask.add(stageMask);
    }
    GlStateMask storage;
    for (const fx::StageProgram* stage : stagesOf(pass))
        for (const fx::StorageBufferBinding& b : stage->storageBuffers) {
            storage.storageBuffers.push_back(b.binding);
            if (b.counterBinding >= 0) storage.storageBuffers.push_back(b.counterBinding);
        }
    mask.add(storage);
    return mask;
}

}  // namespace runtime
