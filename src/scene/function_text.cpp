#include "asos/scene/function_text.hpp"

#include <charconv>
#include <vector>

namespace asos {

namespace {

std::string numberText(double v) {
    if (v == 0.0) return "0";
    char buffer[64];
    const auto r = std::to_chars(buffer, buffer + sizeof buffer, v);
    std::string s(buffer, r.ptr);
    return v < 0.0 ? "(" + s + ")" : s;
}

const char* nameOf(FunctionProgram::Op op) {
    using Op = FunctionProgram::Op;
    switch (op) {
    case Op::Abs: return "abs";
    case Op::Sqrt: return "sqrt";
    case Op::Sin: return "sin";
    case Op::Cos: return "cos";
    case Op::Tan: return "tan";
    case Op::Asin: return "asin";
    case Op::Acos: return "acos";
    case Op::Atan: return "atan";
    case Op::Sinh: return "sinh";
    case Op::Cosh: return "cosh";
    case Op::Tanh: return "tanh";
    case Op::Asinh: return "asinh";
    case Op::Acosh: return "acosh";
    case Op::Atanh: return "atanh";
    case Op::Floor: return "floor";
    case Op::Ceil: return "ceil";
    case Op::Int: return "int";
    case Op::Sqr: return "sqr";
    case Op::Radians: return "radians";
    case Op::Degrees: return "degrees";
    case Op::Exp: return "exp";
    case Op::Log: return "log";
    case Op::Ln: return "ln";
    case Op::Min: return "min";
    case Op::Max: return "max";
    case Op::Pow: return "pow";
    case Op::Atan2: return "atan2";
    case Op::Mod: return "mod";
    case Op::IntDiv: return "div";
    case Op::Add: return "+";
    case Op::Sub: return "-";
    case Op::Mul: return "*";
    case Op::Div: return "/";
    case Op::Less: return "<";
    case Op::LessEqual: return "<=";
    case Op::Equal: return "=";
    case Op::NotEqual: return "!=";
    case Op::GreaterEqual: return ">=";
    case Op::Greater: return ">";
    case Op::And: return "&";
    case Op::Or: return "|";
    default: return "";
    }
}

// `loops`: loop variables named so far (each gets its own name, callees' too).
std::string write(const FunctionProgram& f, std::span<const std::string> arguments, int& loops) {
    using Op = FunctionProgram::Op;
    std::vector<std::string> stack;
    std::vector<std::string> localNames(arguments.begin(), arguments.end());
    localNames.resize(f.locals);
    auto pop = [&] {
        std::string s = std::move(stack.back());
        stack.pop_back();
        return s;
    };
    for (const FunctionProgram::Instr& i : f.code) {
        switch (i.op) {
        case Op::Const: stack.push_back(numberText(i.k)); break;
        case Op::Load: stack.push_back(localNames[i.a]); break;
        case Op::Neg: stack.push_back("(-" + pop() + ")"); break;
        case Op::Not: stack.push_back("(!" + pop() + ")"); break;
        case Op::Add: case Op::Sub: case Op::Mul: case Op::Div: case Op::Less: case Op::LessEqual:
        case Op::Equal: case Op::NotEqual: case Op::GreaterEqual: case Op::Greater: case Op::And: case Op::Or: {
            const std::string right = pop();
            const std::string left = pop();
            stack.push_back("(" + left + " " + nameOf(i.op) + " " + right + ")");
            break;
        }
        case Op::Min: case Op::Max: case Op::Pow: case Op::Atan2: case Op::Mod: case Op::IntDiv: {
            const std::string right = pop();
            const std::string left = pop();
            stack.push_back(std::string(nameOf(i.op)) + "(" + left + ", " + right + ")");
            break;
        }
        case Op::Choose: {
            const std::string no = pop();
            const std::string yes = pop();
            const std::string c = pop();
            stack.push_back("(" + c + " ? " + yes + " : " + no + ")");
            break;
        }
        case Op::Select3: case Op::Select4: {
            std::string args = pop();
            const int more = i.op == Op::Select3 ? 2 : 3;
            for (int k = 0; k < more; ++k) args = pop() + ", " + args;
            stack.push_back("select(" + args + ")");
            break;
        }
        case Op::Call: {
            const FunctionProgram& callee = *f.callees[i.a];
            std::vector<std::string> args(callee.parameters());
            for (std::size_t k = args.size(); k-- > 0;) args[k] = pop();
            stack.push_back(write(callee, args, loops));  // an operation's text is in parentheses already
            break;
        }
        case Op::LoopStart: {
            const std::string to = pop();
            const std::string from = pop();
            localNames[i.a] = "asos_loop_" + std::to_string(loops++);
            stack.push_back((i.k != 0.0 ? "prod(" : "sum(") + localNames[i.a] + ", " + from + ", " + to);
            break;
        }
        case Op::LoopEnd: {
            const std::string body = pop();
            const std::string head = pop();
            stack.push_back(head + ", " + body + ")");
            break;
        }
        default: {
            const std::string a = pop();
            stack.push_back(std::string(nameOf(i.op)) + "(" + a + ")");
        }
        }
    }
    return stack.empty() ? "0" : stack.back();
}

}  // namespace

std::string functionText(const FunctionProgram& f, std::span<const std::string> arguments) {
    int loops = 0;
    return write(f, arguments, loops);
}

}  // namespace asos
