// PreshaderCompiler: compiles effect expressions (Expr, fx/Effect.h) into PreshaderPrograms, and
// evaluates an expression once through a one-off program. The compiler side of fx/Preshader.h; the
// programs run in Preshader.cpp.
#include <fx/Preshader.h>

#include "PreshaderEvaluator.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>

namespace fx {

using detail::functionOf;
using detail::operatorOf;
using detail::parseTypeName;
using detail::wrapToInt32;

// [SECTION] Compiling an expression

class PreshaderCompiler {
public:
    PreshaderCompiler(const SlotResolver& slotOf, PreshaderProgram& program)
        : mSlotOf(slotOf), mProgram(program) {}

    void compile(const Expr& e) {
        using Op = PreshaderProgram::Instruction::Op;
        switch (e.kind) {
            case Expr::Kind::Number:
                constant(e.isInteger ? Value::integer(wrapToInt32(e.number))
                                     : Value::scalar(static_cast<float>(e.number)));
                return;
            case Expr::Kind::Bool:
                constant(Value::boolean(e.number != 0.0));
                return;
            case Expr::Kind::String:
                constant(Value::text(e.text));
                return;
            case Expr::Kind::Identifier: {
                if (e.text == "true" || e.text == "false") {
                    constant(Value::boolean(e.text == "true"));
                    return;
                }
                const std::optional<size_t> slot = mSlotOf ? mSlotOf(e.text) : std::nullopt;
                if (!slot) {
                    fail(DiagId::UnknownIdentifier, e.loc, {e.text});
                    return;
                }
                emit(Op::Load, e.loc).operand = static_cast<uint32_t>(*slot);
                mProgram.mInputs.push_back(*slot);
                return;
            }
            case Expr::Kind::Unary:
                compile(e.args[0]);
                emitOperator(Op::Unary, e);
                return;
            case Expr::Kind::Binary:
                compile(e.args[0]);
                compile(e.args[1]);
                emitOperator(Op::Binary, e);
                return;
            case Expr::Kind::Ternary:
                for (const Expr& a : e.args) compile(a);
                emit(Op::Select, e.loc);
                return;
            case Expr::Kind::Call: {
                for (const Expr& a : e.args) compile(a);
                const std::optional<TypeDesc> type = parseTypeName(e.text);
                auto& in = emit(type ? Op::Construct : Op::Intrinsic, e.loc);
                in.count = static_cast<uint32_t>(e.args.size());
                if (type) {
                    in.type = *type;
                } else {
                    in.function = functionOf(e.text);
                    in.text = e.text;
                }
                return;
            }
            case Expr::Kind::Member: {
                compile(e.args[0]);
                auto& member = emit(Op::Member, e.loc);
                member.text = e.text;
                member.member = detail::memberComponents(e.text);
                return;
            }
            case Expr::Kind::Index:
                compile(e.args[0]);
                compile(e.args[1]);
                emit(Op::Index, e.loc);
                return;
            case Expr::Kind::InitList:
                for (const Expr& a : e.args) compile(a);
                emit(Op::InitList, e.loc).count = static_cast<uint32_t>(e.args.size());
                return;
            case Expr::Kind::Cast:
                compile(e.args[0]);
                emit(Op::Convert, e.loc).type = e.castType;
                return;
            case Expr::Kind::TextureRef:
            case Expr::Kind::Compile:
                fail(DiagId::NotAValue, e.loc, {e.str()});
                return;
        }
    }

    void convertTo(const TypeDesc& type, const SourceLoc& loc) {
        emit(PreshaderProgram::Instruction::Op::Convert, loc).type = type;
    }

    // A program that reads no slot is run now and replaced by its value (or kept, to fail at run time as the
    // expression would). Inputs end sorted and unique.
    void finish() {
        std::vector<size_t>& inputs = mProgram.mInputs;
        std::sort(inputs.begin(), inputs.end());
        inputs.erase(std::unique(inputs.begin(), inputs.end()), inputs.end());
        if (!inputs.empty() || mProgram.isConstant()) return;
        std::optional<Value> value = mProgram.run({}, nullptr);
        if (!value) return;
        mProgram.mCode.clear();
        mProgram.mConstants.clear();
        mProgram.mErrors.clear();
        constant(std::move(*value));
    }

private:
    void emitOperator(PreshaderProgram::Instruction::Op op, const Expr& e) {
        PreshaderProgram::Instruction& in = emit(op, e.loc);
        in.operation = operatorOf(e.text, op == PreshaderProgram::Instruction::Op::Unary);
        in.text = e.text;
    }
    PreshaderProgram::Instruction& emit(PreshaderProgram::Instruction::Op op, const SourceLoc& loc) {
        PreshaderProgram::Instruction& in = mProgram.mCode.emplace_back();
        in.op = op;
        in.loc = loc;
        return in;
    }
    void constant(Value value) {
        emit(PreshaderProgram::Instruction::Op::Constant, {}).operand =
            static_cast<uint32_t>(mProgram.mConstants.size());
        mProgram.mConstants.push_back(std::move(value));
    }
    void fail(DiagId id, const SourceLoc& loc, std::vector<std::string> args) {
        emit(PreshaderProgram::Instruction::Op::Fail, loc).operand =
            static_cast<uint32_t>(mProgram.mErrors.size());
        mProgram.mErrors.push_back({id, loc, std::move(args)});
    }

    const SlotResolver& mSlotOf;
    PreshaderProgram& mProgram;
};

PreshaderProgram compilePreshader(const Expr& expr, const SlotResolver& slotOf, const TypeDesc* targetType) {
    PreshaderProgram program;
    PreshaderCompiler compiler(slotOf, program);
    compiler.compile(expr);
    if (targetType) compiler.convertTo(*targetType, expr.loc);
    compiler.finish();
    return program;
}

std::optional<Value> evaluate(const Expr& expr, const ParameterLookup& lookup, const TypeDesc* targetType,
                              DiagnosticSink* diagnostics) {
    // The names the expression reads become slots of a one-off program.
    std::vector<Value> slots;
    std::vector<std::string> names;
    const SlotResolver slotOf = [&](std::string_view name) -> std::optional<size_t> {
        for (size_t i = 0; i < names.size(); ++i)
            if (names[i] == name) return i;
        const Value* value = lookup ? lookup(name) : nullptr;
        if (!value) return std::nullopt;
        names.emplace_back(name);
        slots.push_back(*value);
        return slots.size() - 1;
    };
    return compilePreshader(expr, slotOf, targetType).run(slots, diagnostics);
}

}  // namespace fx
