// HlslToSpirv: glslang's HLSL front end, configured as TOOLCHAIN.md prescribes (see HlslToSpirv.h).
#include "HlslToSpirv.h"

#include <glslang/Include/intermediate.h>
#include <glslang/MachineIndependent/localintermediate.h>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include <algorithm>
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
    return "glslang-hlsl dx9 vulkan1.0 spv1.0 msgs=" + std::to_string(static_cast<int>(kMessages));
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

// A swizzle of several matrix elements (`m._11_22`, `m._m00_m11`) is kept by glslang's HLSL front end as a
// matrix swizzle node (a single element, or the elements of one of its vectors, become ordinary indexing
// there), which its SPIR-V back end does not compile: it logs "Missing functionality: matrix swizzle" and
// writes an element index in the swizzle's place, a constant (a known glslang defect). Each such read is
// rewritten into what fxc compiled, a vector constructed from the single elements, each indexed the way the
// front end indexes `m._12` (m[first selector][second selector]: glslang's matrices are HLSL's rows), so
// `m._11_22` reads as `float2(m._11, m._22)`. The matrix operand then stands once per element, which reads
// the same value only where evaluating it has no side effects; anything else (a call's result) is
// evaluated once into a temporary first: `(t = f(), float2(t._11, t._22))`. A swizzle a write or an `out`
// argument reaches is left as it is with a warning at it, not an error: the unit also holds code whose
// value no output reads (a function D3DX ran on the host, a static only a compile argument uses), where
// the constant changes nothing and fxc's effect still runs.
class MatrixSwizzleRewriter : public glslang::TIntermTraverser {
public:
    // `unusedSymbolId`: above every symbol id of the tree, for the temporaries.
    MatrixSwizzleRewriter(glslang::TIntermediate& intermediate, long long unusedSymbolId)
        : glslang::TIntermTraverser(false, false, true),
          intermediate(intermediate),
          nextSymbolId(unusedSymbolId) {}

    std::vector<HlslMessage> leftAsTheyAre;

    // Post-order: a swizzle inside the matrix operand (an index) is rewritten before the swizzle around it.
    bool visitBinary(glslang::TVisit, glslang::TIntermBinary* node) override {
        if (node->getOp() != glslang::EOpMatrixSwizzle) return true;
        if (isWritten(node)) {
            if (!writeOneElement(node)) warnAt(node, Reason::Written);
            return true;
        }
        glslang::TIntermTyped* elements = readOfElements(node);
        if (!elements || !replaceChild(getParentNode(), node, elements)) warnAt(node, Reason::NotRewritable);
        return true;
    }

private:
    glslang::TIntermediate& intermediate;
    long long nextSymbolId;

    // The swizzle's elements read from its matrix, the matrix evaluated once; nullptr where glslang has no
    // constructor for their type.
    glslang::TIntermTyped* readOfElements(glslang::TIntermBinary* swizzle) {
        glslang::TIntermTyped* matrix = swizzle->getLeft();
        if (isSideEffectFree(matrix)) return constructFromElements(swizzle, matrix);
        const glslang::TSourceLoc& at = swizzle->getLoc();
        const glslang::TType temporaryType(matrix->getBasicType(), glslang::EvqTemporary, 0,
                                           matrix->getMatrixCols(), matrix->getMatrixRows());
        const long long id = nextSymbolId++;
        const auto temporary = [&] {
            glslang::TIntermSymbol* symbol =
                new glslang::TIntermSymbol(id, glslang::TString("swizzledMatrix"), temporaryType);
            symbol->setLoc(at);
            return symbol;
        };
        glslang::TIntermTyped* evaluation =
            intermediate.addAssign(glslang::EOpAssign, temporary(), matrix, at);
        glslang::TIntermTyped* elements = constructFromElements(swizzle, temporary());
        if (!evaluation || !elements) return nullptr;
        return intermediate.addComma(evaluation, elements, at);
    }

    // Symbols and constants combined by indexing, member selection, swizzles, arithmetic and constructors:
    // evaluating it again reads the same value and changes nothing.
    static bool isSideEffectFree(const TIntermNode* node) {
        if (node->getAsSymbolNode() || node->getAsConstantUnion()) return true;
        if (const glslang::TIntermBinary* binary = node->getAsBinaryNode()) {
            if (binary->modifiesState()) return false;
            // A vector swizzle's selectors are a sequence of constants.
            return isSideEffectFree(binary->getLeft()) &&
                   (binary->getOp() == glslang::EOpVectorSwizzle || isSideEffectFree(binary->getRight()));
        }
        if (const glslang::TIntermUnary* unary = node->getAsUnaryNode())
            return !unary->modifiesState() && isSideEffectFree(unary->getOperand());
        if (const glslang::TIntermAggregate* aggregate = node->getAsAggregate()) {
            if (!aggregate->isConstructor()) return false;
            for (const TIntermNode* operand : aggregate->getSequence())
                if (!isSideEffectFree(operand)) return false;
            return true;
        }
        return false;
    }

    // The vector of the swizzle's elements read from `matrix`, or nullptr for an element type glslang has no
    // constructor for.
    glslang::TIntermTyped* constructFromElements(glslang::TIntermBinary* swizzle,
                                                 glslang::TIntermTyped* matrix) {
        const glslang::TIntermSequence& selectors = swizzle->getRight()->getAsAggregate()->getSequence();
        const glslang::TType& vectorType = swizzle->getType();
        const glslang::TOperator construct = intermediate.mapTypeToConstructorOp(vectorType);
        if (construct == glslang::EOpNull) return nullptr;
        const glslang::TSourceLoc& at = swizzle->getLoc();
        const glslang::TType columnType(matrix->getType(), 0);
        const glslang::TType elementType(columnType, 0);
        glslang::TIntermAggregate* vector = new glslang::TIntermAggregate;
        for (size_t i = 0; i + 1 < selectors.size(); i += 2) {
            glslang::TIntermTyped* column =
                intermediate.addIndex(glslang::EOpIndexDirect, matrix, selectors[i]->getAsTyped(), at);
            column->setType(columnType);
            glslang::TIntermTyped* element =
                intermediate.addIndex(glslang::EOpIndexDirect, column, selectors[i + 1]->getAsTyped(), at);
            element->setType(elementType);
            vector->getSequence().push_back(element);
        }
        return intermediate.setAggregateOperator(vector, construct, vectorType, at);
    }

    // Whether the swizzle's elements are written: the swizzle, or an element or vector swizzle of it
    // (`m._11_22.x`, `m._11_22[0]`), is an assignment's target, incremented or decremented, or an `out`
    // argument. A constructor put in its place could not be written (glslang would store through a value).
    bool isWritten(const glslang::TIntermTyped* swizzle) const {
        const TIntermNode* written = swizzle;
        for (size_t i = path.size(); i-- > 0;) {
            const TIntermNode* parent = path[i];
            if (const glslang::TIntermBinary* binary = parent->getAsBinaryNode()) {
                if (binary->getLeft() != written) return false;
                if (binary->modifiesState()) return true;
                const glslang::TOperator op = binary->getOp();
                if (op != glslang::EOpIndexDirect && op != glslang::EOpIndexIndirect &&
                    op != glslang::EOpVectorSwizzle)
                    return false;
                written = parent;
                continue;
            }
            if (const glslang::TIntermUnary* unary = parent->getAsUnaryNode()) return unary->modifiesState();
            if (const glslang::TIntermAggregate* aggregate = parent->getAsAggregate()) {
                const glslang::TIntermSequence& operands = aggregate->getSequence();
                for (size_t operand = 0; operand < operands.size(); ++operand)
                    if (operands[operand] == written)
                        return writesOperand(*aggregate, operand, aggregate->getQualifierList());
            }
            return false;
        }
        return false;
    }

    // A written swizzle whose element or vector swizzle picks one element by constants (`m._11_22.y = e;`,
    // `m._11_22[1]++`, `f(m._11_22.x)` with an `out` parameter): that chain replaced by the element itself,
    // `m[1][1]`, which can be written. False (nothing changed) for any other write.
    bool writeOneElement(glslang::TIntermBinary* swizzle) {
        glslang::TIntermTyped* matrix = swizzle->getLeft();
        if (!isSideEffectFree(matrix)) return false;
        const glslang::TIntermSequence& selectors = swizzle->getRight()->getAsAggregate()->getSequence();
        std::vector<size_t> picked;  // into the swizzle's elements
        for (size_t i = 0; i + 1 < selectors.size(); i += 2) picked.push_back(i / 2);
        glslang::TIntermTyped* chain = swizzle;
        size_t depth = path.size();
        while (depth > 0) {
            glslang::TIntermBinary* parent = path[depth - 1]->getAsBinaryNode();
            if (!parent || parent->getLeft() != chain) break;
            const glslang::TOperator op = parent->getOp();
            std::vector<size_t> narrowed;
            if (op == glslang::EOpVectorSwizzle) {
                for (const TIntermNode* component : parent->getRight()->getAsAggregate()->getSequence())
                    narrowed.push_back(component->getAsConstantUnion()->getConstArray()[0].getIConst());
            } else if (op == glslang::EOpIndexDirect && parent->getRight()->getAsConstantUnion()) {
                narrowed.push_back(parent->getRight()->getAsConstantUnion()->getConstArray()[0].getIConst());
            } else {
                break;
            }
            for (size_t& n : narrowed) {
                if (n >= picked.size()) return false;
                n = picked[n];
            }
            picked = std::move(narrowed);
            chain = parent;
            --depth;
        }
        if (picked.size() != 1 || chain == swizzle || depth == 0) return false;
        const glslang::TSourceLoc& at = swizzle->getLoc();
        const glslang::TType columnType(matrix->getType(), 0);
        glslang::TIntermTyped* column = intermediate.addIndex(glslang::EOpIndexDirect, matrix,
                                                              selectors[2 * picked[0]]->getAsTyped(), at);
        column->setType(columnType);
        glslang::TIntermTyped* element = intermediate.addIndex(
            glslang::EOpIndexDirect, column, selectors[2 * picked[0] + 1]->getAsTyped(), at);
        element->setType(glslang::TType(columnType, 0));
        return replaceChild(path[depth - 1], chain, element);
    }

    // Puts `to` where `parent` holds `from`; false where the parent is a node glslang gives no way to
    // change (a loop's step expression).
    bool replaceChild(TIntermNode* parent, glslang::TIntermTyped* from, glslang::TIntermTyped* to) {
        if (!parent) return false;
        if (glslang::TIntermBinary* binary = parent->getAsBinaryNode()) {
            if (binary->getLeft() == from) {
                binary->setLeft(to);
                return true;
            }
            if (binary->getRight() != from) return false;
            binary->setRight(to);
            return true;
        }
        if (glslang::TIntermUnary* unary = parent->getAsUnaryNode()) {
            unary->setOperand(to);
            return true;
        }
        if (glslang::TIntermAggregate* aggregate = parent->getAsAggregate()) {
            for (TIntermNode*& operand : aggregate->getSequence()) {
                if (operand != from) continue;
                operand = to;
                return true;
            }
            return false;
        }
        if (glslang::TIntermSelection* selection = parent->getAsSelectionNode()) {
            if (selection->getCondition() == from)
                selection->setCondition(to);
            else if (selection->getTrueBlock() == from)
                selection->setTrueBlock(to);
            else if (selection->getFalseBlock() == from)
                selection->setFalseBlock(to);
            else
                return false;
            return true;
        }
        if (glslang::TIntermBranch* branch = parent->getAsBranchNode()) {
            if (branch->getExpression() != from) return false;
            branch->setExpression(to);
            return true;
        }
        return false;
    }

    // Whether the call writes its `i`th operand: an `out` or `inout` parameter of the effect's function,
    // the whole-number part of `modf` and the exponent of `frexp`.
    static bool writesOperand(const glslang::TIntermAggregate& call, size_t i,
                              const glslang::TQualifierList& qualifiers) {
        if (i < qualifiers.size() && (qualifiers[i] == glslang::EvqOut || qualifiers[i] == glslang::EvqInOut))
            return true;
        return i == 1 && (call.getOp() == glslang::EOpModf || call.getOp() == glslang::EOpFrexp);
    }

    enum class Reason {
        Written,        // isWritten: the fix is the user's, through a vector variable
        NotRewritable,  // no constructor for the element type, or a parent glslang gives no way to change
    };

    void warnAt(const glslang::TIntermBinary* swizzle, Reason reason) {
        const glslang::TSourceLoc& at = swizzle->getLoc();
        const std::string elements = std::to_string(swizzle->getType().getVectorSize());
        const std::string example = swizzle->getType().getVectorSize() > 2 ? "_11_22_33" : "_11_22";
        const std::string text =
            reason == Reason::Written
                ? "'.' : a swizzle of " + elements +
                      " matrix elements written here compiles to a constant (glslang compiles it to an "
                      "element index, not the elements fxc wrote; shadowfx rewrites the swizzles it reads): "
                      "write a vector variable and assign it after, e.g. float" +
                      elements + " v; f(v); m." + example + " = v;"
                : "'.' : a swizzle of " + elements +
                      " matrix elements is not rewritten here and reads a constant (glslang compiles it to "
                      "an "
                      "element index, not the elements fxc read): spell the elements one by one, e.g. float" +
                      elements + "(m._11, m._22" + (swizzle->getType().getVectorSize() > 2 ? ", ..." : "") +
                      ")";
        leftAsTheyAre.push_back({false, at.getFilenameStr(), at.line, at.column, text});
    }
};

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
    glslang::TShader shader(language);
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

    bool parsed = shader.parse(GetDefaultResources(), 100, false, kMessages);
    std::vector<HlslMessage> syntaxTreeWarnings;
    result.log = shader.getInfoLog();
    if (parsed) {
        glslang::TProgram program;
        program.addShader(&shader);
        if (program.link(kMessages) && program.mapIO()) {
            TruncationFinder truncations;
            program.getIntermediate(language)->getTreeRoot()->traverse(&truncations);
            syntaxTreeWarnings = std::move(truncations.found);
            HighestSymbolId symbols;
            program.getIntermediate(language)->getTreeRoot()->traverse(&symbols);
            MatrixSwizzleRewriter matrixSwizzles(*program.getIntermediate(language), symbols.highest + 1);
            program.getIntermediate(language)->getTreeRoot()->traverse(&matrixSwizzles);
            syntaxTreeWarnings.insert(syntaxTreeWarnings.end(), matrixSwizzles.leftAsTheyAre.begin(),
                                      matrixSwizzles.leftAsTheyAre.end());
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
