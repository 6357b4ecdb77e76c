#include "asos/scene/function_program.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace asos {

double FunctionProgram::evaluate(std::span<const double> arguments) const {
    std::array<double, kMaxStack> stack;
    std::array<double, kMaxLocals> local;
    std::copy(arguments.begin(), arguments.end(), local.begin());
    std::size_t top = 0;  // values on the stack
    const Instr* const begin = code.data();
    const Instr* const end = begin + code.size();
    auto unary = [&](double r) { stack[top - 1] = r; };
    auto binary = [&](double r) {
        --top;
        stack[top - 1] = r;
    };
    for (const Instr* i = begin; i != end; ++i) {
        const double a = top >= 1 ? stack[top - 1] : 0.0;  // the top operand
        const double b = top >= 2 ? stack[top - 2] : 0.0;  // the one under it
        switch (i->op) {
        case Op::Const: stack[top++] = i->k; break;
        case Op::Load: stack[top++] = local[i->a]; break;
        case Op::Neg: unary(-a); break;
        case Op::Not: unary(a == 0.0 ? 1.0 : 0.0); break;
        case Op::Abs: unary(std::fabs(a)); break;
        case Op::Sqrt: unary(std::sqrt(a)); break;
        case Op::Sin: unary(std::sin(a)); break;
        case Op::Cos: unary(std::cos(a)); break;
        case Op::Tan: unary(std::tan(a)); break;
        case Op::Asin: unary(std::asin(a)); break;
        case Op::Acos: unary(std::acos(a)); break;
        case Op::Atan: unary(std::atan(a)); break;
        case Op::Sinh: unary(std::sinh(a)); break;
        case Op::Cosh: unary(std::cosh(a)); break;
        case Op::Tanh: unary(std::tanh(a)); break;
        case Op::Asinh: unary(std::asinh(a)); break;
        case Op::Acosh: unary(std::acosh(a)); break;
        case Op::Atanh: unary(std::atanh(a)); break;
        case Op::Floor: unary(std::floor(a)); break;
        case Op::Ceil: unary(std::ceil(a)); break;
        case Op::Int: unary(std::trunc(a)); break;
        case Op::Sqr: unary(a * a); break;
        case Op::Radians: unary(a * std::numbers::pi / 180.0); break;
        case Op::Degrees: unary(a * 180.0 / std::numbers::pi); break;
        case Op::Exp: unary(std::exp(a)); break;
        case Op::Log: unary(std::log10(a)); break;
        case Op::Ln: unary(std::log(a)); break;
        // b is the left operand, a the right.
        case Op::Add: binary(b + a); break;
        case Op::Sub: binary(b - a); break;
        case Op::Mul: binary(b * a); break;
        case Op::Div: binary(b / a); break;
        case Op::Less: binary(b < a ? 1.0 : 0.0); break;
        case Op::LessEqual: binary(b <= a ? 1.0 : 0.0); break;
        case Op::Equal: binary(b == a ? 1.0 : 0.0); break;
        case Op::NotEqual: binary(b != a ? 1.0 : 0.0); break;
        case Op::GreaterEqual: binary(b >= a ? 1.0 : 0.0); break;
        case Op::Greater: binary(b > a ? 1.0 : 0.0); break;
        case Op::And: binary(b != 0.0 && a != 0.0 ? 1.0 : 0.0); break;
        case Op::Or: binary(b != 0.0 || a != 0.0 ? 1.0 : 0.0); break;
        case Op::Min: binary(std::min(b, a)); break;
        case Op::Max: binary(std::max(b, a)); break;
        case Op::Pow: binary(std::pow(b, a)); break;
        case Op::Atan2: binary(std::atan2(b, a)); break;
        case Op::Mod: binary(std::fmod(b, a)); break;
        case Op::IntDiv: binary(std::trunc(b / a)); break;
        case Op::Choose: {
            const double c = stack[top - 3];
            top -= 2;
            stack[top - 1] = c != 0.0 ? b : a;
            break;
        }
        case Op::Select3: {
            const double c = stack[top - 3];
            top -= 2;
            stack[top - 1] = c < 0.0 ? b : a;
            break;
        }
        case Op::Select4: {
            const double c = stack[top - 4];
            const double negative = stack[top - 3];
            top -= 3;
            stack[top - 1] = c < 0.0 ? negative : c == 0.0 ? b : a;
            break;
        }
        case Op::Call: {
            const FunctionProgram& callee = *callees[i->a];
            const std::size_t n = callee.parameters();
            top -= n;
            const double value = callee.evaluate(std::span<const double>(stack.data() + top, n));
            stack[top++] = value;
            break;
        }
        case Op::LoopStart: {
            local[i->a] = b;      // from
            local[i->a + 1] = a;  // to
            top -= 2;
            stack[top++] = i->k;  // 0: a sum, 1: a product
            if (b > a) i = begin + i->b - 1;
            break;
        }
        case Op::LoopEnd: {
            --top;
            stack[top - 1] = i->k != 0.0 ? b * a : b + a;
            local[i->a] += 1.0;
            if (local[i->a] <= local[i->a + 1]) i = begin + i->b - 1;
            break;
        }
        }
    }
    return top > 0 ? stack[top - 1] : 0.0;
}

}  // namespace asos
