// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// ssmd._ssmd: the compiled part of the Python package ssmd (pybind11). The
// package's __init__.py re-exports it; its docstrings are the user's
// reference (see doc/python.md and ssmd/_ssmd.pyi).

#include "Deformation_binding.h"
#include "Mesh_files.h"
#include "Numpy_mesh.h"
#include "Progress_bridge.h"

#include <CGAL/Manifold_harmonics_basis.h>
#include <CGAL/Spectral_deformation/Spectral_deformation_error.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <algorithm>
#include <string>
#include <utility>

namespace py = pybind11;
using namespace ssmd_python;

namespace {

// (V, F) as given, or, when F is None, the arrays of the mesh object V
// (ssmd.mesh_arrays: a meshio mesh, a trimesh-style object, a (V, F) pair).
std::pair<py::object, py::object> mesh_or_arrays(const py::object& V, const py::object& F)
{
  if(!F.is_none())
    return {V, F};
  const py::tuple arrays = py::module_::import("ssmd._meshes").attr("mesh_arrays")(V);
  return {arrays[0], arrays[1]};
}

py::tuple manifold_harmonics(const py::object& V, const py::object& F, const py::object& frequencies,
                             py::object progress, bool return_mass)
{
  // manifold_harmonics(mesh, 30) would read 30 as the faces.
  if(py::isinstance<py::int_>(F) && frequencies.is_none())
    throw py::type_error("manifold_harmonics(): F is a number; give the number of frequencies as m "
                         "(manifold_harmonics(mesh, m=" + py::str(F).cast<std::string>() + "))");
  if(frequencies.is_none())
    throw py::type_error("manifold_harmonics() needs m, the number of frequencies");
  const long long m = frequencies.cast<long long>();
  if(!progress.is_none() && !PyCallable_Check(progress.ptr()))
    throw py::value_error("progress must be callable");
  const auto [vertices, faces] = mesh_or_arrays(V, F);
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
Deforms a triangle mesh (CGAL::Spectral_surface_mesh_deformation).

The constructor builds the mesh, computes the manifold harmonics basis of the
region of interest and factors the systems; then set_targets(), translate()
or rotate() move the handles' targets and deform() returns the new vertex
positions. Coordinates are in the unit of the mesh (any unit: the method is
invariant to scale); angles are in degrees.
)doc")
      .def(py::init([warn](const py::object& V_in, const py::object& F_in, const py::handle& handles,
                           const py::handle& roi, const py::handle& fixed, long long m,
                           const std::string& policy, const std::string& algorithm,
                           const std::string& energy, const py::object& constraint_weight,
                           const py::object& rotation_patches, const py::object& stage_angle,
                           bool volume_preservation, const std::string& basis,
                           const py::object& basis_cache, const py::object& progress,
                           const py::object& single_precision_basis_threshold) {
             const auto [V, F] = mesh_or_arrays(V_in, F_in);
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
               settings.basis_cache = path_string(basis_cache);
             if(!progress.is_none() && !PyCallable_Check(progress.ptr()))
               throw py::value_error("progress must be callable");
             return new Deformation_session(V, F, roi, handles, fixed, settings, progress, warn);
           }),
           py::arg("V"), py::arg("F") = py::none(), py::kw_only(), py::arg("handles"), py::arg("roi") = py::none(),
           py::arg("fixed") = py::none(), py::arg("m") = 100, py::arg("policy") = "exact",
           py::arg("algorithm") = "spectral", py::arg("energy") = "dual_laplacian_and_arap",
           py::arg("constraint_weight") = py::none(),
           py::arg("rotation_patches") = py::none(),
           py::arg("stage_angle") = py::none(), py::arg("volume_preservation") = false,
           py::arg("basis") = "approximate", py::arg("basis_cache") = py::none(),
           py::arg("progress") = py::none(), py::arg("single_precision_basis_threshold") = py::none(),
           R"doc(
Builds the deformation of the triangle mesh (V, F) and preprocesses it.

Parameters
----------
V : array-like (n, 3), or a mesh
    Vertex positions, in the unit of the mesh; any real dtype (a C-contiguous
    float64 array is read in place). With F None: a mesh object, a meshio
    mesh, anything with .vertices and .faces (trimesh) or a (V, F) pair (see
    ssmd.mesh_arrays).
F : array-like (f, 3) of int, optional
    Vertex indices of the triangles (a float array is refused, not truncated).
handles : array-like of int
    The control vertices (indices into V), whose targets you set.
roi : array-like of int, optional
    The region of interest: the vertices that may move. Default: every
    vertex not in fixed.
fixed : array-like of int, optional
    Vertices that do not move (the other way to give the region; roi and
    fixed must not overlap).
m : int
    Number of manifold harmonics of the reduced system (default 100).
policy : {'exact', 'soft'}
    'exact': the handles land exactly on their targets and the vertices
    outside roi never move (CGAL's semantics); 'soft': the paper's
    least-squares constraints, no sparse factorization per constraint set.
algorithm : {'spectral', 'linear', 'spatial'}
    The iterated spectral method, one linear solve without rotations, or
    dual Laplacian editing on the full mesh (no basis).
energy : {'dual_laplacian_and_arap', 'dual_laplacian', 'arap'}
    What the spectral iteration minimizes.
constraint_weight : float, optional
    Weight of the handles in the reduced system (None: 1).
rotation_patches : int, optional
    Rotation patches of the iteration (None: 1000; 0: one rotation per dual
    vertex, the full iteration).
stage_angle : float, optional
    Largest turn of a handle per stage of the iteration, in degrees (None:
    30; 0: the targets in one stage).
volume_preservation : bool
    The detail transfer keeps the volume the surface encloses (when the
    region is cut out of a closed surface).
basis : {'approximate', 'exact'}
    'approximate': eigenvectors approximated in a space of sampled functions
    on large regions (exact on small ones); 'exact': at every size.
basis_cache : str or os.PathLike, optional
    A file to read the basis from when it holds this mesh and region's,
    written once the basis is computed.
progress : callable, optional
    Called with a dict after every step of the eigensolver (see
    ssmd.progress_bar).
single_precision_basis_threshold : int, optional
    Regions of at least this many vertices keep their basis in float, half
    the memory (None: 20000; 0: always).

Raises
------
ValueError
    For every input the library rejects (shapes, dtypes, non-finite
    coordinates, indices out of range or repeated, non-manifold or
    degenerate faces, an empty region, no handle, a part of the region
    without constraint, m out of range, an unknown option), with its message.
OSError
    When basis_cache cannot be read or written.
ssmd.SolverError
    When a factorization or the eigensolver fails.

The GIL is released while the basis is computed.
)doc")
      .def_property_readonly("number_of_vertices", &Deformation_session::number_of_vertices,
                             "The number of vertices n.")
      .def_property_readonly("handles", &Deformation_session::handles,
                             "The control vertices (int64, (k,)), in the order of the rows of targets.")
      .def_property_readonly("roi", &Deformation_session::roi,
                             "The vertices of the region of interest (int64), sorted.")
      .def_property_readonly("vertices", &Deformation_session::vertices,
                             "A copy of the current positions (float64, (n, 3)), in the unit of the mesh.")
      .def_property_readonly("targets", &Deformation_session::targets,
                             "A copy of the targets of the handles (float64, (k, 3)), in the unit of the mesh.")
      .def("set_targets", &Deformation_session::set_targets, py::arg("P"), py::arg("which") = py::none(),
           R"doc(
Sets the targets of the handles.

Parameters
----------
P : array-like (k, 3)
    The new targets, in the unit of the mesh, one row per handle in the
    order of handles (or of handles[which]).
which : array-like of int, optional
    Indices into handles: only these handles get new targets.

Raises
------
ValueError
    When P has the wrong shape or a non-finite value, or which is not a set
    of indices into handles; nothing changes then.
)doc")
      .def("translate", &Deformation_session::translate, py::arg("vector"), py::arg("which") = py::none(),
           R"doc(
Moves the targets of the handles by a vector.

Parameters
----------
vector : array-like (3,)
    The translation, in the unit of the mesh.
which : array-like of int, optional
    Indices into handles: only these targets move.

Raises
------
ValueError
    When vector does not hold 3 finite numbers or which is not a set of
    indices into handles; nothing changes then.
)doc")
      .def("rotate", &Deformation_session::rotate, py::arg("rotation"), py::arg("center") = py::none(),
           py::arg("which") = py::none(),
           R"doc(
Rotates the targets of the handles; cumulative, as in CGAL.

Parameters
----------
rotation : array-like (3, 3) or (4,)
    A rotation matrix, or a unit quaternion (w, x, y, z).
center : array-like (3,), optional
    The centre of the rotation, in the unit of the mesh (default: the
    centroid of the rotated targets).
which : array-like of int, optional
    Indices into handles: only these targets turn.

Raises
------
ValueError
    When rotation is not a rotation matrix (orthonormal, determinant 1) or a
    quaternion of norm 1, or center is not finite; nothing changes then.
)doc")
      .def("deform", &Deformation_session::deform, py::arg("iterations") = 10, py::arg("tolerance") = 1e-4,
           R"doc(
Deforms towards the targets and returns the new positions.

A second call continues the iteration from the previous result, as in CGAL.
The GIL is released meanwhile.

Parameters
----------
iterations : int
    The largest number of solves.
tolerance : float
    Stops when the relative step (the change of the smooth positions divided
    by the square root of the region's area times its bounding-box diagonal:
    unitless) falls below it; 0 runs all the solves.

Returns
-------
numpy.ndarray
    The positions, float64 (n, 3), in the unit of the mesh.

Raises
------
ValueError
    When tolerance is negative.
RuntimeError
    When the deformation fails numerically (the positions are unchanged).
)doc")
      .def("refine", &Deformation_session::refine, py::arg("max_iterations") = 100, py::arg("tolerance") = 1e-5,
           R"doc(
Refines the current positions towards the as-rigid-as-possible optimum.

Runs as-rigid-as-possible iterations (Sorkine and Alexa 2007, CGAL's
ORIGINAL_ARAP) on the detailed mesh from the positions it holds, usually
the result of deform(): the handles stay on their targets and the vertices
outside roi fixed. The next deform() goes on from its own iteration, not
from the refined shape. The GIL is released meanwhile.

Parameters
----------
max_iterations : int
    The largest number of iterations.
tolerance : float
    Stops when an iteration lowers the energy by less than tolerance times
    its value (unitless); 0 runs all the iterations.

Returns
-------
bool
    Whether the positions were updated; the energies, iterations and times
    are in refine_report.

Raises
------
TypeError
    When max_iterations is not a non-negative int. Any other failure (a
    negative or NaN tolerance, a numerical one) returns False with the
    reason in refine_report["message"] and leaves the positions unchanged.
)doc")
      .def("reset", &Deformation_session::reset,
           "Puts the vertices back at their initial positions and the targets on them. Raises nothing.")
      .def_property_readonly("preprocess_report", &Deformation_session::preprocess_report,
                             "What the last preprocessing did, as a dict (times in seconds).")
      .def_property_readonly("deform_report", &Deformation_session::deform_report,
                             "What the last deform() did, as a dict (times in seconds, residuals in the unit of "
                             "the mesh).")
      .def_property_readonly("refine_report", &Deformation_session::refine_report,
                             "What the last refine() did, as a dict (times in seconds; energies: the unitless "
                             "as-rigid-as-possible energy before the first iteration and after each, a list).")
      .def("save_basis",
           [](Deformation_session& self, const py::object& file) { self.save_basis(path_string(file)); },
           py::arg("file"),
           R"doc(
Writes the basis to a file (through a temporary file).

Parameters
----------
file : str or os.PathLike
    The file to write.

Raises
------
OSError
    When the file cannot be written.
ValueError
    With the 'spatial' algorithm, which has no basis.
)doc")
      .def("load_basis",
           [warn](Deformation_session& self, const py::object& file, const py::object& progress) {
             self.load_basis(path_string(file), progress, warn);
           },
           py::arg("file"), py::arg("progress") = py::none(),
           R"doc(
Uses the basis stored in a file (its number of frequencies prevails) and
preprocesses again.

Parameters
----------
file : str or os.PathLike
    A file written by save_basis() or basis_cache.
progress : callable, optional
    Called as by the constructor during the preprocessing.

Raises
------
OSError
    When the file cannot be read.
ValueError
    When it holds the basis of another mesh or region, or with the
    'spatial' algorithm.
)doc");

  m.def("manifold_harmonics", &manifold_harmonics, py::arg("V"), py::arg("F") = py::none(),
        py::arg("m") = py::none(), py::kw_only(), py::arg("progress") = py::none(), py::arg("mass") = false,
        R"doc(
The first m manifold harmonics of a triangle mesh.

Parameters
----------
V : array-like (n, 3), or a mesh
    Vertex positions; with F None, a mesh object (see ssmd.mesh_arrays).
F : array-like (f, 3) of int, optional
    Vertex indices of the triangles.
m : int
    The number of harmonics, 1 to n (required; give it by name with a mesh
    object: manifold_harmonics(mesh, m=30)).
progress : callable, optional
    Called with a dict after every step of the eigensolver.
mass : bool
    Also return the lumped vertex masses.

Returns
-------
eigenvalues : numpy.ndarray
    float64 (m,), increasing, in the inverse square of the mesh's unit.
basis : numpy.ndarray
    float64 (n, m), Fortran order, orthonormal for the lumped mass matrix.
mass : numpy.ndarray
    float64 (n,), the vertex areas (square of the mesh's unit); with
    mass=True only.

Raises
------
ValueError
    For a mesh the library rejects or m out of range.
TypeError
    When m is missing.
ssmd.SolverError
    When the eigensolver fails.

The GIL is released during the eigensolve.
)doc");

  m.def("from_file", &read_mesh_file, py::arg("file"),
        R"doc(
Reads a triangle mesh file as ssmd_deform reads it (CGAL::IO::read_polygon_mesh).

Parameters
----------
file : str or os.PathLike
    An .off, .obj, .ply, .stl or .ts file.

Returns
-------
V : numpy.ndarray
    float64 (n, 3), the positions in the file's unit, in the file's vertex
    order (STL, which repeats the vertices of every triangle, gives each
    point once).
F : numpy.ndarray
    int64 (f, 3), the triangles.

Raises
------
OSError
    When the file does not exist (FileNotFoundError), is a directory or
    cannot be opened.
ValueError
    When the extension is not one of these, the content is malformed, the
    polygons do not form a manifold mesh, a face is not a triangle or a
    coordinate is not finite.
)doc");

  m.def("to_file",
        [](const py::object& file, const py::object& V, const py::object& F) {
          const auto [vertices, faces] = mesh_or_arrays(V, F);
          write_mesh_file(file, vertices, faces);
        },
        py::arg("file"), py::arg("V"), py::arg("F") = py::none(),
        R"doc(
Writes the triangle mesh (V, F) as ssmd_deform writes its results.

The coordinates are written with 17 significant digits (STL: 32-bit floats),
through a temporary file renamed at the end.

Parameters
----------
file : str or os.PathLike
    An .off, .obj, .ply, .stl or .ts file.
V : array-like (n, 3), or a mesh
    Vertex positions, in any unit; with F None, a mesh object (see
    ssmd.mesh_arrays).
F : array-like (f, 3) of int, optional
    Vertex indices of the triangles.

Raises
------
ValueError
    When the extension is not one of these or (V, F) is not a mesh the
    package accepts (same checks as Deformation).
OSError
    When the folder does not exist or the file cannot be written.
)doc");

  m.def("read_selection", &read_selection_file, py::arg("file"), py::arg("number_of_vertices"),
        R"doc(
Reads a .sel file of the Botsch-Sorkine benchmark format (as ssmd_deform --sel).

Parameters
----------
file : str or os.PathLike
    One status per vertex: 0 fixed, 1 in the region, 2 handle.
number_of_vertices : int
    The number of vertices of the mesh, which the file must match.

Returns
-------
roi : numpy.ndarray
    int64, the vertices of status 1 or 2, increasing.
handles : numpy.ndarray
    int64, the vertices of status 2, increasing.

Raises
------
OSError
    When the file does not exist or cannot be opened.
ValueError
    When it holds anything else than number_of_vertices statuses.
)doc");

  m.def("read_handle_transformation", &read_handle_transformation_file, py::arg("file"),
        R"doc(
Reads a .def file: the 4 x 4 affine matrix that moves the handles.

Parameters
----------
file : str or os.PathLike
    16 numbers, row-major, the last row 0 0 0 1.

Returns
-------
numpy.ndarray
    float64 (4, 4): a point p goes to (T @ [p, 1])[:3].

Raises
------
OSError
    When the file does not exist or cannot be opened.
ValueError
    When it does not hold 16 finite numbers with the last row 0 0 0 1.
)doc");
}
