// PreshaderEvaluator: the operations a preshader program runs, on values (HLSL semantics: scalar
// broadcast, component-wise operators, intrinsics, constructors, swizzles), and the type helpers they
// share. Defined in Preshader.cpp (conversion, operators, members) and PreshaderIntrinsics.cpp (intrinsics
// and constructors). Private to fx.
#pragma once

#include <fx/PreshaderProgram.h>

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace fx::detail {

using Operator = PreshaderProgram::Instruction::Operator;
using Function = PreshaderProgram::Instruction::Function;
// An operator's spelling resolved once, when a program is compiled.
Operator operatorOf(std::string_view spelling, bool unary);
// An intrinsic's name resolved once, when a program is compiled (Unknown: not one the host evaluates).
Function functionOf(std::string_view name);
bool isNumericBase(BaseType b);
size_t elementCount(const TypeDesc& t);
size_t componentCount(const TypeDesc& t);
int baseRank(BaseType b);
TypeDesc makeType(BaseType base, Shape shape, int rows, int cols);
TypeDesc vectorType(BaseType base, int n);
// Gives `t` the type (base, shape, rows, cols) and nothing else (no array, no names), keeping its storage.
void setType(TypeDesc& t, BaseType base, Shape shape, int rows, int cols);
void setVectorType(TypeDesc& t, BaseType base, int n);
// Makes `v` a scalar of `base` holding `x`, keeping its storage.
void setScalar(Value& v, BaseType base, float x);
// HLSL's value for an integer that does not fit 32 bits (the D3DCOLOR idiom `int c = 0xff202080;`, a
// `0xFFFFFFFF` mask): the low 32 bits, as two's complement. A plain cast of such a double is undefined.
int32_t wrapToInt32(double x);
// Stores a component in the representation of its base type: bools 0/1, ints truncated.
float normalizeComponent(BaseType base, float x);
// A member's text (`xy`, `_m00_11`) read as a swizzle and as a matrix member (Instruction::member).
PreshaderProgram::Instruction::MemberComponents memberComponents(std::string_view text);

// Parses a type constructor name: "float4" -> (Float, 1, 4, Vector), "float4x3", "int", "bool2".
std::optional<TypeDesc> parseTypeName(std::string_view name);

// The operations of a program, on the values of its registers. Each leaves its result in place of its
// first operand (`a`, `v`, `base`, operands[0]; a constructor or list of none, in `out`), reusing that
// value's storage; one that fails records why (error()) and returns false, and the program decides whether
// the failure reaches its result.
class Evaluator {
public:
    // `scratch`: storage an operation builds its result in while it still reads its operands.
    explicit Evaluator(std::vector<float>& scratch) : mScratch(scratch) {}

    bool convert(Value& v, const TypeDesc& target, const SourceLoc& loc);
    bool unary(Operator op, Value& a, const SourceLoc& loc);
    // `spelling`: the operator as written, for the message when the host cannot evaluate it.
    bool binary(Operator op, const std::string& spelling, Value& a, Value& b, const SourceLoc& loc);
    // `c` selects `a`'s component where non-zero, else `b`'s.
    bool select(const Value& c, Value& a, Value& b, const SourceLoc& loc);
    bool construct(const TypeDesc& type, std::span<Value> operands, Value& out, const SourceLoc& loc);
    // `name`: the intrinsic as written, for messages.
    bool intrinsic(Function function, const std::string& name, std::span<Value> operands,
                   const SourceLoc& loc);
    bool initList(std::span<Value> operands, Value& out, const SourceLoc& loc);
    // `components`: `text` as memberComponents read it; `text` for messages.
    bool member(const PreshaderProgram::Instruction::MemberComponents& components, const std::string& text,
                Value& base, const SourceLoc& loc);
    bool index(Value& base, const Value& idx, const SourceLoc& loc);

    const PreshaderProgram::Error& error() const { return mError; }

private:
    bool fail(DiagId id, const SourceLoc& loc, std::vector<std::string> args = {}) {
        mError = {id, loc, std::move(args)};
        return false;
    }

    // Brings two operands to a common shape (scalar broadcast, or truncation to the smaller vector).
    bool broadcast(Value& a, Value& b, const SourceLoc& loc);

    std::vector<float>& mScratch;
    PreshaderProgram::Error mError{DiagId::CannotEvaluateType, {}, {}};
};

}  // namespace fx::detail
