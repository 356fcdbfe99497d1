#include "panels.h"

#include "graph.h"

#include <algorithm>
#include <cinttypes>
#include <cmath>
#include <cstdio>

#include <imgui.h>
#include <imgui_stdlib.h>

#include "cases.h"
#include "colormap.h"
#include "stats_panel.h"
#include "tolerance_panel.h"

namespace hlens::gui {

namespace {

const char* kSide[2] = {"A", "B"};
const ImU32 kWitnessColor[2] = {IM_COL32(255, 150, 40, 255), IM_COL32(70, 200, 255, 255)};

float em() { return ImGui::GetFontSize(); }

std::string fmt(const char* f, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, f, v);
    return buf;
}

// A label in the first column of a two-column table row, a value in the second.
void row(const char* label, const std::string& value, const char* tooltip = nullptr) {
    ImGui::TableNextRow();
    ImGui::TableSetColumnIndex(0);
    ImGui::TextDisabled("%s", label);
    ImGui::TableSetColumnIndex(1);
    ImGui::TextUnformatted(value.c_str());
    if (tooltip && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tooltip);
}

void files_section(AppState& s) {
    for (int side = 0; side < 2; ++side) {
        ImGui::Text("%s:", kSide[side]);
        ImGui::SameLine();
        ImGui::TextUnformatted(s.name[side].c_str());
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", s.path[side].c_str());
        if (s.scene) {
            const TriangleMesh& m = s.scene->mesh[side];
            ImGui::SameLine();
            ImGui::TextDisabled("%zu tri, %zu vert", m.num_triangles(), m.num_used_vertices());
        }
    }
}

void progress_section(AppState& s) {
    if (s.computing) {
        char overlay[128];
        if (s.progress >= 0)
            std::snprintf(overlay, sizeof overlay, "%s  %.0f%%  %.1f s", s.phase.c_str(), 100 * s.progress, s.elapsed);
        else
            std::snprintf(overlay, sizeof overlay, "%s  %.1f s", s.phase.c_str(), s.elapsed);
        float frac = s.progress >= 0 ? (float)s.progress : (float)std::fmod(s.elapsed * 0.5, 1.0);
        ImGui::ProgressBar(frac, ImVec2(-6 * em(), 0), overlay);
        ImGui::SameLine();
        if (ImGui::Button("Cancel", ImVec2(-1, 0))) s.req.cancel = true;
    } else if (s.computed) {
        ImGui::TextDisabled("Computed in %.2f s", s.result.seconds);
        ImGui::SameLine(ImGui::GetContentRegionAvail().x - 6 * em());
        if (ImGui::Button("Recompute", ImVec2(-1, 0))) s.req.recompute = true;
    } else if (s.cancelled) {
        ImGui::TextColored(ImVec4(1, 0.7f, 0.3f, 1), "Cancelled");
        ImGui::SameLine(ImGui::GetContentRegionAvail().x - 6 * em());
        if (ImGui::Button("Recompute", ImVec2(-1, 0))) s.req.recompute = true;
    } else if (!s.errors.empty()) {
        ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "Not loaded (see the error panel)");
    }
}

void distances_section(AppState& s) {
    if (!ImGui::CollapsingHeader("Distances", ImGuiTreeNodeFlags_DefaultOpen)) return;
    if (!s.computed) {
        ImGui::TextDisabled(s.computing ? "computing..." : "not computed");
        return;
    }
    for (int d = 0; d < 2; ++d) {
        const OneSidedResult& r = d == 0 ? s.result.a_to_b : s.result.b_to_a;
        ImGui::PushID(d);
        ImGui::PushStyleColor(ImGuiCol_CheckMark, ImGui::ColorConvertU32ToFloat4(kWitnessColor[d]));
        ImGui::Checkbox("##witness", &s.show_witness[d]);
        ImGui::PopStyleColor();
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("show the witness point and segment");
        ImGui::SameLine();
        ImGui::Text("h(%s,%s) = %.15g", kSide[d], kSide[1 - d], r.distance);
        if (ImGui::BeginTable("interval", 2, ImGuiTableFlags_SizingFixedFit)) {
            ImGui::TableSetupColumn("k", ImGuiTableColumnFlags_WidthFixed, 4.5f * em());
            row("lower", fmt("%.17g", r.lower), "certified: the true h is at least this");
            row("upper", fmt("%.17g", r.upper), "certified: the true h is at most this");
            char t[96];
            std::snprintf(t, sizeof t, "triangle %u of %s", r.target, kSide[d]);
            row("witness", t, "the target triangle where h is attained (from_point)");
            ImGui::EndTable();
        }
        ImGui::PopID();
    }
    const bool ab = s.result.a_to_b.distance >= s.result.b_to_a.distance;
    ImGui::Separator();
    ImGui::Text("Hausdorff = %.15g", s.result.hausdorff);
    ImGui::SameLine();
    ImGui::TextDisabled(ab ? "h(A,B)" : "h(B,A)");
}

void direction_section(AppState& s) {
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted("Measure");
    ImGui::SameLine();
    int dir = s.direction;
    if (ImGui::RadioButton("A to B", &dir, 0)) s.req.set_direction = 0;
    ImGui::SameLine();
    if (ImGui::RadioButton("B to A", &dir, 1)) s.req.set_direction = 1;
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("the measured mesh carries the colour map and the targets");
}

// 12,345
std::string with_commas(size_t n) {
    std::string d = std::to_string(n), out;
    for (size_t i = 0; i < d.size(); ++i) {
        if (i && (d.size() - i) % 3 == 0) out += ',';
        out += d[i];
    }
    return out;
}

// A swatch of the "not yet exact" hatch, as the 3D view draws it (mesh.frag.glsl): the two greys in
// diagonal stripes of period hatch_period(font size) along x.
void hatch_swatch(float w, float h) {
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const ImVec2 p = ImGui::GetCursorScreenPos();
    auto grey = [](float g) {
        const int v = (int)std::lround(g * 255);
        return IM_COL32(v, v, v, 255);
    };
    dl->AddRectFilled(p, ImVec2(p.x + w, p.y + h), grey(kNotExactGrey[0]));
    dl->PushClipRect(p, ImVec2(p.x + w, p.y + h), true);
    const float period = hatch_period(em());
    for (float x = p.x - h - period; x < p.x + w + period; x += period)   // lines of slope +1 (screen)
        dl->AddLine(ImVec2(x + 0.25f * period, p.y), ImVec2(x + 0.25f * period + h, p.y + h), grey(kNotExactGrey[1]),
                    0.5f * period / std::sqrt(2.0f));
    dl->PopClipRect();
    dl->AddRect(p, ImVec2(p.x + w, p.y + h), IM_COL32(0, 0, 0, 255));
    ImGui::Dummy(ImVec2(w, h));
}

void colour_bar(AppState& s, const ColourRange& r) {
    ImDrawList* dl = ImGui::GetWindowDrawList();
    ImVec2 p = ImGui::GetCursorScreenPos();
    float w = ImGui::GetContentRegionAvail().x, h = 1.1f * em();
    s.colour_bar_rect[0] = p.x, s.colour_bar_rect[1] = p.y, s.colour_bar_rect[2] = w, s.colour_bar_rect[3] = h;
    const auto& table = colormap_table();
    const int n = 64;
    for (int i = 0; i < n; ++i) {
        auto c0 = table[(size_t)i * (kColormapSize - 1) / n];
        auto c1 = table[(size_t)(i + 1) * (kColormapSize - 1) / n];
        ImU32 a = IM_COL32(c0[0], c0[1], c0[2], 255), b = IM_COL32(c1[0], c1[1], c1[2], 255);
        float x0 = p.x + w * i / n, x1 = p.x + w * (i + 1) / n;
        dl->AddRectFilledMultiColor(ImVec2(x0, p.y), ImVec2(x1, p.y + h), a, b, b, a);
    }
    dl->AddRect(p, ImVec2(p.x + w, p.y + h), IM_COL32(0, 0, 0, 255));
    ImGui::Dummy(ImVec2(w, h));
    // Tick labels: low, middle, high.
    char lo[32], mid[32], hi[32];
    std::snprintf(lo, sizeof lo, "%.4g", r.lo);
    std::snprintf(mid, sizeof mid, "%.4g", 0.5 * (r.lo + r.hi));
    std::snprintf(hi, sizeof hi, "%.4g", r.hi);
    float y = ImGui::GetCursorPosY();
    float x0 = ImGui::GetCursorPosX();
    ImGui::TextUnformatted(lo);
    ImGui::SetCursorPos(ImVec2(x0 + 0.5f * (w - ImGui::CalcTextSize(mid).x), y));
    ImGui::TextUnformatted(mid);
    s.colour_bar_hi_label = s.units.empty() ? std::string(hi) : std::string(hi) + " " + s.units;
    ImGui::SetCursorPos(ImVec2(x0 + w - ImGui::CalcTextSize(s.colour_bar_hi_label.c_str()).x, y));
    ImGui::TextUnformatted(s.colour_bar_hi_label.c_str());
}

// The exact colour map's state for direction d: the legend of the grey triangles, the fill-in's
// progress with Cancel, or why it is not running.
void exact_section(AppState& s) {
    const int d = s.direction;
    const ExactMap& m = s.exact[d];
    const size_t n = m.value.size();
    if (n == 0) return;
    // (once cancelled it shows as stopped, though the targets in progress still finish)
    const bool running = s.exact_running && s.exact_side == d && !m.stopped;
    if (!m.complete()) {
        hatch_swatch(2.2f * em(), 1.1f * em());
        ImGui::SameLine();
        ImGui::TextWrapped("not yet exact: %s of %s triangles (their exact maximum is still unknown; not coloured by a bound)",
                           with_commas(n - m.exact).c_str(), with_commas(n).c_str());
    }
    const std::string counts = with_commas(m.exact) + " / " + with_commas(n) + " triangles";
    auto disabled_wrapped = [](const std::string& text) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
        ImGui::TextWrapped("%s", text.c_str());
        ImGui::PopStyleColor();
    };
    const bool stopped = !running && m.stopped && !m.complete() && m.failed.empty() && s.exact_mode != ExactMode::Off;
    if (running || stopped) {   // Cancel and Continue take the same place
        ImGui::TextWrapped("exact colour map: %s", counts.c_str());
        char pct[48];
        std::snprintf(pct, sizeof pct, "%s%.0f%%", stopped ? "stopped at " : "", 100.0 * m.exact / n);
        ImGui::ProgressBar((float)m.exact / (float)n, ImVec2(-6 * em(), 0), pct);
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("the exact maximum over every triangle the fast computation skipped,\n"
                              "computed in the background, largest upper bound first");
        ImGui::SameLine();
        if (running && ImGui::Button("Cancel##exact", ImVec2(-1, 0))) s.req.exact_cancel = true;
        if (stopped && ImGui::Button("Continue##exact", ImVec2(-1, 0))) s.req.exact_resume = true;
        if (stopped && ImGui::IsItemHovered()) ImGui::SetTooltip("continue filling in the exact colour map");
    } else if (m.complete()) {
        disabled_wrapped("exact colour map: every triangle exact (" + with_commas(n) + ")");
    } else if (!m.failed.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1, 0.4f, 0.4f, 1));
        ImGui::TextWrapped("exact colour map failed: %s", m.failed.c_str());
        ImGui::PopStyleColor();
    } else if (s.exact_mode == ExactMode::Off) {
        disabled_wrapped("exact colour map: off (--exact-colormap off); " + counts + " exact");
    } else {
        disabled_wrapped("exact colour map: " + counts);
    }
}

// What the colour map shows per triangle: the exact maximum, or the mean or RMS distance over
// the triangle (from the statistics, computed when first asked for).
void colour_by_combo(AppState& s) {
    static const char* items[3] = {"max distance", "mean distance", "RMS distance"};
    int c = (int)s.colour_by;
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted("per triangle");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(-1);
    if (ImGui::Combo("##colour_by", &c, items, 3) && c != (int)s.colour_by) {
        s.colour_by = (ColourBy)c;
        s.req.colours = true;
        if (s.colour_by != ColourBy::Max && !s.stats.ready() && !s.stats.running) s.req.stats_start = true;
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("the exact maximum over each triangle, or the exact mean or RMS over it\n"
                                                  "(these need the statistics: every triangle's full construction)");
    if (s.colour_by != ColourBy::Max && !s.stats.ready())
        ImGui::TextDisabled("%s: once the statistics are computed; max until then", items[(int)s.colour_by]);
}

void colormap_section(AppState& s) {
    const int d = s.direction;
    static const char* kQuantity[3] = {"max", "mean", "RMS"};
    const bool by_stats = s.colour_by != ColourBy::Max && s.stats.ready();
    char title[96];
    std::snprintf(title, sizeof title, "Colour map: %s distance on %s###colormap", kQuantity[by_stats ? (int)s.colour_by : 0], kSide[d]);
    if (!ImGui::CollapsingHeader(title, ImGuiTreeNodeFlags_DefaultOpen)) return;
    ColourRange& r = s.range[d];
    if (!r.valid) {
        ImGui::TextDisabled("available once h(%s,%s) is computed", kSide[d], kSide[1 - d]);
        return;
    }
    ImGui::Checkbox("show", &s.show_colormap);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(-4.5f * em());
    float speed = std::max(1e-6f, (r.data_hi - r.data_lo) * 0.002f);
    ImGui::DragFloatRange2("##range", &r.lo, &r.hi, speed, 0, 0, "%.5g", "%.5g");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("colour map range (drag, or double-click to type)");
    ImGui::SameLine();
    if (ImGui::Button("Reset", ImVec2(-1, 0))) {
        r.lo = r.data_lo;
        r.hi = r.data_hi;
    }
    colour_bar(s, r);
    exact_section(s);
    colour_by_combo(s);   // (below: the fill-in's Cancel keeps its place)
}

void meshes_section(AppState& s) {
    if (!ImGui::CollapsingHeader("Meshes", ImGuiTreeNodeFlags_DefaultOpen)) return;
    static const char* modes[] = {"Solid", "Solid+edges", "Wireframe"};
    for (int side = 0; side < 2; ++side) {
        MeshStyle& st = s.style[side];
        ImGui::PushID(side);
        ImGui::Checkbox(kSide[side], &st.visible);
        ImGui::SameLine();
        ImGui::ColorEdit3("##color", st.color, ImGuiColorEditFlags_NoInputs);
        if (side == s.direction && s.show_colormap && s.range[side].valid && ImGui::IsItemHovered())
            ImGui::SetTooltip("colour used when the colour map is off");
        ImGui::SameLine();
        int mode = (int)st.mode;
        ImGui::SetNextItemWidth(8.6f * em());
        if (ImGui::Combo("##mode", &mode, modes, 3)) {
            st.mode = (DrawMode)mode;
            st.touched = true;
        }
        ImGui::SameLine();
        ImGui::SetNextItemWidth(-1);
        if (ImGui::SliderFloat("##opacity", &st.opacity, 0.05f, 1.0f, "opacity %.2f")) st.touched = true;
        ImGui::PopID();
    }
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted("Up axis");
    ImGui::SameLine();
    int up = s.up_axis;
    ImGui::RadioButton("+Y", &up, 1);
    ImGui::SameLine();
    ImGui::RadioButton("+Z", &up, 2);
    if (up != s.up_axis) {
        s.up_axis = up;
        s.req.home = true;
    }
    ImGui::SameLine();
    if (ImGui::Button("Reset view (Home)", ImVec2(-1, 0))) s.req.home = true;
}

void target_contents(AppState& s);

// The target panel: its own window at the top-right of the view, so it stays visible whatever the
// sidebar's scroll position (the domain view, timeline and event log will sit next to it).
void target_window(AppState& s) {
    if (!s.scene) return;
    const int d = s.direction;
    const ViewRect& v = s.view;
    const float w = std::min((s.tiles.on ? 17 : 19) * em(), 0.5f * v.w);
    ImGui::SetNextWindowPos(ImVec2(v.x + v.w - 0.5f * em(), v.y + 0.5f * em()), ImGuiCond_Always, ImVec2(1, 0));
    ImGui::SetNextWindowSize(ImVec2(w, 0), ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(0.88f);
    char title[64];
    std::snprintf(title, sizeof title, "Target T' (a triangle of %s)###target", kSide[d]);
    ImGui::Begin(title, nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoSavedSettings |
                     ImGuiWindowFlags_NoFocusOnAppearing);
    target_contents(s);
    const ImVec2 pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
    s.target_window = ViewRect{pos.x, pos.y, size.x, size.y};
    ImGui::End();
}

void target_contents(AppState& s) {
    const int d = s.direction;
    const long n = (long)s.scene->mesh[d].num_triangles();
    int index = (int)s.selected[d];
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted("index");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(8 * em());
    if (ImGui::InputInt("##index", &index, 1, 10, ImGuiInputTextFlags_EnterReturnsTrue)) {
        if (index >= 0 && index < n) s.req.select = index;
    }
    ImGui::SameLine();
    if (ImGui::Button("Clear", ImVec2(-1, 0))) s.req.select = -1;
    if (s.selected[d] < 0) {
        ImGui::TextDisabled("Click a triangle of %s.", kSide[d]);
        return;
    }
    const long t = s.selected[d];
    if (ImGui::BeginTable("target", 2, ImGuiTableFlags_SizingFixedFit)) {
        ImGui::TableSetupColumn("k", ImGuiTableColumnFlags_WidthFixed, 6 * em());
        const OneSidedResult& r = d == 0 ? s.result.a_to_b : s.result.b_to_a;
        if (s.computed && s.exact[d].known(t)) {
            row("target_max", fmt("%.17g", s.exact[d].value[t]), "max distance over T' (exact)");
            row("", (size_t)t < r.target_exact.size() && r.target_exact[t] ? "exact" : "exact (colour map fill-in)");
        } else if (s.computed && (size_t)t < r.target_max.size()) {
            row("target_max", fmt("%.17g", r.target_max[t]),
                "fast mode skipped this target: an upper bound, below the result;\n"
                "its exact value comes with the exact colour map (or the trace below)");
            row("", "upper bound (not yet exact)");
        }
        ImGui::EndTable();
    }
    if (ImGui::Button(s.stepper.open ? "Close timeline" : "Step through (timeline & domain view)", ImVec2(-1, 0)))
        s.stepper.open = !s.stepper.open;
    ImGui::TextUnformatted("Trace (TargetSolver)");
    if (s.trace_running && (!s.trace[d] || s.trace[d]->target != (uint32_t)t)) {
        ImGui::SameLine();
        ImGui::TextDisabled("running...");
        return;
    }
    if (!s.trace[d] || s.trace[d]->target != (uint32_t)t) return;
    const TraceSummary& tr = *s.trace[d];
    if (!tr.error.empty()) {
        ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "failed: %s", tr.error.c_str());
        return;
    }
    if (s.tiles.on) {   // the timeline is open: one line, to leave the small 3D view visible
        ImGui::SameLine();
        ImGui::TextDisabled("%d ins., %.3f s", tr.insertions, tr.seconds);
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("the whole construction: %d insertions, %d domains, %d arcs, %d vertices;\nmax %.17g",
                              tr.insertions, tr.domains, tr.arcs, tr.vertices, tr.max);
        return;
    }
    if (ImGui::BeginTable("trace", 4, ImGuiTableFlags_SizingFixedFit)) {
        auto cell = [](const char* k, long v) {
            ImGui::TableNextColumn();
            ImGui::TextDisabled("%s", k);
            ImGui::TableNextColumn();
            ImGui::Text("%ld", v);
        };
        cell("insertions", tr.insertions);
        cell("domains", tr.domains);
        cell("arcs", tr.arcs);
        cell("vertices", tr.vertices);
        ImGui::EndTable();
    }
    if (ImGui::BeginTable("tracemax", 2, ImGuiTableFlags_SizingFixedFit)) {
        ImGui::TableSetupColumn("k", ImGuiTableColumnFlags_WidthFixed, 6 * em());
        row("max", fmt("%.17g", tr.max), "sqrt of the maximum of d^2 over T'");
        row("time", fmt("%.3f s", tr.seconds));
        ImGui::EndTable();
    }
    if (tr.degenerate) ImGui::TextDisabled("degenerate target: handled as its edges");
    if (tr.cancelled) ImGui::TextColored(ImVec4(1, 0.7f, 0.3f, 1), "cancelled");
}

void open_section(AppState& s) {
    if (!ImGui::CollapsingHeader("Open meshes")) return;
    for (int side = 0; side < 2; ++side) {
        ImGui::PushID(side);
        ImGui::AlignTextToFramePadding();
        ImGui::TextUnformatted(kSide[side]);
        ImGui::SameLine();
        ImGui::SetNextItemWidth(-4.5f * em());
        ImGui::InputTextWithHint("##path", "path to a mesh (.obj .ply .stl .off .gltf .glb)", &s.edit_path[side]);
        ImGui::SameLine();
        if (ImGui::Button("Recent", ImVec2(-1, 0))) ImGui::OpenPopup("recent");
        if (ImGui::BeginPopup("recent")) {
            if (s.recent.empty()) ImGui::TextDisabled("no recent files");
            for (const std::string& r : s.recent)
                if (ImGui::Selectable(r.c_str())) s.edit_path[side] = r;
            ImGui::EndPopup();
        }
        ImGui::PopID();
    }
    const bool ok = !s.edit_path[0].empty() && !s.edit_path[1].empty();
    if (!ok) ImGui::BeginDisabled();
    if (ImGui::Button("Load")) {
        s.req.load = true;
        s.req.load_path[0] = s.edit_path[0];
        s.req.load_path[1] = s.edit_path[1];
    }
    if (!ok) ImGui::EndDisabled();
    ImGui::SameLine();
    if (ImGui::Button("Swap")) std::swap(s.edit_path[0], s.edit_path[1]);
    ImGui::SameLine();
    if (ImGui::Button("Demo pair")) {
        s.edit_path[0] = s.demo_path[0];
        s.edit_path[1] = s.demo_path[1];
    }
    ImGui::TextDisabled("or drop files on the window");
}

// Files dropped on the window: ask which side they are.
void drop_popup(AppState& s) {
    const char* id = "Load dropped files";
    if (!s.dropped.empty() && !ImGui::IsPopupOpen(id)) ImGui::OpenPopup(id);
    if (!ImGui::BeginPopupModal(id, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    auto load = [&](const std::string& a, const std::string& b) {
        s.req.load = true;
        s.req.load_path[0] = a;
        s.req.load_path[1] = b;
        s.dropped.clear();
        ImGui::CloseCurrentPopup();
    };
    if (s.dropped.size() == 1) {
        ImGui::Text("Open %s as", s.dropped[0].c_str());
        if (ImGui::Button("A", ImVec2(5 * em(), 0))) load(s.dropped[0], s.path[1]);
        ImGui::SameLine();
        if (ImGui::Button("B", ImVec2(5 * em(), 0))) load(s.path[0], s.dropped[0]);
    } else if (s.dropped.size() >= 2) {
        ImGui::Text("A: %s", s.dropped[0].c_str());
        ImGui::Text("B: %s", s.dropped[1].c_str());
        if (s.dropped.size() > 2) ImGui::TextDisabled("(only the first two files are used)");
        if (ImGui::Button("Open", ImVec2(5 * em(), 0))) load(s.dropped[0], s.dropped[1]);
        ImGui::SameLine();
        if (ImGui::Button("Swap", ImVec2(5 * em(), 0))) std::swap(s.dropped[0], s.dropped[1]);
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel", ImVec2(5 * em(), 0)) || (!ImGui::GetIO().WantTextInput && ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape)))) {
        s.dropped.clear();
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
}

void cases_section(AppState& s) {
    if (!ImGui::CollapsingHeader("Cases")) return;
    const auto& cases = builtin_cases();
    s.case_choice = std::clamp(s.case_choice, 0, (int)cases.size() - 1);
    ImGui::SetNextItemWidth(-1);
    if (ImGui::BeginCombo("##case", cases[s.case_choice].name)) {
        for (int i = 0; i < (int)cases.size(); ++i) {
            if (ImGui::Selectable(cases[i].name, i == s.case_choice)) s.case_choice = i;
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", cases[i].description);
        }
        ImGui::EndCombo();
    }
    ImGui::TextWrapped("%s", cases[s.case_choice].description);
    ImGui::Checkbox("near-degenerate", &s.case_near);
    if (s.case_near) {
        ImGui::SameLine();
        ImGui::SetNextItemWidth(-1);
        ImGui::SliderFloat("##eps", &s.case_log_eps, -12, -1, "eps 1e%.1f");
    }
    if (ImGui::Button("Load case", ImVec2(-1, 0))) {
        s.req.load_case = cases[s.case_choice].name;
        s.req.case_eps = s.case_near ? std::pow(10.0, (double)s.case_log_eps) : 0.0;
    }
    ImGui::Separator();
    ImGui::TextUnformatted("Export case (selected target)");
    ImGui::SetNextItemWidth(-1);
    ImGui::InputText("##exportdir", &s.export_dir);
    ImGui::BeginDisabled(s.selected[s.direction] < 0 || !s.scene || !s.scene->grid);
    if (ImGui::Button("Export case", ImVec2(-1, 0))) s.req.export_case = true;
    ImGui::EndDisabled();
    if (!s.export_status.empty())
        ImGui::TextColored(s.export_ok ? ImVec4(0.6f, 1, 0.6f, 1) : ImVec4(1, 0.5f, 0.5f, 1), "%s", s.export_status.c_str());
}

// Every mouse action and keyboard shortcut (the sidebar's Help section and the F1 window).
// Shortcuts are ignored while a text field has the keyboard (io.WantTextInput).
void help_text() {
    ImGui::TextDisabled("3D view");
    ImGui::BulletText("left-drag: orbit");
    ImGui::BulletText("right-drag, middle-drag or shift+left-drag: pan");
    ImGui::BulletText("wheel: zoom");
    ImGui::BulletText("click: pick the target T' (click the background: clear)");
    ImGui::BulletText("double-click: recentre there");
    ImGui::TextDisabled("Domain view (timeline)");
    ImGui::BulletText("right-drag: pan   wheel: zoom");
    ImGui::BulletText("double-click: fit   hover: the domain's label");
    ImGui::TextDisabled("Graph of d^2");
    ImGui::BulletText("left-drag: orbit   wheel: zoom");
    ImGui::TextDisabled("Event log");
    ImGui::BulletText("click a row: jump to that step");
    ImGui::TextDisabled("Keys (not while typing in a text field)");
    ImGui::BulletText("Home: reset the view");
    ImGui::BulletText("F: frame the target and the sphere of its largest distance (also on opening its timeline)");
    ImGui::BulletText("F12: save hlens-<time>.png");
    ImGui::BulletText("F1: this help in a window");
    ImGui::BulletText("Left / Right: one event back / forward (timeline)");
    ImGui::BulletText("Space: play / pause (timeline)");
    ImGui::BulletText("Escape: cancel the dropped-files dialog");
    ImGui::TextDisabled("Other");
    ImGui::BulletText("drop files on the window: open them as A and B");
    ImGui::BulletText("grey, hatched triangles: not yet exact (the exact colour map is filling in)");
    ImGui::TextDisabled("'voxels & radius' (timeline): voxels seen so far");
    ImGui::TextDisabled("(green visited, yellow pending, grey culled) and a");
    ImGui::TextDisabled("sphere of radius r + reach of T' around its centroid,");
    ImGui::TextDisabled("enclosing all points within the search radius r of T'.");
}

void help_section() {
    if (!ImGui::CollapsingHeader("Help")) return;
    help_text();
}

void help_window(AppState& s) {
    if (!s.help_open) return;
    ImGui::SetNextWindowPos(ImVec2(s.view.x + 2 * em(), s.view.y + 2 * em()), ImGuiCond_FirstUseEver);
    if (ImGui::Begin("Help (F1)", &s.help_open, ImGuiWindowFlags_AlwaysAutoResize)) help_text();
    ImGui::End();
}

void error_panel(AppState& s) {
    if (s.errors.empty()) return;
    const ViewRect& v = s.view;
    ImGui::SetNextWindowPos(ImVec2(v.x + 0.5f * v.w, v.y + 0.4f * v.h), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSize(ImVec2(std::min(34 * em(), v.w - 2 * em()), 0), ImGuiCond_Always);
    ImGui::PushStyleColor(ImGuiCol_WindowBg, ImVec4(kErrorBg[0], kErrorBg[1], kErrorBg[2], kErrorBg[3]));
    ImGui::PushStyleColor(ImGuiCol_TitleBg, ImVec4(0.70f, 0.15f, 0.15f, 1));
    ImGui::PushStyleColor(ImGuiCol_TitleBgActive, ImVec4(0.70f, 0.15f, 0.15f, 1));
    ImGui::PushStyleColor(ImGuiCol_Border, ImVec4(1, 0.5f, 0.5f, 1));
    ImGui::Begin("Error", nullptr,
                 ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                     ImGuiWindowFlags_NoSavedSettings);
    for (size_t i = 0; i < s.errors.size(); ++i) {
        const AppError& e = s.errors[i];
        if (i) ImGui::Separator();
        ImGui::TextUnformatted(e.title.c_str());
        if (!e.file.empty()) {
            ImGui::TextDisabled("File:");
            ImGui::SameLine();
            ImGui::TextWrapped("%s", e.file.c_str());
        }
        ImGui::TextDisabled("Reason:");
        ImGui::SameLine();
        ImGui::TextWrapped("%s", e.reason.c_str());
    }
    if (!s.headless) {
        ImGui::Spacing();
        if (ImGui::Button("Dismiss")) s.req.clear_errors = true;
    }
    ImGui::End();
    ImGui::PopStyleColor(4);
}

bool project(const glm::mat4& mvp, const ViewRect& v, const glm::vec3& p, ImVec2& out) {
    glm::vec4 c = mvp * glm::vec4(p, 1.0f);
    if (c.w <= 1e-7f) return false;
    out = ImVec2(v.x + (0.5f + 0.5f * c.x / c.w) * v.w, v.y + (0.5f - 0.5f * c.y / c.w) * v.h);
    return true;
}

}  // namespace

void place_tile(const AppState::Tile& t) {
    ImGui::SetNextWindowPos(ImVec2(t.r.x, t.r.y), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(t.r.w, t.r.h), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSizeConstraints(ImVec2(t.lo_w, t.lo_h), ImVec2(t.hi_w, t.hi_h));
}

bool selected_target_ball(const AppState& s, Vec3& centroid, double& reach) {
    const int d = s.direction;
    const long t = s.selected[d];
    if (!s.scene || t < 0 || (size_t)t >= s.scene->mesh[d].num_triangles()) return false;
    const auto c = s.scene->mesh[d].corners((size_t)t);
    centroid = (c[0] + c[1] + c[2]) / 3.0;
    reach = 0;
    for (const Vec3& p : c) reach = std::max(reach, norm(p - centroid));
    return true;
}

void layout(AppState& s, float display_w, float display_h) {
    const float e = em();
    s.sidebar_width = std::min(std::round(23 * e), std::round(0.6f * display_w));
    const ViewRect area{s.sidebar_width, 0, std::max(1.0f, display_w - s.sidebar_width), std::max(1.0f, display_h)};
    AppState::Tiles& t = s.tiles;
    const Stepper& st = s.stepper;
    t.on = st.open && st.active();
    t.graph_on = t.on && st.graph_open;
    t.log_on = t.on && st.event_log;
    if (!t.on) {
        s.view = area;
        return;
    }
    // A tile's free dimension: the chosen size (or the default) within [lo, hi].
    auto pick = [](float chosen, float def, float lo, float hi) {
        hi = std::max(lo, hi);
        return std::max(lo, std::min(chosen > 0 ? chosen : def, hi));
    };
    auto pinned = [](AppState::Tile& tile) {
        tile.lo_w = tile.hi_w = tile.r.w;
        tile.lo_h = tile.hi_h = tile.r.h;
    };
    // Timeline at the bottom, full width (pinned).
    // (as tall as its contents were on the last frame: its toolbar wraps in narrow windows)
    const float tl_h = std::min(std::round(t.timeline_need > 0 ? std::max(5 * e, t.timeline_need) : 8.5f * e), 0.45f * area.h);
    t.timeline.r = ViewRect{area.x, area.y + area.h - tl_h, area.w, tl_h};
    pinned(t.timeline);
    // Domain view on the left above it; its right edge is the user's.
    const float up_h = std::max(1.0f, area.h - tl_h);
    const float dv_lo = std::min(24 * e, 0.5f * area.w), dv_hi = area.w - std::min(16 * e, 0.3f * area.w);
    const float dv_w = pick(t.domain_w, std::min(0.55f * area.w, up_h + 13 * e), dv_lo, dv_hi);
    t.domain.r = ViewRect{area.x, area.y, dv_w, up_h};
    pinned(t.domain);
    t.domain.lo_w = dv_lo, t.domain.hi_w = std::max(dv_lo, dv_hi);
    // The 3D view on the right, above a strip with the graph (left) and the event log (right).
    ViewRect right{area.x + dv_w, area.y, std::max(1.0f, area.w - dv_w), up_h};
    if (t.graph_on || t.log_on) {
        const float sh_lo = std::min(8 * e, 0.3f * right.h), sh_hi = right.h - std::min(8 * e, 0.3f * right.h);
        const float sh = pick(t.strip_h, 0.45f * right.h, sh_lo, sh_hi);
        const float y = right.y + right.h - sh;
        float gw = t.log_on ? 0 : right.w;
        const float gw_lo = std::min(12 * e, 0.3f * right.w), gw_hi = right.w - std::min(12 * e, 0.3f * right.w);
        if (t.graph_on && t.log_on) gw = pick(t.graph_w, 0.55f * right.w, gw_lo, gw_hi);
        t.graph.r = ViewRect{right.x, y, gw, sh};
        t.log.r = ViewRect{right.x + gw, y, right.w - gw, sh};
        pinned(t.graph);
        pinned(t.log);
        // The strip's top edge belongs to the graph when it is open, else to the event log; the
        // graph's right edge too when the log shares the strip.
        AppState::Tile& top = t.graph_on ? t.graph : t.log;
        top.lo_h = sh_lo, top.hi_h = std::max(sh_lo, sh_hi);
        if (t.graph_on && t.log_on) t.graph.lo_w = gw_lo, t.graph.hi_w = std::max(gw_lo, gw_hi);
        right.h = std::max(1.0f, right.h - sh);
    }
    s.view = right;
}

void draw_panels(AppState& s) {
    ImGui::SetNextWindowPos(ImVec2(0, 0), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(s.sidebar_width, ImGui::GetIO().DisplaySize.y), ImGuiCond_Always);
    ImGui::Begin("Hausdorff Lens", nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                     ImGuiWindowFlags_NoSavedSettings);
    files_section(s);
    progress_section(s);
    distances_section(s);
    ImGui::Separator();
    direction_section(s);
    colormap_section(s);
    draw_stats_section(s);
    draw_tolerance_section(s);
    meshes_section(s);
    open_section(s);
    cases_section(s);
    help_section();
    if (!s.status.empty()) {
        ImGui::Separator();
        ImGui::TextDisabled("%s", s.status.c_str());
    }
    ImGui::End();
    target_window(s);
    draw_domain_view(s);
    draw_graph_view(s);
    draw_timeline(s);
    draw_event_log(s);
    help_window(s);
    error_panel(s);
    drop_popup(s);
}

void draw_view_overlay(const AppState& s, const Scene& scene, const glm::mat4& mvp) {
    ImDrawList* dl = ImGui::GetBackgroundDrawList();
    const ViewRect& v = s.view;
    dl->PushClipRect(ImVec2(v.x, v.y), ImVec2(v.x + v.w, v.y + v.h), false);
    const float r = 0.38f * em();
    if (scene.loaded() && s.scene) {
        // The selected target: outline, and where its maximum is.
        const int d = s.direction;
        const long t = s.selected[d];
        if (t >= 0 && (size_t)t < s.scene->mesh[d].num_triangles()) {
            auto c = s.scene->mesh[d].corners((size_t)t);
            ImVec2 q[3];
            bool ok = true;
            for (int i = 0; i < 3; ++i) ok = ok && project(mvp, v, scene.local(c[i]), q[i]);
            if (ok) dl->AddPolyline(q, 3, IM_COL32(255, 255, 255, 255), ImDrawFlags_Closed, 2.0f);
            ImVec2 m;
            if (s.trace[d] && s.trace[d]->target == (uint32_t)t && s.trace[d]->error.empty() &&
                project(mvp, v, scene.local(s.trace[d]->max_point), m)) {
                dl->AddLine(ImVec2(m.x - r, m.y - r), ImVec2(m.x + r, m.y + r), IM_COL32(255, 255, 255, 255), 2);
                dl->AddLine(ImVec2(m.x - r, m.y + r), ImVec2(m.x + r, m.y - r), IM_COL32(255, 255, 255, 255), 2);
            }
        }
        // The timeline's target: the sources inserted so far, over the other mesh (the latest brighter).
        const Stepper& st = s.stepper;
        if (st.open && st.active() && st.scene == s.scene && st.side == d && st.target == t) {
            const std::vector<uint32_t> ins = st.inserted_sources();
            const TriangleMesh& other = s.scene->mesh[1 - d];
            for (size_t i = 0; i < ins.size(); ++i) {
                if (ins[i] >= other.num_triangles()) continue;
                auto c = other.corners(ins[i]);
                ImVec2 q[3];
                bool ok = true;
                for (int k = 0; k < 3; ++k) ok = ok && project(mvp, v, scene.local(c[k]), q[k]);
                if (!ok) continue;
                const bool last = i + 1 == ins.size();
                dl->AddTriangleFilled(q[0], q[1], q[2], last ? IM_COL32(255, 200, 40, 150) : IM_COL32(40, 220, 255, 90));
                dl->AddPolyline(q, 3, last ? IM_COL32(255, 220, 80, 255) : IM_COL32(60, 230, 255, 220), ImDrawFlags_Closed, 1.5f);
            }
            if (st.show_voxels && s.scene->grid) {
                // Voxels seen so far at the current step, as wireframe boxes coloured by state.
                static const int kEdge[12][2] = {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3},
                                                 {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
                const MeshGrid& sources = s.scene->grid->of(1 - d);  // the grid the target searches
                for (const auto& [vox, state] : st.voxels) {
                    if (vox >= sources.num_voxels()) continue;
                    const Box3 b = sources.voxel_box(vox);
                    ImVec2 q[8];
                    bool ok = true;
                    for (int k = 0; k < 8 && ok; ++k)
                        ok = project(mvp, v, scene.local(Vec3{k & 1 ? b.hi.x : b.lo.x, k & 2 ? b.hi.y : b.lo.y, k & 4 ? b.hi.z : b.lo.z}), q[k]);
                    if (!ok) continue;
                    const ImU32 col = state == 2 ? IM_COL32(70, 230, 90, 200) : state == 1 ? IM_COL32(240, 220, 60, 200)
                                                                                        : IM_COL32(140, 140, 140, 150);
                    for (const auto& e : kEdge) dl->AddLine(q[e[0]], q[e[1]], col, 1.0f);
                }
                // The search radius envelope: the sphere around the centroid of T' of radius
                // r + (farthest corner from the centroid). It encloses every point within r of T'
                // (a bounding sphere of that set, not the set itself). Drawn as the projected
                // outline of the sphere (the farthest projection of points sampled on it).
                const double r = st.search_radius();
                Vec3 g;
                double reach = 0;
                if (std::isfinite(r) && selected_target_ball(s, g, reach)) {
                    const double R = r + reach;
                    ImVec2 cg;
                    if (project(mvp, v, scene.local(g), cg)) {
                        float rad = 0;
                        bool ok = true;
                        for (int i = 0; i <= 12 && ok; ++i)
                            for (int j = 0; j < 24 && ok; ++j) {
                                const double th = M_PI * i / 12, ph = 2 * M_PI * j / 24;
                                const Vec3 p{g.x + R * std::sin(th) * std::cos(ph), g.y + R * std::sin(th) * std::sin(ph), g.z + R * std::cos(th)};
                                ImVec2 q;
                                ok = project(mvp, v, scene.local(p), q);
                                if (ok) rad = std::max(rad, std::hypot(q.x - cg.x, q.y - cg.y));
                            }
                        if (ok && rad > 0) {
                            dl->AddCircleFilled(cg, rad, IM_COL32(120, 170, 255, 40), 64);
                            dl->AddCircle(cg, rad, IM_COL32(140, 190, 255, 200), 64, 1.5f);
                            dl->AddText(ImVec2(cg.x + 0.72f * rad, cg.y - 0.72f * rad), IM_COL32(170, 205, 255, 255), "search radius");
                        }
                    }
                }
            }
        }
        // Witnesses: from_point (filled) on the measured mesh, to_point (ring) on the other.
        if (s.computed)
            for (int dd = 0; dd < 2; ++dd) {
                if (!s.show_witness[dd]) continue;
                const OneSidedResult& w = dd == 0 ? s.result.a_to_b : s.result.b_to_a;
                ImVec2 a, b;
                if (!project(mvp, v, scene.local(w.from_point), a) || !project(mvp, v, scene.local(w.to_point), b))
                    continue;
                dl->AddLine(a, b, IM_COL32(0, 0, 0, 200), 4.0f);
                dl->AddLine(a, b, kWitnessColor[dd], 2.0f);
                dl->AddCircleFilled(a, r, kWitnessColor[dd]);
                dl->AddCircle(a, r, IM_COL32(0, 0, 0, 255), 0, 1.5f);
                dl->AddCircle(b, r, kWitnessColor[dd], 0, 2.0f);
                char label[32];
                std::snprintf(label, sizeof label, "h(%s,%s)", kSide[dd], kSide[1 - dd]);
                ImVec2 lp(a.x + 1.6f * r, a.y - 2.6f * r), ls = ImGui::CalcTextSize(label);
                dl->AddRectFilled(ImVec2(lp.x - 3, lp.y - 1), ImVec2(lp.x + ls.x + 3, lp.y + ls.y + 1),
                                  IM_COL32(20, 20, 24, 210), 3.0f);
                dl->AddText(lp, kWitnessColor[dd], label);
            }
    }
    const char* hint = "drag: orbit  right-drag: pan  wheel: zoom  click: pick";
    ImVec2 ts = ImGui::CalcTextSize(hint);
    if (scene.loaded() && ts.x + em() < v.w)
        dl->AddText(ImVec2(v.x + 0.5f * em(), v.y + v.h - ts.y - 0.4f * em()), IM_COL32(170, 170, 180, 255), hint);
    dl->PopClipRect();
}

}  // namespace hlens::gui
