// Fits from Python, with the CLI's results bit for bit:
//   summary = motoflex.fit("scenarios/fit/nao_quick.yaml", out="runs/q", max_generations=2,
//                          progress=lambda p: print(p.line))
//   spec = motoflex.FitSpec.load("fit.yaml"); spec.budget.max_generations = 5
//   motoflex.fit(spec)                          # writes spec as <out>/fit.yaml, then fits
//   motoflex.resume("runs/q", max_generations=4)
// Ctrl-C (KeyboardInterrupt) or an exception in the progress callback ends the run after the
// current generation with its checkpoint written (resume continues it), then re-raises.

#include <pybind11/functional.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>

#include "bindings.hpp"
#include "json_python.hpp"
#include "motoflex/core/atomic_file.hpp"
#include "motoflex/core/error.hpp"
#include "motoflex/fit/fit_config.hpp"
#include "motoflex/fit/fit_session.hpp"
#include "motoflex/report/report_page.hpp"

namespace py = pybind11;
namespace fs = std::filesystem;

namespace motoflex::python {
namespace {

FitOverrides overrides_of(std::optional<int> threads, std::optional<std::uint64_t> seed,
                          std::optional<std::uint64_t> max_generations,
                          std::optional<std::uint64_t> max_evaluations,
                          std::optional<double> max_seconds, std::optional<std::string> out) {
  FitOverrides overrides;
  overrides.threads = threads;
  overrides.seed = seed;
  overrides.max_generations = max_generations;
  overrides.max_evaluations = max_evaluations;
  overrides.max_seconds = max_seconds;
  overrides.out = out;
  return overrides;
}

// The summary as a dict: summary.json's content plus the one-line and full reports.
py::dict summary_dict(const FitSummary& summary) {
  py::dict out = json_to_python(summary.details).cast<py::dict>();
  out["run_dir"] = summary.run_dir;
  out["stop_reason"] = summary.stop_reason;
  out["converged"] = summary.converged;
  out["best_fitness"] = summary.best_fitness;
  out["brief_report"] = summary.brief_report();
  out["full_report"] = summary.full_report();
  return out;
}

// Runs a session with the GIL released; the progress callback and the Ctrl-C check run with
// the GIL held, once per generation. A Python exception there cancels the run (checkpoint
// kept) and is re-raised when run() has returned.
py::dict run_session(FitSession session, const std::optional<py::function>& progress,
                     bool write_report) {
  std::optional<py::error_already_set> pending;
  FitSession* self = &session;
  session.set_progress([&](const FitProgress& event) {
    py::gil_scoped_acquire acquire;
    if (pending) return;
    try {
      if (progress) (*progress)(event);
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    } catch (py::error_already_set& error) {
      pending = std::move(error);
      self->cancel();
    }
  });
  FitSummary summary;
  {
    py::gil_scoped_release release;
    summary = session.run();
  }
  if (pending) throw *pending;
  if (write_report && summary.stop_reason != "interrupted") {
    try {
      report::write_report(summary.run_dir);
    } catch (const std::exception& error) {
      PyErr_WarnEx(PyExc_RuntimeWarning,
                   (std::string("no report for ") + summary.run_dir + ": " + error.what()).c_str(),
                   1);
    }
  }
  return summary_dict(summary);
}

// A spec built or changed in Python is written as <out>/fit.yaml and fitted from there, so that
// the run folder records it and `resume` can rebuild it.
std::string spec_file(FitSpec spec) {
  if (spec.out_dir.empty() && !spec.name.empty()) {
    spec.out_dir = (fs::path("runs") / spec.name).string();
  }
  std::string error;
  if (!spec.is_valid(&error)) throw InputError(spec.path, 0, "", error);
  fs::create_directories(spec.out_dir);
  const std::string path = (fs::path(spec.out_dir) / "fit.yaml").string();
  write_file_atomically(path, "# Written by the motoflex Python module (JSON is valid YAML)\n" +
                                  fit_spec_to_json(spec).dump(2) + "\n");
  return path;
}

py::dict fit(const py::object& spec_or_path, std::optional<py::function> progress,
             const FitOverrides& overrides, bool write_report) {
  std::string path;
  FitOverrides file_overrides = overrides;
  if (py::isinstance<py::str>(spec_or_path)) {
    path = spec_or_path.cast<std::string>();
  } else {
    FitSpec spec = spec_or_path.cast<FitSpec>();
    if (overrides.out) spec.out_dir = *overrides.out;
    file_overrides.out.reset();
    path = spec_file(spec);
  }
  FitConfig config;
  {
    py::gil_scoped_release release;
    config = load_fit_config(path, file_overrides);
  }
  return run_session(FitSession::start(std::move(config)), progress, write_report);
}

py::dict run_summary(const std::string& run_dir) {
  const fs::path path = fs::path(run_dir) / "summary.json";
  std::ifstream in(path);
  if (!in) throw InputError(path.string(), 0, "", "no summary (has the fit finished?)");
  std::stringstream text;
  text << in.rdbuf();
  return json_text_to_python(text.str()).cast<py::dict>();
}

}  // namespace

void bind_fit_spec(py::module_& m);  // bind_fit_spec.cpp

void bind_fit(py::module_& m) {
  bind_fit_spec(m);
  py::class_<FitProgress>(m, "FitProgress", "One finished generation (or the end of the polish).")
      .def_readonly("polish", &FitProgress::polish)
      .def_readonly("generation", &FitProgress::generation)
      .def_readonly("evaluations", &FitProgress::evaluations)
      .def_readonly("best_fitness", &FitProgress::best_fitness)
      .def_readonly("batch_median", &FitProgress::batch_median)
      .def_readonly("mean_sigma", &FitProgress::mean_sigma)
      .def_readonly("stopped_early", &FitProgress::stopped_early)
      .def_readonly("seconds", &FitProgress::seconds)
      .def_property_readonly("line", &FitProgress::line)
      .def("__repr__",
           [](const FitProgress& p) { return "<motoflex.FitProgress " + p.line() + ">"; });

  m.def(
      "fit",
      [](const py::object& spec, std::optional<py::function> progress, std::optional<int> threads,
         std::optional<std::uint64_t> seed, std::optional<std::uint64_t> max_generations,
         std::optional<std::uint64_t> max_evaluations, std::optional<double> max_seconds,
         std::optional<std::string> out, bool report) {
        return fit(spec, progress,
                   overrides_of(threads, seed, max_generations, max_evaluations, max_seconds, out),
                   report);
      },
      py::arg("spec"), py::kw_only(), py::arg("progress") = py::none(),
      py::arg("threads") = py::none(), py::arg("seed") = py::none(),
      py::arg("max_generations") = py::none(), py::arg("max_evaluations") = py::none(),
      py::arg("max_seconds") = py::none(), py::arg("out") = py::none(), py::arg("report") = true,
      "Runs a fit from a fit YAML path (exactly as `motoflex fit`) or a FitSpec; returns the "
      "summary dict (summary.json plus brief_report/full_report).");
  m.def(
      "resume",
      [](const std::string& run_dir, std::optional<py::function> progress,
         std::optional<int> threads, std::optional<std::uint64_t> max_generations,
         std::optional<std::uint64_t> max_evaluations, std::optional<double> max_seconds,
         bool report) {
        const FitOverrides overrides =
            overrides_of(threads, {}, max_generations, max_evaluations, max_seconds, {});
        return run_session(FitSession::resume(run_dir, overrides), progress, report);
      },
      py::arg("run_dir"), py::kw_only(), py::arg("progress") = py::none(),
      py::arg("threads") = py::none(), py::arg("max_generations") = py::none(),
      py::arg("max_evaluations") = py::none(), py::arg("max_seconds") = py::none(),
      py::arg("report") = true,
      "Continues the fit of run_dir from its checkpoint (exactly as `motoflex resume`).");
  m.def("run_summary", &run_summary, py::arg("run_dir"),
        "A finished run's summary.json as a dict.");
  m.def(
      "write_report", [](const std::string& run_dir) { return report::write_report(run_dir); },
      py::arg("run_dir"), "Writes RUN_DIR/report.html (as `motoflex report`); returns its path.");
}

}  // namespace motoflex::python
