// ConstantFolding: see ConstantFolding.h.
#include "ConstantFolding.h"

#include "TypeNames.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace fx::detail {

bool foldConstant(const Effect& effect, const Expr& e, double& out, int depth) {
    if (depth > 32) return false;
    auto integer = [](double x) {
        return std::isfinite(x) && std::abs(x) < 2147483648.0 ? static_cast<int64_t>(x) : int64_t{0};
    };
    switch (e.kind) {
        case Expr::Kind::Number:
        case Expr::Kind::Bool:
            out = e.number;
            return true;
        case Expr::Kind::Identifier: {
            const Parameter* p = effect.findParameter(e.text);
            if (!p || !(p->isConst || p->isStatic) || !p->initializer || !p->type.isNumeric() ||
                !p->type.arrayDims.empty())
                return false;
            if (!foldConstant(effect, *p->initializer, out, depth + 1)) return false;
            if (p->type.base == BaseType::Int || p->type.base == BaseType::UInt) out = std::trunc(out);
            return true;
        }
        case Expr::Kind::Member: {
            // One component of a constant vector: `SIZE.x` of `static const int2 SIZE = int2(4, 2);`.
            static const std::string kComponents[] = {"xyzw", "rgba"};
            int component = -1;
            for (const std::string& set : kComponents)
                if (e.text.size() == 1 && set.find(e.text[0]) != std::string::npos)
                    component = static_cast<int>(set.find(e.text[0]));
            if (component < 0 || e.args.size() != 1) return false;
            const Expr* vector = &e.args[0];
            if (vector->kind == Expr::Kind::Identifier) {
                const Parameter* p = effect.findParameter(vector->text);
                if (!p || !(p->isConst || p->isStatic) || !p->initializer || !p->type.arrayDims.empty())
                    return false;
                vector = &*p->initializer;
            }
            TypeDesc constructed;
            const bool constructor =
                vector->kind == Expr::Kind::Call && parseScalarTypeName(vector->text, constructed);
            if ((!constructor && vector->kind != Expr::Kind::InitList) ||
                static_cast<int>(vector->args.size()) <= component)
                return false;
            return foldConstant(effect, vector->args[static_cast<size_t>(component)], out, depth + 1);
        }
        case Expr::Kind::Call:
            // min, max and abs of constants: fxc folded them in array sizes.
            if ((e.text == "min" || e.text == "max") && e.args.size() == 2) {
                double a, b;
                if (!foldConstant(effect, e.args[0], a, depth + 1) ||
                    !foldConstant(effect, e.args[1], b, depth + 1))
                    return false;
                out = e.text == "min" ? std::min(a, b) : std::max(a, b);
                return true;
            }
            if (e.text == "abs" && e.args.size() == 1) {
                if (!foldConstant(effect, e.args[0], out, depth + 1)) return false;
                out = std::abs(out);
                return true;
            }
            [[fallthrough]];
        case Expr::Kind::Cast:
            // (int)x, int(x), float(x)
            if (e.args.size() != 1 || !foldConstant(effect, e.args[0], out, depth + 1)) return false;
            if (e.kind == Expr::Kind::Call && e.text != "int" && e.text != "uint" && e.text != "float")
                return false;
            if ((e.kind == Expr::Kind::Cast &&
                 (e.castType.base == BaseType::Int || e.castType.base == BaseType::UInt)) ||
                e.text == "int" || e.text == "uint")
                out = std::trunc(out);
            return true;
        case Expr::Kind::Unary: {
            double a;
            if (e.args.size() != 1 || !foldConstant(effect, e.args[0], a, depth + 1)) return false;
            out = e.text == "-" ? -a : e.text == "+" ? a : e.text == "!" ? !a : 0;
            return e.text != "~";
        }
        case Expr::Kind::Ternary: {
            double c;
            if (e.args.size() != 3 || !foldConstant(effect, e.args[0], c, depth + 1)) return false;
            return foldConstant(effect, e.args[c != 0 ? 1 : 2], out, depth + 1);
        }
        case Expr::Kind::Binary: {
            double a, b;
            if (e.args.size() != 2 || !foldConstant(effect, e.args[0], a, depth + 1) ||
                !foldConstant(effect, e.args[1], b, depth + 1))
                return false;
            const int64_t ia = integer(a), ib = integer(b);
            if (e.text == "+")
                out = a + b;
            else if (e.text == "-")
                out = a - b;
            else if (e.text == "*")
                out = a * b;
            else if (e.text == "/" && b != 0)  // whole operands divide as HLSL's ints do
                out = a == std::trunc(a) && b == std::trunc(b) ? std::trunc(a / b) : a / b;
            else if (e.text == "%" && ib != 0)
                out = static_cast<double>(ia % ib);
            else if (e.text == "<<" && ib >= 0 && ib < 32)
                out = static_cast<double>(ia * (int64_t{1} << ib));
            else if (e.text == ">>" && ib >= 0 && ib < 32)
                out = static_cast<double>(ia >> ib);
            else if (e.text == "<" || e.text == "<=" || e.text == ">" || e.text == ">=" || e.text == "==" ||
                     e.text == "!=")  // a loop's condition over its counter
                out = e.text == "<"    ? a < b
                      : e.text == "<=" ? a <= b
                      : e.text == ">"  ? a > b
                      : e.text == ">=" ? a >= b
                      : e.text == "==" ? a == b
                                       : a != b;
            else if (e.text == "&&" || e.text == "||")
                out = e.text == "&&" ? (a != 0 && b != 0) : (a != 0 || b != 0);
            else
                return false;
            return true;
        }
        default:
            return false;
    }
}

}  // namespace fx::detail
