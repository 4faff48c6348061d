// InstancedPass: the variant of a compiled pass that draws many objects sharing a mesh in one instanced
// draw. The runtime asks for it with the set of uniform-block members whose values differ from object to
// object (World and what derives from it, the object's colour and id, compile arguments computed from
// them); the effect's author writes nothing different.
//
// The variant is the pass's GLSL (after SPIRV-Cross) with every read of a per-object member redirected
// from the stage's uniform block to one record per scene object in a shader storage buffer, indexed by
// the object index the instance list gives for gl_InstanceID:
//   buffer binding kObjectBufferBinding (std140): fx_Object fx_objects[], one record per scene object
//   buffer binding kInstanceBufferBinding (std430): uint fx_instances[], the object of each instance
// The vertex stage passes the object index to the pixel stage as a flat varying at
// kObjectVaryingLocation when the pixel stage reads per-object members. Per-frame members stay in the
// uniform blocks; the per-object ones are marked inactive there (the runtime no longer packs them).
#pragma once

#include <fx/CompiledEffect.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace fx {

inline constexpr int kObjectBufferBinding = 6;
inline constexpr int kInstanceBufferBinding = 7;
inline constexpr int kObjectVaryingLocation = 31;

struct InstancedPass {
    CompiledPass pass;  // the rewritten GLSL; per-object members inactive in the uniform blocks
    // The per-object members of both stages, once each, with their offsets in one object's record
    // (`source` and `index` name the parameter or compile argument, as in the blocks).
    std::vector<UniformBinding> record;
    uint32_t recordSize = 0;  // bytes between consecutive records (std140 array stride)
};

// `perObjectParameter` has one flag per effect parameter, `perObjectArgument` one per pass.arguments
// entry. Returns nullopt, with the reason in `whyNot`, where the pass cannot be drawn instanced
// (its code reads gl_InstanceID or uses shader storage buffers itself, the varying location is taken, or a
// per-object member has a type the record does not carry): the runtime then draws object by object.
std::optional<InstancedPass> instancedPass(const CompiledPass& pass,
                                           const std::vector<bool>& perObjectParameter,
                                           const std::vector<bool>& perObjectArgument, std::string& whyNot);

}  // namespace fx
