// FxcDirectives: directive lines fxc accepted that glslang's preprocessor refuses, rewritten before it runs.
#include "FxcDirectives.h"

#include <cctype>
#include <charconv>
#include <map>
#include <optional>

namespace fx::detail {

namespace {

const char kMarker[] = "shadowfx_undefined_condition_call_";
const char kDefinitionMarker[] = "shadowfx_macro_definition_";

bool isIdentStart(char c) {
    return std::isalpha(static_cast<unsigned char>(c)) || c == '_';
}
bool isIdentChar(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}

// The lines of `text`, each without its '\n'.
std::vector<std::string> splitLines(const std::string& text) {
    std::vector<std::string> lines;
    size_t start = 0;
    while (start <= text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        lines.push_back(text.substr(start, end - start));
        start = end + 1;
    }
    return lines;
}

// Whether a block comment is still open at the end of `line`, given whether one was open at its start.
bool blockCommentOpenAfter(const std::string& line, bool open) {
    for (size_t i = 0; i < line.size(); ++i) {
        if (open) {
            if (line.compare(i, 2, "*/") == 0) open = false, ++i;
        } else if (line.compare(i, 2, "//") == 0) {
            return false;
        } else if (line.compare(i, 2, "/*") == 0) {
            open = true, ++i;
        } else if (line[i] == '"') {
            for (++i; i < line.size() && line[i] != '"'; ++i)
                if (line[i] == '\\') ++i;
        }
    }
    return open;
}

// A call `name(...)` in a condition: where the name starts, the name, and its argument count.
struct Call {
    size_t at;
    std::string name;
    int arity;
};

// The calls in the condition `line[from..]` (up to a `//` comment), `defined(...)` excepted.
std::vector<Call> callsIn(const std::string& line, size_t from) {
    std::vector<Call> calls;
    std::string previous;
    size_t i = from;
    while (i < line.size()) {
        if (line.compare(i, 2, "//") == 0) break;
        if (!isIdentStart(line[i])) {
            if (!std::isspace(static_cast<unsigned char>(line[i]))) previous.clear();
            if (std::isdigit(static_cast<unsigned char>(line[i])))
                while (i < line.size() && isIdentChar(line[i])) ++i;  // 1ul, 0x1F
            else
                ++i;
            continue;
        }
        const size_t begin = i;
        while (i < line.size() && isIdentChar(line[i])) ++i;
        const std::string name = line.substr(begin, i - begin);
        size_t next = line.find_first_not_of(" \t", i);
        if (name != "defined" && previous != "defined" && next != std::string::npos && line[next] == '(') {
            int depth = 0, commas = 0;
            bool empty = true;
            for (size_t k = next; k < line.size(); ++k) {
                const char c = line[k];
                if (c == '(') ++depth;
                if (c == ')' && --depth == 0) break;
                if (c == ',' && depth == 1) ++commas;
                if (depth >= 1 && c != '(' && !std::isspace(static_cast<unsigned char>(c))) empty = false;
            }
            calls.push_back({begin, name, empty ? 0 : commas + 1});
        }
        previous = name;
    }
    return calls;
}

std::string parameterList(int arity) {
    std::string list;
    for (int k = 0; k < arity; ++k) list += (k ? ",p" : "p") + std::to_string(k);
    return list;
}

// A #define's name, where it starts, and its parameter list and body with comments dropped and blanks
// collapsed (two definitions with equal keys are the same definition); `logical` is the whole directive,
// its continued lines joined.
struct Definition {
    std::string name;
    size_t at = 0;
    std::string key;
};

std::optional<Definition> definitionIn(const std::string& logical, size_t from) {
    Definition d;
    d.at = logical.find_first_not_of(" \t", from);
    if (d.at == std::string::npos || !isIdentStart(logical[d.at])) return std::nullopt;
    size_t end = d.at;
    while (end < logical.size() && isIdentChar(logical[end])) ++end;
    d.name = logical.substr(d.at, end - d.at);
    bool blank = false, inBlockComment = false;
    for (size_t i = end; i < logical.size(); ++i) {
        if (inBlockComment) {
            if (logical.compare(i, 2, "*/") == 0) inBlockComment = false, ++i, blank = true;
            continue;
        }
        if (logical.compare(i, 2, "//") == 0) break;
        if (logical.compare(i, 2, "/*") == 0) {
            inBlockComment = true, ++i;
            continue;
        }
        if (std::isspace(static_cast<unsigned char>(logical[i]))) {
            blank = true;
            continue;
        }
        if (blank && !d.key.empty()) d.key += ' ';
        blank = false;
        d.key += logical[i];
    }
    // `#define F(x) x` and `#define F (x) x` differ: only the first has parameters.
    d.key.insert(0, end < logical.size() && logical[end] == '(' ? "function " : "object ");
    return d;
}

// Takes the markers `#pragma <prefix>N` (N < count) out of glslang's output, calling `report(N)` for each.
// The effect may spell such a directive itself: only a marker this pass wrote (one of its numbers, nothing
// after it) is taken; any other line is the effect's pragma and stays.
template <typename Report>
void takeMarkers(std::string& preprocessed, const char* prefix, size_t count, Report report) {
    const std::string directive = std::string("#pragma ") + prefix;
    for (size_t at = preprocessed.find(directive); at != std::string::npos;
         at = preprocessed.find(directive, at)) {
        size_t end = preprocessed.find('\n', at);
        if (end == std::string::npos) end = preprocessed.size();
        const char* first = preprocessed.data() + at + directive.size();
        const char* last = preprocessed.data() + end;
        size_t number = 0;
        const auto [stop, error] = std::from_chars(first, last, number);
        if (error != std::errc() || stop != last || number >= count) {
            at = end;
            continue;
        }
        report(number);
        preprocessed.erase(at, end - at);
    }
}

}  // namespace

void FxcDirectives::predefine(const std::string& name, const std::string& body) {
    if (const std::optional<Definition> d = definitionIn(name + " " + body, 0)) mPredefined[d->name] = d->key;
}

std::string FxcDirectives::rewrite(const std::string& text, const std::string& file,
                                   DiagnosticSink& diagnostics) {
    const std::vector<std::string> lines = splitLines(text);
    std::string out;
    out.reserve(text.size());
    std::vector<int> extraEndifs;  // per open conditional: #endif lines its #elif rewrites opened
    bool inComment = false, continued = false;
    bool added = false;  // whether lines were added before this one
    for (size_t index = 0; index < lines.size(); ++index) {
        const std::string& line = lines[index];
        const int number = static_cast<int>(index) + 1;
        const bool last = index + 1 == lines.size();
        auto emit = [&](const std::string& piece) { out += piece + (last ? "" : "\n"); };
        const bool directiveLine = !inComment && !continued;
        inComment = blockCommentOpenAfter(line, inComment);
        continued = !line.empty() && (line.back() == '\\' || (line.size() > 1 && line.back() == '\r' &&
                                                              line[line.size() - 2] == '\\'));
        const size_t hash = line.find_first_not_of(" \t");
        if (!directiveLine || hash == std::string::npos || line[hash] != '#') {
            emit(line);
            continue;
        }
        const size_t wordAt = line.find_first_not_of(" \t", hash + 1);
        size_t wordEnd = wordAt;
        while (wordEnd < line.size() && isIdentChar(line[wordEnd])) ++wordEnd;
        const std::string word = wordAt == std::string::npos ? "" : line.substr(wordAt, wordEnd - wordAt);

        if (word == "include") {
            const size_t open = line.find_first_of("\"<", wordEnd);
            const size_t close =
                open == std::string::npos ? open : line.find(line[open] == '"' ? '"' : '>', open + 1);
            const size_t rest =
                close == std::string::npos ? close : line.find_first_not_of(" \t\r", close + 1);
            if (rest != std::string::npos && line.compare(rest, 2, "//") != 0 &&
                line.compare(rest, 2, "/*") != 0) {
                std::string trailing = line.substr(rest);
                while (!trailing.empty() && (trailing.back() == '\r' || trailing.back() == ' '))
                    trailing.pop_back();
                diagnostics.report(DiagId::IncludeTrailingText,
                                   SourceLoc{file, number, static_cast<int>(rest) + 1}, {trailing});
                emit(line.substr(0, close + 1));
                continue;
            }
            emit(line);
            continue;
        }
        if (word == "ifdef" || word == "ifndef") extraEndifs.push_back(0);
        // glslang does not count the lines of a region it skips (the #line after guards there is skipped
        // too): where it may resume, after #else, #elif and #endif, the numbering is set again.
        auto resynchronize = [&] {
            if (added && !last) out += "#line " + std::to_string(number + 1) + "\n";
        };
        if (word == "endif") {
            emit(line);
            if (!extraEndifs.empty()) {
                const int extra = extraEndifs.back();
                extraEndifs.pop_back();
                if (extra > 0) {
                    out += last ? "\n" : "";
                    for (int k = 0; k < extra; ++k) out += "#endif\n";
                    added = true;
                }
            }
            resynchronize();
            continue;
        }
        if (word == "else") {
            emit(line);
            resynchronize();
            continue;
        }
        if (word == "define") {
            // The whole directive, its continued lines joined (a '\\' and a '\r' before a line break are
            // blanks).
            std::string logical = line;
            for (size_t k = index + 1; k < lines.size(); ++k) {
                while (!logical.empty() && logical.back() == '\r') logical.pop_back();
                if (logical.empty() || logical.back() != '\\') break;
                logical.back() = ' ';
                logical += lines[k];
            }
            if (const std::optional<Definition> d = definitionIn(logical, wordEnd)) {
                // Marker 2 N + 1 where the macro is defined (it is undefined first), 2 N where it is not:
                // in glslang's output, the order the definitions ran in.
                added = true;
                out += "#ifdef " + d->name + "\n#pragma " + kDefinitionMarker +
                       std::to_string(2 * mDefinitions.size() + 1) + "\n#undef " + d->name +
                       "\n#else\n#pragma " + kDefinitionMarker + std::to_string(2 * mDefinitions.size()) +
                       "\n#endif\n#line " + std::to_string(number) + "\n";
                mDefinitions.push_back(
                    {SourceLoc{file, number, static_cast<int>(d->at) + 1}, d->name, d->key});
            }
            emit(line);
            continue;
        }
        if (word != "if" && word != "elif") {
            emit(line);
            continue;
        }
        if (word == "if") extraEndifs.push_back(0);
        const std::vector<Call> calls = callsIn(line, wordEnd);
        if (calls.empty()) {
            emit(line);
            if (word == "elif") resynchronize();
            continue;
        }
        added = true;
        // Each name gets an alias: the macro itself where it is defined, else a macro of the call's arity
        // that reads 0, next to the marker that says the condition read it so.
        std::string guards = word == "elif" ? "#else\n" : "";
        std::map<std::string, std::string> aliases;
        for (const Call& call : calls) {
            if (aliases.count(call.name)) continue;
            const std::string alias = "shadowfx_condition_call_" + std::to_string(mCalls.size());
            aliases[call.name] = alias;
            guards += "#ifdef " + call.name + "\n#define " + alias + " " + call.name + "\n#else\n#define " +
                      alias + "(" + parameterList(call.arity) + ") 0\n#pragma " + kMarker +
                      std::to_string(mCalls.size()) + "\n#endif\n";
            mCalls.push_back({SourceLoc{file, number, static_cast<int>(call.at) + 1}, call.name});
        }
        std::string condition =
            line.substr(0, hash) + "#if" + line.substr(wordEnd, calls.front().at - wordEnd);
        for (size_t k = 0; k < calls.size(); ++k) {
            const size_t after = calls[k].at + calls[k].name.size();
            const size_t next = k + 1 < calls.size() ? calls[k + 1].at : line.size();
            condition += aliases[calls[k].name] + line.substr(after, next - after);
        }
        if (word == "elif" && !extraEndifs.empty()) ++extraEndifs.back();
        out += guards + "#line " + std::to_string(number) + "\n";
        emit(condition);
    }
    return out;
}

void FxcDirectives::takeUndefinedCallMarkers(std::string& preprocessed, DiagnosticSink& diagnostics) const {
    takeMarkers(preprocessed, kMarker, mCalls.size(), [&](size_t number) {
        diagnostics.report(DiagId::UndefinedConditionCall, mCalls[number].loc, {mCalls[number].name});
    });
}

void FxcDirectives::takeRedefinitionMarkers(std::string& preprocessed, DiagnosticSink& diagnostics) const {
    std::map<std::string, std::string> inForce = mPredefined;  // each defined macro's key
    takeMarkers(preprocessed, kDefinitionMarker, 2 * mDefinitions.size(), [&](size_t number) {
        const MacroDefinition& d = mDefinitions[number / 2];
        const auto previous = inForce.find(d.name);
        // A macro defined where shadowfx saw no definition (none is known to be the same) warns too.
        if (number % 2 == 1 && (previous == inForce.end() || previous->second != d.key))
            diagnostics.report(DiagId::MacroRedefined, d.loc, {d.name});
        inForce[d.name] = d.key;
    });
}

std::string FxcDirectives::undefineGlslangPredefines() {
    // glslang's TParseVersions::getPreamble (12.0.0) for every profile and version, and the client
    // macros; an #undef of a name that this glslang does not define does nothing.
    static const char* const kPredefines[] = {
        "VULKAN",
        "GL_SPIRV",
        "GL_ES",
        "GL_core_profile",
        "GL_compatibility_profile",
        "GL_FRAGMENT_PRECISION_HIGH",
        "GL_OES_texture_3D",
        "GL_OES_standard_derivatives",
        "GL_EXT_frag_depth",
        "GL_OES_EGL_image_external",
        "GL_OES_EGL_image_external_essl3",
        "GL_EXT_YUV_target",
        "GL_EXT_shader_texture_lod",
        "GL_EXT_shadow_samplers",
        "GL_ANDROID_extension_pack_es31a",
        "GL_KHR_blend_equation_advanced",
        "GL_OES_sample_variables",
        "GL_OES_shader_image_atomic",
        "GL_OES_shader_multisample_interpolation",
        "GL_OES_texture_storage_multisample_2d_array",
        "GL_EXT_geometry_shader",
        "GL_EXT_geometry_point_size",
        "GL_EXT_gpu_shader5",
        "GL_EXT_primitive_bounding_box",
        "GL_EXT_shader_io_blocks",
        "GL_EXT_tessellation_shader",
        "GL_EXT_tessellation_point_size",
        "GL_EXT_texture_buffer",
        "GL_EXT_texture_cube_map_array",
        "GL_OES_geometry_shader",
        "GL_OES_geometry_point_size",
        "GL_OES_gpu_shader5",
        "GL_OES_primitive_bounding_box",
        "GL_OES_shader_io_blocks",
        "GL_OES_tessellation_shader",
        "GL_OES_tessellation_point_size",
        "GL_OES_texture_buffer",
        "GL_OES_texture_cube_map_array",
        "GL_EXT_shader_non_constant_global_initializers",
        "GL_NV_shader_noperspective_interpolation",
        "GL_ARB_texture_rectangle",
        "GL_ARB_shading_language_420pack",
        "GL_ARB_texture_gather",
        "GL_ARB_gpu_shader5",
        "GL_ARB_separate_shader_objects",
        "GL_ARB_compute_shader",
        "GL_ARB_tessellation_shader",
        "GL_ARB_enhanced_layouts",
        "GL_ARB_texture_cube_map_array",
        "GL_ARB_shader_texture_lod",
        "GL_ARB_explicit_attrib_location",
        "GL_ARB_explicit_uniform_location",
        "GL_ARB_shader_image_load_store",
        "GL_ARB_shader_atomic_counters",
        "GL_ARB_shader_draw_parameters",
        "GL_ARB_shader_group_vote",
        "GL_ARB_derivative_control",
        "GL_ARB_shader_texture_image_samples",
        "GL_ARB_viewport_array",
        "GL_ARB_gpu_shader_int64",
        "GL_ARB_shader_ballot",
        "GL_ARB_sparse_texture2",
        "GL_ARB_sparse_texture_clamp",
        "GL_ARB_shader_stencil_export",
        "GL_ARB_sample_shading",
        "GL_ARB_cull_distance",
        "GL_ARB_post_depth_coverage",
        "GL_ARB_fragment_shader_interlock",
        "GL_ARB_shader_viewport_layer_array",
        "GL_ARB_shader_clock",
        "GL_EXT_shader_image_load_formatted",
        "GL_EXT_post_depth_coverage",
        "GL_EXT_control_flow_attributes",
        "GL_EXT_nonuniform_qualifier",
        "GL_EXT_shader_16bit_storage",
        "GL_EXT_shader_8bit_storage",
        "GL_EXT_samplerless_texture_functions",
        "GL_EXT_scalar_block_layout",
        "GL_EXT_fragment_invocation_density",
        "GL_EXT_buffer_reference",
        "GL_EXT_buffer_reference2",
        "GL_EXT_buffer_reference_uvec2",
        "GL_EXT_demote_to_helper_invocation",
        "GL_EXT_debug_printf",
        "GL_EXT_fragment_shading_rate",
        "GL_EXT_shader_atomic_int64",
        "GL_EXT_shader_realtime_clock",
        "GL_EXT_ray_tracing",
        "GL_EXT_ray_query",
        "GL_EXT_ray_flags_primitive_culling",
        "GL_EXT_mesh_shader",
        "GL_EXT_shader_atomic_float",
        "GL_EXT_shader_atomic_float2",
        "GL_EXT_fragment_shader_barycentric",
        "GL_EXT_terminate_invocation",
        "GL_EXT_spirv_intrinsics",
        "GL_EXT_null_initializer",
        "GL_EXT_subgroup_uniform_control_flow",
        "GL_EXT_shared_memory_block",
        "GL_EXT_shader_image_int64",
        "GL_EXT_blend_func_extended",
        "GL_EXT_device_group",
        "GL_EXT_multiview",
        "GL_EXT_shader_explicit_arithmetic_types",
        "GL_EXT_shader_explicit_arithmetic_types_int8",
        "GL_EXT_shader_explicit_arithmetic_types_int16",
        "GL_EXT_shader_explicit_arithmetic_types_int32",
        "GL_EXT_shader_explicit_arithmetic_types_int64",
        "GL_EXT_shader_explicit_arithmetic_types_float16",
        "GL_EXT_shader_explicit_arithmetic_types_float32",
        "GL_EXT_shader_explicit_arithmetic_types_float64",
        "GL_EXT_shader_subgroup_extended_types_int8",
        "GL_EXT_shader_subgroup_extended_types_int16",
        "GL_EXT_shader_subgroup_extended_types_int64",
        "GL_EXT_shader_subgroup_extended_types_float16",
        "GL_KHR_shader_subgroup_basic",
        "GL_KHR_shader_subgroup_vote",
        "GL_KHR_shader_subgroup_arithmetic",
        "GL_KHR_shader_subgroup_ballot",
        "GL_KHR_shader_subgroup_shuffle",
        "GL_KHR_shader_subgroup_shuffle_relative",
        "GL_KHR_shader_subgroup_clustered",
        "GL_KHR_shader_subgroup_quad",
        "GL_KHR_memory_scope_semantics",
        "E_GL_EXT_shader_atomic_int64",
        "E_GL_EXT_shader_realtime_clock",
        "GL_AMD_shader_ballot",
        "GL_AMD_shader_trinary_minmax",
        "GL_AMD_shader_explicit_vertex_parameter",
        "GL_AMD_gcn_shader",
        "GL_AMD_gpu_shader_half_float",
        "GL_AMD_texture_gather_bias_lod",
        "GL_AMD_gpu_shader_int16",
        "GL_AMD_shader_image_load_store_lod",
        "GL_AMD_shader_fragment_mask",
        "GL_AMD_gpu_shader_half_float_fetch",
        "GL_INTEL_shader_integer_functions2",
        "GL_NV_sample_mask_override_coverage",
        "GL_NV_geometry_shader_passthrough",
        "GL_NV_viewport_array2",
        "GL_NV_stereo_view_rendering",
        "GL_NVX_multiview_per_view_attributes",
        "GL_NV_shader_atomic_int64",
        "GL_NV_conservative_raster_underestimation",
        "GL_NV_shader_subgroup_partitioned",
        "GL_NV_shading_rate_image",
        "GL_NV_ray_tracing",
        "GL_NV_ray_tracing_motion_blur",
        "GL_NV_fragment_shader_barycentric",
        "GL_NV_compute_shader_derivatives",
        "GL_NV_shader_texture_footprint",
        "GL_NV_mesh_shader",
        "GL_NV_cooperative_matrix",
        "GL_NV_integer_cooperative_matrix",
        "GL_NV_shader_sm_builtins",
        "GL_NV_shader_invocation_reorder",
        "GL_OVR_multiview",
        "GL_OVR_multiview2",
        "GL_GOOGLE_cpp_style_line_directive",
        "GL_GOOGLE_include_directive",
    };
    std::string lines;
    for (const char* name : kPredefines) lines += std::string("#undef ") + name + "\n";
    return lines;
}

}  // namespace fx::detail
