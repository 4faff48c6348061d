// Compiler: which samplers of a full-screen pass read the host's picture of the scene
// (SamplerBinding::hostPicture).
//
// A D3D9 pass with a pixel shader alone (FixedFunctionPass.cpp's screen quad), or one whose vertex shader
// hands the position through unchanged (PositionPassThrough.h), was a post-processing pass:
// its application rendered the scene into a texture of its own and bound that texture to the shader's
// sampler before drawing the quad over the whole target (the DirectX SDK's post-process samples), or, for
// a pixel shader handed to XNA's and MonoGame's SpriteBatch, the sprite's texture to register s0. The
// effect itself gives such a sampler nothing: no file, no render target, no texture function. Drawn on
// its own, the pass samples the runtime's neutral white and the frame is one colour; drawn by the host,
// the sampler reads the host's picture of the scene, as its application's would have. A view of a
// read-write texture (`string ViewOf`) has contents: what the effect's compute passes write.
#include "Compiler.h"

#include <set>

namespace fx::detail {

void Compiler::hostPictureSamplers() {
    std::set<size_t> noted;  // each sampler or pair's texture once, at its first full-screen pass
    for (const PassSlot& slot : mScreenQuadPasses) {
        if (slot.technique >= mOut->techniques.size() ||
            slot.pass >= mOut->techniques[slot.technique].passes.size())
            continue;
        CompiledPass& pass = mOut->techniques[slot.technique].passes[slot.pass];
        for (SamplerBinding& binding : pass.fragment.samplers) {
            if (!binding.read || binding.depthCompare || binding.samplerParameter == kNoSampler) continue;
            // The picture is a 2D texture: a cube or volume sampler keeps its neutral texture.
            const BaseType samplerType = mOut->parameters[binding.samplerParameter].type.base;
            if (binding.pairTexture.empty() && samplerType != BaseType::Sampler &&
                samplerType != BaseType::Sampler2D)
                continue;
            const SamplerDesc* sampler = mOut->findSampler(binding.samplerParameter);
            const std::optional<size_t> texture = binding.textureParameter ? binding.textureParameter
                                                  : sampler                ? sampler->texture
                                                                           : std::nullopt;
            if (!texture) {
                // A bare sampler (`sampler2D s : register(s0);`), or one whose block names no texture.
                binding.hostPicture = true;
                continue;
            }
            const TextureDesc* desc = mOut->findTexture(*texture);
            binding.hostPicture = desc && desc->kind == TextureDesc::Kind::Runtime &&
                                  desc->type == BaseType::Texture2D && !mOut->parameters[*texture].viewOf;
        }
        // A D3D10 pair is named by its texture: one SamplerState may sample several textures.
        for (const SamplerBinding& binding : pass.fragment.samplers) {
            if (!binding.hostPicture) continue;
            const ParameterInfo& sampler = mOut->parameters[binding.samplerParameter];
            if (binding.pairTexture.empty() || !binding.textureParameter) {
                if (noted.insert(binding.samplerParameter).second)
                    mDiagnostics.report(DiagId::SamplerReadsHostPicture, sampler.loc,
                                        {sampler.name, pass.name});
            } else if (noted.insert(*binding.textureParameter).second) {
                const ParameterInfo& texture = mOut->parameters[*binding.textureParameter];
                mDiagnostics.report(DiagId::TextureReadsHostPicture, texture.loc,
                                    {texture.name, sampler.name, pass.name});
            }
        }
    }
}

}  // namespace fx::detail
