// User-defined functions: `function(…) { … }` compiled once to a
// FunctionProgram (scene/function_program.hpp), their calls in expressions,
// and the function pattern's body. What a function may hold is POV-Ray 3.7's
// (its fnsyntax.cpp): floats only, its parameters (x, y, z by default, u and v
// standing for x and y), the arithmetic, comparison and logic operators, ?:,
// the float built-ins, select, min and max of any number of arguments,
// sum/prod over a range, other functions, and declared floats, taken by value
// when the function is declared. A part that depends on no parameter is
// computed then, once, as any expression.
#include <algorithm>

#include "interpreter_impl.hpp"

namespace asos::lang {

namespace {

using Op = FunctionProgram::Op;

// A refused function (internal(N), pigment { } …) met while compiling:
// the new function is refused too, for the same reason.
struct Refused {
    std::string message;
};

class FunctionCompiler {
public:
    struct Parameter {
        Word word = Word::None;  // x, y, z, u, v, t written as a parameter
        std::uint32_t name = 0;  // otherwise its name
    };

    FunctionCompiler(Interpreter& in, FunctionProgram& out, std::vector<Parameter> parameters, bool defaults,
                     std::uint32_t declaring)
        : in_(in), out_(out), parameters_(std::move(parameters)), defaults_(defaults), declaring_(declaring) {
        out_.locals = static_cast<std::uint32_t>(parameters_.size());
    }

    void compileBody(const Node& body, const Node& at) {
        allowed(body);
        compile(body);
        // The deepest stack the code reaches, its locals and its callees' depth.
        std::ptrdiff_t depth = 0, deepest = 0;
        for (const FunctionProgram::Instr& i : out_.code) {
            depth += effect(i);
            deepest = std::max(deepest, depth);
        }
        if (static_cast<std::size_t>(deepest) > FunctionProgram::kMaxStack ||
            out_.locals > FunctionProgram::kMaxLocals)
            in_.fail(at, "this function is too complex for asos (more than " +
                             std::to_string(FunctionProgram::kMaxStack) + " pending values or " +
                             std::to_string(FunctionProgram::kMaxLocals) + " parameters and sum/prod variables)");
        for (const auto& callee : out_.callees) out_.callDepth = std::max(out_.callDepth, callee->callDepth + 1);
        if (out_.callDepth > FunctionProgram::kMaxCallDepth)
            in_.fail(at, "functions calling functions more than " + std::to_string(FunctionProgram::kMaxCallDepth) +
                             " deep are not supported by asos");
    }

private:
    // What POV-Ray's function parser refuses, refused anywhere in the body.
    void allowed(const Node& n) const {
        auto refuse = [&](std::string_view what) {
            in_.fail(n, quote(what) + " is not allowed in a function, as in POV-Ray");
        };
        switch (n.kind) {
        case NodeKind::Conditional: refuse("?:"); break;
        case NodeKind::Unary:
            if (n.word == Word::OpNot) refuse("!");
            break;
        case NodeKind::Call:
            if (n.word == Word::Sqr) refuse("sqr");
            break;
        case NodeKind::Constant:
            switch (n.word) {
            case Word::True: case Word::False: case Word::Yes: case Word::No: case Word::On: case Word::Off:
                refuse(wordText(n.word));
            default: break;
            }
            break;
        default: break;
        }
        if (n.hasChildren())
            for (const Node& c : n.children()) allowed(c);
    }

    std::ptrdiff_t effect(const FunctionProgram::Instr& i) const {
        switch (i.op) {
        case Op::Const: case Op::Load: return 1;
        case Op::Add: case Op::Sub: case Op::Mul: case Op::Div: case Op::Less: case Op::LessEqual:
        case Op::Equal: case Op::NotEqual: case Op::GreaterEqual: case Op::Greater: case Op::And: case Op::Or:
        case Op::Min: case Op::Max: case Op::Pow: case Op::Atan2: case Op::Mod: case Op::IntDiv:
        case Op::LoopStart: case Op::LoopEnd:
            return -1;
        case Op::Choose: case Op::Select3: return -2;
        case Op::Select4: return -3;
        case Op::Call: return 1 - static_cast<std::ptrdiff_t>(out_.callees[i.a]->parameters());
        default: return 0;
        }
    }

    void emit(Op op, std::uint16_t a = 0, std::uint32_t b = 0, double k = 0.0) { out_.code.push_back({op, a, b, k}); }

    // The local a name or x, y, z … stands for, or -1.
    int localOf(const Node& n) const {
        if (n.kind == NodeKind::Name) {
            for (auto it = loops_.rbegin(); it != loops_.rend(); ++it)
                if (it->first == n.id) return it->second;
            for (std::size_t i = 0; i < parameters_.size(); ++i)
                if (parameters_[i].word == Word::None && parameters_[i].name == n.id) return static_cast<int>(i);
            return -1;
        }
        if (n.kind != NodeKind::Constant) return -1;
        if (defaults_) {
            switch (n.word) {
            case Word::X: case Word::U: return 0;
            case Word::Y: case Word::V: return 1;
            case Word::Z: return 2;
            default: return -1;
            }
        }
        for (std::size_t i = 0; i < parameters_.size(); ++i)
            if (parameters_[i].word == n.word) return static_cast<int>(i);
        return -1;
    }

    static bool isCoordinate(Word w) {
        return w == Word::X || w == Word::Y || w == Word::Z || w == Word::U || w == Word::V || w == Word::T;
    }

    // Whether the value of `n` depends on the function's parameters (or
    // needs the function machinery: sum, prod, other functions).
    bool depends(const Node& n) const {
        switch (n.kind) {
        case NodeKind::Name: return localOf(n) >= 0;
        case NodeKind::Constant: return localOf(n) >= 0 || isCoordinate(n.word);
        case NodeKind::Call:
            if (n.word == Word::Sum || n.word == Word::Prod) return true;
            break;
        case NodeKind::MacroCall: return true;
        default: break;
        }
        if (!n.hasChildren()) return false;
        for (const Node& c : n.children())
            if (depends(c)) return true;
        return false;
    }

    void compile(const Node& n) {
        if (!depends(n)) {
            constant(n);
            return;
        }
        switch (n.kind) {
        case NodeKind::Name: case NodeKind::Constant: {
            const int local = localOf(n);
            if (local < 0)
                in_.fail(n, quote(wordText(n.word)) + " is not a parameter of this function (its parameters are " +
                                parameterList() + ")");
            emit(Op::Load, static_cast<std::uint16_t>(local));
            return;
        }
        case NodeKind::Unary:
            compile(n[0]);
            if (n.word == Word::OpSub) emit(Op::Neg);
            if (n.word == Word::OpNot) emit(Op::Not);
            return;
        case NodeKind::Binary:
            compile(n[0]);
            compile(n[1]);
            emit(binaryOp(n.word));
            return;
        case NodeKind::Conditional:
            for (const Node& c : n.children()) compile(c);
            emit(Op::Choose);
            return;
        case NodeKind::Call: builtin(n); return;
        case NodeKind::MacroCall: userCall(n); return;
        case NodeKind::Member:
            // F(…).gray: a member of a vector function's value (pigment,
            // transform, spline), which asos refuses as those functions.
            if (n[0].kind == NodeKind::MacroCall)
                if (const Value* v = in_.lookup(n[0][0].id))
                    if (const auto* f = std::get_if<std::shared_ptr<const FunctionValue>>(v); f && !(*f)->program)
                        throw Refused{(*f)->refusal};
            in_.fail(n, quote(std::string(".") += wordText(n.word)) +
                            " needs a vector; a float function's value has no members");
        default:
            in_.fail(n, "a function holds floats only; this is not a float expression POV-Ray allows in a function");
        }
    }

    std::string parameterList() const {
        std::string s;
        for (const std::string& p : out_.parameterNames) s += (s.empty() ? "" : ", ") + p;
        return s;
    }

    void constant(const Node& n) {
        if (n.kind == NodeKind::Number) {
            emit(Op::Const, 0, 0, n.number);
            return;
        }
        const Value v = in_.eval(n);
        const auto* num = std::get_if<Num>(&v);
        if (!num || !num->isFloat())
            in_.fail(n, "a function holds floats only; this is " + describe(v));
        emit(Op::Const, 0, 0, num->v[0]);
    }

    static Op binaryOp(Word w) {
        switch (w) {
        case Word::OpAdd: return Op::Add;
        case Word::OpSub: return Op::Sub;
        case Word::OpMul: return Op::Mul;
        case Word::OpDiv: return Op::Div;
        case Word::OpLess: return Op::Less;
        case Word::OpLessEqual: return Op::LessEqual;
        case Word::OpEqual: return Op::Equal;
        case Word::OpNotEqual: return Op::NotEqual;
        case Word::OpGreaterEqual: return Op::GreaterEqual;
        case Word::OpGreater: return Op::Greater;
        case Word::OpAnd: return Op::And;
        default: return Op::Or;
        }
    }

    static bool unaryBuiltin(Word w, Op& op) {
        switch (w) {
        case Word::Abs: op = Op::Abs; break;
        case Word::Sqrt: op = Op::Sqrt; break;
        case Word::Sin: op = Op::Sin; break;
        case Word::Cos: op = Op::Cos; break;
        case Word::Tan: op = Op::Tan; break;
        case Word::Asin: op = Op::Asin; break;
        case Word::Acos: op = Op::Acos; break;
        case Word::Atan: op = Op::Atan; break;
        case Word::Sinh: op = Op::Sinh; break;
        case Word::Cosh: op = Op::Cosh; break;
        case Word::Tanh: op = Op::Tanh; break;
        case Word::Asinh: op = Op::Asinh; break;
        case Word::Acosh: op = Op::Acosh; break;
        case Word::Atanh: op = Op::Atanh; break;
        case Word::Floor: op = Op::Floor; break;
        case Word::Ceil: op = Op::Ceil; break;
        case Word::Int: op = Op::Int; break;
        case Word::Sqr: op = Op::Sqr; break;
        case Word::Radians: op = Op::Radians; break;
        case Word::Degrees: op = Op::Degrees; break;
        case Word::Exp: op = Op::Exp; break;
        case Word::Log: op = Op::Log; break;
        case Word::Ln: op = Op::Ln; break;
        default: return false;
        }
        return true;
    }

    void builtin(const Node& n) {
        Op op{};
        if (unaryBuiltin(n.word, op)) {
            compile(n[0]);
            emit(op);
            return;
        }
        switch (n.word) {
        case Word::Pow: case Word::Atan2: case Word::Mod: case Word::Div:
            compile(n[0]);
            compile(n[1]);
            emit(n.word == Word::Pow ? Op::Pow : n.word == Word::Atan2 ? Op::Atan2 : n.word == Word::Mod ? Op::Mod : Op::IntDiv);
            return;
        case Word::Min: case Word::Max:
            compile(n[0]);
            for (std::uint32_t i = 1; i < n.count; ++i) {
                compile(n[i]);
                emit(n.word == Word::Min ? Op::Min : Op::Max);
            }
            return;
        case Word::Select:
            for (const Node& c : n.children()) compile(c);
            emit(n.count == 3 ? Op::Select3 : Op::Select4);
            return;
        case Word::Sum: case Word::Prod: loop(n); return;
        default:
            in_.fail(n, quote(wordText(n.word)) +
                            " is not allowed in a function: POV-Ray's functions take and give floats only");
        }
    }

    // sum(i, from, to, expr) and prod(…): i runs from `from` to `to` by 1.
    void loop(const Node& n) {
        if (n[0].kind != NodeKind::Name)
            in_.fail(n[0], "expected the name of the " + std::string(wordText(n.word)) + "'s variable");
        compile(n[1]);
        compile(n[2]);
        const auto local = static_cast<std::uint16_t>(out_.locals);
        out_.locals += 2;
        const double product = n.word == Word::Prod ? 1.0 : 0.0;
        const std::size_t start = out_.code.size();
        emit(Op::LoopStart, local, 0, product);
        loops_.emplace_back(n[0].id, local);
        compile(n[3]);
        loops_.pop_back();
        emit(Op::LoopEnd, local, static_cast<std::uint32_t>(start + 1), product);
        out_.code[start].b = static_cast<std::uint32_t>(out_.code.size());
    }

    // F(…): another function, or a macro whose arguments need no parameter.
    void userCall(const Node& n) {
        const Node& name = n[0];
        const Value* value = in_.lookup(name.id);
        const auto* f = value ? std::get_if<std::shared_ptr<const FunctionValue>>(value) : nullptr;
        if (!f) {
            if (name.id == declaring_)
                in_.fail(name, "a function cannot call itself: '" + in_.nameOf(name) +
                                   "' is the function being declared (POV-Ray's functions are not recursive)");
            for (std::uint32_t i = 1; i < n.count; ++i)
                if (depends(n[i]))
                    in_.fail(n, "a macro called inside a function with the function's parameters is not supported by "
                                "asos; declare a function instead");
            constant(n);
            return;
        }
        const FunctionValue& callee = **f;
        if (!callee.program) throw Refused{callee.refusal};
        const std::size_t given = n.count - 1;
        if (given != callee.program->parameters())
            in_.fail(n, quote(in_.nameOf(name)) + " takes " + countOf(callee.program->parameters(), "argument") +
                            ", not " + std::to_string(given));
        for (std::uint32_t i = 1; i < n.count; ++i) compile(n[i]);
        std::size_t index = 0;
        while (index < out_.callees.size() && out_.callees[index] != callee.program) ++index;
        if (index == out_.callees.size()) out_.callees.push_back(callee.program);
        emit(Op::Call, static_cast<std::uint16_t>(index));
    }

    Interpreter& in_;
    FunctionProgram& out_;
    std::vector<Parameter> parameters_;
    bool defaults_;
    std::uint32_t declaring_;
    std::vector<std::pair<std::uint32_t, std::uint16_t>> loops_;  // sum/prod variables, innermost last
};

const char* blockFunctionWord(std::uint8_t flags) {
    switch (flags) {
    case 1: return "pigment";
    case 2: return "pattern";
    case 3: return "transform";
    default: return "spline";
    }
}

}  // namespace

Value Interpreter::makeFunction(const Node& fn) {
    const bool written = (fn.flags & 1) != 0;
    const Node& body = fn[fn.count - 1];
    const std::string where = formatLocation(locOf(fn));
    auto refused = [](std::string message) {
        return std::make_shared<const FunctionValue>(FunctionValue{nullptr, std::move(message)});
    };
    if (body.kind == NodeKind::Item && body.word == Word::Internal) {
        const double number = evalFloat(body[0]);
        return refused("'internal' is not supported by asos (the function { internal(" + formatNumber(number) +
                       ") } declared at " + where + ")");
    }
    if (body.kind == NodeKind::Item && body.word == Word::Function) {
        const std::string word = blockFunctionWord(body.flags);
        return refused("'" + word + "' in a function is not supported by asos (the function { " + word +
                       " { … } } declared at " + where + ")");
    }
    auto program = std::make_shared<FunctionProgram>();
    std::vector<FunctionCompiler::Parameter> parameters;
    if (written) {
        for (std::uint32_t i = 0; i + 1 < fn.count; ++i) {
            const Node& p = fn[i];
            FunctionCompiler::Parameter parameter;
            if (p.kind == NodeKind::Constant) {
                parameter.word = p.word;
                program->parameterNames.emplace_back(wordText(p.word));
            } else {
                parameter.name = p.id;
                program->parameterNames.push_back(nameOf(p));
            }
            for (std::size_t j = 0; j + 1 < program->parameterNames.size(); ++j)
                if (program->parameterNames[j] == program->parameterNames.back())
                    fail(p, "the parameter '" + program->parameterNames.back() + "' is named twice");
            parameters.push_back(parameter);
        }
    } else {
        program->parameterNames = {"x", "y", "z"};
        parameters = {{Word::X, 0}, {Word::Y, 0}, {Word::Z, 0}};
    }
    try {
        FunctionCompiler(*this, *program, std::move(parameters), !written, declaring_).compileBody(body, fn);
    } catch (const Refused& r) {
        return refused(r.message);
    }
    return std::make_shared<const FunctionValue>(FunctionValue{std::move(program), {}});
}

std::shared_ptr<const FunctionProgram> Interpreter::compileFunctionOfPoint(const Node& body) {
    auto program = std::make_shared<FunctionProgram>();
    program->parameterNames = {"x", "y", "z"};
    try {
        FunctionCompiler(*this, *program, {{Word::X, 0}, {Word::Y, 0}, {Word::Z, 0}}, true, kNoName)
            .compileBody(body, body);
    } catch (const Refused& r) {
        fail(body, r.message);
    }
    return program;
}

Num Interpreter::callFunction(const Node& call, const FunctionValue& f) {
    const std::string name = nameOf(call[0]);
    if (!f.program) fail(call, f.refusal + ", called here as '" + name + "'");
    const std::size_t given = call.count - 1;
    if (given != f.program->parameters())
        fail(call, quote(name) + " takes " + countOf(f.program->parameters(), "argument") + ", not " +
                       std::to_string(given));
    std::array<double, FunctionProgram::kMaxLocals> arguments{};
    for (std::size_t i = 0; i < given; ++i) arguments[i] = evalFloat(call[i + 1]);
    const double r = f.program->evaluate(std::span<const double>(arguments.data(), given));
    if (!std::isfinite(r))
        fail(call, quote(name) + ": the result is not a finite number (" + formatNumber(r) + ")");
    return Num::scalar(r);
}

}  // namespace asos::lang
