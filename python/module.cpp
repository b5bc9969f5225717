// The native half of the Python module `ncvm` (ncvm/__init__.py is the other): the C++ API
// (include/ncvm) as _ncvm.Job, with the moves of a run gathered into flat arrays that
// __init__.py turns into one numpy structured array.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <vector>

#include "ncvm/ncvm.hpp"

namespace py = pybind11;
using namespace ncvm::api;

namespace {

// Every move of a run, column by column (numpy wants columns).
class MoveColumns final : public EventHandler {
 public:
  void onMove(const Move& m) override {
    start.insert(start.end(), m.start.begin(), m.start.end());
    end.insert(end.end(), m.end.begin(), m.end.end());
    center.insert(center.end(), m.center.begin(), m.center.end());
    kind.push_back(static_cast<uint8_t>(m.kind));
    plane.push_back(static_cast<uint8_t>(m.plane));
    feed.push_back(m.feed);
    length.push_back(m.length);
    time.push_back(m.time);
    line.push_back(m.at.line);
    n.push_back(m.at.n);
  }
  std::vector<double> start, end, center, feed, length, time;
  std::vector<uint8_t> kind, plane;
  std::vector<uint32_t> line;
  std::vector<int32_t> n;
};

template <typename T>
py::array_t<T> column(const std::vector<T>& v, size_t width = 1) {
  const size_t rows = width ? v.size() / width : 0;
  std::vector<py::ssize_t> shape{static_cast<py::ssize_t>(rows)};
  if (width != 1) shape.push_back(static_cast<py::ssize_t>(width));
  py::array_t<T> a(shape);
  if (!v.empty()) std::copy(v.begin(), v.end(), a.mutable_data());
  return a;
}

}  // namespace

PYBIND11_MODULE(_ncvm, m) {
  m.doc() = "ncvm's engine (use the ncvm package: ncvm.run, ncvm.check)";
  py::register_exception<Error>(m, "Error", PyExc_RuntimeError);
  m.def("version", &version);
  m.def("data_folder", &dataFolder);

  py::class_<Alarm>(m, "Alarm", "an alarm: code, message, file, line, column, n")
      .def_readonly("code", &Alarm::code)
      .def_readonly("message", &Alarm::message)
      .def_property_readonly("file", [](const Alarm& a) { return a.where.file; })
      .def_property_readonly("line", [](const Alarm& a) { return a.where.line; })
      .def_property_readonly("column", [](const Alarm& a) { return a.where.column; })
      .def_readonly("n", &Alarm::n)
      .def("__str__",
           [](const Alarm& a) {
             return a.where.file + ":" + std::to_string(a.where.line) + ":" +
                    std::to_string(a.where.column) + ": " + a.code + " " + a.message;
           })
      .def("__repr__", [](const Alarm& a) {
        return "<ncvm.Alarm " + a.code + " at " + a.where.file + ":" +
               std::to_string(a.where.line) + ":" + std::to_string(a.where.column) + ">";
      });
  py::class_<Warning>(m, "Warning", "a warning: code, message, file, line, column")
      .def_readonly("code", &Warning::code)
      .def_readonly("message", &Warning::message)
      .def_property_readonly("file", [](const Warning& w) { return w.where.file; })
      .def_property_readonly("line", [](const Warning& w) { return w.where.line; })
      .def_property_readonly("column", [](const Warning& w) { return w.where.column; })
      .def("__repr__", [](const Warning& w) {
        return "<ncvm.Warning " + w.code + " at " + w.where.file + ":" +
               std::to_string(w.where.line) + ">";
      });

  py::class_<Job>(m, "Job")
      .def(py::init<>())
      .def("load_setup", &Job::loadSetup)
      .def("load_preset", &Job::loadPreset)
      .def("set", &Job::set)
      .def("add_program_text",
           [](Job& j, const py::bytes& text, const std::string& name) {
             j.addProgramText(std::string(text), name);
           })
      .def("add_program_file", &Job::addProgramFile)
      .def("add_folder", &Job::addFolder)
      .def("use_bundled_macros", &Job::useBundledMacros)
      // (end, alarm, warnings, stats, state_json, printed, move columns)
      .def("run",
           [](Job& j) {
             MoveColumns moves;
             RunResult r = j.run(&moves);
             py::dict stats;
             stats["blocks"] = r.stats.blocks;
             stats["moves"] = r.stats.moves;
             stats["rapid_length"] = r.stats.rapidLength;
             stats["feed_length"] = r.stats.feedLength;
             stats["simple_time"] = r.stats.simpleTime;
             stats["modelled_time"] = r.stats.modelledTime;
             py::dict cols;
             cols["start"] = column(moves.start, 6);
             cols["end"] = column(moves.end, 6);
             cols["center"] = column(moves.center, 3);
             cols["kind"] = column(moves.kind);
             cols["plane"] = column(moves.plane);
             cols["feed"] = column(moves.feed);
             cols["length"] = column(moves.length);
             cols["time"] = column(moves.time);
             cols["line"] = column(moves.line);
             cols["n"] = column(moves.n);
             return py::make_tuple(endReasonName(r.end), r.alarm, r.warnings, stats, r.stateJson,
                                   py::bytes(r.printed), cols);
           })
      .def("check", [](Job& j) {
        CheckResult c = j.check();
        return py::make_tuple(c.alarms, c.warnings, c.json);
      });
}
