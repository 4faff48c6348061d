// EffectTechnique, EffectPass: an application drives an effect's passes itself, as D3DX9 and FX11
// applications did (docs/api.md): it looks a technique up, applies its passes one after the other and
// issues its own draws with its own vertex arrays between them.
//
//     runtime::EffectTechnique technique = renderer.technique("main");
//     technique.begin();                                  // saves the GL state the passes touch
//     for (size_t p = 0; p < technique.passCount(); ++p) {
//         runtime::EffectPass pass = technique.pass(p);
//         pass.apply();                                   // program, states, blocks, textures, targets
//         for (const Object& object : objects) {
//             renderer.variableBySemantic("World").setMatrix(object.world);
//             pass.commitChanges();                       // the new values into the uniform blocks
//             gl::BindVertexArray(object.vao);
//             gl::DrawElements(GL_TRIANGLES, object.count, GL_UNSIGNED_INT, nullptr);
//         }
//     }
//     technique.end();                                    // restores it
//
// apply() needs a current GL 4.5 context with the runtime's conventions (runtime/GlContext.h:
// glClipControl(GL_UPPER_LEFT, GL_ZERO_TO_ONE)). Like the variables (runtime/EffectVariable.h), techniques
// and passes are handles into their EffectRenderer: lookups never return null, an invalid handle's
// isValid() is false and its apply() does nothing and returns false.
#pragma once

#include <runtime/EffectVariable.h>
#include <runtime/GlStateSnapshot.h>
#include <runtime/StreamOutBuffers.h>

#include <fx/Diagnostics.h>
#include <fx/HostFile.h>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace runtime {

// One input of a pass's vertex shader: where the application's vertex array feeds it. Inputs are floats;
// an input the application leaves disabled reads the current generic attribute value (glVertexAttrib4f),
// as in any GL program.
struct PassInput {
    std::string semantic;  // the D3D9 stream name with its index: "POSITION0"... as written ("TEXCOORD0")
    int location = 0;      // the attribute location
    int components = 4;    // float, float2, float3 or float4 as the shader declares it
};

class EffectPass {
public:
    EffectPass() = default;  // invalid
    EffectPass(EffectResources* resources, size_t technique, size_t pass)
        : mResources(resources), mTechnique(technique), mPass(pass) {}

    bool isValid() const { return mResources != nullptr; }
    const std::string& name() const;  // "" when invalid or unnamed
    size_t techniqueIndex() const { return mTechnique; }
    size_t index() const { return mPass; }

    // The vertex shader's inputs, in location order (empty for a pass without shaders).
    std::vector<PassInput> inputSignature() const;
    // What apply() writes to the context (FX11's ComputeStateBlockMask); `framebuffer` is set for a pass
    // whose Script names render targets.
    GlStateMask stateMask() const;

    // Makes the current context ready to draw with the pass:
    // - targets: a pass whose Script annotation names render targets (RenderColorTarget0..3,
    //   RenderDepthStencilTarget) gets the effect's textures bound with the viewport at their size; naming
    //   none ("RenderColorTarget0=;") binds the application's framebuffer and viewport back: those bound at
    //   EffectTechnique::begin(), or, without one, at the first apply(). A pass whose script names no
    //   target leaves the framebuffer to the application. The script's clears, render ports and draws are
    //   the application's to do (docs/api.md).
    // - every render state (those the pass does not set at their D3D9 defaults), its program, its compile
    //   arguments evaluated over the current values, its uniform blocks, textures, samplers and storage
    //   buffers.
    // False, with a diagnostic, where the pass cannot be applied (an invalid handle, a render target that
    // cannot be bound); a pass without shaders (a clear pass) applies targets and states only, and leaves
    // the bound program as it is.
    bool apply(fx::DiagnosticSink* diagnostics = nullptr) const;
    // After values changed (a per-object World between draws): evaluates the applied pass's compile
    // arguments again and uploads the blocks whose bytes changed, touching nothing else. Setting a value
    // never writes GL by itself: GL state changes only at apply() and commitChanges(), where the
    // application knows a context is current and what is bound, as D3DX9's CommitChanges. False if this
    // pass is not the one last applied.
    bool commitChanges(fx::DiagnosticSink* diagnostics = nullptr) const;

    // A compute pass (SetComputeShader; docs/d3d10.md, "Compute shaders and read-write resources"): apply()
    // binds its storage buffers, images, textures, program and values, and touches no target or render
    // state; dispatch() then runs x * y * z thread groups (FX11's Dispatch after Apply; it applies the pass
    // first where another was applied last) and orders the writes before whatever reads them next, draws,
    // dispatches and the application's reads of the buffers alike (glMemoryBarrier). What a dispatch
    // writes stays in the effect's buffers and images between frames. A pass that also sets graphics
    // shaders applies as a drawing pass; its dispatch() runs the compute stage and leaves the graphics
    // program current for the application's draws. False, with a diagnostic, for a pass without a compute
    // shader or more groups than the context dispatches.
    bool dispatch(uint32_t x, uint32_t y = 1, uint32_t z = 1,
                  fx::DiagnosticSink* diagnostics = nullptr) const;

    // A stream-output pass's (ConstructGSWithSO) last capture, as render() or the application's own
    // captures left it: the buffers, the transform feedback object to hand glDrawTransformFeedback (D3D10's
    // DrawAuto) and a vertex array whose attribute k is element k of the declaration (docs/d3d10.md,
    // "Stream output"). Nothing (nullopt) for a pass without stream output.
    std::optional<StreamOutCapture> streamOutput() const;
    // The application's draws between beginStreamOutput() and endStreamOutput(), after apply(), are captured
    // into the pass's buffers (the set that does not hold the last capture), rasterizing nothing where the
    // pass's pixel shader is NULL. False for a pass without stream output.
    bool beginStreamOutput() const;
    void endStreamOutput() const;

    size_t annotationCount() const;
    EffectAnnotation annotation(size_t i) const;
    EffectAnnotation annotation(std::string_view name) const;

private:
    EffectResources* mResources = nullptr;
    size_t mTechnique = 0;
    size_t mPass = 0;
};

class EffectTechnique {
public:
    EffectTechnique() = default;  // invalid
    EffectTechnique(EffectResources* resources, size_t technique)
        : mResources(resources), mTechnique(technique) {}

    bool isValid() const { return mResources != nullptr; }
    const std::string& name() const;   // "" when invalid
    const std::string& group() const;  // the D3D11 fxgroup holding it, "" if none
    size_t index() const { return mTechnique; }

    size_t passCount() const;
    EffectPass pass(size_t index) const;
    EffectPass pass(std::string_view name) const;  // case-blind, as SAS scripts name passes

    // Begin/end pair (D3DX9's Begin/End): begin() records the application's framebuffer and viewport,
    // allocates the effect's render targets at the viewport's size (for ViewPortRatio targets) and, unless
    // `saveState` is false (D3DXFX_DONOTSAVESTATE), reads the state every pass may touch (stateMask());
    // end() writes it back. False if the technique is invalid or another begin() is open.
    bool begin(bool saveState = true) const;
    void end() const;
    // The union of the passes' masks: what begin() saves.
    GlStateMask stateMask() const;

    size_t annotationCount() const;
    EffectAnnotation annotation(size_t i) const;
    EffectAnnotation annotation(std::string_view name) const;

private:
    EffectResources* mResources = nullptr;
    size_t mTechnique = 0;
};

// D3D10's RSSetViewports: viewport i becomes viewports[i] (glViewportIndexedf), the one a geometry shader's
// SV_ViewportArrayIndex i draws into; the others keep theirs. Depth ranges stay 0 to 1. A pass whose Script
// names render targets binds them with one viewport at their size, as glViewport sets every viewport, so
// an application sets its viewports after apply(). More viewports than the context has
// (GL_MAX_VIEWPORTS, 16 on GL 4.5) are ignored.
void setViewports(const std::vector<fx::Viewport>& viewports);

// D3DX9's ValidateTechnique: whether a technique of the effect can run here, and the reason it cannot: for
// a technique the parser or compiler left out (fx/RefusedTechnique.h), what it uses that GL cannot run.
struct TechniqueValidation {
    bool valid = false;
    std::string reason;  // "" when valid
};

}  // namespace runtime
