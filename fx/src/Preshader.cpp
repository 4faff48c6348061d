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
#include <span>

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

Function functionOf(std::string_view name) {
    static const std::pair<std::string_view, Function> kFunctions[] = {
        {"abs", Function::Abs},
        {"sqrt", Function::Sqrt},
        {"rsqrt", Function::Rsqrt},
        {"exp", Function::Exp},
        {"exp2", Function::Exp2},
        {"log", Function::Log},
        {"log2", Function::Log2},
        {"log10", Function::Log10},
        {"sin", Function::Sin},
        {"cos", Function::Cos},
        {"tan", Function::Tan},
        {"asin", Function::Asin},
        {"acos", Function::Acos},
        {"atan", Function::Atan},
        {"radians", Function::Radians},
        {"degrees", Function::Degrees},
        {"floor", Function::Floor},
        {"ceil", Function::Ceil},
        {"round", Function::Round},
        {"trunc", Function::Trunc},
        {"frac", Function::Frac},
        {"saturate", Function::Saturate},
        {"sign", Function::Sign},
        {"min", Function::Min},
        {"max", Function::Max},
        {"pow", Function::Pow},
        {"atan2", Function::Atan2},
        {"fmod", Function::Fmod},
        {"step", Function::Step},
        {"clamp", Function::Clamp},
        {"lerp", Function::Lerp},
        {"smoothstep", Function::Smoothstep},
        {"dot", Function::Dot},
        {"length", Function::Length},
        {"normalize", Function::Normalize},
        {"distance", Function::Distance},
        {"cross", Function::Cross},
        {"transpose", Function::Transpose},
        {"determinant", Function::Determinant},
        {"inverse", Function::Inverse},
        {"mul", Function::Mul},
    };
    for (const auto& [text, function] : kFunctions)
        if (name == text) return function;
    return Function::Unknown;
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

void setType(TypeDesc& t, BaseType base, Shape shape, int rows, int cols) {
    t.base = base;
    t.shape = shape;
    t.rows = rows;
    t.cols = cols;
    t.arrayDims.clear();
    t.structName.clear();
    t.rowMajor = false;
    t.templateArgs.clear();
}

void setVectorType(TypeDesc& t, BaseType base, int n) {
    setType(t, base, n == 1 ? Shape::Scalar : Shape::Vector, 1, n);
}

void setScalar(Value& v, BaseType base, float x) {
    setType(v.type, base, Shape::Scalar, 1, 1);
    v.data.assign(1, x);
    v.string.clear();
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

bool Evaluator::convert(Value& v, const TypeDesc& target, const SourceLoc& loc) {
    if (target.base == BaseType::String) {
        if (v.type.base != BaseType::String) return fail(DiagId::ExpectedString, loc);
        v.type = target;
        return true;
    }
    if (!isNumericBase(target.base)) return fail(DiagId::CannotEvaluateType, loc, {target.hlslName()});
    if (v.type.base == BaseType::String) return fail(DiagId::ExpectedNumber, loc);
    const size_t want = componentCount(target);
    if (v.data.size() == 1) {
        const float x = v.data[0];
        v.data.assign(want, x);
    } else if (target.shape == Shape::Matrix && v.type.shape == Shape::Matrix && target.arrayDims.empty() &&
               v.type.arrayDims.empty()) {
        // Matrix truncation keeps the upper-left block, as HLSL does. In place: each component moves to
        // an index no greater than its own, after every component before it.
        if (target.rows > v.type.rows || target.cols > v.type.cols)
            return fail(DiagId::CannotConvertType, loc, {v.type.hlslName(), target.hlslName()});
        size_t out = 0;
        for (int r = 0; r < target.rows; ++r)
            for (int c = 0; c < target.cols; ++c)
                v.data[out++] = v.data[static_cast<size_t>(r * v.type.cols + c)];
        v.data.resize(out);
    } else if (v.data.size() >= want) {
        v.data.resize(want);
    } else {
        return fail(DiagId::ComponentCountMismatch, loc,
                    {std::to_string(v.data.size()), target.hlslName(), std::to_string(want)});
    }
    for (float& x : v.data) x = normalizeComponent(target.base, x);
    v.type = target;
    v.string.clear();
    return true;
}

bool Evaluator::broadcast(Value& a, Value& b, const SourceLoc& loc) {
    if (a.data.size() == b.data.size()) return true;
    if (a.data.size() == 1) {
        const float x = a.data[0];
        a.data.assign(b.data.size(), x);
        const BaseType base = a.type.base;
        a.type = b.type;
        a.type.base = base;
        return true;
    }
    if (b.data.size() == 1) {
        const float x = b.data[0];
        b.data.assign(a.data.size(), x);
        const BaseType base = b.type.base;
        b.type = a.type;
        b.type.base = base;
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
    return fail(DiagId::OperandsMismatch, loc, {a.type.hlslName(), b.type.hlslName()});
}

// [SECTION] Operators

bool Evaluator::unary(Operator op, Value& a, const SourceLoc& loc) {
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
    return true;
}

bool Evaluator::binary(Operator op, const std::string& spelling, Value& a, Value& b, const SourceLoc& loc) {
    if (a.type.base == BaseType::String || b.type.base == BaseType::String) {
        if (op == Operator::Equal || op == Operator::NotEqual) {
            setScalar(a, BaseType::Bool, (a.string == b.string) == (op == Operator::Equal) ? 1.0f : 0.0f);
            return true;
        }
        return fail(DiagId::BinaryOperatorOnString, loc, {spelling});
    }
    if (!broadcast(a, b, loc)) return false;
    bool logical = op == Operator::LogicalAnd || op == Operator::LogicalOr;
    bool compare = op == Operator::Less || op == Operator::Greater || op == Operator::LessEqual ||
                   op == Operator::GreaterEqual || op == Operator::Equal || op == Operator::NotEqual;
    bool bitwise = op == Operator::BitAnd || op == Operator::BitOr || op == Operator::BitXor ||
                   op == Operator::ShiftLeft || op == Operator::ShiftRight;
    BaseType base = baseRank(a.type.base) >= baseRank(b.type.base) ? a.type.base : b.type.base;
    if (logical || compare) base = BaseType::Bool;
    if (bitwise && base == BaseType::Bool) base = BaseType::Int;
    if (!logical && !compare && !bitwise && base == BaseType::Bool) base = BaseType::Int;
    bool integer = base == BaseType::Int || base == BaseType::UInt;
    for (size_t i = 0; i < a.data.size(); ++i) {
        float x = a.data[i], y = b.data[i];
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
        a.data[i] = normalizeComponent(base, r);
    }
    a.type.base = base;
    a.string.clear();
    return true;
}

// A vector condition selects per component; a scalar one is handled by the program (it picks a branch).
bool Evaluator::select(const Value& c, Value& a, Value& b, const SourceLoc& loc) {
    if (!broadcast(a, b, loc)) return false;
    if (c.data.size() != a.data.size()) return fail(DiagId::ConditionSizeMismatch, loc);
    for (size_t i = 0; i < a.data.size(); ++i)
        if (c.data[i] == 0.0f) a.data[i] = b.data[i];
    return true;
}

// [SECTION] Members and indexing

bool Evaluator::member(const PreshaderProgram::Instruction::MemberComponents& components,
                       const std::string& text, Value& base, const SourceLoc& loc) {
    using Instruction = PreshaderProgram::Instruction;
    mScratch.clear();
    if (base.type.shape == Shape::Matrix) {
        if (components.matrixCount == 0) return fail(DiagId::InvalidMatrixMember, loc, {text});
        for (size_t k = 0; k < components.matrixCount; ++k) {
            const int r = components.rows[k], c = components.columns[k];
            if (r == Instruction::kNoComponent || c == Instruction::kNoComponent || r >= base.type.rows ||
                c >= base.type.cols)
                return fail(DiagId::MatrixMemberOutOfRange, loc, {text});
            mScratch.push_back(base.data[static_cast<size_t>(r * base.type.cols + c)]);
        }
    } else {
        if (components.swizzleCount == 0) return fail(DiagId::InvalidSwizzle, loc, {text});
        const int available = base.type.shape == Shape::Scalar ? 1 : base.type.cols;
        for (size_t k = 0; k < components.swizzleCount; ++k) {
            const int component = components.swizzle[k];
            if (component >= available)  // kNoComponent included
                return fail(DiagId::InvalidSwizzleOnType, loc, {text, base.type.hlslName()});
            mScratch.push_back(base.data[static_cast<size_t>(component)]);
        }
    }
    base.data.assign(mScratch.begin(), mScratch.end());
    setVectorType(base.type, base.type.base, static_cast<int>(mScratch.size()));
    base.string.clear();
    return true;
}

PreshaderProgram::Instruction::MemberComponents memberComponents(std::string_view m) {
    using Instruction = PreshaderProgram::Instruction;
    Instruction::MemberComponents components;
    if (!m.empty() && m.size() <= 4) {
        components.swizzleCount = static_cast<uint8_t>(m.size());
        for (size_t k = 0; k < m.size(); ++k) {
            const size_t xyzw = std::string_view("xyzw").find(m[k]);
            const size_t rgba = std::string_view("rgba").find(m[k]);
            components.swizzle[k] = xyzw != std::string_view::npos   ? static_cast<uint8_t>(xyzw)
                                    : rgba != std::string_view::npos ? static_cast<uint8_t>(rgba)
                                                                     : Instruction::kNoComponent;
        }
    }
    // ._m00 (zero-based) / ._11 (one-based), possibly chained: ._11_22_33
    uint8_t count = 0;
    size_t i = 0;
    while (i < m.size()) {
        if (m[i] != '_' || count == 4) return components;
        ++i;
        int offset = 1;
        if (i < m.size() && m[i] == 'm') {
            offset = 0;
            ++i;
        }
        if (i + 2 > m.size() || !std::isdigit(static_cast<unsigned char>(m[i])) ||
            !std::isdigit(static_cast<unsigned char>(m[i + 1])))
            return components;
        const int r = m[i] - '0' - offset, c = m[i + 1] - '0' - offset;
        i += 2;
        components.rows[count] = r < 0 ? Instruction::kNoComponent : static_cast<uint8_t>(r);
        components.columns[count] = c < 0 ? Instruction::kNoComponent : static_cast<uint8_t>(c);
        ++count;
    }
    components.matrixCount = count;
    return components;
}

bool Evaluator::index(Value& base, const Value& idx, const SourceLoc& loc) {
    int i = idx.asInt();
    TypeDesc& elem = base.type;
    size_t stride = 1;
    if (!elem.arrayDims.empty()) {
        if (i < 0 || i >= elem.arrayDims[0]) return fail(DiagId::IndexOutOfRange, loc);
        elem.arrayDims.erase(elem.arrayDims.begin());
        stride = componentCount(elem);
    } else if (elem.shape == Shape::Matrix) {
        // m[i] is row i, as in HLSL.
        if (i < 0 || i >= elem.rows) return fail(DiagId::MatrixRowIndexOutOfRange, loc);
        setVectorType(elem, elem.base, elem.cols);
        stride = static_cast<size_t>(elem.cols);
    } else if (elem.shape == Shape::Vector) {
        if (i < 0 || i >= elem.cols) return fail(DiagId::VectorIndexOutOfRange, loc);
        setVectorType(elem, elem.base, 1);
    } else {
        return fail(DiagId::ScalarIndexed, loc);
    }
    const size_t first = static_cast<size_t>(i) * stride;
    if (first > 0) std::memmove(base.data.data(), base.data.data() + first, stride * sizeof(float));
    base.data.resize(stride);
    base.string.clear();
    return true;
}

}  // namespace detail

// [SECTION] Running a program

using detail::Evaluator;

std::optional<DiagId> PreshaderProgram::malformation(size_t slotCount) const {
    using Op = Instruction::Op;
    size_t depth = 0;
    for (const Instruction& in : mCode) {
        if (in.op == Op::Constant && in.operand >= mConstants.size())
            return DiagId::CompiledEffectPreshaderConstantOutOfRange;
        if (in.op == Op::Fail && in.operand >= mErrors.size())
            return DiagId::CompiledEffectPreshaderErrorOutOfRange;
        if (in.op == Op::Member && (in.member.swizzleCount > 4 || in.member.matrixCount > 4))
            return DiagId::CompiledEffectPreshaderMemberTooWide;
        const size_t pops = in.op == Op::Constant || in.op == Op::Load || in.op == Op::Fail     ? 0
                            : in.op == Op::Unary || in.op == Op::Member || in.op == Op::Convert ? 1
                            : in.op == Op::Binary || in.op == Op::Index                         ? 2
                            : in.op == Op::Select                                               ? 3
                                                                                                : in.count;
        if (pops > depth) return DiagId::CompiledEffectPreshaderStackUnderflow;
        depth = depth - pops + 1;
    }
    if (!mCode.empty() && depth != 1) return DiagId::CompiledEffectPreshaderResultCount;
    for (size_t input : mInputs)
        if (input >= slotCount) return DiagId::CompiledEffectPreshaderInputOutOfRange;
    return std::nullopt;
}

const Value* PreshaderProgram::run(const std::vector<Value>& slots, Registers& registers,
                                   DiagnosticSink* diagnostics) const {
    using Op = Instruction::Op;
    // Every depth of the stack holds a value or the error that stands in its place (entryErrors >= 0): an
    // operation on an error gives that error, so a failure counts only if it reaches the result (a scalar
    // condition's branch not taken does not), as when the tree was walked lazily. An operation's result
    // takes the place of its first operand; values are copied into place, never swapped, so that each
    // depth keeps the storage this program's values need there.
    std::vector<Value>& values = registers.mValues;
    std::vector<int>& entryErrors = registers.mEntryErrors;
    std::vector<Error>& errors = registers.mErrors;
    errors.clear();
    Evaluator evaluator(registers.mScratch);
    size_t depth = 0;
    const auto push = [&]() -> Value& {
        if (depth == values.size()) {
            values.emplace_back();
            entryErrors.push_back(-1);
        }
        entryErrors[depth] = -1;
        return values[depth++];
    };
    const auto pushError = [&](const Error& error) {
        push();
        errors.push_back(error);
        entryErrors[depth - 1] = static_cast<int>(errors.size() - 1);
    };
    for (const Instruction& in : mCode) {
        switch (in.op) {
            case Op::Constant:
                push() = mConstants[in.operand];
                break;
            case Op::Load:
                if (in.operand < slots.size()) {
                    push() = slots[in.operand];
                } else {
                    pushError({DiagId::UnknownIdentifier, in.loc, {in.text}});
                }
                break;
            case Op::Fail:
                pushError(mErrors[in.operand]);
                break;
            case Op::Select: {
                depth -= 2;
                const size_t condition = depth - 1, then = depth, other = depth + 1;
                if (entryErrors[condition] >= 0) break;
                if (values[condition].data.size() == 1) {
                    const size_t taken = values[condition].data[0] != 0.0f ? then : other;
                    values[condition] = values[taken];
                    entryErrors[condition] = entryErrors[taken];
                } else if (entryErrors[then] >= 0 || entryErrors[other] >= 0) {
                    entryErrors[condition] = entryErrors[then] >= 0 ? entryErrors[then] : entryErrors[other];
                } else if (evaluator.select(values[condition], values[then], values[other], in.loc)) {
                    values[condition] = values[then];
                } else {
                    errors.push_back(evaluator.error());
                    entryErrors[condition] = static_cast<int>(errors.size() - 1);
                }
                break;
            }
            default: {
                const size_t n = in.op == Op::Unary || in.op == Op::Member || in.op == Op::Convert ? 1
                                 : in.op == Op::Binary || in.op == Op::Index                       ? 2
                                                                                                   : in.count;
                // The operands' first error, if any, takes their place.
                const size_t first = depth - n;
                int error = -1;
                for (size_t i = first; i < depth && error < 0; ++i) error = entryErrors[i];
                depth = first;
                Value& out = push();
                if (error >= 0) {
                    entryErrors[first] = error;
                    break;
                }
                const std::span<Value> operands(values.data() + first, n);
                bool ok = true;
                switch (in.op) {
                    case Op::Unary:
                        ok = evaluator.unary(in.operation, out, in.loc);
                        break;
                    case Op::Binary:
                        ok = evaluator.binary(in.operation, in.text, out, values[first + 1], in.loc);
                        break;
                    case Op::Construct:
                        ok = evaluator.construct(in.type, operands, out, in.loc);
                        break;
                    case Op::Intrinsic:
                        ok = evaluator.intrinsic(in.function, in.text, operands, in.loc);
                        break;
                    case Op::InitList:
                        ok = evaluator.initList(operands, out, in.loc);
                        break;
                    case Op::Member:
                        ok = evaluator.member(in.member, in.text, out, in.loc);
                        break;
                    case Op::Index:
                        ok = evaluator.index(out, values[first + 1], in.loc);
                        break;
                    case Op::Convert:
                        ok = evaluator.convert(out, in.type, in.loc);
                        break;
                    default:
                        break;
                }
                if (!ok) {
                    errors.push_back(evaluator.error());
                    entryErrors[first] = static_cast<int>(errors.size() - 1);
                }
            }
        }
    }
    if (depth != 1) return nullptr;  // an empty program
    if (entryErrors[0] >= 0) {
        if (diagnostics) {
            const Error& error = errors[static_cast<size_t>(entryErrors[0])];
            diagnostics->report(error.id, error.loc, error.args);
        }
        return nullptr;
    }
    return &values[0];
}

std::optional<Value> PreshaderProgram::run(const std::vector<Value>& slots,
                                           DiagnosticSink* diagnostics) const {
    Registers registers;
    const Value* value = run(slots, registers, diagnostics);
    return value ? std::optional<Value>(*value) : std::nullopt;
}

}  // namespace fx
