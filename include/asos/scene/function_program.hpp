#pragma once
// A user-defined function (POV-Ray's `function { … }`), compiled once by the
// interpreter (lang/functions.cpp) to a compact stack program and run for
// each evaluation: a float pattern evaluates one per sample, so no syntax
// tree is walked there. Plain data plus its evaluation; the text form, for
// the dump, is in function_text.hpp.
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace asos {

struct FunctionProgram {
    enum class Op : std::uint8_t {
        Const,  // push k
        Load,   // push local a (parameters first)
        // one operand
        Neg, Not, Abs, Sqrt, Sin, Cos, Tan, Asin, Acos, Atan, Sinh, Cosh, Tanh, Asinh, Acosh, Atanh,
        Floor, Ceil, Int, Sqr, Radians, Degrees, Exp, Log, Ln,
        // two operands
        Add, Sub, Mul, Div, Less, LessEqual, Equal, NotEqual, GreaterEqual, Greater, And, Or, Min, Max, Pow,
        Atan2, Mod, IntDiv,
        // three and four operands
        Choose,   // c ? a : b
        Select3,  // select(c, negative, otherwise)
        Select4,  // select(c, negative, zero, positive)
        Call,     // callees[a], its parameters popped, its value pushed
        // sum(i, from, to, expr) and prod(…): LoopStart pops from and to,
        // sets local a (the variable) and a + 1 (the end), pushes 0 (sum) or
        // 1 (prod, k = 1), and jumps to b (past the LoopEnd) when from > to;
        // LoopEnd folds the body's value in, steps local a, and jumps back to
        // b (the body's start) while it is <= the end.
        LoopStart,
        LoopEnd,
    };
    struct Instr {
        Op op = Op::Const;
        std::uint16_t a = 0;
        std::uint32_t b = 0;
        double k = 0.0;
    };

    // The most values pending and locals one evaluation may use (the
    // compiler refuses more).
    static constexpr std::size_t kMaxStack = 128;
    static constexpr std::size_t kMaxLocals = 64;
    static constexpr std::size_t kMaxCallDepth = 64;

    std::vector<Instr> code;
    std::vector<std::shared_ptr<const FunctionProgram>> callees;
    std::vector<std::string> parameterNames;  // as written (x, y, z by default)
    std::uint32_t locals = 0;                 // parameters, then two per sum/prod
    std::uint32_t callDepth = 1;              // this one and its deepest chain of callees

    std::size_t parameters() const { return parameterNames.size(); }
    // The value for these arguments (as many as parameters()). Not checked:
    // NaN and infinities come out as the arithmetic gives them.
    double evaluate(std::span<const double> arguments) const;
};

}  // namespace asos
