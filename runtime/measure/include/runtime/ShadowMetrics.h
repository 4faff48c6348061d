// ShadowMetrics: how far an effect's shadow term is from the ground truth (runtime/GroundTruth.h), and
// how coarse its shadow map is on screen.
//
// Receiver pixels: covered pixels of the G-buffer whose surface faces the light (N·L > 0); a surface
// facing away is dark by its own shading whatever the shadow method says, so it cannot be scored; nor can
// a pixel outside a spot light's cone, which the light does not reach.
#pragma once

#include <runtime/EffectRenderer.h>
#include <runtime/GBuffer.h>
#include <runtime/GroundTruth.h>
#include <runtime/LightParameterization.h>
#include <runtime/Scene.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace runtime {

// 1 for pixels that face `light`, else 0.
std::vector<uint8_t> receiverMask(const GBuffer& gbuffer, const Light& light);

struct ShadowErrors {
    size_t receiverPixels = 0;
    size_t falseShadowPixels = 0;     // lit in truth, shadowed by the effect (acne, over-darkening)
    size_t falseLightPixels = 0;      // shadowed in truth, lit by the effect (peter-panning, light leaks)
    double falseShadowPercent = 0.0;  // of receiver pixels
    double falseLightPercent = 0.0;
    double misclassifiedPercent = 0.0;  // the sum
    // Visibility as a fraction: mean and 95th percentile of |effect - truth| over receiver pixels. For
    // hard shadows these say how much of the error is filtering rather than classification.
    double meanAbsoluteError = 0.0;
    double p95AbsoluteError = 0.0;
    // The same mean over the penumbra only: receiver pixels whose truth is partly lit (kPenumbra). Where
    // most receivers are fully lit or in umbra, the mean over all of them hides how well a soft-shadow
    // method draws the penumbra itself. 0 pixels (hard truth): 0.
    size_t penumbraPixels = 0;
    double penumbraMeanAbsoluteError = 0.0;
};

// A truth visibility in (kPenumbra, 1 - kPenumbra) is penumbra: more than 1% of the light's area both
// visible and hidden (1% is 2.5 samples of the ground truth's default 256).
constexpr float kPenumbra = 0.01f;

// Classification threshold: visibility < 0.5 is "shadowed", for truth (area lights: less than half the
// light visible) and effect alike. `effect` holds one visibility in [0, 1] per pixel.
constexpr float kShadowedBelow = 0.5f;
ShadowErrors compareVisibility(const std::vector<float>& truth, const std::vector<float>& effect,
                               const std::vector<uint8_t>& receivers);

// The visibility an effect compiled with SHADOWFX_VISIBILITY wrote: its frame's red channel.
std::vector<float> visibilityFromFrame(const FrameImage& frame);

// The error image: `frame` in grey, false-shadow pixels red, false-light pixels blue.
FrameImage errorImage(const FrameImage& frame, const std::vector<float>& truth,
                      const std::vector<float>& effect, const std::vector<uint8_t>& receivers);

// Perspective aliasing in the sense of Lloyd et al. ("Logarithmic perspective shadow maps", 2008): how many
// screen pixels one shadow-map texel covers. For each receiver pixel, the shadow-map texel coordinates
// s(x, y) = mapSize * uv(lightViewProjection * P(x, y)) of the G-buffer's world point are differentiated
// by finite differences with neighbouring pixels of the same object; the footprint is 1 / sigma_min(J)
// of the Jacobian J = ds/d(x, y) (texels per pixel): the texel's extent in pixels along its longest
// screen direction. > 1 is undersampling (a texel spans several pixels: jagged edges). It includes
// projective aliasing, because the derivatives are those of the real surface.
struct AliasingMeasure {
    double maxFootprint = 0.0;
    double meanFootprint = 0.0;
    double p95Footprint = 0.0;  // the max is one grazing pixel; this says how far the bulk goes
    size_t pixels = 0;          // receiver pixels with a usable neighbourhood
};
// `lightView` and `lightProjection` are glm (column-vector) matrices as Light::view/projection return.
AliasingMeasure perspectiveAliasing(const GBuffer& gbuffer, const std::vector<uint8_t>& receivers,
                                    const glm::mat4& lightView, const glm::mat4& lightProjection,
                                    int mapSize);
// The same for cascaded shadow maps (runtime/CascadedShadowMaps.h): each receiver in the texels of its own
// cascade (the first whose splitFar lies beyond its view depth under `cameraView`), a tile of the
// `atlasSize`² atlas; derivatives are not taken across cascades.
AliasingMeasure cascadedAliasing(const GBuffer& gbuffer, const std::vector<uint8_t>& receivers,
                                 const glm::mat4& cameraView, const std::vector<LightView>& cascades,
                                 int atlasSize);
// The same for a PSMCube fit (runtime/PerspectiveShadowCubeMap.h): each receiver in the texels of the face
// that `fit.faceSelect` picks for it (as psm_cube.fx does), its tile (LightView::atlasRect) of the
// `atlasSize`² atlas; derivatives are not taken across faces.
AliasingMeasure cubeFaceAliasing(const GBuffer& gbuffer, const std::vector<uint8_t>& receivers,
                                 const LightFit& fit, int atlasSize);
// Whichever of the three `fit` calls for: its cube faces, its cascades (under `cameraView`), or its one map.
AliasingMeasure fitAliasing(const GBuffer& gbuffer, const std::vector<uint8_t>& receivers,
                            const glm::mat4& cameraView, const LightFit& fit, int mapSize);

// The sampling-limited error of `fit` at `mapSize`: the misclassified % of receiver pixels that a shadow map
// of exactly that fit and size has in expectation when each texel holds the truth's classification at a
// uniformly placed point of it, from pixels whose texel straddles the truth's shadow boundary (the pixels
// of each texel on the other side, 2 s (n - s) / n of its n pixels, s of them shadowed in `truth`). Depends
// on where the fit puts its resolution and on where the view sees shadow boundaries, on no bias or filter:
// what a case asks of the fit's resolution alone. A texel smaller than a pixel adds nothing.
double samplingLimitedError(const GBuffer& gbuffer, const std::vector<uint8_t>& receivers,
                            const std::vector<float>& truth, const glm::mat4& cameraView, const LightFit& fit,
                            int mapSize);

}  // namespace runtime
