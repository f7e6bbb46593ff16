#include "framefix/blocks/sheets.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace framefix {

namespace {

using Poly = std::vector<Eigen::Vector3d>;

Poly to_poly(const Points& P) {
    Poly out(P.rows());
    for (int i = 0; i < int(P.rows()); ++i) out[i] = P.row(i).transpose();
    return out;
}

double poly_length(const Poly& P) {
    double l = 0;
    for (size_t i = 1; i < P.size(); ++i) l += (P[i] - P[i - 1]).norm();
    return l;
}

// Point at arc length s (clamped).
Poly resample(const Poly& P, const std::vector<double>& at) {
    Poly out;
    out.reserve(at.size());
    size_t i = 1;
    double base = 0;
    for (double s : at) {
        while (i + 1 < P.size() && base + (P[i] - P[i - 1]).norm() < s) base += (P[i] - P[i - 1]).norm(), ++i;
        if (P.size() < 2) { out.push_back(P.front()); continue; }
        const double seg = (P[i] - P[i - 1]).norm();
        const double w = seg > 0 ? std::clamp((s - base) / seg, 0.0, 1.0) : 0;
        out.push_back(P[i - 1] + w * (P[i] - P[i - 1]));
    }
    return out;
}

std::vector<double> linspace(double a, double b, int n) {
    std::vector<double> out(n);
    for (int i = 0; i < n; ++i) out[i] = n > 1 ? a + (b - a) * i / (n - 1) : a;
    return out;
}

struct Traced {
    Poly points;
    StopReason reason;
};

class SoupBuilder {
public:
    SoupBuilder(SheetSoup& soup, double h, double overshoot) : soup_(soup), h_(h), overshoot_(overshoot) {}

    // Zip two streamlines: by normalised arc length if both left the solid, else up to the
    // shorter one. `widen`: rule 6, widen the strip by overshoot h on both lateral sides.
    // Returns the largest gap between the two resampled streamlines.
    double ribbon(const Traced& A, const Traced& B, int source, bool widen) {
        const double la = poly_length(A.points), lb = poly_length(B.points);
        Poly Ar, Br;
        if (A.reason == StopReason::LeftSolid && B.reason == StopReason::LeftSolid) {
            const int m = int(std::ceil(std::max(la, lb) / (0.5 * h_))) + 2;
            Ar = resample(A.points, linspace(0, la, m)), Br = resample(B.points, linspace(0, lb, m));
        } else {
            const double l = std::min(la, lb);
            const int m = int(std::ceil(l / (0.5 * h_))) + 2;
            Ar = resample(A.points, linspace(0, l, m)), Br = resample(B.points, linspace(0, l, m));
        }
        double gap = 0;
        for (size_t k = 0; k < Ar.size(); ++k) gap = std::max(gap, (Ar[k] - Br[k]).norm());
        if (widen && overshoot_ > 0) widen_strip(Ar, Br);
        for (size_t k = 0; k + 1 < Ar.size(); ++k) {
            add_triangle(Ar[k], Br[k], Ar[k + 1], source);
            add_triangle(Br[k], Br[k + 1], Ar[k + 1], source);
        }
        return gap;
    }

    void finish() {
        soup_.points.resize(Eigen::Index(points_.size()), 3);
        for (size_t i = 0; i < points_.size(); ++i) soup_.points.row(Eigen::Index(i)) = points_[i].transpose();
        soup_.triangles.resize(Eigen::Index(sources_.size()), 3);
        soup_.source.resize(Eigen::Index(sources_.size()));
        for (size_t t = 0; t < sources_.size(); ++t) {
            soup_.triangles.row(Eigen::Index(t)) << int(3 * t), int(3 * t + 1), int(3 * t + 2);
            soup_.source[Eigen::Index(t)] = sources_[t];
        }
    }

private:
    // Move each pair apart along A - B; rows where the two coincide borrow the nearest direction.
    void widen_strip(Poly& A, Poly& B) const {
        const double d = overshoot_ * h_;
        std::vector<Eigen::Vector3d> u(A.size(), Eigen::Vector3d::Zero());
        int first = -1;
        for (size_t k = 0; k < A.size(); ++k) {
            const Eigen::Vector3d g = A[k] - B[k];
            if (g.norm() > 1e-9) u[k] = g.normalized(), first = first < 0 ? int(k) : first;
            else if (k > 0) u[k] = u[k - 1];
        }
        if (first < 0) return;
        for (int k = 0; k < first; ++k) u[k] = u[first];
        for (size_t k = 0; k < A.size(); ++k) A[k] += d * u[k], B[k] -= d * u[k];
    }
    void add_triangle(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c, int source) {
        if ((b - a).cross(c - a).norm() < 1e-14) return;  // zero area: cuts nothing
        points_.push_back(a), points_.push_back(b), points_.push_back(c);
        sources_.push_back(source);
    }

    SheetSoup& soup_;
    double h_, overshoot_;
    std::vector<Eigen::Vector3d> points_;
    std::vector<int> sources_;
};

void count(SheetStats& s, StopReason r) {
    switch (r) {
        case StopReason::LeftSolid: ++s.left_solid; break;
        case StopReason::ReachedSingularity: ++s.reached_singularity; break;
        case StopReason::SharpTurn: ++s.sharp_turn; break;
        case StopReason::LimitCycle: ++s.limit_cycle; break;
        case StopReason::MaxSteps: ++s.max_steps; break;
        case StopReason::StartOutside: ++s.start_outside; break;
    }
}

}  // namespace

Points singular_points(const SingularityGraph& graph) {
    int n = 0;
    for (const SingularCurve& c : graph.curves)
        if (c.kind != CurveKind::Other && c.faces.size() >= 3) n += int(c.points.rows());
    Points out(n, 3);
    int r = 0;
    for (const SingularCurve& c : graph.curves)
        if (c.kind != CurveKind::Other && c.faces.size() >= 3) out.middleRows(r, c.points.rows()) = c.points, r += int(c.points.rows());
    return out;
}

namespace {

using Junctions = BlockOptions::Junctions;
bool closes(Junctions m) {
    return m == Junctions::DropAndClose || m == Junctions::DropCloseAndZip || m == Junctions::ContinueAndClose;
}
bool drops(Junctions m) { return m != Junctions::Continue && m != Junctions::ContinueAndClose; }
bool zips(Junctions m) { return m == Junctions::DropAndZip || m == Junctions::DropCloseAndZip; }

bool any_within(const Eigen::Vector3d& a, const std::vector<Eigen::Vector3d>& D, double cos_min) {
    for (const auto& b : D) if (a.dot(b) >= cos_min) return true;
    return false;
}

// The sheet spanned by `d` and `out` at end e of source si is another singular curve's sheet
// at the same junction node, spanned by that curve's tangent t leaving the node and one of its
// directions d': d along t and out along d', or d along d' and out along t. On the filleted notch
// the two halves of the fillet's valence-5 curve meet at the node, and continuing either one's
// curtain past it put a second sheet beside the other's, 1-3 h apart: a 5-faced wedge.
bool continued_at_junction(const std::vector<SheetSource>& sources, int si, int e, const Eigen::Vector3d& d,
                           const Eigen::Vector3d& out, double cos_match) {
    const int node = sources[si].junction[e];
    if (node < 0) return false;
    if (std::abs(d.dot(out)) > kJunctionAlongCos) return true;  // d along the curve: spans no sheet past the node
    for (int sj = 0; sj < int(sources.size()); ++sj)
        for (int f = 0; f < 2; ++f) {
            if ((sj == si && f == e) || sources[sj].junction[f] != node) continue;
            const JunctionEnd j = junction_end(sources[sj], f);
            if (j.seed < 0) continue;
            const std::vector<Eigen::Vector3d>& D = sources[sj].seeds[j.seed].directions;
            if ((d.dot(j.tangent) > kJunctionAlongCos && any_within(out, D, cos_match)) ||
                (out.dot(j.tangent) > kJunctionAlongCos && any_within(d, D, cos_match)))
                return true;
        }
    return false;
}

// The state of one build_sheets call: traced streamlines, the soup under construction, and the
// streamline pairs that later steps continue.
class SheetTracer {
public:
    SheetTracer(const TetMesh& mesh, const FrameField& field, const TetLocator& locator,
                const std::vector<SheetSource>& sources, const Points& singular, double h, const BlockOptions& o,
                SheetSoup& soup, SheetStats& stats)
        : mesh_(mesh), field_(field), locator_(locator), sources_(sources), h_(h), stats_(stats),
          soup_(soup, h, o.overshoot), cos_match_(std::cos(o.match_deg * M_PI / 180)), junctions_(o.junctions) {
        trace_.step = o.step * h;
        trace_.stop_distance = o.stop_distance * h;
        trace_.singular_points = singular;
        trace_.threads = o.threads;
    }

    void trace_seeds();
    void zip_seeds(int si);
    void extend_past_boundary_ends(int si);
    void collect_cross_jobs(int si);
    void zip_across_junctions();
    void zip_ends(int si, int ki, int sj, int kj);
    void cross_extensions();
    void finish() { soup_.finish(); }

private:
    struct Job { int si, ki, di, sign; };  // cross extension from streamline (si, ki, di), tangent sign

    std::vector<Traced> run(const std::vector<Eigen::Vector3d>& P, const std::vector<Eigen::Vector3d>& V,
                            const std::vector<Eigen::Vector3d>* prefix);
    const Traced& line(int si, int ki, int di) const { return lines_[index_.at({si, ki, di})]; }
    bool widen(int si) const { return si >= 0 && sources_[si].kind != SheetSource::Singular; }
    bool matched(const Eigen::Vector3d& a, const std::vector<Eigen::Vector3d>& D) const {
        return any_within(a, D, cos_match_);
    }
    bool continued(int si, int e, const Eigen::Vector3d& d, const Eigen::Vector3d& out) const {
        return drops(junctions_) && continued_at_junction(sources_, si, e, d, out, cos_match_);
    }

    const TetMesh& mesh_;
    const FrameField& field_;
    const TetLocator& locator_;
    const std::vector<SheetSource>& sources_;
    double h_;
    SheetStats& stats_;
    SoupBuilder soup_;
    double cos_match_;
    BlockOptions::Junctions junctions_;
    TraceOptions trace_;
    std::map<std::tuple<int, int, int>, int> index_;  // (source, seed, direction) -> lines_ index
    std::vector<Traced> lines_;
    std::vector<std::pair<Poly, Poly>> diverging_;   // neighbouring streamlines > 3 h apart
    std::vector<Job> jobs_;
};

bool usable(const Traced& t) { return t.points.size() >= 2; }

std::vector<Traced> SheetTracer::run(const std::vector<Eigen::Vector3d>& P, const std::vector<Eigen::Vector3d>& V,
                                     const std::vector<Eigen::Vector3d>* prefix) {
    Points seeds(Eigen::Index(P.size()), 3), dirs(Eigen::Index(P.size()), 3);
    for (size_t i = 0; i < P.size(); ++i) seeds.row(Eigen::Index(i)) = P[i].transpose(), dirs.row(Eigen::Index(i)) = V[i].transpose();
    const std::vector<Streamline> raw = trace_streamlines(mesh_, field_, locator_, seeds, dirs, trace_);
    std::vector<Traced> out(raw.size());
    for (size_t i = 0; i < raw.size(); ++i) {
        count(stats_, raw[i].reason);
        out[i].reason = raw[i].reason;
        if (raw[i].reason == StopReason::StartOutside) continue;
        out[i].points = to_poly(raw[i].points);
        if (prefix) out[i].points.insert(out[i].points.begin(), (*prefix)[i]);
        // A streamline that left the solid ends on the boundary: go 0.25 h beyond so that the
        // mesh edges next to the boundary are cut too.
        const Poly& q = out[i].points;
        if (raw[i].reason == StopReason::LeftSolid && q.size() >= 2 && (q.back() - q[q.size() - 2]).norm() > 0)
            out[i].points.push_back(q.back() + 0.25 * h_ * (q.back() - q[q.size() - 2]).normalized());
    }
    stats_.streamlines += int(raw.size());
    return out;
}

// One streamline per (source, seed, direction); singular seeds start 0.5 h off the curve, and
// every polyline starts AT its seed.
void SheetTracer::trace_seeds() {
    std::vector<Eigen::Vector3d> p0, v0, anchor;
    for (int si = 0; si < int(sources_.size()); ++si)
        for (int ki = 0; ki < int(sources_[si].seeds.size()); ++ki) {
            const SheetSeed& seed = sources_[si].seeds[ki];
            const double off = sources_[si].kind == SheetSource::Singular ? 0.5 * h_ : 0.02 * h_;
            for (int di = 0; di < int(seed.directions.size()); ++di) {
                index_[{si, ki, di}] = int(p0.size());
                p0.push_back(seed.point + off * seed.directions[di]), v0.push_back(seed.directions[di]);
                anchor.push_back(seed.point);
            }
        }
    lines_ = run(p0, v0, &anchor);
}

// Ribbons between consecutive seeds whose directions match (a seed that lost a direction is
// skipped, up to 2 seeds ahead).
void SheetTracer::zip_seeds(int si) {
    const std::vector<SheetSeed>& S = sources_[si].seeds;
    const int n = int(S.size()), last = sources_[si].closed ? n : n - 1;  // a closed one wraps round
    for (int ki = 0; ki < last; ++ki)
        for (int di = 0; di < int(S[ki].directions.size()); ++di) {
            const Eigen::Vector3d& a = S[ki].directions[di];
            for (int kk = ki + 1; kk < std::min(ki + 4, sources_[si].closed ? ki + n : n); ++kk) {
                const int kj = kk % n;
                int best = -1;
                for (int dj = 0; dj < int(S[kj].directions.size()); ++dj)
                    if (best < 0 || a.dot(S[kj].directions[dj]) > a.dot(S[kj].directions[best])) best = dj;
                if (best < 0 || a.dot(S[kj].directions[best]) < cos_match_) continue;
                const Traced &A = line(si, ki, di), &B = line(si, kj, best);
                if (usable(A) && usable(B)) {
                    const double gap = soup_.ribbon(A, B, si, widen(si));
                    ++stats_.ribbons;
                    if (gap > 3 * h_) diverging_.push_back({A.points, B.points});
                }
                break;
            }
        }
}

// Where one curve runs straight on through a junction node (the two halves of the fillet's
// valence-5 curve), its sheets are the other's: with the continuation past the node dropped,
// the end streamlines of the two are zipped across the node as one curve's would be. Without
// this the quadrant between the two, where the field turns round the node, stayed open.
void SheetTracer::zip_across_junctions() {
    if (!zips(junctions_)) return;
    for (int si = 0; si < int(sources_.size()); ++si)
        for (int e = 0; e < 2; ++e)
            for (int sj = si + 1; sj < int(sources_.size()); ++sj)
                for (int f = 0; f < 2; ++f)
                    if (straight_through(sources_, si, e, sj, f))
                        zip_ends(si, junction_end(sources_[si], e).seed, sj, junction_end(sources_[sj], f).seed);
}

// Each direction of seed ki of source si zipped to the closest one (within match_deg) of seed kj
// of source sj; pairs more than 3 h apart are bridged later, as diverging neighbours.
void SheetTracer::zip_ends(int si, int ki, int sj, int kj) {
    const std::vector<Eigen::Vector3d>&DA = sources_[si].seeds[ki].directions, &DB = sources_[sj].seeds[kj].directions;
    for (int di = 0; di < int(DA.size()); ++di) {
        int best = -1;
        for (int dj = 0; dj < int(DB.size()); ++dj)
            if (best < 0 || DA[di].dot(DB[dj]) > DA[di].dot(DB[best])) best = dj;
        if (best < 0 || DA[di].dot(DB[best]) < cos_match_) continue;
        const Traced &A = line(si, ki, di), &B = line(sj, kj, best);
        if (!usable(A) || !usable(B)) continue;
        if (soup_.ribbon(A, B, si, widen(si)) > 3 * h_) diverging_.push_back({A.points, B.points});
        ++stats_.ribbons;
    }
}

// Past a source end on the boundary (and, in the modes that close, at a junction node): the nearest
// complete seed's streamlines, translated to the end point and 0.5 h beyond it.
void SheetTracer::extend_past_boundary_ends(int si) {
    const std::vector<SheetSeed>& S = sources_[si].seeds;
    if (S.size() < 2) return;
    std::map<int, int> counts;
    for (const auto& s : S) counts[int(s.directions.size())] += 1;
    int full = 0, most = 0;
    for (auto [k, c] : counts) if (c > most) most = c, full = k;
    for (int e = 0; e < 2; ++e) {
        const bool junc = sources_[si].junction[e] >= 0 && closes(junctions_);
        if ((!sources_[si].boundary_end[e] && !junc) || full == 0) continue;
        int k0 = -1;
        for (int j = 0; j < int(S.size()) && k0 < 0; ++j) {
            const int k = e == 0 ? j : int(S.size()) - 1 - j;
            bool ok = int(S[k].directions.size()) == full;
            for (int d = 0; d < full && ok; ++d) ok = usable(line(si, k, d));
            if (ok) k0 = k;
        }
        if (k0 < 0) continue;
        const Eigen::Vector3d pend = e == 0 ? S.front().point : S.back().point;
        const Eigen::Vector3d pin = e == 0 ? S[1].point : S[S.size() - 2].point;
        const Eigen::Vector3d ext = pend + 0.5 * h_ * (pend - pin).normalized();
        for (int d = 0; d < full; ++d) {
            Traced A = line(si, k0, d);
            for (const Eigen::Vector3d& target : {pend, ext}) {
                Traced B = A;
                const Eigen::Vector3d shift = target - S[k0].point;
                for (auto& p : B.points) p += shift;
                soup_.ribbon(A, B, si, widen(si));
                A = B;
            }
        }
    }
}

// Sheet borders that the cross extension continues: the streamlines of both end seeds and of
// seed pairs whose directions jump.
void SheetTracer::collect_cross_jobs(int si) {
    const std::vector<SheetSeed>& S = sources_[si].seeds;
    if (S.size() < 2) return;
    const int n = int(S.size()), last = sources_[si].closed ? n : n - 1;  // a closed one wraps round
    for (int ki = 0; ki < last; ++ki) {
        const int kn = (ki + 1) % n;
        if (!S[ki].continue_jumps || !S[kn].continue_jumps) continue;
        for (int di = 0; di < int(S[ki].directions.size()); ++di)
            if (!matched(S[ki].directions[di], S[kn].directions)) jobs_.push_back({si, ki, di, +1});
        for (int dj = 0; dj < int(S[kn].directions.size()); ++dj)
            if (!matched(S[kn].directions[dj], S[ki].directions)) jobs_.push_back({si, kn, dj, -1});
    }
    if (sources_[si].closed) return;
    // Outward tangents over 2 seeds: a curve can bend within 1 h of its node.
    const Eigen::Vector3d out0 = (S[0].point - S[std::min(2, n - 1)].point).normalized(),
                          out1 = (S[n - 1].point - S[std::max(n - 3, 0)].point).normalized();
    for (int di = 0; di < int(S.front().directions.size()); ++di)
        if (!continued(si, 0, S.front().directions[di], out0)) jobs_.push_back({si, 0, di, -1});
    for (int di = 0; di < int(S.back().directions.size()); ++di)
        if (!continued(si, 1, S.back().directions[di], out1)) jobs_.push_back({si, n - 1, di, +1});
}

// From each job's streamline, trace along the source tangent (away from the sheet), zip
// neighbouring cross streamlines, and close up to both ends of the generating streamline.
// Diverging neighbours are bridged the same way along the in-sheet normal.
void SheetTracer::cross_extensions() {
    std::vector<Eigen::Vector3d> cp, cv;
    std::vector<std::vector<int>> members;           // per cross job: indices into cp
    std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> anchors;  // ends of the generating streamline
    std::vector<int> job_source;                     // -1: diverging bridge (never widened)
    auto add_job = [&](const Poly& A, int source, auto&& direction_at) {
        members.emplace_back(), anchors.push_back({A.front(), A.back()}), job_source.push_back(source);
        const double la = poly_length(A);
        const Poly Ar = resample(A, linspace(0, la, std::max(2, int(std::ceil(la / (0.5 * h_)))) + 1));
        for (size_t k = 1; k < Ar.size(); ++k) {
            Eigen::Vector3d dir;
            if (!direction_at(Ar, k, dir)) continue;
            members.back().push_back(int(cp.size()));
            cp.push_back(Ar[k] + 0.05 * h_ * dir), cv.push_back(dir);
        }
    };
    for (const Job& j : jobs_) {
        const std::vector<SheetSeed>& S = sources_[j.si].seeds;
        const Traced& A = line(j.si, j.ki, j.di);
        if (!usable(A) || poly_length(A.points) < 1e-9) continue;
        const Eigen::Vector3d a = S[std::max(j.ki - 1, 0)].point, b = S[std::min(j.ki + 1, int(S.size()) - 1)].point;
        const Eigen::Vector3d tv = j.sign * (b - a).normalized();
        if (!tv.allFinite()) continue;
        add_job(A.points, j.si, [&](const Poly&, size_t, Eigen::Vector3d& d) { d = tv; return true; });
    }
    for (const auto& [P, Q] : diverging_)
        for (const auto& [X, Y] : {std::pair<const Poly&, const Poly&>(P, Q), std::pair<const Poly&, const Poly&>(Q, P)}) {
            const double lx = poly_length(X), ly = poly_length(Y);
            if (lx < 1e-9 || ly < 1e-9) continue;
            const int ns = std::max(2, int(std::ceil(lx / (0.5 * h_)))) + 1;
            const Poly Yr = resample(Y, linspace(0, ly, ns));
            add_job(X, -1, [&](const Poly& Xr, size_t k, Eigen::Vector3d& d) {
                const Eigen::Vector3d tg = (Xr[std::min(k + 1, Xr.size() - 1)] - Xr[k - 1]).normalized();
                const Eigen::Vector3d g = Yr[std::min(k, Yr.size() - 1)] - Xr[k];
                d = g - g.dot(tg) * tg;
                if (d.norm() < 0.5 * h_) return false;
                d.normalize();
                return true;
            });
        }
    if (cp.empty()) return;
    // A source tangent read from two seeds can be 47 degrees off the field's axis there (a
    // snapped path's kinked end on HexMe's notch at 0.7 x): it only picks the axis.
    trace_.start_picks_axis = true;
    const std::vector<Traced> cross = run(cp, cv, nullptr);
    trace_.start_picks_axis = false;
    for (size_t ji = 0; ji < members.size(); ++ji) {
        const int si = job_source[ji], source = std::max(si, 0);
        std::vector<int> valid;
        for (int i : members[ji]) if (usable(cross[i])) valid.push_back(i);
        for (size_t k = 0; k + 1 < valid.size(); ++k) {
            soup_.ribbon(cross[valid[k]], cross[valid[k + 1]], source, widen(si));
            ++stats_.cross_ribbons;
        }
        if (valid.empty()) continue;
        for (auto [i, target] : {std::pair<int, Eigen::Vector3d>(valid.front(), anchors[ji].first),
                                 std::pair<int, Eigen::Vector3d>(valid.back(), anchors[ji].second)}) {
            Traced B = cross[i];
            const Eigen::Vector3d shift = target - B.points.front();
            for (auto& p : B.points) p += shift;
            soup_.ribbon(cross[i], B, source, widen(si));
            ++stats_.cross_ribbons;
        }
    }
}

}  // namespace

SheetSoup build_sheets(const TetMesh& mesh, const FrameField& field, const TetLocator& locator,
                       const std::vector<SheetSource>& sources, const Points& singular, double h,
                       const BlockOptions& options, SheetStats& stats) {
    SheetSoup soup;
    for (const SheetSource& s : sources) soup.source_kind.push_back(s.name);
    SheetTracer tracer(mesh, field, locator, sources, singular, h, options, soup, stats);
    tracer.trace_seeds();
    for (int si = 0; si < int(sources.size()); ++si) {
        tracer.zip_seeds(si);
        tracer.collect_cross_jobs(si);
        tracer.extend_past_boundary_ends(si);
    }
    tracer.zip_across_junctions();
    tracer.cross_extensions();
    tracer.finish();
    stats.sources += int(sources.size());
    return soup;
}

}  // namespace framefix
