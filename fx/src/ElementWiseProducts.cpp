#include "ElementWiseProducts.h"

#include <set>
#include <string>
#include <tuple>

namespace fx::detail {

namespace {

using glslang::TIntermBinary;
using glslang::TOperator;
using glslang::TType;

// A place in the unit as glslang's source locations give it: the file of the unit's `#line`, the line that
// `#line` numbers, and the column in the unit's own line.
using Place = std::tuple<std::string, int, int>;

std::string typeName(const TType& type) {
    const std::string base = type.getBasicTypeString().c_str();
    // glslang's matrix columns are HLSL's rows (HlslToSpirv.h).
    if (type.isMatrix())
        return base + std::to_string(type.getMatrixCols()) + "x" + std::to_string(type.getMatrixRows());
    return type.getVectorSize() > 1 ? base + std::to_string(type.getVectorSize()) : base;
}

// Whether `a` stands before `b` in the same file of the unit.
bool before(const glslang::TSourceLoc& a, const glslang::TSourceLoc& b) {
    return a.string == b.string && (a.line < b.line || (a.line == b.line && a.column < b.column));
}

class StarProducts : public glslang::TIntermTraverser {
public:
    explicit StarProducts(std::set<Place> stars)
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
        if (mStars.count(Place{at.getFilenameStr(), at.line, at.column}) == 0) return true;  // a mul()
        // A `*` stands between its operands; mul(a, b) is built with its operands swapped, so one of them
        // stands on the far side of the call's place. This keeps a mul() that happens to share a `*`'s
        // place (a function's copies, generated code behind its own #line) a product.
        if (before(at, node->getLeft()->getLoc()) || before(node->getRight()->getLoc(), at)) return true;
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
    std::set<Place> mStars;
};

}  // namespace

std::string elementWiseProductOfShapesMessage(const glslang::TType& left, const glslang::TType& right) {
    return "'*' : HLSL multiplies a '" + typeName(left) + "' and a '" + typeName(right) +
           "' element by element, which shadowfx does not do for operands of different shapes; write mul() "
           "for their product, or give both one shape";
}

std::vector<HlslMessage> makeStarProductsElementWise(glslang::TIntermediate& intermediate,
                                                     const std::vector<Token>& tokens) {
    std::set<Place> stars;
    for (const Token& token : tokens)
        if (token.kind == Token::Kind::Punct && (token.text == "*" || token.text == "*="))
            stars.insert(Place{token.loc.file, token.loc.line, token.ppColumn});
    if (stars.empty()) return {};
    StarProducts products(std::move(stars));
    intermediate.getTreeRoot()->traverse(&products);
    return products.errors;
}

}  // namespace fx::detail
