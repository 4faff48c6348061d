#include "ElementWiseProducts.h"

#include <set>
#include <string>
#include <tuple>

namespace fx::detail {

namespace {

using glslang::TIntermBinary;
using glslang::TOperator;
using glslang::TType;

std::string typeName(const TType& type) {
    const std::string base = type.getBasicTypeString().c_str();
    // glslang's matrix columns are HLSL's rows (HlslToSpirv.h).
    if (type.isMatrix())
        return base + std::to_string(type.getMatrixCols()) + "x" + std::to_string(type.getMatrixRows());
    return type.getVectorSize() > 1 ? base + std::to_string(type.getVectorSize()) : base;
}

class StarProducts : public glslang::TIntermTraverser {
public:
    explicit StarProducts(std::set<SourcePlace> stars)
        : TIntermTraverser(false, false, true), mStars(std::move(stars)) {}

    std::vector<HlslMessage> errors;

    bool visitBinary(glslang::TVisit, TIntermBinary* node) override {
        const TOperator op = node->getOp();
        const bool ofMatrices =
            op == glslang::EOpMatrixTimesMatrix || op == glslang::EOpMatrixTimesMatrixAssign;
        const bool withVector = op == glslang::EOpMatrixTimesVector || op == glslang::EOpVectorTimesMatrix ||
                                op == glslang::EOpVectorTimesMatrixAssign;
        if (!ofMatrices && !withVector) return true;
        const glslang::TSourceLoc& at = node->getLoc();
        if (mStars.count(placeOf(at)) == 0 || !standsBetweenItsOperands(*node)) return true;  // a mul()
        const TType& left = node->getLeft()->getType();
        const TType& right = node->getRight()->getType();
        // A product of two matrices of one shape is one of square matrices, whose result has that shape too.
        if (ofMatrices && left.getMatrixCols() == right.getMatrixCols() &&
            left.getMatrixRows() == right.getMatrixRows()) {
            node->setOp(op == glslang::EOpMatrixTimesMatrix ? glslang::EOpMul : glslang::EOpMulAssign);
            return true;
        }
        errors.push_back(
            {true, at.getFilenameStr(), at.line, at.column, elementWiseProductOfShapesMessage(left, right)});
        return true;
    }

private:
    std::set<SourcePlace> mStars;
};

// Whether `a` stands before `b` in the same file of the unit.
bool before(const glslang::TSourceLoc& a, const glslang::TSourceLoc& b) {
    return a.string == b.string && (a.line < b.line || (a.line == b.line && a.column < b.column));
}

}  // namespace

SourcePlace placeOf(const Token& token) {
    return SourcePlace{token.loc.file, token.loc.line, token.ppColumn};
}

SourcePlace placeOf(const glslang::TSourceLoc& loc) {
    return SourcePlace{loc.getFilenameStr(), loc.line, loc.column};
}

bool standsBetweenItsOperands(const glslang::TIntermBinary& node) {
    const glslang::TSourceLoc& at = node.getLoc();
    return !before(at, node.getLeft()->getLoc()) && !before(node.getRight()->getLoc(), at);
}

std::string elementWiseProductOfShapesMessage(const glslang::TType& left, const glslang::TType& right) {
    return "'*' : HLSL multiplies a '" + typeName(left) + "' and a '" + typeName(right) +
           "' element by element, which shadowfx does not do for operands of different shapes; write mul() "
           "for their product, or give both one shape";
}

std::vector<HlslMessage> makeStarProductsElementWise(glslang::TIntermediate& intermediate,
                                                     const std::vector<Token>& tokens) {
    std::set<SourcePlace> stars;
    for (const Token& token : tokens)
        if (token.kind == Token::Kind::Punct && (token.text == "*" || token.text == "*="))
            stars.insert(placeOf(token));
    if (stars.empty()) return {};
    StarProducts products(std::move(stars));
    intermediate.getTreeRoot()->traverse(&products);
    return products.errors;
}

}  // namespace fx::detail
