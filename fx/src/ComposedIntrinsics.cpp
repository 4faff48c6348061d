// ComposedIntrinsics: intrinsics the host evaluator lacks, written with those it has (see the header).
#include "ComposedIntrinsics.h"

#include <utility>

namespace fx::detail {

Expr exprNode(Expr::Kind kind, const SourceLoc& loc, std::string text, std::vector<Expr> args) {
    Expr e;
    e.kind = kind;
    e.loc = loc;
    e.text = std::move(text);
    e.args = std::move(args);
    return e;
}

void expandComposedIntrinsic(Expr& e) {
    const SourceLoc loc = e.loc;
    auto number = [&](double value) {
        Expr n;
        n.kind = Expr::Kind::Number;
        n.number = value;
        n.loc = loc;
        return n;
    };
    auto binary = [&](const char* op, Expr a, Expr b) {
        return exprNode(Expr::Kind::Binary, loc, op, {std::move(a), std::move(b)});
    };
    auto call = [&](const char* name, std::vector<Expr> args) {
        return exprNode(Expr::Kind::Call, loc, name, std::move(args));
    };
    auto negated = [&](Expr a) { return exprNode(Expr::Kind::Unary, loc, "-", {std::move(a)}); };
    const std::vector<Expr>& a = e.args;
    const std::string& name = e.text;
    if (name == "ldexp" && a.size() == 2) {
        e = binary("*", a[0], call("exp2", {a[1]}));
    } else if (name == "rcp" && a.size() == 1) {
        e = binary("/", number(1), a[0]);
    } else if (name == "mad" && a.size() == 3) {
        e = binary("+", binary("*", a[0], a[1]), a[2]);
    } else if ((name == "sinh" || name == "cosh") && a.size() == 1) {
        e = binary("*", binary(name == "sinh" ? "-" : "+", call("exp", {a[0]}), call("exp", {negated(a[0])})),
                   number(0.5));
    } else if (name == "tanh" && a.size() == 1) {
        // 1 - 2 / (e^2x + 1): ±1 where e^2x overflows or vanishes, not inf / inf.
        e = binary(
            "-", number(1),
            binary("/", number(2), binary("+", call("exp", {binary("*", number(2), a[0])}), number(1))));
    } else if (name == "reflect" && a.size() == 2) {
        e = binary("-", a[0], binary("*", binary("*", number(2), call("dot", {a[0], a[1]})), a[1]));
    } else if (name == "faceforward" && a.size() == 3) {
        e = binary("*", negated(a[0]), call("sign", {call("dot", {a[1], a[2]})}));
    } else if ((name == "any" || name == "all") && a.size() == 1) {
        // Over the components that are not zero (1) or are (0): any sums the first, all the second.
        Expr nonZero = call("abs", {call("sign", {a[0]})});
        Expr counted = name == "any" ? nonZero : binary("-", number(1), nonZero);
        Expr sum = call("dot", {counted, counted});
        e = name == "any" ? binary(">", std::move(sum), number(0)) : binary("==", std::move(sum), number(0));
    } else if (name == "lit" && a.size() == 3) {
        // As the shaders' replacement (HlslRewriting.h): the specular term is 0 where either cosine is.
        Expr specular = exprNode(Expr::Kind::Ternary, loc, "",
                                 {binary("||", binary("<", a[0], number(0)), binary("<", a[1], number(0))),
                                  number(0), call("pow", {call("max", {a[1], number(0)}), a[2]})});
        e = call("float4", {number(1), call("max", {a[0], number(0)}), std::move(specular), number(1)});
    }
}

}  // namespace fx::detail
