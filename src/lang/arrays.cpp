// Arrays, as POV-Ray 3.7's: `array[N][M]…` with up to 5 dimensions, an
// optional initialiser (one level of braces per dimension), elements read and
// assigned as A[i][j], all of one kind. A size or an index is the float plus
// POV-Ray's epsilon, truncated: A[1.9999999999999] is A[2].
#include <cmath>

#include "src/lang/interpreter_impl.hpp"

namespace asos::lang {

int kindOf(const Value& v) {
    if (const auto* n = std::get_if<Num>(&v)) return n->colour || n->dim == 5 ? 5 : n->dim;
    return 10 + static_cast<int>(v.index());
}

Value Interpreter::makeArray(const Node& n) {
    const std::size_t dimensions = n.flags;
    auto array = std::make_shared<ArrayValue>();
    std::size_t total = 1;
    for (std::size_t d = 0; d < dimensions; ++d) {
        const double v = evalFloat(n[d]) + kPovEpsilon;
        if (!(v >= 1.0) || v >= 4294967296.0)
            fail(n[d], "the size of an array must be a whole number, at least 1, not " + formatNumber(v - kPovEpsilon));
        const auto size = static_cast<std::uint32_t>(v);
        if (static_cast<double>(total) * size > static_cast<double>(options_.maxArrayElements))
            fail(n[d], "this array would hold more than " + std::to_string(options_.maxArrayElements) +
                           " elements, the limit (raise it with --max-array-elements)");
        total *= size;
        array->sizes.push_back(size);
    }
    checkMemory(n, total * sizeof(Value), "this array");
    array->elements.assign(total, Unset{});
    if (n.count > dimensions) fillArray(*array, n[dimensions], 0, 0);
    return array;
}

void Interpreter::fillArray(ArrayValue& array, const Node& initialiser, std::size_t dimension, std::size_t offset) {
    const auto elements = initialiser.children();
    const std::uint32_t size = array.sizes[dimension];
    if (elements.size() != size)
        fail(initialiser, "this initialiser has " + countOf(elements.size(), "element") + "; the array has " +
                              std::to_string(size) + " along its dimension " + std::to_string(dimension + 1));
    std::size_t stride = 1;
    for (std::size_t d = dimension + 1; d < array.sizes.size(); ++d) stride *= array.sizes[d];
    const bool last = dimension + 1 == array.sizes.size();
    for (std::size_t i = 0; i < size; ++i) {
        const Node& e = elements[i];
        const bool nested = e.kind == NodeKind::Initialiser;
        if (!last && !nested) fail(e, "expected '{' and the elements of the array's dimension " + std::to_string(dimension + 2));
        if (last && nested) fail(e, "the array has " + countOf(array.sizes.size(), "dimension") + ": expected an element, not '{'");
        if (nested)
            fillArray(array, e, dimension + 1, offset + i * stride);
        else
            storeElement(array, offset + i, evalDeclarable(e), e);
    }
}

void Interpreter::storeElement(ArrayValue& array, std::size_t offset, Value value, const Node& at) {
    const int kind = kindOf(value);
    if (array.kind >= 0 && kind != array.kind) {
        const auto held = std::find_if(array.elements.begin(), array.elements.end(),
                                       [&](const Value& e) { return !std::holds_alternative<Unset>(e); });
        fail(at, "an array holds one kind of value: this one holds " +
                     (held == array.elements.end() ? std::string("another kind") : describe(*held)) + ", not " +
                     describe(value));
    }
    array.kind = kind;
    array.elements[offset] = std::move(value);
}

Interpreter::ElementRef Interpreter::elementRef(const Node& index) {
    ElementRef ref;
    const Node* base = &index;
    while (base->kind == NodeKind::Index) {
        if (ref.count == ref.subscripts.size()) fail(index, "an array has at most 5 dimensions: too many subscripts");
        ref.subscripts[ref.count++] = &(*base)[1];
        base = &(*base)[0];
    }
    std::reverse(ref.subscripts.begin(), ref.subscripts.begin() + static_cast<std::ptrdiff_t>(ref.count));
    ref.name = base;
    for (std::size_t d = 0; d < ref.count; ++d) ref.values[d] = evalFloat(*ref.subscripts[d]);
    return ref;
}

std::size_t Interpreter::elementOffset(const ArrayValue& array, const ElementRef& ref, const Node& at) {
    if (ref.count != array.sizes.size())
        fail(at, "'" + nameOf(*ref.name) + "' has " + countOf(array.sizes.size(), "dimension") + ", not " +
                     std::to_string(ref.count));
    std::size_t offset = 0;
    for (std::size_t d = 0; d < ref.count; ++d) {
        const Node& subscript = *ref.subscripts[d];
        const double v = ref.values[d];
        if (!(v >= -kPovEpsilon) || !(v + kPovEpsilon < array.sizes[d]))
            fail(subscript, "the index " + formatNumber(v) + " is outside '" + nameOf(*ref.name) + "', which has " +
                                std::to_string(array.sizes[d]) + " elements along this dimension (0 to " +
                                std::to_string(array.sizes[d] - 1) + ")");
        offset = offset * array.sizes[d] + static_cast<std::size_t>(v + kPovEpsilon);
    }
    return offset;
}

Value Interpreter::arrayElement(const Node& index) {
    const ElementRef ref = elementRef(index);
    const Value base = eval(*ref.name);
    const auto* array = std::get_if<std::shared_ptr<ArrayValue>>(&base);
    if (!array) fail(*ref.name, "'" + nameOf(*ref.name) + "' is " + describe(base) + ", not an array");
    const Value& element = (*array)->elements[elementOffset(**array, ref, index)];
    if (std::holds_alternative<Unset>(element)) fail(index, "this element of '" + nameOf(*ref.name) + "' has no value yet");
    return element;
}

void Interpreter::assignElement(const Node& index, Value value) {
    const ElementRef ref = elementRef(index);
    const Node& name = *ref.name;
    std::size_t scope = 0;
    Slot* slot = const_cast<Slot*>(findSlot(name.id, &scope));
    if (slot) slot = resolve(*slot);
    if (!slot) fail(name, "'" + nameOf(name) + "' is not declared");
    auto* array = std::get_if<std::shared_ptr<ArrayValue>>(&slot->value);
    if (!array) fail(name, "'" + nameOf(name) + "' is " + describe(slot->value) + ", not an array");
    const std::size_t offset = elementOffset(**array, ref, index);
    if (array->use_count() > 1) *array = std::make_shared<ArrayValue>(**array);  // another name has it too
    storeElement(**array, offset, std::move(value), index);
}

bool Interpreter::isDefined(const Node& n) {
    if (n.kind == NodeKind::Name) return lookup(n.id) != nullptr;
    if (n.kind != NodeKind::Index) fail(n, "defined() takes an identifier or an array's element");
    const ElementRef ref = elementRef(n);
    const Value* base = lookup(ref.name->id);
    if (!base) return false;
    const auto* array = std::get_if<std::shared_ptr<ArrayValue>>(base);
    if (!array) fail(*ref.name, "'" + nameOf(*ref.name) + "' is " + describe(*base) + ", not an array");
    return !std::holds_alternative<Unset>((*array)->elements[elementOffset(**array, ref, n)]);
}

}  // namespace asos::lang
