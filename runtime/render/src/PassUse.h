// PassUse: what one pass reads, from its compiled data alone: the parameters its stages' uniform blocks
// name and the inputs of its preshader programs (render states, compile arguments). Only these are bound
// (semantics) and hashed (FramePlan signatures); compile arguments that read no per-object semantic run
// once per pass instead of once per draw.
#pragma once

#include "SemanticBinder.h"

#include <fx/CompiledEffect.h>
#include <runtime/Scene.h>

#include <vector>

namespace runtime {

struct PassUse {
    std::vector<bool> used;                 // per effect parameter
    std::vector<bool> argumentPerObject;    // per CompiledPass::arguments entry
    std::vector<bool> argumentPerPass;      // its complement
    bool anyArgumentPerObject = false;      // some argumentPerObject entry is true
    std::vector<size_t> perPassParameters;  // used and not bound per object
    // Per effect parameter: used, and its per-object value derives from the view too
    // (SemanticBinder::derivesFromView): batching packs it again when only the view changed.
    std::vector<bool> viewDerived;
    // Per effect parameter: what a draw binds when only the view changed: the viewDerived parameters and
    // the per-object inputs of per-object compile arguments (they run again with them).
    std::vector<bool> viewRebound;
    // The view/projection matrices it reads: the port's, and those of annotated lights. Culling trusts
    // the port's frustum only for passes that project with it (a camera-port pass that draws a light's
    // view with frustum="light0" matrices is not culled).
    bool readsPortMatrix = false;
    std::vector<int> lightMatrices;  // light slots (SemanticBinder::lightSlot)

    // True if a draw with the render port (`portLight`: its light, null for the camera) projects with the
    // port's matrices, so that culling to the port's frustum keeps everything it can draw.
    bool projectsWith(const Light* portLight, const SemanticBinder& binder) const;
};

// Per effect parameter (`count` of them): whether the pass reads its value, in a uniform-block member its
// code reads or in a state's or compile argument's expression.
std::vector<bool> passValueReads(const fx::CompiledPass& pass, size_t count);

// One PassUse per pass of `technique`, for the parameter count `parameters`: from the compiled effect and
// the binder's classification alone, so made once when the effect is created.
std::vector<PassUse> passUses(const fx::CompiledTechnique& technique, size_t parameters,
                              const SemanticBinder& binder);

}  // namespace runtime
