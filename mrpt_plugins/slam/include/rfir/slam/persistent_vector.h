/* rfir: a persistent (copy-on-write) vector of shared, immutable elements.
 * FastSLAM particles hold one landmark EKF per tag; on resampling many
 * particles become copies of one. With this structure a particle copy is one
 * pointer copy, and changing one element copies only the path of trie nodes
 * (depth log16 N) plus that element: the per-particle landmark trees of
 * Montemerlo's FastSLAM, as a 16-ary trie. */
#pragma once

#include <array>
#include <cstddef>
#include <memory>

namespace rfir::slam {
template <class T>
class CPersistentVector {
  public:
    using ElemPtr = std::shared_ptr<const T>;
    static constexpr unsigned BITS = 4;
    static constexpr size_t FANOUT = size_t(1) << BITS;

    /** Element i, or nullptr when never set. */
    const T* get(size_t i) const {
        if (!root_ || i >= capacity()) return nullptr;
        const Node* n = root_.get();
        for (unsigned shift = shift_; shift > 0; shift -= BITS) {
            n = n->kids[(i >> shift) & (FANOUT - 1)].get();
            if (!n) return nullptr;
        }
        return n->vals[i & (FANOUT - 1)].get();
    }

    /** Replaces element i in this version only: copies the nodes on its path. */
    void set(size_t i, ElemPtr v) {
        while (i >= capacity()) grow();
        root_ = setRec(root_, shift_, i, std::move(v));
    }

  private:
    struct Node {
        std::array<std::shared_ptr<const Node>, FANOUT> kids;
        std::array<ElemPtr, FANOUT> vals;
    };
    using NodePtr = std::shared_ptr<const Node>;

    size_t capacity() const { return root_ ? size_t(1) << (shift_ + BITS) : 0; }
    void grow() {
        if (!root_) {
            root_ = std::make_shared<Node>();
            shift_ = 0;
            return;
        }
        auto r = std::make_shared<Node>();
        r->kids[0] = root_;
        root_ = r;
        shift_ += BITS;
    }
    static NodePtr setRec(const NodePtr& n, unsigned shift, size_t i, ElemPtr v) {
        auto c = n ? std::make_shared<Node>(*n) : std::make_shared<Node>();
        const size_t k = (i >> shift) & (FANOUT - 1);
        if (shift == 0)
            c->vals[k] = std::move(v);
        else
            c->kids[k] = setRec(c->kids[k], shift - BITS, i, std::move(v));
        return c;
    }

    NodePtr root_;
    unsigned shift_ = 0;
};

}  // namespace rfir::slam
