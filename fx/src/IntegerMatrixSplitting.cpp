// IntegerMatrixSplitting: see IntegerMatrixSplitting.h.
#include "IntegerMatrixSplitting.h"

#include "GlslangTreeEdits.h"

#include <algorithm>
#include <string>

namespace fx::detail {

namespace {

using glslang::TIntermAggregate;
using glslang::TIntermBinary;
using glslang::TIntermSelection;
using glslang::TIntermTyped;
using glslang::TIntermUnary;
using glslang::TOperator;
using glslang::TType;

// An integer or bool matrix: what glslang's SPIR-V back end cannot compute with.
bool isIntegerMatrix(const TType& type) {
    if (!type.isMatrix() || type.isArray()) return false;
    const glslang::TBasicType base = type.getBasicType();
    return base == glslang::EbtBool || base == glslang::EbtInt || base == glslang::EbtUint;
}

bool isComparison(TOperator op) {
    switch (op) {
        case glslang::EOpEqual:
        case glslang::EOpNotEqual:
        case glslang::EOpVectorEqual:
        case glslang::EOpVectorNotEqual:
        case glslang::EOpLessThan:
        case glslang::EOpGreaterThan:
        case glslang::EOpLessThanEqual:
        case glslang::EOpGreaterThanEqual:
            return true;
        default:
            return false;
    }
}

// A binary operator HLSL applies element by element (on a matrix and a matrix or a scalar); `*` of a
// matrix by a scalar is glslang's EOpMatrixTimesScalar.
bool isElementWiseBinary(TOperator op) {
    switch (op) {
        case glslang::EOpAdd:
        case glslang::EOpSub:
        case glslang::EOpMul:
        case glslang::EOpDiv:
        case glslang::EOpMod:
        case glslang::EOpRightShift:
        case glslang::EOpLeftShift:
        case glslang::EOpAnd:
        case glslang::EOpInclusiveOr:
        case glslang::EOpExclusiveOr:
        case glslang::EOpLogicalAnd:
        case glslang::EOpLogicalOr:
        case glslang::EOpLogicalXor:
        case glslang::EOpMatrixTimesScalar:
            return true;
        default:
            return isComparison(op);
    }
}

// A compound assignment, and the operator each row applies.
TOperator rowCompoundAssignment(TOperator op) {
    switch (op) {
        case glslang::EOpAddAssign:
        case glslang::EOpSubAssign:
        case glslang::EOpMulAssign:
        case glslang::EOpDivAssign:
        case glslang::EOpModAssign:
        case glslang::EOpAndAssign:
        case glslang::EOpInclusiveOrAssign:
        case glslang::EOpExclusiveOrAssign:
        case glslang::EOpLeftShiftAssign:
        case glslang::EOpRightShiftAssign:
            return op;
        case glslang::EOpMatrixTimesScalarAssign:
            return glslang::EOpMulAssign;
        default:
            return glslang::EOpNull;
    }
}

// A unary operator or intrinsic of one operand that HLSL applies element by element: the conversions
// (casts), negation, the bit intrinsics and abs.
bool isElementWiseUnary(TOperator op) {
    if (op >= glslang::EOpConvInt8ToBool && op <= glslang::EOpConvDoubleToFloat) return true;
    switch (op) {
        case glslang::EOpNegative:
        case glslang::EOpLogicalNot:
        case glslang::EOpBitwiseNot:
        case glslang::EOpAbs:
        case glslang::EOpSign:
        case glslang::EOpBitCount:
        case glslang::EOpBitFieldReverse:
        case glslang::EOpFindLSB:
        case glslang::EOpFindMSB:
        case glslang::EOpFloatBitsToInt:
        case glslang::EOpFloatBitsToUint:
        case glslang::EOpIntBitsToFloat:
        case glslang::EOpUintBitsToFloat:
            return true;
        default:
            return false;
    }
}

// An intrinsic of several operands that HLSL applies element by element (EOpMix: a select whose
// condition is a bool vector or matrix).
bool isElementWiseAggregate(TOperator op) {
    return op == glslang::EOpMin || op == glslang::EOpMax || op == glslang::EOpClamp || op == glslang::EOpMix;
}

// Whether `expression` reads the variable that `assigned` (a variable, or an element or member of one)
// writes: true where the variable cannot be told, so that the caller evaluates the expression once, first.
bool readsAssignedVariable(TIntermTyped* expression, TIntermTyped* assigned) {
    TIntermTyped* base = assigned;
    while (TIntermBinary* access = base->getAsBinaryNode()) base = access->getLeft();
    const glslang::TIntermSymbol* variable = base->getAsSymbolNode();
    if (!variable) return true;
    struct Reads : glslang::TIntermTraverser {
        long long id = 0;
        bool found = false;
        void visitSymbol(glslang::TIntermSymbol* symbol) override { found = found || symbol->getId() == id; }
    } reads;
    reads.id = variable->getId();
    expression->traverse(&reads);
    return reads.found;
}

class IntegerMatrixSplitter : public glslang::TIntermTraverser {
public:
    IntegerMatrixSplitter(glslang::TIntermediate& intermediate, long long unusedSymbolId)
        : glslang::TIntermTraverser(true, false, true),
          mIntermediate(intermediate),
          mNextSymbolId(unusedSymbolId) {}

    std::vector<HlslMessage> errors;

    bool visitBinary(glslang::TVisit visit, TIntermBinary* node) override {
        if (visit != glslang::EvPostVisit) return true;
        const TOperator op = node->getOp();
        TIntermTyped* left = node->getLeft();
        TIntermTyped* right = node->getRight();
        if (isElementWiseBinary(op) && (isSplit(left->getType(), op) || isSplit(right->getType(), op))) {
            const TType& matrix = left->getType().isMatrix() ? left->getType() : right->getType();
            const glslang::TBasicType base = isComparison(op) ? glslang::EbtBool : matrix.getBasicType();
            TOperator rowOp = op == glslang::EOpEqual               ? glslang::EOpVectorEqual
                              : op == glslang::EOpNotEqual          ? glslang::EOpVectorNotEqual
                              : op == glslang::EOpMatrixTimesScalar ? glslang::EOpMul
                                                                    : op;
            std::vector<TIntermTyped*> evaluations;
            const std::vector<TIntermTyped*> leftRows = rowsOf(left, matrix, evaluations);
            const std::vector<TIntermTyped*> rightRows = rowsOf(right, matrix, evaluations);
            std::vector<TIntermTyped*> rows;
            for (size_t i = 0; i < leftRows.size(); ++i) {
                TIntermBinary* row = new TIntermBinary(rowOp);
                row->setLeft(leftRows[i]);
                row->setRight(rightRows[i]);
                row->setType(rowType(base, matrix));
                row->setLoc(node->getLoc());
                rows.push_back(row);
            }
            replace(node, withEvaluations(evaluations, fromRows(rows, base, matrix, node->getLoc())));
            return true;
        }
        const TOperator rowAssign = rowCompoundAssignment(op);
        if (rowAssign != glslang::EOpNull && isIntegerMatrix(left->getType())) {
            if (!isSideEffectFree(left)) {
                errorAt(node, "an integer matrix assigned through an expression with side effects");
                return true;
            }
            std::vector<TIntermTyped*> evaluations;
            // HLSL evaluates the right side before it writes: one that reads the matrix would see the rows
            // written before its own (m *= m._11).
            if (readsAssignedVariable(right, left)) right = evaluatedOnce(right, evaluations);
            const std::vector<TIntermTyped*> rightRows = rowsOf(right, left->getType(), evaluations);
            TIntermTyped* sequence = nullptr;
            for (size_t i = 0; i < rightRows.size(); ++i) {
                TIntermBinary* row = new TIntermBinary(rowAssign);
                row->setLeft(rowOfVariable(left, static_cast<int>(i)));
                row->setRight(rightRows[i]);
                row->setType(rowType(left->getBasicType(), left->getType()));
                row->setLoc(node->getLoc());
                sequence = sequence ? mIntermediate.addComma(sequence, row, node->getLoc()) : row;
            }
            sequence = mIntermediate.addComma(sequence, left, node->getLoc());
            replace(node, withEvaluations(evaluations, sequence));
            return true;
        }
        if ((op == glslang::EOpMatrixTimesMatrix || op == glslang::EOpMatrixTimesVector ||
             op == glslang::EOpVectorTimesMatrix) &&
            (isIntegerMatrix(left->getType()) || isIntegerMatrix(right->getType())))
            errorAt(node, "mul() of an integer or bool matrix");
        return true;
    }

    bool visitUnary(glslang::TVisit visit, TIntermUnary* node) override {
        if (visit != glslang::EvPostVisit) return true;
        const TOperator op = node->getOp();
        TIntermTyped* operand = node->getOperand();
        if (!operand->getType().isMatrix()) return true;
        const bool splitOperand = isIntegerMatrix(operand->getType()) || isIntegerMatrix(node->getType());
        if (isElementWiseUnary(op) && splitOperand) {
            const glslang::TBasicType base = node->getBasicType();
            std::vector<TIntermTyped*> evaluations;
            std::vector<TIntermTyped*> rows = rowsOf(operand, operand->getType(), evaluations);
            for (TIntermTyped*& row : rows) {
                TIntermUnary* converted = new TIntermUnary(op);
                converted->setOperand(row);
                converted->setType(rowType(base, operand->getType()));
                converted->setLoc(node->getLoc());
                row = converted;
            }
            replace(node,
                    withEvaluations(evaluations, fromRows(rows, base, operand->getType(), node->getLoc())));
            return true;
        }
        if ((op == glslang::EOpAny || op == glslang::EOpAll) && splitOperand) {
            std::vector<TIntermTyped*> evaluations;
            TIntermTyped* reduced = nullptr;
            for (TIntermTyped* row : rowsOf(operand, operand->getType(), evaluations)) {
                TIntermUnary* rowReduced = new TIntermUnary(op);
                rowReduced->setOperand(row);
                rowReduced->setType(TType(glslang::EbtBool));
                rowReduced->setLoc(node->getLoc());
                if (!reduced) {
                    reduced = rowReduced;
                    continue;
                }
                TIntermBinary* both =
                    new TIntermBinary(op == glslang::EOpAny ? glslang::EOpLogicalOr : glslang::EOpLogicalAnd);
                both->setLeft(reduced);
                both->setRight(rowReduced);
                both->setType(TType(glslang::EbtBool));
                both->setLoc(node->getLoc());
                reduced = both;
            }
            replace(node, withEvaluations(evaluations, reduced));
            return true;
        }
        if (!splitOperand) return true;
        switch (op) {
            case glslang::EOpTranspose:
                errorAt(node, "transpose() of an integer or bool matrix");
                break;
            case glslang::EOpDeterminant:
                errorAt(node, "determinant() of an integer or bool matrix");
                break;
            case glslang::EOpPreIncrement:
            case glslang::EOpPreDecrement:
            case glslang::EOpPostIncrement:
            case glslang::EOpPostDecrement:
                errorAt(node, "++ or -- of an integer matrix (write m += 1)");
                break;
            default:
                break;
        }
        return true;
    }

    bool visitSelection(glslang::TVisit visit, TIntermSelection* node) override {
        TIntermTyped* condition = node->getCondition();
        if (visit != glslang::EvPostVisit || !condition->getType().isMatrix() || !isValueSelection(node))
            return true;
        TIntermTyped* whenTrue = node->getTrueBlock()->getAsTyped();
        TIntermTyped* whenFalse = node->getFalseBlock()->getAsTyped();
        if (!whenTrue || !whenFalse) return true;
        // A bool matrix selects element by element: each row a vector select (glslang's EOpMix, as its
        // front end writes `b ? x : y` for a bool vector b).
        const TType& matrix = condition->getType();
        const glslang::TBasicType base = node->getBasicType();
        std::vector<TIntermTyped*> evaluations;
        const std::vector<TIntermTyped*> conditions = rowsOf(condition, matrix, evaluations);
        const std::vector<TIntermTyped*> trues = rowsOf(whenTrue, matrix, evaluations);
        const std::vector<TIntermTyped*> falses = rowsOf(whenFalse, matrix, evaluations);
        std::vector<TIntermTyped*> rows;
        for (size_t i = 0; i < conditions.size(); ++i)
            rows.push_back(rowOperation(glslang::EOpMix, {falses[i], trues[i], conditions[i]}, base, matrix,
                                        node->getLoc()));
        replace(node, withEvaluations(evaluations, fromRows(rows, base, matrix, node->getLoc())));
        return true;
    }

    bool visitAggregate(glslang::TVisit visit, TIntermAggregate* node) override {
        glslang::TIntermSequence& operands = node->getSequence();
        if (visit == glslang::EvPreVisit) {
            // HLSL's scalar-to-matrix conversion: glslang's front end repeats the one scalar operand once
            // per element (the same node), which a rewrite of that node would replace in one place only.
            if (node->isConstructor() && isIntegerMatrix(node->getType()) && operands.size() > 1 &&
                std::all_of(operands.begin(), operands.end(),
                            [&](const TIntermNode* operand) { return operand == operands[0]; }))
                operands.resize(1);
            return true;
        }
        if (node->isConstructor() && isIntegerMatrix(node->getType())) {
            buildFromRows(node);
            return true;
        }
        if (!isElementWiseAggregate(node->getOp())) return true;
        const TIntermTyped* matrixOperand = nullptr;
        for (const TIntermNode* operand : operands)
            if (operand->getAsTyped() && operand->getAsTyped()->getType().isMatrix() &&
                (isIntegerMatrix(operand->getAsTyped()->getType()) || isIntegerMatrix(node->getType())))
                matrixOperand = operand->getAsTyped();
        if (!matrixOperand) return true;
        const TType& matrix = matrixOperand->getType();
        const glslang::TBasicType base = node->getBasicType();
        std::vector<TIntermTyped*> evaluations;
        std::vector<std::vector<TIntermTyped*>> operandRows;
        for (TIntermNode* operand : operands)
            operandRows.push_back(rowsOf(operand->getAsTyped(), matrix, evaluations));
        std::vector<TIntermTyped*> rows;
        for (int i = 0; i < matrix.getMatrixCols(); ++i) {
            std::vector<TIntermTyped*> rowOperands;
            for (const std::vector<TIntermTyped*>& of : operandRows) rowOperands.push_back(of[i]);
            rows.push_back(rowOperation(node->getOp(), rowOperands, base, matrix, node->getLoc()));
        }
        replace(node, withEvaluations(evaluations, fromRows(rows, base, matrix, node->getLoc())));
        return true;
    }

private:
    glslang::TIntermediate& mIntermediate;
    long long mNextSymbolId;

    // Whether a binary operation `op` on an operand of `type` is split: an integer or bool matrix, or
    // any matrix compared.
    static bool isSplit(const TType& type, TOperator op) {
        return isIntegerMatrix(type) || (type.isMatrix() && !type.isArray() && isComparison(op));
    }

    // One row of `matrix` (HLSL's row: glslang's column) with elements of `base`.
    static TType rowType(glslang::TBasicType base, const TType& matrix) {
        return TType(base, glslang::EvqTemporary, matrix.getMatrixRows());
    }

    static TType matrixType(glslang::TBasicType base, const TType& matrix) {
        return TType(base, glslang::EvqTemporary, 0, matrix.getMatrixCols(), matrix.getMatrixRows());
    }

    TIntermTyped* rowOfVariable(TIntermTyped* matrix, int i) {
        TIntermTyped* row =
            mIntermediate.addIndex(glslang::EOpIndexDirect, matrix,
                                   mIntermediate.addConstantUnion(i, matrix->getLoc()), matrix->getLoc());
        row->setType(rowType(matrix->getBasicType(), matrix->getType()));
        return row;
    }

    // The rows of `operand` as operands of an element-wise operation on matrices of `shape`: a matrix's
    // own rows (a matrix built from rows gives them up, so a chain of operations builds no matrix in
    // between), a scalar repeated in a vector. An operand whose evaluation has effects is evaluated once,
    // into a temporary `evaluations` gains.
    std::vector<TIntermTyped*> rowsOf(TIntermTyped* operand, const TType& shape,
                                      std::vector<TIntermTyped*>& evaluations) {
        const int count = shape.getMatrixCols();
        std::vector<TIntermTyped*> rows;
        if (TIntermAggregate* built = operand->getAsAggregate();
            built && built->isConstructor() && operand->getType().isMatrix() &&
            static_cast<int>(built->getSequence().size()) == count &&
            std::all_of(built->getSequence().begin(), built->getSequence().end(), [&](TIntermNode* row) {
                const TType& type = row->getAsTyped()->getType();  // a whole row, not vectors of mixed sizes
                return type.isVector() && type.getVectorSize() == operand->getType().getMatrixRows() &&
                       type.getBasicType() == operand->getBasicType();
            })) {
            for (TIntermNode* row : built->getSequence()) rows.push_back(row->getAsTyped());
            return rows;
        }
        if (!isSideEffectFree(operand)) operand = evaluatedOnce(operand, evaluations);
        for (int i = 0; i < count; ++i) {
            if (operand->getType().isMatrix()) {
                rows.push_back(rowOfVariable(operand, i));
                continue;
            }
            TIntermAggregate* repeated = new TIntermAggregate;
            repeated->getSequence().push_back(operand);
            const TType vector = rowType(operand->getBasicType(), shape);
            rows.push_back(mIntermediate.setAggregateOperator(
                repeated, mIntermediate.mapTypeToConstructorOp(vector), vector, operand->getLoc()));
        }
        return rows;
    }

    TIntermTyped* evaluatedOnce(TIntermTyped* value, std::vector<TIntermTyped*>& evaluations) {
        TType type;
        type.shallowCopy(value->getType());
        type.getQualifier().makeTemporary();
        const long long id = mNextSymbolId++;
        const auto temporary = [&] {
            glslang::TIntermSymbol* symbol =
                new glslang::TIntermSymbol(id, glslang::TString("splitMatrix"), type);
            symbol->setLoc(value->getLoc());
            return symbol;
        };
        evaluations.push_back(
            mIntermediate.addAssign(glslang::EOpAssign, temporary(), value, value->getLoc()));
        return temporary();
    }

    TIntermTyped* withEvaluations(const std::vector<TIntermTyped*>& evaluations, TIntermTyped* value) {
        for (auto it = evaluations.rbegin(); it != evaluations.rend(); ++it)
            value = mIntermediate.addComma(*it, value, value->getLoc());
        return value;
    }

    TIntermTyped* rowOperation(TOperator op, const std::vector<TIntermTyped*>& operands,
                               glslang::TBasicType base, const TType& matrix, const glslang::TSourceLoc& at) {
        TIntermAggregate* call = new TIntermAggregate(op);
        for (TIntermTyped* operand : operands) call->getSequence().push_back(operand);
        call->setType(rowType(base, matrix));
        call->setLoc(at);
        return call;
    }

    // A matrix of `base` and the shape of `matrix` built from its rows. Its constructor is glslang's of a
    // struct, which its back end builds with one OpCompositeConstruct of the operands (what an array of
    // rows needs): its matrix constructor starts from a float identity and crashes on bool elements. An
    // integer or bool matrix's result is an array of rows after IntegerMatrixArrays; a float one (from a
    // conversion) is a matrix of those vectors alike.
    TIntermTyped* fromRows(const std::vector<TIntermTyped*>& rows, glslang::TBasicType base,
                           const TType& matrix, const glslang::TSourceLoc& at) {
        TIntermAggregate* built = new TIntermAggregate(glslang::EOpConstructStruct);
        for (TIntermTyped* row : rows) built->getSequence().push_back(row);
        built->setType(matrixType(base, matrix));
        built->setLoc(at);
        return built;
    }

    // An integer matrix's constructor made one of row vectors, which SPIR-V builds an array from: from
    // its elements in order, from one scalar (every element, after the pre-visit above), from a matrix
    // (converted element by element, and truncated to its rows and columns).
    void buildFromRows(TIntermAggregate* node) {
        glslang::TIntermSequence& operands = node->getSequence();
        const TType& type = node->getType();
        const int rowCount = type.getMatrixCols(), columns = type.getMatrixRows();
        const glslang::TBasicType base = type.getBasicType();
        const TType row = rowType(base, type);
        const auto converted = [&](TIntermTyped* value) {
            return value->getBasicType() == base ? value : mIntermediate.addConversion(base, value);
        };
        std::vector<TIntermTyped*> rows;
        if (operands.size() == 1 && operands[0]->getAsTyped()->getType().isMatrix()) {
            TIntermTyped* source = operands[0]->getAsTyped();
            if (source->getType().getMatrixCols() < rowCount || source->getType().getMatrixRows() < columns) {
                errorAt(node, "a matrix made from a smaller matrix");  // fxc refuses it too (X3017)
                return;
            }
            std::vector<TIntermTyped*> evaluations;
            const std::vector<TIntermTyped*> sourceRows = rowsOf(source, source->getType(), evaluations);
            for (int i = 0; i < rowCount; ++i) {
                TIntermAggregate* truncated = new TIntermAggregate;
                truncated->getSequence().push_back(converted(sourceRows[i]));
                rows.push_back(mIntermediate.setAggregateOperator(
                    truncated, mIntermediate.mapTypeToConstructorOp(row), row, node->getLoc()));
            }
            replace(node, withEvaluations(evaluations, fromRows(rows, base, type, node->getLoc())));
            return;
        }
        if (operands.size() == 1 && operands[0]->getAsTyped()->getType().isScalarOrVec1()) {
            std::vector<TIntermTyped*> evaluations;
            TIntermTyped* scalar = converted(operands[0]->getAsTyped());
            for (TIntermTyped* repeated : rowsOf(scalar, type, evaluations)) rows.push_back(repeated);
            replace(node, withEvaluations(evaluations, fromRows(rows, base, type, node->getLoc())));
            return;
        }
        const bool fromRowVectors =
            static_cast<int>(operands.size()) == rowCount &&
            std::all_of(operands.begin(), operands.end(),
                        [&](const TIntermNode* operand) { return operand->getAsTyped()->getType() == row; });
        if (fromRowVectors) {
            node->setOperator(glslang::EOpConstructStruct);  // as fromRows builds one
            return;
        }
        const bool fromElements =
            static_cast<int>(operands.size()) == rowCount * columns &&
            std::all_of(operands.begin(), operands.end(), [&](const TIntermNode* operand) {
                return operand->getAsTyped()->getType().isScalarOrVec1();
            });
        if (!fromElements) {
            errorAt(node,
                    "this constructor of an integer or bool matrix (build it from its elements or rows)");
            return;
        }
        for (int i = 0; i < rowCount; ++i) {
            TIntermAggregate* elements = new TIntermAggregate;
            for (int j = 0; j < columns; ++j)
                elements->getSequence().push_back(converted(operands[i * columns + j]->getAsTyped()));
            rows.push_back(mIntermediate.setAggregateOperator(
                elements, mIntermediate.mapTypeToConstructorOp(row), row, node->getLoc()));
        }
        replace(node, fromRows(rows, base, type, node->getLoc()));
    }

    // Puts `to` in `from`'s place. A bool matrix from a comparison that glslang typed as one bool, where
    // its parent takes one bool (no operation split above), is read at its first element, as fxc
    // truncated it.
    void replace(TIntermTyped* from, TIntermTyped* to) {
        TIntermNode* parent = getParentNode();
        if (!from->getType().isMatrix() && to->getType().isMatrix() && !splitsMatrixOperands(parent))
            to = firstElement(to);
        if (!replaceChild(parent, from, to))
            errorAt(from, "this operation on an integer or bool matrix here");
    }

    TIntermTyped* firstElement(TIntermTyped* matrix) {
        std::vector<TIntermTyped*> evaluations;
        TIntermTyped* row = rowsOf(matrix, matrix->getType(), evaluations)[0];
        TIntermTyped* element = mIntermediate.addIndex(
            glslang::EOpIndexDirect, row, mIntermediate.addConstantUnion(0, row->getLoc()), row->getLoc());
        element->setType(TType(row->getBasicType()));
        return withEvaluations(evaluations, element);
    }

    // `c ? x : y`, not an `if` statement.
    static bool isValueSelection(const TIntermSelection* selection) {
        return selection->getBasicType() != glslang::EbtVoid && selection->getTrueBlock() &&
               selection->getFalseBlock() && selection->getTrueBlock()->getAsTyped() &&
               selection->getFalseBlock()->getAsTyped();
    }

    // Whether `parent` is an operation this rewrite splits when an operand is a matrix.
    static bool splitsMatrixOperands(const TIntermNode* parent) {
        if (!parent) return false;
        if (const TIntermBinary* binary = parent->getAsBinaryNode())
            return isElementWiseBinary(binary->getOp());
        if (const TIntermUnary* unary = parent->getAsUnaryNode())
            return isElementWiseUnary(unary->getOp()) || unary->getOp() == glslang::EOpAny ||
                   unary->getOp() == glslang::EOpAll;
        if (const TIntermSelection* selection = parent->getAsSelectionNode())
            return isValueSelection(selection);
        if (const TIntermAggregate* aggregate = parent->getAsAggregate())
            return isElementWiseAggregate(aggregate->getOp()) ||
                   (aggregate->isConstructor() && isIntegerMatrix(aggregate->getType()) &&
                    aggregate->getSequence().size() == 1);
        return false;
    }

    void errorAt(const TIntermNode* node, const std::string& what) {
        const glslang::TSourceLoc& at = node->getLoc();
        errors.push_back({true, at.getFilenameStr(), at.line, at.column,
                          "'matrix' : " + what +
                              " is not supported (shadowfx computes integer and bool matrices row by row)"});
    }
};

}  // namespace

std::vector<HlslMessage> splitIntegerMatrixOperations(glslang::TIntermediate& intermediate,
                                                      long long unusedSymbolId) {
    IntegerMatrixSplitter splitter(intermediate, unusedSymbolId);
    intermediate.getTreeRoot()->traverse(&splitter);
    return std::move(splitter.errors);
}

}  // namespace fx::detail
