#include "framefix/singularities/three_five.h"

#include <algorithm>

#include "framefix/core/error.h"

namespace framefix {
namespace {

// Majority of labels[begin, end); a tie goes to `tie`.
int majority(const std::vector<int>& labels, int begin, int end, int tie) {
    int n3 = 0, n5 = 0;
    for (int i = begin; i < end; ++i) (labels[i] == 3 ? n3 : n5) += 1;
    return n3 > n5 ? 3 : n5 > n3 ? 5 : tie;
}

CurveKind kind_of(int label) { return label == 3 ? CurveKind::Valence3 : CurveKind::Valence5; }

}  // namespace

std::vector<int> smooth_labels(const std::vector<int>& labels, int window, bool closed) {
    const int n = int(labels.size()), half = std::max(window, 1) / 2;
    for (int l : labels) FF_ASSERT(l == 3 || l == 5);
    std::vector<int> out(labels);
    for (int i = 0; i < n; ++i) {
        int n3 = 0, n5 = 0;
        for (int d = -half; d <= half; ++d) {
            int j = i + d;
            if (closed) j = ((j % n) + n) % n;
            else if (j < 0 || j >= n) continue;
            (labels[j] == 3 ? n3 : n5) += 1;
        }
        out[i] = n3 > n5 ? 3 : n5 > n3 ? 5 : labels[i];
    }
    return out;
}

LabelClass classify_labels(const std::vector<int>& labels, bool closed, int window, const int forced_end[2]) {
    FF_ASSERT(!labels.empty());
    const int n = int(labels.size());
    const std::vector<int> s = smooth_labels(labels, window, closed);
    LabelClass out;
    const bool mixed = std::count(s.begin(), s.end(), 3) != 0 && std::count(s.begin(), s.end(), 5) != 0;
    if (closed) {
        out.kind = mixed ? CurveKind::Other : kind_of(s[0]);
        return out;
    }
    const int k = std::max(1, std::min(3, n / 3));
    out.end_label[0] = majority(s, 0, k, s.front());
    out.end_label[1] = majority(s, n - k, n, s.back());
    for (int e = 0; e < 2 && forced_end; ++e)
        if (forced_end[e] == 3 || forced_end[e] == 5) out.end_label[e] = forced_end[e];
    if (out.end_label[0] == out.end_label[1]) {
        out.kind = kind_of(out.end_label[0]);
        return out;
    }
    out.kind = CurveKind::ThreeFive;
    // Transition: the single cut that agrees best with "end-0 label before, end-1 label after".
    int agree = int(std::count(s.begin(), s.end(), out.end_label[1]));
    int best = -1;
    out.transition = 0;
    for (int i = 1; i < n; ++i) {
        agree += (s[i - 1] == out.end_label[0]) - (s[i - 1] == out.end_label[1]);
        if (agree > best) best = agree, out.transition = i;
    }
    return out;
}

}  // namespace framefix
