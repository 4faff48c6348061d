// Preshader: runs PreshaderPrograms (fx/PreshaderProgram.h) with HLSL semantics: the preshader VM of the
// contract library, which an application loading compiled effects links without the compiler
// (PreshaderCompiler.cpp compiles expressions into programs).
//
// Values are flat float arrays plus a TypeDesc (see Value.h: matrices row by row). Every operator works
// component-wise after HLSL's scalar broadcast; mul() follows HLSL's convention that a vector on the left
// is a row vector and one on the right a column vector.
//
// [SECTION] Type helpers
// [SECTION] Conversion
// [SECTION] Operators
// [SECTION] Intrinsics and constructors: PreshaderIntrinsics.cpp
// [SECTION] Members and indexing
// [SECTION] Running a program
// [SECTION] Compiling an expression: PreshaderCompiler.cpp
#include <fx/Preshader.h>

#include "PreshaderEvaluator.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>

namespace fx {

namespace detail {

// An operator's spelling resolved once, when a program is compiled.
Operator operatorOf(std::string_view spelling, bool unary) {
    if (unary) {
        return spelling == "-"   ? Operator::Negate
               : spelling == "!" ? Operator::Not
               : spelling == "~" ? Operator::Complement
                                 : Operator::Unknown;
    }
    static const std::pair<std::string_view, Operator> kBinary[] = {
        {"+", Operator::Add},        {"-", Operator::Subtract},   {"*", Operator::Multiply},
        {"/", Operator::Divide},     {"%", Operator::Modulo},     {"<", Operator::Less},
        {">", Operator::Greater},    {"<=", Operator::LessEqual}, {">=", Operator::GreaterEqual},
        {"==", Operator::Equal},     {"!=", Operator::NotEqual},  {"&&", Operator::LogicalAnd},
        {"||", Operator::LogicalOr}, {"&", Operator::BitAnd},     {"|", Operator::BitOr},
        {"^", Operator::BitXor},     {"<<", Operator::ShiftLeft}, {">>", Operator::ShiftRight},
    };
    for (const auto& [text, op] : kBinary)
        if (spelling == text) return op;
    return Operator::Unknown;
}

// [SECTION] Type helpers

bool isNumericBase(BaseType b) {
    return b == BaseType::Bool || b == BaseType::Int || b == BaseType::UInt || b == BaseType::Half ||
           b == BaseType::Float || b == BaseType::Double;
}

size_t elementCount(const TypeDesc& t) {
    size_t n = 1;
    for (int d : t.arrayDims) n *= static_cast<size_t>(d > 0 ? d : 1);
    return n;
}

size_t componentCount(const TypeDesc& t) {
    return static_cast<size_t>(t.rows * t.cols) * elementCount(t);
}

int baseRank(BaseType b) {
    switch (b) {
        case BaseType::Bool:
            return 0;
        case BaseType::Int:
            return 1;
        case BaseType::UInt:
            return 2;
        case BaseType::Half:
            return 3;
        case BaseType::Float:
            return 4;
        case BaseType::Double:
            return 5;
        default:
            return 4;
    }
}

TypeDesc makeType(BaseType base, Shape shape, int rows, int cols) {
    TypeDesc t;
    t.base = base;
    t.shape = shape;
    t.rows = rows;
    t.cols = cols;
    return t;
}

TypeDesc vectorType(BaseType base, int n) {
    return makeType(base, n == 1 ? Shape::Scalar : Shape::Vector, 1, n);
}

Value makeValue(const TypeDesc& type, std::vector<float> data) {
    Value v;
    v.type = type;
    v.data = std::move(data);
    return v;
}

// HLSL's value for an integer that does not fit 32 bits (the D3DCOLOR idiom `int c = 0xff202080;`, a
// `0xFFFFFFFF` mask): the low 32 bits, as two's complement. A plain cast of such a double is undefined.
int32_t wrapToInt32(double x) {
    if (!std::isfinite(x)) return 0;
    const double wrapped = std::fmod(std::trunc(x), 4294967296.0);  // (-2^32, 2^32)
    return static_cast<int32_t>(static_cast<uint32_t>(static_cast<int64_t>(wrapped)));
}

// Stores a component in the representation of its base type: bools 0/1, ints truncated.
float normalizeComponent(BaseType base, float x) {
    switch (base) {
        case BaseType::Bool:
            return x != 0.0f ? 1.0f : 0.0f;
        case BaseType::Int:
            return std::trunc(x);
        case BaseType::UInt:
            return x < 0 ? static_cast<float>(static_cast<uint32_t>(wrapToInt32(x))) : std::trunc(x);
        default:
            return x;
    }
}

// Parses a type constructor name: "float4" -> (Float, 1, 4, Vector), "float4x3", "int", "bool2".
std::optional<TypeDesc> parseTypeName(std::string_view name) {
    static const std::pair<std::string_view, BaseType> kBases[] = {
        {"float", BaseType::Float}, {"half", BaseType::Half}, {"double", BaseType::Double},
        {"int", BaseType::Int},     {"uint", BaseType::UInt}, {"bool", BaseType::Bool},
        {"dword", BaseType::UInt},
    };
    for (const auto& [prefix, base] : kBases) {
        if (name.substr(0, prefix.size()) != prefix) continue;
        std::string_view rest = name.substr(prefix.size());
        if (rest.empty()) return makeType(base, Shape::Scalar, 1, 1);
        if (rest.size() == 1 && rest[0] >= '1' && rest[0] <= '4') return vectorType(base, rest[0] - '0');
        if (rest.size() == 3 && rest[1] == 'x' && rest[0] >= '1' && rest[0] <= '4' && rest[2] >= '1' &&
            rest[2] <= '4')
            return makeType(base, Shape::Matrix, rest[0] - '0', rest[2] - '0');
    }
    return std::nullopt;
}

// [SECTION] Conversion

std::optional<Value> Evaluator::convert(const Value& v, const TypeDesc& target, const SourceLoc& loc) {
    if (target.base == BaseType::String) {
        if (v.type.base != BaseType::String) return fail(DiagId::ExpectedString, loc);
        Value out = v;
        out.type = target;
        return out;
    }
    if (!isNumericBase(target.base)) return fail(DiagId::CannotEvaluateType, loc, {target.hlslName()});
    if (v.type.base == BaseType::String) return fail(DiagId::ExpectedNumber, loc);
    size_t want = componentCount(target);
    std::vector<float> out;
    if (v.data.size() == 1) {
        out.assign(want, v.data[0]);
    } else if (target.shape == Shape::Matrix && v.type.shape == Shape::Matrix && target.arrayDims.empty() &&
               v.type.arrayDims.empty()) {
        // Matrix truncation keeps the upper-left block, as HLSL does.
        if (target.rows > v.type.rows || target.cols > v.type.cols)
            return fail(DiagId::CannotConvertType, loc, {v.type.hlslName(), target.hlslName()});
        for (int r = 0; r < target.rows; ++r)
            for (int c = 0; c < target.cols; ++c)
                out.push_back(v.data[static_cast<size_t>(r * v.type.cols + c)]);
    } else if (v.data.size() >= want) {
        out.assign(v.data.begin(), v.data.begin() + static_cast<std::ptrdiff_t>(want));
    } else {
        return fail(DiagId::ComponentCountMismatch, loc,
                    {std::to_string(v.data.size()), target.hlslName(), std::to_string(want)});
    }
    for (float& x : out) x = normalizeComponent(target.base, x);
    return makeValue(target, std::move(out));
}

bool Evaluator::broadcast(Value& a, Value& b, const SourceLoc& loc) {
    if (a.data.size() == b.data.size()) return true;
    if (a.data.size() == 1) {
        a.data.assign(b.data.size(), a.data[0]);
        a.type = [&] {
            TypeDesc t = b.type;
            t.base = a.type.base;
            return t;
        }();
        return true;
    }
    if (b.data.size() == 1) {
        b.data.assign(a.data.size(), b.data[0]);
        b.type = [&] {
            TypeDesc t = a.type;
            t.base = b.type.base;
            return t;
        }();
        return true;
    }
    // HLSL truncates the longer vector (with a warning).
    if (a.type.shape == Shape::Vector && b.type.shape == Shape::Vector) {
        int n = std::min(a.type.cols, b.type.cols);
        a.data.resize(static_cast<size_t>(n));
        b.data.resize(static_cast<size_t>(n));
        a.type.cols = b.type.cols = n;
        return true;
    }
    fail(DiagId::OperandsMismatch, loc, {a.type.hlslName(), b.type.hlslName()});
    return false;
}

// [SECTION] Operators

std::optional<Value> Evaluator::unary(Operator op, Value a, const SourceLoc& loc) {
    if (a.type.base == BaseType::String) return fail(DiagId::UnaryOperatorOnString, loc);
    for (float& x : a.data) {
        switch (op) {
            case Operator::Negate:
                x = -x;
                break;
            case Operator::Not:
                x = x == 0.0f ? 1.0f : 0.0f;
                break;
            case Operator::Complement:
                x = static_cast<float>(~wrapToInt32(x));
                break;
            default:
                break;
        }
    }
    if (op == Operator::Not) a.type.base = BaseType::Bool;
    if (op == Operator::Negate && a.type.base == BaseType::Bool) a.type.base = BaseType::Int;
    return a;
}

std::optional<Value> Evaluator::binary(Operator op, const std::string& spelling, Value av, Value bv,
                                       const SourceLoc& loc) {
    Value* a = &av;
    Value* b = &bv;
    if (a->type.base == BaseType::String || b->type.base == BaseType::String) {
        if (op == Operator::Equal || op == Operator::NotEqual)
            return Value::boolean((a->string == b->string) == (op == Operator::Equal));
        return fail(DiagId::BinaryOperatorOnString, loc, {spelling});
    }
    if (!broadcast(*a, *b, loc)) return std::nullopt;
    bool logical = op == Operator::LogicalAnd || op == Operator::LogicalOr;
    bool compare = op == Operator::Less || op == Operator::Greater || op == Operator::LessEqual ||
                   op == Operator::GreaterEqual || op == Operator::Equal || op == Operator::NotEqual;
    bool bitwise = op == Operator::BitAnd || op == Operator::BitOr || op == Operator::BitXor ||
                   op == Operator::ShiftLeft || op == Operator::ShiftRight;
    TypeDesc type = a->type;
    type.base = baseRank(a->type.base) >= baseRank(b->type.base) ? a->type.base : b->type.base;
    if (logical || compare) type.base = BaseType::Bool;
    if (bitwise && type.base == BaseType::Bool) type.base = BaseType::Int;
    if (!logical && !compare && !bitwise && type.base == BaseType::Bool) type.base = BaseType::Int;
    bool integer = type.base == BaseType::Int || type.base == BaseType::UInt;
    std::vector<float> out(a->data.size());
    for (size_t i = 0; i < out.size(); ++i) {
        float x = a->data[i], y = b->data[i];
        const int64_t ix = wrapToInt32(x), iy = wrapToInt32(y);
        float r = 0.0f;
        switch (op) {
            case Operator::Add:
                r = x + y;
                break;
            case Operator::Subtract:
                r = x - y;
                break;
            case Operator::Multiply:
                r = x * y;
                break;
            case Operator::Divide:
                if (integer) {
                    if (iy == 0) return fail(DiagId::IntegerDivisionByZero, loc);
                    r = static_cast<float>(ix / iy);
                } else {
                    r = x / y;
                }
                break;
            case Operator::Modulo:
                if (integer) {
                    if (iy == 0) return fail(DiagId::IntegerModuloByZero, loc);
                    r = static_cast<float>(ix % iy);
                } else {
                    r = std::fmod(x, y);
                }
                break;
            case Operator::Less:
                r = x < y;
                break;
            case Operator::Greater:
                r = x > y;
                break;
            case Operator::LessEqual:
                r = x <= y;
                break;
            case Operator::GreaterEqual:
                r = x >= y;
                break;
            case Operator::Equal:
                r = x == y;
                break;
            case Operator::NotEqual:
                r = x != y;
                break;
            case Operator::LogicalAnd:
                r = (x != 0.0f) && (y != 0.0f);
                break;
            case Operator::LogicalOr:
                r = (x != 0.0f) || (y != 0.0f);
                break;
            case Operator::BitAnd:
                r = static_cast<float>(ix & iy);
                break;
            case Operator::BitOr:
                r = static_cast<float>(ix | iy);
                break;
            case Operator::BitXor:
                r = static_cast<float>(ix ^ iy);
                break;
            case Operator::ShiftLeft:
                r = static_cast<float>(ix << iy);
                break;
            case Operator::ShiftRight:
                r = static_cast<float>(ix >> iy);
                break;
            default:
                return fail(DiagId::OperatorNotHostEvaluable, loc, {spelling});
        }
        out[i] = normalizeComponent(type.base, r);
    }
    return makeValue(type, std::move(out));
}

// A vector condition selects per component; a scalar one is handled by the program (it picks a branch).
std::optional<Value> Evaluator::select(const Value& c, Value a, Value b, const SourceLoc& loc) {
    if (!broadcast(a, b, loc)) return std::nullopt;
    if (c.data.size() != a.data.size()) return fail(DiagId::ConditionSizeMismatch, loc);
    for (size_t i = 0; i < a.data.size(); ++i)
        if (c.data[i] == 0.0f) a.data[i] = b.data[i];
    return a;
}

// [SECTION] Members and indexing

std::optional<Value> Evaluator::member(const std::string& m, const Value& baseValue, const SourceLoc& loc) {
    const Value* base = &baseValue;
    std::vector<float> out;
    if (base->type.shape == Shape::Matrix) {
        // ._m00 (zero-based) / ._11 (one-based), possibly chained: ._11_22_33
        size_t i = 0;
        while (i < m.size()) {
            if (m[i] != '_') return fail(DiagId::InvalidMatrixMember, loc, {m});
            ++i;
            int offset = 1;
            if (i < m.size() && m[i] == 'm') {
                offset = 0;
                ++i;
            }
            if (i + 2 > m.size() || !std::isdigit(static_cast<unsigned char>(m[i])) ||
                !std::isdigit(static_cast<unsigned char>(m[i + 1])))
                return fail(DiagId::InvalidMatrixMember, loc, {m});
            int r = m[i] - '0' - offset, c = m[i + 1] - '0' - offset;
            i += 2;
            if (r < 0 || c < 0 || r >= base->type.rows || c >= base->type.cols)
                return fail(DiagId::MatrixMemberOutOfRange, loc, {m});
            out.push_back(base->data[static_cast<size_t>(r * base->type.cols + c)]);
        }
    } else {
        if (m.empty() || m.size() > 4) return fail(DiagId::InvalidSwizzle, loc, {m});
        for (char ch : m) {
            const char* xyzw = "xyzw";
            const char* rgba = "rgba";
            const char* p = std::strchr(xyzw, ch);
            int idx = p ? static_cast<int>(p - xyzw) : -1;
            if (idx < 0 && (p = std::strchr(rgba, ch))) idx = static_cast<int>(p - rgba);
            int avail = base->type.shape == Shape::Scalar ? 1 : base->type.cols;
            if (idx < 0 || ch == '\0' || idx >= avail)
                return fail(DiagId::InvalidSwizzleOnType, loc, {m, base->type.hlslName()});
            out.push_back(base->data[static_cast<size_t>(idx)]);
        }
    }
    return makeValue(vectorType(base->type.base, static_cast<int>(out.size())), std::move(out));
}

std::optional<Value> Evaluator::index(const Value& baseValue, const Value& idx, const SourceLoc& loc) {
    const Value* base = &baseValue;
    int i = idx.asInt();
    TypeDesc elem = base->type;
    size_t stride = 1;
    if (!elem.arrayDims.empty()) {
        elem.arrayDims.erase(elem.arrayDims.begin());
        stride = componentCount(elem);
        if (i < 0 || i >= base->type.arrayDims[0]) return fail(DiagId::IndexOutOfRange, loc);
    } else if (elem.shape == Shape::Matrix) {
        // m[i] is row i, as in HLSL.
        if (i < 0 || i >= elem.rows) return fail(DiagId::MatrixRowIndexOutOfRange, loc);
        elem = vectorType(elem.base, elem.cols);
        stride = static_cast<size_t>(elem.cols);
    } else if (elem.shape == Shape::Vector) {
        if (i < 0 || i >= elem.cols) return fail(DiagId::VectorIndexOutOfRange, loc);
        elem = vectorType(elem.base, 1);
    } else {
        return fail(DiagId::ScalarIndexed, loc);
    }
    auto begin = base->data.begin() + static_cast<std::ptrdiff_t>(static_cast<size_t>(i) * stride);
    return makeValue(elem, std::vector<float>(begin, begin + static_cast<std::ptrdiff_t>(stride)));
}

}  // namespace detail

// [SECTION] Running a program

using detail::Evaluator;
using detail::Operator;

std::string PreshaderProgram::malformation(size_t slotCount) const {
    using Op = Instruction::Op;
    size_t depth = 0;
    for (const Instruction& in : mCode) {
        if (in.op == Op::Constant && in.operand >= mConstants.size()) return "a constant out of range";
        if (in.op == Op::Fail && in.operand >= mErrors.size()) return "an error out of range";
        const size_t pops = in.op == Op::Constant || in.op == Op::Load || in.op == Op::Fail     ? 0
                            : in.op == Op::Unary || in.op == Op::Member || in.op == Op::Convert ? 1
                            : in.op == Op::Binary || in.op == Op::Index                         ? 2
                            : in.op == Op::Select                                               ? 3
                                                                                                : in.count;
        if (pops > depth) return "an instruction takes more operands than the stack holds";
        depth = depth - pops + 1;
    }
    if (!mCode.empty() && depth != 1) return "the program leaves other than one value";
    for (size_t input : mInputs)
        if (input >= slotCount) return "an input slot out of range";
    return "";
}

std::optional<Value> PreshaderProgram::run(const std::vector<Value>& slots,
                                           DiagnosticSink* diagnostics) const {
    using Op = Instruction::Op;
    // Every stack entry is a value or the error that stands in its place (`error` >= 0): an operation on an
    // error gives that error, so a failure counts only if it reaches the result (a scalar condition's
    // branch not taken does not), as when the tree was walked lazily.
    struct Entry {
        Value value;
        int error = -1;
    };
    std::vector<Entry> stack;
    std::vector<Error> errors;
    Evaluator evaluator;
    const auto failed = [&](std::optional<Value> value) {
        if (value) return Entry{std::move(*value), -1};
        errors.push_back(evaluator.error());
        return Entry{Value{}, static_cast<int>(errors.size() - 1)};
    };
    // Pops `n` operands; the first error among them, or -1.
    std::vector<Value> args;
    const auto pop = [&](size_t n) {
        int error = -1;
        args.clear();
        for (size_t i = stack.size() - n; i < stack.size(); ++i) {
            if (error < 0) error = stack[i].error;
            args.push_back(std::move(stack[i].value));
        }
        stack.resize(stack.size() - n);
        return error;
    };
    for (const Instruction& in : mCode) {
        switch (in.op) {
            case Op::Constant:
                stack.push_back({mConstants[in.operand], -1});
                break;
            case Op::Load:
                if (in.operand < slots.size()) {
                    stack.push_back({slots[in.operand], -1});
                } else {
                    errors.push_back({DiagId::UnknownIdentifier, in.loc, {in.text}});
                    stack.push_back({Value{}, static_cast<int>(errors.size() - 1)});
                }
                break;
            case Op::Fail:
                errors.push_back(mErrors[in.operand]);
                stack.push_back({Value{}, static_cast<int>(errors.size() - 1)});
                break;
            case Op::Select: {
                Entry other = std::move(stack.back());
                stack.pop_back();
                Entry then = std::move(stack.back());
                stack.pop_back();
                Entry condition = std::move(stack.back());
                stack.pop_back();
                if (condition.error >= 0) {
                    stack.push_back(std::move(condition));
                } else if (condition.value.data.size() == 1) {
                    stack.push_back(condition.value.data[0] != 0.0f ? std::move(then) : std::move(other));
                } else if (then.error >= 0 || other.error >= 0) {
                    stack.push_back(then.error >= 0 ? std::move(then) : std::move(other));
                } else {
                    stack.push_back(failed(evaluator.select(condition.value, std::move(then.value),
                                                            std::move(other.value), in.loc)));
                }
                break;
            }
            default: {
                const size_t n = in.op == Op::Unary || in.op == Op::Member || in.op == Op::Convert ? 1
                                 : in.op == Op::Binary || in.op == Op::Index                       ? 2
                                                                                                   : in.count;
                const int error = pop(n);
                if (error >= 0) {
                    stack.push_back({Value{}, error});
                    break;
                }
                switch (in.op) {
                    case Op::Unary:
                        stack.push_back(failed(evaluator.unary(in.operation, std::move(args[0]), in.loc)));
                        break;
                    case Op::Binary:
                        stack.push_back(failed(evaluator.binary(in.operation, in.text, std::move(args[0]),
                                                                std::move(args[1]), in.loc)));
                        break;
                    case Op::Construct:
                        stack.push_back(failed(evaluator.construct(in.type, args, in.loc)));
                        break;
                    case Op::Intrinsic:
                        stack.push_back(failed(evaluator.intrinsic(in.text, args, in.loc)));
                        break;
                    case Op::InitList:
                        stack.push_back(failed(evaluator.initList(args, in.loc)));
                        break;
                    case Op::Member:
                        stack.push_back(failed(evaluator.member(in.text, args[0], in.loc)));
                        break;
                    case Op::Index:
                        stack.push_back(failed(evaluator.index(args[0], args[1], in.loc)));
                        break;
                    case Op::Convert:
                        stack.push_back(failed(evaluator.convert(args[0], in.type, in.loc)));
                        break;
                    default:
                        break;
                }
            }
        }
    }
    if (stack.size() != 1) return std::nullopt;  // an empty program
    if (stack.back().error >= 0) {
        if (diagnostics) {
            const Error& error = errors[static_cast<size_t>(stack.back().error)];
            diagnostics->report(error.id, error.loc, error.args);
        }
        return std::nullopt;
    }
    return std::move(stack.back().value);
}

}  // namespace fx
