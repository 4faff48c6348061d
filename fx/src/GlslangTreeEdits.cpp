// GlslangTreeEdits: see GlslangTreeEdits.h.
#include "GlslangTreeEdits.h"

namespace fx::detail {

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
        if (unary->getOperand() != from) return false;
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

bool isSideEffectFree(const TIntermNode* node) {
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

}  // namespace fx::detail
