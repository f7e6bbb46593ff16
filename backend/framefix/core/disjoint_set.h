#pragma once
// Disjoint sets (union-find) over 0..n-1 with path halving.
// Two union rules, because callers number things by their roots: `unite` keeps the smaller root,
// so roots do not depend on the order of the unions; `merge_into(a, b)` hangs a's root under b's
// root, for callers whose results were defined with that rule.
#include <numeric>
#include <vector>

namespace framefix {

class DisjointSet {
public:
    explicit DisjointSet(int n = 0) : parent_(size_t(n)) { std::iota(parent_.begin(), parent_.end(), 0); }

    int size() const { return int(parent_.size()); }

    int find(int a) {
        while (parent_[a] != a) a = parent_[a] = parent_[parent_[a]];
        return a;
    }

    // Joins the sets of a and b; the smaller root stays root. False if they were one set already.
    bool unite(int a, int b) {
        a = find(a), b = find(b);
        if (a == b) return false;
        if (a < b) parent_[b] = a;
        else parent_[a] = b;
        return true;
    }

    // Joins the sets of a and b; b's root stays root. False if they were one set already.
    bool merge_into(int a, int b) {
        a = find(a), b = find(b);
        if (a == b) return false;
        parent_[a] = b;
        return true;
    }

    // Resets to n singletons, keeping the storage (for loops over many small sets).
    void reset(int n) {
        parent_.resize(size_t(n));
        std::iota(parent_.begin(), parent_.end(), 0);
    }

private:
    std::vector<int> parent_;
};

}  // namespace framefix
