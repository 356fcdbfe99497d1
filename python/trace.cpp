#include "trace.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <memory>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <hlens/domain_mesh.h>
#include <hlens/target_solver.h>
#include <hlens/voxel_grid.h>

#include "convert.h"
#include "report.h"

namespace hlens::py_bindings {

namespace {

// Frame points (k, 2) as a numpy array.
py::array points_array(const std::vector<Vec2>& pts) {
    py::array_t<double> a({(py::ssize_t)pts.size(), (py::ssize_t)2});
    auto v = a.mutable_unchecked<2>();
    for (size_t i = 0; i < pts.size(); ++i) v(i, 0) = pts[i].x, v(i, 1) = pts[i].y;
    return a;
}

// One target of A against B, owning everything it refers to (the grid refers to the meshes, the
// solver to the grid). Events are kept as report values, as `hlens-cli trace --json` prints them.
//
// A core TargetSolver must be stepped on the thread that built it (it borrows that thread's
// thread_local stamp arrays, core/target_solver.cpp), so it is stepped here on the calling thread
// with the GIL released, not on a worker thread, and a call from another thread is refused. One
// step is one source triangle (or one event): short, so Ctrl-C is handled between steps.
class PySolver {
public:
    PySolver(py::handle VA, py::handle FA, py::handle VB, py::handle FB, long long target)
        : A_(mesh_from_arrays(VA, FA, "A")), B_(mesh_from_arrays(VB, FB, "B")) {
        if (target < 0 || target >= (long long)A_.num_triangles())
            throw py::value_error("target " + std::to_string(target) + " is out of range: A has " +
                                  std::to_string(A_.num_triangles()) + " triangles (0.." +
                                  std::to_string(A_.num_triangles() - 1) + ")");
        owner_ = std::this_thread::get_id();
        grid_ = std::make_unique<VoxelGrid>(A_, B_);
        ts_ = std::make_unique<TargetSolver>(*grid_, 0, (uint32_t)target);
        ts_->on_event([this, target](const Event& e) { events_.push_back(event_json(e, ts_->frame(), target)); });
    }

    bool step() { return blocking([&] { return ts_->step(); }); }
    py::object step_event() {
        const Event* e = nullptr;
        blocking([&] { return (e = ts_->step_event()) != nullptr; });
        return e ? to_python(event_json(*e, ts_->frame(), ts_->target())) : py::none();
    }
    void run() {
        while (step()) {
            if (PyErr_CheckSignals() != 0) throw py::error_already_set();
        }
    }

    // Every event so far, then (once finished) the final summary line, as trace --json.
    py::list events() const {
        py::list l;
        for (const Value& v : events_) l.append(to_python(v));
        if (ts_->finished()) l.append(to_python(trace_final_json(*ts_, (long)events_.size())));
        return l;
    }
    const TargetSolver& solver() const { return *ts_; }
    py::list domains(int per_arc) const;

private:
    template <class F>
    bool blocking(F&& f) {
        if (std::this_thread::get_id() != owner_)
            throw std::runtime_error("a TargetSolver can only be used from the thread that created it");
        py::gil_scoped_release nogil;
        return f();
    }
    py::dict arc(const DomainMesh& dm, int h, int per_arc) const;

    std::thread::id owner_;
    TriangleMesh A_, B_;
    std::unique_ptr<VoxelGrid> grid_;
    std::unique_ptr<TargetSolver> ts_;
    std::vector<Value> events_;
};

// Half-edge h's arc, in the direction of the face's loop: half-edge 2e runs along edge e's
// parameter, 2e+1 against it.
py::dict PySolver::arc(const DomainMesh& dm, int h, int per_arc) const {
    const int e = h / 2;
    const DomainMesh::Edge& edge = dm.edges()[e];
    std::vector<Vec2> pts;
    for (int k = 0; k <= per_arc; ++k) {
        const double s = double(k) / per_arc;
        pts.push_back(dm.edge_point(e, h % 2 == 0 ? s : 1 - s));
    }
    py::dict d;
    d["edge"] = e;
    d["kind"] = arc_kind_name(edge.kind);
    d["curve_kind"] = curve_kind_name(edge.curve_kind);
    d["equation"] = to_python(curve_json(edge.equation));
    d["points"] = points_array(pts);
    return d;
}

py::list PySolver::domains(int per_arc) const {
    if (per_arc < 1) throw py::value_error("per_arc must be >= 1");
    py::list out;
    const DomainMesh* dm = ts_->domain_mesh();
    if (!dm) return out;  // a degenerate target has no domain mesh
    for (int f = 1; f < (int)dm->faces().size(); ++f) {
        const DomainMesh::Face& face = dm->faces()[f];
        if (!face.alive) continue;
        py::list loops, arcs;
        for (int h : face.loops) {
            std::vector<Vec2> loop = dm->sample_loop(h, per_arc);  // straight arcs: one segment
            loop.push_back(loop.front());                           // closed, ready to plot
            loops.append(points_array(loop));
            py::list loop_arcs;
            int k = h;
            do {
                loop_arcs.append(arc(*dm, k, per_arc));
                k = dm->half_edges()[k].next;
            } while (k != h);
            arcs.append(loop_arcs);
        }
        py::dict d;
        d["face"] = f;
        d["label"] = to_python(label_json(face.label));
        d["covered"] = !face.infinite;
        d["poly"] = to_python(curve_json(face.poly));
        d["area"] = dm->face_area(f);
        d["loops"] = loops;
        d["arcs"] = arcs;
        out.append(d);
    }
    return out;
}

py::list trace(py::handle VA, py::handle FA, py::handle VB, py::handle FB, long long target) {
    PySolver s(VA, FA, VB, FB, target);
    s.run();
    return s.events();
}

}  // namespace

void bind_trace(py::module_& m) {
    m.def("trace", &trace, py::arg("VA"), py::arg("FA"), py::arg("VB"), py::arg("FB"), py::arg("target"),
          "trace(VA, FA, VB, FB, target) -> list[dict]\n\n"
          "Runs triangle `target` of A against B and returns every event of the construction, then a\n"
          "final summary, as dicts with the fields of `hlens-cli trace --json` (one per line there).\n"
          "Points are in the target's 2D frame ('point', 'regions') and in world coordinates ('world').");

    py::class_<PySolver>(m, "TargetSolver",
                         "One target triangle of A against B, step by step (core/target_solver.h).\n\n"
                         "TargetSolver(VA, FA, VB, FB, target). step() inserts the next source triangle,\n"
                         "step_event() advances one event; domains() describes the domain mesh for plotting.")
        .def(py::init<py::handle, py::handle, py::handle, py::handle, long long>(), py::arg("VA"), py::arg("FA"),
             py::arg("VB"), py::arg("FB"), py::arg("target"))
        .def("step", &PySolver::step, "Insert the next source triangle; False once finished.")
        .def("step_event", &PySolver::step_event, "Advance one event and return it (a dict), or None once finished.")
        .def("run", &PySolver::run, "Run to the end.")
        .def_property_readonly("events", &PySolver::events,
                               "Every event so far as dicts (trace's fields), plus the final summary once finished.")
        .def_property_readonly("finished", [](const PySolver& s) { return s.solver().finished(); })
        .def_property_readonly("max_sq", [](const PySolver& s) { return s.solver().max_sq(); },
                               "the running maximum of the squared distance over the target")
        .def_property_readonly("max_point", [](const PySolver& s) { return to_python(vec3(s.solver().max_point())); },
                               "where it is attained, in world coordinates")
        .def_property_readonly("max_point_2d", [](const PySolver& s) { return to_python(vec2(s.solver().max_point_2d())); },
                               "the same in the target's frame")
        .def_property_readonly("search_radius", [](const PySolver& s) { return s.solver().search_radius(); },
                               "sqrt(max_sq), inf before the first source")
        .def_property_readonly("insertions", [](const PySolver& s) { return s.solver().insertions(); })
        .def_property_readonly("corners", [](const PySolver& s) { return points_array({s.solver().frame().corners.begin(), s.solver().frame().corners.end()}); },
                               "the target's corners (3, 2) in its frame, in mesh order")
        .def("domains", &PySolver::domains, py::arg("per_arc") = 16,
             "domains(per_arc=16) -> list[dict]\n\n"
             "The domains of the current domain mesh (empty for a degenerate target). Each dict: 'face' (id),\n"
             "'label' {'source', 'region'}, 'covered' (False while no source reaches it), 'area', 'poly'\n"
             "{'a'..'f', 'type'}: the squared distance there, a x^2 + 2b xy + c y^2 + 2d x + 2e y + f in\n"
             "the frame (frame units: the target's longest edge is 1), 'loops': the boundary loops (outer\n"
             "first, then holes) as closed (k, 2) polylines (per_arc segments per curved arc, one per straight\n"
             "arc, the first point repeated at the end), and 'arcs': per loop,\n"
             "its arcs in order, each {'edge', 'kind', 'curve_kind', 'equation' {'a'..'f', 'type'}: the\n"
             "conic the arc lies on (same form, = 0), 'points': (per_arc + 1, 2) along the loop's direction}.");
}

}  // namespace hlens::py_bindings
