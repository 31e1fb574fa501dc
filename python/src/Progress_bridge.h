// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Calls a Python progress callback from the eigensolver, which runs without
// the GIL. An exception raised by the callback cannot cross the solver: it is
// kept, later reports are skipped, and it is raised again once the solver
// has returned.

#ifndef SSMD_PYTHON_PROGRESS_BRIDGE_H
#define SSMD_PYTHON_PROGRESS_BRIDGE_H

#include <CGAL/Spectral_deformation/Block_lanczos_eigensolver_traits.h>

#include <pybind11/pybind11.h>

#include <memory>

namespace ssmd_python {

namespace py = pybind11;

typedef CGAL::Block_lanczos_eigensolver_traits<> Eigensolver_traits;

inline const char* stage_name(Eigensolver_traits::Progress::Stage stage)
{
  switch(stage)
  {
  case Eigensolver_traits::Progress::FACTORIZATION: return "factorization";
  case Eigensolver_traits::Progress::ITERATION: return "iteration";
  case Eigensolver_traits::Progress::REFERENCE_SOLVE: return "reference_solve";
  case Eigensolver_traits::Progress::DENSE_SOLVE: return "dense_solve";
  case Eigensolver_traits::Progress::APPROXIMATION: return "approximation";
  case Eigensolver_traits::Progress::FINISHED: return "finished";
  }
  return "unknown";
}

class Progress_bridge
{
public:
  // `callback` may be None: then no report is made.
  explicit Progress_bridge(py::object callback) : m_callback(std::move(callback)) {}

  Progress_bridge(const Progress_bridge&) = delete;
  Progress_bridge& operator=(const Progress_bridge&) = delete;

  // Eigensolver traits that report to the callback (plain traits without
  // one); `Traits` reports the `Progress` of `Eigensolver_traits`.
  template <class Traits = Eigensolver_traits>
  Traits traits()
  {
    Traits traits;
    if(!m_callback.is_none())
      traits.set_progress_callback([this](const Eigensolver_traits::Progress& progress) { report(progress); });
    return traits;
  }

  // Raises the callback's exception, if any; call with the GIL held.
  void rethrow_if_failed()
  {
    if(m_error)
    {
      std::unique_ptr<py::error_already_set> error = std::move(m_error);
      throw py::error_already_set(std::move(*error));
    }
  }

private:
  void report(const Eigensolver_traits::Progress& progress)
  {
    py::gil_scoped_acquire gil;
    if(m_error)
      return;
    try
    {
      py::dict state;
      state["stage"] = stage_name(progress.stage);
      state["solves"] = progress.solves;
      state["subspace_dimension"] = progress.subspace_dimension;
      state["maximum_subspace_dimension"] = progress.maximum_subspace_dimension;
      state["converged_eigenpairs"] = progress.converged_eigenpairs;
      state["number_of_eigenpairs"] = progress.number_of_eigenpairs;
      state["number_of_vertices"] = progress.number_of_vertices;
      m_callback(state);
    }
    catch(py::error_already_set& e)
    {
      m_error.reset(new py::error_already_set(std::move(e)));
    }
  }

  py::object m_callback;
  std::unique_ptr<py::error_already_set> m_error;
};

} // namespace ssmd_python

#endif // SSMD_PYTHON_PROGRESS_BRIDGE_H
