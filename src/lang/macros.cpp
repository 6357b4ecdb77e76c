// Macros, as POV-Ray 3.7 runs them. A macro's body is text (of the file that
// defines it) read where the macro is called: as entries of the block the
// call stands in, or as a value. Each such reading is parsed once, on the
// first call from that kind of place, and kept; a call copies neither text nor
// tree. A call evaluates its arguments in the caller's scopes, then runs the
// body in a scope of its own holding the parameters (and the body's #local
// names); a bare identifier as argument is passed by reference, so that
// `#declare P = …` in the body assigns to it. Scopes are dynamic: the body
// sees its caller's names. #break ends the macro.
#include "src/lang/interpreter_impl.hpp"

namespace asos::lang {

void Interpreter::defineMacro(const Node& n) {
    const Node& name = n[0];
    const auto parts = n.children();
    if (const Value* existing = lookup(name.id);
        existing && !std::holds_alternative<std::shared_ptr<const MacroDef>>(*existing))
        fail(name, "cannot define the macro '" + nameOf(name) + "': '" + nameOf(name) + "' is " +
                       describe(*existing));
    auto macro = std::make_shared<MacroDef>();
    macro->name = name.id;
    for (const Node& parameter : parts.subspan(1, parts.size() - 2)) {
        if (std::find(macro->parameters.begin(), macro->parameters.end(), parameter.id) != macro->parameters.end())
            fail(parameter, "the macro '" + nameOf(name) + "' has two parameters named '" + nameOf(parameter) + "'");
        macro->parameters.push_back(parameter.id);
    }
    const Node& body = parts.back();
    macro->file = file_;
    macro->body = TextSpan{body.id, body.count, body.line, body.column};
    // Macros are global, wherever they are defined (POV-Ray's).
    scopes_.front()[name.id] = Slot{std::shared_ptr<const MacroDef>(std::move(macro))};
}

const Ast& Interpreter::macroBody(const MacroDef& macro, BodyContext context) {
    auto& cached = macro.bodies[static_cast<std::size_t>(context)];
    if (!cached) {
        Diagnostics syntax;
        auto ast = parseMacroBody(macro.file->text, macro.body, macro.file->name, context, depth_, names_, syntax);
        if (!ast) {
            forwardSyntaxErrors(syntax);
            throw Stop{};  // as for an include: what follows cannot be trusted
        }
        cached = std::make_shared<const Ast>(std::move(*ast));
    }
    return *cached;
}

void Interpreter::invokeMacro(const Node& call, BodyContext context, EntryHandler handle) {
    const Node& name = call[0];
    const Value* found = lookup(name.id);
    if (!found) fail(name, "'" + nameOf(name) + "' is not declared");
    if (std::holds_alternative<std::shared_ptr<const FunctionValue>>(*found) && context == BodyContext::Value) {
        handle(call);  // a function's call standing as a macro's value
        return;
    }
    const auto* pointer = std::get_if<std::shared_ptr<const MacroDef>>(found);
    if (!pointer) fail(name, "'" + nameOf(name) + "' is " + describe(*found) + ", not a macro");
    const std::shared_ptr<const MacroDef> macro = *pointer;  // alive even if the body #undefs it
    const auto arguments = call.children().subspan(1);
    if (arguments.size() != macro->parameters.size())
        fail(call, "the macro '" + nameOf(name) + "' takes " + countOf(macro->parameters.size(), "argument") +
                       ", not " + std::to_string(arguments.size()));

    // The arguments, in the caller's scopes, before the macro's scope exists
    // (so that a recursive call sees the caller's parameters).
    Scope parameters;
    parameters.reserve(arguments.size());
    for (std::size_t i = 0; i < arguments.size(); ++i) {
        const Node& argument = arguments[i];
        Slot slot;
        if (argument.kind == NodeKind::Name) {
            std::size_t scope = 0;
            const Slot* target = findSlot(argument.id, &scope);
            if (!target) fail(argument, "'" + nameOf(argument) + "' is not declared: a macro's argument needs a value");
            if (target->refScope >= 0) {  // a parameter standing for an entry: pass that entry on
                slot.refScope = target->refScope;
                slot.refId = target->refId;
            } else {
                slot.refScope = static_cast<std::int32_t>(scope);
                slot.refId = argument.id;
            }
        } else {
            slot.value = evalDeclarable(argument);
        }
        parameters[macro->parameters[i]] = std::move(slot);
    }

    const Nested nested(*this, call);
    const Entered entered(*this, Frame{"in macro " + nameOf(name) + " called at", locOf(call), {}},
                          std::move(parameters));
    const Ast& body = macroBody(*macro, context);
    file_ = macro->file;
    ast_ = &body;
    runBody(body.root.children(), handle);  // a #break returns from the macro
}

// A macro called for its value: its body is one value (after any directives).
Value Interpreter::evalMacroValue(const Node& call) {
    if (const Value* callee = lookup(call[0].id))
        if (const auto* f = std::get_if<std::shared_ptr<const FunctionValue>>(callee)) return callFunction(call, **f);
    std::optional<Value> result;
    auto collect = [&](const Node& n) {
        if (result) fail(n, "the macro '" + nameOf(call[0]) + "' gives a second value here; one is wanted");
        result = evalDeclarable(n);
    };
    const std::size_t errorsBefore = errorCount_;
    invokeMacro(call, BodyContext::Value, EntryHandler(collect));
    if (!result && errorCount_ > errorsBefore) throw Abandon{};  // the body's error says why
    if (!result) fail(call, "the macro '" + nameOf(call[0]) + "' gives no value, and one is wanted here");
    return std::move(*result);
}

}  // namespace asos::lang
