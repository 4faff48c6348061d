// CompiledEffectFields: every field of a compiled effect, listed once per struct for both directions of
// fx/src/BinaryArchive.h: `fields(archive, value)` writes them with a BinaryWriter and reads them, in the
// same order, with a BinaryReader. Adding a field to a struct of fx/CompiledEffect.h is one entry in its
// list here (and a new format version, docs/compiled-effect.md); the size checks below fail the build
// until the list and the struct agree.
#pragma once

#include "BinaryArchive.h"

#include <fx/CompiledEffect.h>
#include <fx/Diagnostics.h>
#include <fx/RenderStates.h>

#include <algorithm>
#include <optional>
#include <string_view>

namespace fx::detail {

// [SECTION] Enumerators the reader accepts

// By name: the tables that grow with the language. A new diagnostic or render state, wherever it goes in
// its table, leaves older files readable and meaning what they meant.
template <>
struct EnumByName<DiagId> : std::true_type {
    static std::string_view name(DiagId id) { return diagnosticName(id); }
    static std::optional<DiagId> find(std::string_view name) { return findDiagnostic(name); }
};
template <>
struct EnumByName<RenderStateId> : std::true_type {
    static std::string_view name(RenderStateId id) { return renderStateInfo(id).name; }
    static std::optional<RenderStateId> find(std::string_view name) { return findRenderState(name); }
};

// By number: the short enums of the compiled effect's own structures. Their lengths are pinned to the
// format version below, so that an enumerator added, removed or moved fails the build here until the
// version is raised: an older file is then refused, never read with other meanings.
template <class E, E last>
struct EnumLast {
    static constexpr E kLast = last;
};
template <>
struct EnumLimit<ShaderStage> : EnumLast<ShaderStage, ShaderStage::Compute> {};
template <>
struct EnumLimit<SemanticKind> : EnumLast<SemanticKind, SemanticKind::StandardsGlobal> {};
template <>
struct EnumLimit<UniformBinding::Source>
    : EnumLast<UniformBinding::Source, UniformBinding::Source::CompileArgument> {};
template <>
struct EnumLimit<VertexStream> : EnumLast<VertexStream, VertexStream::BlendIndices> {};
template <>
struct EnumLimit<LeaveOutCondition> : EnumLast<LeaveOutCondition, LeaveOutCondition::NoLightArea> {};
template <>
struct EnumLimit<CompiledPass::DrawPrimitive>
    : EnumLast<CompiledPass::DrawPrimitive, CompiledPass::DrawPrimitive::TrianglesAdjacency> {};
template <>
struct EnumLimit<StreamOutElement::Component>
    : EnumLast<StreamOutElement::Component, StreamOutElement::Component::UInt> {};
template <>
struct EnumLimit<StreamOutput::Primitive>
    : EnumLast<StreamOutput::Primitive, StreamOutput::Primitive::Triangles> {};
template <>
struct EnumLimit<TextureFormat> : EnumLast<TextureFormat, TextureFormat::D32F> {};
template <>
struct EnumLimit<TextureDesc::Kind> : EnumLast<TextureDesc::Kind, TextureDesc::Kind::Noise> {};
template <>
struct EnumLimit<BaseType> : EnumLast<BaseType, BaseType::Struct> {};
template <>
struct EnumLimit<Shape> : EnumLast<Shape, Shape::Matrix> {};
template <>
struct EnumLimit<ScriptCommand::Kind> : EnumLast<ScriptCommand::Kind, ScriptCommand::Kind::Dispatch> {};
template <>
struct EnumLimit<ScriptCommand::ClearWhat>
    : EnumLast<ScriptCommand::ClearWhat, ScriptCommand::ClearWhat::Stencil> {};
template <>
struct EnumLimit<ScriptCommand::DrawWhat>
    : EnumLast<ScriptCommand::DrawWhat, ScriptCommand::DrawWhat::Buffer> {};
template <>
struct EnumLimit<PreshaderProgram::Instruction::Op>
    : EnumLast<PreshaderProgram::Instruction::Op, PreshaderProgram::Instruction::Op::Convert> {};
template <>
struct EnumLimit<PreshaderProgram::Instruction::Operator>
    : EnumLast<PreshaderProgram::Instruction::Operator, PreshaderProgram::Instruction::Operator::Unknown> {};
template <>
struct EnumLimit<PreshaderProgram::Instruction::Function>
    : EnumLast<PreshaderProgram::Instruction::Function, PreshaderProgram::Instruction::Function::Unknown> {};

template <class E>
constexpr int enumLength() {
    return static_cast<int>(EnumLimit<E>::kLast) + 1;
}
static_assert(kCompiledEffectFormatVersion == 20,
              "the enum lengths below were pinned at format version 20: re-pin them with the new version");
static_assert(enumLength<ShaderStage>() == 6);
static_assert(enumLength<SemanticKind>() == 40);
static_assert(enumLength<UniformBinding::Source>() == 2);
static_assert(enumLength<VertexStream>() == 8);
static_assert(enumLength<LeaveOutCondition>() == 3);
static_assert(enumLength<CompiledPass::DrawPrimitive>() == 4);
static_assert(enumLength<StreamOutElement::Component>() == 3);
static_assert(enumLength<StreamOutput::Primitive>() == 3);
static_assert(enumLength<TextureFormat>() == 12);
static_assert(enumLength<TextureDesc::Kind>() == 7);
static_assert(enumLength<BaseType>() == 49);
static_assert(enumLength<Shape>() == 3);
static_assert(enumLength<ScriptCommand::Kind>() == 19);
static_assert(enumLength<ScriptCommand::ClearWhat>() == 3);
static_assert(enumLength<ScriptCommand::DrawWhat>() == 2);
static_assert(enumLength<PreshaderProgram::Instruction::Op>() == 12);
static_assert(enumLength<PreshaderProgram::Instruction::Operator>() == 22);
static_assert(enumLength<PreshaderProgram::Instruction::Function>() == 42);

// [SECTION] Size checks: a field added to a struct changes its size; list it below, then update the size.
// (x86-64 with libstdc++, the platform the project builds on.)

#if defined(__x86_64__) && defined(__GLIBCXX__)
static_assert(sizeof(SourceLoc) == 40);
static_assert(sizeof(TypeDesc) == 112);
static_assert(sizeof(Value) == 168);
static_assert(sizeof(AnnotationValue) == 200);
static_assert(sizeof(UniformField) == 168);
static_assert(sizeof(UniformBinding) == 208);
static_assert(sizeof(SamplerBinding) == 144);
static_assert(sizeof(StorageBufferBinding::Run) == 12);
static_assert(sizeof(StorageBufferBinding) == 88);
static_assert(sizeof(VertexInput) == 48);
static_assert(sizeof(ImageBinding) == 80);
static_assert(sizeof(StageEffects) == 12);
static_assert(sizeof(StageProgram) == 320);
static_assert(sizeof(PreshaderProgram::Instruction::MemberComponents) == 14);
static_assert(sizeof(PreshaderProgram::Instruction) == 216);
static_assert(sizeof(PreshaderProgram::Error) == 72);
static_assert(sizeof(PreshaderProgram) == 96);
static_assert(sizeof(CompileArgument) == 240);
static_assert(sizeof(RenderStateSetting) == 160);
static_assert(sizeof(ScriptCommand::DispatchTerm) == 8);
static_assert(sizeof(ScriptCommand) == 456);
static_assert(sizeof(StreamOutElement) == 48);
static_assert(sizeof(StreamOutput) == 80);
static_assert(sizeof(CompiledPass) == 2240);
static_assert(sizeof(CompiledTechnique) == 184);
static_assert(sizeof(TextureDesc) == 2416);
static_assert(sizeof(SamplerDesc) == 128);
static_assert(sizeof(RefusedTechnique) == 136);
static_assert(sizeof(StructMemberInfo) == 176);
static_assert(sizeof(StructInfo) == 56);
static_assert(sizeof(SemanticBinding) == 16);
static_assert(sizeof(MemberBinding) == 168);
static_assert(sizeof(BufferTexel) == 8);
static_assert(sizeof(ParameterInfo) == 448);
static_assert(sizeof(EffectProvenance) == 112);
static_assert(sizeof(CompiledEffect) == 400);
#endif

// [SECTION] Fields, in file order

template <class A>
void fields(A& a, SourceLoc& x) {
    a(x.file, x.line, x.column);
}
template <class A>
void fields(A& a, TypeDesc& x) {
    a(x.base, x.shape, x.rows, x.cols, x.arrayDims, x.structName, x.rowMajor, x.templateArgs);
    // A type sizes the values the runtime builds from it (zeroValue, constructors in preshaders).
    a.require(x.rows >= 0 && x.rows <= 4 && x.cols >= 0 && x.cols <= 4, DiagId::CompiledEffectTypeTooLarge);
    int64_t elements = 1;
    for (int dim : x.arrayDims) {
        a.require(dim >= 0 && dim <= (1 << 20), DiagId::CompiledEffectArrayDimensionOutOfRange);
        elements *= dim >= 0 && dim <= (1 << 20) ? std::max(dim, 1) : 1;
        a.require(elements <= (1 << 20), DiagId::CompiledEffectArrayTooLarge);
        if (elements > (1 << 20)) break;
    }
}
template <class A>
void fields(A& a, Value& x) {
    a(x.type, x.data, x.string);
}
template <class A>
void fields(A& a, AnnotationValue& x) {
    a(x.name, x.value);
}
template <class A>
void fields(A& a, UniformField& x) {
    a(x.path, x.type, x.firstComponent, x.offset, x.arrayStride, x.matrixStride, x.hlslColumnsContiguous);
}
template <class A>
void fields(A& a, UniformBinding& x) {
    a(x.name, x.source, x.index, x.type, x.offset, x.size, x.arrayStride, x.matrixStride);
    a(x.hlslColumnsContiguous, x.active, x.fields);
}
template <class A>
void fields(A& a, SamplerBinding& x) {
    a(x.glslName, x.unit, x.samplerParameter, x.depthCompare, x.pairTexture, x.pairSampler,
      x.textureParameter);
    a(x.passSampler, x.read, x.hostPicture);
}
template <class A>
void fields(A& a, StorageBufferBinding::Run& x) {
    a(x.d3dOffset, x.glOffset, x.bytes);
}
template <class A>
void fields(A& a, StorageBufferBinding& x) {
    a(x.glslName, x.parameter, x.binding, x.glStride, x.d3dStride, x.runs, x.counterBinding);
}
template <class A>
void fields(A& a, ImageBinding& x) {
    a(x.glslName, x.parameter, x.format, x.unit);
}
template <class A>
void fields(A& a, VertexStreamSlot& x) {
    a(x.stream, x.index);
}
template <class A>
void fields(A& a, VertexInput& x) {
    a(x.semantic, x.location, x.components, x.stream);
}
template <class A>
void fields(A& a, StageEffects& x) {
    a(x.discards, x.writesDepth, x.writesSampleMask, x.writesImages, x.writesBuffers, x.atomics);
    a(x.writesPointSize, x.writesDiffuse, x.clipDistances);
}
template <class A>
void fields(A& a, StageProgram& x) {
    a(x.stage, x.entryPoint, x.profile, x.hlsl, x.glsl, x.uniformBlockName, x.uniformBlockBinding);
    a(x.uniformBlockSize, x.uniforms, x.samplers, x.storageBuffers, x.images, x.inputs, x.sourceHash);
    a(x.effects);
}
template <class A>
void fields(A& a, PreshaderProgram::Instruction::MemberComponents& x) {
    a(x.swizzleCount, x.swizzle, x.matrixCount, x.rows, x.columns);
}
template <class A>
void fields(A& a, PreshaderProgram::Instruction& x) {
    a(x.op, x.operation, x.function, x.operand, x.count, x.text, x.type, x.member, x.loc);
}
template <class A>
void fields(A& a, PreshaderProgram::Error& x) {
    a(x.id, x.loc, x.args);
}
struct PreshaderProgramFields {
    template <class A>
    static void fields(A& a, PreshaderProgram& x) {
        a(x.mCode, x.mConstants, x.mErrors, x.mInputs);
    }
};
template <class A>
void fields(A& a, PreshaderProgram& x) {
    PreshaderProgramFields::fields(a, x);
}
template <class A>
void fields(A& a, CompileArgument& x) {
    a(x.value, x.type, x.memberName);
}
template <class A>
void fields(A& a, RenderStateSetting& x) {
    a(x.id, x.constant, x.value, x.loc);
}
template <class A>
void fields(A& a, ScriptCommand::DispatchTerm& x) {
    a(x.parameter, x.count);
}
template <class A>
void fields(A& a, ScriptCommand& x) {
    a(x.kind, x.index, x.pass, x.value, x.cascade, x.loc, x.selectorCondition, x.selectorTrue);
    a(x.selectorFalse, x.selectorAlternatives, x.clear, x.clearTarget, x.draw);
    a(x.parameter, x.literal, x.light, x.dispatch, x.technique, x.techniqueIfFalse, x.selectorParameter);
}
template <class A>
void fields(A& a, StreamOutElement& x) {
    a(x.semantic, x.slot, x.offset, x.components, x.component);
}
template <class A>
void fields(A& a, StreamOutput& x) {
    a(x.varyings, x.elements, x.strides, x.primitive, x.rasterizes, x.capacity);
}
template <class A>
void fields(A& a, CompiledPass& x) {
    a(x.name, x.loc, x.cullClosedOnly, x.leaveOutWhen, x.filterReachTexels, x.castersOnly);
    a(x.vertex, x.fragment, x.geometry, x.hull, x.domain, x.compute, x.patchVertices, x.primitive);
    a(x.arguments, x.states, x.hasScript, x.script, x.annotations);
    a(x.streamOut, x.drawAuto, x.readParameters);
}
template <class A>
void fields(A& a, CompiledTechnique& x) {
    a(x.name, x.group, x.loc, x.passes, x.hasScript, x.script, x.annotations);
}
template <class A>
void fields(A& a, TextureDesc& x) {
    a(x.parameter, x.kind, x.type, x.format, x.arraySize, x.samples, x.width, x.height, x.viewportRatio);
    a(x.mipLevels, x.resourceName, x.resolvedPath, x.seed, x.depth, x.fill, x.loc);
}
template <class A>
void fields(A& a, SamplerDesc& x) {
    a(x.parameter, x.texture, x.addressU, x.addressV, x.addressW, x.minFilter, x.magFilter, x.mipFilter);
    a(x.borderColor, x.maxAnisotropy, x.mipLodBias, x.minLod, x.maxLod, x.comparisonFunc, x.loc);
}
template <class A>
void fields(A& a, RefusedTechnique& x) {
    a(x.name, x.group, x.reason, x.loc);
}
template <class A>
void fields(A& a, StructMemberInfo& x) {
    a(x.name, x.type, x.semantic);
}
template <class A>
void fields(A& a, StructInfo& x) {
    a(x.name, x.members);
}
template <class A>
void fields(A& a, SemanticBinding& x) {
    a(x.kind, x.inverse, x.transpose, x.byName, x.eachLight, x.viewSpace, x.towardsLight, x.light);
}
template <class A>
void fields(A& a, BufferTexel& x) {
    a(x.component, x.components);
}
template <class A>
void fields(A& a, MemberBinding& x) {
    a(x.member, x.type, x.firstComponent, x.elementStride, x.standard);
}
template <class A>
void fields(A& a, ParameterInfo& x) {
    a(x.name, x.type, x.semantic, x.standard, x.isStatic, x.isShared, x.loc, x.light);
    a(x.hasParameterization, x.parameterization, x.parameterizationLoc, x.viewOf, x.elementCount);
    a(x.imageSize, x.imageFormat, x.bufferTexel, x.annotations, x.memberBindings);
}
template <class A>
void fields(A& a, EffectProvenance& x) {
    a(x.sourcePath, x.defines, x.includeDirs, x.compilerVersion);
}
template <class A>
void fields(A& a, CompiledEffect& x) {
    a(x.provenance, x.path, x.parameters, x.initialValues, x.structs, x.textures, x.samplers, x.passSamplers);
    a(x.techniques);
    a(x.refusedTechniques, x.hasGlobalScript, x.globalScript, x.sceneClass, x.lights, x.maxScriptLoopCount);
}

}  // namespace fx::detail
