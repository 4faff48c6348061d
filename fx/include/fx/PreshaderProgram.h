// PreshaderProgram: an effect expression compiled for the host, the way D3DX compiles the expressions of
// render states and shader arguments into preshaders. Parameters are slots (their indices in the effect),
// operators and intrinsics are opcodes and constructor types parsed at compile time; running a program
// walks a flat instruction list over the slots' current values, with no parameter names and no syntax
// tree, on registers the caller keeps (Registers), so that a program run again allocates nothing.
//
// Compiled from an Expr by fx/Preshader.h (compilePreshader); run by the runtime before a draw when one of
// its input slots changed (inputs()).
#pragma once

#include <fx/Diagnostics.h>
#include <fx/Types.h>
#include <fx/Value.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace fx {

namespace detail {
struct PreshaderProgramFields;  // fx/src/CompiledEffectFields.h: the program in a compiled effect file
}

class PreshaderProgram {
public:
    struct Instruction {
        enum class Op : uint8_t {
            Constant,   // push constants[operand]
            Load,       // push slots[operand]
            Fail,       // push an error (errors[operand]): an unknown name, a non-value
            Unary,      // pop 1; `operation` is the operator ("-", "!", "~", "+")
            Binary,     // pop 2; `operation` is the operator
            Select,     // pop 3: condition, then, else (HLSL evaluates both; a scalar condition picks one)
            Construct,  // pop `count`: a `type` from their components (float4(...))
            Intrinsic,  // pop `count`: the intrinsic `function` (mul, normalize, ...), spelled `text`
            InitList,   // pop `count`: { ... }
            Member,     // pop 1: swizzle or matrix member `text` (`member`)
            Index,      // pop 2: base[index]
            Convert,    // pop 1: to `type` (casts, the program's target type)
        };
        // Unary and Binary: the operator, resolved from its spelling when the program is compiled, so that
        // running it compares no strings. Unknown: a spelling the host cannot evaluate (binary: an error
        // at run time, naming `text`; unary: the value unchanged).
        enum class Operator : uint8_t {
            Add,
            Subtract,
            Multiply,
            Divide,
            Modulo,
            Less,
            Greater,
            LessEqual,
            GreaterEqual,
            Equal,
            NotEqual,
            LogicalAnd,
            LogicalOr,
            BitAnd,
            BitOr,
            BitXor,
            ShiftLeft,
            ShiftRight,
            Negate,      // unary -
            Not,         // unary !
            Complement,  // unary ~
            Unknown,
        };
        // Intrinsic: the HLSL intrinsic, resolved from its name when the program is compiled. Unknown: one
        // the host cannot evaluate (an error at run time, naming `text`).
        enum class Function : uint8_t {
            Abs,
            Sqrt,
            Rsqrt,
            Exp,
            Exp2,
            Log,
            Log2,
            Log10,
            Sin,
            Cos,
            Tan,
            Asin,
            Acos,
            Atan,
            Radians,
            Degrees,
            Floor,
            Ceil,
            Round,
            Trunc,
            Frac,
            Saturate,
            Sign,
            Min,
            Max,
            Pow,
            Atan2,
            Fmod,
            Step,
            Clamp,
            Lerp,
            Smoothstep,
            Dot,
            Length,
            Normalize,
            Distance,
            Cross,
            Transpose,
            Determinant,
            Inverse,
            Mul,
            Unknown,
        };
        // Member: `text` read when the program is compiled, both ways the base's type (known when the
        // program runs) may take it, so that running it reads no letters. As a swizzle of a scalar or
        // vector (`.xy`, `.rgba`): each letter's component (kNoComponent: a letter naming none);
        // swizzleCount 0 where the text is no swizzle's length (1 to 4). As a matrix member (`._m00_m11`,
        // `._11`): each zero-based row and column (kNoComponent: a one-based 0); matrixCount 0 where the
        // text is not one of at most 4.
        static constexpr uint8_t kNoComponent = 0xff;
        struct MemberComponents {
            uint8_t swizzleCount = 0;
            uint8_t swizzle[4] = {0, 0, 0, 0};
            uint8_t matrixCount = 0;
            uint8_t rows[4] = {0, 0, 0, 0};
            uint8_t columns[4] = {0, 0, 0, 0};
        };
        Op op = Op::Constant;
        Operator operation = Operator::Unknown;  // Unary, Binary
        Function function = Function::Unknown;   // Intrinsic
        uint32_t operand = 0;                    // Constant, Load, Fail
        uint32_t count = 0;                      // Construct, Intrinsic, InitList
        std::string text;         // operator or intrinsic (for messages), member; never a parameter's name
        TypeDesc type;            // Construct, Convert
        MemberComponents member;  // Member
        SourceLoc loc;            // for the error it may report
    };
    struct Error {
        DiagId id;
        SourceLoc loc;
        std::vector<std::string> args;  // the id's template's {0}, {1}, ...
    };

    // The stack a program runs on, one value per depth, kept by the caller between runs. Its values keep
    // their storage, so once they have held a program's values, running that program again allocates
    // nothing (save the message of an error). One Registers serves any number of programs, one run at a
    // time.
    class Registers {
    private:
        friend class PreshaderProgram;
        std::vector<Value> mValues;
        std::vector<int> mEntryErrors;  // per depth: the index in mErrors of the error in its place, or -1
        std::vector<Error> mErrors;     // this run's
        std::vector<float> mScratch;    // an operation's result while its operands are still read
    };

    // The value over `slots` (every parameter's current value, by index), converted to the program's
    // target type if it has one, held by `registers` until their next run. nullptr, with the error
    // reported to `diagnostics` (if given), when it fails; an error in the branch a scalar condition does
    // not take is not one.
    const Value* run(const std::vector<Value>& slots, Registers& registers,
                     DiagnosticSink* diagnostics) const;
    // The same on registers of its own: for a program run once.
    std::optional<Value> run(const std::vector<Value>& slots, DiagnosticSink* diagnostics) const;

    // The slots the program reads, ascending and unique: it must be run again only when one changed.
    const std::vector<size_t>& inputs() const { return mInputs; }
    // True if the program is one constant (folded at compile time).
    bool isConstant() const { return mCode.size() == 1 && mCode[0].op == Instruction::Op::Constant; }
    // The folded constant (isConstant()).
    const Value& constant() const { return mConstants.front(); }
    bool empty() const { return mCode.empty(); }
    // Whether running the program over `slotCount` slots stays within its constants, errors, slots and
    // stack (what a program read from a file must show before it runs); none if so, else the diagnostic
    // that says what is wrong (its argument: the pass that holds the program).
    std::optional<DiagId> malformation(size_t slotCount) const;

private:
    friend class PreshaderCompiler;  // fx/src/Preshader.cpp
    friend struct detail::PreshaderProgramFields;

    std::vector<Instruction> mCode;  // postfix: operands before the instruction that uses them
    std::vector<Value> mConstants;
    std::vector<Error> mErrors;
    std::vector<size_t> mInputs;
};

}  // namespace fx
