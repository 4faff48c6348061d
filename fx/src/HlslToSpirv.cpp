// HlslToSpirv: glslang's HLSL front end, configured as TOOLCHAIN.md prescribes (see HlslToSpirv.h).
#include "HlslToSpirv.h"

#include "BoolCompoundAssignments.h"
#include "ConstantMatrixProducts.h"
#include "ElementWiseProducts.h"
#include "IntegerMatrixSplitting.h"
#include "MatrixSwizzles.h"
#include "MulOperands.h"
#include "PostfixOperands.h"

#include <glslang/Include/intermediate.h>
#include <glslang/MachineIndependent/localintermediate.h>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include <algorithm>
#include <functional>
#include <memory>
#include <mutex>
#include <regex>
#include <set>
#include <sstream>

namespace fx {

namespace {

// glslang keeps process-wide tables; initialised once, never finalised (tests and the runtime may compile
// from several places).
void initGlslang() {
    static std::once_flag once;
    std::call_once(once, [] { glslang::InitializeProcess(); });
}

constexpr EShMessages kMessages = static_cast<EShMessages>(
    EShMsgReadHlsl |           // HLSL grammar and semantics
    EShMsgHlslDX9Compatible |  // sampler2D is a combined sampler, tex2D/tex2Dproj exist
    EShMsgSpvRules |           // SPIR-V output
    EShMsgVulkanRules);        // HLSL input only works under Vulkan client semantics
// glslang 12.0.0 has no EShMsgDisplayErrorColumn (later releases do): it reports file:line only, and the
// effect compiler recovers the column from the token the message quotes.

}  // namespace

std::string hlslToSpirvOptionsKey() {
    return "glslang-hlsl dx9 vulkan1.0 spv1.0 swizzle-writes int-matrix-rows bool-assign prefix-steps msgs=" +
           std::to_string(static_cast<int>(kMessages));
}

std::vector<HlslMessage> parseGlslangLog(const std::string& log) {
    std::vector<HlslMessage> out;
    // The file may itself contain ':' (a Windows path), so the numbers are matched from the right.
    static const std::regex withColumn(R"(^(ERROR|WARNING): (.*):(\d+):(\d+): (.*)$)");
    static const std::regex withLine(R"(^(ERROR|WARNING): (.*):(\d+): (.*)$)");
    static const std::regex bare(R"(^(ERROR|WARNING): (.*)$)");
    std::istringstream in(log);
    std::string line;
    std::smatch m;
    while (std::getline(in, line)) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        HlslMessage msg;
        if (std::regex_match(line, m, withColumn)) {
            msg = {m[1] == "ERROR", m[2], std::stoi(m[3]), std::stoi(m[4]), m[5]};
        } else if (std::regex_match(line, m, withLine)) {
            msg = {m[1] == "ERROR", m[2], std::stoi(m[3]), 0, m[4]};
        } else if (std::regex_match(line, m, bare)) {
            // "ERROR: 2 compilation errors.  No code generated." repeats what the lines above said.
            if (line.find("compilation errors") != std::string::npos ||
                line.find("compilation terminated") != std::string::npos)
                continue;
            msg = {m[1] == "ERROR", "", 0, 0, m[2]};
        } else {
            continue;
        }
        out.push_back(std::move(msg));
    }
    return out;
}

namespace {

// Whether the module declares a function-local variable of an image, sampler or sampled-image type.
bool hasOpaqueTemporaries(const std::vector<uint32_t>& spirv) {
    constexpr uint32_t kOpTypeImage = 25, kOpTypeSampler = 26, kOpTypeSampledImage = 27, kOpTypePointer = 32,
                       kOpVariable = 59, kStorageFunction = 7;
    std::set<uint32_t> opaque, opaquePointers;
    for (size_t at = 5; at < spirv.size();) {
        const uint32_t opcode = spirv[at] & 0xffff, words = spirv[at] >> 16;
        if (words == 0 || at + words > spirv.size()) break;
        if ((opcode == kOpTypeImage || opcode == kOpTypeSampler || opcode == kOpTypeSampledImage) &&
            words > 1)
            opaque.insert(spirv[at + 1]);
        else if (opcode == kOpTypePointer && words > 3 && spirv[at + 2] == kStorageFunction &&
                 opaque.count(spirv[at + 3]))
            opaquePointers.insert(spirv[at + 1]);
        else if (opcode == kOpVariable && words > 3 && opaquePointers.count(spirv[at + 1]))
            return true;
        at += words;
    }
    return false;
}

// The vector truncations glslang's HLSL front end makes without a word where fxc warned (X3206): a
// `float4` assigned, returned or passed as a `float3` or a `float`. glslang writes each as a constructor
// of the smaller type standing where its operand stands; a constructor the code spells (`float3(v)`, a
// cast) stands at its type's name instead.
class TruncationFinder : public glslang::TIntermTraverser {
public:
    std::vector<HlslMessage> found;

    bool visitAggregate(glslang::TVisit, glslang::TIntermAggregate* node) override {
        if (!node->isConstructor() || node->getSequence().size() != 1) return true;
        const glslang::TIntermTyped* operand = node->getSequence()[0]->getAsTyped();
        const glslang::TType& to = node->getType();
        if (!operand || to.isArray() || to.isStruct() || to.isMatrix()) return true;
        const glslang::TType& from = operand->getType();
        if (from.isArray() || from.isStruct() || from.isMatrix() ||
            from.getVectorSize() <= to.getVectorSize())
            return true;
        const glslang::TSourceLoc& at = node->getLoc();
        const glslang::TSourceLoc& operandAt = operand->getLoc();
        if (at.line != operandAt.line || at.column != operandAt.column || at.string != operandAt.string)
            return true;
        const auto name = [](const glslang::TType& type) {
            const std::string base = type.getBasicTypeString().c_str();
            return type.getVectorSize() > 1 ? base + std::to_string(type.getVectorSize()) : base;
        };
        found.push_back(
            {false, at.getFilenameStr(), at.line, at.column,
             std::string(kImplicitTruncationPrefix) + "'" + name(from) + "' to '" + name(to) + "'"});
        return true;
    }
};

// The highest id of the symbols of a tree.
class HighestSymbolId : public glslang::TIntermTraverser {
public:
    long long highest = 0;

    void visitSymbol(glslang::TIntermSymbol* symbol) override {
        highest = std::max(highest, symbol->getId());
    }
};

// Parses `source` into `shader` (whose stage is set) with the settings every unit is compiled with.
bool parseHlsl(glslang::TShader& shader, const std::string& source, const std::string& entryPoint) {
    const EShLanguage language = shader.getStage();
    const char* text = source.c_str();
    shader.setStrings(&text, 1);
    shader.setEntryPoint(entryPoint.c_str());
    shader.setSourceEntryPoint(entryPoint.c_str());
    shader.setEnvInput(glslang::EShSourceHlsl, language, glslang::EShClientVulkan, 100);
    shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_0);
    shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_0);
    // Bindings are assigned later by SpirvToGlsl; auto-mapping keeps Vulkan rules satisfied meanwhile.
    shader.setAutoMapBindings(true);
    shader.setAutoMapLocations(true);
    return shader.parse(GetDefaultResources(), 100, false, kMessages);
}

}  // namespace

HlslCompileResult compileHlslToSpirv(const std::string& source, ShaderStage stage,
                                     const std::string& entryPoint) {
    initGlslang();
    HlslCompileResult result;
    EShLanguage language = stage == ShaderStage::Vertex     ? EShLangVertex
                           : stage == ShaderStage::Fragment ? EShLangFragment
                           : stage == ShaderStage::Geometry ? EShLangGeometry
                           : stage == ShaderStage::Hull     ? EShLangTessControl
                           : stage == ShaderStage::Domain   ? EShLangTessEvaluation
                                                            : EShLangCompute;
    // Text glslang's front end would crash on is refused or checked before it parses the real text.
    const std::vector<detail::Token> tokens = detail::lexHlslUnit(source);
    result.messages = detail::mulCallsGlslangCannotCompile(tokens);
    if (!result.messages.empty()) return result;
    const detail::PostfixRewrite postfix = detail::rewritePostfixOperators(source, tokens);
    result.messages = postfix.errors;
    if (!result.messages.empty()) return result;
    if (postfix.checkText) {
        glslang::TShader check(language);
        if (!parseHlsl(check, *postfix.checkText, entryPoint)) {
            result.log = check.getInfoLog();
            result.messages = parseGlslangLog(result.log);
            return result;
        }
    }
    auto shader = std::make_unique<glslang::TShader>(language);
    std::string text = postfix.text;
    bool parsed = parseHlsl(*shader, text, entryPoint);
    if (parsed) {
        const detail::ParseUnit parseCopy = [&](const std::string& copy,
                                                const std::function<void(glslang::TIntermediate&)>& read) {
            glslang::TShader copyShader(language);
            parseHlsl(copyShader, copy, entryPoint);
            if (!copyShader.getIntermediate()->getTreeRoot()) return false;
            read(*copyShader.getIntermediate());
            return true;
        };
        const detail::ConstantProductRewrite products = detail::rewriteConstantMatrixProducts(
            *shader->getIntermediate(), text, postfix.text == source ? tokens : detail::lexHlslUnit(text),
            parseCopy);
        if (!products.errors.empty()) {
            result.messages = products.errors;
            return result;
        }
        if (products.text) {
            text = *products.text;
            shader = std::make_unique<glslang::TShader>(language);
            parsed = parseHlsl(*shader, text, entryPoint);
        }
    }
    std::vector<HlslMessage> syntaxTreeWarnings;
    result.log = shader->getInfoLog();
    if (parsed) {
        glslang::TProgram program;
        program.addShader(shader.get());
        if (program.link(kMessages) && program.mapIO()) {
            TruncationFinder truncations;
            program.getIntermediate(language)->getTreeRoot()->traverse(&truncations);
            syntaxTreeWarnings = std::move(truncations.found);
            // The places of the text glslang parsed: the postfix rewrite may have moved a line's tokens.
            const std::vector<HlslMessage> productErrors = detail::makeStarProductsElementWise(
                *program.getIntermediate(language), text == source ? tokens : detail::lexHlslUnit(text));
            HighestSymbolId symbols;
            program.getIntermediate(language)->getTreeRoot()->traverse(&symbols);
            const std::vector<HlslMessage> swizzlesLeft =
                detail::rewriteMatrixSwizzles(*program.getIntermediate(language), symbols.highest + 1);
            syntaxTreeWarnings.insert(syntaxTreeWarnings.end(), swizzlesLeft.begin(), swizzlesLeft.end());
            HighestSymbolId afterSwizzles;
            program.getIntermediate(language)->getTreeRoot()->traverse(&afterSwizzles);
            std::vector<HlslMessage> matrixErrors = detail::splitIntegerMatrixOperations(
                *program.getIntermediate(language), afterSwizzles.highest + 1);
            matrixErrors.insert(matrixErrors.begin(), productErrors.begin(), productErrors.end());
            syntaxTreeWarnings.insert(syntaxTreeWarnings.end(), matrixErrors.begin(), matrixErrors.end());
            HighestSymbolId afterMatrices;
            program.getIntermediate(language)->getTreeRoot()->traverse(&afterMatrices);
            detail::rewriteBoolCompoundAssignments(*program.getIntermediate(language),
                                                   afterMatrices.highest + 1);
            if (!matrixErrors.empty()) {
                result.messages = parseGlslangLog(result.log);
                result.messages.insert(result.messages.end(), syntaxTreeWarnings.begin(),
                                       syntaxTreeWarnings.end());
                return result;
            }
            glslang::SpvOptions spvOptions;
            spvOptions.validate = false;
            spvOptions.disableOptimizer = true;
            glslang::GlslangToSpv(*program.getIntermediate(language), result.spirv, &spvOptions);
            // A texture or sampler object handed to a user function is copied into a temporary by
            // glslang's HLSL front end, which SPIR-V cannot express until spirv-opt legalizes it (inlines
            // and forwards the copy); without that, SPIRV-Cross pairs the temporary ("param"), not the
            // effect's texture, and the pair is bound to nothing. Only such units are legalized: the
            // optimizer rewrites the whole unit, every other unit stays as glslang wrote it.
            if (hasOpaqueTemporaries(result.spirv)) {
                result.spirv.clear();
                spvOptions.disableOptimizer = false;
                glslang::GlslangToSpv(*program.getIntermediate(language), result.spirv, &spvOptions);
            }
            result.success = !result.spirv.empty();
        } else {
            result.log += program.getInfoLog();
        }
    }
    result.messages = parseGlslangLog(result.log);
    result.messages.insert(result.messages.end(), syntaxTreeWarnings.begin(), syntaxTreeWarnings.end());
    if (!result.success && std::none_of(result.messages.begin(), result.messages.end(),
                                        [](const HlslMessage& m) { return m.error; }))
        result.messages.push_back({true, "", 0, 0, "glslang failed: " + result.log});
    return result;
}

}  // namespace fx
