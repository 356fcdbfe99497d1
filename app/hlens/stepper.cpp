#include "tolerance_view.h"
#include "stepper.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <map>

#include <imgui.h>

#include "app_state.h"
#include "panels.h"
#include "gl.h"
#include "overlay.h"

namespace hlens::gui {

namespace {

float em() { return ImGui::GetFontSize(); }

// A colour per label: the source's index hashed to a hue, the region varying lightness and
// saturation (face region light, edge regions middle, vertex regions dark).
ImU32 label_colour(const DomainLabel& l, bool infinite) {
    if (infinite || l.source < 0) return IM_COL32(70, 72, 80, 255);
    // Golden-ratio hues: consecutive indices (often neighbours in a mesh) get far-apart hues.
    float hue = (float)std::fmod(0.13 + 0.6180339887498949 * (double)l.source, 1.0);
    const int r = (int)l.region;
    static const float kSat[7] = {0.35f, 0.55f, 0.55f, 0.55f, 0.72f, 0.72f, 0.72f};
    static const float kVal[7] = {0.96f, 0.84f, 0.76f, 0.68f, 0.58f, 0.50f, 0.42f};
    static const float kHue[7] = {0.0f, -0.04f, 0.0f, 0.04f, -0.04f, 0.0f, 0.04f};
    const float s = kSat[r], v = kVal[r];
    hue += kHue[r] + 1.0f;
    hue -= std::floor(hue);
    float rr, gg, bb;
    ImGui::ColorConvertHSVtoRGB(hue, s, v, rr, gg, bb);
    return ImGui::ColorConvertFloat4ToU32(ImVec4(rr, gg, bb, 1.0f));
}

std::string label_text(const DomainLabel& l, bool infinite) {
    if (infinite || l.source < 0) return "no source (d^2 = inf)";
    return "T " + std::to_string(l.source) + ", " + region_name(l.region);
}

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

const char* kind_name(EventKind k) { return event_name(k); }

std::string vec_text(Vec2 p) {
    char b[64];
    std::snprintf(b, sizeof b, "(%.4g, %.4g)", p.x, p.y);
    return b;
}

// One line with the event's main fields.
std::string event_text(const Event& e) {
    char b[256];
    std::string t;
    switch (e.kind) {
    case EventKind::TargetBegun: return "the target's frame is set up";
    case EventKind::VoxelVisited:
    case EventKind::VoxelCulled:
        std::snprintf(b, sizeof b, "voxel %lld, distance %.6g", e.voxel, e.distance);
        return b;
    case EventKind::SourceChosen:
        std::snprintf(b, sizeof b, "source T %d from voxel %lld, distance %.6g", e.source, e.voxel, e.distance);
        return b;
    case EventKind::SourceCulled:
        std::snprintf(b, sizeof b, "source T %d, distance %.6g", e.source, e.distance);
        return b;
    case EventKind::RegionsProjected:
        std::snprintf(b, sizeof b, "source T %d: %zu regions clipped to T'", e.source, e.regions.size());
        return b;
    case EventKind::DomainSplit:
        t = "face " + std::to_string(e.face) + " -> {";
        for (size_t i = 0; i < e.faces.size(); ++i) t += (i ? ", " : "") + std::to_string(e.faces[i]);
        return t + "} by " + conic_type_name(decompose_conic(e.curve).type);
    case EventKind::DomainCreated:
        return "face " + std::to_string(e.face) + ": " + label_text(e.old_label, e.old_label.source < 0) + " -> " +
               label_text(e.label, false);
    case EventKind::DomainMerged:
        return "face " + std::to_string(e.face) + " absorbed face " + std::to_string(e.other);
    case EventKind::ArcMaximum:
    case EventKind::MaximumRaised:
    case EventKind::TargetFinished:
        std::snprintf(b, sizeof b, "at %s, d^2 %.6g (d %.6g)", vec_text(e.point).c_str(), e.value, std::sqrt(std::max(0.0, e.value)));
        return b;
    case EventKind::SearchRadiusShrunk:
        std::snprintf(b, sizeof b, "radius %.6g", e.radius);
        return b;
    }
    return "";
}

}  // namespace

namespace {
// SameLine() when an item `w` wide still fits on the current row, else the item starts a new row.
void same_line_if_fits(float w) {
    const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
    if (ImGui::GetItemRectMax().x + ImGui::GetStyle().ItemSpacing.x + w <= right) ImGui::SameLine();
}
float checkbox_width(const char* label) {
    return ImGui::GetFrameHeight() + ImGui::GetStyle().ItemInnerSpacing.x + ImGui::CalcTextSize(label).x;
}
}  // namespace

std::string event_summary(const Event& e) { return event_text(e); }

void face_polygon(const DomainMesh& m, int f, std::vector<Vec2>& outer, std::vector<int>& tris) {
    outer = simplify(m.sample_loop(m.faces()[f].loops[0], 24));
    tris = triangulate(outer);
}
unsigned domain_label_colour(const DomainLabel& l, bool infinite) { return label_colour(l, infinite); }

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
        d.colour = label_colour(d.label, d.infinite);
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

// ---- Timeline panel

void draw_timeline(AppState& s) {
    Stepper& st = s.stepper;
    if (!st.open || !st.active()) return;
    place_tile(s.tiles.timeline);
    char title[96];
    std::snprintf(title, sizeof title, "Timeline: target %ld of %s###timeline", st.target, st.side == 0 ? "A" : "B");
    bool open = true;
    if (!ImGui::Begin(title, &open, kTileFlags)) {
        ImGui::End();
        st.open = open;
        return;
    }
    st.open = open;
    if (ImGui::Button("|<")) st.jump(-1);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("first: before any event");
    ImGui::SameLine();
    if (ImGui::Button("<")) st.back();
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("one event back (Left; replays from the start)");
    ImGui::SameLine();
    if (ImGui::Button(">")) st.forward();
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("one event forward (Right)");
    ImGui::SameLine();
    if (ImGui::Button(">>")) st.next_insertion();
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("to the end of the next insertion");
    ImGui::SameLine();
    if (ImGui::Button(">|")) st.to_end();
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("last: the finished target");
    ImGui::SameLine();
    if (ImGui::Button(st.playing ? "Pause" : "Play ", ImVec2(4 * em(), 0))) st.playing = !st.playing;
    same_line_if_fits(9 * em() + ImGui::GetStyle().ItemInnerSpacing.x + ImGui::CalcTextSize("ev/s").x);
    ImGui::SetNextItemWidth(9 * em());
    ImGui::SliderFloat("ev/s", &st.speed, 1, 500, "%.0f", ImGuiSliderFlags_Logarithmic);
    same_line_if_fits(7 * em() + ImGui::GetStyle().ItemSpacing.x + ImGui::CalcTextSize("Go to step").x + 2 * ImGui::GetStyle().FramePadding.x);
    ImGui::SetNextItemWidth(7 * em());
    bool go = ImGui::InputInt("##jump", &st.jump_input, 1, 100, ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::SameLine();
    go = ImGui::Button("Go to step") || go;
    if (go) st.jump(std::max(-1, st.jump_input));
    same_line_if_fits(checkbox_width("regions"));
    ImGui::Checkbox("regions", &st.show_regions);
    same_line_if_fits(checkbox_width("voxels & radius"));
    ImGui::Checkbox("voxels & radius", &st.show_voxels);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("3D view: voxels seen so far (green visited, yellow pending, grey culled)\n"
                          "and the search radius envelope: a sphere around the centroid of T' of\n"
                          "radius r + (farthest corner from the centroid), enclosing every point\n"
                          "within r of T' (%ld visited, %ld pending, %ld culled)",
                          st.vox_visited, st.vox_pending, st.vox_culled);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("outline the seven regions of the source being inserted");
    same_line_if_fits(checkbox_width("event log"));
    ImGui::Checkbox("event log", &st.event_log);
    same_line_if_fits(checkbox_width("graph"));
    ImGui::Checkbox("graph", &st.graph_open);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("the graph of d^2 over T' at this step (drag orbits, wheel zooms)");

    // Keys: Left/Right step, Space plays, unless a text field (or another widget) has the keyboard.
    ImGuiIO& io = ImGui::GetIO();
    if (!io.WantTextInput && !io.WantCaptureKeyboard) {
        if (ImGui::IsKeyPressed(GLFW_KEY_LEFT)) st.back();
        if (ImGui::IsKeyPressed(GLFW_KEY_RIGHT)) st.forward();
        if (ImGui::IsKeyPressed(GLFW_KEY_SPACE, false)) st.playing = !st.playing;
    }
    if (st.playing) {   // (headless: ImGui's clock runs 1/60 s a frame)
        st.play_accum += io.DeltaTime * st.speed;
        int n = std::min(1000, (int)st.play_accum);
        st.play_accum -= n;
        if (n > 0) st.jump(st.step + n);
        if (st.at_end) st.playing = false;
    } else {
        st.play_accum = 0;
    }

    const TargetSolver& ts = *st.solver;
    if (st.current)
        ImGui::Text("step %ld  %s  (insertion %d)", st.step, kind_name(st.current->kind), st.current->insertion);
    else
        ImGui::Text("step -  before the first event");
    if (st.at_end) {
        ImGui::SameLine();
        ImGui::TextColored(ImVec4(0.5f, 1, 0.5f, 1), "  finished");
    }
    ImGui::TextDisabled("%s", st.current ? event_text(*st.current).c_str() : "");
    const double mx = st.max_sq();
    const double r = st.search_radius();
    ImGui::Text("insertions %d   domains %d   arcs %d   vertices %d   max %s   search radius %s", st.insertions(),
                st.live_domains, st.live_arcs, st.live_vertices,
                std::isfinite(mx) ? std::to_string(std::sqrt(mx)).c_str() : "inf",
                std::isfinite(r) ? std::to_string(r).c_str() : "inf");
    // The search radius after each insertion up to the current step (right of the text, if it fits).
    st.radius_plot.clear();
    {
        const auto& ev = ts.events();
        for (long i = 0; i <= std::min<long>(st.step, (long)ev.size() - 1); ++i) {
            const Event& e = ev[i];
            if (e.insertion < 1 || !std::isfinite(e.radius)) continue;
            if ((int)st.radius_plot.size() < e.insertion) st.radius_plot.resize(e.insertion, (float)e.radius);
            st.radius_plot[e.insertion - 1] = (float)e.radius;
        }
    }
    // The plot goes right of the three lines of text when it fits, else below them.
    const float plot_w = 22 * em();
    if (!st.radius_plot.empty()) {
        const float lh = ImGui::GetTextLineHeightWithSpacing();
        const bool beside = ImGui::GetWindowContentRegionMax().x > plot_w + 48 * em();
        if (beside) ImGui::SetCursorPos(ImVec2(ImGui::GetWindowContentRegionMax().x - plot_w, ImGui::GetCursorPosY() - 3 * lh));
        char overlay[64];
        std::snprintf(overlay, sizeof overlay, "search radius %.4g", st.radius_plot.back());
        ImGui::PlotLines("##radius", st.radius_plot.data(), (int)st.radius_plot.size(), 0, overlay, 0.0f, FLT_MAX,
                         ImVec2(beside ? plot_w : std::max(plot_w, ImGui::GetContentRegionAvail().x), 3 * lh - ImGui::GetStyle().ItemSpacing.y));
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("search radius after each insertion, up to the current step");
    }
    // The height all this needs: the layout gives the timeline tile that much from the next frame.
    s.tiles.timeline_need = ImGui::GetCursorPosY() + ImGui::GetStyle().WindowPadding.y - ImGui::GetStyle().ItemSpacing.y;
    ImGui::End();
}

// ---- Domain view

void draw_domain_view(AppState& s) {
    Stepper& st = s.stepper;
    if (!st.open || !st.active()) return;
    place_tile(s.tiles.domain);
    bool open = true;
    if (!ImGui::Begin("Domain view", &open, kTileFlags | ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse)) {
        ImGui::End();
        st.open = open;
        return;
    }
    st.open = open;
    s.tiles.domain_w = ImGui::GetWindowSize().x;   // the user may drag the right edge
    const TargetSolver& ts = *st.solver;
    const DomainMesh* mesh = st.mesh();   // as it was at the current step
    const TargetFrame& fr = ts.frame();
    // Arc maxima belong to a finished insertion (inside one, the solver's are of the previous mesh).
    static const std::vector<Candidate> kNone;
    const std::vector<Candidate>& candidates = st.snapshot() ? kNone : ts.candidates();

    const float legend_w = 10 * em();
    ImVec2 avail = ImGui::GetContentRegionAvail();
    ImVec2 c0 = ImGui::GetCursorScreenPos();
    ImVec2 csize(std::max(4 * em(), avail.x - legend_w - 0.5f * em()), std::max(4 * em(), avail.y));
    ImGui::InvisibleButton("canvas", csize, ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight);
    const bool hovered = ImGui::IsItemHovered();
    const bool active = ImGui::IsItemActive();
    st.view_rect[0] = c0.x, st.view_rect[1] = c0.y, st.view_rect[2] = csize.x, st.view_rect[3] = csize.y;

    // Frame -> screen: T' fitted into the canvas, then zoom and pan.
    Box2 box;
    for (const Vec2& c : fr.corners) box.add(c);
    const double bw = std::max(1e-9, box.hi.x - box.lo.x), bh = std::max(1e-9, box.hi.y - box.lo.y);
    const double s0 = 0.9 * std::min(csize.x / bw, csize.y / bh);
    if (st.fit) st.zoom = 1, st.pan_x = st.pan_y = 0, st.fit = false;
    ImGuiIO& io = ImGui::GetIO();
    const ImVec2 cc(c0.x + 0.5f * csize.x, c0.y + 0.5f * csize.y);
    auto scale = [&]() { return s0 * st.zoom; };
    auto centre = [&]() { return Vec2(0.5 * (box.lo.x + box.hi.x) + st.pan_x, 0.5 * (box.lo.y + box.hi.y) + st.pan_y); };
    auto to_screen = [&](Vec2 p) {
        Vec2 c = centre();
        return ImVec2(cc.x + (float)((p.x - c.x) * scale()), cc.y - (float)((p.y - c.y) * scale()));
    };
    auto to_frame = [&](ImVec2 q) {
        Vec2 c = centre();
        return Vec2(c.x + (q.x - cc.x) / scale(), c.y - (q.y - cc.y) / scale());
    };
    if (active && ImGui::IsMouseDragging(ImGuiMouseButton_Right, 0.0f)) {
        st.pan_x -= io.MouseDelta.x / scale();
        st.pan_y += io.MouseDelta.y / scale();
    }
    if (hovered && io.MouseWheel != 0) {
        Vec2 before = to_frame(io.MousePos);
        st.zoom = std::clamp(st.zoom * std::pow(1.2f, io.MouseWheel), 0.2f, 1e5f);
        Vec2 after = to_frame(io.MousePos);
        st.pan_x += before.x - after.x;
        st.pan_y += before.y - after.y;
    }
    if (hovered && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) st.fit = true;
    for (int k = 0; k < 3; ++k) {
        const ImVec2 q = to_screen(fr.corners[k]);
        st.corner_screen[k][0] = q.x, st.corner_screen[k][1] = q.y;
    }
    st.hover_arc = st.hover_face = -1;

    ImDrawList* dl = ImGui::GetWindowDrawList();
    const ImVec2 c1(c0.x + csize.x, c0.y + csize.y);
    dl->PushClipRect(c0, c1, true);
    dl->AddRectFilled(c0, c1, IM_COL32(24, 25, 30, 255));

    // The overlay (nearest feature, independent of the domain mesh) replaces the domain fills.
    if (st.show_overlay) update_overlay(st);
    const bool overlay = st.show_overlay && st.overlay_tex && st.overlay_w > 0;
    if (overlay)
        dl->AddImage((ImTextureID)(intptr_t)st.overlay_tex, to_screen(Vec2(st.overlay_lo.x, st.overlay_hi.y)),
                     to_screen(Vec2(st.overlay_hi.x, st.overlay_lo.y)), ImVec2(0, st.overlay_gpu ? 1.0f : 0.0f),
                     ImVec2(1, st.overlay_gpu ? 0.0f : 1.0f));
    // Domains: triangles without anti-aliased fringes, so neighbouring triangles leave no seams.
    const ImVec2 uv = ImGui::GetFontTexUvWhitePixel();
    for (const DomainDraw& d : st.domains) {
        if (overlay) break;
        if (d.tris.empty()) continue;
        const int nv = (int)d.outer.size(), ni = (int)d.tris.size();
        dl->PrimReserve(ni, nv);
        const ImDrawIdx base = (ImDrawIdx)dl->_VtxCurrentIdx;
        for (const Vec2& p : d.outer) dl->PrimWriteVtx(to_screen(p), uv, d.colour);
        for (int i : d.tris) dl->PrimWriteIdx((ImDrawIdx)(base + i));
    }
    // The tolerance: the part above T shaded, the curve d = T.
    draw_tolerance_in_domain_view(s, dl, c0, c1, to_screen, !overlay);
    // Arcs: region boundaries thin, conics thick, the target's boundary white.
    std::vector<ImVec2> pts;
    for (const ArcDraw& a : st.arcs) {
        pts.clear();
        for (const Vec2& p : a.pts) pts.push_back(to_screen(p));
        ImU32 col = a.kind == ArcKind::TargetBoundary ? IM_COL32(255, 255, 255, 255)
                    : a.kind == ArcKind::Conic        ? IM_COL32(15, 15, 20, 255)
                                                      : IM_COL32(45, 45, 55, 200);
        float w = a.kind == ArcKind::RegionBoundary ? 1.0f : 2.5f;
        dl->AddPolyline(pts.data(), (int)pts.size(), col, 0, w);
    }
    for (const Vec2& p : st.vertices) dl->AddCircleFilled(to_screen(p), 2.2f, IM_COL32(20, 20, 25, 255), 8);
    for (const Candidate& c : candidates)
        if (c.edge >= 0) dl->AddCircle(to_screen(c.p), 4.5f, IM_COL32(255, 140, 0, 255), 12, 2.0f);
    // Regions of the source being inserted.
    const Event* reg = st.show_regions ? st.regions_event() : nullptr;
    if (reg) {
        for (const RegionPolygon& rp : reg->regions) {
            if (rp.polygon.size() < 2) continue;
            std::vector<ImVec2> pts;
            Vec2 mid;
            for (const Vec2& p : rp.polygon) pts.push_back(to_screen(p)), mid += p;
            mid = mid / (double)rp.polygon.size();
            dl->AddPolyline(pts.data(), (int)pts.size(), IM_COL32(255, 230, 60, 220), ImDrawFlags_Closed, 1.5f);
            std::string name = region_name(rp.kind);
            ImVec2 q = to_screen(mid), ts2 = ImGui::CalcTextSize(name.c_str());
            dl->AddText(ImVec2(q.x - 0.5f * ts2.x, q.y - 0.5f * ts2.y), IM_COL32(255, 240, 120, 255), name.c_str());
        }
    }
    // The domains the current event is about (split pieces, the relabelled or the merged domain).
    if (st.current && st.snapshot()) {
        const Event& e = *st.current;
        std::vector<int> ids = e.kind == EventKind::DomainSplit ? e.faces : std::vector<int>{};
        if (e.kind == EventKind::DomainCreated || e.kind == EventKind::DomainMerged) ids.push_back(e.face);
        for (const DomainDraw& d : st.domains)
            if (std::find(ids.begin(), ids.end(), d.face) != ids.end()) {
                pts.clear();
                for (const Vec2& p : d.outer) pts.push_back(to_screen(p));
                dl->AddPolyline(pts.data(), (int)pts.size(), IM_COL32(0, 230, 255, 255), ImDrawFlags_Closed, 3.0f);
            }
    }
    if (std::isfinite(st.max_sq()) && mesh) {
        ImVec2 q = to_screen(st.max_2d());
        dl->AddCircleFilled(q, 8, IM_COL32(230, 30, 40, 255), 20);
        dl->AddCircle(q, 8, IM_COL32(255, 255, 255, 255), 20, 2.0f);
        dl->AddLine(ImVec2(q.x - 12, q.y), ImVec2(q.x + 12, q.y), IM_COL32(255, 255, 255, 255), 1.5f);
        dl->AddLine(ImVec2(q.x, q.y - 12), ImVec2(q.x, q.y + 12), IM_COL32(255, 255, 255, 255), 1.5f);
    }
    if (!mesh) dl->AddText(ImVec2(c0.x + em(), c0.y + em()), IM_COL32(220, 220, 220, 255), "degenerate target: no domain mesh");
    if (mesh && st.inserting() >= 0) {
        char note[160];
        std::snprintf(note, sizeof note, "inside insertion %d (T %d): domains it has not reached keep their labels",
                      st.insertions(), st.inserting());
        dl->AddText(nullptr, 0, ImVec2(c0.x + 0.5f * em(), c0.y + 0.4f * em()), IM_COL32(0, 230, 255, 255), note, nullptr,
                    csize.x - em());   // wrapped to the canvas
    }
    dl->PopClipRect();

    // Hover: an arc within 5 px first, else the domain under the mouse.
    if (hovered && mesh && (!s.headless || s.scripted_input) && !ImGui::IsMouseDragging(ImGuiMouseButton_Right)) {
        const ImVec2 m = io.MousePos;
        int best = -1;
        float bd = 5.0f;
        for (const ArcDraw& a : st.arcs)
            for (size_t i = 0; i + 1 < a.pts.size(); ++i) {
                ImVec2 p = to_screen(a.pts[i]), q = to_screen(a.pts[i + 1]);
                float dx = q.x - p.x, dy = q.y - p.y, l2 = dx * dx + dy * dy;
                float t = l2 > 0 ? std::clamp(((m.x - p.x) * dx + (m.y - p.y) * dy) / l2, 0.0f, 1.0f) : 0.0f;
                float ex = p.x + t * dx - m.x, ey = p.y + t * dy - m.y, dd = std::sqrt(ex * ex + ey * ey);
                if (dd < bd) bd = dd, best = a.edge;
            }
        st.hover_arc = best;
        if (best >= 0) {
            const auto& E = mesh->edges()[best];
            ImGui::BeginTooltip();
            ImGui::Text("arc %d: %s, %s", best, arc_kind_name(E.kind), conic_type_name(decompose_conic(E.equation).type));
            ImGui::Text("%s = 0", E.equation.to_string().c_str());
            bool any = false;
            for (const Candidate& c : candidates)
                if (c.edge == best) {
                    ImGui::Text("interior maximum d^2 %.6g at %s", c.value, vec_text(c.p).c_str());
                    any = true;
                }
            if (!any) ImGui::TextDisabled("no interior maximum");
            ImGui::EndTooltip();
        } else {
            const int f = mesh->face_at(to_frame(m));
            st.hover_face = f;
            if (f >= 0) {
                const auto& F = mesh->faces()[f];
                ImGui::BeginTooltip();
                ImGui::Text("domain %d: %s", f, label_text(F.label, F.infinite).c_str());
                if (!F.infinite) ImGui::Text("d^2 = %s", F.poly.to_string().c_str());
                ImGui::Text("area %.6g (frame units)", mesh->face_area(f));
                ImGui::EndTooltip();
            }
        }
    }

    // Legend: every label once, with its colour.
    ImGui::SameLine();
    ImGui::BeginChild("legend", ImVec2(0, csize.y), false);
    ImGui::Checkbox("overlay", &st.show_overlay);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("colour T' by the nearest source feature, computed directly from the sources\n"
                          "(CPU, %d px), and compare with the domain mesh's labels", 256);
    if (st.show_overlay && st.overlay_revision == st.revision && mesh) {
        if (st.overlay_disagree == 0)
            ImGui::TextColored(ImVec4(0.5f, 1, 0.5f, 1), "overlay agrees");
        else
            ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "overlay disagrees at %ld samples: core bug?", st.overlay_disagree);
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("%ld samples compared (%ld agree by a tie: another feature with the same\n"
                              "quadratic is nearest, e.g. coplanar sources or a shared edge),\n%ld within 2 px of a change not compared",
                              st.overlay_samples, st.overlay_ties, st.overlay_ignored);
        if (st.overlay_ties > 0)  // shown as ties, not as disagreements (on a line of its own: the legend is narrow)
            ImGui::TextColored(ImVec4(0.5f, 1, 0.5f, 1), "%.0f%% ties", 100.0 * st.overlay_ties / std::max(1L, st.overlay_samples));
    }
    ImGui::TextDisabled("%d domains", st.live_domains);
    std::map<std::pair<int, int>, std::pair<ImU32, int>> labels;
    for (const DomainDraw& d : st.domains) {
        auto& e = labels[{d.infinite ? -1 : d.label.source, d.infinite ? 0 : (int)d.label.region}];
        e.first = d.colour;
        ++e.second;
    }
    for (const auto& [key, val] : labels) {
        ImVec2 p = ImGui::GetCursorScreenPos();
        const float sz = ImGui::GetTextLineHeight();
        ImGui::GetWindowDrawList()->AddRectFilled(p, ImVec2(p.x + sz, p.y + sz), val.first);
        ImGui::Dummy(ImVec2(sz, sz));
        ImGui::SameLine();
        DomainLabel l;
        l.source = key.first;
        l.region = (Region)key.second;
        if (val.second > 1)
            ImGui::Text("%s  (x%d)", label_text(l, key.first < 0).c_str(), val.second);
        else
            ImGui::TextUnformatted(label_text(l, key.first < 0).c_str());
    }
    ImGui::EndChild();
    ImGui::End();
}

}  // namespace hlens::gui
