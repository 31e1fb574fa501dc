// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// ssmd._ssmd: the compiled part of the Python package ssmd (pybind11). The
// package's __init__.py re-exports it; its docstrings are the user's
// reference (see doc/python.md and ssmd/_ssmd.pyi).

#include "Deformation_binding.h"
#include "Numpy_mesh.h"
#include "Progress_bridge.h"

#include <CGAL/Manifold_harmonics_basis.h>
#include <CGAL/Spectral_deformation/Spectral_deformation_error.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <algorithm>
#include <string>

namespace py = pybind11;
using namespace ssmd_python;

namespace {

py::tuple manifold_harmonics(const py::handle& vertices, const py::handle& faces, long long m,
                             py::object progress, bool return_mass)
{
  if(m < 1)
    throw py::value_error("m (the number of frequencies) must be positive, not " + std::to_string(m));
  Mesh mesh;
  fill_mesh(vertices, faces, mesh);
  if(static_cast<std::size_t>(m) > mesh.number_of_vertices())
    throw py::value_error("m = " + std::to_string(m) + " frequencies asked of a mesh of " +
                          std::to_string(mesh.number_of_vertices()) + " vertices");
  Progress_bridge bridge(progress);
  CGAL::Manifold_harmonics_basis<Mesh> basis;
  {
    py::gil_scoped_release release;
    basis.compute(mesh, static_cast<std::size_t>(m), CGAL::parameters::default_values(), bridge.traits());
  }
  bridge.rethrow_if_failed();

  const Eigen::VectorXd& lambda = basis.eigenvalues();
  py::array_t<double> eigenvalues(lambda.size());
  std::copy(lambda.data(), lambda.data() + lambda.size(), eigenvalues.mutable_data());
  // Eigen stores the basis by columns: a Fortran-ordered array takes it in
  // one copy.
  const Eigen::MatrixXd& phi = basis.basis();
  py::array_t<double, py::array::f_style> functions({phi.rows(), phi.cols()});
  std::copy(phi.data(), phi.data() + phi.size(), functions.mutable_data());
  if(!return_mass)
    return py::make_tuple(eigenvalues, functions);
  const Eigen::VectorXd& M = basis.mass();
  py::array_t<double> mass(M.size());
  std::copy(M.data(), M.data() + M.size(), mass.mutable_data());
  return py::make_tuple(eigenvalues, functions, mass);
}

// An optional count given in Python: -1 for None (the library's default),
// ValueError "`requirement`, not k" for a negative k.
long long optional_count(const py::object& value, const std::string& requirement)
{
  if(value.is_none())
    return -1;
  const long long count = value.cast<long long>();
  if(count < 0)
    throw py::value_error(requirement + ", not " + std::to_string(count));
  return count;
}

} // namespace

PYBIND11_MODULE(_ssmd, m)
{
  m.doc() = "Spectral surface mesh deformation (compiled part; use the package ssmd).";
  m.attr("__version__") = SSMD_PYTHON_VERSION;

  static py::handle solver_error =
      PyErr_NewExceptionWithDoc("ssmd.SolverError",
                                "A factorization or an eigensolver failed or did not converge.",
                                PyExc_RuntimeError, nullptr);
  m.attr("SolverError") = solver_error;
  py::register_exception_translator([](std::exception_ptr p) {
    try
    {
      if(p)
        std::rethrow_exception(p);
    }
    catch(const CGAL::Spectral_deformation_error& e)
    {
      switch(e.code())
      {
      case CGAL::Spectral_deformation_error::IO_ERROR: PyErr_SetString(PyExc_OSError, e.what()); return;
      case CGAL::Spectral_deformation_error::SOLVER_FAILURE: PyErr_SetString(solver_error.ptr(), e.what()); return;
      default: PyErr_SetString(PyExc_ValueError, e.what()); return;
      }
    }
  });

  const py::object warn = py::module_::import("warnings").attr("warn");

  py::class_<Deformation_session>(m, "Deformation", R"doc(
Deforms a triangle mesh given as NumPy arrays (CGAL::Spectral_surface_mesh_deformation).

V: (n, 3) float64 vertex positions; F: (f, 3) integer vertex indices.
roi: vertex indices of the region of interest (default: every vertex not in
fixed); the vertices outside it do not move. handles: the control vertices,
in the region of interest. fixed: vertices that do not move (an alternative
to roi; the two must not overlap). m: number of manifold harmonics.
policy: 'exact' (handles land exactly on their targets) or 'soft'.
algorithm: 'spectral' (default), 'linear' or 'spatial'. constraint_weight:
weight of the handles in the reduced system (None: the library's default, 1).
energy: what the spectral iteration minimizes, 'dual_laplacian_and_arap'
(default, the sum of the two), 'dual_laplacian' (the paper's: open sheets
bend with the least stretch) or 'arap' (the ARAP energy of the smooth mesh).
rotation_patches: rotation patches of the iteration (None: the library's
default, 1000; 0: one rotation per dual vertex, the full iteration).
stage_angle: the largest turn of a handle per stage of the iteration, in
degrees (None: the library's default, 30, with which large bends do not
fold; 0: the targets in one stage).
volume_preservation: the detail transfer keeps the volume the surface
encloses (when the region is cut out of a closed surface).
basis: 'approximate' (default: eigenvectors approximated in a space of sampled
functions on large regions, several times faster, exact on small ones) or
'exact' (the eigenvectors at every size).
single_precision_basis_threshold: regions of at least this many vertices
keep their basis in float, half the memory (None: the library's default,
200000; 0: always).
basis_cache: a file to read the basis from, or to write it to once computed.
progress: a callable receiving a dict after each step of the eigensolver.

The basis is computed by the constructor (the GIL is released meanwhile).
Raises ValueError for every input the library rejects, with its message.
)doc")
      .def(py::init([warn](const py::handle& V, const py::handle& F, const py::handle& handles,
                           const py::handle& roi, const py::handle& fixed, long long m,
                           const std::string& policy, const std::string& algorithm,
                           const std::string& energy, const py::object& constraint_weight, bool single_precision_basis,
                           const py::object& rotation_patches, const py::object& stage_angle,
                           bool volume_preservation, const std::string& basis,
                           const py::object& basis_cache, const py::object& progress,
                           const py::object& single_precision_basis_threshold) {
             Deformation_settings settings;
             if(m < 1)
               throw py::value_error("m (the number of frequencies) must be positive, not " + std::to_string(m));
             settings.frequencies = static_cast<std::size_t>(m);
             settings.policy = policy;
             settings.algorithm = algorithm;
             energy_from_name(energy); // checked here, before the basis
             settings.energy = energy;
             if(!constraint_weight.is_none())
             {
               const double w = constraint_weight.cast<double>();
               if(!(w > 0) || !std::isfinite(w))
                 throw py::value_error("constraint_weight must be a positive finite number");
               settings.constraint_weight = w;
             }
             settings.single_precision_basis = single_precision_basis;
             settings.single_precision_basis_threshold = optional_count(
                 single_precision_basis_threshold, "single_precision_basis_threshold must be 0 or positive");
             settings.rotation_patches =
                 optional_count(rotation_patches, "rotation_patches must be 0 (the full iteration) or positive");
             if(!stage_angle.is_none())
             {
               const double degrees = stage_angle.cast<double>();
               if(!(degrees >= 0) || !std::isfinite(degrees))
                 throw py::value_error("stage_angle must be a finite angle of at least 0 degrees");
               settings.stage_angle = degrees;
             }
             settings.volume_preservation = volume_preservation;
             exact_basis_from_name(basis); // checked here, before the basis
             settings.basis = basis;
             if(!basis_cache.is_none())
               settings.basis_cache = py::str(py::module_::import("os").attr("fspath")(basis_cache));
             if(!progress.is_none() && !PyCallable_Check(progress.ptr()))
               throw py::value_error("progress must be callable");
             return new Deformation_session(V, F, roi, handles, fixed, settings, progress, warn);
           }),
           py::arg("V"), py::arg("F"), py::kw_only(), py::arg("handles"), py::arg("roi") = py::none(),
           py::arg("fixed") = py::none(), py::arg("m") = 100, py::arg("policy") = "exact",
           py::arg("algorithm") = "spectral", py::arg("energy") = "dual_laplacian_and_arap",
           py::arg("constraint_weight") = py::none(),
           py::arg("single_precision_basis") = false, py::arg("rotation_patches") = py::none(),
           py::arg("stage_angle") = py::none(), py::arg("volume_preservation") = false,
           py::arg("basis") = "approximate", py::arg("basis_cache") = py::none(),
           py::arg("progress") = py::none(), py::arg("single_precision_basis_threshold") = py::none())
      .def_property_readonly("number_of_vertices", &Deformation_session::number_of_vertices,
                             "The number of vertices n.")
      .def_property_readonly("handles", &Deformation_session::handles,
                             "The control vertices, in the order of the rows of targets.")
      .def_property_readonly("roi", &Deformation_session::roi,
                             "The vertices of the region of interest, sorted.")
      .def_property_readonly("vertices", &Deformation_session::vertices,
                             "A copy of the current positions, (n, 3).")
      .def_property_readonly("targets", &Deformation_session::targets,
                             "A copy of the targets of the handles, (k, 3).")
      .def("set_targets", &Deformation_session::set_targets, py::arg("P"), py::arg("which") = py::none(),
           "Sets the targets of the handles to the rows of P, (k, 3); with which (indices into handles), "
           "only of those handles. Nothing changes when a row is not finite (ValueError).")
      .def("translate", &Deformation_session::translate, py::arg("vector"), py::arg("which") = py::none(),
           "Moves the targets of the handles (or of handles[which]) by vector.")
      .def("rotate", &Deformation_session::rotate, py::arg("rotation"), py::arg("center") = py::none(),
           py::arg("which") = py::none(),
           "Rotates the targets of the handles (or of handles[which]) about center (default: their "
           "centroid); rotation is a 3 x 3 rotation matrix or a unit quaternion (w, x, y, z). "
           "Cumulative, as in CGAL.")
      .def("deform", &Deformation_session::deform, py::arg("iterations") = 10, py::arg("tolerance") = 1e-4,
           "Deforms towards the targets with at most `iterations` iterations, stopping when the relative "
           "step falls below `tolerance`; continues from the previous result, as in CGAL. Returns the new "
           "positions, (n, 3). Raises RuntimeError when the deformation fails numerically (the positions "
           "are then unchanged).")
      .def("reset", &Deformation_session::reset,
           "Puts the vertices back at their initial positions and the targets on them.")
      .def_property_readonly("preprocess_report", &Deformation_session::preprocess_report,
                             "What the last preprocessing did, as a dict.")
      .def_property_readonly("deform_report", &Deformation_session::deform_report,
                             "What the last deform() did, as a dict.")
      .def("save_basis",
           [](Deformation_session& self, const py::object& file) {
             self.save_basis(py::str(py::module_::import("os").attr("fspath")(file)));
           },
           py::arg("file"),
           "Writes the basis to file (through a temporary file).")
      .def("load_basis",
           [warn](Deformation_session& self, const py::object& file, const py::object& progress) {
             self.load_basis(py::str(py::module_::import("os").attr("fspath")(file)), progress, warn);
           },
           py::arg("file"), py::arg("progress") = py::none(),
           "Uses the basis stored in file (its number of frequencies prevails) and preprocesses again. "
           "Raises OSError when the file cannot be read and ValueError when it belongs to another mesh.");

  m.def("manifold_harmonics", &manifold_harmonics, py::arg("V"), py::arg("F"), py::arg("m"),
        py::kw_only(), py::arg("progress") = py::none(), py::arg("mass") = false,
        R"doc(
The first m manifold harmonics of the triangle mesh (V, F): returns
(eigenvalues, basis), eigenvalues of shape (m,) in increasing order and the
basis of shape (n, m), orthonormal for the lumped mass matrix; with mass=True,
(eigenvalues, basis, mass) with the lumped vertex masses of shape (n,).
The GIL is released during the eigensolve; progress is called as for Deformation.
)doc");
}
