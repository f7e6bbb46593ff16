#pragma once
// Disjoint sets with path halving; `unite` keeps the smaller root so that cluster roots (and the
// ids derived from them) do not depend on the order of the unions.
#include <numeric>
#include <vector>

namespace framefix {

class UnionFind {
public:
    explicit UnionFind(int n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }
    int find(int a) {
        while (parent_[a] != a) a = parent_[a] = parent_[parent_[a]];
        return a;
    }
    void unite(int a, int b) {
        a = find(a), b = find(b);
        if (a < b) parent_[b] = a;
        else if (b < a) parent_[a] = b;
    }

private:
    std::vector<int> parent_;
};

}  // namespace framefix
