// ComponentWrites: see ComponentWrites.h.
#include "ComponentWrites.h"

#include "ComposedIntrinsics.h"
#include "PreshaderEvaluator.h"

#include <algorithm>
#include <cstring>

namespace fx::detail {

namespace {

Expr castTo(const TypeDesc& type, Expr value, const SourceLoc& loc) {
    Expr e = exprNode(Expr::Kind::Cast, loc, "", {std::move(value)});
    e.castType = type;
    return e;
}

}  // namespace

std::optional<Expr> writeComponents(const TypeDesc& type, const std::string& member, Expr old, Expr value,
                                    const SourceLoc& loc) {
    if (!type.arrayDims.empty() || (type.shape != Shape::Vector && type.shape != Shape::Scalar))
        return std::nullopt;
    const int columns = type.shape == Shape::Scalar ? 1 : type.cols;
    std::vector<int> written;
    for (char c : member) {
        const char* at = std::strchr("xyzw", c);
        const char* colour = std::strchr("rgba", c);
        const int index = c == '\0' ? -1
                          : at      ? static_cast<int>(at - "xyzw")
                          : colour  ? static_cast<int>(colour - "rgba")
                                    : -1;
        if (index < 0 || index >= columns) return std::nullopt;
        written.push_back(index);
    }
    TypeDesc component = type;
    component.shape = Shape::Scalar;
    component.cols = 1;
    std::vector<Expr> spread, mask;
    for (int i = 0; i < columns; ++i) {
        const auto k = std::find(written.begin(), written.end(), i);
        Expr flag;
        flag.kind = Expr::Kind::Bool;
        flag.loc = loc;
        flag.number = k != written.end() ? 1.0 : 0.0;
        mask.push_back(std::move(flag));
        Expr zero;
        zero.kind = Expr::Kind::Number;
        zero.loc = loc;
        spread.push_back(
            k == written.end() ? std::move(zero)
            : written.size() == 1
                ? castTo(component, value, loc)
                : exprNode(Expr::Kind::Member, loc, std::string(1, "xyzw"[k - written.begin()]), {value}));
    }
    if (columns == 1) return castTo(type, std::move(value), loc);
    TypeDesc boolean = type;
    boolean.base = BaseType::Bool;
    return exprNode(Expr::Kind::Ternary, loc, kComponentSelect,
                    {exprNode(Expr::Kind::Call, loc, boolean.hlslName(), std::move(mask)),
                     exprNode(Expr::Kind::Call, loc, type.hlslName(), std::move(spread)), std::move(old)});
}

TypeDesc matrixRowType(const TypeDesc& matrix) {
    TypeDesc row = matrix;
    row.shape = Shape::Vector;
    row.rows = 1;
    return row;
}

std::vector<Expr> matrixRows(const TypeDesc& type, const Expr& old, const SourceLoc& loc) {
    if (old.kind == Expr::Kind::Call && old.text == type.hlslName() &&
        old.args.size() == static_cast<size_t>(type.rows))
        return old.args;
    std::vector<Expr> rows;
    for (int r = 0; r < type.rows; ++r) {
        Expr index = exprNode(Expr::Kind::Number, loc, "", {});
        index.number = r;
        index.isInteger = true;
        rows.push_back(exprNode(Expr::Kind::Index, loc, "", {old, std::move(index)}));
    }
    return rows;
}

std::optional<Expr> writeMatrixElements(const TypeDesc& type, const std::string& member, const Expr& old,
                                        const Expr& value, const SourceLoc& loc) {
    const PreshaderProgram::Instruction::MemberComponents elements = memberComponents(member);
    const size_t count = elements.matrixCount;
    if (count == 0 || !type.arrayDims.empty()) return std::nullopt;
    for (size_t k = 0; k < count; ++k) {
        if (elements.rows[k] >= type.rows || elements.columns[k] >= type.cols) return std::nullopt;
        for (size_t j = 0; j < k; ++j)
            if (elements.rows[j] == elements.rows[k] && elements.columns[j] == elements.columns[k])
                return std::nullopt;
    }
    const TypeDesc row = matrixRowType(type);
    std::vector<Expr> rows = matrixRows(type, old, loc);
    for (size_t r = 0; r < rows.size(); ++r) {
        std::string columns, picked;
        for (size_t k = 0; k < count; ++k) {
            if (elements.rows[k] != r) continue;
            columns += "xyzw"[elements.columns[k]];
            picked += "xyzw"[k];
        }
        if (columns.empty()) continue;
        Expr part = count == 1 ? value : exprNode(Expr::Kind::Member, loc, picked, {value});
        std::optional<Expr> changed = writeComponents(row, columns, std::move(rows[r]), std::move(part), loc);
        if (!changed) return std::nullopt;
        rows[r] = std::move(*changed);
    }
    return exprNode(Expr::Kind::Call, loc, type.hlslName(), std::move(rows));
}

}  // namespace fx::detail
