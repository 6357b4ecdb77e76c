// Where the interpreter keeps what a big scene is made of: objects in large
// chunks, textures shared by content.
#include <algorithm>
#include <cstring>

#include "src/lang/interpreter_impl.hpp"

namespace asos::lang {

namespace {

// 64 MiB per chunk: glibc maps blocks this large on their own (its mmap
// threshold tops out at 32 MiB), so each chunk is returned to the system as
// soon as it is freed. reserve() does not touch the pages, so a small scene
// pays address space, not memory.
constexpr std::size_t kChunkBytes = std::size_t{64} << 20;
constexpr std::size_t kChunkObjects = kChunkBytes / sizeof(Object);

}  // namespace

void ObjectStore::reserve(std::size_t count) {
    try {
        main_.reserve(count);
    } catch (const std::exception&) {
        // Too much address space for this system: the chunks will do.
    }
}

Object& ObjectStore::add() {
    if (main_.size() < main_.capacity()) return main_.emplace_back();
    if (chunks_.empty() || chunks_.back().size() == kChunkObjects) {
        chunks_.emplace_back();
        chunks_.back().reserve(kChunkObjects);
    }
    ++overflow_;
    return chunks_.back().emplace_back();
}

std::vector<Object> ObjectStore::take() {
    if (chunks_.empty()) return std::move(main_);
    std::vector<Object> all;
    all.reserve(size());
    for (Object& o : main_) all.push_back(std::move(o));
    std::vector<Object>().swap(main_);
    for (auto& chunk : chunks_) {
        for (Object& o : chunk) all.push_back(std::move(o));
        std::vector<Object>().swap(chunk);  // give the chunk back now
    }
    chunks_.clear();
    overflow_ = 0;
    return all;
}

namespace {

// -0 and 0 compare equal, so they must hash alike.
void mix(std::uint64_t& h, double v) {
    v += 0.0;
    std::uint64_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    h ^= bits;
    h *= 0x100000001b3ULL;
    h ^= h >> 29;
}

void mix(std::uint64_t& h, const Vec3& v) {
    mix(h, v.x);
    mix(h, v.y);
    mix(h, v.z);
}

void mix(std::uint64_t& h, const Color& c) {
    mix(h, c.rgb);
    mix(h, c.filter);
    mix(h, c.transmit);
}

// The colours and the finish tell textures apart well enough; equal hashes
// are compared in full.
std::uint64_t hashOf(const Texture& t) {
    std::uint64_t h = 0xcbf29ce484222325ULL;
    const Pigment& p = t.pigment;
    mix(h, static_cast<double>(p.kind));
    mix(h, p.color1);
    mix(h, p.color2);
    mix(h, Vec3(p.worldFromPattern.matrix()[3]));
    const Finish& f = t.finish;
    mix(h, f.ambient);
    mix(h, f.diffuse);
    mix(h, f.phong);
    mix(h, f.specular);
    mix(h, f.reflection);
    mix(h, f.reflectionMin.value_or(f.reflection));
    mix(h, f.metallic);
    mix(h, t.normal ? static_cast<double>(t.normal->kind) : -1.0);
    mix(h, static_cast<double>(t.above.size()));
    return h;
}

bool sameLayer(const TextureLayer& a, const TextureLayer& b) {
    return a.pigment == b.pigment && a.finish == b.finish && a.normal == b.normal;
}

bool sameTexture(const Texture& a, const Texture& b) {
    return sameLayer(a, b) && std::equal(a.above.begin(), a.above.end(), b.above.begin(), b.above.end(), sameLayer);
}

}  // namespace

std::shared_ptr<const Texture> TextureInterner::intern(const std::shared_ptr<const Texture>& texture) {
    if (texture == lastInput_) return lastInterned_;
    auto& bucket = byHash_[hashOf(*texture)];
    std::shared_ptr<const Texture> interned;
    for (const auto& candidate : bucket)
        if (sameTexture(*candidate, *texture)) interned = candidate;
    if (!interned) {
        bucket.push_back(texture);
        interned = texture;
    }
    lastInput_ = texture;
    lastInterned_ = interned;
    return interned;
}

}  // namespace asos::lang
