#include "stepper.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "app_state.h"
#include "colormap.h"

namespace hlens::gui {

namespace {

// Ear clipping of a simple polygon (either orientation); returns index triples.
std::vector<int> triangulate(const std::vector<Vec2>& p) {
    std::vector<int> out;
    const int n = (int)p.size();
    if (n < 3) return out;
    double area = 0;
    for (int i = 0; i < n; ++i) area += cross(p[i], p[(i + 1) % n]);
    std::vector<int> v(n);
    for (int i = 0; i < n; ++i) v[i] = area >= 0 ? i : n - 1 - i;
    auto inside = [&](Vec2 q, Vec2 a, Vec2 b, Vec2 c) {
        return cross(b - a, q - a) > 0 && cross(c - b, q - b) > 0 && cross(a - c, q - c) > 0;
    };
    int guard = 0;
    while (v.size() > 3 && guard++ < 4 * n) {
        const int m = (int)v.size();
        bool found = false;
        for (int i = 0; i < m && !found; ++i) {
            int ia = v[(i + m - 1) % m], ib = v[i], ic = v[(i + 1) % m];
            Vec2 a = p[ia], b = p[ib], c = p[ic];
            if (cross(b - a, c - b) <= 0) continue;
            bool ok = true;
            for (int j = 0; j < m && ok; ++j) {
                int k = v[j];
                if (k == ia || k == ib || k == ic) continue;
                if (inside(p[k], a, b, c)) ok = false;
            }
            if (!ok) continue;
            out.insert(out.end(), {ia, ib, ic});
            v.erase(v.begin() + i);
            found = true;
        }
        if (!found) {   // degenerate (collinear or self-touching): drop the flattest vertex
            int best = 0;
            double bc = HUGE_VAL;
            for (int i = 0; i < m; ++i) {
                Vec2 a = p[v[(i + m - 1) % m]], b = p[v[i]], c = p[v[(i + 1) % m]];
                double cr = std::fabs(cross(b - a, c - b));
                if (cr < bc) bc = cr, best = i;
            }
            v.erase(v.begin() + best);
        }
    }
    if (v.size() == 3) out.insert(out.end(), {v[0], v[1], v[2]});
    return out;
}

// Drops repeated points and points in the middle of straight runs.
std::vector<Vec2> simplify(const std::vector<Vec2>& in) {
    std::vector<Vec2> p;
    for (const Vec2& q : in)
        if (p.empty() || norm2(q - p.back()) > 1e-24) p.push_back(q);
    while (p.size() > 1 && norm2(p.front() - p.back()) <= 1e-24) p.pop_back();
    bool changed = true;
    while (changed && p.size() > 3) {
        changed = false;
        std::vector<Vec2> r;
        const size_t n = p.size();
        for (size_t i = 0; i < n; ++i) {
            Vec2 a = r.empty() ? p[(i + n - 1) % n] : r.back(), b = p[i], c = p[(i + 1) % n];
            double l = norm(c - a);
            if (n - (i - r.size()) > 3 && l > 0 && std::fabs(cross(b - a, c - a)) <= 1e-12 * l * l &&
                dot(b - a, c - b) >= 0) {
                changed = true;
                continue;
            }
            r.push_back(b);
        }
        if (r.size() >= 3) p.swap(r);
        else break;
    }
    return p;
}


}  // namespace

void face_polygon(const DomainMesh& m, int f, std::vector<Vec2>& outer, std::vector<int>& tris) {
    outer = simplify(m.sample_loop(m.faces()[f].loops[0], 24));
    tris = triangulate(outer);
}

// ---- Stepper

void Stepper::new_solver() {
    snapshots.clear();
    last_copy.reset();
    mesh_changed = true;
    solver = std::make_unique<TargetSolver>(*scene->grid, side, (uint32_t)target);
    solver->record_events();
    // Runs inside the solver, at each event as it happens (the solver is not being read then).
    solver->on_event([this](const Event& e) {
        switch (e.kind) {
            case EventKind::ArcMaximum:
            case EventKind::MaximumRaised:
            case EventKind::SearchRadiusShrunk:
            case EventKind::TargetFinished:
            case EventKind::VoxelCulled:
                // After the insertion: the solver's own state is the state here (and the mesh
                // has been tidied since the last copy).
                mesh_changed = true;
                return;
            case EventKind::SourceChosen:
            case EventKind::DomainSplit:
            case EventKind::DomainCreated:
            case EventKind::DomainMerged:
                mesh_changed = true;
                break;
            default:
                break;
        }
        const DomainMesh* m = solver->domain_mesh();
        if (m && (mesh_changed || !last_copy)) last_copy = std::make_shared<const DomainMesh>(*m);
        mesh_changed = false;
        StepSnapshot& sn = snapshots[e.step];
        sn.mesh = m ? last_copy : nullptr;
        sn.max_sq = solver->max_sq();
        sn.max_2d = solver->max_point_2d();
        sn.insertions = solver->insertions();
        const bool inside = e.kind == EventKind::RegionsProjected || e.kind == EventKind::DomainSplit ||
                            e.kind == EventKind::DomainCreated || e.kind == EventKind::DomainMerged;
        sn.inserting = inside ? e.source : -1;
    });
}

const Event* Stepper::advance() {
    // The current step is the solver's last event: the next one starts a new insertion, and the
    // snapshots of the previous one are no longer reachable without a replay.
    if (step + 1 >= (long)solver->events().size()) snapshots.clear();
    return solver->step_event();
}

const StepSnapshot* Stepper::snapshot() const {
    auto it = snapshots.find(step);
    return it == snapshots.end() ? nullptr : &it->second;
}
const DomainMesh* Stepper::mesh() const {
    if (const StepSnapshot* sn = snapshot()) return sn->mesh.get();
    return solver ? solver->domain_mesh() : nullptr;
}
double Stepper::max_sq() const {
    if (const StepSnapshot* sn = snapshot()) return sn->max_sq;
    return solver ? solver->max_sq() : HUGE_VAL;
}
Vec2 Stepper::max_2d() const {
    if (const StepSnapshot* sn = snapshot()) return sn->max_2d;
    return solver ? solver->max_point_2d() : Vec2();
}
int Stepper::insertions() const {
    if (const StepSnapshot* sn = snapshot()) return sn->insertions;
    return solver ? solver->insertions() : 0;
}
int32_t Stepper::inserting() const {
    const StepSnapshot* sn = snapshot();
    return sn ? sn->inserting : -1;
}
double Stepper::d2_at(Vec2 p) const {
    if (!solver) return HUGE_VAL;
    const StepSnapshot* sn = snapshot();
    if (sn && sn->inserting >= 0 && sn->mesh) {   // half-inserted: only the domain mesh knows
        const int f = sn->mesh->face_at(p);
        if (f >= 0 && !sn->mesh->faces()[f].infinite) return sn->mesh->faces()[f].poly(p);
        if (f >= 0) return HUGE_VAL;
    }
    // Between insertions: the exact distance to the sources inserted so far.
    double best = HUGE_VAL;
    for (uint32_t src : inserted_sources()) best = std::min(best, source_distance2(solver->frame(), solver->source_corners(src), p));
    return best;
}
std::vector<uint32_t> Stepper::inserted_sources() const {
    if (!solver) return {};
    const auto& all = solver->inserted_sources();   // the solver may be ahead of the step
    return std::vector<uint32_t>(all.begin(), all.begin() + std::min<size_t>(all.size(), (size_t)insertions()));
}

void Stepper::clear() {
    snapshots.clear();
    last_copy.reset();
    solver.reset();
    scene.reset();
    side = -1;
    target = -1;
    step = -1;
    at_end = false;
    current.reset();
    playing = false;
    domains.clear();
    arcs.clear();
    vertices.clear();
    live_domains = live_arcs = live_vertices = 0;
    voxels.clear();
    vox_visited = vox_pending = vox_culled = 0;
}

void Stepper::reset(std::shared_ptr<const LoadedScene> sc, int sd, long t) {
    clear();
    scene = std::move(sc);
    side = sd;
    target = t;
    fit = true;
    new_solver();
    if (pending != -2) {
        long n = pending;
        pending = -2;
        jump(n);
    } else {
        rebuild();
    }
}

void Stepper::forward() {
    if (!solver || at_end) return;
    if (const Event* e = advance()) {
        step = e->step;
        current = *e;
    } else {
        at_end = true;
    }
    if (!at_end && solver->finished() && step + 1 >= (long)solver->events().size()) at_end = true;
    rebuild();
}

void Stepper::next_insertion() {
    if (!solver || at_end) return;
    if (const Event* e = advance()) {   // (at the end of an insertion: the first event of the next)
        step = e->step;
        current = *e;
    }
    const long last = (long)solver->events().size() - 1;
    while (step < last) {
        const Event* e = solver->step_event();
        if (!e) break;
        step = e->step;
        current = *e;
    }
    at_end = solver->finished() && step + 1 >= (long)solver->events().size();
    rebuild();
}

void Stepper::to_end() { jump(LONG_MAX); }

void Stepper::back() {
    if (step >= 0) jump(step - 1);
}

void Stepper::jump(long n) {
    if (!solver) return;
    if (n < step) {   // replay from the start (as TargetSolver::replay_to, observed)
        new_solver();
        step = -1;
        current.reset();
        at_end = false;
    }
    {
        while (step < n && !at_end) {
            const Event* e = advance();
            if (!e) {
                at_end = true;
                break;
            }
            step = e->step;
            current = *e;
        }
        if (solver->finished() && step + 1 >= (long)solver->events().size()) at_end = true;
    }
    rebuild();
}

void Stepper::rebuild_voxels() {
    voxels.clear();
    vox_visited = vox_pending = vox_culled = 0;
    if (!solver) return;
    const auto& ev = solver->events();
    long V = 0, C = 0;
    for (long i = 0; i <= std::min<long>(step, (long)ev.size() - 1); ++i) {
        if (ev[i].kind == EventKind::VoxelVisited) ++V;
        if (ev[i].kind == EventKind::VoxelCulled) ++C;
    }
    // The k-th visited (culled) entry of voxel_states() is the k-th VoxelVisited (VoxelCulled)
    // event; pending entries belong to the visit before them.
    std::map<size_t, uint8_t> state;
    long v = 0, c = 0;
    for (const auto& [vox, st] : solver->voxel_states()) {
        if (st == 2 && v++ >= V) break;
        if (st == 3 && c++ >= C) break;
        state[vox] = st;
    }
    for (const auto& [vox, st] : state) {
        voxels.push_back({vox, st});
        (st == 2 ? vox_visited : st == 3 ? vox_culled : vox_pending)++;
    }
}

const Event* Stepper::regions_event() const {
    if (!solver) return nullptr;
    const auto& ev = solver->events();
    for (long i = std::min<long>(step, (long)ev.size() - 1); i >= 0; --i)
        if (ev[i].kind == EventKind::RegionsProjected) return &ev[i];
    return nullptr;
}

void Stepper::rebuild() {
    ++revision;
    jump_input = (int)std::max(-1L, step);
    domains.clear();
    arcs.clear();
    vertices.clear();
    live_domains = live_arcs = live_vertices = 0;
    rebuild_voxels();
    const DomainMesh* m = mesh();
    if (!m) return;
    live_domains = m->num_live_faces();
    live_arcs = m->num_live_edges();
    live_vertices = m->num_live_vertices();
    const auto& F = m->faces();
    for (int f = 0; f < (int)F.size(); ++f) {
        if (f == m->outside_face() || !F[f].alive || F[f].loops.empty()) continue;
        DomainDraw d;
        d.face = f;
        d.label = F[f].label;
        d.infinite = F[f].infinite;
        d.colour = domain_label_colour(d.label, d.infinite);
        d.area = m->face_area(f);
        face_polygon(*m, f, d.outer, d.tris);
        domains.push_back(std::move(d));
    }
    // Outer loops in decreasing area: a face inside another's hole is drawn over it.
    std::vector<double> key(F.size(), 0);
    for (const DomainDraw& d : domains) key[d.face] = std::fabs(m->loop_area(F[d.face].loops[0]));
    std::stable_sort(domains.begin(), domains.end(), [&](const DomainDraw& a, const DomainDraw& b) { return key[a.face] > key[b.face]; });
    const auto& E = m->edges();
    for (int e = 0; e < (int)E.size(); ++e) {
        if (!E[e].alive) continue;
        ArcDraw a;
        a.edge = e;
        a.kind = E[e].kind;
        const int n = E[e].curve.straight() ? 2 : 24;
        for (int i = 0; i <= n; ++i) a.pts.push_back(m->edge_point(e, double(i) / n));
        arcs.push_back(std::move(a));
    }
    for (const auto& v : m->vertices())
        if (v.alive) vertices.push_back(v.p);
}

void sync_stepper(AppState& s) {
    Stepper& st = s.stepper;
    const int d = s.direction;
    const long t = s.selected[d];
    if (!st.open || !s.scene || !s.scene->grid || t < 0) {
        if (st.active() && (t < 0 || !s.scene || st.scene != s.scene)) st.clear();
        return;
    }
    if (!st.active() || st.scene != s.scene || st.side != d || st.target != t) st.reset(s.scene, d, t);
}

std::optional<DegenerateTarget> degenerate_target(const TargetFrame& fr) {
    if (!fr.degenerate) return std::nullopt;
    if (fr.corners[0] == fr.corners[1] && fr.corners[1] == fr.corners[2]) return DegenerateTarget{"point", 0, 0};
    const double h = TargetSolver::sliver_slack(fr);
    return DegenerateTarget{h == 0 ? "segment" : "sliver", h, fr.scale};
}

}  // namespace hlens::gui
