// MatrixSwizzles: see MatrixSwizzles.h.
#include "MatrixSwizzles.h"

#include "GlslangTreeEdits.h"

#include <string>

namespace fx::detail {

namespace {

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
            if (!writeElements(node)) warnAt(node, Reason::Written);
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

    // The elements of a matrix swizzle that a chain of vector swizzles and constant indices above it picks
    // (`m._11_22_33.zx`: the third and the first), and the top of that chain.
    struct PickedElements {
        std::vector<size_t> picked;  // into the swizzle's elements
        glslang::TIntermTyped* top = nullptr;
        size_t levels = 0;  // the nodes of the chain above the swizzle
    };

    // Climbs from `swizzle` through `chain` (the nodes above it, nearest first) while they pick elements by
    // constants; false where an index picks outside the swizzle.
    static bool pickElements(glslang::TIntermBinary* swizzle,
                             const std::vector<glslang::TIntermBinary*>& chain, PickedElements& out) {
        const size_t count = swizzle->getRight()->getAsAggregate()->getSequence().size() / 2;
        out.picked.clear();
        for (size_t i = 0; i < count; ++i) out.picked.push_back(i);
        out.top = swizzle;
        out.levels = 0;
        for (glslang::TIntermBinary* parent : chain) {
            if (parent->getLeft() != out.top) break;
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
                if (n >= out.picked.size()) return false;
                n = out.picked[n];
            }
            out.picked = std::move(narrowed);
            out.top = parent;
            ++out.levels;
        }
        return true;
    }

    // Element `k` of the swizzle's elements, `m[row][column]`: a node that can be written.
    glslang::TIntermTyped* element(glslang::TIntermBinary* swizzle, size_t k) {
        glslang::TIntermTyped* matrix = swizzle->getLeft();
        const glslang::TIntermSequence& selectors = swizzle->getRight()->getAsAggregate()->getSequence();
        const glslang::TSourceLoc& at = swizzle->getLoc();
        const glslang::TType columnType(matrix->getType(), 0);
        glslang::TIntermTyped* column =
            intermediate.addIndex(glslang::EOpIndexDirect, matrix, selectors[2 * k]->getAsTyped(), at);
        column->setType(columnType);
        glslang::TIntermTyped* element =
            intermediate.addIndex(glslang::EOpIndexDirect, column, selectors[2 * k + 1]->getAsTyped(), at);
        element->setType(glslang::TType(columnType, 0));
        return element;
    }

    // The picked elements read into a vector of `type` (one element: the element).
    glslang::TIntermTyped* readOfPicked(glslang::TIntermBinary* swizzle, const std::vector<size_t>& picked,
                                        const glslang::TType& type) {
        if (picked.size() == 1) return element(swizzle, picked[0]);
        glslang::TIntermAggregate* vector = new glslang::TIntermAggregate;
        for (size_t k : picked) vector->getSequence().push_back(element(swizzle, k));
        return intermediate.setAggregateOperator(vector, intermediate.mapTypeToConstructorOp(type), type,
                                                 swizzle->getLoc());
    }

    glslang::TIntermSymbol* temporary(long long id, const glslang::TType& of, const glslang::TSourceLoc& at) {
        glslang::TType type;
        type.shallowCopy(of);
        type.getQualifier().makeTemporary();
        glslang::TIntermSymbol* symbol =
            new glslang::TIntermSymbol(id, glslang::TString("swizzledElements"), type);
        symbol->setLoc(at);
        return symbol;
    }

    // Component `k` of the vector `vector`.
    glslang::TIntermTyped* component(glslang::TIntermTyped* vector, size_t k) {
        if (vector->getType().isScalarOrVec1()) return vector;
        glslang::TIntermTyped* picked = intermediate.addIndex(
            glslang::EOpIndexDirect, vector,
            intermediate.addConstantUnion(static_cast<int>(k), vector->getLoc()), vector->getLoc());
        picked->setType(glslang::TType(vector->getBasicType()));
        return picked;
    }

    // A written swizzle made writes of its single elements. One element picked (`m._11_22.y = e;`,
    // `m._11_22[1]++`, `f(m._11_22.x)` with an `out` parameter): the chain replaced by the element itself,
    // `m[1][1]`. Several elements assigned (`m._11_22_33.zx = v;`, `m._11_22 *= s;`): the value evaluated
    // once into a temporary whose components are assigned to the elements one by one, the expression's
    // value read from them after. Several elements passed to an `out` or `inout` parameter
    // (`f(m._11_22)`, `f(m._11_22_33.xz)`): the call is handed a temporary, initialized from the elements
    // for `inout`, and the temporary's components are written back to the elements after the call, as
    // HLSL copies an argument out. False (nothing changed) for any other write.
    bool writeElements(glslang::TIntermBinary* swizzle) {
        if (!isSideEffectFree(swizzle->getLeft())) return false;
        std::vector<glslang::TIntermBinary*> chain;  // the binary nodes above the swizzle, nearest first
        for (size_t i = path.size(); i-- > 0 && path[i]->getAsBinaryNode();)
            chain.push_back(path[i]->getAsBinaryNode());
        PickedElements elements;
        if (!pickElements(swizzle, chain, elements) || elements.levels >= path.size()) return false;
        const size_t depth = path.size() - elements.levels;  // path[depth - 1] uses the chain's top
        TIntermNode* user = path[depth - 1];
        TIntermNode* aboveUser = depth > 1 ? path[depth - 2] : nullptr;
        if (elements.picked.size() == 1 && elements.top != swizzle)
            return replaceChild(user, elements.top, element(swizzle, elements.picked[0]));
        if (glslang::TIntermBinary* assignment = user->getAsBinaryNode();
            assignment && assignment->modifiesState() && assignment->getLeft() == elements.top)
            return assignElements(assignment, aboveUser, swizzle, elements.picked);
        if (glslang::TIntermAggregate* call = user->getAsAggregate()) return passElements(call, aboveUser);
        return false;
    }

    bool assignElements(glslang::TIntermBinary* assignment, TIntermNode* aboveAssignment,
                        glslang::TIntermBinary* swizzle, const std::vector<size_t>& picked) {
        if (!aboveAssignment) return false;
        const glslang::TSourceLoc& at = assignment->getLoc();
        const long long id = nextSymbolId++;
        glslang::TIntermTyped* value = assignment->getRight();
        glslang::TIntermTyped* sequence =
            intermediate.addAssign(glslang::EOpAssign, temporary(id, value->getType(), at), value, at);
        for (size_t k = 0; k < picked.size(); ++k) {
            glslang::TIntermBinary* write = new glslang::TIntermBinary(assignment->getOp());
            write->setLeft(element(swizzle, picked[k]));
            write->setRight(component(temporary(id, value->getType(), at), k));
            write->setType(write->getLeft()->getType());
            write->setLoc(at);
            sequence = intermediate.addComma(sequence, write, at);
        }
        sequence = intermediate.addComma(sequence, readOfPicked(swizzle, picked, assignment->getType()), at);
        return replaceChild(aboveAssignment, assignment, sequence);
    }

    // Every argument of `call` that is written and is a swizzle of several matrix elements (or a chain of
    // vector swizzles and constant indices on one) passed through a temporary, as writeElements says.
    bool passElements(glslang::TIntermAggregate* call, TIntermNode* aboveCall) {
        // The operands below are replaced by temporaries whose copies back follow the call: a call that
        // cannot be replaced by that sequence (a loop's step) must keep its operands.
        if (!canReplaceChild(aboveCall, call)) return false;
        const glslang::TSourceLoc& at = call->getLoc();
        glslang::TIntermSequence& operands = call->getSequence();
        std::vector<glslang::TIntermTyped*> before, after;
        for (size_t i = 0; i < operands.size(); ++i) {
            if (!writesOperand(*call, i, call->getQualifierList())) continue;
            glslang::TIntermTyped* operand = operands[i]->getAsTyped();
            std::vector<glslang::TIntermBinary*> chain;  // nearest the swizzle first
            glslang::TIntermTyped* node = operand;
            while (node->getAsBinaryNode() && node->getAsBinaryNode()->getOp() != glslang::EOpMatrixSwizzle) {
                chain.insert(chain.begin(), node->getAsBinaryNode());
                node = node->getAsBinaryNode()->getLeft();
            }
            glslang::TIntermBinary* swizzle = node->getAsBinaryNode();
            PickedElements elements;
            if (!swizzle || !isSideEffectFree(swizzle->getLeft()) ||
                !pickElements(swizzle, chain, elements) || elements.top != operand)
                continue;
            if (elements.picked.size() == 1) {
                operands[i] = element(swizzle, elements.picked[0]);
                continue;
            }
            const long long id = nextSymbolId++;
            operands[i] = temporary(id, operand->getType(), at);
            if (i < call->getQualifierList().size() && call->getQualifierList()[i] == glslang::EvqInOut)
                before.push_back(
                    intermediate.addAssign(glslang::EOpAssign, temporary(id, operand->getType(), at),
                                           readOfPicked(swizzle, elements.picked, operand->getType()), at));
            for (size_t k = 0; k < elements.picked.size(); ++k)
                after.push_back(
                    intermediate.addAssign(glslang::EOpAssign, element(swizzle, elements.picked[k]),
                                           component(temporary(id, operand->getType(), at), k), at));
        }
        if (after.empty()) return false;
        const bool returns = call->getBasicType() != glslang::EbtVoid;
        const long long resultId = nextSymbolId++;
        glslang::TIntermTyped* sequence = nullptr;
        const auto append = [&](glslang::TIntermTyped* next) {
            sequence = sequence ? intermediate.addComma(sequence, next, at) : next;
        };
        for (glslang::TIntermTyped* initialization : before) append(initialization);
        append(returns ? intermediate.addAssign(glslang::EOpAssign, temporary(resultId, call->getType(), at),
                                                call, at)
                       : call);
        for (glslang::TIntermTyped* writeBack : after) append(writeBack);
        if (returns) append(temporary(resultId, call->getType(), at));
        return replaceChild(aboveCall, call, sequence);
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
        Written,        // isWritten, and writeElements made no writes of it (++, --, a matrix with side
                        // effects): the fix is the user's
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
                      "element index, not the elements fxc wrote; shadowfx rewrites assignments to a "
                      "variable's elements and out arguments): copy them into a vector variable, write it "
                      "and assign it back, e.g. float" +
                      elements + " v = m." + example + "; v++; m." + example + " = v;"
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

std::vector<HlslMessage> rewriteMatrixSwizzles(glslang::TIntermediate& intermediate,
                                               long long unusedSymbolId) {
    MatrixSwizzleRewriter rewriter(intermediate, unusedSymbolId);
    intermediate.getTreeRoot()->traverse(&rewriter);
    return std::move(rewriter.leftAsTheyAre);
}

}  // namespace fx::detail
