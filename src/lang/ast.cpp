#include "asos/lang/ast.hpp"

#include <algorithm>

namespace asos::lang {

std::uint32_t NameTable::intern(std::string_view name) {
    if (auto it = index_.find(name); it != index_.end()) return it->second;
    const auto id = static_cast<std::uint32_t>(names_.size());
    names_.emplace_back(name);
    index_.emplace(names_.back(), id);
    return id;
}

Node* NodeArena::allocate(std::size_t n) {
    if (n == 0) return nullptr;
    if (blocks_.empty() || used_ + n > blocks_.back().capacity) {
        // Blocks grow with the tree so that small files stay small and huge
        // ones need few allocations.
        const std::size_t last = blocks_.empty() ? 0 : blocks_.back().capacity;
        const std::size_t capacity = std::max<std::size_t>(n, std::clamp<std::size_t>(last * 2, 256, 1 << 20));
        blocks_.push_back({std::make_unique<Node[]>(capacity), capacity});
        used_ = 0;
    }
    Node* p = blocks_.back().nodes.get() + used_;
    used_ += n;
    return p;
}

void NodeArena::reset() {
    if (blocks_.size() > 1) blocks_.erase(blocks_.begin(), blocks_.end() - 1);
    used_ = 0;
}

}  // namespace asos::lang
