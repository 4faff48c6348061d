// SpirvToGlsl: SPIRV-Cross GLSL backend and reflection (see SpirvToGlsl.h).
#include "SpirvToGlsl.h"

#include "IntegerMatrixArrays.h"
#include "PassLowering.h"
#include "SemanticTables.h"

#include <spirv_cross/spirv_glsl.hpp>

#include <algorithm>
#include <map>
#include <regex>
#include <string_view>
#include <unordered_set>

namespace fx {

std::string spirvToGlslOptionsKey() {
    return "spirv-cross glsl450 core novk pairs finite-cube user-main int-matrix-rows";
}

namespace {

// The runs of bytes one element of type `type` occupies at `glOffset` in a GL block, in D3D order, each
// at `d3dCursor` in a D3D element (members packed at 4-byte alignment), which advances past them.
void storageRuns(const spirv_cross::CompilerGLSL& compiler, const spirv_cross::SPIRType& type,
                 uint32_t glOffset, uint32_t& d3dCursor, std::vector<StorageBufferBinding::Run>& runs) {
    auto add = [&](uint32_t gl, uint32_t bytes) {
        if (!runs.empty() && runs.back().d3dOffset + runs.back().bytes == d3dCursor &&
            runs.back().glOffset + runs.back().bytes == gl) {
            runs.back().bytes += bytes;
        } else {
            runs.push_back({d3dCursor, gl, bytes});
        }
        d3dCursor += bytes;
    };
    if (type.basetype != spirv_cross::SPIRType::Struct) {
        add(glOffset, type.vecsize * type.columns * std::max(type.width, 32u) / 8);
        return;
    }
    for (uint32_t i = 0; i < type.member_types.size(); ++i) {
        const spirv_cross::SPIRType& member = compiler.get_type(type.member_types[i]);
        const uint32_t offset = glOffset + compiler.type_struct_member_offset(type, i);
        uint32_t count = 1, stride = 0;
        const spirv_cross::SPIRType* element = &member;
        if (!member.array.empty()) {
            for (uint32_t dim : member.array) count *= std::max(dim, 1u);
            stride = compiler.type_struct_member_array_stride(type, i);
            while (!element->array.empty()) element = &compiler.get_type(element->parent_type);
        }
        for (uint32_t k = 0; k < count; ++k) {
            const uint32_t at = offset + k * stride;
            if (element->basetype == spirv_cross::SPIRType::Struct) {
                storageRuns(compiler, *element, at, d3dCursor, runs);
            } else if (element->columns > 1) {
                // A matrix: its contiguous vectors (HLSL's columns, or its rows when row_major) in turn.
                const bool rowMajor = compiler.has_member_decoration(type.self, i, spv::DecorationRowMajor);
                const uint32_t vectors = rowMajor ? element->vecsize : element->columns;
                const uint32_t bytes = (rowMajor ? element->columns : element->vecsize) * 4;
                const uint32_t matrixStride = compiler.type_struct_member_matrix_stride(type, i);
                for (uint32_t v = 0; v < vectors; ++v) add(at + v * matrixStride, bytes);
            } else {
                add(at, element->vecsize * std::max(element->width, 32u) / 8);
            }
        }
    }
}

// The type of an array's elements (of every dimension); `type` itself if it is no array.
const spirv_cross::SPIRType& arrayElement(const spirv_cross::CompilerGLSL& compiler,
                                          const spirv_cross::SPIRType& type) {
    const spirv_cross::SPIRType* element = &type;
    while (!element->array.empty()) element = &compiler.get_type(element->parent_type);
    return *element;
}

// Where a block member's matrix is: its stride between vectors, whether they are HLSL's columns, and the
// stride of an array of such matrices (0 for one). An integer matrix is an array of its rows since
// IntegerMatrixArrays: its rows' stride is its matrix stride, and an array of them is the outer array.
struct MatrixPlacement {
    uint32_t matrixStride = 0;
    bool hlslColumnsContiguous = false;
    uint32_t arrayStride = 0;
};

MatrixPlacement matrixPlacement(const spirv_cross::CompilerGLSL& compiler, const spirv_cross::SPIRType& type,
                                uint32_t member, const detail::IntegerMatrixLowering& lowered) {
    const spirv_cross::SPIRType& memberType = compiler.get_type(type.member_types[member]);
    MatrixPlacement placement;
    if (const auto rows = lowered.members.find({type.self, member}); rows != lowered.members.end()) {
        placement.matrixStride = rows->second.rowStride;
        if (memberType.array.size() > 1)
            placement.arrayStride = compiler.type_struct_member_array_stride(type, member);
        return placement;
    }
    if (!memberType.array.empty())
        placement.arrayStride = compiler.type_struct_member_array_stride(type, member);
    if (memberType.columns > 1) {
        placement.matrixStride = compiler.type_struct_member_matrix_stride(type, member);
        // glslang declares HLSL column_major matrices RowMajor (the GLSL matrix is the HLSL one
        // transposed, so its rows are HLSL's columns): RowMajor => HLSL columns contiguous.
        placement.hlslColumnsContiguous =
            compiler.has_member_decoration(type.self, member, spv::DecorationRowMajor);
    }
    return placement;
}

// The numeric members of one element of struct `type` as a uniform block lays them out, at `base` bytes
// from the block member, named by `path` and their member names (UniformField).
void structFields(const spirv_cross::CompilerGLSL& compiler, const spirv_cross::SPIRType& type, uint32_t base,
                  const std::string& path, const detail::IntegerMatrixLowering& lowered,
                  std::vector<UniformField>& fields) {
    for (uint32_t i = 0; i < type.member_types.size(); ++i) {
        const spirv_cross::SPIRType& member = compiler.get_type(type.member_types[i]);
        const uint32_t offset = base + compiler.type_struct_member_offset(type, i);
        const std::string name = path + "." + compiler.get_member_name(type.self, i);
        if (member.basetype == spirv_cross::SPIRType::Struct) {
            // Each element of an array of structs has fields of its own: "[k]" counts the elements of
            // every dimension in turn, as the host's value holds them.
            uint32_t count = 1, stride = 0;
            if (!member.array.empty()) {
                for (uint32_t dim : member.array) count *= std::max(dim, 1u);
                stride = compiler.type_struct_member_array_stride(type, i);
            }
            for (uint32_t k = 0; k < count; ++k)
                structFields(compiler, arrayElement(compiler, member), offset + k * stride,
                             member.array.empty() ? name : name + "[" + std::to_string(k) + "]", lowered,
                             fields);
            continue;
        }
        UniformField field;
        field.path = name;
        field.offset = offset;
        const MatrixPlacement placement = matrixPlacement(compiler, type, i, lowered);
        field.arrayStride = placement.arrayStride;
        field.matrixStride = placement.matrixStride;
        field.hlslColumnsContiguous = placement.hlslColumnsContiguous;
        fields.push_back(std::move(field));
    }
}

// GLSL's layout qualifier of a storage image's format, as the runtime reads it (GpuTexture's image formats).
std::string imageFormatQualifier(spv::ImageFormat format) {
    switch (format) {
        case spv::ImageFormatRgba32f:
            return "rgba32f";
        case spv::ImageFormatRgba16f:
            return "rgba16f";
        case spv::ImageFormatRg32f:
            return "rg32f";
        case spv::ImageFormatRg16f:
            return "rg16f";
        case spv::ImageFormatR32f:
            return "r32f";
        case spv::ImageFormatR16f:
            return "r16f";
        case spv::ImageFormatRgba8:
            return "rgba8";
        case spv::ImageFormatRgba32ui:
            return "rgba32ui";
        case spv::ImageFormatRg32ui:
            return "rg32ui";
        case spv::ImageFormatR32ui:
            return "r32ui";
        case spv::ImageFormatRgba32i:
            return "rgba32i";
        case spv::ImageFormatRg32i:
            return "rg32i";
        case spv::ImageFormatR32i:
            return "r32i";
        default:
            return "";
    }
}

// Mesa's llvmpipe crashes on a cube-map lookup whose direction is not finite (a normalized zero vector,
// interpolated): every lookup of a cube sampler of `samplers` takes its direction through a helper that
// makes such a direction +z. A finite direction passes unchanged, so no image changes; D3D9 hardware read
// some texel there.
void guardCubeDirections(std::string& glsl, const std::vector<std::string>& samplers) {
    if (samplers.empty()) return;
    static const std::regex kLookup(R"(\b(texture|textureLod|textureGrad|textureGather)\(\s*(\w+)\s*,)");
    std::string out;
    size_t copied = 0;
    for (auto m = std::sregex_iterator(glsl.begin(), glsl.end(), kLookup); m != std::sregex_iterator(); ++m) {
        if (std::find(samplers.begin(), samplers.end(), (*m)[2].str()) == samplers.end()) continue;
        const size_t start = static_cast<size_t>(m->position(0) + m->length(0));
        if (start < copied) continue;
        size_t end = start;
        for (int depth = 0; end < glsl.size(); ++end) {
            const char c = glsl[end];
            if (c == '(' || c == '[') ++depth;
            if ((c == ')' || c == ']') && depth-- == 0) break;
            if (c == ',' && depth == 0) break;
        }
        const size_t argument = glsl.find_first_not_of(" \t\n", start);
        out.append(glsl, copied, argument - copied);
        out += "fx_finite_direction(" + glsl.substr(argument, end - argument) + ")";
        copied = end;
    }
    if (copied == 0) return;
    out.append(glsl, copied, std::string::npos);
    // After the #version and #extension lines.
    size_t at = 0;
    while (at < out.size() && out[at] == '#') at = out.find('\n', at) + 1;
    out.insert(at,
               "vec3 fx_finite_direction(vec3 d) { return any(isnan(d)) || any(isinf(d)) ? vec3(0.0, 0.0, "
               "1.0) : d; }\n"
               "vec4 fx_finite_direction(vec4 d) { return vec4(fx_finite_direction(d.xyz), d.w); }\n");
    glsl = std::move(out);
}

// What the stage does besides computing its outputs: its instructions (a discard, an image store, an
// atomic), its builtin outputs and its storage blocks.
StageEffects stageEffects(const std::vector<uint32_t>& spirv, const spirv_cross::CompilerGLSL& compiler,
                          const spirv_cross::ShaderResources& resources, ShaderStage stage) {
    StageEffects effects;
    for (size_t at = 5; at < spirv.size();) {
        const uint32_t words = spirv[at] >> 16;
        const auto opcode = static_cast<spv::Op>(spirv[at] & 0xffff);
        if (words == 0) break;
        at += words;
        switch (opcode) {
            case spv::OpKill:
            case spv::OpTerminateInvocation:
            case spv::OpDemoteToHelperInvocationEXT:
                effects.discards = true;
                break;
            case spv::OpImageWrite:
                effects.writesImages = true;
                break;
            case spv::OpAtomicLoad:
            case spv::OpAtomicStore:
            case spv::OpAtomicExchange:
            case spv::OpAtomicCompareExchange:
            case spv::OpAtomicCompareExchangeWeak:
            case spv::OpAtomicIIncrement:
            case spv::OpAtomicIDecrement:
            case spv::OpAtomicIAdd:
            case spv::OpAtomicISub:
            case spv::OpAtomicSMin:
            case spv::OpAtomicUMin:
            case spv::OpAtomicSMax:
            case spv::OpAtomicUMax:
            case spv::OpAtomicAnd:
            case spv::OpAtomicOr:
            case spv::OpAtomicXor:
                effects.atomics = true;
                break;
            default:
                break;
        }
    }
    for (const spirv_cross::BuiltInResource& output : resources.builtin_outputs) {
        switch (output.builtin) {
            case spv::BuiltInFragDepth:
                effects.writesDepth = true;
                break;
            case spv::BuiltInSampleMask:
                effects.writesSampleMask = true;
                break;
            case spv::BuiltInPointSize:
                effects.writesPointSize = true;
                break;
            case spv::BuiltInClipDistance: {
                const spirv_cross::SPIRType& type = compiler.get_type(output.value_type_id);
                effects.clipDistances =
                    type.array.empty() ? 1 : static_cast<int>(std::min(type.array[0], 8u));
                break;
            }
            default:
                break;
        }
    }
    // A block the code may write is one not declared NonWritable (a StructuredBuffer's is).
    for (const spirv_cross::Resource& r : resources.storage_buffers)
        if (!compiler.get_buffer_block_flags(r.id).get(spv::DecorationNonWritable))
            effects.writesBuffers = true;
    if (stage == ShaderStage::Vertex)
        for (const spirv_cross::Resource& r : resources.stage_outputs)
            if (compiler.has_decoration(r.id, spv::DecorationLocation) &&
                static_cast<int>(compiler.get_decoration(r.id, spv::DecorationLocation)) ==
                    *varyingLocation("COLOR0"))
                effects.writesDiffuse = true;
    return effects;
}

// GLSL reserves `main` for the entry point, and D3DX compiled any function as a shader: XNA's sprite
// effects name their pixel shader `main`. That function, which the stage's wrapper calls, would come out as
// a second main() that the GL driver refuses; it gets a name of its own.
void renameUserMain(spirv_cross::CompilerGLSL& compiler, const std::vector<uint32_t>& spirv) {
    constexpr uint32_t kOpEntryPoint = 15;
    constexpr uint32_t kOpFunction = 54;
    constexpr size_t kHeaderWords = 5;
    std::vector<uint32_t> entries;
    std::vector<uint32_t> functions;
    for (size_t at = kHeaderWords; at < spirv.size();) {
        const uint32_t words = spirv[at] >> 16;
        const uint32_t opcode = spirv[at] & 0xffff;
        if (words == 0 || at + words > spirv.size()) break;
        if (opcode == kOpEntryPoint && words > 2) entries.push_back(spirv[at + 2]);
        if (opcode == kOpFunction && words > 2) functions.push_back(spirv[at + 2]);
        at += words;
    }
    for (uint32_t id : functions) {
        if (std::find(entries.begin(), entries.end(), id) != entries.end()) continue;
        const std::string& name = compiler.get_name(id);
        if (name == "main" || name.rfind("main(", 0) == 0) compiler.set_name(id, "fx_user_main");
    }
}

}  // namespace

bool spirvToGlsl(const std::vector<uint32_t>& glslangSpirv, ShaderStage stage, const CrossOptions& options,
                 StageProgram& program, std::string& error) {
    try {
        std::vector<uint32_t> spirv = glslangSpirv;
        const detail::IntegerMatrixLowering loweredMatrices = detail::lowerIntegerMatrices(spirv);
        if (!loweredMatrices.error.empty()) {
            error = loweredMatrices.error;
            return false;
        }
        spirv_cross::CompilerGLSL compiler(spirv);
        spirv_cross::CompilerGLSL::Options glsl;
        glsl.version = 450;
        glsl.es = false;
        glsl.vulkan_semantics = false;
        // Clip space stays D3D's (z in [0,1], y up): the runtime sets glClipControl accordingly.
        glsl.vertex.fixup_clipspace = false;
        glsl.vertex.flip_vert_y = false;
        glsl.enable_420pack_extension = true;
        compiler.set_common_options(glsl);
        renameUserMain(compiler, spirv);
        // The runtime sets glClipControl(GL_UPPER_LEFT), which already makes gl_FragCoord top-down; an
        // origin_upper_left redeclaration on top would flip it back.
        if (stage == ShaderStage::Fragment) compiler.unset_execution_mode(spv::ExecutionModeOriginUpperLeft);

        // DX9 sampler2D is already a combined sampler; the depth-compare pairs (Texture2D fx_depth_S +
        // SamplerComparisonState fx_cmp_S) become one sampler2DShadow, renamed back to S.
        // Texture2D.Load (texelFetch) samples with no sampler: GLSL still needs a combined one.
        const spirv_cross::VariableID loadSampler = compiler.build_dummy_sampler_for_combined_images();
        compiler.build_combined_image_samplers();
        // What the entry point reaches: a declared sampler outside it is one the stage does not read. (The
        // combined samplers built above are made for the samples the code takes, so all are read.)
        const std::unordered_set<spirv_cross::VariableID> reached = compiler.get_active_interface_variables();
        program.samplers.clear();
        for (const spirv_cross::CombinedImageSampler& c : compiler.get_combined_image_samplers()) {
            std::string image = compiler.get_name(c.image_id);
            if (image.rfind("fx_depth_", 0) != 0) {
                // A D3D10 (texture, sampler) pair: one GL sampler per pair the code uses; the effect
                // compiler gives it a unit once every stage of the pass is known (no binding here).
                SamplerBinding s;
                s.pairTexture = image;
                s.pairSampler = c.sampler_id == loadSampler ? "" : compiler.get_name(c.sampler_id);
                s.depthCompare = compiler.get_type_from_variable(c.combined_id).image.depth;
                std::string name = "fx_pair_" + image + "_" +
                                   (s.pairSampler.empty() ? "load" : s.pairSampler) +
                                   (s.depthCompare ? "_cmp" : "");
                for (size_t at = name.find("__"); at != std::string::npos; at = name.find("__"))
                    name.replace(at, 2, "_u_");  // GLSL reserves names with "__"
                compiler.set_name(c.combined_id, name);
                s.glslName = name;
                s.unit = -1;
                program.samplers.push_back(s);
                continue;
            }
            std::string name = image.rfind("fx_depth_", 0) == 0 ? image.substr(9) : image;
            compiler.set_name(c.combined_id, name);
            auto unit = options.samplerUnits.find(name);
            int binding = unit == options.samplerUnits.end() ? 0 : unit->second;
            compiler.set_decoration(c.combined_id, spv::DecorationBinding, static_cast<uint32_t>(binding));
            SamplerBinding s;
            s.glslName = name;
            s.unit = binding;
            s.depthCompare = image.rfind("fx_depth_", 0) == 0;
            program.samplers.push_back(s);
        }
        spirv_cross::ShaderResources resources = compiler.get_shader_resources();
        for (const spirv_cross::Resource& r : resources.sampled_images) {
            std::string name = compiler.get_name(r.id);
            auto unit = options.samplerUnits.find(name);
            int binding = unit == options.samplerUnits.end() ? 0 : unit->second;
            compiler.set_decoration(r.id, spv::DecorationBinding, static_cast<uint32_t>(binding));
            bool known = false;
            for (const SamplerBinding& s : program.samplers) known |= s.glslName == name;
            if (known) continue;
            SamplerBinding s;
            s.glslName = name;
            s.unit = binding;
            s.read = reached.count(r.id) > 0;
            program.samplers.push_back(s);
        }

        // Buffer<T>: a texel buffer that GLSL reads as a samplerBuffer (texelFetch); like a pair without a
        // sampler, it gets a unit of the pass's.
        for (const spirv_cross::Resource& r : resources.separate_images) {
            if (compiler.get_type(r.type_id).image.dim != spv::DimBuffer) continue;
            SamplerBinding s;
            s.glslName = compiler.get_name(r.id);
            s.pairTexture = s.glslName;
            s.unit = -1;
            s.read = reached.count(r.id) > 0;
            program.samplers.push_back(s);
        }
        program.storageBuffers.clear();
        // Every block is declared at its parameter's binding point (CrossOptions::storageBindings), which
        // the runtime binds the parameter's buffer to.
        const auto bindingOf = [](const std::map<std::string, int>& bindings, const std::string& name) {
            const auto at = bindings.find(name);
            return at == bindings.end() ? -1 : at->second;
        };
        // An AppendStructuredBuffer's or ConsumeStructuredBuffer's counter (and a RWStructuredBuffer's
        // IncrementCounter) is a block of its own, which glslang names "<buffer>@count": one uint.
        std::map<std::string, int> counterBindings;  // by buffer name
        constexpr std::string_view kCounterSuffix = "@count";
        for (const spirv_cross::Resource& r : resources.storage_buffers) {
            const std::string name = compiler.get_name(r.id);
            if (name.size() <= kCounterSuffix.size() ||
                name.compare(name.size() - kCounterSuffix.size(), kCounterSuffix.size(), kCounterSuffix) != 0)
                continue;
            const std::string buffer = name.substr(0, name.size() - kCounterSuffix.size());
            const int binding = bindingOf(options.counterBindings, buffer);
            if (binding < 0) continue;
            counterBindings[buffer] = binding;
            // "@" is no GLSL identifier character; fx_ names are the generator's own.
            compiler.set_name(r.id, "fx_counter_" + buffer);
            compiler.set_name(r.base_type_id, std::string());  // the block named after it, as below
            compiler.set_decoration(r.id, spv::DecorationBinding, static_cast<uint32_t>(binding));
        }
        for (const spirv_cross::Resource& r : resources.storage_buffers) {
            // glslang's block for a StructuredBuffer<T> or ByteAddressBuffer holds one runtime array of T.
            const spirv_cross::SPIRType& block = compiler.get_type(r.base_type_id);
            const std::string name = compiler.get_name(r.id);
            const int binding = bindingOf(options.storageBindings, name);
            if (binding < 0 || block.member_types.size() != 1 ||
                compiler.get_type(block.member_types[0]).array.empty())
                continue;
            // Buffers of one element type share one SPIR-V block type: left unnamed, the type gives each
            // GLSL block its buffer's name, which GL matches between the stages of a program.
            compiler.set_name(r.base_type_id, std::string());
            compiler.set_decoration(r.id, spv::DecorationBinding, static_cast<uint32_t>(binding));
            StorageBufferBinding b;
            b.glslName = name;
            b.binding = binding;
            b.glStride = compiler.type_struct_member_array_stride(block, 0);
            const spirv_cross::SPIRType& array = compiler.get_type(block.member_types[0]);
            storageRuns(compiler, compiler.get_type(array.parent_type), 0, b.d3dStride, b.runs);
            if (auto counter = counterBindings.find(name); counter != counterBindings.end())
                b.counterBinding = counter->second;
            program.storageBuffers.push_back(std::move(b));
        }

        // RWTexture2D<T>: a storage image; glslang gives it T's format (float4: rgba32f, float: r32f,
        // uint: r32ui, ...), which the runtime creates the texture in.
        program.images.clear();
        for (const spirv_cross::Resource& r : resources.storage_images) {
            ImageBinding image;
            image.glslName = compiler.get_name(r.id);
            image.format = imageFormatQualifier(compiler.get_type(r.type_id).image.format);
            program.images.push_back(std::move(image));
        }

        program.uniforms.clear();
        program.uniformBlockName.clear();
        program.uniformBlockBinding = -1;
        program.uniformBlockSize = 0;
        for (const spirv_cross::Resource& r : resources.uniform_buffers) {
            const spirv_cross::SPIRType& type = compiler.get_type(r.base_type_id);
            compiler.set_name(r.base_type_id, options.uniformBlockName);
            compiler.set_name(r.id, options.uniformBlockName + "_");
            compiler.set_decoration(r.id, spv::DecorationBinding,
                                    static_cast<uint32_t>(options.uniformBlockBinding));
            program.uniformBlockName = options.uniformBlockName;
            program.uniformBlockBinding = options.uniformBlockBinding;
            program.uniformBlockSize = static_cast<uint32_t>(compiler.get_declared_struct_size(type));
            const spirv_cross::SmallVector<spirv_cross::BufferRange> active =
                compiler.get_active_buffer_ranges(r.id);
            for (uint32_t i = 0; i < type.member_types.size(); ++i) {
                const spirv_cross::SPIRType& member = compiler.get_type(type.member_types[i]);
                UniformBinding u;
                u.name = compiler.get_member_name(type.self, i);
                u.offset = compiler.type_struct_member_offset(type, i);
                u.size = static_cast<uint32_t>(compiler.get_declared_struct_member_size(type, i));
                const MatrixPlacement placement = matrixPlacement(compiler, type, i, loweredMatrices);
                u.arrayStride = placement.arrayStride;
                u.matrixStride = placement.matrixStride;
                u.hlslColumnsContiguous = placement.hlslColumnsContiguous;
                u.active =
                    std::any_of(active.begin(), active.end(),
                                [i](const spirv_cross::BufferRange& range) { return range.index == i; });
                if (member.basetype == spirv_cross::SPIRType::Struct) {
                    uint32_t count = 1;
                    for (uint32_t dim : member.array) count *= std::max(dim, 1u);
                    for (uint32_t k = 0; k < count; ++k)
                        structFields(compiler, arrayElement(compiler, member), k * u.arrayStride,
                                     member.array.empty() ? "" : "[" + std::to_string(k) + "]",
                                     loweredMatrices, u.fields);
                }
                program.uniforms.push_back(u);
            }
            break;  // one $Global block per unit
        }

        // A geometry shader's array output (`float4 Face[2] : FACEDATA`, GeometryWrapper.cpp) comes from
        // glslang as one output per element ("fx_stream.Face[1]"), every one at the array's location:
        // element k goes to the location after it by k, where the next stage reads it.
        if (stage == ShaderStage::Geometry) {
            std::map<uint32_t, int> atLocation;
            for (const spirv_cross::Resource& r : resources.stage_outputs)
                if (compiler.has_decoration(r.id, spv::DecorationLocation))
                    ++atLocation[compiler.get_decoration(r.id, spv::DecorationLocation)];
            // Nine digits at most: more would be no element of an array a stage can output.
            static const std::regex kElement(R"((?:\[(\d{1,9})\]|_(\d{1,9})_)$)");
            for (const spirv_cross::Resource& r : resources.stage_outputs) {
                std::smatch element;
                if (!compiler.has_decoration(r.id, spv::DecorationLocation)) continue;
                const uint32_t location = compiler.get_decoration(r.id, spv::DecorationLocation);
                if (atLocation[location] > 1 && std::regex_search(r.name, element, kElement))
                    compiler.set_decoration(r.id, spv::DecorationLocation,
                                            location + static_cast<uint32_t>(std::stoul(
                                                           element[element[1].matched ? 1 : 2].str())));
            }
        }

        program.inputs.clear();
        if (stage == ShaderStage::Vertex) {
            for (const spirv_cross::Resource& r : resources.stage_inputs) {
                if (!compiler.has_decoration(r.id, spv::DecorationLocation)) continue;
                int location = static_cast<int>(compiler.get_decoration(r.id, spv::DecorationLocation));
                const spirv_cross::SPIRType& t = compiler.get_type(r.type_id);
                const std::optional<VertexStreamSlot> stream = vertexStreamAt(location);
                if (!stream) continue;  // the lowering declares attributes at the table's locations only
                program.inputs.push_back(VertexInput{vertexInputSemantic(location), location,
                                                     static_cast<int>(t.vecsize), *stream});
                // Attribute names say their semantic, for anyone reading the GLSL or a GL debugger.
                compiler.set_name(r.id, "fx_attr_" + vertexInputSemantic(location));
            }
        }

        program.effects = stageEffects(spirv, compiler, resources, stage);
        program.glsl = compiler.compile();
        std::vector<std::string> cubeSamplers;
        for (const spirv_cross::Resource& r : compiler.get_shader_resources().sampled_images)
            if (compiler.get_type(r.type_id).image.dim == spv::DimCube)
                cubeSamplers.push_back(compiler.get_name(r.id));
        guardCubeDirections(program.glsl, cubeSamplers);
        // Belt and braces for the comment above: SPIRV-Cross versions differ in when they emit this.
        program.glsl = std::regex_replace(
            program.glsl, std::regex(R"(layout\(origin_upper_left\) in vec4 gl_FragCoord;\n)"), "");
        return true;
    } catch (const std::exception& e) {
        error = e.what();
        return false;
    } catch (...) {  // every throw is a diagnostic, whatever SPIRV-Cross (or the allocator) throws
        error = "SPIRV-Cross threw an exception that is not a std::exception";
        return false;
    }
}

bool declareBinding(std::string& glsl, std::string_view name, int binding) {
    const std::string qualifier = "binding = " + std::to_string(binding);
    for (size_t start = 0; start < glsl.size();) {
        size_t end = glsl.find('\n', start);
        if (end == std::string::npos) end = glsl.size();
        const std::string_view line(glsl.data() + start, end - start);
        // `[layout(...) ]uniform [qualifiers ]type name[[N]];`: the name is the last word, before any array
        // dimensions.
        const bool declaration =
            line.rfind("uniform ", 0) == 0 ||
            (line.rfind("layout(", 0) == 0 && line.find(") uniform ") != std::string_view::npos);
        if (declaration && line.size() > 1 && line.back() == ';') {
            const size_t wordStart = line.rfind(' ') + 1;
            std::string_view declared = line.substr(wordStart, line.size() - 1 - wordStart);
            declared = declared.substr(0, declared.find('['));
            if (declared == name) {
                if (line.rfind("layout(", 0) != 0) {
                    glsl.insert(start, "layout(" + qualifier + ") ");
                    return true;
                }
                const size_t close = line.find(')');
                const std::string_view inside = line.substr(7, close - 7);
                const size_t at = inside.find("binding = ");
                if (at == std::string_view::npos) {
                    glsl.insert(start + 7, qualifier + ", ");
                    return true;
                }
                size_t digits = at + 10;
                while (digits < inside.size() && inside[digits] >= '0' && inside[digits] <= '9') ++digits;
                glsl.replace(start + 7 + at, digits - at, qualifier);
                return true;
            }
        }
        start = end + 1;
    }
    return false;
}

void declareDualSourceOutput(std::string& fragmentGlsl) {
    fragmentGlsl = std::regex_replace(fragmentGlsl, std::regex(R"(layout\(location = 1\) out )"),
                                      "layout(location = 0, index = 1) out ");
}

}  // namespace fx
