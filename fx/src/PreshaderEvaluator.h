// PreshaderEvaluator: the operations a preshader program runs, on values (HLSL semantics: scalar
// broadcast, component-wise operators, intrinsics, constructors, swizzles), and the type helpers they
// share. Defined in Preshader.cpp (conversion, operators, members) and PreshaderIntrinsics.cpp (intrinsics
// and constructors). Private to fx.
#pragma once

#include <fx/PreshaderProgram.h>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fx::detail {

using Operator = PreshaderProgram::Instruction::Operator;
// An operator's spelling resolved once, when a program is compiled.
Operator operatorOf(std::string_view spelling, bool unary);
bool isNumericBase(BaseType b);
size_t elementCount(const TypeDesc& t);
size_t componentCount(const TypeDesc& t);
int baseRank(BaseType b);
TypeDesc makeType(BaseType base, Shape shape, int rows, int cols);
TypeDesc vectorType(BaseType base, int n);
Value makeValue(const TypeDesc& type, std::vector<float> data);
// HLSL's value for an integer that does not fit 32 bits (the D3DCOLOR idiom `int c = 0xff202080;`, a
// `0xFFFFFFFF` mask): the low 32 bits, as two's complement. A plain cast of such a double is undefined.
int32_t wrapToInt32(double x);
// Stores a component in the representation of its base type: bools 0/1, ints truncated.
float normalizeComponent(BaseType base, float x);
// Parses a type constructor name: "float4" -> (Float, 1, 4, Vector), "float4x3", "int", "bool2".
std::optional<TypeDesc> parseTypeName(std::string_view name);

// The operations of a program, on values. An operation that fails records why (error()) and returns
// nullopt; the program decides whether the failure reaches its result.
class Evaluator {
public:
    std::optional<Value> convert(const Value& v, const TypeDesc& target, const SourceLoc& loc);
    std::optional<Value> unary(Operator op, Value a, const SourceLoc& loc);
    // `spelling`: the operator as written, for the message when the host cannot evaluate it.
    std::optional<Value> binary(Operator op, const std::string& spelling, Value a, Value b,
                                const SourceLoc& loc);
    std::optional<Value> select(const Value& c, Value a, Value b, const SourceLoc& loc);
    std::optional<Value> construct(const TypeDesc& type, const std::vector<Value>& args,
                                   const SourceLoc& loc);
    std::optional<Value> intrinsic(const std::string& name, std::vector<Value>& args, const SourceLoc& loc);
    std::optional<Value> initList(const std::vector<Value>& args, const SourceLoc& loc);
    std::optional<Value> member(const std::string& m, const Value& base, const SourceLoc& loc);
    std::optional<Value> index(const Value& base, const Value& idx, const SourceLoc& loc);

    const PreshaderProgram::Error& error() const { return mError; }

private:
    std::nullopt_t fail(DiagId id, const SourceLoc& loc, std::vector<std::string> args = {}) {
        mError = {id, loc, std::move(args)};
        return std::nullopt;
    }

    // Brings two operands to a common shape (scalar broadcast, or truncation to the smaller vector).
    bool broadcast(Value& a, Value& b, const SourceLoc& loc);

    PreshaderProgram::Error mError{DiagId::CannotEvaluateType, {}, {}};
};

}  // namespace fx::detail
