// BoolCompoundAssignments: see BoolCompoundAssignments.h.
#include "BoolCompoundAssignments.h"

#include "GlslangTreeEdits.h"

namespace fx::detail {

namespace {

class BoolCompoundAssignmentRewriter : public glslang::TIntermTraverser {
public:
    BoolCompoundAssignmentRewriter(glslang::TIntermediate& intermediate, long long unusedSymbolId)
        : glslang::TIntermTraverser(false, false, true),
          mIntermediate(intermediate),
          mNextSymbolId(unusedSymbolId) {}

    bool visitBinary(glslang::TVisit, glslang::TIntermBinary* node) override {
        const glslang::TOperator logical = logicalOperator(node->getOp());
        glslang::TIntermTyped* target = node->getLeft();
        if (logical == glslang::EOpNull || target->getBasicType() != glslang::EbtBool ||
            target->getType().isMatrix() || target->getType().isArray() ||
            node->getRight()->getType() != target->getType() || !isSideEffectFree(target))
            return true;
        const glslang::TSourceLoc& at = node->getLoc();
        glslang::TType type;
        type.shallowCopy(target->getType());
        type.getQualifier().makeTemporary();
        glslang::TIntermTyped* operand = node->getRight();
        glslang::TIntermTyped* evaluation = nullptr;
        if (!isSideEffectFree(operand)) {
            const long long id = mNextSymbolId++;
            const auto temporary = [&] {
                glslang::TIntermSymbol* symbol =
                    new glslang::TIntermSymbol(id, glslang::TString("boolOperand"), type);
                symbol->setLoc(at);
                return symbol;
            };
            evaluation = mIntermediate.addAssign(glslang::EOpAssign, temporary(), operand, at);
            operand = temporary();
        }
        glslang::TIntermBinary* combined = new glslang::TIntermBinary(logical);
        combined->setLeft(target);
        combined->setRight(operand);
        combined->setType(type);
        combined->setLoc(at);
        glslang::TIntermTyped* assignment = mIntermediate.addAssign(glslang::EOpAssign, target, combined, at);
        if (assignment && evaluation) assignment = mIntermediate.addComma(evaluation, assignment, at);
        if (assignment) replaceChild(getParentNode(), node, assignment);
        return true;
    }

private:
    glslang::TIntermediate& mIntermediate;
    long long mNextSymbolId;

    static glslang::TOperator logicalOperator(glslang::TOperator op) {
        switch (op) {
            case glslang::EOpInclusiveOrAssign:
                return glslang::EOpLogicalOr;
            case glslang::EOpAndAssign:
                return glslang::EOpLogicalAnd;
            case glslang::EOpExclusiveOrAssign:
                return glslang::EOpLogicalXor;
            default:
                return glslang::EOpNull;
        }
    }
};

}  // namespace

void rewriteBoolCompoundAssignments(glslang::TIntermediate& intermediate, long long unusedSymbolId) {
    BoolCompoundAssignmentRewriter rewriter(intermediate, unusedSymbolId);
    intermediate.getTreeRoot()->traverse(&rewriter);
}

}  // namespace fx::detail
