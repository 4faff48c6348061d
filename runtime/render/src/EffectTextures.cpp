// EffectTextures: see EffectTextures.h.
#include "EffectTextures.h"
#include "TextureFunctionFill.h"

#include <private/runtime/FramePlan.h>
#include <private/runtime/ProceduralTexture.h>
#include <runtime/Image.h>
#include <runtime/TextureFile.h>

#include <algorithm>
#include <cmath>

namespace runtime {

namespace {

// A deterministic noise texture for the `noise` semantic (the thesis's jitter lookups): RGBA uniform in
// [0, 1], from a fixed-seed LCG so every run renders the same image.
GpuTexture makeNoiseTexture() {
    constexpr int kSize = 64;
    std::vector<uint8_t> pixels(kSize * kSize * 4);
    uint32_t state = 0x2545F491u;
    for (uint8_t& p : pixels) {
        state = state * 1664525u + 1013904223u;
        p = static_cast<uint8_t>(state >> 24);
    }
    GpuTexture texture = GpuTexture::create2D(fx::TextureFormat::RGBA8, kSize, kSize);
    texture.uploadRGBA8(pixels.data());
    return texture;
}

bool isArrayType(fx::BaseType type) {
    return type == fx::BaseType::Texture1DArray || type == fx::BaseType::Texture2DArray ||
           type == fx::BaseType::TextureCubeArray;
}

// An array texture of a D3D10 array type: `elements` elements (cubes for a TextureCubeArray).
GpuTexture makeArrayTexture(fx::BaseType type, fx::TextureFormat format, int width, int height, int elements,
                            int mipLevels) {
    if (type == fx::BaseType::Texture1DArray)
        return GpuTexture::create1DArray(format, width, elements, mipLevels);
    if (type == fx::BaseType::TextureCubeArray)
        return GpuTexture::createCubeArray(format, width, elements, mipLevels);
    return GpuTexture::create2DArray(format, width, height, elements, mipLevels);
}

// A multisample texture's sample count: the effect's, or the most this GL's textures of its kind hold (an
// effect written for 8 samples runs with 4 where the driver offers 4; loading warns).
int supportedSamples(const fx::TextureDesc& desc) {
    GLint most = 0;
    gl::GetIntegerv(isDepthFormat(desc.format) ? GL_MAX_DEPTH_TEXTURE_SAMPLES : GL_MAX_COLOR_TEXTURE_SAMPLES,
                    &most);
    return std::max(1, std::min(desc.samples, int(most)));
}

// White: the neutral value for textures the effect multiplies with. A texture array gets its ArraySize
// elements of it, so that GetDimensions reports what the effect declared.
GpuTexture makeNeutralTexture(fx::BaseType type, int elements = 1, int samples = 1) {
    const uint8_t white[4] = {255, 255, 255, 255};
    if (type == fx::BaseType::Texture2DMS || type == fx::BaseType::Texture2DMSArray) {
        GpuTexture texture =
            GpuTexture::createMultisample(fx::TextureFormat::RGBA8, 1, 1, samples,
                                          type == fx::BaseType::Texture2DMSArray ? std::max(elements, 1) : 0);
        gl::ClearTexImage(texture.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, white);
        return texture;
    }
    if (isArrayType(type)) {
        const float one[4] = {1.0f, 1.0f, 1.0f, 1.0f};
        GpuTexture texture = makeArrayTexture(type, fx::TextureFormat::RGBA8, 1, 1, elements, 1);
        for (int layer = 0; layer < texture.layers(); ++layer) texture.uploadLayerRGBA32F(one, 0, layer);
        return texture;
    }
    if (type == fx::BaseType::Texture1D) {
        GpuTexture texture = GpuTexture::create1D(fx::TextureFormat::RGBA8, 1);
        gl::ClearTexImage(texture.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, white);
        return texture;
    }
    if (type == fx::BaseType::Texture3D) {
        const float one[4] = {1.0f, 1.0f, 1.0f, 1.0f};
        GpuTexture texture = GpuTexture::create3D(fx::TextureFormat::RGBA8, 1, 1, 1);
        texture.uploadVolumeRGBA32F(one);
        return texture;
    }
    if (type == fx::BaseType::TextureCube) {
        GpuTexture texture = GpuTexture::createCube(fx::TextureFormat::RGBA8, 1);
        for (int face = 0; face < 6; ++face) texture.uploadRGBA8(white, 0, face);
        return texture;
    }
    GpuTexture texture = GpuTexture::create2D(fx::TextureFormat::RGBA8, 1, 1);
    texture.uploadRGBA8(white);
    return texture;
}

// A render target of the effect's type, `w` x `h` (a cube's faces `w` square). The layered ones (cubes,
// arrays, volumes) are bound whole (RenderTargetAttachment::wholeOf).
GpuTexture makeRenderTarget(const fx::TextureDesc& desc, int w, int h) {
    switch (desc.type) {
        case fx::BaseType::TextureCube:
            return GpuTexture::createCube(desc.format, w, desc.mipLevels);
        case fx::BaseType::Texture3D:
            return GpuTexture::create3D(desc.format, w, h, desc.depth, desc.mipLevels);
        case fx::BaseType::Texture1DArray:
        case fx::BaseType::Texture2DArray:
        case fx::BaseType::TextureCubeArray:
            return makeArrayTexture(desc.type, desc.format, w, h, desc.arraySize, desc.mipLevels);
        case fx::BaseType::Texture2DMS:
            return GpuTexture::createMultisample(desc.format, w, h, supportedSamples(desc));
        case fx::BaseType::Texture2DMSArray:
            return GpuTexture::createMultisample(desc.format, w, h, supportedSamples(desc),
                                                 std::max(desc.arraySize, 1));
        default:
            return GpuTexture::create2D(desc.format, w, h, desc.mipLevels);
    }
}

std::string textureFileKindName(const TextureFile& file) {
    const std::string kind = file.kind == TextureFile::Kind::Cube     ? "cube"
                             : file.kind == TextureFile::Kind::Volume ? "volume"
                                                                      : "2D";
    return file.elements > 1 ? kind + " array (" + std::to_string(file.elements) + " elements)" : kind;
}

std::string textureTypeName(fx::BaseType type) {
    switch (type) {
        case fx::BaseType::TextureCube:
            return "cube";
        case fx::BaseType::Texture3D:
            return "volume";
        case fx::BaseType::Texture1DArray:
            return "1D array";
        case fx::BaseType::Texture2DArray:
            return "2D array";
        case fx::BaseType::TextureCubeArray:
            return "cube array";
        default:
            return "2D";
    }
}

// A texture array from a file's levels (each level every layer in turn).
GpuTexture makeFileArray(const TextureFile& file, const fx::TextureDesc& desc) {
    const size_t faces = file.kind == TextureFile::Kind::Cube ? 6 : 1;
    const size_t layers = faces * static_cast<size_t>(file.elements);
    int levels = 0;
    for (const std::vector<float>& level : file.levels) {
        const size_t w = static_cast<size_t>(std::max(file.width >> levels, 1));
        const size_t h = static_cast<size_t>(std::max(file.height >> levels, 1));
        if (level.size() != w * h * layers * 4) break;
        ++levels;
    }
    const bool regenerate = levels == 1 && desc.mipLevels != 1;
    GpuTexture texture = makeArrayTexture(desc.type, fx::TextureFormat::RGBA16F, file.width, file.height,
                                          file.elements, regenerate ? 0 : levels);
    for (int level = 0; level < levels; ++level) {
        const size_t layerFloats = static_cast<size_t>(std::max(file.width >> level, 1)) *
                                   static_cast<size_t>(std::max(file.height >> level, 1)) * 4;
        for (size_t layer = 0; layer < layers; ++layer)
            texture.uploadLayerRGBA32F(file.levels[static_cast<size_t>(level)].data() + layer * layerFloats,
                                       level, static_cast<int>(layer));
    }
    if (regenerate) texture.generateMipmaps();
    return texture;
}

// A DDS file's texture, when its kind is what the effect samples: every level the file has, float storage
// so that no file format loses range. nullopt on a mismatch.
std::optional<GpuTexture> makeFileTexture(const TextureFile& file, const fx::TextureDesc& desc) {
    // A Texture2DArray takes any 2D file (one element or more), a Texture1DArray one a texel high, a
    // TextureCubeArray any cube file; a plain texture takes no array.
    if (isArrayType(desc.type)) {
        const bool fits = desc.type == fx::BaseType::TextureCubeArray
                              ? file.kind == TextureFile::Kind::Cube
                              : file.kind == TextureFile::Kind::Flat &&
                                    (desc.type == fx::BaseType::Texture2DArray || file.height == 1);
        if (!fits || file.levels.empty()) return std::nullopt;
        return makeFileArray(file, desc);
    }
    if (file.elements > 1) return std::nullopt;
    const bool wantCube = desc.type == fx::BaseType::TextureCube;
    const bool wantVolume = desc.type == fx::BaseType::Texture3D;
    if (wantCube != (file.kind == TextureFile::Kind::Cube) ||
        wantVolume != (file.kind == TextureFile::Kind::Volume))
        return std::nullopt;
    // Only levels of the size the chain expects (a truncated file keeps what it has).
    int levels = 0;
    for (const std::vector<float>& level : file.levels) {
        const size_t w = static_cast<size_t>(std::max(file.width >> levels, 1));
        const size_t h = static_cast<size_t>(std::max(file.height >> levels, 1));
        const size_t d = static_cast<size_t>(std::max(file.depth >> levels, 1));
        const size_t faces = file.kind == TextureFile::Kind::Cube ? 6 : 1;
        if (level.size() != w * h * d * faces * 4) break;
        ++levels;
    }
    const bool regenerate = levels == 1 && desc.mipLevels != 1;
    const int storageLevels = regenerate ? 0 : levels;
    const fx::TextureFormat format = fx::TextureFormat::RGBA16F;
    if (file.kind == TextureFile::Kind::Cube) {
        GpuTexture texture = GpuTexture::createCube(format, file.width, storageLevels);
        for (int level = 0; level < levels; ++level) {
            const size_t face = static_cast<size_t>(std::max(file.width >> level, 1)) *
                                static_cast<size_t>(std::max(file.height >> level, 1)) * 4;
            for (int f = 0; f < 6; ++f)
                texture.uploadRGBA32F(
                    file.levels[static_cast<size_t>(level)].data() + face * static_cast<size_t>(f), level, f);
        }
        if (regenerate) texture.generateMipmaps();
        return texture;
    }
    if (file.kind == TextureFile::Kind::Volume) {
        GpuTexture texture = GpuTexture::create3D(format, file.width, file.height, file.depth, storageLevels);
        for (int level = 0; level < levels; ++level)
            texture.uploadVolumeRGBA32F(file.levels[static_cast<size_t>(level)].data(), level);
        if (regenerate) texture.generateMipmaps();
        return texture;
    }
    GpuTexture texture = GpuTexture::create2D(format, file.width, file.height, storageLevels);
    for (int level = 0; level < levels; ++level)
        texture.uploadRGBA32F(file.levels[static_cast<size_t>(level)].data(), level);
    if (regenerate) texture.generateMipmaps();
    return texture;
}

}  // namespace

glm::ivec2 renderTargetSize(const fx::TextureDesc& desc, int width, int height) {
    return glm::ivec2(
        desc.width > 0 ? desc.width
                       : std::max(1, static_cast<int>(std::lround(desc.viewportRatio[0] * width))),
        desc.height > 0 ? desc.height
                        : std::max(1, static_cast<int>(std::lround(desc.viewportRatio[1] * height))));
}

bool isRenderTarget(const fx::TextureDesc& desc) {
    return desc.kind == fx::TextureDesc::Kind::RenderColorTarget ||
           desc.kind == fx::TextureDesc::Kind::RenderDepthStencilTarget;
}

std::unique_ptr<EffectTextures> EffectTextures::create(const fx::CompiledEffect& effect,
                                                       const std::vector<fx::Value>& values,
                                                       UniformRing& ring, fx::DiagnosticSink& diagnostics) {
    auto textures = std::unique_ptr<EffectTextures>(new EffectTextures(effect));
    if (!textures->createFileTextures(values, ring, diagnostics)) return nullptr;
    return textures;
}

const GpuTexture* EffectTextures::find(size_t parameter) const {
    auto it = mTextures.find(parameter);
    return it == mTextures.end() ? nullptr : &it->second;
}

const GpuTexture& EffectTextures::neutralFor(fx::BaseType samplerType) {
    const fx::BaseType type = samplerType == fx::BaseType::SamplerCube ? fx::BaseType::TextureCube
                              : samplerType == fx::BaseType::Sampler3D ? fx::BaseType::Texture3D
                              : samplerType == fx::BaseType::Sampler1D ? fx::BaseType::Texture1D
                                                                       : fx::BaseType::Texture2D;
    auto it = mNeutralTextures.find(type);
    if (it == mNeutralTextures.end()) it = mNeutralTextures.emplace(type, makeNeutralTexture(type)).first;
    return it->second;
}

bool EffectTextures::bindTargets(const RenderTargets& targets, FramebufferFault& fault) {
    if (!mFramebuffers.bind(targets, fault)) return false;
    for (const RenderTargetAttachment& color : targets.colors)
        if (color.texture && color.texture->mipLevels() > 1) mStaleMipChains.insert(color.texture);
    return true;
}

bool EffectTextures::bindFramebuffer(const RenderTargets& targets, FramebufferFault& fault) {
    return mFramebuffers.bind(targets, fault);
}

void EffectTextures::refreshMipChain(const GpuTexture& texture) {
    if (mStaleMipChains.erase(&texture) > 0) texture.generateMipmaps();
}

void EffectTextures::setApplicationTexture(size_t parameter, GLuint name, GLenum target) {
    if (name == 0) {
        mApplicationTextures.erase(parameter);
    } else {
        mApplicationTextures[parameter] = ApplicationTexture{name, target};
    }
}

const EffectTextures::ApplicationTexture* EffectTextures::applicationTexture(size_t parameter) const {
    auto found = mApplicationTextures.find(parameter);
    return found == mApplicationTextures.end() ? nullptr : &found->second;
}

bool EffectTextures::givenByApplication(size_t parameter) const {
    return mApplicationTextures.count(parameter) || mSetByApplication.count(parameter);
}

RenderTargets EffectTextures::hostPictureTargets(int width, int height) {
    if (mHostPicture.width() != width || mHostPicture.height() != height) {
        if (mHostPicture) mFramebuffers.evict(mHostPicture);
        if (mHostPictureDepth) mFramebuffers.evict(mHostPictureDepth);
        mHostPicture = GpuTexture::create2D(fx::TextureFormat::RGBA8, width, height);
        mHostPicture.setLabel("host picture");
        mHostPictureDepth = GpuTexture::create2D(fx::TextureFormat::D24S8, width, height);
    }
    RenderTargets targets;
    targets.colors[0].texture = &mHostPicture;
    targets.depth.texture = &mHostPictureDepth;
    return targets;
}

void EffectTextures::uploadFrameColor(const uint8_t* rgba8) {
    mFrameColor.uploadRGBA8(rgba8);
}

void EffectTextures::replace(size_t parameter, GpuTexture texture) {
    auto it = mTextures.find(parameter);
    if (it != mTextures.end()) {
        mFramebuffers.evict(it->second);
        mStaleMipChains.erase(&it->second);
    }
    mTextures[parameter] = std::move(texture);
}

bool EffectTextures::createFileTextures(const std::vector<fx::Value>& values, UniformRing& ring,
                                        fx::DiagnosticSink& diagnostics) {
    for (const fx::TextureDesc& desc : mEffect->textures) {
        if ((desc.type == fx::BaseType::Texture2DMS || desc.type == fx::BaseType::Texture2DMSArray) &&
            supportedSamples(desc) < desc.samples)
            diagnostics.report(fx::DiagId::SampleCountReduced, desc.loc,
                               {mEffect->parameters[desc.parameter].name, std::to_string(desc.samples),
                                std::to_string(supportedSamples(desc))});
        if (isRenderTarget(desc)) continue;
        const bool cube = desc.type == fx::BaseType::TextureCube;
        if (desc.kind == fx::TextureDesc::Kind::Noise) {
            mTextures[desc.parameter] = makeNoiseTexture();
            continue;
        }
        if (desc.kind == fx::TextureDesc::Kind::Function) {
            std::optional<GpuTexture> texture = fillTextureFunction(desc, values, ring, diagnostics);
            if (!texture) return false;
            mTextures[desc.parameter] = std::move(*texture);
            continue;
        }
        if (desc.kind == fx::TextureDesc::Kind::Procedural) {
            GpuTexture texture = GpuTexture::create2D(desc.format, desc.width, desc.height, desc.mipLevels);
            texture.uploadRGBA32F(whiteNoiseTexels(texture.width(), texture.height(), desc.seed).data());
            texture.generateMipmaps();
            mTextures[desc.parameter] = std::move(texture);
            continue;
        }
        if (desc.kind == fx::TextureDesc::Kind::File && !desc.resolvedPath.empty() &&
            isTextureFile(desc.resolvedPath)) {
            std::optional<TextureFileFault> fault;
            std::optional<TextureFile> file = loadTextureFile(desc.resolvedPath, fault);
            if (!file) {
                std::vector<std::string> arguments{desc.resourceName};
                arguments.insert(arguments.end(), fault->values.begin(), fault->values.end());
                diagnostics.report(fault->id, desc.loc, arguments);
                return false;
            }
            std::optional<GpuTexture> texture = makeFileTexture(*file, desc);
            if (!texture) {
                // A cube file behind a 2D sampler (or the like) samples as black in GL: say so, and draw
                // with the neutral texture as for a missing file.
                diagnostics.report(fx::Diagnostic{
                    fx::DiagId::TextureFileNotFound, fx::Severity::Warning, desc.loc,
                    "texture file '" + desc.resourceName + "' holds a " + textureFileKindName(*file) +
                        " texture, but the effect samples it as a " + textureTypeName(desc.type) +
                        " texture; using a neutral texture"});
                mTextures[desc.parameter] =
                    makeNeutralTexture(desc.type, desc.arraySize, supportedSamples(desc));
                continue;
            }
            texture->setLabel(mEffect->parameters[desc.parameter].name);
            mTextures[desc.parameter] = std::move(*texture);
            continue;
        }
        if (desc.kind == fx::TextureDesc::Kind::File && !desc.resolvedPath.empty() && !cube &&
            desc.type == fx::BaseType::Texture2D) {
            std::string error;
            std::optional<Image> image = loadImageFile(desc.resolvedPath, error);
            if (!image) {
                diagnostics.report(fx::DiagId::TextureFileUnreadable, desc.loc, {desc.resourceName, error});
                return false;
            }
            // HDR files keep their range in a float texture; everything else is 8-bit RGBA.
            const int levels = desc.mipLevels == 1 ? 1 : 0;
            GpuTexture texture =
                GpuTexture::create2D(image->isFloat ? fx::TextureFormat::RGBA32F : fx::TextureFormat::RGBA8,
                                     image->width, image->height, levels);
            if (image->isFloat) {
                texture.uploadRGBA32F(image->floats.data());
            } else {
                texture.uploadRGBA8(image->toRGBA8().bytes.data());
            }
            texture.generateMipmaps();
            mTextures[desc.parameter] = std::move(texture);
            continue;
        }
        mTextures[desc.parameter] = makeNeutralTexture(desc.type, desc.arraySize, supportedSamples(desc));
    }
    return true;
}

bool EffectTextures::ensureFrame(int width, int height, const std::vector<bool>* needed) {
    const bool made = mFrameColor.width() != width || mFrameColor.height() != height;
    if (made) {
        if (mFrameColor) mFramebuffers.evict(mFrameColor);
        if (mFrameDepth) mFramebuffers.evict(mFrameDepth);
        mFrameColor = GpuTexture::create2D(fx::TextureFormat::RGBA8, width, height);
        mFrameDepth = GpuTexture::create2D(fx::TextureFormat::D24S8, width, height);
    }
    ensureRenderTargets(width, height, needed);
    return made;
}

void EffectTextures::ensureRenderTargets(int width, int height, const std::vector<bool>* needed) {
    for (const fx::TextureDesc& desc : mEffect->textures) {
        if (!isRenderTarget(desc)) continue;
        const glm::ivec2 size = renderTargetSize(desc, width, height);
        const int w = size.x, h = size.y;
        auto it = mTextures.find(desc.parameter);
        if (it == mTextures.end() && needed &&
            !(desc.parameter < needed->size() && (*needed)[desc.parameter]))
            continue;
        if (it != mTextures.end() && it->second.width() == w && it->second.height() == h) continue;
        GpuTexture texture = makeRenderTarget(desc, w, h);
        texture.setLabel(mEffect->parameters[desc.parameter].name);
        replace(desc.parameter, std::move(texture));
    }
}

bool EffectTextures::set(size_t index, const TextureData& data, fx::DiagnosticSink& diagnostics) {
    const fx::TextureDesc* desc = index < mEffect->parameters.size() ? mEffect->findTexture(index) : nullptr;
    const fx::SourceLoc where = index < mEffect->parameters.size() ? mEffect->parameters[index].loc
                                                                   : fx::SourceLoc{mEffect->path, 0, 0};
    auto refuse = [&](fx::DiagId id, const std::vector<std::string>& args) {
        diagnostics.report(id, where, args);
        return false;
    };
    if (!desc || isRenderTarget(*desc) || desc->type == fx::BaseType::Texture3D ||
        desc->type == fx::BaseType::Texture2DMS || desc->type == fx::BaseType::Texture2DMSArray)
        return refuse(fx::DiagId::SetTextureNotReadTexture, {std::to_string(index)});
    const bool cube = desc->type == fx::BaseType::TextureCube || desc->type == fx::BaseType::TextureCubeArray;
    const int elements = isArrayType(desc->type) ? data.elements : 1;
    const size_t layers = static_cast<size_t>(std::max(elements, 0)) * (cube ? 6 : 1);
    const bool sizeOk =
        data.width >= 1 && data.height >= 1 && data.width <= 16384 && data.height <= 16384 && elements >= 1 &&
        elements <= 2048 && (!cube || data.width == data.height) &&
        (desc->type != fx::BaseType::Texture1DArray || data.height == 1) &&
        data.rgba.size() == static_cast<size_t>(data.width) * static_cast<size_t>(data.height) * layers * 4;
    if (!sizeOk)
        return refuse(cube ? fx::DiagId::SetCubeTextureDataSize : fx::DiagId::SetTextureDataSize,
                      {mEffect->parameters[index].name, mEffect->parameters[index].type.hlslName()});
    const int levels = desc->mipLevels == 1 ? 1 : 0;
    const fx::TextureFormat format = fx::TextureFormat::RGBA32F;
    const size_t layerFloats = static_cast<size_t>(data.width) * static_cast<size_t>(data.height) * 4;
    GpuTexture texture;
    if (isArrayType(desc->type)) {
        texture = makeArrayTexture(desc->type, format, data.width, data.height, elements, levels);
        for (size_t layer = 0; layer < layers; ++layer)
            texture.uploadLayerRGBA32F(data.rgba.data() + layer * layerFloats, 0, static_cast<int>(layer));
    } else if (cube) {
        texture = GpuTexture::createCube(format, data.width, levels);
        for (int face = 0; face < 6; ++face)
            texture.uploadRGBA32F(data.rgba.data() + static_cast<size_t>(face) * layerFloats, 0, face);
    } else {
        texture = GpuTexture::create2D(format, data.width, data.height, levels);
        texture.uploadRGBA32F(data.rgba.data());
    }
    texture.generateMipmaps();
    texture.setLabel(mEffect->parameters[index].name);
    replace(index, std::move(texture));
    mSetByApplication.insert(index);
    return true;
}

uint64_t EffectTextures::identity(int resource) const {
    const GpuTexture* texture = nullptr;
    if (resource == kFrameColor) texture = &mFrameColor;
    if (resource == kFrameDepth) texture = &mFrameDepth;
    if (resource >= 0) {
        auto it = mTextures.find(static_cast<size_t>(resource));
        if (it != mTextures.end()) texture = &it->second;
    }
    uint64_t h = hashCombine(0, static_cast<uint64_t>(static_cast<int64_t>(resource)));
    if (!texture) return h;
    h = hashCombine(h, texture->id());
    h = hashCombine(h, (uint64_t(uint32_t(texture->width())) << 32) | uint32_t(texture->height()));
    return hashCombine(h, static_cast<uint64_t>(texture->format()));
}

}  // namespace runtime
